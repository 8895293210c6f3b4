/* Near field in the solve: goniometric luminaires spread over their
 * luminous opening ("near_field" on the luminaire), against closed forms.
 *  - "auto": the opening where the point model could err by more than a
 *    quarter of the target (never within 5 opening sizes), the point
 *    beyond, and the plan says which per light and grid and at what
 *    distance; at every quality a Lambertian disk probed 3 m below on its
 *    axis is within the target of its closed form; "never" a point; a file without an
 *    opening a point whatever is asked, named in the plan and a warning.
 *  - A Lambertian table on a disk written as an ellipse (the cubature) at
 *    quality "high": every point against the disk's configuration factor.
 *  - Soft shadows: a Lambertian rectangle half hidden by a black plate,
 *    the penumbra against the contour integral of the visible part; a
 *    skewed table the same way against the integral of its visible part,
 *    sampled to quality "high", the stated errors calibrated.
 *  - A sphere of uniform luminance spread over its surface: E = I cos / d^2
 *    exactly wherever all of it is seen; the sphere-to-tilted-element
 *    factor where the horizon cuts it, sampled to "high", calibrated.
 *  - Interreflection lit by openings: the integrating sphere, by paths and
 *    by the irradiance cache.
 */
// ctest-timeout: 600
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ellipse_segment.h"
#include "file_fixture.h"
#include "polygon_factor.h"
#include "radiometry/constants.h"
#include "solver/solve_fixture.h"
#include "sphere_factor.h"

#define I0 1000.0

/* I = I0 cos(gamma) below the horizontal, dark above; with `skew`, times
 * (1 + skew sin(gamma) cos(C)): brighter towards C = 0. */
static double table_value(double skew, double C, double g)
{
    double r = g * CDL_DEG_TO_RAD;
    return g < 90.0 ? I0 * cos(r) * (1.0 + skew * sin(r) * cos(C * CDL_DEG_TO_RAD)) : 0.0;
}

/* An LM-63 file (version "2002" or "1995") with opening (W, L, 0) and the
 * table above at every degree of gamma (C every 15 degrees when skewed,
 * one plane otherwise), written to path. */
static int write_ies(const char *path, const char *version, double W, double L, double skew)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    int planes = skew != 0.0 ? 25 : 1;
    fprintf(f, "IESNA:LM-63-%s\n[TEST] near field\nTILT=NONE\n1 -1 1 181 %d 1 2 %.17g %.17g 0\n1 1 0\n", version,
            planes, W, L);
    for (int g = 0; g <= 180; ++g) fprintf(f, "%d ", g);
    fprintf(f, "\n");
    for (int c = 0; c < planes; ++c) fprintf(f, "%d ", 15 * c);
    fprintf(f, "\n");
    for (int c = 0; c < planes; ++c) {
        for (int g = 0; g <= 180; ++g) fprintf(f, "%.17g ", table_value(skew, 15.0 * c, g));
        fprintf(f, "\n");
    }
    return fclose(f) == 0;
}

static int write_lambert_ies(const char *path, const char *version, double W, double L)
{
    return write_ies(path, version, W, L, 0.0);
}

/* E on a plane parallel to a Lambertian disk (radius r, luminance L) at
 * depth h and lateral offset a: pi L F, F the configuration factor of a
 * parallel disk to a differential element (Siegel and Howell B-13). */
static double disk_E(double L, double r, double h, double a)
{
    double s = h * h + a * a + r * r;
    return CDL_PI * L * 0.5 * (1.0 - (h * h + a * a - r * r) / sqrt(s * s - 4.0 * a * a * r * r));
}

/* E at p facing up from the Lambertian axis-aligned rectangle [x0, x1] x
 * [y0, y1] at height z above p (facing down), luminance L: the contour
 * integral (L / 2) sum beta_i n.u_i (configuration factor of a polygon to a
 * differential element). */
static double rect_E(double L, double x0, double x1, double y0, double y1, double z, double px, double py)
{
    double v[4][3] = {{x0 - px, y0 - py, z}, {x1 - px, y0 - py, z}, {x1 - px, y1 - py, z}, {x0 - px, y1 - py, z}};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        const double *a = v[i], *b = v[(i + 1) % 4];
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        double beta = atan2(lc, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
        sum += beta * c[2] / lc;
    }
    return 0.5 * L * fabs(sum);
}

static char folder[512];

/* "auto", "never", "always" on a 1.2 x 0.3 m Lambertian rectangle 3 m up:
 * a probe 1 m below gets the rectangle's closed form under "auto" and
 * "always", the point's I0 / d^2 under "never"; a probe 400 m below the
 * point's under "auto" (at quality "high" the opening reaches about
 * 0.62 sqrt(K / 2.5e-4) m, 39 m for K = 1: near_field_bound.h). A file with
 * no opening stays a point under "always". The plan names the near-field
 * split. */
static void test_modes(void)
{
    char rect[600], none[600], json[4096];
    snprintf(rect, sizeof rect, "%s/rect.ies", folder);
    snprintf(none, sizeof none, "%s/none.ies", folder);
    CHECK(write_lambert_ies(rect, "2002", 0.3, 1.2));
    CHECK(write_lambert_ies(none, "2002", 0.0, 0.0));
    const char *modes[3] = {"auto", "always", "never"};
    double L = I0 / 0.36;
    double near_ext = rect_E(L, -0.6, 0.6, -0.15, 0.15, 1.0, 0.0, 0.0), near_pt = I0 / 1.0;
    /* the far probe 400 m below: the point's I0 / d^2 */
    double far_pt = I0 / (400.0 * 400.0);
    double far_ext = rect_E(L, -0.6, 0.6, -0.15, 0.15, 400.0, 0.0, 0.0);
    for (int m = 0; m < 3; ++m) {
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, "
                 "0, 3], \"near_field\": \"%s\"}, {\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [100, "
                 "0, 3], \"near_field\": \"always\"}],"
                 " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 2], \"n\": [0, 0, "
                 "1]}, {\"p\": [0, 0, -397], \"n\": [0, 0, 1]}, {\"p\": [100, 0, 2], \"n\": [0, 0, 1]}]}],"
                 " \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}",
                 rect, modes[m], none);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 1)) return;
        const double *E = sol.grids[0].E;
        /* Each probe also sees the other luminaire, as a point (the
         * opening-less file) or the rectangle as its mode says, at d^2 =
         * 10001 (probes 0 and 2) and 100^2 + 400^2 (probe 1): I0 cos^2 / d^2. */
        double d1 = 100.0 * 100.0 + 400.0 * 400.0;
        double none0 = I0 / (10001.0 * 10001.0), none1 = I0 * 400.0 * 400.0 / (d1 * d1);
        double rect2 = m == 1 ? rect_E(L, -0.6, 0.6, -0.15, 0.15, 1.0, 100.0, 0.0) : I0 / (10001.0 * 10001.0);
        CHECK_REL(E[0], (m == 2 ? near_pt : near_ext) + none0, 1e-9);
        /* the point model interpolates the table linearly in gamma: up to
         * (1 degree)^2 / 8 = 3.8e-5 below the cosine off the nadir; the
         * opening 400 m away is the cubature's, to its tolerance (1/50 of
         * the 0.1 % target) */
        CHECK_REL(E[1], (m == 1 ? far_ext : far_pt) + none1, m == 1 ? 2e-5 : 4e-5);
        CHECK_REL(E[2], I0 + rect2, 1e-9);
        const char *near_text = strstr(sol.plan_json, "spread over its luminous opening at 1 of 3 points");
        CHECK_MSG((m == 0) == (near_text != NULL), "mode %s: plan %s the near-field split", modes[m],
                  near_text ? "names" : "does not name");
        const char *always_text = strstr(sol.plan_json, "near field \\\"always\\\": spread over its luminous opening");
        CHECK_MSG((m == 1) == (always_text != NULL), "mode %s: plan %s the opening everywhere", modes[m],
                  always_text ? "names" : "does not name");
        /* the opening-less file asked for "always" stays a point, and says so */
        CHECK(strstr(sol.plan_json, "lit as a point") != NULL);
        int warned = 0;
        for (size_t w = 0; w < sol.warning_count; ++w)
            warned += strstr(sol.warnings[w], "luminaires[1]: near_field \"always\"") != NULL &&
                      strstr(sol.warnings[w], "no luminous opening") != NULL;
        CHECK_MSG(warned == 1, "mode %s: %d warnings that luminaires[1] stays a point", modes[m], warned);
        fixture_release(scene, &sol);
    }
    CHECK(near_ext < 0.95 * near_pt); /* the probe is truly in the near field */
}

/* The probe: a Lambertian disk 0.5 m across ("auto"), a receiver
 * 3 m below on its axis. Its closed form is pi L R^2 / (d^2 + R^2), the
 * point model's I0 / d^2, 0.69 % more. At every quality "auto" must be
 * within the target of the closed form; with the old rule (the point
 * beyond 5 opening sizes, 2.5 m) it read the point's value at "high" and
 * "normal". The plan says the distance used, beyond 3 m at "high". */
static void test_switch_by_target(void)
{
    char path[600], json[4096];
    snprintf(path, sizeof path, "%s/disk_switch.ies", folder);
    CHECK(write_lambert_ies(path, "2002", -0.5, -0.5));
    double R = 0.25, d = 3.0, L = I0 / (CDL_PI * R * R);
    double exact = CDL_PI * L * R * R / (d * d + R * R);
    CHECK(I0 / (d * d) > 1.006 * exact); /* the point model is truly off by more than the high target */
    const char *qualities[4] = {"draft", "normal", "high", "reference"};
    const double targets[4] = {0.02, 0.005, 0.001, 0.0002};
    for (int q = 0; q < 4; ++q) {
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, "
                 "0, 3]}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], "
                 "\"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"direct\", \"quality\": \"%s\"}}",
                 path, qualities[q]);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 1)) return;
        double E = sol.grids[0].E[0], se = sol.grids[0].E_stderr[0];
        /* within a quarter of the target (the share the switch allows) plus
         * the table's interpolation (3.8e-5) and the cubature's 1/50 */
        CHECK_MSG(fabs(E - exact) <= (0.25 * targets[q] + 4e-5 + targets[q] / 50.0) * exact + 2.0 * se,
                  "quality %s: %.9g +- %.3g lx, exact %.9g (point model %.9g)", qualities[q], E, se, exact,
                  I0 / (d * d));
        if (q >= 2)
            CHECK_MSG(strstr(sol.plan_json, "spread over its luminous opening at 1 of 1 points") != NULL,
                      "quality %s: the plan does not say the probe is in the near field", qualities[q]);
        fixture_release(scene, &sol);
    }
}

/* Closes the points array of a scene written into json[0..at) with a
 * direct solve at quality "high" and `seed`, and solves it on 2 threads. */
static int solve_points_high_route(char *json, size_t size, int at, int seed, cdl_scene **scene, cdl_solution *sol,
                                   int no_exact_route)
{
    snprintf(json + at, size - (size_t)at,
             "]}], \"solver\": {\"method\": \"direct\", \"quality\": \"high\", \"seed\": %d}}", seed);
    return fixture_solve_route(json, scene, sol, 2, no_exact_route);
}

static int solve_points_high(char *json, size_t size, int at, int seed, cdl_scene **scene, cdl_solution *sol)
{
    return solve_points_high_route(json, size, at, seed, scene, sol, 0);
}

/* The same disk (0.6 m) written with the 1995 ellipse code (no closed
 * form: the adaptive cubature) at quality "high", 64 probes from 2 cm to
 * 3 m below, on and off the axis: exact (no stated error) and within the
 * table's interpolation error of the disk's closed form (linear in gamma
 * between 1-degree samples: up to 3.8e-5 below the cosine) plus the
 * cubature's tolerance (1/50 of the 0.1 % target: 2e-5), or, where the
 * cubature declines (a few centimetres
 * from the opening), sampled within five stated sigmas. */
static void test_cubature(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/ellipse.ies", folder);
    CHECK(write_lambert_ies(path, "1995", -0.6, 0.6));
    const double depths[8] = {0.02, 0.06, 0.15, 0.3, 0.6, 1.0, 1.8, 3.0};
    const double lateral[8] = {0.0, 0.1, 0.2, 0.28, 0.33, 0.45, 0.8, 1.5};
    double L = I0 / (CDL_PI * 0.09);
    int at = snprintf(json, sizeof json,
                      "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", "
                      "\"position\": [0, 0, 3], \"near_field\": \"always\"}], \"grids\": [{\"name\": \"p\", "
                      "\"type\": \"points\", \"points\": [",
                      path);
    /* point i: depth i / 8, offset i % 8 */
    for (int i = 0; i < 64; ++i)
        at += snprintf(json + at, sizeof json - (size_t)at, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [0, 0, 1]}",
                       i ? ", " : "", 0.6 * lateral[i % 8], 0.8 * lateral[i % 8], 3.0 - depths[i / 8]);
    snprintf(json + at, sizeof json - (size_t)at, "]}], \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    int exact = 0;
    for (size_t i = 0; i < 64; ++i) {
        double want = disk_E(L, 0.3, depths[i / 8], lateral[i % 8]);
        exact += g->E_stderr[i] == 0.0;
        CHECK_MSG(fabs(g->E[i] - want) <= 5.0 * g->E_stderr[i] + 5.8e-5 * want, "depth %g offset %g: %.7g +- %.3g, expected %.7g",
                  depths[i / 8], lateral[i % 8], g->E[i], g->E_stderr[i], want);
    }
    CHECK(exact >= 56);
    fixture_release(scene, &sol);
}

/* E at the floor point (px, py, 0) from the skewed table on the 1.2 x
 * 0.3 m opening at height h (long side along x), counting only the
 * opening's part x_o < cut: the model's definition (1 / A) int I(w) cos /
 * r^2 dA, I as the table interpolates it, by the midpoint rule on 800 x
 * 200 cells of that part (halving the cells moved it by under 1e-6 at
 * these probes). */
static double skewed_visible_E(double px, double py, double h, double cut)
{
    int nx = 800, ny = 200;
    double x0 = -0.6, x1 = fmin(0.6, cut), sum = 0.0;
    if (!(x1 > x0)) return 0.0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            double x = x0 + (x1 - x0) * (i + 0.5) / nx, y = -0.15 + 0.3 * (j + 0.5) / ny;
            double dx = px - x, dy = py - y, r2 = dx * dx + dy * dy + h * h, r = sqrt(r2);
            double gamma = acos(h / r) * CDL_RAD_TO_DEG, C = atan2(dy, dx) * CDL_RAD_TO_DEG;
            if (C < 0.0) C += 360.0;
            /* the table's own bilinear interpolation between its samples
             * (whole degrees of gamma, C every 15 degrees) */
            double g0 = floor(gamma), t = gamma - g0, c0 = 15.0 * floor(C / 15.0), tc = (C - c0) / 15.0;
            double I = (1.0 - tc) * ((1.0 - t) * table_value(0.6, c0, g0) + t * table_value(0.6, c0, g0 + 1.0)) +
                       tc * ((1.0 - t) * table_value(0.6, c0 + 15.0, g0) + t * table_value(0.6, c0 + 15.0, g0 + 1.0));
            sum += I * (h / r) / r2;
        }
    return sum * (x1 - x0) * 0.3 / ((double)nx * ny) / 0.36;
}

/* Soft shadow of a table that is not Lambertian (skewed towards C = 0) on
 * the 1.2 x 0.3 m opening at 2.5 m, a black plate at 2 m over x >= 0: as
 * in test_soft_shadow the visible part is x_o < -px / 4. On the exact
 * route (the opening's visible part integrated by the cubature) every
 * probe is exact (no stated error) and within the cubature's tolerance
 * (1/50 of the 0.1 % target: 2e-5) plus the reference's 1e-6 of it, the route named in the plan; sampled (the
 * route turned off) to the target of quality "high" (0.1 %) across the
 * penumbra, each point within five stated sigmas of the reference, the
 * sigmas calibrated over 4 seeds. */
static void test_skewed_shadow(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/skewed.ies", folder);
    CHECK(write_ies(path, "2002", 0.3, 1.2, 0.6));
    double target = 1e-3;
    calibration tally = CALIBRATION_INIT;
    int n = 21;
    /* seed 0: the exact route; seeds 1 to 4: sampled */
    for (int seed = 0; seed <= 4; ++seed) {
        int at = snprintf(json, sizeof json,
                          "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, -6, 2], \"u\": [6, 0, "
                          "0], \"v\": [0, 12, 0], \"reflectance\": 0}], \"luminaires\": [{\"type\": \"goniometric\", "
                          "\"file\": \"%s\", \"position\": [0, 0, 2.5], \"near_field\": \"always\"}], \"grids\": "
                          "[{\"name\": \"p\", \"type\": \"points\", \"points\": [",
                          path);
        for (int k = 0; k < n; ++k)
            at += snprintf(json + at, sizeof json - (size_t)at, "%s{\"p\": [%.17g, 0, 0], \"n\": [0, 0, 1]}",
                           k ? ", " : "", -2.4 + 4.8 * k / (n - 1));
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_points_high_route(json, sizeof json, at, seed, &scene, &sol, seed > 0)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        double scale = skewed_visible_E(-2.4, 0.0, 2.5, 1.0); /* the opening in full view */
        for (int k = 0; k < n; ++k) {
            double px = -2.4 + 4.8 * k / (n - 1);
            double want = skewed_visible_E(px, 0.0, 2.5, -px / 4.0);
            if (seed == 0)
                CHECK_MSG(g->E_stderr[k] == 0.0 && fabs(g->E[k] - want) <= 2.1e-5 * want + 1e-8 * scale,
                          "skewed shadow probe %g, exact route: %.9g +- %.3g, expected %.9g", px, g->E[k],
                          g->E_stderr[k], want);
            CHECK_MSG(fabs(g->E[k] - want) <= 5.0 * g->E_stderr[k] + 2.1e-5 * want + 1e-8 * scale,
                      "skewed shadow probe %g: %.7g +- %.3g, expected %.7g", px, g->E[k], g->E_stderr[k], want);
            if (g->E_stderr[k] > 0.0 && want > 0.0) calibration_add(&tally, g->E[k], want, g->E_stderr[k], target);
        }
        if (seed == 0) CHECK(strstr(sol.plan_json, "exact: visible polygon past up to 1 occluders") != NULL);
        fixture_release(scene, &sol);
    }
    CHECK(tally.count >= 40);
    calibration_check(&tally, "penumbra of a skewed opening, quality high");
}

/* The plate scene of the soft-shadow tests: the opening of the file at
 * `path` 2.5 m up ("always" spread), a black plate at 2 m over x >= 0,
 * and two rows of floor probes (x from -x_end to x_end in n steps, y 0
 * and y_step), at target 0.2 % and `seed`; the JSON into json[size]. */
static void plate_scene(char *json, size_t size, const char *path, int n, double x_end, double y_step, int seed)
{
    int at = snprintf(json, size,
                      "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, -6, 2], \"u\": [6, 0, 0], "
                      "\"v\": [0, 12, 0], \"reflectance\": 0}], \"luminaires\": [{\"type\": \"goniometric\", \"file\": "
                      "\"%s\", \"position\": [0, 0, 2.5], \"near_field\": \"always\"}], \"grids\": [{\"name\": \"p\", "
                      "\"type\": \"points\", \"points\": [",
                      path);
    for (int r = 0; r < 2; ++r)
        for (int k = 0; k < n; ++k)
            at += snprintf(json + at, size - (size_t)at, "%s{\"p\": [%.17g, %.17g, 0], \"n\": [0, 0, 1]}",
                           r + k ? ", " : "", -x_end + 2.0 * x_end * k / (n - 1), y_step * r);
    snprintf(json + at, size - (size_t)at,
             "]}], \"solver\": {\"method\": \"direct\", \"target_error\": 0.002, \"seed\": %d}}", seed);
}

/* Soft shadow: the 1.2 x 0.3 m Lambertian rectangle at 2.5 m (long side
 * along x), a black plate at 2 m over x >= 0. From a floor probe at
 * (px, py, 0) the segment to an opening point x_o crosses z = 2 at
 * px + 0.8 (x_o - px), hidden where that is >= 0: the visible part is the
 * rectangle's x_o < -px / 4, whose closed form is the contour integral.
 * Probes across the penumbra (px from -3 to 3), two rows in y. On the
 * exact route each is exact and within the cubature's tolerance (1/50 of
 * the 0.2 % target: 4e-5) of the closed form; sampled (the route turned off) each within five stated sigmas,
 * the sigmas calibrated over 4 seeds. */
static void test_soft_shadow(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/rect_shadow.ies", folder);
    CHECK(write_lambert_ies(path, "2002", 0.3, 1.2));
    double L = I0 / 0.36, target = 2e-3;
    calibration tally = CALIBRATION_INIT;
    int n = 25;
    /* seed 0: the exact route; seeds 1 to 4: sampled */
    for (int seed = 0; seed <= 4; ++seed) {
        plate_scene(json, sizeof json, path, n, 3.0, 0.7, seed);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve_route(json, &scene, &sol, 2, seed > 0)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        double scale = rect_E(L, -0.6, 0.6, -0.15, 0.15, 2.5, 0.0, 0.0); /* under the opening in full view */
        for (int r = 0; r < 2; ++r)
            for (int k = 0; k < n; ++k) {
                size_t i = (size_t)(r * n + k);
                double px = -3.0 + 6.0 * k / (n - 1), py = 0.7 * r, cut = fmin(0.6, -px / 4.0);
                double want = cut > -0.6 ? rect_E(L, -0.6, cut, -0.15, 0.15, 2.5, px, py) : 0.0;
                if (seed == 0)
                    CHECK_MSG(g->E_stderr[i] == 0.0 && fabs(g->E[i] - want) <= 4e-5 * want + 1e-8 * scale,
                              "shadow probe (%g, %g), exact route: %.9g +- %.3g, expected %.9g", px, py, g->E[i],
                              g->E_stderr[i], want);
                CHECK_MSG(fabs(g->E[i] - want) <= 5.0 * g->E_stderr[i] + 4e-5 * want + 1e-8 * scale,
                          "shadow probe (%g, %g): %.7g +- %.3g, expected %.7g", px, py, g->E[i], g->E_stderr[i], want);
                if (g->E_stderr[i] > 0.0 && want > 0.0) calibration_add(&tally, g->E[i], want, g->E_stderr[i], target);
            }
        if (seed == 0) CHECK(strstr(sol.plan_json, "exact: visible polygon past up to 1 occluders") != NULL);
        fixture_release(scene, &sol);
    }
    CHECK(tally.count > 100); /* the penumbra is sampled, not skipped */
    calibration_check(&tally, "penumbra of a Lambertian opening");
}

/* Soft shadow of a disk: the Lambertian circle 0.6 m across (the 2002
 * circle code) at 2.5 m, the black plate at 2 m over x >= 0 of
 * test_soft_shadow, so that the visible part is the disk's x_o < -px / 4,
 * a circular segment (ellipse_segment.h's integral). On the exact route
 * (the visible part of the disk's bounding square, clipped to the circle
 * with exact arcs) every probe is exact and within the cubature's
 * tolerance (1/50 of the 0.2 % target: 4e-5) of it, the fully hidden ones
 * dark. */
static void test_disk_shadow(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/disk_shadow.ies", folder);
    CHECK(write_lambert_ies(path, "2002", -0.6, -0.6));
    double L = I0 / (CDL_PI * 0.09);
    int n = 17;
    plate_scene(json, sizeof json, path, n, 1.6, 0.4, 1);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    double scale = ellipse_segment_E(L, 0.3, 0.3, 2.5, 0.0, 0.0, 0.3); /* under the disk in full view */
    for (int r = 0; r < 2; ++r)
        for (int k = 0; k < n; ++k) {
            size_t i = (size_t)(r * n + k);
            double px = -1.6 + 3.2 * k / (n - 1), py = 0.4 * r, cut = -px / 4.0;
            double want = cut > -0.3 ? ellipse_segment_E(L, 0.3, 0.3, 2.5, px, py, fmin(0.3, cut)) : 0.0;
            CHECK_MSG(g->E_stderr[i] == 0.0 && fabs(g->E[i] - want) <= 4e-5 * want + 1e-8 * scale,
                      "disk shadow probe (%g, %g): %.9g +- %.3g, expected %.9g", px, py, g->E[i], g->E_stderr[i], want);
        }
    CHECK(strstr(sol.plan_json, "exact: visible polygon past up to 1 occluders") != NULL);
    fixture_release(scene, &sol);
}

/* An LM-63-2002 file of one plane, gamma 0, 90 and 180 with the three
 * intensities `candela`, and the opening "W L H" in metres, written to path. */
static int write_one_plane_ies(const char *path, const char *opening, const char *candela)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return 0;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] solid\nTILT=NONE\n1 -1 1 3 1 1 2 %s\n1 1 0\n0 90 180\n0\n%s\n", opening,
            candela);
    int ok = fclose(f) == 0;
    CHECK(ok);
    return ok;
}

/* The start of a scene of the file at `path` spread ("always") 2 m up,
 * and a points grid whose points follow: the JSON's length so far. */
static int always_points_scene(char *json, size_t size, const char *path)
{
    return snprintf(json, size,
                    "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": "
                    "[0, 0, 2], \"near_field\": \"always\"}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", "
                    "\"points\": [",
                    path);
}

/* A sphere of uniform luminance (LM-63-2002 code -D -D -D, I = 500 cd in
 * every direction, 0.3 m across) spread over its surface ("always"), from
 * 1.1 r to 10 r: an element that sees it whole gets E = I cos(theta) /
 * d^2 (Lambert: a uniform sphere is a point to it), exact (the cone's
 * cubature, 1e-5; stated error 0); an element tilted past that, whose
 * horizon cuts the sphere, gets L pi F (sphere_factor.h), sampled to
 * quality "high" within five stated sigmas, calibrated over 4 seeds. */
static void test_sphere(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/sphere.ies", folder);
    if (!write_one_plane_ies(path, "-0.3 -0.3 -0.3", "500 500 500")) return;
    const double r = 0.15, I = 500.0, L = I / (CDL_PI * r * r), target = 1e-3;
    enum { N = 24 };
    double want[N];
    int whole[N];
    calibration tally = CALIBRATION_INIT;
    for (int seed = 1; seed <= 4; ++seed) {
        int at = always_points_scene(json, sizeof json, path);
        for (int k = 0; k < N; ++k) {
            /* distance 1.1 r .. 10 r along a direction turning round the
             * sphere; even k tilted within the angle that sees it whole,
             * odd k past it, up to where it sets */
            double d = r * (1.1 + 8.9 * k / (N - 1)), az = 0.7 * k, el = -1.2 + 2.4 * k / (N - 1);
            double rise = acos(r / d), set = 0.5 * CDL_PI + asin(r / d);
            double theta = k % 2 == 0 ? 0.45 * (k % 4) * rise : rise + (0.2 + 0.25 * (k % 4)) * (set - rise);
            double dir[3] = {cos(el) * cos(az), cos(el) * sin(az), sin(el)}, across[3] = {-sin(az), cos(az), 0.0}, n[3];
            /* the normal: towards the centre, turned by theta about a direction across it */
            for (int i = 0; i < 3; ++i) n[i] = -dir[i] * cos(theta) + across[i] * sin(theta);
            whole[k] = k % 2 == 0;
            want[k] = L * CDL_PI * sphere_factor(r, d, theta);
            at += snprintf(json + at, sizeof json - (size_t)at,
                           "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}", k ? ", " : "",
                           d * dir[0], d * dir[1], 2.0 + d * dir[2], n[0], n[1], n[2]);
        }
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_points_high(json, sizeof json, at, seed, &scene, &sol)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        for (int k = 0; k < N; ++k) {
            if (whole[k]) {
                CHECK_MSG(g->E_stderr[k] == 0.0 && fabs(g->E[k] - want[k]) <= 2e-5 * want[k],
                          "sphere probe %d seeing it whole: %.9g +- %.3g, expected %.9g exactly", k, g->E[k],
                          g->E_stderr[k], want[k]);
                continue;
            }
            CHECK_MSG(fabs(g->E[k] - want[k]) <= 5.0 * g->E_stderr[k],
                      "sphere probe %d: %.7g +- %.3g, expected %.7g", k, g->E[k], g->E_stderr[k], want[k]);
            if (g->E_stderr[k] > 0.0) calibration_add(&tally, g->E[k], want[k], g->E_stderr[k], target);
        }
        CHECK(strstr(sol.plan_json, "near field \\\"always\\\": spread over its luminous opening") != NULL);
        fixture_release(scene, &sol);
    }
    CHECK(tally.count >= 40);
    calibration_check(&tally, "sphere cut by the horizon, quality high");
}

/* A box with luminous sides of one luminance (LM-63-2002 code 0.2 0.6
 * 0.1: 0.6 m along x, 0.2 m along y, 0.1 m high; I = LUM x its projected
 * area, C and gamma every degree), spread ("always") and sampled face by
 * face at quality "high": 12 probes from 0.35 to 1.5 m, each facing the
 * centre (so every face it sees is in front of it), against Lambert's
 * factor of each face it sees (polygon_factor.h). Each within five stated
 * sigmas plus the table's interpolation (1e-4 of E: (1 deg)^2 / 8 per
 * |cos| term). Over 4 seeds at least 95 % within two sigmas, no bias, and
 * every sigma near the target. Not held to two thirds within one sigma:
 * here the sigmas are conservative (measured: all 48 within 0.56 sigma),
 * because the planner adds one phantom differing pair of a whole sample's
 * size for an edge its samples might have missed (direct_extended.c),
 * while this smooth, edgeless integrand's true spread is far smaller. */
static void test_box_calibration(void)
{
    char path[600], json[16384];
    snprintf(path, sizeof path, "%s/box.ies", folder);
    const double lum = 2000.0, h[3] = {0.3, 0.1, 0.05}, target = 1e-3;
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] box\nTILT=NONE\n1 -1 1 181 361 1 2 0.2 0.6 0.1\n1 1 0\n");
    for (int g = 0; g <= 180; ++g) fprintf(f, "%d ", g);
    fprintf(f, "\n");
    for (int c = 0; c <= 360; ++c) fprintf(f, "%d ", c);
    for (int c = 0; c <= 360; ++c) {
        fprintf(f, "\n");
        for (int g = 0; g <= 180; ++g) {
            double C = c * CDL_DEG_TO_RAD, G = g * CDL_DEG_TO_RAD;
            double x = fabs(sin(G) * cos(C)), y = fabs(sin(G) * sin(C)), z = fabs(cos(G));
            /* the projected area: 4 (h_y h_z x + h_x h_z y + h_x h_y z) */
            fprintf(f, "%.17g ", lum * 4.0 * (h[1] * h[2] * x + h[0] * h[2] * y + h[0] * h[1] * z));
        }
    }
    CHECK(fclose(f) == 0);
    enum { N = 12 };
    cdl_vec3 c = cdl_vec3_make(0, 0, 2), pts[N], nrm[N];
    double want[N];
    const double tops[4] = {h[2], h[2], h[2], h[2]};
    for (int k = 0; k < N; ++k) {
        double d = 0.35 + 1.15 * k / (N - 1), az = 0.9 * k, el = -1.3 + 2.6 * k / (N - 1);
        cdl_vec3 dir = cdl_vec3_make(cos(el) * cos(az), cos(el) * sin(az), sin(el));
        pts[k] = cdl_vec3_madd(c, d, dir);
        nrm[k] = cdl_vec3_neg(dir);
        want[k] = lambert_box(c, h, tops, lum, pts[k], nrm[k]);
    }
    calibration tally = CALIBRATION_INIT;
    for (int seed = 1; seed <= 4; ++seed) {
        int at = always_points_scene(json, sizeof json, path);
        for (int k = 0; k < N; ++k)
            at += snprintf(json + at, sizeof json - (size_t)at,
                           "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}", k ? ", " : "",
                           pts[k].x, pts[k].y, pts[k].z, nrm[k].x, nrm[k].y, nrm[k].z);
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_points_high(json, sizeof json, at, seed, &scene, &sol)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        for (int k = 0; k < N; ++k) {
            CHECK_MSG(g->E_stderr[k] > 0.0 && fabs(g->E[k] - want[k]) <= 5.0 * g->E_stderr[k] + 1e-4 * want[k],
                      "box probe %d: %.7g +- %.3g, expected %.7g", k, g->E[k], g->E_stderr[k], want[k]);
            if (g->E_stderr[k] > 0.0) calibration_add(&tally, g->E[k], want[k], g->E_stderr[k], target);
        }
        fixture_release(scene, &sol);
    }
    CHECK(tally.count >= 40);
    CHECK_MSG((double)tally.within2 >= 0.95 * (double)tally.count && fabs(tally.zsum / (double)tally.count) <= 4.0 / sqrt((double)tally.count) &&
                  tally.sigma_over_target_min >= 0.5 && tally.sigma_over_target_max <= 1.5,
              "box with luminous sides, quality high: %zu points, %.1f %% within 2 sigma, mean error %+.3f sigma, "
              "sigma / target %.2f .. %.2f",
              tally.count, 100.0 * (double)tally.within2 / (double)tally.count, tally.zsum / (double)tally.count,
              tally.sigma_over_target_min, tally.sigma_over_target_max);
}

/* The other luminous solids of LM-63 Table 1 (an ellipsoid, a vertical
 * elliptic cylinder, horizontal cylinders along and across, in their 2002
 * and 1995 codes) are spread under near_field "always": the plan says so,
 * nothing warns that they stay points, and a probe below each is lit
 * (its light from the solid, sampled with a stated error). */
static void test_other_solids(void)
{
    static const char *const codes[6][2] = {
        {"ellipsoid", "-0.3 -0.6 -0.2"},          {"vertical elliptic cylinder", "-0.2 -0.5 0.3"},
        {"horizontal cylinder along", "-0.2 0.8 -0.12"}, {"horizontal cylinder across", "0.6 -0.25 -0.15"},
        {"1995 along", "0 0.8 -0.12"},            {"1995 ellipsoid", "-0.3 0.6 -0.2"},
    };
    for (int m = 0; m < 6; ++m) {
        char path[600], json[2048];
        snprintf(path, sizeof path, "%s/solid%d.ies", folder, m);
        if (!write_one_plane_ies(path, codes[m][1], "500 400 300")) return;
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, "
                 "0, 2], \"near_field\": \"always\"}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", "
                 "\"points\": [{\"p\": [0.1, 0, 1.2], \"n\": [0, 0, 1]}]}],"
                 " \"solver\": {\"method\": \"direct\", \"quality\": \"draft\"}}",
                 path);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 1)) return;
        CHECK_MSG(strstr(sol.plan_json, "near field \\\"always\\\": spread over its luminous opening") != NULL &&
                      strstr(sol.plan_json, "lit as a point") == NULL,
                  "%s: not spread: %s", codes[m][0], sol.plan_json);
        for (size_t w = 0; w < sol.warning_count; ++w)
            CHECK_MSG(strstr(sol.warnings[w], "near_field") == NULL, "%s: %s", codes[m][0], sol.warnings[w]);
        /* 500 cd at the nadir from 0.8 m: some hundreds of lux, sampled */
        CHECK_MSG(sol.grids[0].E[0] > 100.0 && sol.grids[0].E[0] < 2000.0 && sol.grids[0].E_stderr[0] > 0.0,
                  "%s: E %g +- %g", codes[m][0], sol.grids[0].E[0], sol.grids[0].E_stderr[0]);
        fixture_release(scene, &sol);
    }
}

/* Interreflection lit by openings and a luminous solid: inside an
 * integrating sphere (radius 1, reflectance rho) every wall point receives
 * the interreflected illuminance rho Phi / (A (1 - rho)) whatever the
 * source's shape and distribution (solve_fixture.h). The office's 1.2 m
 * linear luminaire and 0.15 m downlight spread over their openings
 * ("always": their tables are not Lambertian, so next-event estimation
 * samples the openings), and a tilted 0.6 m luminous box (sampled), by
 * paths and by the irradiance cache, each point within five stated sigmas,
 * the sigmas calibrated over all of them. The closed form is for sources
 * that absorb nothing: the luminaires' bodies are left out ("body": false;
 * test_luminaire_body.c tests them). */
static void test_interreflection(void)
{
    calibration tally = CALIBRATION_INIT;
    const char *linear = "{\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR
                         "/data/office/linear.ies\", \"position\": [0.1, 0, 0.3], \"rotation\": [0, 0, 30], "
                         "\"flux_lm\": 3000, \"near_field\": \"always\", \"body\": false}";
    const char *down = "{\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR
                       "/data/office/downlight.ies\", \"position\": [0, 0.2, 0.7], \"flux_lm\": 3000, "
                       "\"near_field\": \"always\", \"body\": false}";
    /* a luminous box (0.6 x 0.2 x 0.1 m, brighter below), tilted: sampled, no closed form */
    char box_path[600], box[1024];
    snprintf(box_path, sizeof box_path, "%s/box.ies", folder);
    if (!write_one_plane_ies(box_path, "0.2 0.6 0.1", "900 400 100")) return;
    snprintf(box, sizeof box,
             "{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, -0.2, 0.1], \"rotation\": [20, 0, "
             "40], \"flux_lm\": 3000, \"near_field\": \"always\", \"body\": false}",
             box_path);
    const char *methods[2] = {"pathtrace", "icache"};
    for (int m = 0; m < 2; ++m) {
        char label[128];
        snprintf(label, sizeof label, "sphere, luminous box, %s", methods[m]);
        fixture_sphere_check(0.6, box, 3000.0, 20, methods[m], 0.01, &tally, label);
        snprintf(label, sizeof label, "sphere, linear opening, %s", methods[m]);
        fixture_sphere_check(0.5, linear, 3000.0, 20, methods[m], 0.01, &tally, label);
        snprintf(label, sizeof label, "sphere, downlight opening, %s", methods[m]);
        fixture_sphere_check(0.8, down, 3000.0, 20, methods[m], 0.01, &tally, label);
    }
    calibration_check(&tally, "interreflection from openings");
}

int main(void)
{
    if (!fixture_folder("near_field", folder, sizeof folder)) {
        CHECK(0);
        return check_finish();
    }
    test_modes();
    test_switch_by_target();
    test_cubature();
    test_skewed_shadow();
    test_soft_shadow();
    test_disk_shadow();
    test_sphere();
    test_other_solids();
    test_box_calibration();
    test_interreflection();
    return check_finish();
}
