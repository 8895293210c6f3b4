/* Surface meshes of planar patches refined to a field (surface_mesh.h):
 * coarse where the field is even, dense in a spot's penumbra, the linear
 * interpolant within the tolerance, the stated interpolation error, the
 * flux a spot puts on a wall, the angle bound, holes, and determinism. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "solver/geometry/mesh2d.h"
#include "solver/geometry/polygon.h"
#include "surface_mesh_fixture.h"

/* ---- fields -------------------------------------------------------------------------- */

/* A spot (DESIGN.md): I0 inside falloff_start, none beyond half_angle, the
 * smoothstep 3t^2 - 2t^3 of t = (cos a - cos half) / (cos falloff - cos
 * half) between; E = I cos(theta) / d^2 on the receiving plane. */
typedef struct spot_light {
    cdl_vec3 position, axis;
    double I0, half_deg, falloff_deg;
} spot_light;

static double smoothstep(double t)
{
    t = fmax(0.0, fmin(1.0, t));
    return t * t * (3.0 - 2.0 * t);
}

static double spot_E(const spot_light *s, cdl_vec3 p, cdl_vec3 n)
{
    cdl_vec3 d = cdl_vec3_sub(p, s->position);
    double r = cdl_vec3_length(d);
    cdl_vec3 w = cdl_vec3_scale(d, 1.0 / r);
    double c1 = cos(s->half_deg * CDL_DEG_TO_RAD), c0 = cos(s->falloff_deg * CDL_DEG_TO_RAD);
    double I = s->I0 * smoothstep((cdl_vec3_dot(w, s->axis) - c1) / (c0 - c1));
    double cos_in = -cdl_vec3_dot(w, n);
    return cos_in > 0.0 ? I * cos_in / (r * r) : 0.0;
}

/* pbrt's spot normaliser: flux 2 pi I0 [(1 - cos falloff) + (cos falloff -
 * cos half) / 2], the smoothstep integrating to 1/2 over [0, 1]. */
static double spot_flux(const spot_light *s)
{
    double c1 = cos(s->half_deg * CDL_DEG_TO_RAD), c0 = cos(s->falloff_deg * CDL_DEG_TO_RAD);
    return 2.0 * CDL_PI * s->I0 * ((1.0 - c0) + 0.5 * (c0 - c1));
}

typedef enum field_kind { FIELD_UNIFORM, FIELD_SPOT, FIELD_QUADRATIC, FIELD_NAN } field_kind;

typedef struct field_ctx {
    field_kind kind;
    spot_light spot;
    size_t calls, probes;
} field_ctx;

static cdl_status field(void *user, const cdl_field_probe *probes, size_t count, double *value, double *sigma,
                        double *noise, double *aux, cdl_error *err)
{
    (void)err;
    (void)noise;
    field_ctx *f = user;
    ++f->calls;
    f->probes += count;
    for (size_t i = 0; i < count; ++i) {
        cdl_vec3 p = probes[i].position;
        switch (f->kind) {
        case FIELD_UNIFORM: value[i] = 200.0; break;
        case FIELD_SPOT: value[i] = spot_E(&f->spot, p, probes[i].normal); break;
        case FIELD_QUADRATIC: value[i] = 100.0 + 50.0 * p.x * p.x + 30.0 * p.x * p.z - 20.0 * p.z * p.z; break;
        case FIELD_NAN: value[i] = i == count / 2 ? NAN : 1.0; break;
        }
        sigma[i] = 0.0;
        /* Two more channels when asked: a half and a double of the value. */
        if (aux) aux[2 * i] = 0.5 * value[i], aux[2 * i + 1] = 2.0 * value[i];
    }
    return CDL_OK;
}

static cdl_surface_mesh_settings settings(double rel_tol, double min_edge)
{
    cdl_surface_mesh_settings s = {.rel_tol = rel_tol,
                                   .floor_fraction = 0.5,
                                   .min_edge = min_edge,
                                   .join_tolerance = 1e-9,
                                   .feature_angle_deg = 40.0,
                                   .max_vertices = 1000000};
    return s;
}

/* A 4 x 3 m wall in the plane y = 0 facing -y, lit by a spot 2 m in front
 * of it aimed at (2, 0, 1.5): falloff 15 deg, half angle 20 deg, so its
 * penumbra on the wall is the ring 2 tan 15 = 0.536 m <= r <= 2 tan 20 =
 * 0.728 m about the aim point, and the whole beam lands on the wall. */
static cdl_vec3 wall_corners[4] = {{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
static const cdl_vec3 aim = {2, 0, 1.5};

static cdl_patch wall_patch(void)
{
    cdl_patch p = {0};
    p.kind = CDL_PATCH_POLYGON;
    p.max_edge = 0.7;
    p.outer.points = wall_corners;
    p.outer.count = 4;
    return p;
}

static field_ctx spot_field(void)
{
    field_ctx f = {FIELD_SPOT, {{2, -2, 1.5}, {0, 1, 0}, 5000.0, 20.0, 15.0}, 0, 0};
    return f;
}

/* ---- a uniform field keeps the first mesh ------------------------------------------------- */

static size_t vertices_beyond(const cdl_surface_mesh *m, double r_min)
{
    size_t n = 0;
    for (uint32_t v = 0; v < m->vertex_count; ++v) n += cdl_vec3_distance(fx_vertex(m, v), aim) > r_min;
    return n;
}

static void test_uniform(cdl_surface_mesh *uniform)
{
    cdl_error err;
    cdl_patch patch = wall_patch();
    field_ctx f = {.kind = FIELD_UNIFORM};
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(0.005, 0.002), field, &f};
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, uniform, &stats, &err), &err);
    CHECK(stats.rounds == 0);
    /* The first mesh is Delaunay refinement's of the rect at max_edge. */
    const double xy[8] = {0, 0, 4, 0, 4, 3, 0, 3};
    cdl_cdt2d *cdt;
    CHECK_OK(cdl_cdt2d_create((cdl_ring2d){xy, 4}, NULL, 0, 0.7, SIZE_MAX, &cdt, &err), &err);
    CHECK_MSG(uniform->vertex_count == cdl_cdt2d_vertex_count(cdt), "%zu vertices, Delaunay refinement %zu",
              uniform->vertex_count, cdl_cdt2d_vertex_count(cdt));
    cdl_cdt2d_release(cdt);
    CHECK(fx_max_edge(uniform) <= 0.7 + 1e-12);
    /* One round: the vertices and every edge's midpoint, in one call. */
    size_t edges = uniform->vertex_count + uniform->triangle_count - 1; /* Euler, a disk */
    CHECK(f.calls == 1 && f.probes == uniform->vertex_count + edges);
    CHECK_REL(uniform->area, 12.0, 1e-12);
    for (uint32_t v = 0; v < uniform->vertex_count; ++v) CHECK(uniform->interpolation[v] == 0.0);
}

/* ---- a spot: dense in its penumbra, coarse elsewhere ---------------------------------------- */

static void test_spot(const cdl_surface_mesh *uniform)
{
    cdl_error err;
    cdl_patch patch = wall_patch();
    field_ctx f = spot_field();
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(0.005, 0.001), field, &f};
    cdl_surface_mesh m;
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(stats.unresolved == 0 && !stats.budget_reached);
    CHECK(stats.evaluations == f.probes);

    /* Vertices per square metre: the penumbra ring against the wall beyond
     * 1.1 m from the aim point (0.37 m outside the beam), where the light is
     * zero as on the uniform wall. */
    double r0 = 2.0 * tan(15.0 * CDL_DEG_TO_RAD), r1 = 2.0 * tan(20.0 * CDL_DEG_TO_RAD);
    size_t ring = 0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) {
        double r = cdl_vec3_distance(fx_vertex(&m, v), aim);
        ring += r >= r0 && r <= r1;
    }
    double ring_density = ring / (CDL_PI * (r1 * r1 - r0 * r0));
    double outside_density = vertices_beyond(&m, 1.1) / (12.0 - CDL_PI * 1.1 * 1.1);
    double uniform_density = vertices_beyond(uniform, 1.1) / (12.0 - CDL_PI * 1.1 * 1.1);
    /* Measured: 25 000 per m^2 in the ring, 8.2 outside it, 6.8 on the
     * uniformly lit wall (the grading from the ring adds a few). */
    CHECK_MSG(ring_density > 1000.0 * outside_density, "ring %g per m^2, outside %g", ring_density, outside_density);
    CHECK_MSG(outside_density < 1.5 * uniform_density, "outside %g per m^2, uniform wall %g", outside_density,
              uniform_density);

    /* The interpolant at points inside every triangle against the field:
     * within 1.5 times the tolerance max(0.005 E, floor) everywhere (4/3 is
     * the bound where the field is quadratic over a triangle, surface_mesh.h;
     * the rest is its higher-order terms), and within two stated
     * interpolation errors of its triangle's vertices at nearly all. */
    double Em = fx_integral(&m) / m.area, floor = 0.005 * 0.5 * Em;
    uint64_t rng = 7;
    size_t samples = 0, over_bound = 0, over_stated = 0;
    double worst = 0.0;
    for (size_t t = 0; t < m.triangle_count; ++t) {
        const uint32_t *v = &m.triangles[3 * t];
        double stated = fmax(m.interpolation[v[0]], fmax(m.interpolation[v[1]], m.interpolation[v[2]]));
        for (int j = 0; j < 4; ++j) {
            double s = fx_uniform(&rng), u = fx_uniform(&rng), interpolated;
            if (s + u > 1.0) {
                s = 1.0 - s;
                u = 1.0 - u;
            }
            cdl_vec3 p = fx_point(&m, t, s, u, &interpolated);
            double e = fabs(interpolated - spot_E(&f.spot, p, cdl_vec3_make(0, -1, 0)));
            double tol = fmax(0.005 * fabs(spot_E(&f.spot, p, cdl_vec3_make(0, -1, 0))), floor);
            worst = fmax(worst, e / tol);
            over_bound += e > 1.5 * tol;
            over_stated += e > 2.0 * stated + 1e-12;
            ++samples;
        }
    }
    CHECK_MSG(over_bound == 0, "%zu of %zu points beyond 1.5 tolerances (worst %.3g)", over_bound, samples, worst);
    /* Measured: 58 of 330 000 points (the largest of a vertex's triangles
     * is stated, so it errs on the safe side). */
    CHECK_MSG(over_stated < samples / 1000, "%zu of %zu points beyond 2 stated interpolation errors", over_stated,
              samples);

    /* The light the wall receives is the spot's flux (the whole beam lands
     * on it): the interpolant's integral within the tolerance. */
    CHECK_REL(fx_integral(&m), spot_flux(&f.spot), 0.005);
    cdl_surface_mesh_release(&m);
}

/* ---- the stated interpolation error is exact for a quadratic field ---------------------------- */

static void test_quadratic_triangle(void)
{
    cdl_error err;
    /* One triangle no refinement touches (tolerance 100 %): every vertex
     * states that triangle's rms interpolation error. */
    cdl_vec3 corners[3] = {{0.2, 0, 0.1}, {1.4, 0, 0.3}, {0.5, 0, 1.2}};
    cdl_patch patch = {0};
    patch.kind = CDL_PATCH_POLYGON;
    patch.max_edge = 10.0;
    patch.outer.points = corners;
    patch.outer.count = 3;
    field_ctx f = {.kind = FIELD_QUADRATIC};
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(1.0, 0.001), field, &f};
    cdl_surface_mesh m;
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(m.vertex_count == 3 && m.triangle_count == 1);
    if (m.triangle_count == 1) {
        /* The rms of (field - interpolant) over the triangle by the midpoint
         * rule on 400^2 sub-triangles (a quartic integrand: error ~1e-5). */
        const int n = 400;
        double sum = 0.0, weight = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j)
                for (int up = 0; up < (i + j < n - 1 ? 2 : 1); ++up) {
                    double s = up ? (i + 2.0 / 3.0) / n : (i + 1.0 / 3.0) / n;
                    double u = up ? (j + 2.0 / 3.0) / n : (j + 1.0 / 3.0) / n;
                    double interpolated;
                    cdl_vec3 p = fx_point(&m, 0, s, u, &interpolated);
                    double exact = 100.0 + 50.0 * p.x * p.x + 30.0 * p.x * p.z - 20.0 * p.z * p.z;
                    sum += (exact - interpolated) * (exact - interpolated);
                    weight += 1.0;
                }
        double rms = sqrt(sum / weight);
        for (uint32_t v = 0; v < 3; ++v) CHECK_REL(m.interpolation[v], rms, 1e-4);
    }
    cdl_surface_mesh_release(&m);
}

/* ---- holes, a tilted plane, the angle bound, orientation --------------------------------------- */

/* Points of an L-shaped outline with a square hole, in plane coordinates
 * (x, y), placed on a plane tilted about x by 30 degrees. */
static cdl_vec3 tilted(double x, double y)
{
    double c = cos(30.0 * CDL_DEG_TO_RAD), s = sin(30.0 * CDL_DEG_TO_RAD);
    return cdl_vec3_make(1.0 + x, 2.0 + c * y, 0.5 + s * y);
}

static void test_holes(void)
{
    cdl_error err;
    const double outline[6][2] = {{0, 0}, {5, 0}, {5, 2}, {2, 2}, {2, 4}, {0, 4}};
    const double square[4][2] = {{0.5, 0.5}, {0.5, 1.5}, {1.5, 1.5}, {1.5, 0.5}};
    cdl_vec3 outer_points[6], hole_points[4];
    for (int i = 0; i < 6; ++i) outer_points[i] = tilted(outline[i][0], outline[i][1]);
    for (int i = 0; i < 4; ++i) hole_points[i] = tilted(square[i][0], square[i][1]);
    cdl_ring3 hole = {hole_points, 4};
    cdl_patch patch = {0};
    patch.kind = CDL_PATCH_POLYGON;
    patch.max_edge = 0.8;
    patch.outer = (cdl_ring3){outer_points, 6};
    patch.holes = &hole;
    patch.hole_count = 1;
    /* A spot above the plane, aimed at its inner corner. */
    cdl_vec3 normal = cdl_vec3_make(0, -sin(30.0 * CDL_DEG_TO_RAD), cos(30.0 * CDL_DEG_TO_RAD));
    field_ctx f = spot_field();
    f.spot.position = cdl_vec3_madd(tilted(2.2, 2.2), 1.5, normal);
    f.spot.axis = cdl_vec3_neg(normal);
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(0.005, 0.003), field, &f};
    cdl_surface_mesh m;
    cdl_surface_mesh_stats stats;
    CHECK_OK(cdl_surface_mesh_build(&q, &m, &stats, &err), &err);
    CHECK(stats.rounds > 3);

    cdl_polygon_plane plane;
    cdl_polygon_problem problem;
    CHECK(cdl_polygon_check(&patch.outer, &hole, 1, &plane, &problem));
    /* Every vertex on the plane (to rounding of the lift) and its normal the plane's. */
    double off_plane = 0.0, normal_error = 0.0;
    for (uint32_t v = 0; v < m.vertex_count; ++v) {
        off_plane = fmax(off_plane, fabs(cdl_vec3_dot(cdl_vec3_sub(fx_vertex(&m, v), outer_points[0]), normal)));
        normal_error = fmax(normal_error, cdl_vec3_distance(fx_normal(&m, v), normal));
    }
    CHECK_MSG(off_plane < 1e-14, "a vertex %g m off the plane", off_plane);
    CHECK(normal_error < 1e-14);
    /* Every triangle inside the outline and outside the hole (its centroid,
     * in plane coordinates), counter-clockwise seen from the front, and the
     * triangles tile the polygon: area 5 x 2 + 2 x 2 - 1. */
    size_t outside = 0, clockwise = 0;
    for (size_t t = 0; t < m.triangle_count; ++t) {
        const uint32_t *v = &m.triangles[3 * t];
        cdl_vec3 c = cdl_vec3_scale(cdl_vec3_add(cdl_vec3_add(fx_vertex(&m, v[0]), fx_vertex(&m, v[1])), fx_vertex(&m, v[2])),
                                    1.0 / 3.0);
        double x, y;
        cdl_polygon_project(&plane, c, &x, &y);
        double X = cdl_vec3_dot(cdl_vec3_sub(c, tilted(0, 0)), cdl_vec3_make(1, 0, 0));
        double Y = cdl_vec3_dot(cdl_vec3_sub(c, tilted(0, 0)),
                                cdl_vec3_make(0, cos(30.0 * CDL_DEG_TO_RAD), sin(30.0 * CDL_DEG_TO_RAD)));
        int in_l = X > 0 && Y > 0 && ((X < 5 && Y < 2) || (X < 2 && Y < 4));
        int in_hole = X > 0.5 && X < 1.5 && Y > 0.5 && Y < 1.5;
        outside += !in_l || in_hole;
        clockwise += !(cdl_vec3_dot(fx_area_vector(&m, t), normal) > 0.0);
    }
    CHECK(outside == 0 && clockwise == 0);
    CHECK_REL(m.area, 13.0, 1e-12);
    /* No sliver: Delaunay refinement's angle bound (the outline's corners
     * are 90 and 270 degrees, none sharper). */
    CHECK_MSG(fx_min_angle_deg(&m) >= CDL_MESH2D_MIN_ANGLE_DEG - 1e-9, "smallest angle %.6g deg",
              fx_min_angle_deg(&m));
    cdl_surface_mesh_release(&m);
}

/* ---- seeds, determinism, the budget, errors --------------------------------------------------- */

static int same_mesh(const cdl_surface_mesh *a, const cdl_surface_mesh *b)
{
    return a->vertex_count == b->vertex_count && a->triangle_count == b->triangle_count &&
           !memcmp(a->xyz, b->xyz, 3 * a->vertex_count * sizeof *a->xyz) &&
           !memcmp(a->value, b->value, a->vertex_count * sizeof *a->value) &&
           !memcmp(a->interpolation, b->interpolation, a->vertex_count * sizeof *a->interpolation) &&
           !memcmp(a->triangles, b->triangles, 3 * a->triangle_count * sizeof *a->triangles);
}

static void test_seeds_budget_determinism(void)
{
    cdl_error err;
    cdl_patch patch = wall_patch();
    cdl_vec3 seed = cdl_vec3_make(2.0, 0.0, 1.5), far_off = cdl_vec3_make(9.0, 0.0, 1.0);
    cdl_vec3 seeds[2] = {seed, far_off};
    patch.seeds = seeds;
    patch.seed_count = 2;
    field_ctx f = spot_field();
    cdl_surface_mesh_request q = {&patch, 1, 1, settings(0.005, 0.004), field, &f};
    cdl_surface_mesh a, b;
    cdl_surface_mesh_stats sa, sb;
    CHECK_OK(cdl_surface_mesh_build(&q, &a, &sa, &err), &err);
    CHECK_OK(cdl_surface_mesh_build(&q, &b, &sb, &err), &err);
    CHECK(same_mesh(&a, &b));
    CHECK(a.aux == NULL);
    cdl_surface_mesh_release(&b);
    /* Channels beside the field reach every vertex, inherited ones too. */
    q.settings.aux_channels = 2;
    CHECK_OK(cdl_surface_mesh_build(&q, &b, &sb, &err), &err);
    CHECK(same_mesh(&a, &b) && b.aux != NULL);
    size_t wrong = 0;
    for (size_t v = 0; b.aux && v < b.vertex_count; ++v)
        wrong += b.aux[2 * v] != 0.5 * b.value[v] || b.aux[2 * v + 1] != 2.0 * b.value[v] || b.patch[v] != 0;
    CHECK(wrong == 0);
    q.settings.aux_channels = 0;
    size_t at_seed = 0;
    for (uint32_t v = 0; v < a.vertex_count; ++v) at_seed += cdl_vec3_distance(fx_vertex(&a, v), seed) < 1e-12;
    CHECK(at_seed == 1);
    cdl_surface_mesh_release(&a);
    cdl_surface_mesh_release(&b);

    /* A budget of 2000 vertices stops refinement within it. */
    q.settings.max_vertices = 2000;
    CHECK_OK(cdl_surface_mesh_build(&q, &a, &sa, &err), &err);
    CHECK(sa.budget_reached && a.vertex_count <= 2000);
    cdl_surface_mesh_release(&a);

    /* Settings out of range, a surface number out of range, a field giving NaN. */
    q.settings = settings(0.0, 0.004);
    CHECK(cdl_surface_mesh_build(&q, &a, &sa, &err) == CDL_ERR_INPUT && a.xyz == NULL);
    q.settings = settings(0.005, 0.004);
    patch.surface = 1;
    CHECK(cdl_surface_mesh_build(&q, &a, &sa, &err) == CDL_ERR_INPUT);
    patch.surface = 0;
    f.kind = FIELD_NAN;
    CHECK(cdl_surface_mesh_build(&q, &a, &sa, &err) == CDL_ERR_INTERNAL && strstr(err.message, "no finite value"));
    CHECK(a.xyz == NULL);
}

int main(void)
{
    cdl_surface_mesh uniform;
    test_uniform(&uniform);
    test_spot(&uniform);
    cdl_surface_mesh_release(&uniform);
    test_quadratic_triangle();
    test_holes();
    test_seeds_budget_determinism();
    return check_finish();
}
