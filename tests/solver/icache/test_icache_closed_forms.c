/* The irradiance cache against closed forms of interreflection (see
 * tests/solver/pathtrace for the physics of each), and the honesty of its
 * stated errors:
 *  - the furnace: a closed box whose walls emit L and reflect rho gives
 *    E = pi L / (1 - rho) at every point inside;
 *  - the integrating sphere: a source of flux Phi inside a sphere of area A
 *    and reflectance rho gives every point of the wall the interreflected
 *    illuminance rho Phi / (A (1 - rho)).
 * Both fields are uniform, so what the cache states is what its records'
 * noise and its interpolation could have done; the tally checks that about
 * two thirds of points lie within one stated sigma and 95 % within two. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/solve_fixture.h"

static calibration tally = CALIBRATION_INIT;

/* A 4 m furnace with a 12 x 12 grid across its middle (normals up) and a
 * 12 x 8 grid on a wall (normals inward). */
static void test_furnace(double rho, double target)
{
    const double L = 100.0;
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,4], \"inward\": true, "
             "\"reflectance\": %.17g, \"luminance_cd_m2\": %.17g}], \"grids\": ["
             "{\"name\": \"mid\", \"type\": \"rect\", \"origin\": [0.2,0.2,1.3], \"u\": [3.6,0,0], \"v\": [0,3.6,0], "
             "\"nu\": 12, \"nv\": 12},"
             "{\"name\": \"wall\", \"type\": \"rect\", \"origin\": [0,0.2,0.2], \"u\": [0,3.6,0], \"v\": [0,0,3.6], "
             "\"nu\": 12, \"nv\": 8}],"
             " \"solver\": {\"method\": \"icache\", \"target_error\": %.17g}}",
             rho, L, target);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    double expected = CDL_PI * L / (1.0 - rho);
    CHECK(sol.records > 0);
    for (size_t g = 0; g < sol.grid_count; ++g) {
        const cdl_grid_solution *gs = &sol.grids[g];
        for (size_t i = 0; i < gs->grid.count; ++i) {
            CHECK_MSG(fabs(gs->E[i] - expected) <= 5.0 * gs->E_stderr[i],
                      "icache furnace rho %g grid %zu point %zu: %.6g +- %.3g, expected %.6g", rho, g, i, gs->E[i],
                      gs->E_stderr[i], expected);
            /* The stated error is held to the target (within the factor
             * 1.5 a pilot-planned gather may miss it by). */
            CHECK_MSG(gs->E_stderr[i] <= 1.5 * target * expected, "icache furnace rho %g: stated %.3g, target %.3g",
                      rho, gs->E_stderr[i], target * expected);
            calibration_add(&tally, gs->E[i], expected, gs->E_stderr[i], target);
        }
    }
    fixture_release(scene, &sol);
}

/* n well-spread unit vectors (a Fibonacci sphere). */
static cdl_vec3 spread(int i, int n)
{
    double z = 1.0 - (2.0 * i + 1.0) / n;
    double r = sqrt(fmax(0.0, 1.0 - z * z));
    double phi = i * CDL_PI * (3.0 - sqrt(5.0));
    return cdl_vec3_make(r * cos(phi), r * sin(phi), z);
}

/* A sphere of radius 1, inward, lit by a point source of 1000 lm off its
 * centre; 120 points on the wall facing the centre. */
static void test_sphere(double rho, double target)
{
    static char json[32768];
    int at = snprintf(json, sizeof json,
                      "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, "
                      "\"inward\": true, \"reflectance\": %.17g}], \"luminaires\": [{\"type\": \"point\", "
                      "\"position\": [0.3,0.2,-0.4], \"flux_lm\": 1000}], \"grids\": [{\"name\": \"wall\", "
                      "\"type\": \"points\", \"points\": [",
                      rho);
    const int n = 120;
    for (int i = 0; i < n; ++i) {
        cdl_vec3 u = spread(i, n);
        at += snprintf(json + at, sizeof json - (size_t)at, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}",
                       i ? ", " : "", u.x, u.y, u.z, -u.x, -u.y, -u.z);
    }
    snprintf(json + at, sizeof json - (size_t)at,
             "]}], \"solver\": {\"method\": \"icache\", \"target_error\": %.17g}}", target);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    double expected = rho * 1000.0 / (4.0 * CDL_PI * (1.0 - rho));
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i) {
        CHECK_MSG(fabs(g->E_indirect[i] - expected) <= 5.0 * g->E_stderr[i],
                  "icache sphere rho %g point %zu: indirect %.6g +- %.3g, expected %.6g", rho, i, g->E_indirect[i],
                  g->E_stderr[i], expected);
        calibration_add(&tally, g->E_indirect[i], expected, g->E_stderr[i], 0.0);
    }
    fixture_release(scene, &sol);
}

int main(void)
{
    test_furnace(0.5, 0.01);
    test_furnace(0.9, 0.01);
    test_sphere(0.1, 0.01);
    test_sphere(0.5, 0.01);
    test_sphere(0.95, 0.01);
    calibration_check(&tally, "irradiance cache");
    return check_finish();
}
