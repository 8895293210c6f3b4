/* Lights sealed out of a closed room (solver/solve_sealed.c): a closed,
 * opaque box that holds every point of the solve keeps every light outside
 * it from them, at every bounce, so the solve leaves such a light out: 0 lx
 * from it exactly, with no error (nothing was sampled), and no work spent on
 * it. Before, a closed room under an overcast sky path traced the sky
 * through its walls' "closed form less the hidden part" estimator, zero-mean
 * noise that the planner chased to its cap (minutes a point) and reported as
 * negative illuminance. Where the box is open, or a point lies outside it
 * or looks out of it, or a light reaches into it, nothing is left out. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/solve_fixture.h"

#define SKY "{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 8000}"
#define PANEL_ABOVE                                                                                             \
    "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1, 1, 3.5], \"u\": [0, 1, 0], \"v\": [1, " \
    "0, 0]}, \"flux_lm\": 5000}"
/* a panel whose outline lies in the ceiling's plane: it lights the room */
#define PANEL_IN_CEILING                                                                                        \
    "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1, 1, 3], \"u\": [0, 1, 0], \"v\": [1, " \
    "0, 0]}, \"flux_lm\": 5000}"

/* A 4 x 3 x 3 m box room (walls `rho`, `open` its open faces, "" none),
 * lit by `lights`, one grid `grid` (JSON), solved by `method`. */
static int solve_room(double rho, const char *open, const char *lights, const char *grid, const char *method,
                      cdl_scene **scene, cdl_solution *sol)
{
    char json[4096];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"name\": \"room\", \"type\": \"box\", \"min\": [0, 0, 0], "
             "\"max\": [4, 3, 3], \"inward\": true, \"reflectance\": %.17g, \"open\": [%s]}], "
             "\"luminaires\": [%s], \"grids\": [%s], "
             "\"solver\": {\"method\": \"%s\", \"quality\": \"draft\", \"seed\": 2}}",
             rho, open, lights, grid, method);
    return fixture_solve(json, scene, sol, 1);
}

#define WORKPLANE                                                                                          \
    "{\"name\": \"wp\", \"type\": \"rect\", \"origin\": [0.5, 0.5, 0.8], \"u\": [3, 0, 0], \"v\": [0, 2, 0], " \
    "\"nu\": 3, \"nv\": 2}"

static int has_warning(const cdl_solution *sol, const char *words)
{
    for (size_t i = 0; i < sol->warning_count; ++i)
        if (strstr(sol->warnings[i], words)) return 1;
    return 0;
}

static int sealed(const cdl_solution *sol)
{
    return has_warning(sol, "a closed box that holds every point of the solve") &&
           strstr(sol->plan_json, "not modelled: it lies outside surfaces[0]") != NULL;
}

/* A closed room under a sky, its walls reflecting: exactly dark, no error,
 * the sky said to be left out, and only the path tracer's least paths. */
static void test_closed_room_sky(void)
{
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve_room(0.5, "", SKY, WORKPLANE, "pathtrace", &scene, &sol)) return;
    CHECK(sealed(&sol));
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i)
        CHECK_MSG(g->E[i] == 0.0 && g->E_stderr[i] == 0.0, "point %zu: %g +- %g lx in a closed room", i, g->E[i],
                  g->E_stderr[i]);
    /* two rounds of 8 x 8 strata, two paths each, of a few bounces: the
     * paths end at the first wall (nothing lit to carry) */
    CHECK_MSG((double)sol.rays <= 6.0 * 256.0 * 4.0 * (double)g->grid.count, "%.0f rays for a dark room",
              (double)sol.rays);
    fixture_release(scene, &sol);
}

/* The white furnace's cousin with a sky outside: walls that emit L and
 * reflect rho give pi L / (1 - rho) everywhere inside (the furnace: walls
 * of radiance L / (1 - rho)), the sky left out and adding nothing. */
static void test_furnace_with_sky(void)
{
    const double L = 50.0, rho = 0.5;
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"name\": \"room\", \"type\": \"box\", \"min\": [0, 0, 0], "
             "\"max\": [4, 3, 3], \"inward\": true, \"reflectance\": %.17g, \"luminance_cd_m2\": %.17g}], "
             "\"luminaires\": [" SKY "], \"grids\": [" WORKPLANE "], "
             "\"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.01, \"seed\": 3}}",
             rho, L);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    CHECK(sealed(&sol));
    double expected = CDL_PI * L / (1.0 - rho);
    const cdl_grid_solution *g = &sol.grids[0];
    for (size_t i = 0; i < g->grid.count; ++i)
        /* 4 stated sigma: six points, a test of the sealing, not of calibration */
        CHECK_MSG(g->E_stderr[i] > 0.0 && fabs(g->E[i] - expected) <= 4.0 * g->E_stderr[i],
                  "point %zu: %.6g +- %.3g, expected %.6g", i, g->E[i], g->E_stderr[i], expected);
    fixture_release(scene, &sol);
}

/* Where light can get in or a point can see out, nothing is left out. */
static void test_not_sealed(void)
{
    static const struct {
        const char *what, *open, *lights, *grid;
        int lit;  /* the light reaches the grid */
    } cases[] = {
        {"an open ceiling", "\"ceiling\"", SKY, WORKPLANE, 1},
        {"a point outside the room", "", SKY,
         "{\"name\": \"out\", \"type\": \"points\", \"points\": [{\"p\": [2, 1, 0.8], \"n\": [0, 0, 1]}, "
         "{\"p\": [5, 1, 0.8], \"n\": [0, 0, 1]}]}",
         1},
        /* not held by the box (it looks out), though dark all the same: an
         * overcast sky has nothing below the horizon */
        {"a point on the floor looking down through it", "", SKY,
         "{\"name\": \"down\", \"type\": \"points\", \"points\": [{\"p\": [2, 1, 0], \"n\": [0, 0, -1]}]}", 0},
        {"a panel in the ceiling's plane", "", PANEL_IN_CEILING, WORKPLANE, 1},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_room(0.0, cases[c].open, cases[c].lights, cases[c].grid, "direct", &scene, &sol)) continue;
        CHECK_MSG(!sealed(&sol), "%s: a light was left out", cases[c].what);
        double most = 0.0;
        for (size_t i = 0; i < sol.grids[0].grid.count; ++i)
            if (sol.grids[0].E[i] > most) most = sol.grids[0].E[i];
        CHECK_MSG((most > 0.0) == cases[c].lit, "%s: Emax %g lx", cases[c].what, most);
        fixture_release(scene, &sol);
    }
}

/* A bounded emitter clear of the box is sealed out like a sky; a floor grid
 * on the floor, facing in, is held by the box. */
static void test_panel_above(void)
{
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve_room(0.5, "", PANEL_ABOVE,
                    "{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0.5, 0.5, 0], \"u\": [3, 0, 0], "
                    "\"v\": [0, 2, 0], \"nu\": 3, \"nv\": 2}",
                    "pathtrace", &scene, &sol))
        return;
    CHECK(sealed(&sol));
    for (size_t i = 0; i < sol.grids[0].grid.count; ++i) CHECK(sol.grids[0].E[i] == 0.0);
    fixture_release(scene, &sol);
}

int main(void)
{
    test_closed_room_sky();
    test_furnace_with_sky();
    test_not_sealed();
    test_panel_above();
    return check_finish();
}
