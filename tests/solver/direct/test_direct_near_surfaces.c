/* Rays that never miss a nearby surface, at every scale: 1 km
 * ground planes with walls 1 cm to 0.1 mm from a point, a 1 mm gap between
 * a table and a wall, a scene 1e5 m from the origin, and points exactly on
 * a room's floor-wall corner line. Every expected value is a closed form: a
 * uniform sky of luminance L seen through openings gives
 * E = L x (projected solid angle of what is open), Lambert's polygon formula
 * (lights/emitters/projected_solid_angle.h).
 *
 * Sampled terms (a sky partly hidden) are solved to target_error 1e-3; the
 * tolerance is 4 stated standard errors (a false failure is a 6e-5 event
 * for a normal error, and the run is deterministic), and the stated error
 * must itself be below 2 x target x E, so the check cannot pass vacuously.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "radiometry/vec3.h"
#include "solver/scene/scene_internal.h"
#include "solver/solve_internal.h"

#define L_SKY 1000.0
#define TARGET 1e-3

/* Solve a scene (one thread) and copy E and its standard error for the n
 * points of grid 0; the edge-point count into *edges when not NULL. The
 * exact route through planar occluders is turned off: these tests are of
 * the rays (shadow rays resolve a 1 mm gap in a 1 km scene). */
static int solve_points(const char *json, double *E, double *se, size_t n, size_t *edges)
{
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK_OK(cdl_scene_load_string(json, "near.json", &scene, &err), &err);
    if (!scene) return 0;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    so.threads = 1;
    cdl_solve_debug dbg = CDL_SOLVE_DEBUG_NONE;
    dbg.no_exact_route = 1;
    cdl_solution sol;
    cdl_status st = cdl_solve_scene_into(scene, &so, &dbg, &sol, &err);
    CHECK_OK(st, &err);
    int ok = st == CDL_OK && sol.grids[0].grid.count == n;
    CHECK(ok);
    if (ok) {
        for (size_t i = 0; i < n; ++i) {
            E[i] = sol.grids[0].E[i];
            se[i] = sol.grids[0].E_stderr[i];
        }
        if (edges) *edges = sol.grids[0].edge_point_count;
    }
    if (st == CDL_OK) cdl_solution_clear(&sol);
    cdl_scene_release(scene);
    return ok;
}

/* |projected solid angle| of the rect origin + s u + t v seen from p with normal n. */
static double rect_psa(cdl_vec3 p, cdl_vec3 n, cdl_vec3 origin, cdl_vec3 u, cdl_vec3 v)
{
    cdl_vec3 o = cdl_vec3_sub(origin, p);
    cdl_vec3 c[4] = {o, cdl_vec3_add(o, u), cdl_vec3_add(cdl_vec3_add(o, u), v), cdl_vec3_add(o, v)};
    return fabs(cdl_projected_solid_angle_polygon(c, 4, n));
}

static void check_sampled(double E, double se, double expected, const char *what)
{
    CHECK_MSG(se <= 2.0 * TARGET * expected, "%s: stated error %g lx for %g lx", what, se, expected);
    CHECK_MSG(fabs(E - expected) <= 4.0 * se + 1e-9 * expected, "%s: E = %.9g lx, expected %.9g lx (+- 4 x %.3g)",
              what, E, expected, se);
}

#define SKY "{\"type\": \"environment\", \"luminance_cd_m2\": 1000, \"hemisphere\": \"upper\"}"
#define SOLVER "\"solver\": {\"method\": \"direct\", \"target_error\": 0.001}"
/* 1 km floor (z = 0) and wall (x = 0), black and opaque, both centred on the y axis. */
#define FLOOR "{\"type\": \"rect\", \"origin\": [-500,-500,0], \"u\": [1000,0,0], \"v\": [0,1000,0], \"reflectance\": 0}"
#define WALL_X "{\"type\": \"rect\", \"origin\": [0,-500,0], \"u\": [0,1000,0], \"v\": [0,0,1000], \"reflectance\": 0}"
#define WALL_Y "{\"type\": \"rect\", \"origin\": [-500,0,0], \"u\": [1000,0,0], \"v\": [0,0,1000], \"reflectance\": 0}"

/* Floor and wall: a floor point at distance d from the wall's foot sees the
 * sky except the wall, E = L (pi - Omega_p(wall)); for d -> 0 that is one
 * half of pi L, less the sky over the wall's edges 500 m away (the finite
 * planes' exact value, from Lambert's formula). The old scene-sized ray
 * epsilon (2.5 cm here) let the wall through: 62 % high at 1 cm. */
static void test_floor_and_wall(void)
{
    const double d[3] = {1e-2, 1e-3, 1e-4};
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [" FLOOR ", " WALL_X "], \"luminaires\": [" SKY "], \"grids\": [{\"name\": "
             "\"g\", \"type\": \"points\", \"points\": [{\"p\": [%.17g,0,0], \"n\": [0,0,1]}, {\"p\": [%.17g,0,0], "
             "\"n\": [0,0,1]}, {\"p\": [%.17g,0,0], \"n\": [0,0,1]}]}], " SOLVER "}",
             d[0], d[1], d[2]);
    double E[3], se[3];
    size_t edges = 99;
    if (!solve_points(json, E, se, 3, &edges)) return;
    for (int i = 0; i < 3; ++i) {
        cdl_vec3 p = cdl_vec3_make(d[i], 0, 0), up = cdl_vec3_make(0, 0, 1);
        double wall = rect_psa(p, up, cdl_vec3_make(0, -500, 0), cdl_vec3_make(0, 1000, 0), cdl_vec3_make(0, 0, 1000));
        double expected = L_SKY * (CDL_PI - wall);
        /* the finite planes differ from the half-plane value by ~ d / 500 m and by the sky over the wall's edges */
        CHECK_MSG(fabs(expected / (0.5 * CDL_PI * L_SKY) - 1.0) < 2e-3, "closed form %g", expected);
        char what[64];
        snprintf(what, sizeof what, "floor point %g m from the wall", d[i]);
        check_sampled(E[i], se[i], expected, what);
    }
    /* 0.1 mm is over 3 float ulps (3.05e-5 m) of Embree's 500 m coordinates,
     * beyond the float resolution (direct_grid.c): resolved, no edge point. */
    CHECK_MSG(edges == 0, "edge points: %zu", edges);
}

/* Floor and two walls crossing at the z axis: a floor point at (d, d, 0)
 * sees the sky of its quadrant; the walls hide the rest, the half-walls
 * x = 0, y in [0, 500] and y = 0, x in [0, 500] tiling what it sees of them
 * (a ray to one never crosses the other: their projections are disjoint).
 * E = L (pi - Omega_p(half-wall 1) - Omega_p(half-wall 2)), about a
 * quarter of pi L. */
static void test_floor_and_two_walls(void)
{
    const double d[3] = {1e-2, 1e-3, 1e-4};
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [" FLOOR ", " WALL_X ", " WALL_Y "], \"luminaires\": [" SKY "], \"grids\": "
             "[{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [%.17g,%.17g,0], \"n\": [0,0,1]}, "
             "{\"p\": [%.17g,%.17g,0], \"n\": [0,0,1]}, {\"p\": [%.17g,%.17g,0], \"n\": [0,0,1]}]}], " SOLVER "}",
             d[0], d[0], d[1], d[1], d[2], d[2]);
    double E[3], se[3];
    if (!solve_points(json, E, se, 3, NULL)) return;
    for (int i = 0; i < 3; ++i) {
        cdl_vec3 p = cdl_vec3_make(d[i], d[i], 0), up = cdl_vec3_make(0, 0, 1);
        double w1 = rect_psa(p, up, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 500, 0), cdl_vec3_make(0, 0, 1000));
        double w2 = rect_psa(p, up, cdl_vec3_make(0, 0, 0), cdl_vec3_make(500, 0, 0), cdl_vec3_make(0, 0, 1000));
        double expected = L_SKY * (CDL_PI - w1 - w2);
        CHECK_MSG(fabs(expected / (0.25 * CDL_PI * L_SKY) - 1.0) < 4e-3, "closed form %g", expected);
        char what[64];
        snprintf(what, sizeof what, "corner point %g m from both walls", d[i]);
        check_sampled(E[i], se[i], expected, what);
    }
}

/* A table top 2 mm above a point, covering the 1 km floor but for a 1 mm
 * gap along the wall (x in [0, 1 mm]). The point, 0.5 mm from the wall,
 * sees the sky only through the part of the slit on its far side from the
 * wall (rays through the near part go on into the wall) and, at grazing
 * elevations, past the table's far edges 500 m away (the 2 mm-high side
 * openings at y = +-500 and x = 500): E = L x the sum of those projected
 * solid angles, about 0.12 pi L. With the table against the wall, no gap:
 * only the side openings are left (below 1e-9 pi L). */
static void test_table_gap(void)
{
    const double h = 0.75, z = 0.748, px = 5e-4;
    char json[2048];
    const char *table_x[2] = {"0.001", "0"};
    double E[2][1], se[2][1];
    for (int k = 0; k < 2; ++k) {
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"surfaces\": [" FLOOR ", " WALL_X ", {\"type\": \"rect\", \"origin\": [%s,-500,0.75], "
                 "\"u\": [0,1000,0], \"v\": [%.17g,0,0], \"reflectance\": 0}], \"luminaires\": [" SKY "], \"grids\": "
                 "[{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [%.17g,0,%.17g], \"n\": [0,0,1]}]}], "
                 SOLVER "}",
                 table_x[k], 500.0 - (k == 0 ? 0.001 : 0.0), px, z);
        if (!solve_points(json, E[k], se[k], 1, NULL)) return;
    }
    cdl_vec3 p = cdl_vec3_make(px, 0, z), up = cdl_vec3_make(0, 0, 1);
    double sides = rect_psa(p, up, cdl_vec3_make(px, 500, z), cdl_vec3_make(500 - px, 0, 0), cdl_vec3_make(0, 0, h - z)) +
                   rect_psa(p, up, cdl_vec3_make(px, -500, z), cdl_vec3_make(500 - px, 0, 0), cdl_vec3_make(0, 0, h - z)) +
                   rect_psa(p, up, cdl_vec3_make(500, -500, z), cdl_vec3_make(0, 1000, 0), cdl_vec3_make(0, 0, h - z));
    double slit = rect_psa(p, up, cdl_vec3_make(px, -500, h), cdl_vec3_make(0.001 - px, 0, 0), cdl_vec3_make(0, 1000, 0));
    double expected = L_SKY * (slit + sides);
    CHECK_MSG(slit > 0.1 * CDL_PI && sides < 1e-9 * CDL_PI, "slit %g, sides %g", slit, sides);
    check_sampled(E[0][0], se[0][0], expected, "under the table, 1 mm gap");
    /* no gap: what is left is the side openings, within the stated error */
    CHECK_MSG(fabs(E[1][0] - L_SKY * sides) <= 4.0 * se[1][0] + 1e-6 * CDL_PI * L_SKY,
              "under the table, no gap: E = %g lx +- %g", E[1][0], se[1][0]);
}

/* The same scene at the origin and moved by 1e5 m on every axis: an open
 * room (black box, top open) under the sky, with a table, a tilted ramp
 * carrying grid points on its surface, a point light and an area light.
 * Positions at 1e5 m carry a rounding of 1.5e-11 m, which moves any
 * distance (the shortest here 0.1 m) by 1.5e-10 of itself; samples use the
 * same random numbers and see the same occluders. Agreement to 1e-8
 * (relative, or of the largest value) leaves a margin of 60; a point that
 * shadowed itself at 1e5 m (a ramp point hidden by its own ramp) would lose
 * its sky entirely. */
static void test_far_from_origin(void)
{
    const double offsets[2] = {0.0, 1e5};
    double E[2][6], se[2][6];
    for (int k = 0; k < 2; ++k) {
        double o = offsets[k];
        char json[4096];
        /* the ramp: origin (1, 3, 0), u = (2, 0, 1), v = (0, 1, 0); its normal u x v = (-1, 0, 2) / sqrt 5 */
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [%.17g,%.17g,%.17g], \"max\": "
                 "[%.17g,%.17g,%.17g], \"inward\": true, \"reflectance\": 0, \"open\": [\"+z\"]}, {\"type\": \"rect\", "
                 "\"origin\": [%.17g,%.17g,%.17g], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0}, {\"type\": "
                 "\"rect\", \"origin\": [%.17g,%.17g,%.17g], \"u\": [2,0,1], \"v\": [0,1,0], \"reflectance\": 0}], "
                 "\"luminaires\": [" SKY ", {\"type\": \"point\", \"position\": [%.17g,%.17g,%.17g], \"intensity_cd\": "
                 "500}, {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [%.17g,%.17g,%.17g], \"u\": "
                 "[0.5,0,0], \"v\": [0,-0.5,0]}, \"luminance_cd_m2\": 2000}], \"grids\": [{\"name\": \"g\", \"type\": "
                 "\"rect\", \"origin\": [%.17g,%.17g,%.17g], \"u\": [2,0,1], \"v\": [0,1,0], \"nu\": 3, \"nv\": 2}], "
                 SOLVER "}",
                 o, o, o, o + 4, o + 5, o + 3, o + 0.5, o + 0.5, o + 0.75, o + 1, o + 3, o, o + 2, o + 1, o + 2.5,
                 o + 2.5, o + 1.5, o + 2.9, o + 1, o + 3, o);
        if (!solve_points(json, E[k], se[k], 6, NULL)) return;
    }
    double largest = 0.0;
    for (int i = 0; i < 6; ++i) largest = fmax(largest, E[0][i]);
    for (int i = 0; i < 6; ++i) {
        CHECK_MSG(E[0][i] > 0.1 * largest, "point %d on the ramp is dark (%g lx of %g)", i, E[0][i], largest);
        CHECK_MSG(fabs(E[1][i] - E[0][i]) <= 1e-8 * largest, "point %d: %.12g lx at the origin, %.12g lx at 1e5 m", i,
                  E[0][i], E[1][i]);
        CHECK_MSG(fabs(se[1][i] - se[0][i]) <= 1e-6 * largest, "point %d: stated errors %g and %g", i, se[0][i],
                  se[1][i]);
    }
}

/* Points exactly on a room's edges: an open-topped black room 5 x 4 x 3 m
 * under the sky. A point inside sees the sky through the opening only, so
 * E(q) = L Omega_q(opening), continuous up to the walls from inside. Points
 * on the floor-wall corner line, in the floor's corner and on a wall at
 * work-plane height (a wall through them, n in its plane) are edge points:
 * each keeps its warning and reports that limit from inside the room,
 * not the sky seen through the wall it lies on. */
static void test_edge_points_limit(void)
{
    const cdl_vec3 pts[4] = {cdl_vec3_make(0, 2, 0), cdl_vec3_make(0, 0, 0), cdl_vec3_make(5, 1, 0.8),
                             cdl_vec3_make(2, 2, 0)};
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [5,4,3], \"inward\": true, "
             "\"reflectance\": 0, \"open\": [\"+z\"]}], \"luminaires\": [" SKY "], \"grids\": [{\"name\": \"g\", "
             "\"type\": \"points\", \"points\": [{\"p\": [0,2,0], \"n\": [0,0,1]}, {\"p\": [0,0,0], \"n\": [0,0,1]}, "
             "{\"p\": [5,1,0.8], \"n\": [0,0,1]}, {\"p\": [2,2,0], \"n\": [0,0,1]}]}], " SOLVER "}");
    double E[4], se[4];
    size_t edges = 0;
    if (!solve_points(json, E, se, 4, &edges)) return;
    CHECK_MSG(edges == 3, "edge points: %zu, expected 3", edges);
    for (int i = 0; i < 4; ++i) {
        double expected = L_SKY * rect_psa(pts[i], cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 3),
                                           cdl_vec3_make(5, 0, 0), cdl_vec3_make(0, 4, 0));
        char what[64];
        snprintf(what, sizeof what, "point %d of the room", i);
        /* moved 8 float resolutions (~2e-6 m) inside: E changes by ~1e-6 of itself */
        CHECK_MSG(se[i] <= 2.0 * TARGET * expected, "%s: stated error %g", what, se[i]);
        CHECK_MSG(fabs(E[i] - expected) <= 4.0 * se[i] + 1e-5 * expected, "%s: E = %.9g, expected %.9g (+- 4 x %.3g)",
                  what, E[i], expected, se[i]);
    }
}

int main(void)
{
    test_floor_and_wall();
    test_floor_and_two_walls();
    test_table_gap();
    test_far_from_origin();
    test_edge_points_limit();
    return check_finish();
}
