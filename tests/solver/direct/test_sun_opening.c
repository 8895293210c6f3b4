/* An image sky with a sun seen through an opening, at every preset: the
 * sun's pixels summed exactly over their part of the visible sky, the rest
 * sampled within it (solver/direct/sky_region.h, lights/environment_
 * peaks.h), against an answer computed here by another road.
 *
 * The scene: a black well 2 x 2 m, 1.5 m deep, open at the top, under a
 * 128 x 64 lat-long sky (upper hemisphere): a zenith-bright gradient with
 * an azimuthal swing, a dark band of columns, and a 2 x 2 pixel sun of
 * 1e6 cd/m^2 (250 times the sky) 19.7 to 25.3 degrees from the zenith
 * towards +x. From floor points with x below 1.29 m the opening holds the
 * whole sun, from 1.29 to 1.46 m its edge x = 2 cuts across it, beyond
 * that the sun is hidden.
 *
 * The answer: with the normal up, the visible sky is every azimuth phi up
 * to the polar angle theta_m(phi) at which the direction leaves the
 * opening, tan theta_m = r(phi) / D, r the horizontal distance from the
 * point to the opening's edge along phi. With L constant over each pixel,
 *     E = int dphi g(phi),  g = sum over rows j of L_ij (sin^2 min(theta_j+1,
 *         theta_m) - sin^2 theta_j) / 2 over the rows with theta_j < theta_m,
 * i the column of phi. g is analytic between breakpoints: the columns'
 * edges, the opening's corners (r changes edge) and the azimuths where
 * theta_m crosses a row's edge (r = D tan theta_j on an edge at distance d
 * from the point: phi = psi +- acos(d / r), psi the edge's normal). So a
 * 10-point Gauss-Legendre rule on each piece between breakpoints gives E
 * to rounding (pieces narrower than 2.8 degrees; the rule's error for an
 * integrand with derivatives of order 1 is of order (h/2)^20 / 20!). No
 * clipping, no spherical polygon, no pixel cell: nothing the solver does.
 *
 * Held: each point within its stated sigma as DESIGN.md asks (over all
 * presets: about 68 % within one sigma, 95 % within two, no bias;
 * calibration_check), every stated sigma at most 1.5 times the preset's
 * target and 95 % of them at least 1 / 1.5 of it (the factor
 * 1.5; none below half), the cap of samples holding no point, no
 * shadow ray, the plan naming the sun's route; the same bytes with one and
 * two threads. And a sky bright in more pixels than the exact sum takes
 * (test_aureole) keeps the shadow-ray sampler, honestly, and the plan says
 * why.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/scene/exr_image.h"
#include "solver/solve_internal.h"
#include "solver/solve_fixture.h"

enum { POINTS = 48, MAX_W = 512, MAX_H = 256 };
#define DEPTH 1.5
#define SUN_L 1e6

/* The sky in use: W x H pixels. */
static int W = 128, H = 64;
static float sky[MAX_W * MAX_H];

/* Pixel (i, j): column i spans azimuth pi + 2 pi [i, i + 1) / W from +x
 * towards +y, row j polar angle pi [j, j + 1) / H from the zenith (the
 * environment's frame for "up" +z: emitter_environment.c). */
static void make_sky(void)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double v = 4000.0 * (1.0 - 0.7 * j / H) * (1.0 + 0.3 * cos(CDL_TWO_PI * i / W));
            if (i >= W * 5 / 8 && i < W * 11 / 16) v = 0.0;
            if (i >= W / 2 && i < W / 2 + 2 && j >= 7 && j < 9) v = SUN_L; /* azimuth 0 to 5.6 degrees */
            sky[j * W + i] = (float)v;
        }
    cdl_exr_channel ch = {"Y", sky};
    cdl_error err;
    CHECK_OK(cdl_exr_write(CANDELA_TEST_TMPDIR "/sun_opening.exr", W, H, &ch, 1, NULL, 0, &err), &err);
}

/* The opening's edges seen from (px, py): outward normal azimuth and
 * distance. */
static void opening_edges(double px, double py, double psi[4], double d[4])
{
    psi[0] = 0.0;
    d[0] = 2.0 - px;
    psi[1] = 0.5 * CDL_PI;
    d[1] = 2.0 - py;
    psi[2] = CDL_PI;
    d[2] = px;
    psi[3] = 1.5 * CDL_PI;
    d[3] = py;
}

/* g(phi) (the header). */
static double g_of(double px, double py, double phi)
{
    double psi[4], d[4], r = INFINITY;
    opening_edges(px, py, psi, d);
    for (int e = 0; e < 4; ++e) {
        double c = cos(phi - psi[e]);
        if (c > 0.0) r = fmin(r, d[e] / c);
    }
    double tm = atan(r / DEPTH);
    double u = (phi - CDL_PI) / CDL_TWO_PI;
    u -= floor(u);
    int i = (int)(u * W);
    if (i >= W) i = W - 1;
    double g = 0.0;
    for (int j = 0; j < H / 2; ++j) {
        double ta = CDL_PI * j / H, tb = CDL_PI * (j + 1) / H;
        if (!(ta < tm)) break;
        double top = sin(fmin(tb, tm)), bottom = sin(ta);
        g += sky[j * W + i] * 0.5 * (top * top - bottom * bottom);
    }
    return g;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* E at floor point (px, py) by the breakpoints and Gauss-Legendre. */
static double exact_E(double px, double py)
{
    static const double x10[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                  0.9739065285171717};
    static const double w10[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                  0.0666713443086881};
    static double bp[MAX_W + 4 + 8 * MAX_H + 2];
    int nb = 0;
    for (int i = 0; i < W; ++i) bp[nb++] = fmod(CDL_PI + CDL_TWO_PI * i / W, CDL_TWO_PI);
    const double cx[4] = {0, 2, 2, 0}, cy[4] = {0, 0, 2, 2};
    for (int k = 0; k < 4; ++k) {
        double a = atan2(cy[k] - py, cx[k] - px);
        bp[nb++] = a < 0.0 ? a + CDL_TWO_PI : a;
    }
    double psi[4], d[4];
    opening_edges(px, py, psi, d);
    for (int e = 0; e < 4; ++e)
        for (int j = 1; j < H / 2; ++j) {
            double r = DEPTH * tan(CDL_PI * j / H);
            if (d[e] >= r) continue;
            for (int s = -1; s <= 1; s += 2) {
                double a = fmod(psi[e] + s * acos(d[e] / r) + 2.0 * CDL_TWO_PI, CDL_TWO_PI);
                bp[nb++] = a;
            }
        }
    bp[nb++] = 0.0;
    bp[nb++] = CDL_TWO_PI;
    qsort(bp, (size_t)nb, sizeof bp[0], cmp_double);
    double E = 0.0;
    for (int k = 0; k + 1 < nb; ++k) {
        double a = bp[k], b = bp[k + 1];
        if (!(b > a)) continue;
        double m = 0.5 * (a + b), h = 0.5 * (b - a), s = 0.0;
        for (int q = 0; q < 5; ++q) s += w10[q] * (g_of(px, py, m - h * x10[q]) + g_of(px, py, m + h * x10[q]));
        E += h * s;
    }
    return E;
}

/* Floor points: 32 spread over the floor (a golden-ratio sequence, 0.1 m
 * from the walls) and 16 where the opening's edge cuts across the sun. */
static void floor_points(double pts[POINTS][2])
{
    for (int i = 0; i < 32; ++i) {
        pts[i][0] = 0.1 + 1.8 * (i + 0.5) / 32.0;
        pts[i][1] = 0.1 + 1.8 * fmod(0.6180339887 * (i + 1), 1.0);
    }
    for (int i = 0; i < 16; ++i) {
        pts[32 + i][0] = 1.27 + 0.21 * (i + 0.5) / 16.0;
        pts[32 + i][1] = 0.3 + 1.4 * fmod(0.6180339887 * (i + 7), 1.0);
    }
}

static void scene_json(char *json, size_t size, const double pts[POINTS][2], int count, const char *file,
                       const char *quality)
{
    int n = snprintf(json, size,
                     "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [2, 2, %g],"
                     " \"inward\": true, \"open\": [\"+z\"], \"reflectance\": 0}],"
                     " \"luminaires\": [{\"type\": \"environment\", \"file\": \"%s\", \"hemisphere\": "
                     "\"upper\"}], \"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"points\": [",
                     DEPTH, file);
    for (int i = 0; i < count; ++i)
        n += snprintf(json + n, size - (size_t)n, "%s{\"p\": [%.10g, %.10g, 0], \"n\": [0, 0, 1]}", i ? ", " : "",
                      pts[i][0], pts[i][1]);
    snprintf(json + n, size - (size_t)n, "]}], \"solver\": {\"method\": \"direct\", \"quality\": \"%s\"}}", quality);
}

static void test_preset(const char *quality, const double pts[POINTS][2], const double *exact, calibration *all,
                        int *below)
{
    static char json[16384];
    scene_json(json, sizeof json, pts, POINTS, "sun_opening.exr", quality);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    double target = cdl_quality_target_error(scene->settings.quality);
    const cdl_grid_solution *g = &sol.grids[0];
    calibration tally = CALIBRATION_INIT;
    for (int i = 0; i < POINTS; ++i) {
        calibration_add(all, g->E[i], exact[i], g->E_stderr[i], target);
        calibration_add(&tally, g->E[i], exact[i], g->E_stderr[i], target);
        double r = g->E_stderr[i] / (target * exact[i]);
        CHECK_MSG(r <= 1.5 && r >= 0.5, "%s point %d (%.3f, %.3f): sigma / target %.2f", quality, i, pts[i][0],
                  pts[i][1], r);
        *below += r < 1.0 / 1.5;
        CHECK_MSG(fabs(g->E[i] - exact[i]) <= 4.0 * g->E_stderr[i], "%s point %d: E = %.8g +- %.3g, exact %.8g",
                  quality, i, g->E[i], g->E_stderr[i], exact[i]);
    }
    printf("  %s: %zu within 1 sigma, %zu within 2 of %d, worst %.2f sigma; sigma / target %.2f .. %.2f\n", quality,
           tally.within1, tally.within2, POINTS, tally.worst, tally.sigma_over_target_min,
           tally.sigma_over_target_max);
    CHECK(sol.rays == 0);
    CHECK_MSG(strstr(sol.plan_json, "a sun within the visible sky") != NULL, "%s", sol.plan_json);
    CHECK_MSG(fixture_capped_points(sol.plan_json) == 0, "%s", sol.plan_json);
    fixture_release(scene, &sol);
}

/* One and two threads: the same bytes. */
static void test_threads(const double pts[POINTS][2])
{
    static char json[16384];
    scene_json(json, sizeof json, pts, POINTS, "sun_opening.exr", "high");
    cdl_scene *s1, *s2;
    cdl_solution a, b;
    if (!fixture_solve(json, &s1, &a, 1)) return;
    if (!fixture_solve(json, &s2, &b, 2)) {
        fixture_release(s1, &a);
        return;
    }
    CHECK(memcmp(a.grids[0].E, b.grids[0].E, POINTS * sizeof a.grids[0].E[0]) == 0);
    CHECK(memcmp(a.grids[0].E_stderr, b.grids[0].E_stderr, POINTS * sizeof a.grids[0].E_stderr[0]) == 0);
    fixture_release(s1, &a);
    fixture_release(s2, &b);
}

/* A bright aureole: a 512 x 256 sky of 2000 cd/m^2 whose six rows about
 * the zenith (4.2 degrees, 3072 pixels) are at 1e6. More bright pixels
 * than the exact sum takes a point (1024), so the sky keeps the
 * shadow-ray sampler (E_0 less the hidden part, pixels drawn by L times
 * their projected solid angle), and the plan says why; each point within
 * 4 stated sigma of the answer by azimuth, the stated sigma at most 1.5
 * times the target. */
static void test_aureole(void)
{
    W = 512;
    H = 256;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) sky[j * W + i] = j < 6 ? 1e6f : 2000.0f;
    cdl_exr_channel ch = {"Y", sky};
    cdl_error err;
    CHECK_OK(cdl_exr_write(CANDELA_TEST_TMPDIR "/aureole.exr", W, H, &ch, 1, NULL, 0, &err), &err);
    double pts[POINTS][2];
    for (int i = 0; i < 8; ++i) {
        pts[i][0] = 0.2 + 1.6 * (i + 0.5) / 8.0;
        pts[i][1] = 0.2 + 1.6 * fmod(0.6180339887 * (i + 1), 1.0);
    }
    static char json[16384];
    scene_json(json, sizeof json, (const double(*)[2])pts, 8, "aureole.exr", "normal");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    double target = cdl_quality_target_error(scene->settings.quality);
    const cdl_grid_solution *g = &sol.grids[0];
    for (int i = 0; i < 8; ++i) {
        double exact = exact_E(pts[i][0], pts[i][1]);
        CHECK_MSG(fabs(g->E[i] - exact) <= 4.0 * g->E_stderr[i] && g->E_stderr[i] <= 1.5 * target * exact,
                  "aureole point %d: E = %.8g +- %.3g, exact %.8g", i, g->E[i], g->E_stderr[i], exact);
    }
    CHECK(sol.rays > 0);
    CHECK_MSG(strstr(sol.plan_json, "far brighter in more than 1024 pixels") != NULL, "%s", sol.plan_json);
    fixture_release(scene, &sol);
}

int main(void)
{
    make_sky();
    double pts[POINTS][2], exact[POINTS];
    floor_points(pts);
    int seen = 0, cut = 0;
    for (int i = 0; i < POINTS; ++i) {
        exact[i] = exact_E(pts[i][0], pts[i][1]);
        seen += pts[i][0] < 1.29;
        cut += pts[i][0] > 1.29 && pts[i][0] < 1.46;
    }
    CHECK(seen >= 16 && cut >= 12);
    /* The answer's own check: with the sun taken out and the sky made
     * uniform the rule must give L times the opening's projected solid
     * angle, the parallel-rectangle form (exact_forms.h would do; here the
     * point under the middle: pi L F, F for a 2 x 2 square 1.5 m above). */
    static float saved[MAX_W * MAX_H];
    memcpy(saved, sky, sizeof sky);
    for (int k = 0; k < W * H; ++k) sky[k] = 1000.0f;
    double a = 1.0 / DEPTH, F = 4.0 / CDL_PI * (a / sqrt(1.0 + a * a) * atan(a / sqrt(1.0 + a * a))) ;
    CHECK_MSG(fabs(exact_E(1.0, 1.0) - 1000.0 * CDL_PI * F) <= 1e-12 * 1000.0 * CDL_PI * F, "uniform: %.15g, %.15g",
              exact_E(1.0, 1.0), 1000.0 * CDL_PI * F);
    memcpy(sky, saved, sizeof sky);

    static const char *const presets[] = {"draft", "normal", "high", "reference"};
    calibration all = CALIBRATION_INIT;
    int below = 0;
    for (int q = 0; q < 4; ++q) test_preset(presets[q], (const double(*)[2])pts, exact, &all, &below);
    calibration_check(&all, "image sky with a sun through an opening, every preset");
    /* Below the target a point is only more accurate than asked: a few may
     * be (a plan is a prediction, and a smooth rest of the sky converges faster
     * than the N^-1.5 it is planned with: 3 of 192 measured, at "draft"). */
    CHECK_MSG(below <= 4 * POINTS / 20, "%d of %d points below 1 / 1.5 of the target", below, 4 * POINTS);
    test_threads((const double(*)[2])pts);
    test_aureole();
    return check_finish();
}
