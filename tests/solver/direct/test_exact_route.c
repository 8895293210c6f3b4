/* The exact route: area emitters and uniform skies seen past a few planar
 * occluders are L times the projected solid angle of the visible polygon
 * (solver/direct/direct_exact_route.c). Every expected value here is a
 * closed form of the visible rectangle, computed independently of the
 * route: the parallel-rectangle configuration factor (Hottel; Howell's
 * catalogue, case B-3) for the well and the roof opening, Lambert's contour
 * integral of the one visible rectangle for the window and the wall.
 *
 * Tolerances: the route sums Lambert's formula over convex pieces cut from
 * the faces in double precision, so it agrees with a closed form to about
 * 1e-14 relative; 1e-9 leaves room for the cut points' rounding and is
 * still a million times below any preset's target.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/direct/exact_forms.h"
#include "solver/solve_internal.h"

static const char *const presets[4] = {"draft", "normal", "high", "reference"};
static const cdl_quality qualities[4] = {CDL_QUALITY_DRAFT, CDL_QUALITY_NORMAL, CDL_QUALITY_HIGH, CDL_QUALITY_REFERENCE};

/* Load a scene (from `json`, or else from data/daylight/`file` at
 * `quality`) and solve it on 2 threads; 0 (and CHECK failed) if either
 * step fails, with nothing left to release. */
static int load_solve(const char *json, const char *file, cdl_quality quality, int no_exact_route, cdl_scene **scene,
                      cdl_solution *sol)
{
    cdl_error err;
    cdl_error_clear(&err);
    char path[1024];
    snprintf(path, sizeof path, "%s/data/daylight/%s", CANDELA_SOURCE_DIR, file ? file : "");
    cdl_status st = json ? cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/exact_route.json", scene, &err)
                         : cdl_scene_load(path, scene, &err);
    if (st == CDL_OK) {
        if (!json) (*scene)->settings.quality = quality;
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        o.threads = 2;
        cdl_solve_debug dbg = CDL_SOLVE_DEBUG_NONE;
        dbg.no_exact_route = no_exact_route;
        st = cdl_solve_scene_into(*scene, &o, &dbg, sol, &err);
        if (st != CDL_OK) cdl_scene_release(*scene);
    }
    CHECK_MSG(st == CDL_OK, "%s", err.message);
    return st == CDL_OK;
}

static int solve(const char *json, cdl_scene **scene, cdl_solution *sol, int no_exact_route)
{
    return load_solve(json, NULL, CDL_QUALITY_NORMAL, no_exact_route, scene, sol);
}

static int solve_file(const char *file, cdl_quality quality, cdl_scene **scene, cdl_solution *sol)
{
    return load_solve(NULL, file, quality, 0, scene, sol);
}

static void done(cdl_scene *scene, cdl_solution *sol)
{
    cdl_solution_clear(sol);
    cdl_scene_release(scene);
}

static size_t count_sampled_points(const cdl_grid_solution *g)
{
    size_t k = 0;
    for (size_t i = 0; i < g->grid.count; ++i) k += g->E_stderr[i] != 0.0;
    return k;
}

/* Every point of a grid against pi L F of a rectangular opening
 * [x1, x2] x [y1, y2] at height z above points of a horizontal grid. */
static void check_opening(const cdl_grid_solution *g, double L, double x1, double x2, double y1, double y2, double z,
                          const char *what)
{
    for (size_t i = 0; i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double expected = CDL_PI * L * cf_parallel_rect(x1 - p.x, x2 - p.x, y1 - p.y, y2 - p.y, z - p.z);
        CHECK_MSG(fabs(g->E[i] - expected) <= 1e-9 * expected, "%s: point %zu: E = %.15g, expected %.15g", what, i,
                  g->E[i], expected);
        CHECK_MSG(g->E_stderr[i] == 0.0, "%s: point %zu stderr %g", what, i, g->E_stderr[i]);
    }
}

/* A black light well (data/daylight/light_well.json): a 1 x 1 x 3 m shaft,
 * open at the top, under a uniform sky of 5000 cd/m2. A floor point sees
 * the sky through the opening only: E = pi L F, F the parallel rectangle's
 * factor from the point, at every preset. */
static void test_black_well(void)
{
    for (int q = 0; q < 4; ++q) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_file("light_well.json", qualities[q], &scene, &sol)) return;
        check_opening(&sol.grids[0], 5000.0, 0.0, 1.0, 0.0, 1.0, 3.0, presets[q]);
        CHECK_MSG(strstr(sol.plan_json, "exact: visible polygon past up to 8 occluders at 100 points") != NULL,
                  "plan: %s", sol.plan_json);
        done(scene, &sol);
    }
}

/* Shallow and deep 2 x 2 m wells under a uniform sky, 25 x 25 floor points
 * each: every cell centre, so that many points lie on a diagonal through a
 * corner of the well ((1.08, 0.92) sees the corner (0, 2) at 45 degrees).
 * There a wall's corner projects onto a side of the pyramid through a face
 * of the sky's cube and came out of the clip twice; the repeated vertex made
 * an edge of no direction that dropped the whole face (E 10 % low, stated
 * exact). Each point against pi L F of the opening. */
static void test_well_diagonals(void)
{
    static const double depths[] = {0.4, 1.0, 3.0};
    for (int d = 0; d < 3; ++d) {
        char json[1024], what[64];
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [2, 2, %g],"
                 " \"inward\": true, \"open\": [\"+z\"], \"reflectance\": 0}],"
                 " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 2000, \"hemisphere\": \"upper\"}],"
                 " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [2, 0, 0],"
                 " \"v\": [0, 2, 0], \"nu\": 25, \"nv\": 25}], \"solver\": {\"method\": \"direct\"}}",
                 depths[d]);
        snprintf(what, sizeof what, "well %g m deep", depths[d]);
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve(json, &scene, &sol, 0)) return;
        check_opening(&sol.grids[0], 2000.0, 0.0, 2.0, 0.0, 2.0, depths[d], what);
        done(scene, &sol);
    }
}

/* A 20 x 20 x 4 m room whose roof (a polygon at z = 4) has a 2 x 2 m opening:
 * a work-plane point at 0.8 m sees the sky through it alone, E = pi L F of
 * the opening, also for points whose foot lies outside the opening (signed
 * corners). */
static void test_roof_opening(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [20, 20, 4],"
        " \"inward\": true, \"reflectance\": 0, \"open\": [\"+z\"]},"
        " {\"type\": \"polygon\", \"vertices\": [[0, 0, 4], [20, 0, 4], [20, 20, 4], [0, 20, 4]],"
        " \"holes\": [[[9, 9, 4], [11, 9, 4], [11, 11, 4], [9, 11, 4]]], \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 5000, \"hemisphere\": \"upper\"}],"
        " \"grids\": [{\"name\": \"wp\", \"type\": \"rect\", \"origin\": [0, 0, 0.8], \"u\": [20, 0, 0],"
        " \"v\": [0, 20, 0], \"nu\": 8, \"nv\": 8}],"
        " \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol, 0)) return;
    check_opening(&sol.grids[0], 5000.0, 9.0, 11.0, 9.0, 11.0, 4.0, "roof");
    done(scene, &sol);
}

/* The window room of the issue (data/daylight/window_room.json): 5 x 4 x 3 m, the +x side a facade with a
 * 2 x 1.2 m window (sill 0.9 m), a uniform 5000 cd/m2 sky; each work-plane
 * point gets L Omega_p of the window rectangle, at every preset, and the
 * uniformity U0 = min / mean is the exact one (within 1 %; in fact to
 * rounding). */
static void test_window_room(void)
{
    for (int q = 0; q < 4; ++q) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_file("window_room.json", qualities[q], &scene, &sol)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        double min = INFINITY, sum = 0.0, min_x = INFINITY, sum_x = 0.0, worst = 0.0;
        for (size_t i = 0; i < g->grid.count; ++i) {
            double expected = window_room_exact(g->grid.points[i], g->grid.normals[i]);
            worst = fmax(worst, fabs(g->E[i] - expected) / expected);
            CHECK(g->E_stderr[i] == 0.0);
            min = fmin(min, g->E[i]);
            sum += g->E[i];
            min_x = fmin(min_x, expected);
            sum_x += expected;
        }
        CHECK_MSG(worst <= 1e-9, "%s: worst relative error %g", presets[q], worst);
        double U0 = min / (sum / g->grid.count), U0_x = min_x / (sum_x / g->grid.count);
        CHECK_REL(U0, U0_x, 0.01);
        CHECK_MSG(strstr(sol.plan_json, "exact: visible polygon past") != NULL, "plan: %s", sol.plan_json);
        CHECK(strstr(sol.plan_json, "sampled:") == NULL);
        done(scene, &sol);
    }
}

/* A luminous wall (x = 0, 4 x 3 m, facing +x) behind a partition at x = 1
 * covering y >= 2 (and far beyond the wall's height): from p = (3, y, 1)
 * facing the wall, the partition's edge projects to y' = 3 - y / 2, so the
 * visible part is the rectangle [0, y'] x [0, 3]. From y = 8 nothing is
 * visible: E = 0 with stderr 0, which only the exact route can prove (the
 * sampler must state an error there). */
static const char *partition_scene =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [0, 4, 0],"
    " \"v\": [0, 0, 3], \"luminance_cd_m2\": 1000, \"reflectance\": 0},"
    " {\"type\": \"rect\", \"origin\": [1, 2, -10], \"u\": [0, 8, 0], \"v\": [0, 0, 20], \"reflectance\": 0}%s],"
    " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [3, 0.5, 1], \"n\": [-1, 0, 0]},"
    " {\"p\": [3, 1, 1], \"n\": [-1, 0, 0]}, {\"p\": [3, 1.5, 1], \"n\": [-1, 0, 0]},"
    " {\"p\": [3, 8, 1], \"n\": [-1, 0, 0]}]}],"
    " \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}";

static void test_wall_behind_partition(void)
{
    char json[2048];
    snprintf(json, sizeof json, partition_scene, "");
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol, 0)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < 3; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double cut = 3.0 - 0.5 * p.y;
        double expected = 1000.0 * psa_rect(p, g->grid.normals[i], cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, cut, 0),
                                            cdl_vec3_make(0, 0, 3));
        CHECK_REL(g->E[i], expected, 1e-9);
        CHECK(g->E_stderr[i] == 0.0);
    }
    CHECK_MSG(g->E[3] == 0.0 && g->E_stderr[3] == 0.0, "hidden point: E = %g +- %g", g->E[3], g->E_stderr[3]);
    done(scene, &sol);
    /* The same point sampled: dark in every sample, yet not certain. */
    if (!solve(json, &scene, &sol, 1)) return;
    g = &sol.grids[0];
    CHECK_MSG(g->E_stderr[3] > 0.0, "sampled hidden point: E = %g +- %g", g->E[3], g->E_stderr[3]);
    done(scene, &sol);
}

/* The sampler (exact route off) against the exact route, on the wall
 * behind the partition seen from a row of 40 points at "normal", so that
 * the sampler stays tested against exact answers:
 *  - unbiased: the sampled grid sum is within 3 of its stated sigmas
 *    (sqrt of the summed variances) of the exact sum;
 *  - per point, the issue asks for ~95 % within 2 stated sigma. Of 40
 *    calibrated points about 1.8 fall outside (Poisson-like, 40 x 0.046);
 *    7 or more do with probability 0.3 %, so at least 34 of 40 (85 %) are
 *    asked for here; the 95 % itself is checked over 404 points at two
 *    qualities in test_direct_calibration.c. (Before the pilot and the
 *    planned stage, 32 of 40 were within, one point 13 sigma off.)
 *  - every point sampled (a stated error above 0), the plan saying why. */
static void test_sampler_agrees(void)
{
    char points[4096] = "";
    size_t used = 0;
    for (int i = 0; i < 40; ++i)
        used += (size_t)snprintf(points + used, sizeof points - used, "%s{\"p\": [%g, %g, 1.3], \"n\": [-1, 0, 0]}",
                                 i ? ", " : "", 2.0 + 0.05 * (i % 8), 0.2 + 0.3 * (i / 8));
    char json[8192];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [0, 4, 0],"
             " \"v\": [0, 0, 3], \"luminance_cd_m2\": 1000, \"reflectance\": 0},"
             " {\"type\": \"rect\", \"origin\": [1, 2, -10], \"u\": [0, 8, 0], \"v\": [0, 0, 20], \"reflectance\": 0}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [%s]}],"
             " \"solver\": {\"method\": \"direct\", \"quality\": \"normal\"}}",
             points);
    cdl_scene *scene;
    cdl_solution sampled, exact;
    if (!solve(json, &scene, &sampled, 1)) return;
    cdl_scene_release(scene);
    if (!solve(json, &scene, &exact, 0)) {
        cdl_solution_clear(&sampled);
        return;
    }
    const cdl_grid_solution *g = &sampled.grids[0], *x = &exact.grids[0];
    size_t within = 0;
    double sum_s = 0.0, sum_x = 0.0, var = 0.0;
    for (size_t i = 0; i < g->grid.count; ++i) {
        within += fabs(g->E[i] - x->E[i]) <= 2.0 * g->E_stderr[i];
        sum_s += g->E[i];
        sum_x += x->E[i];
        var += g->E_stderr[i] * g->E_stderr[i];
        CHECK(x->E_stderr[i] == 0.0);
    }
    CHECK_MSG(fabs(sum_s - sum_x) <= 3.0 * sqrt(var), "sum %g, exact %g, sigma %g", sum_s, sum_x, sqrt(var));
    CHECK_MSG(within >= (size_t)(0.85 * g->grid.count), "%zu of %zu within 2 sigma", within, g->grid.count);
    CHECK_MSG(count_sampled_points(g) == g->grid.count, "the sampler was not used at every point");
    CHECK_MSG(strstr(sampled.plan_json, "sampled: exact route turned off") != NULL, "plan: %s", sampled.plan_json);
    printf("sampler behind the partition (normal): %zu of %zu points within 2 sigma\n", within, g->grid.count);
    cdl_solution_clear(&sampled);
    done(scene, &exact);
}

/* A sphere between the points and the wall: no polygon describes what it
 * hides, so the route is refused and the light sampled (the plan says so). */
static void test_sphere_still_samples(void)
{
    char json[2048];
    snprintf(json, sizeof json, partition_scene,
             ", {\"type\": \"sphere\", \"center\": [2, 1, 1], \"radius\": 0.2, \"reflectance\": 0}");
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol, 0)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK_MSG(g->E_stderr[1] > 0.0, "behind the sphere: E = %g +- %g", g->E[1], g->E_stderr[1]);
    CHECK_MSG(strstr(sol.plan_json, "sampled: curved occluder") != NULL, "plan: %s", sol.plan_json);
    done(scene, &sol);
}

int main(void)
{
    test_black_well();
    test_roof_opening();
    test_well_diagonals();
    test_window_room();
    test_sampler_agrees();
    test_wall_behind_partition();
    test_sphere_still_samples();
    return check_finish();
}
