/* Glass ("transmittance": a thin pane, radiometry/glass.h) in the solver,
 * against closed forms with the pane's angular transmittance T(theta)
 * written here apart (Snell, Fresnel's s and p reflectances at n = 1.52,
 * the internal transmittance a^(1 / cos theta_t), the slab's series) and
 * integrated here:
 *  - parallel light through a pane of T_n = 0.8: 0.8 E_n at normal
 *    incidence, T(60 deg) E_n cos 60 deg at 60 degrees (exact: one shadow
 *    ray carries the transmittance), 0 through glass behind an opaque sheet;
 *  - a uniform sky (upper hemisphere) under a horizontal pane far larger
 *    than its height: pi L T_h, T_h = 2 int T cos sin dtheta the pane's
 *    hemispherical transmittance (the open value times T_h / 1, where the
 *    normal value would give 0.8); sampled with shadow rays, within 4
 *    stated sigmas; and without the pane pi L exactly;
 *  - a vertical window pane in a black room under the uniform sky, at
 *    floor points: L int over the window of T(theta_w) (z / r)(px / r) /
 *    r^2 dA (theta_w the incidence on the pane, cos = px / r), by a
 *    composite Gauss-Legendre rule; within 4 stated sigmas;
 *  - interreflection through glass, a closed form: a white floor (rho)
 *    under a pane of glass under the uniform sky, a point above the pane
 *    facing down. The floor receives pi L T_h through the pane and, being
 *    an infinite Lambertian plane, has luminance rho L T_h everywhere; the
 *    point sees it through the pane again: E = pi rho L T_h^2 (all of it
 *    interreflected: the sky is behind the point's plane). Both methods,
 *    within 4 stated sigmas. (The planes are 2 km squares at 1 m: what
 *    they miss of the hemisphere is below 1e-6.)
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "gauss16.h"
#include "solver/solve_fixture.h"

#define TN 0.8
#define L_SKY 1000.0

/* T(theta) of a pane of normal transmittance TN, cos_i the incidence's cosine */
static double pane(double cos_i)
{
    const double n = 1.52, r0 = pow((n - 1) / (n + 1), 2), q = (1 - r0) * (1 - r0);
    /* a from T_n = a q / (1 - r0^2 a^2) */
    double a = (-q + sqrt(q * q + 4 * r0 * r0 * TN * TN)) / (2 * r0 * r0 * TN);
    double sin_t = sqrt(1 - cos_i * cos_i) / n, cos_t = sqrt(1 - sin_t * sin_t);
    double rs = pow((cos_i - n * cos_t) / (cos_i + n * cos_t), 2), rp = pow((n * cos_i - cos_t) / (n * cos_i + cos_t), 2);
    double t = pow(a, 1 / cos_t);
    return 0.5 * (t * (1 - rs) * (1 - rs) / (1 - rs * rs * t * t) + t * (1 - rp) * (1 - rp) / (1 - rp * rp * t * t));
}

/* T_h = 2 int_0^(pi/2) T cos sin dtheta, 16-point rule on 64 parts (to 1e-14) */
static double hemispherical(void)
{
    static double x[16 * 64], w[16 * 64];
    gauss16_composite(64, x, w);
    double s = 0;
    for (int i = 0; i < 16 * 64; ++i) {
        double th = 0.5 * CDL_PI * x[i];
        s += w[i] * pane(cos(th)) * cos(th) * sin(th);
    }
    return 2 * s * 0.5 * CDL_PI;
}

static int solve(const char *json, cdl_scene **scene, cdl_solution *sol)
{
    return fixture_solve(json, scene, sol, 2);
}

static void test_parallel(void)
{
    double c60 = cos(60.0 * CDL_DEG_TO_RAD), s60 = sin(60.0 * CDL_DEG_TO_RAD);
    char json[1200];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-50, -50, 2], \"u\": [100, 0, 0], "
             "\"v\": [0, 100, 0], \"transmittance\": %g},"
             " {\"type\": \"rect\", \"origin\": [20, -5, 3], \"u\": [10, 0, 0], \"v\": [0, 10, 0], \"reflectance\": 0}],"
             " \"luminaires\": [{\"type\": \"directional\", \"direction\": [0, 0, -1], \"illuminance_lx\": 1000},"
             " {\"type\": \"directional\", \"direction\": [%.17g, 0, %.17g], \"illuminance_lx\": 2000}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]},"
             " {\"p\": [21, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [-60, 0, 0], \"n\": [0, 0, 1]},"
             " {\"p\": [25, 0, 0], \"n\": [0, 0, 1]}]}],"
             " \"solver\": {\"method\": \"direct\"}}",
             TN, -s60, -c60);
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol)) return;
    const double *E = sol.grids[0].E;
    /* (0, 0): both beams through the pane. (21, 0): both through the pane
     * and then stopped by the sheet over x in [20, 30] at 3 m (the slanted
     * one, towards (sin 60, 0, cos 60), crosses z = 3 at x = 21 + 3 tan 60
     * = 26.2). (-60, 0): both miss the pane (the slanted one crosses z = 2
     * at x = -56.5). (25, 0): the vertical beam stopped by the sheet, the
     * slanted one through the pane (at x = 28.5) and past the sheet's edge
     * (at x = 30.2). */
    CHECK_REL(E[0], TN * 1000.0 + pane(c60) * 2000.0 * c60, 1e-12);
    CHECK_ABS(E[1], 0.0, 1e-12);
    CHECK_REL(E[2], 1000.0 + 2000.0 * c60, 1e-12);
    CHECK_REL(E[3], pane(c60) * 2000.0 * c60, 1e-12);
    CHECK(sol.grids[0].E_stderr[0] == 0.0);
    fixture_release(scene, &sol);
}

static void test_sky_under_pane(void)
{
    const char *base = "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1000, -1000, 1], \"u\": "
                       "[2000, 0, 0], \"v\": [0, 2000, 0], %s}],"
                       " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": %g, \"hemisphere\": "
                       "\"upper\"}],"
                       " \"grids\": [{\"name\": \"p\", \"type\": \"rect\", \"origin\": [-0.5, -0.5, 0], \"u\": [1, 0, 0], "
                       "\"v\": [0, 1, 0], \"nu\": 3, \"nv\": 3}], \"solver\": {\"method\": \"direct\", \"quality\": "
                       "\"high\"}}";
    char json[1200], material[64];
    snprintf(material, sizeof material, "\"transmittance\": %g", TN);
    snprintf(json, sizeof json, base, material, L_SKY);
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol)) return;
    double Th = hemispherical(), want = CDL_PI * L_SKY * Th;
    printf("hemispherical transmittance of T_n = %g: %.6f\n", TN, Th);
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i) {
        CHECK_MSG(fabs(g->E[i] - want) <= 4.0 * g->E_stderr[i], "point %zu: %.6f +- %.3g, expected %.6f", i, g->E[i],
                  g->E_stderr[i], want);
        CHECK(g->E_stderr[i] > 0.0 && g->E_stderr[i] <= 1.5 * 0.001 * want);
    }
    CHECK(strstr(sol.plan_json, "seen through glass"));
    fixture_release(scene, &sol);
    /* the pane's surface made opaque and black: nothing; the open sky
     * beyond a 2 km pane at 1 m (tan 89.94 deg): below 1e-6 of pi L */
    snprintf(json, sizeof json, base, "\"reflectance\": 0", L_SKY);
    if (!solve(json, &scene, &sol)) return;
    for (size_t i = 0; i < sol.grids[0].grid.count; ++i) CHECK(sol.grids[0].E[i] < 1e-6 * CDL_PI * L_SKY);
    fixture_release(scene, &sol);
}

/* the window x = 0, y in [1.5, 3.5], z in [0.9, 2.4]; floor point (px, py, 0) */
static double window_E(double px, double py)
{
    static double x[16 * 8], w[16 * 8];
    gauss16_composite(8, x, w);
    double s = 0;
    for (int i = 0; i < 16 * 8; ++i)
        for (int j = 0; j < 16 * 8; ++j) {
            double y = 1.5 + 2.0 * x[i], z = 0.9 + 1.5 * x[j];
            double r2 = px * px + (y - py) * (y - py) + z * z, r = sqrt(r2);
            s += w[i] * w[j] * pane(px / r) * (z / r) * (px / r) / r2;
        }
    return L_SKY * s * 2.0 * 1.5;
}

static void test_window(void)
{
    char json[1600];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": "
             "true, \"reflectance\": 0, \"open\": [\"-x\"]},"
             " {\"type\": \"polygon\", \"vertices\": [[0, 0, 0], [0, 5, 0], [0, 5, 3], [0, 0, 3]], \"holes\": [[[0, "
             "1.5, 0.9], [0, 3.5, 0.9], [0, 3.5, 2.4], [0, 1.5, 2.4]]], \"reflectance\": 0},"
             " {\"type\": \"rect\", \"origin\": [0, 1.5, 0.9], \"u\": [0, 2, 0], \"v\": [0, 0, 1.5], \"transmittance\": "
             "%g}],"
             " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": %g, \"hemisphere\": \"upper\"}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0.5, 0.5, 0.001], \"u\": [5, 0, 0],"
             " \"v\": [0, 4, 0], \"nu\": 3, \"nv\": 2}], \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}",
             TN, L_SKY);
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double want = window_E(p.x, p.y);
        CHECK_MSG(fabs(g->E[i] - want) <= 4.0 * g->E_stderr[i] + 1e-9, "point %zu: %.6f +- %.3g, expected %.6f", i,
                  g->E[i], g->E_stderr[i], want);
    }
    fixture_release(scene, &sol);
}

static void test_interreflection(const char *method)
{
    const double rho = 0.6;
    char json[1500];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1000, -1000, 0], \"u\": [2000, 0, 0], "
             "\"v\": [0, 2000, 0], \"reflectance\": %g},"
             " {\"type\": \"rect\", \"origin\": [-1000, -1000, 1], \"u\": [2000, 0, 0], \"v\": [0, 2000, 0], "
             "\"transmittance\": %g}],"
             " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": %g, \"hemisphere\": \"upper\"}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 2], \"n\": [0, 0, -1]},"
             " {\"p\": [3, 7, 1.5], \"n\": [0, 0, -1]}]}], \"solver\": {\"method\": \"%s\", \"quality\": \"normal\"}}",
             rho, TN, L_SKY, method);
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve(json, &scene, &sol)) return;
    double Th = hemispherical(), want = CDL_PI * rho * L_SKY * Th * Th;
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i) {
        CHECK_ABS(g->E_direct[i], 0.0, 1e-12);
        CHECK_MSG(fabs(g->E[i] - want) <= 4.0 * g->E_stderr[i], "%s point %zu: %.6f +- %.3g, expected %.6f", method, i,
                  g->E[i], g->E_stderr[i], want);
        printf("%s: E %.4f +- %.3g, expected pi rho L T_h^2 = %.4f\n", method, g->E[i], g->E_stderr[i], want);
    }
    fixture_release(scene, &sol);
}

int main(void)
{
    test_parallel();
    test_sky_under_pane();
    test_window();
    test_interreflection("pathtrace");
    test_interreflection("icache");
    return check_finish();
}
