/* How honest the sampled direct light's stated errors are: with the exact
 * route turned off, every partly hidden sky or emitter is sampled to the
 * target, and each point's error is tallied in stated sigmas against a
 * closed form (exact_forms.h): a black light well and a roof opening under
 * a uniform sky (parallel-rectangle configuration factors), the window room
 * of data/daylight (Lambert's form of the window) and a luminous wall
 * behind a partition (Lambert's form of its visible rectangle), at
 * "draft", "normal" and "high".
 *
 * DESIGN.md asks for about 68 % of points within one stated sigma and 95 %
 * within two, no bias: calibration_check (solve_fixture.h) holds each
 * quality's tally to these within four binomial sigmas. The direct-light
 * issue asks for a stated sigma within a factor 1.5 of the target
 * wherever the cap of samples a light (CDL_DIRECT_MAX_SAMPLES) does not
 * bind, and the plan to say where it does. A stated sigma is itself an
 * estimate: at a fixed sample count, with no planning at all, it scatters
 * over seeds by 0.58-1.43 of its mean at 128 samples (a "draft" stage on
 * the partition: a few strata along the edge differ) and by 0.60-1.25 at
 * 1152, up to 5 % and 1 % of seeds beyond a factor 1.5; planned, about
 * 99 % of the points the cap did not hold were within a factor 1.5 at
 * "normal" and "high", 96 % at "draft" (93 % before a small pilot's plan
 * was held to 4 times its size: direct_extended.c, PLAN_REACH_SMALL). So
 * the points the cap did not hold are held, over the four scenes, to at
 * least 95 % within a factor 1.5 at every preset; each scene to 95 % at
 * "normal" and "high" (85 % at "draft", where the partition's stages are
 * 72 to 200 samples with one to five differing pairs), none beyond a
 * factor 2 (3 at "draft") but as many as the plan says the cap held; and
 * at "high" the well's every point held by the cap (it needs ~3.5e6
 * samples a point).
 */
// ctest-labels: slow
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/direct/exact_forms.h"
#include "solver/solve_fixture.h"

/* The sky of the well and the roof scene (cd/m2), and the wall's luminance. */
#define SKY_L 5000.0
#define WALL_L 1000.0

typedef double (*exact_fn)(cdl_vec3 p, cdl_vec3 n);

/* How a scene's stated sigmas sit against the target: points within a
 * factor 1.5 of it either way, points beyond the factor `wide`, and the
 * points whose stage the cap held (the plan's count). */
typedef struct band {
    size_t count, within, beyond, capped;
    double wide;
} band;

/* The well (data/daylight/light_well.json): a 1 x 1 x 3 m black shaft open
 * at the top; a floor point sees pi L F of the opening. */
static double well_exact(cdl_vec3 p, cdl_vec3 n)
{
    (void)n;
    return CDL_PI * SKY_L * cf_parallel_rect(-p.x, 1.0 - p.x, -p.y, 1.0 - p.y, 3.0 - p.z);
}

/* The roof scene below: a 2 x 2 m opening [9, 11]^2 at z = 4. */
static double roof_exact(cdl_vec3 p, cdl_vec3 n)
{
    (void)n;
    return CDL_PI * SKY_L * cf_parallel_rect(9.0 - p.x, 11.0 - p.x, 9.0 - p.y, 11.0 - p.y, 4.0 - p.z);
}

static double window_exact(cdl_vec3 p, cdl_vec3 n)
{
    return window_room_exact(p, n);
}

/* The wall x = 0 (y in [0, 4], z in [0, 3]) behind a partition at x = 1
 * covering y >= 2: from p the partition's edge projects onto the wall at
 * y' = p.y + (2 - p.y) p.x / (p.x - 1) (similar triangles), so the visible
 * part is [0, y'] x [0, 3] (y' < 4 for the points below). */
static double partition_exact(cdl_vec3 p, cdl_vec3 n)
{
    double cut = p.y + (2.0 - p.y) * p.x / (p.x - 1.0);
    return WALL_L * psa_rect(p, n, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, cut, 0), cdl_vec3_make(0, 0, 3));
}

static const char *roof_scene =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [20, 20, 4],"
    " \"inward\": true, \"reflectance\": 0, \"open\": [\"+z\"]},"
    " {\"type\": \"polygon\", \"vertices\": [[0, 0, 4], [20, 0, 4], [20, 20, 4], [0, 20, 4]],"
    " \"holes\": [[[9, 9, 4], [11, 9, 4], [11, 11, 4], [9, 11, 4]]], \"reflectance\": 0}],"
    " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 5000, \"hemisphere\": \"upper\"}],"
    " \"grids\": [{\"name\": \"wp\", \"type\": \"rect\", \"origin\": [4, 4, 0.8], \"u\": [12, 0, 0],"
    " \"v\": [0, 12, 0], \"nu\": 8, \"nv\": 8}],"
    " \"solver\": {\"method\": \"direct\", \"quality\": \"%s\"}}";

/* 48 points facing the wall, 2 to 2.35 m from it, 0.2 to 1.6 m along it. */
static void partition_scene(char *json, size_t size, const char *quality)
{
    char points[8192] = "";
    size_t used = 0;
    for (int i = 0; i < 48; ++i)
        used += (size_t)snprintf(points + used, sizeof points - used, "%s{\"p\": [%g, %g, 1.3], \"n\": [-1, 0, 0]}",
                                 i ? ", " : "", 2.0 + 0.05 * (i % 8), 0.2 + 0.28 * (i / 8));
    snprintf(json, size,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [0, 4, 0],"
             " \"v\": [0, 0, 3], \"luminance_cd_m2\": %g, \"reflectance\": 0},"
             " {\"type\": \"rect\", \"origin\": [1, 2, -10], \"u\": [0, 8, 0], \"v\": [0, 0, 20], \"reflectance\": 0}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [%s]}],"
             " \"solver\": {\"method\": \"direct\", \"quality\": \"%s\"}}",
             WALL_L, points, quality);
}

/* Solve `json` (or data/daylight/`file`) at `quality` with the route off
 * and tally every point against `exact`, into `all` and `scene_tally`,
 * and its sigma against the target into `b`. */
static void tally_scene(const char *json, const char *file, cdl_quality quality, exact_fn exact, calibration *all,
                        calibration *scene_tally, band *b)
{
    char path[1024];
    cdl_scene *scene = NULL;
    cdl_solution sol;
    cdl_error err;
    cdl_error_clear(&err);
    if (file) {
        snprintf(path, sizeof path, "%s/data/daylight/%s", CANDELA_SOURCE_DIR, file);
        if (cdl_scene_load(path, &scene, &err) != CDL_OK) {
            CHECK_MSG(0, "%s", err.message);
            return;
        }
        scene->settings.quality = quality;
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        o.threads = 2;
        cdl_solve_debug dbg = CDL_SOLVE_DEBUG_NONE;
        dbg.no_exact_route = 1;
        if (cdl_solve_scene_into(scene, &o, &dbg, &sol, &err) != CDL_OK) {
            CHECK_MSG(0, "%s", err.message);
            cdl_scene_release(scene);
            return;
        }
    } else if (!fixture_solve_route(json, &scene, &sol, 2, 1)) {
        return;
    }
    double target = cdl_quality_target_error(quality);
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i) {
        double expected = exact(g->grid.points[i], g->grid.normals[i]);
        CHECK_MSG(g->E_stderr[i] > 0.0, "point %zu not sampled", i);
        calibration_add(all, g->E[i], expected, g->E_stderr[i], target);
        calibration_add(scene_tally, g->E[i], expected, g->E_stderr[i], target);
        double r = g->E_stderr[i] / (target * expected);
        b->count++;
        b->within += r <= 1.5 && r >= 1.0 / 1.5;
        b->beyond += r > b->wide || r < 1.0 / b->wide;
    }
    b->capped = fixture_capped_points(sol.plan_json);
    fixture_release(scene, &sol);
}

/* The scenes at one quality: calibration over all points, and each scene's
 * sigma against the target (at least `least_within` of the points the cap
 * did not hold within a factor 1.5, none beyond `wide` but as many as it
 * held). */
static void test_calibration(cdl_quality quality, const char *name, double least_within, double wide)
{
    calibration all = CALIBRATION_INIT;
    calibration tallies[4] = {CALIBRATION_INIT, CALIBRATION_INIT, CALIBRATION_INIT, CALIBRATION_INIT};
    band bands[4];
    for (int s = 0; s < 4; ++s) bands[s] = (band){0, 0, 0, 0, wide};
    char json[16384], label[64];
    tally_scene(NULL, "light_well.json", quality, well_exact, &all, &tallies[0], &bands[0]);
    snprintf(json, sizeof json, roof_scene, name);
    tally_scene(json, NULL, quality, roof_exact, &all, &tallies[1], &bands[1]);
    tally_scene(NULL, "window_room.json", quality, window_exact, &all, &tallies[2], &bands[2]);
    partition_scene(json, sizeof json, name);
    tally_scene(json, NULL, quality, partition_exact, &all, &tallies[3], &bands[3]);
    /* Calibration per scene printed for the record; the scenes' counts (48
     * to 192) are too small for the four-sigma bounds to say much one by
     * one. */
    const char *names[4] = {"well", "roof", "window", "partition"};
    size_t within_all = 0, free_all = 0;
    for (int s = 0; s < 4; ++s) {
        const calibration *c = &tallies[s];
        const band *b = &bands[s];
        printf("  %s %s: %zu points, %.1f %% within 1 sigma, %.1f %% within 2, mean %+.3f sigma; sigma / target "
               "%.2f .. %.2f, within a factor 1.5 at %zu, beyond %g at %zu, the cap held %zu\n",
               name, names[s], c->count, 100.0 * c->within1 / c->count, 100.0 * c->within2 / c->count,
               c->zsum / c->count, c->sigma_over_target_min, c->sigma_over_target_max, b->within, wide, b->beyond,
               b->capped);
        size_t free_points = b->count > b->capped ? b->count - b->capped : 0;
        free_all += free_points;
        within_all += b->within < free_points ? b->within : free_points;
        CHECK_MSG((double)b->within >= least_within * (double)free_points,
                  "%s %s: %zu of %zu points within a factor 1.5 of the target (the cap held %zu)", name, names[s],
                  b->within, b->count, b->capped);
        CHECK_MSG(b->beyond <= b->capped, "%s %s: %zu points beyond a factor %g of the target, the cap held %zu", name,
                  names[s], b->beyond, wide, b->capped);
    }
    printf("  %s: %zu of the %zu points the cap did not hold within a factor 1.5 of the target\n", name, within_all,
           free_all);
    CHECK_MSG((double)within_all >= 0.95 * (double)free_all,
              "%s: %zu of the %zu points the cap did not hold within a factor 1.5 of the target", name, within_all,
              free_all);
    if (quality == CDL_QUALITY_HIGH)
        CHECK_MSG(bands[0].capped == bands[0].count, "high: the cap held %zu of the well's %zu points",
                  bands[0].capped, bands[0].count);
    snprintf(label, sizeof label, "sampled direct light, %s", name);
    calibration_check(&all, label);
}

int main(void)
{
    test_calibration(CDL_QUALITY_DRAFT, "draft", 0.85, 3.0);
    test_calibration(CDL_QUALITY_NORMAL, "normal", 0.95, 2.0);
    test_calibration(CDL_QUALITY_HIGH, "high", 0.95, 2.0);
    return check_finish();
}
