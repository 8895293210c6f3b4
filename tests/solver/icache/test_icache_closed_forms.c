/* The irradiance cache against closed forms of interreflection (see
 * tests/solver/pathtrace for the physics of each), and the honesty of its
 * stated errors:
 *  - the furnace: a closed box whose walls emit L and reflect rho gives
 *    E = pi L / (1 - rho) at every point inside;
 *  - the integrating sphere: a source of flux Phi inside a sphere of area A
 *    and reflectance rho gives every point of the wall the interreflected
 *    illuminance rho Phi / (A (1 - rho)), whatever the source's
 *    distribution (point, spot, goniometric);
 *  - the open white furnace: white two-sided plates under a uniform sky of
 *    luminance L: E = pi L everywhere.
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
    /* rho 0: nothing to interreflect, so no record is gathered, and the
     * walls' light is direct (closed forms: exact). */
    CHECK(rho > 0.0 ? sol.records > 0 : sol.records == 0);
    for (size_t g = 0; g < sol.grid_count; ++g) {
        const cdl_grid_solution *gs = &sol.grids[g];
        for (size_t i = 0; i < gs->grid.count; ++i) {
            CHECK_MSG(fabs(gs->E[i] - expected) <= 5.0 * gs->E_stderr[i] + 1e-9 * expected,
                      "icache furnace rho %g grid %zu point %zu: %.6g +- %.3g, expected %.6g", rho, g, i, gs->E[i],
                      gs->E_stderr[i], expected);
            /* The stated error is held to the target (within the factor
             * 1.5 a pilot-planned gather may miss it by). */
            CHECK_MSG(gs->E_stderr[i] <= 1.5 * target * expected, "icache furnace rho %g: stated %.3g, target %.3g",
                      rho, gs->E_stderr[i], target * expected);
            if (rho > 0.0) calibration_add(&tally, gs->E[i], expected, gs->E_stderr[i], target);
        }
    }
    fixture_release(scene, &sol);
}

/* A sphere of radius 1, inward, lit by `luminaire` (JSON) of flux `flux`
 * inside it; n points on the wall facing the centre. */
static void test_sphere(double rho, const char *luminaire, double flux, int n, double target, const char *what)
{
    char label[128];
    snprintf(label, sizeof label, "icache sphere (%s) rho %g, indirect", what, rho);
    fixture_sphere_check(rho, luminaire, flux, n, "icache", target, &tally, label);
}

/* The open white furnace: white (rho 1) two-sided plates under a uniform
 * sky of luminance L; every point, on a plate or between them, facing any
 * way, receives E = pi L (the plates return all they receive). */
static void test_white_furnace(void)
{
    const double L = 2000.0;
    const char *json =
        WHITE_FURNACE_SCENE
        " \"grids\": [{\"name\": \"between\", \"type\": \"rect\", \"origin\": [0.2,0.2,1.25], \"u\": [1.6,0,0], "
        "\"v\": [0,1.6,0], \"nu\": 8, \"nv\": 8},"
        " {\"name\": \"under\", \"type\": \"rect\", \"origin\": [0.2,0.2,1], \"u\": [0,1.6,0], \"v\": [1.6,0,0], "
        "\"nu\": 8, \"nv\": 8},"
        " {\"name\": \"beside\", \"type\": \"rect\", \"origin\": [1.9,0.2,0.2], \"u\": [0,1.6,0], \"v\": [0,0,0.6], "
        "\"nu\": 8, \"nv\": 3, \"normal\": [1,0,0]}],"
        " \"solver\": {\"method\": \"icache\", \"target_error\": 0.01}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    CHECK(sol.records > 0);
    fixture_check_all(&sol, CDL_PI * L, 0, &tally, 0.01, "icache white furnace");
    /* Between plates 0.5 m apart the records' gathers see mostly each
     * other's light: the stated error must still reach the 1 % target
     * (points above it get records of their own) - measured at most 0.99 %;
     * 1.5x allows for the last gather's own noise in its stated variance. */
    for (size_t g = 0; g < sol.grid_count; ++g)
        for (size_t i = 0; i < sol.grids[g].grid.count; ++i)
            CHECK_MSG(sol.grids[g].E_stderr[i] <= 1.5 * 0.01 * CDL_PI * L,
                      "white furnace grid %zu point %zu: stated %.3g lx, target %.3g lx", g, i, sol.grids[g].E_stderr[i],
                      0.01 * CDL_PI * L);
    fixture_release(scene, &sol);
}

int main(void)
{
    test_furnace(0.0, 0.01);
    test_furnace(0.5, 0.01);
    test_furnace(0.9, 0.01);
    const char *point = "{\"type\": \"point\", \"position\": [0.3,0.2,-0.4], \"flux_lm\": 1000}";
    /* cos^3 spot: flux 2 pi I0 / (n + 1) = pi I0 / 2 for n = 3 */
    const char *spot = "{\"type\": \"spot\", \"position\": [0,0,0.2], \"direction\": [0.3,0,-1], \"intensity_cd\": 500, "
                       "\"exponent\": 3}";
    /* the sphere's closed form is for a source that absorbs nothing: the
     * downlight's body (its black opening) is left out */
    const char *gonio = "{\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR
                        "/data/office/downlight.ies\", \"position\": [0,0,0.5], \"flux_lm\": 3000, \"body\": false}";
    test_sphere(0.1, point, 1000.0, 120, 0.01, "point");
    test_sphere(0.5, point, 1000.0, 120, 0.01, "point");
    test_sphere(0.95, point, 1000.0, 120, 0.01, "point");
    test_sphere(0.1, spot, CDL_PI * 500.0 / 2.0, 60, 0.01, "cos^3 spot");
    test_sphere(0.95, spot, CDL_PI * 500.0 / 2.0, 60, 0.01, "cos^3 spot");
    test_sphere(0.5, gonio, 3000.0, 60, 0.01, "goniometric downlight");
    test_sphere(0.95, gonio, 3000.0, 60, 0.01, "goniometric downlight");
    test_white_furnace();
    calibration_check(&tally, "irradiance cache");
    return check_finish();
}
