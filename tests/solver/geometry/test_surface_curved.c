/* Surface meshes of spheres and imported meshes (surface_mesh.h, remesh.h,
 * bisect_mesh.h): vertices on the surface, normals, orientation, closed
 * and conforming after refinement, the angle bound of longest-edge
 * bisection, refinement along a sphere's terminator, an imported cube's
 * faces as regions with their own normals, and a mesh CGAL cannot remesh
 * refined as given. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "solver/geometry/key_table.h"
#include "solver/geometry/remesh.h"
#include "surface_mesh_fixture.h"

/* Parallel light of 1000 lx along -s: E = 1000 max(0, n . s); on a sphere
 * it has a kink along the terminator (n . s = 0), none elsewhere. */
static const cdl_vec3 sun = {0.40824829046386301, 0.40824829046386301, 0.81649658092772603}; /* (1, 1, 2) / sqrt 6 */

typedef struct light {
    int directional;
    cdl_vec3 position;   /* point source of 500 cd otherwise */
} light;

static cdl_status lit(void *user, const cdl_field_probe *probes, size_t count, double *value, double *sigma,
                      double *noise, double *aux, cdl_error *err)
{
    (void)aux;
    (void)noise;
    (void)err;
    const light *l = user;
    for (size_t i = 0; i < count; ++i) {
        if (l->directional) {
            value[i] = 1000.0 * fmax(0.0, cdl_vec3_dot(probes[i].normal, sun));
        } else {
            cdl_vec3 d = cdl_vec3_sub(l->position, probes[i].position);
            double r = cdl_vec3_length(d);
            value[i] = 500.0 * fmax(0.0, cdl_vec3_dot(d, probes[i].normal) / r) / (r * r);
        }
        sigma[i] = 0.0;
    }
    return CDL_OK;
}

static cdl_surface_mesh_settings settings(void)
{
    cdl_surface_mesh_settings s = {.rel_tol = 0.01,
                                   .floor_fraction = 0.5,
                                   .min_edge = 0.02,
                                   .join_tolerance = 1e-9,
                                   .feature_angle_deg = 40.0,
                                   .max_vertices = 1000000};
    return s;
}

/* Every edge used by exactly two triangles, in opposite directions: a
 * closed, consistently oriented, conforming mesh. Returns the edge count,
 * or 0 when not. */
static size_t closed_edges(const cdl_surface_mesh *m)
{
    cdl_key_table forward = {0}, uses = {0};
    cdl_error err;
    int ok = 1;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = m->triangles[3 * t + k], b = m->triangles[3 * t + (k + 1) % 3];
            uint64_t key = cdl_key_pair(a, b);
            size_t n = cdl_key_table_find(&uses, key);
            cdl_key_table_put(&uses, key, n == CDL_KEY_TABLE_NONE ? 1 : n + 1, &err);
            if (cdl_key_table_find(&forward, cdl_key_ordered(a, b)) != CDL_KEY_TABLE_NONE) ok = 0;
            cdl_key_table_put(&forward, cdl_key_ordered(a, b), 1, &err);
        }
    size_t edges = uses.count;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k)
            if (cdl_key_table_find(&uses, cdl_key_pair(m->triangles[3 * t + k], m->triangles[3 * t + (k + 1) % 3])) != 2)
                ok = 0;
    cdl_key_table_release(&forward);
    cdl_key_table_release(&uses);
    return ok ? edges : 0;
}

static void test_sphere(int inward)
{
    cdl_error err;
    const cdl_vec3 c = {1, 2, 3};
    const double r = 1.5;
    cdl_patch patch = {0};
    patch.kind = CDL_PATCH_SPHERE;
    patch.max_edge = 0.4;
    patch.center = c;
    patch.radius = r;
    patch.inward = inward;
    /* The first mesh: a field that asks for nothing. */
    light flat = {0, {1, 2, 1000}};
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(), lit, &flat};
    q.settings.rel_tol = 1.0;
    cdl_surface_mesh first, m;
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, &first, &stats, &err), &err);
    CHECK(stats.rounds == 0);
    /* Isotropic remeshing to 0.4 m: edges between 4/5 and 4/3 of it. */
    CHECK_MSG(fx_max_edge(&first) < 0.4 * 4.0 / 3.0 + 1e-9, "longest edge %g", fx_max_edge(&first));

    light l = {.directional = 1};
    q.user = &l;
    q.settings.rel_tol = 0.01;
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(stats.rounds > 2 && m.vertex_count > first.vertex_count);
    /* On the sphere, normals radial (inward: towards the centre), each
     * triangle facing the normal's side, closed: V - E + F = 2. */
    double off = 0.0, normal_error = 0.0;
    size_t facing_wrong = 0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) {
        cdl_vec3 d = cdl_vec3_sub(fx_vertex(&m, v), c);
        off = fmax(off, fabs(cdl_vec3_length(d) - r));
        cdl_vec3 n = cdl_vec3_scale(d, (inward ? -1.0 : 1.0) / cdl_vec3_length(d));
        normal_error = fmax(normal_error, cdl_vec3_distance(fx_normal(&m, v), n));
    }
    for (size_t t = 0; t < m.triangle_count; ++t)
        facing_wrong += !(cdl_vec3_dot(fx_area_vector(&m, t), fx_normal(&m, m.triangles[3 * t])) > 0.0);
    CHECK_MSG(off < 1e-14 * r * 8, "a vertex %g m off the sphere", off);
    CHECK(normal_error < 1e-14 * 8);
    CHECK(facing_wrong == 0);
    size_t edges = closed_edges(&m);
    CHECK(edges > 0 && (long)m.vertex_count - (long)edges + (long)m.triangle_count == 2);
    /* Longest-edge bisection keeps every angle above half the smallest of
     * the mesh it started from (Rivara 1997). */
    CHECK_MSG(fx_min_angle_deg(&m) >= 0.5 * fx_min_angle_deg(&first), "smallest angle %g, first mesh %g",
              fx_min_angle_deg(&m), fx_min_angle_deg(&first));
    /* Refined along the terminator: vertices per area within 5 degrees of
     * it against the lit cap more than 60 degrees from it (where the field,
     * a cosine, bends gently). */
    size_t near = 0, cap = 0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) {
        double mu = cdl_vec3_dot(cdl_vec3_normalize(cdl_vec3_sub(fx_vertex(&m, v), c)), sun);
        near += fabs(mu) < sin(5.0 * CDL_DEG_TO_RAD);
        cap += mu > cos(30.0 * CDL_DEG_TO_RAD);
    }
    /* Zone areas: 2 pi r^2 (2 sin 5 deg) and 2 pi r^2 (1 - cos 30 deg). */
    double near_density = near / (2 * sin(5.0 * CDL_DEG_TO_RAD)), cap_density = cap / (1 - cos(30.0 * CDL_DEG_TO_RAD));
    CHECK_MSG(near_density > 5.0 * cap_density, "terminator %g, cap %g (per 2 pi r^2)", near_density, cap_density);
    /* The light it receives, from the vertices' interpolant: pi r^2 x
     * 1000 lx, its cross-section, within the triangles' flatness (the
     * chords' area is below the sphere's by about h^2 / (4 r^2) of it) and
     * the tolerance. */
    CHECK_REL(fx_integral(&m), CDL_PI * r * r * 1000.0, 0.02);
    cdl_surface_mesh_release(&first);
    cdl_surface_mesh_release(&m);
}

/* A unit cube of 12 triangles, counter-clockwise seen from outside. */
static const double cube_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t cube_tri[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

/* The face of the cube a point is on and its outward normal (-1 if none). */
static int cube_face(cdl_vec3 p, const cdl_vec3 *n)
{
    const double e = 1e-12;
    double c[3] = {p.x, p.y, p.z}, m[3] = {n->x, n->y, n->z};
    for (int k = 0; k < 3; ++k) {
        if (c[k] < -e || c[k] > 1 + e) return -1;
    }
    for (int k = 0; k < 3; ++k) {
        int lo = fabs(c[k]) < e, hi = fabs(c[k] - 1) < e;
        if (!lo && !hi) continue;
        if (fabs(m[k] - (hi ? 1.0 : -1.0)) < 1e-12 && fabs(m[(k + 1) % 3]) < 1e-12 && fabs(m[(k + 2) % 3]) < 1e-12)
            return 2 * k + hi;
    }
    return -1;
}

static void test_cube(void)
{
    cdl_error err;
    cdl_patch patch = {0};
    patch.kind = CDL_PATCH_TRIANGLES;
    patch.max_edge = 0.3;
    patch.xyz = cube_xyz;
    patch.vertex_count = 8;
    patch.triangles = cube_tri;
    patch.triangle_count = 12;
    light l = {0, {1.3, 0.2, 0.5}};
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(), lit, &l};
    q.settings.min_edge = 0.01;
    cdl_surface_mesh m;
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(stats.mesh_as_given == 0 && stats.rounds > 2);
    /* Each vertex lies on a face of the cube and carries that face's
     * normal, the three vertices of a triangle the same face; the cube's
     * area is 6 (held edges keep its corners and edges). */
    size_t off_face = 0, mixed = 0;
    int faces_seen = 0;
    for (size_t t = 0; t < m.triangle_count; ++t) {
        int f[3];
        for (int k = 0; k < 3; ++k) {
            cdl_vec3 n = fx_normal(&m, m.triangles[3 * t + k]);
            f[k] = cube_face(fx_vertex(&m, m.triangles[3 * t + k]), &n);
            off_face += f[k] < 0;
        }
        mixed += f[0] != f[1] || f[1] != f[2];
        if (f[0] >= 0) faces_seen |= 1 << f[0];
    }
    CHECK(off_face == 0 && mixed == 0 && faces_seen == 63);
    CHECK_REL(m.area, 6.0, 1e-12);
    /* A corner is one point of the surface, in three regions: three vertices. */
    size_t at_corner = 0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) at_corner += cdl_vec3_length(fx_vertex(&m, v)) == 0.0;
    CHECK(at_corner == 3);
    /* Refined on the face the lamp is near (x = 1, 0.3 m away) more than on
     * the face it cannot see (x = 0). */
    size_t near = 0, far = 0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) {
        near += m.normal[3 * v] > 0.5;
        far += m.normal[3 * v] < -0.5;
    }
    CHECK_MSG(near > 10 * far, "%zu vertices facing the lamp, %zu facing away", near, far);
    cdl_surface_mesh_release(&m);

    /* Non-manifold: three triangles on one edge. CGAL refuses to remesh it;
     * it is refined as given, and every vertex stays on its triangle's plane. */
    const double fin_xyz[] = {0, 0, 0, 0, 0, 1, 1, 0, 0, -1, 0, 0, 0, 1, 0};
    const uint32_t fin_tri[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    cdl_trimesh remeshed;
    CHECK(cdl_remesh_triangles(fin_xyz, 5, fin_tri, 3, 0.3, 40.0, &remeshed, &err) == CDL_ERR_INPUT &&
          strstr(err.message, "manifold"));
    patch.xyz = fin_xyz;
    patch.vertex_count = 5;
    patch.triangles = fin_tri;
    patch.triangle_count = 3;
    l.position = cdl_vec3_make(0.3, 0.3, 0.4);
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(stats.mesh_as_given == 1 && stats.rounds > 0);
    CHECK_REL(m.area, 1.5, 1e-12);
    cdl_surface_mesh_release(&m);
}

int main(void)
{
    test_sphere(0);
    test_sphere(1);
    test_cube();
    return check_finish();
}
