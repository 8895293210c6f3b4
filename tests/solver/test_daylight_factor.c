/* Daylight factor (grid output "daylight_factor", DF_percent = 100 E / E_h
 * under the CIE overcast sky, E_h = 7 pi L_z / 9):
 *  - 100 % on an unobstructed plane, with a reflecting floor below it
 *    (nothing it reflects reaches a plane facing up from above it), and
 *    for ISO 15469's type 1 sky as well (E_h its own);
 *  - a window in a wall of a black room: at floor points the sky seen
 *    through the window, computed here from the overcast formula, nothing
 *    of the solver's: for a floor point p = (px, py, 0) and a point q =
 *    (0, y, z) of the window in the wall x = 0, r = |q - p|, the zenith
 *    angle and the receiver's angle have cosine z / r, the window's px / r,
 *    and dw = (px / r) dA / r^2, so
 *        E = (L_z / 3) int_window [z px / r^4 + 2 z^2 px / r^5] dy dz,
 *    by a composite Gauss-Legendre rule (doubled until it settles to 1e-12);
 *    the solver samples the visible sky (its luminance varies over it):
 *    within 4 stated sigmas, at "high" (0.1 %);
 *  - the same room with reflecting walls, floor and ceiling (0.5): the
 *    irradiance cache's DF against path tracing's at two points, within 4
 *    combined sigmas, and above the direct part alone (interreflection
 *    included);
 *  - the CSV column, the summary statistic and the plan; a scene lit by
 *    anything else than the overcast sky alone refused, naming the grid.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "gauss16.h"
#include "solver/solve_fixture.h"

#define LZ 8000.0
#define WIN_Y0 1.5
#define WIN_Y1 3.5
#define WIN_Z0 0.9
#define WIN_Z1 2.4

/* int over the window of z px / r^4 (term 0) or 2 z^2 px / r^5 (term 1), m x m parts */
static double window_integral(int term, double px, double py, int m)
{
    double x[16 * 32], w[16 * 32], sum = 0.0;
    gauss16_composite(m, x, w);
    for (int i = 0; i < 16 * m; ++i)
        for (int j = 0; j < 16 * m; ++j) {
            double y = WIN_Y0 + (WIN_Y1 - WIN_Y0) * x[i], z = WIN_Z0 + (WIN_Z1 - WIN_Z0) * x[j];
            double r2 = px * px + (y - py) * (y - py) + z * z, r = sqrt(r2);
            double f = term == 0 ? z * px / (r2 * r2) : 2.0 * z * z * px / (r2 * r2 * r);
            sum += w[i] * w[j] * f;
        }
    return sum * (WIN_Y1 - WIN_Y0) * (WIN_Z1 - WIN_Z0);
}

/* DF at floor point (px, py) through the window, percent */
static double window_df(double px, double py)
{
    double total = 0.0;
    for (int term = 0; term < 2; ++term) {
        double prev = window_integral(term, px, py, 1), next = prev;
        for (int m = 2; m <= 32; m *= 2) {
            next = window_integral(term, px, py, m);
            if (fabs(next - prev) <= 1e-12 * fabs(next)) break;
            prev = next;
        }
        CHECK_MSG(fabs(next - prev) <= 1e-12 * fabs(next), "window quadrature did not settle");
        total += next;
    }
    return 100.0 * (LZ / 3.0 * total) / (7.0 * CDL_PI * LZ / 9.0);
}

/* A 6 x 5 x 3 m room, the window in the wall x = 0 (the box's -x face
 * open, that wall a polygon with the window as its hole). */
static void room_json(char *out, size_t size, double rho, int nu, int nv, const char *solver)
{
    snprintf(out, size,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], "
             "\"inward\": true, \"reflectance\": %g, \"open\": [\"-x\"]},"
             " {\"type\": \"polygon\", \"vertices\": [[0, 0, 0], [0, 5, 0], [0, 5, 3], [0, 0, 3]],"
             " \"holes\": [[[0, %g, %g], [0, %g, %g], [0, %g, %g], [0, %g, %g]]], \"reflectance\": %g}],"
             " \"luminaires\": [{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": %g}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0.5, 0.5, 0.001], \"u\": [5, 0, 0],"
             " \"v\": [0, 4, 0], \"nu\": %d, \"nv\": %d, \"outputs\": [\"daylight_factor\"]}],"
             " \"solver\": {%s, \"seed\": 7}}",
             rho, WIN_Y0, WIN_Z0, WIN_Y1, WIN_Z0, WIN_Y1, WIN_Z1, WIN_Y0, WIN_Z1, rho, LZ, nu, nv, solver);
}

static void test_unobstructed(void)
{
    const char *skies[2] = {"\"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 5000",
                            "\"sky\": \"cie\", \"cie_type\": 1, \"diffuse_horizontal_illuminance_lx\": 12000"};
    for (int k = 0; k < 2; ++k) {
        char json[1024];
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-5, -5, 0], \"u\": [10, 0, 0], "
                 "\"v\": [0, 10, 0], \"reflectance\": 0.5}],"
                 " \"luminaires\": [{\"type\": \"environment\", %s}],"
                 " \"grids\": [{\"name\": \"open\", \"type\": \"rect\", \"origin\": [-1, -1, 0.8], \"u\": [2, 0, 0], "
                 "\"v\": [0, 2, 0], \"nu\": 3, \"nv\": 3, \"outputs\": [\"daylight_factor\"]}],"
                 " \"solver\": {\"method\": \"pathtrace\", \"quality\": \"draft\"}}",
                 skies[k]);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 2)) continue;
        const cdl_grid_solution *g = &sol.grids[0];
        CHECK(g->DF != NULL);
        /* the closed form and the sky's quadrature over itself: to rounding (and 3e-8) */
        for (size_t i = 0; g->DF && i < g->grid.count; ++i) CHECK_REL(g->DF[i], 100.0, 1e-7);
        CHECK(strstr(sol.plan_json, "\"daylight_factor\"") && strstr(sol.plan_json, "100 E / E_h"));
        fixture_release(scene, &sol);
    }
}

static void test_black_room(void)
{
    char json[2048];
    room_json(json, sizeof json, 0.0, 4, 3, "\"method\": \"direct\", \"quality\": \"high\"");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    double E_h = 7.0 * CDL_PI * LZ / 9.0, worst = 0.0;
    for (size_t i = 0; i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double want = window_df(p.x, p.y), df = g->DF[i], sigma = 100.0 * g->E_stderr[i] / E_h;
        CHECK_REL(df, 100.0 * g->E[i] / E_h, 1e-15);
        CHECK_MSG(fabs(df - want) <= 4.0 * sigma + 1e-9, "point %zu: DF %.6f +- %.2g %%, expected %.6f %%", i, df,
                  sigma, want);
        /* and the stated error near the target, 0.1 % of E */
        CHECK_MSG(sigma <= 1.5 * 0.001 * df, "point %zu: sigma %.3g of %.4g", i, sigma, df);
        worst = fmax(worst, fabs(df - want) / fmax(sigma, 1e-12));
    }
    printf("black room: %zu points within %.2f stated sigma of the window's integral\n", g->grid.count, worst);
    fixture_release(scene, &sol);
}

static void test_reflecting_room(void)
{
    char json[2048];
    /* two points at 4 %: path tracing through a window costs (next-event
     * samples of the sky mostly hidden by the walls), 9 s at this target */
    room_json(json, sizeof json, 0.5, 2, 1, "\"method\": \"icache\", \"target_error\": 0.04");
    cdl_scene *s1, *s2;
    cdl_solution cache, paths;
    if (!fixture_solve(json, &s1, &cache, 2)) return;
    room_json(json, sizeof json, 0.5, 2, 1, "\"method\": \"pathtrace\", \"target_error\": 0.04");
    if (!fixture_solve(json, &s2, &paths, 2)) {
        fixture_release(s1, &cache);
        return;
    }
    double E_h = 7.0 * CDL_PI * LZ / 9.0;
    const cdl_grid_solution *a = &cache.grids[0], *b = &paths.grids[0];
    for (size_t i = 0; i < a->grid.count; ++i) {
        double sa = 100.0 * a->E_stderr[i] / E_h, sb = 100.0 * b->E_stderr[i] / E_h;
        CHECK_MSG(fabs(a->DF[i] - b->DF[i]) <= 4.0 * sqrt(sa * sa + sb * sb),
                  "point %zu: icache DF %.5f +- %.2g, pathtrace %.5f +- %.2g", i, a->DF[i], sa, b->DF[i], sb);
        /* interreflection adds: more than the direct part alone */
        CHECK(a->E_indirect[i] > 0.0 && b->DF[i] > 100.0 * b->E_direct[i] / E_h);
    }
    printf("reflecting room: DF from %.3f to %.3f %% (icache), %.3f to %.3f %% (pathtrace)\n", a->DF[0],
           a->DF[a->grid.count - 1], b->DF[0], b->DF[b->grid.count - 1]);
    fixture_release(s1, &cache);
    fixture_release(s2, &paths);
}

static void test_refused(void)
{
    const char *lights[3] = {
        "{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 5000}, "
        "{\"type\": \"point\", \"position\": [0, 0, 3], \"intensity_cd\": 100}",
        "{\"type\": \"environment\", \"luminance_cd_m2\": 5000}",
        "{\"type\": \"environment\", \"sky\": \"cie\", \"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, \"sun\": "
        "{\"azimuth_deg\": 180, \"altitude_deg\": 40}}"};
    for (int k = 0; k < 3; ++k) {
        char json[1024];
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"luminaires\": [%s], \"grids\": [{\"name\": \"g\", \"type\": \"points\", "
                 "\"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}], \"outputs\": [\"daylight_factor\"]}]}",
                 lights[k]);
        cdl_scene *scene = NULL;
        cdl_solution *sol = NULL;
        cdl_error err;
        CHECK_OK(cdl_scene_load_string(json, "df.json", &scene, &err), &err);
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        CHECK(cdl_solve_scene(scene, &o, &sol, &err) == CDL_ERR_INPUT);
        CHECK_MSG(strstr(err.message, "df.json: grids[0].outputs: expected a scene lit by one CIE overcast sky alone"),
                  "%s", err.message);
        cdl_solution_release(sol);
        cdl_scene_release(scene);
    }
}

int main(void)
{
    test_unobstructed();
    test_black_room();
    test_reflecting_room();
    test_refused();
    return check_finish();
}
