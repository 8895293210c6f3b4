/* Surface meshes are watertight where planar patches meet (surface_mesh.h,
 * "Watertight"): a closed room's six faces, refined near a lamp in one
 * corner, and a doorstep outside it whose edge runs along part of the
 * room's floor edge. Every outline edge of a patch is matched, coordinate
 * for coordinate, by an edge of each patch that shares that stretch of
 * outline, and no patch's outline vertex lies inside another's outline
 * edge (a T-junction, where a crack would open). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "solver/geometry/key_table.h"
#include "surface_mesh_fixture.h"

/* The room's frame in the world: turned 30 degrees about z, then moved. */
static cdl_vec3 world(cdl_vec3 p)
{
    double c = cos(CDL_PI / 6.0), s = sin(CDL_PI / 6.0);
    return cdl_vec3_make(0.3 + c * p.x - s * p.y, -1.7 + s * p.x + c * p.y, 0.1 + p.z);
}

static cdl_vec3 room(const double *w)
{
    double c = cos(CDL_PI / 6.0), s = sin(CDL_PI / 6.0), x = w[0] - 0.3, y = w[1] + 1.7;
    return cdl_vec3_make(c * x + s * y, -s * x + c * y, w[2] - 0.1);
}

/* An isotropic point source of 1000 cd near the room's corner (0, 0, h):
 * E = I cos(theta) / d^2 on the side the normal faces. */
static cdl_vec3 lamp;

static cdl_status point_light(void *user, const cdl_field_probe *probes, size_t count, double *value, double *sigma,
                              double *noise, double *aux, cdl_error *err)
{
    (void)aux;
    (void)noise;
    (void)user;
    (void)err;
    for (size_t i = 0; i < count; ++i) {
        cdl_vec3 d = cdl_vec3_sub(lamp, probes[i].position);
        double r = cdl_vec3_length(d);
        double c = cdl_vec3_dot(d, probes[i].normal) / r;
        value[i] = c > 0.0 ? 1000.0 * c / (r * r) : 0.0;
        sigma[i] = 0.0;
    }
    return CDL_OK;
}

/* One outline edge of a patch: its end points in a canonical order. */
typedef struct segment {
    double p[6];
    size_t mesh;
} segment;

static int compare_segments(const void *a, const void *b)
{
    return memcmp(((const segment *)a)->p, ((const segment *)b)->p, sizeof ((const segment *)a)->p);
}

/* The edges used by one triangle of their mesh. (Patches of one surface
 * have their own vertices, so a box face's outline is its own.) */
static size_t outline_segments(const cdl_surface_mesh *m, size_t mesh, segment *out)
{
    cdl_key_table uses = {0};
    cdl_error err;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            uint64_t key = cdl_key_pair(m->triangles[3 * t + k], m->triangles[3 * t + (k + 1) % 3]);
            size_t n = cdl_key_table_find(&uses, key);
            cdl_key_table_put(&uses, key, n == CDL_KEY_TABLE_NONE ? 1 : n + 1, &err);
        }
    size_t count = 0;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = m->triangles[3 * t + k], b = m->triangles[3 * t + (k + 1) % 3];
            if (cdl_key_table_find(&uses, cdl_key_pair(a, b)) != 1) continue;
            const double *pa = &m->xyz[3 * a], *pb = &m->xyz[3 * b];
            if (memcmp(pa, pb, 3 * sizeof *pa) > 0) {
                const double *swap = pa;
                pa = pb;
                pb = swap;
            }
            memcpy(out[count].p, pa, 3 * sizeof *pa);
            memcpy(out[count].p + 3, pb, 3 * sizeof *pb);
            out[count++].mesh = mesh;
        }
    cdl_key_table_release(&uses);
    return count;
}

/* How many patches' outlines cover the point in the middle of segment s:
 * the room's faces meeting at a box edge (2), and on the stretch x = 4,
 * 1 <= y <= 2, z = 0 the doorstep as well (3). */
static int patches_along(const segment *s)
{
    double mid[3] = {0.5 * (s->p[0] + s->p[3]), 0.5 * (s->p[1] + s->p[4]), 0.5 * (s->p[2] + s->p[5])};
    cdl_vec3 r = room(mid);
    double x = r.x, y = r.y, z = r.z;
    const double e = 1e-9;
    int on_box_edge = (fabs(x) < e || fabs(x - 4) < e) + (fabs(y) < e || fabs(y - 3) < e) +
                      (fabs(z) < e || fabs(z - 2.5) < e) >= 2;
    int on_step = fabs(z) < e && x >= 4 - e && x <= 6 + e && y >= 1 - e && y <= 2 + e;
    int step_edge_on_room = on_step && fabs(x - 4) < e;
    if (step_edge_on_room) return 3;
    if (on_box_edge) return 2;
    return on_step ? 1 : 0;
}

/* Distance from p to the segment ab, and where along it (0..1). */
static double along(const double *p, const double *a, const double *b, double *t)
{
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    *t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / len2;
    double q[3] = {a[0] + *t * d[0] - p[0], a[1] + *t * d[1] - p[1], a[2] + *t * d[2] - p[2]};
    return sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}

int main(void)
{
    cdl_error err;
    const double h = 2.5;
    /* The room's faces, counter-clockwise seen from inside. */
    cdl_vec3 faces[6][4] = {
        {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}},  /* floor, +z */
        {{0, 0, h}, {0, 3, h}, {4, 3, h}, {4, 0, h}},  /* ceiling, -z */
        {{0, 0, 0}, {0, 0, h}, {4, 0, h}, {4, 0, 0}},  /* y = 0, +y */
        {{0, 3, 0}, {4, 3, 0}, {4, 3, h}, {0, 3, h}},  /* y = 3, -y */
        {{0, 0, 0}, {0, 3, 0}, {0, 3, h}, {0, 0, h}},  /* x = 0, +x */
        {{4, 0, 0}, {4, 0, h}, {4, 3, h}, {4, 3, 0}},  /* x = 4, -x */
    };
    cdl_vec3 step[4] = {{4, 1, 0}, {6, 1, 0}, {6, 2, 0}, {4, 2, 0}};
    for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 4; ++k) faces[f][k] = world(faces[f][k]);
    for (int k = 0; k < 4; ++k) step[k] = world(step[k]);
    lamp = world(cdl_vec3_make(0.4, 0.5, 2.2));
    cdl_patch patches[7];
    memset(patches, 0, sizeof patches);
    for (int f = 0; f < 7; ++f) {
        patches[f].kind = CDL_PATCH_POLYGON;
        patches[f].surface = f < 6 ? 0 : 1;
        patches[f].max_edge = 0.8;
        patches[f].outer = (cdl_ring3){f < 6 ? faces[f] : step, 4};
    }
    cdl_surface_mesh_request q = {patches, 7, 2,
                                  {.rel_tol = 0.01, .floor_fraction = 0.5, .min_edge = 0.01, .join_tolerance = 1e-9,
                                   .feature_angle_deg = 40.0, .max_vertices = 1000000},
                                  point_light, NULL};
    cdl_surface_mesh m[2];
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, m, &stats, &err), &err);
    CHECK(stats.rounds > 3 && stats.joined > 0);
    CHECK_REL(m[0].area, 2 * (4 * 3 + 4 * h + 3 * h), 1e-12);
    CHECK_REL(m[1].area, 2.0, 1e-12);

    /* Points inserted into outlines off their line by a rounding leave no
     * triangle turned over: each faces the side its vertices' normal says. */
    size_t flipped = 0;
    for (int s = 0; s < 2; ++s)
        for (size_t t = 0; t < m[s].triangle_count; ++t)
            flipped += !(cdl_vec3_dot(fx_area_vector(&m[s], t), fx_normal(&m[s], m[s].triangles[3 * t])) > 0.0);
    CHECK(flipped == 0);

    size_t capacity = 3 * (m[0].triangle_count + m[1].triangle_count);
    segment *seg = malloc(capacity * sizeof *seg);
    size_t n = outline_segments(&m[0], 0, seg);
    n += outline_segments(&m[1], 1, seg + n);
    qsort(seg, n, sizeof *seg, compare_segments);

    /* Each outline edge appears once for every patch along that stretch:
     * the same coordinates, bit for bit. */
    size_t wrong = 0, on_shared = 0;
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && !compare_segments(&seg[i], &seg[j])) ++j;
        int expected = patches_along(&seg[i]);
        if ((int)(j - i) != (expected ? expected : 1)) {
            if (wrong < 5)
                fprintf(stderr, "edge (%g %g %g)-(%g %g %g): %zu copies, %d patches along it\n", seg[i].p[0],
                        seg[i].p[1], seg[i].p[2], seg[i].p[3], seg[i].p[4], seg[i].p[5], j - i, expected);
            ++wrong;
        }
        on_shared += expected >= 2;
        i = j;
    }
    CHECK_MSG(wrong == 0, "%zu outline edges not matched", wrong);
    CHECK(on_shared > 12);

    /* No T-junction: no outline vertex of any patch strictly inside another outline edge. */
    size_t t_junctions = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            for (int end = 0; end < 2; ++end) {
                double t;
                const double *p = seg[j].p + 3 * end;
                if (along(p, seg[i].p, seg[i].p + 3, &t) < 1e-9 && t > 1e-9 && t < 1 - 1e-9) ++t_junctions;
            }
    CHECK_MSG(t_junctions == 0, "%zu outline vertices inside other outline edges", t_junctions);

    /* The box's faces are one surface whose vertices carry their own face's
     * normal: a corner vertex appears three times. */
    size_t at_corner = 0;
    for (uint32_t v = 0; v < m[0].vertex_count; ++v)
        at_corner += cdl_vec3_distance(fx_vertex(&m[0], v), world(cdl_vec3_make(0, 0, h))) < 1e-9;
    CHECK(at_corner == 3);
    free(seg);
    cdl_surface_mesh_release(&m[0]);
    cdl_surface_mesh_release(&m[1]);
    return check_finish();
}
