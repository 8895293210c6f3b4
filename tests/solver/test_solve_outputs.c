/* The grid outputs beyond horizontal lux, solved end to end and held to
 * closed forms: cylindrical illuminance E_z = I sin(theta) / (pi d^2) and
 * semicylindrical E_sz = I sin(theta) (1 + cos alpha) / (pi d^2) of a point
 * source (EN 12464-1's E_z, CIE 136's E_sc), each checked also against an
 * independent quadrature of the plane illuminance over the cylinder's
 * facets; luminance L = rho E / pi of the surface under a grid; the
 * refusals where these cannot be computed yet; the area each polygon-grid
 * point stands for. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/direct/direct.h"
#include "solver/output/grid_result.h"
#include "solver/output/solution_write.h"
#include "solver/scene/exr_image.h"
#include "solver/solve_internal.h"
#include "solver/solve_fixture.h"

#define I_CD 1234.5

/* Probe points around a point source at the origin: distances and zenith
 * angles of the light as seen from the point, and the semicylinder's facing
 * azimuth relative to the light's. */
typedef struct probe {
    double d, theta_deg, alpha_deg;
} probe;

static const probe probes[] = {
    {2.0, 0.0, 0.0},    {2.0, 30.0, 0.0},  {3.5, 45.0, 60.0},  {1.0, 60.0, 90.0},
    {5.0, 89.0, 135.0}, {2.5, 120.0, 180.0}, {0.3, 150.0, -45.0}, {7.0, 90.0, 30.0},
};
#define PROBES (sizeof probes / sizeof probes[0])

/* Where probe k sits (the light, at the origin, is seen from it at zenith
 * angle theta, azimuth 0 towards +x) and which horizontal way it faces
 * (azimuth alpha from the light's). */
static void probe_place(const probe *pr, cdl_vec3 *p, cdl_vec3 *facing)
{
    double t = pr->theta_deg * CDL_DEG_TO_RAD, a = pr->alpha_deg * CDL_DEG_TO_RAD;
    /* to_light = (sin t, 0, cos t): the point lies at -d to_light. */
    *p = cdl_vec3_make(-pr->d * sin(t), 0.0, -pr->d * cos(t));
    *facing = cdl_vec3_make(cos(a), sin(a), 0.0);
}

static void test_point_source_closed_forms(void)
{
    char json[8192];
    int n = snprintf(json, sizeof json,
                     "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0], "
                     "\"intensity_cd\": %.17g}], \"grids\": [{\"name\": \"probes\", \"type\": \"points\", "
                     "\"outputs\": [\"cylindrical\", \"semicylindrical\"], \"points\": [",
                     I_CD);
    for (size_t k = 0; k < PROBES; ++k) {
        cdl_vec3 p, f;
        probe_place(&probes[k], &p, &f);
        n += snprintf(json + n, sizeof json - (size_t)n, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, 0]}",
                      k ? ", " : "", p.x, p.y, p.z, f.x, f.y);
    }
    snprintf(json + n, sizeof json - (size_t)n, "]}], \"solver\": {\"method\": \"direct\"}}");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK(g->Ez != NULL && g->Esz != NULL);
    if (!g->Ez || !g->Esz) {
        fixture_release(scene, &sol);
        return;
    }
    double worst_z = 0.0, worst_sz = 0.0, worst_quad = 0.0;
    for (size_t k = 0; k < PROBES; ++k) {
        const probe *pr = &probes[k];
        double t = pr->theta_deg * CDL_DEG_TO_RAD, a = pr->alpha_deg * CDL_DEG_TO_RAD;
        double En = I_CD / (pr->d * pr->d);
        double Ez = En * sin(t) / CDL_PI, Esz = En * sin(t) * (1.0 + cos(a)) / CDL_PI;
        /* The closed forms and the solver evaluate the same I / d^2 and sin
         * by different roundings: a few ulps, far below 1e-12. A light
         * straight above (theta = 0) gives exactly 0. */
        if (Ez == 0.0) {
            CHECK_ABS(g->Ez[k], 0.0, 1e-12 * En);
            CHECK_ABS(g->Esz[k], 0.0, 1e-12 * En);
        } else {
            CHECK_REL(g->Ez[k], Ez, 1e-12);
            worst_z = fmax(worst_z, fabs(g->Ez[k] - Ez) / Ez);
            if (Esz > 1e-12 * En) {
                CHECK_REL(g->Esz[k], Esz, 1e-12);
                worst_sz = fmax(worst_sz, fabs(g->Esz[k] - Esz) / Esz);
            } else {
                CHECK_ABS(g->Esz[k], 0.0, 1e-12 * En);
            }
        }
        /* Independently: the mean over 7200 facets of the cylinder of the
         * illuminance on each facet's vertical plane, I cos / d^2 (the
         * midpoint rule on a periodic, piecewise smooth integrand with two
         * kinks: error below 1e-6 relative), and over the 3600 facing f. */
        enum { FACETS = 7200 };
        cdl_vec3 p, f;
        probe_place(pr, &p, &f);
        double sum_z = 0.0, sum_sz = 0.0;
        cdl_vec3 w = cdl_vec3_normalize(cdl_vec3_neg(p));
        for (int j = 0; j < FACETS; ++j) {
            double phi = 2.0 * CDL_PI * (j + 0.5) / FACETS;
            cdl_vec3 m = cdl_vec3_make(cos(phi), sin(phi), 0.0);
            double c = cdl_vec3_dot(m, w);
            double e = c > 0.0 ? I_CD * c / (pr->d * pr->d) : 0.0;
            sum_z += e;
            if (cdl_vec3_dot(m, f) > 0.0) sum_sz += e;
        }
        double quad_z = sum_z / FACETS, quad_sz = sum_sz / (FACETS / 2);
        if (quad_z > 0.0) {
            CHECK_REL(g->Ez[k], quad_z, 1e-6);
            worst_quad = fmax(worst_quad, fabs(g->Ez[k] - quad_z) / quad_z);
        }
        if (quad_sz > 1e-9 * En) CHECK_REL(g->Esz[k], quad_sz, 1e-6);
    }
    printf("cylindrical: worst relative deviation from I sin(theta)/(pi d^2) %.3g, semicylindrical %.3g, "
           "from the facet quadrature %.3g\n",
           worst_z, worst_sz, worst_quad);
    /* Statistics of the extra outputs come out as for E. */
    cdl_grid_result r;
    cdl_grid_solution_result(g, &r);
    cdl_grid_stats s;
    cdl_grid_result_stats(&r, &s);
    double mean = 0.0, lo = g->Ez[0];
    for (size_t k = 0; k < PROBES; ++k) {
        mean += g->Ez[k] / PROBES;
        lo = fmin(lo, g->Ez[k]);
    }
    CHECK_REL(s.Ez.avg, mean, 1e-12);
    CHECK(s.Ez.min == lo);
    fixture_release(scene, &sol);
}

/* A spot aimed by "aim" lights a cylinder as the closed form says, and a
 * wall between the light and some probes shadows both outputs exactly as
 * it shadows E. */
static void test_shadowed_spot(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [1, -5, -5], \"u\": [0, 10, 0], "
        "\"v\": [0, 0, 10], \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"spot\", \"position\": [0, 0, 3], \"aim\": [0, 0, 0], \"intensity_cd\": 800,"
        " \"exponent\": 1}],"
        " \"grids\": [{\"name\": \"c\", \"type\": \"points\", \"outputs\": [\"cylindrical\", \"semicylindrical\"],"
        " \"points\": [{\"p\": [-2, 0, 1.5], \"n\": [-1, 0, 0]}, {\"p\": [2, 0, 1.5], \"n\": [1, 0, 0]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    /* Probe 0 at (-2, 0, 1.5): d^2 = 4 + 2.25, the spot's axis -z, angle to
     * it cos = 1.5 / d; I = 800 cos. Light from above-right: sin(theta) = 2 / d;
     * facing -x, away from the light's azimuth (+x): alpha = 180 deg, E_sz = 0. */
    double d2 = 6.25, d = 2.5, I = 800.0 * 1.5 / d;
    CHECK_REL(g->Ez[0], I / d2 * (2.0 / d) / CDL_PI, 1e-12);
    CHECK_ABS(g->Esz[0], 0.0, 1e-12);
    /* Probe 1 behind the wall at x = 1: dark in every output. */
    CHECK(g->E[1] == 0.0 && g->Ez[1] == 0.0 && g->Esz[1] == 0.0);
    fixture_release(scene, &sol);
}

/* Each extra output is an EXR channel holding the same values (as
 * floats) at every raster pixel, and absent when not asked for. */
static void check_exr_channels(const cdl_scene *scene, const cdl_solution *sol, const char *folder)
{
    char dir[512], path[600];
    snprintf(dir, sizeof dir, "%s/%s", CANDELA_TEST_TMPDIR, folder);
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_solution_prepare_folder(dir, &err) == CDL_OK);
    CHECK(cdl_solution_write(scene, sol, dir, NULL, &err) == CDL_OK);
    const cdl_grid_solution *g = &sol->grids[0];
    snprintf(path, sizeof path, "%s/%s.exr", dir, scene->grids[0].name);
    cdl_exr_image img;
    if (cdl_exr_read(path, &img, &err) != CDL_OK) {
        CHECK_MSG(0, "%s", err.message);
        return;
    }
    const struct {
        const char *name;
        const double *values;
    } channels[] = {{"Ez", g->Ez}, {"Esz", g->Esz}, {"L", g->L}};
    for (size_t c = 0; c < 3; ++c) {
        const float *plane = cdl_exr_image_channel(&img, channels[c].name);
        CHECK_MSG((plane != NULL) == (channels[c].values != NULL), "channel %s", channels[c].name);
        for (int k = 0; plane && channels[c].values && k < img.width * img.height; ++k) {
            int32_t idx = g->grid.raster_index[k];
            if (idx >= 0) CHECK(plane[k] == (float)channels[c].values[idx]);
        }
    }
    cdl_exr_image_release(&img);
}

/* A rect grid asking for both vertical outputs gets both channels. */
static void test_vertical_channels(void)
{
    const char *json =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [1, 1, 3], \"intensity_cd\": 700}],"
        " \"grids\": [{\"name\": \"v\", \"type\": \"rect\", \"origin\": [0, 0, 1.5], \"u\": [4, 0, 0], \"v\": [0, 3, 0],"
        " \"nu\": 8, \"nv\": 6, \"normal\": [0, -1, 0], \"outputs\": [\"cylindrical\", \"semicylindrical\"]}]}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    check_exr_channels(scene, &sol, "outputs_vertical");
    fixture_release(scene, &sol);
}

/* L = rho E / pi on a grid lying on a floor of reflectance 0.35. */
static void test_luminance(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [-2, -2, 0], "
        "\"u\": [4, 0, 0], \"v\": [0, 4, 0], \"reflectance\": 0.35}],"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [0.3, 0.2, 2.5], \"intensity_cd\": 500}],"
        " \"grids\": [{\"name\": \"f\", \"type\": \"rect\", \"origin\": [-1.5, -1.5, 0], \"u\": [3, 0, 0],"
        " \"v\": [0, 3, 0], \"nu\": 5, \"nv\": 4, \"outputs\": [\"luminance\"]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK(g->L != NULL);
    for (size_t i = 0; g->L && i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double dx = 0.3 - p.x, dy = 0.2 - p.y, dz = 2.5;
        double d2 = dx * dx + dy * dy + dz * dz;
        double E = 500.0 * dz / sqrt(d2) / d2;
        /* E is the closed form to a few ulps (nothing occludes), L one
         * multiplication and division more. */
        CHECK_REL(g->L[i], 0.35 * E / CDL_PI, 1e-12);
    }
    check_exr_channels(scene, &sol, "outputs_luminance");
    fixture_release(scene, &sol);
}

/* Cylindrical and semicylindrical illuminance from skies, area emitters
 * and interreflection are sampled: checked against closed forms within
 * four of their stated standard errors (a point fails by chance with
 * probability 6e-5), and the stated errors near the target. */
static int within_sigma(double value, double stderr, double exact, double k)
{
    return fabs(value - exact) <= k * stderr + 1e-12 * fabs(exact);
}

/* A scene of one sky (the luminaire's JSON) and three points asking for
 * both vertical outputs, at draft quality. */
static const char *sky_scene(const char *sky)
{
    static char json[1024];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [%s], \"grids\": [{\"name\": \"c\", \"type\": \"points\", "
             "\"outputs\": [\"cylindrical\", \"semicylindrical\"], \"points\": [{\"p\": [0, 0, 1.5], \"n\": [1, 0, 0]}, "
             "{\"p\": [3, 2, 1], \"n\": [0, -1, 0.2]}, {\"p\": [-5, 1, 0], \"n\": [1, 1, 0]}]}], "
             "\"solver\": {\"quality\": \"draft\"}}",
             sky);
    return json;
}

static void test_sampled_vertical(void)
{
    /* Uniform skies, nothing around: the full sphere of L gives every
     * facet pi L, so E_z = E_sz = pi L; each sample of E_z is exactly that
     * (no error). The upper hemisphere alone: E_z = (1 / pi) L 2 pi int_0^pi/2
     * sin^2 = pi L / 2, and E_sz too (cos alpha averages to 0 over phi). */
    const double L = 1000.0;
    const char *full = sky_scene("{\"type\": \"environment\", \"luminance_cd_m2\": 1000}");
    cdl_scene *scene;
    cdl_solution sol;
    if (fixture_solve(full, &scene, &sol, 1)) {
        const cdl_grid_solution *g = &sol.grids[0];
        CHECK(g->Ez_stderr != NULL && g->Esz_stderr != NULL);
        for (size_t i = 0; g->Ez_stderr && i < 3; ++i) {
            CHECK_REL(g->Ez[i], CDL_PI * L, 1e-12);
            CHECK(g->Ez_stderr[i] < 1e-9 * CDL_PI * L);
            /* E_sz's samples, pi L (1 + cos alpha), vary with azimuth */
            CHECK_MSG(within_sigma(g->Esz[i], g->Esz_stderr[i], CDL_PI * L, 4.0), "full sky point %zu: Esz %g +- %g",
                      i, g->Esz[i], g->Esz_stderr[i]);
        }
        fixture_release(scene, &sol);
    }
    const char *upper = sky_scene("{\"type\": \"environment\", \"luminance_cd_m2\": 1000, \"hemisphere\": \"upper\"}");
    if (fixture_solve(upper, &scene, &sol, 1)) {
        const cdl_grid_solution *g = &sol.grids[0];
        for (size_t i = 0; g->Ez_stderr && i < 3; ++i) {
            /* The strata in F(theta) split at the horizon (F = 1/2), so each
             * stratum lies wholly in the sky or below it: E_z's estimate is
             * exact, and says so. E_sz's samples vary with azimuth. */
            double exact = CDL_PI * L / 2.0;
            CHECK_REL(g->Ez[i], exact, 1e-12);
            CHECK(g->Ez_stderr[i] < 1e-9 * exact);
            CHECK_MSG(within_sigma(g->Esz[i], g->Esz_stderr[i], exact, 4.0), "upper sky point %zu: Esz %g +- %g", i,
                      g->Esz[i], g->Esz_stderr[i]);
        }
        fixture_release(scene, &sol);
    }
    /* The CIE overcast sky, L = Lz (1 + 2 cos theta) / 3 above the horizon:
     * E_z = (1 / pi) 2 pi (Lz / 3) int_0^pi/2 (1 + 2 cos) sin^2 = (2 Lz / 3)
     * (pi / 4 + 2 / 3) = Lz (pi / 6 + 4 / 9); E_sz the same (nothing depends
     * on azimuth). Sampled: within 4 stated sigma, stated near the 2 %. */
    const char *overcast = sky_scene("{\"type\": \"environment\", \"sky\": \"cie_overcast\", "
                                     "\"zenith_luminance_cd_m2\": 1000}");
    if (fixture_solve(overcast, &scene, &sol, 1)) {
        const cdl_grid_solution *g = &sol.grids[0];
        double exact = L * (CDL_PI / 6.0 + 4.0 / 9.0);
        for (size_t i = 0; g->Ez_stderr && i < 3; ++i) {
            CHECK_MSG(within_sigma(g->Ez[i], g->Ez_stderr[i], exact, 4.0), "overcast point %zu: Ez %g +- %g, exact %g",
                      i, g->Ez[i], g->Ez_stderr[i], exact);
            CHECK_MSG(within_sigma(g->Esz[i], g->Esz_stderr[i], exact, 4.0), "overcast point %zu: Esz %g +- %g", i,
                      g->Esz[i], g->Esz_stderr[i]);
            CHECK_MSG(g->Ez_stderr[i] > 0.0 && g->Ez_stderr[i] < 0.03 * exact, "stated %g", g->Ez_stderr[i]);
            printf("overcast sky: Ez %.6g lx +- %.3g (exact %.6g, %.2f sigma)\n", g->Ez[i], g->Ez_stderr[i], exact,
                   (g->Ez[i] - exact) / g->Ez_stderr[i]);
        }
        fixture_release(scene, &sol);
    }

    /* An integrating sphere (radius 2 m, rho 0.5) with a 1000 cd point
     * source at its centre: the wall's direct irradiance I / R^2 = 250 lx is
     * uniform, so after all reflections its radiance is uniform, L = rho E_w
     * / pi with E_w = 250 / (1 - rho), and every inside point sees it from
     * every direction: E_z,ind = E_sz,ind = pi L = rho I / (R^2 (1 - rho))
     * = 250 lx, on top of the source's exact I sin(theta) / (pi d^2). */
    const char *sphere =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 2, "
        "\"inward\": true, \"reflectance\": 0.5}], \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0],"
        " \"intensity_cd\": 1000}], \"grids\": [{\"name\": \"c\", \"type\": \"points\", \"outputs\": "
        "[\"cylindrical\", \"semicylindrical\"], \"points\": [{\"p\": [0.8, 0, 0], \"n\": [0, 1, 0]}, {\"p\": [0, 0.6, 0.8], "
        "\"n\": [1, 0, 0]}, {\"p\": [-0.5, -0.5, -1], \"n\": [0, -1, 0]}]}], \"solver\": {\"method\": \"pathtrace\", "
        "\"quality\": \"draft\"}}";
    if (fixture_solve(sphere, &scene, &sol, 2)) {
        const cdl_grid_solution *g = &sol.grids[0];
        for (size_t i = 0; g->Ez_stderr && i < 3; ++i) {
            cdl_vec3 p = g->grid.points[i];
            double d2 = cdl_vec3_dot(p, p), sin_theta = sqrt(p.x * p.x + p.y * p.y) / sqrt(d2);
            double exact = 1000.0 * sin_theta / (CDL_PI * d2) + 250.0;
            CHECK_MSG(within_sigma(g->Ez[i], g->Ez_stderr[i], exact, 4.0), "sphere point %zu: Ez %g +- %g, exact %g", i,
                      g->Ez[i], g->Ez_stderr[i], exact);
            /* the facing direction and the source's: alpha from the point's normal to -p (horizontal parts) */
            cdl_vec3 n = g->grid.normals[i], w = cdl_vec3_scale(p, -1.0 / sqrt(d2));
            double h = sqrt(w.x * w.x + w.y * w.y), cos_alpha = h > 0.0 ? (w.x * n.x + w.y * n.y) / h : 0.0;
            double exact_sz = 1000.0 * sin_theta * (1.0 + cos_alpha) / (CDL_PI * d2) + 250.0;
            CHECK_MSG(within_sigma(g->Esz[i], g->Esz_stderr[i], exact_sz, 4.0), "sphere point %zu: Esz %g +- %g, exact %g",
                      i, g->Esz[i], g->Esz_stderr[i], exact_sz);
            printf("integrating sphere: Ez %.6g lx +- %.3g (exact %.6g, %.2f sigma), Esz %.6g +- %.3g (exact %.6g)\n",
                   g->Ez[i], g->Ez_stderr[i], exact, (g->Ez[i] - exact) / g->Ez_stderr[i], g->Esz[i],
                   g->Esz_stderr[i], exact_sz);
        }
        fixture_release(scene, &sol);
    }

    /* A luminous ceiling panel (2 x 1 m, 500 cd/m2, 2.5 m up) and a point
     * below its corner: E_z = (1 / pi) int L sin(theta) dw over the panel,
     * here by the midpoint rule on 400 x 200 cells (dw = cos(e) dA / r^2;
     * smooth integrand, error far below the 2 % target). */
    const char *panel =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0, 0, 2.5],"
        " \"u\": [0, 1, 0], \"v\": [2, 0, 0]}, \"luminance_cd_m2\": 500}], \"grids\": [{\"name\": \"c\", \"type\": "
        "\"points\", \"outputs\": [\"cylindrical\"], \"points\": [{\"p\": [-0.5, -0.3, 1.2], \"n\": [1, 0, 0]}]}],"
        " \"solver\": {\"quality\": \"draft\"}}";
    if (fixture_solve(panel, &scene, &sol, 1)) {
        const cdl_grid_solution *g = &sol.grids[0];
        double sum = 0.0;
        cdl_vec3 p = g->grid.points[0];
        for (int a = 0; a < 400; ++a)
            for (int b = 0; b < 200; ++b) {
                double x = 2.0 * (a + 0.5) / 400.0, y = (b + 0.5) / 200.0, dA = (2.0 / 400.0) * (1.0 / 200.0);
                cdl_vec3 r = cdl_vec3_sub(cdl_vec3_make(x, y, 2.5), p);
                double r2 = cdl_vec3_dot(r, r), rl = sqrt(r2);
                double cos_e = r.z / rl, sin_t = sqrt(r.x * r.x + r.y * r.y) / rl; /* panel faces down: cos at it = r.z / r */
                sum += 500.0 * sin_t * cos_e * dA / r2;
            }
        double exact = sum / CDL_PI;
        CHECK_MSG(g->Ez_stderr && within_sigma(g->Ez[0], g->Ez_stderr[0], exact, 4.0), "panel: Ez %g +- %g, exact %g",
                  g->Ez[0], g->Ez_stderr ? g->Ez_stderr[0] : 0.0, exact);
        printf("luminous panel: Ez %.6g lx +- %.3g (quadrature %.6g)\n", g->Ez[0], g->Ez_stderr ? g->Ez_stderr[0] : 0.0,
               exact);
        fixture_release(scene, &sol);
    }
}

/* A small panel (0.3 x 0.3 m, 2000 cd/m2, facing down at 2.5 m) half
 * hidden by an opaque plate at 2.3 m: E_z by the midpoint rule on 300 x
 * 300 cells of the panel, each counted where the segment to the point
 * misses the plate (tested here, in closed form, at the plate's height). */
static void test_shadowed_panel(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1, -1, 2.3], \"u\": [1.15, 0, 0], "
        "\"v\": [0, 2, 0], \"reflectance\": 0}], \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": "
        "\"rect\", \"origin\": [0, 0, 2.5], \"u\": [0, 0.3, 0], \"v\": [0.3, 0, 0]}, \"luminance_cd_m2\": 2000}], "
        "\"grids\": [{\"name\": \"c\", \"type\": \"points\", \"outputs\": [\"cylindrical\", \"semicylindrical\"], "
        "\"points\": [{\"p\": [0.3, 0.1, 1.0], \"n\": [-1, 0, 0]}, {\"p\": [1.5, -0.4, 0.5], \"n\": [0, 1, 0]}]}], "
        "\"solver\": {\"quality\": \"draft\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; g->Ez_stderr && i < 2; ++i) {
        cdl_vec3 p = g->grid.points[i], f = g->grid.normals[i];
        double ez = 0.0, esz = 0.0, dA = (0.3 / 300.0) * (0.3 / 300.0);
        for (int a = 0; a < 300; ++a)
            for (int b = 0; b < 300; ++b) {
                cdl_vec3 q = cdl_vec3_make(0.3 * (a + 0.5) / 300.0, 0.3 * (b + 0.5) / 300.0, 2.5);
                cdl_vec3 r = cdl_vec3_sub(q, p);
                double t = (2.3 - p.z) / r.z; /* where the segment crosses the plate's plane */
                double x = p.x + t * r.x, y = p.y + t * r.y;
                if (x >= -1.0 && x <= 0.15 && y >= -1.0 && y <= 1.0) continue;
                double r2 = cdl_vec3_dot(r, r), rl = sqrt(r2);
                double w_h = sqrt(r.x * r.x + r.y * r.y) / rl, along = (r.x * f.x + r.y * f.y) / rl;
                double dw = (r.z / rl) * dA / r2;
                ez += 2000.0 * w_h * dw / CDL_PI;
                esz += 2000.0 * (w_h + along) * dw / CDL_PI;
            }
        CHECK_MSG(within_sigma(g->Ez[i], g->Ez_stderr[i], ez, 4.0), "half-hidden panel %zu: Ez %g +- %g, exact %g", i,
                  g->Ez[i], g->Ez_stderr[i], ez);
        CHECK_MSG(within_sigma(g->Esz[i], g->Esz_stderr[i], esz, 4.0), "half-hidden panel %zu: Esz %g +- %g, exact %g",
                  i, g->Esz[i], g->Esz_stderr[i], esz);
        printf("half-hidden panel: Ez %.6g lx +- %.3g (quadrature %.6g, %.2f sigma), Esz %.6g +- %.3g (%.6g)\n", g->Ez[i],
               g->Ez_stderr[i], ez, (g->Ez[i] - ez) / g->Ez_stderr[i], g->Esz[i], g->Esz_stderr[i], esz);
    }
    fixture_release(scene, &sol);
}

/* Outputs that cannot be computed are refused with the grid's JSON path
 * and what is missing, never returned as a part. */
static void expect_refusal(const char *json, const char *fragment)
{
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    CHECK(cdl_scene_load_string(json, "refuse.json", &scene, &err) == CDL_OK);
    if (!scene) return;
    cdl_solution sol;
    cdl_status st = cdl_solve_scene_into(scene, NULL, NULL, &sol, &err);
    CHECK_MSG(st == CDL_ERR_INPUT && strstr(err.message, fragment), "status %d, message %s", (int)st, err.message);
    if (st == CDL_OK) cdl_solution_clear(&sol);
    cdl_scene_release(scene);
}

static void test_refusals(void)
{
    expect_refusal("{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 2], "
                   "\"intensity_cd\": 100}], \"grids\": [{\"name\": \"c\", \"type\": \"points\", "
                   "\"outputs\": [\"semicylindrical\"], \"points\": [{\"p\": [0, 0, 1], \"n\": [0, 0, 1]}]}]}",
                   "expected points facing a horizontal direction for semicylindrical illuminance");
    expect_refusal("{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-2, -2, 0], \"u\": [4, 0, 0],"
                   " \"v\": [0, 4, 0], \"reflectance\": 0.5}],"
                   " \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 2], \"intensity_cd\": 100}],"
                   " \"grids\": [{\"name\": \"c\", \"type\": \"points\", \"outputs\": [\"luminance\"],"
                   " \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [0, 0, 0.8], \"n\": [0, 0, 1]}]}],"
                   " \"solver\": {\"method\": \"direct\"}}",
                   "expected a grid lying on a surface for \"luminance\" (rho E / pi of that surface), found point 1 "
                   "at [0, 0, 0.8]");
}

/* Polygon grids: the area_m2 column sums to the polygon's area (an L
 * shape, 4 x 4 minus 2 x 2 = 12 m^2), and Em recomputed from the CSV's
 * columns equals summary.json's (same sum, rounding of 17 digits apart). */
static void test_polygon_area_column(void)
{
    const char *json =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [1, 1, 2.5], \"intensity_cd\": 900}],"
        " \"grids\": [{\"name\": \"ell\", \"type\": \"polygon\", \"spacing\": 0.5,"
        " \"vertices\": [[0,0,0.8],[4,0,0.8],[4,2,0.8],[2,2,0.8],[2,4,0.8],[0,4,0.8]]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    char dir[512];
    snprintf(dir, sizeof dir, "%s/outputs_polygon", CANDELA_TEST_TMPDIR);
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_solution_prepare_folder(dir, &err) == CDL_OK);
    CHECK(cdl_solution_write(scene, &sol, dir, NULL, &err) == CDL_OK);
    char path[600];
    snprintf(path, sizeof path, "%s/ell.csv", dir);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    if (f) {
        char line[1024];
        CHECK(fgets(line, sizeof line, f) != NULL);
        CHECK(strcmp(line, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,area_m2\n") == 0);
        double area = 0.0, weighted = 0.0;
        size_t rows = 0;
        while (fgets(line, sizeof line, f)) {
            double v[11];
            CHECK(sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4],
                         &v[5], &v[6], &v[7], &v[8], &v[9], &v[10]) == 11);
            area += v[10];
            weighted += v[10] * v[6];
            ++rows;
        }
        fclose(f);
        CHECK(rows == sol.grids[0].grid.count);
        /* The triangles tile the polygon: their areas add up to it to rounding. */
        CHECK_REL(area, 12.0, 1e-12);
        cdl_grid_result r;
        cdl_grid_solution_result(&sol.grids[0], &r);
        cdl_grid_stats s;
        cdl_grid_result_stats(&r, &s);
        CHECK_REL(weighted / area, s.E_avg_lx, 1e-13);
        CHECK_REL(s.area_m2, 12.0, 1e-12);
    }
    fixture_release(scene, &sol);
}

/* A point lying on a surface sees nothing behind it: the vertical outputs
 * are the limit from the side the point's normal faces (issue: a floor
 * grid's cylinders stand on the floor, a wall grid's semicylinders on the
 * wall). Delta lights: a floor (z = 0) and a wall (x = -2, facing +x); A
 * below the floor, B behind the wall, C in front of both. Every grid point
 * lies on the floor or the wall, so only C reaches it: E_z = I_C sin(theta)
 * / (pi d^2), E_sz = I_C sin(theta) (1 + cos alpha) / (pi d^2). Before the
 * mask, A reached the floor points and B the wall points (no shadow ray:
 * the plan's box test, made for E's hemisphere, ignores surfaces that
 * only touch the grid). */
static void test_on_surface_hides_behind(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": ["
        "{\"type\": \"rect\", \"origin\": [-5, -5, 0], \"u\": [10, 0, 0], \"v\": [0, 10, 0], \"reflectance\": 0},"
        "{\"type\": \"rect\", \"origin\": [-2, -5, 0], \"u\": [0, 10, 0], \"v\": [0, 0, 4], \"reflectance\": 0}],"
        "\"luminaires\": ["
        "{\"name\": \"A\", \"type\": \"point\", \"position\": [1, 0, -1], \"intensity_cd\": 1000},"
        "{\"name\": \"B\", \"type\": \"point\", \"position\": [-3, 0, 1], \"intensity_cd\": 1000},"
        "{\"name\": \"C\", \"type\": \"point\", \"position\": [0.5, 0.3, 2], \"intensity_cd\": 500}],"
        "\"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"outputs\": [\"cylindrical\"], \"points\": ["
        "{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [1, 1, 0], \"n\": [0, 0, 1]}]},"
        "{\"name\": \"wall\", \"type\": \"points\", \"outputs\": [\"cylindrical\", \"semicylindrical\"], \"points\": ["
        "{\"p\": [-2, 0, 1.5], \"n\": [1, 0, 0]}, {\"p\": [-2, 1, 2.5], \"n\": [1, 0, 0]}]}],"
        "\"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_vec3 c = cdl_vec3_make(0.5, 0.3, 2.0);
    for (size_t g = 0; g < 2; ++g) {
        const cdl_grid_solution *gs = &sol.grids[g];
        CHECK(gs->Ez != NULL);
        for (size_t i = 0; gs->Ez && i < gs->grid.count; ++i) {
            cdl_vec3 d = cdl_vec3_sub(c, gs->grid.points[i]);
            double d2 = cdl_vec3_dot(d, d), r = sqrt(d2);
            double sin_t = sqrt(d.x * d.x + d.y * d.y) / r, cos_a = d.x / sqrt(d.x * d.x + d.y * d.y);
            double Ez = 500.0 / d2 * sin_t / CDL_PI;
            /* the same I / d^2 and sin by other roundings: a few ulps */
            CHECK_MSG(fabs(gs->Ez[i] - Ez) <= 1e-12 * Ez, "%s point %zu: Ez %.10g, only C gives %.10g",
                      scene->grids[g].name, i, gs->Ez[i], Ez);
            if (gs->Esz) {
                double Esz = 500.0 / d2 * sin_t * (1.0 + cos_a) / CDL_PI;
                CHECK_MSG(fabs(gs->Esz[i] - Esz) <= 1e-12 * Esz, "wall point %zu: Esz %.10g, only C gives %.10g", i,
                          gs->Esz[i], Esz);
            }
        }
    }
    fixture_release(scene, &sol);

    /* Sampled: a full uniform sky L over the same floor and, apart, a wall
     * (x = 20, facing +x, wholly below the floor: neither sees the other
     * from its front). On the floor only the upper hemisphere is seen: E_z = (1 / pi) L 2 pi
     * int_0^pi/2 sin^2 = pi L / 2, estimated exactly (the strata split at
     * the horizon). On the wall (facing +x) the half-space w_x > 0:
     * int sin(theta) dw there = pi^2 / 2 and int w_x dw = pi, so E_z = pi L
     * / 2 and E_sz = (L / pi)(pi^2 / 2 + pi) = L (pi / 2 + 1); sampled at
     * normal, within 4 stated sigma. Seen through the surface they would be pi L. */
    const double L = 1000.0;
    const char *sky =
        "{\"version\": 1, \"surfaces\": ["
        "{\"type\": \"rect\", \"origin\": [-5, -5, 0], \"u\": [10, 0, 0], \"v\": [0, 10, 0], \"reflectance\": 0},"
        "{\"type\": \"rect\", \"origin\": [20, -5, -30], \"u\": [0, 10, 0], \"v\": [0, 0, 10], \"reflectance\": 0}],"
        "\"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 1000}],"
        "\"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"outputs\": [\"cylindrical\"], \"points\": ["
        "{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [1, 1, 0], \"n\": [0, 0, 1]}]},"
        "{\"name\": \"wall\", \"type\": \"points\", \"outputs\": [\"cylindrical\", \"semicylindrical\"], \"points\": ["
        "{\"p\": [20, 0, -25], \"n\": [1, 0, 0]}, {\"p\": [20, 1, -23], \"n\": [1, 0, 0]}]}],"
        "\"solver\": {\"method\": \"direct\", \"quality\": \"normal\"}}";
    if (!fixture_solve(sky, &scene, &sol, 2)) return;
    const cdl_grid_solution *fl = &sol.grids[0], *wl = &sol.grids[1];
    for (size_t i = 0; fl->Ez_stderr && i < 2; ++i) {
        CHECK_MSG(fabs(fl->Ez[i] - CDL_PI * L / 2.0) <= 1e-9 * L, "floor point %zu: Ez %.10g, exact %.10g", i,
                  fl->Ez[i], CDL_PI * L / 2.0);
        CHECK(fl->Ez_stderr[i] < 1e-9 * L);
    }
    for (size_t i = 0; wl->Ez_stderr && wl->Esz_stderr && i < 2; ++i) {
        double ez = CDL_PI * L / 2.0, esz = L * (CDL_PI / 2.0 + 1.0);
        CHECK_MSG(within_sigma(wl->Ez[i], wl->Ez_stderr[i], ez, 4.0), "wall point %zu: Ez %g +- %g, exact %g", i,
                  wl->Ez[i], wl->Ez_stderr[i], ez);
        CHECK_MSG(within_sigma(wl->Esz[i], wl->Esz_stderr[i], esz, 4.0), "wall point %zu: Esz %g +- %g, exact %g", i,
                  wl->Esz[i], wl->Esz_stderr[i], esz);
        /* Both held to the target, 0.5 % at normal (E_sz used to get only
         * the samples E_z asked for, which can be none beyond the pilot),
         * within the factor 1.5. */
        CHECK_MSG(wl->Ez_stderr[i] < 1.5 * 0.005 * ez, "Ez stated %g", wl->Ez_stderr[i]);
        CHECK_MSG(wl->Esz_stderr[i] < 1.5 * 0.005 * esz && wl->Esz_stderr[i] > 0.0, "Esz stated %g",
                  wl->Esz_stderr[i]);
        printf("on a wall under a uniform sky: Ez %.6g +- %.3g (exact %.6g), Esz %.6g +- %.3g (exact %.6g)\n",
               wl->Ez[i], wl->Ez_stderr[i], ez, wl->Esz[i], wl->Esz_stderr[i], esz);
    }
    fixture_release(scene, &sol);
}

int main(void)
{
    test_point_source_closed_forms();
    test_shadowed_spot();
    test_luminance();
    test_refusals();
    test_vertical_channels();
    test_sampled_vertical();
    test_shadowed_panel();
    test_polygon_area_column();
    test_on_surface_hides_behind();
    return check_finish();
}
