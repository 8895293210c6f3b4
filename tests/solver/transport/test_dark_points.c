/* Points that no light reaches, where light could have arrived: a probe
 * inside a box open only at the bottom, a luminous panel above it. Every sample such a
 * point takes is dark, and the answer is exactly 0; what the solver owes is
 * a stated error that is not 0 (its samples could have missed light,
 * estimate.h) and a bounded effort. The unseen variance after N dark
 * samples falls as potential^2 / N^2, so holding it to the target of a dark
 * point (a thousandth of what the samples could carry, times the target)
 * takes about 1 / (1e-3 target) samples; planned as if it fell as 1 / N it
 * took the sampler's cap, a million samples a point (a fuzzed office with a
 * wall grid moved outside the room took minutes at draft). Checked for
 * both samplers that plan from a pilot: cylindrical illuminance
 * (transport/vertical_sampled.c) and the path tracer (pathtrace.c). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "solver/solve_fixture.h"

#define TARGET 0.05

/* A 1 m box about (0.5, 0.5, 0.5) open at the bottom, its walls `rho`, a
 * probe at its centre facing up, and a light 3 m above it (outside; no
 * light can come in, but the box is not closed, so the solve cannot leave
 * the light out, as it does for a closed one: solve_sealed.h): `light` is a 1 m^2
 * panel of 10 000 lm, or with `point` set a point source. `box` 0 leaves
 * the box out (the light then reaches the probe). */
static const char *const panel = "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0, 0, 3.5], "
                                 "\"u\": [0, 1, 0], \"v\": [1, 0, 0]}, \"flux_lm\": 10000}";
static const char *const point = "{\"type\": \"point\", \"position\": [0.5, 0.5, 3.5], \"intensity_cd\": 1000}";

static int solve_probe(int box, double rho, const char *light, const char *method, const char *outputs,
                       cdl_scene **scene, cdl_solution *sol)
{
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [%s%.17g%s], "
             "\"luminaires\": [%s], "
             "\"grids\": [{\"name\": \"probe\", \"type\": \"points\", \"points\": [{\"p\": [0.5, 0.5, 0.5], "
             "\"n\": [0, 0, 1]}], \"outputs\": [%s]}], "
             "\"solver\": {\"method\": \"%s\", \"target_error\": %.17g, \"seed\": 5}}",
             box ? "{\"name\": \"box\", \"type\": \"box\", \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"inward\": true, "
                   "\"open\": [\"floor\"], \"reflectance\": "
                 : "{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [-50, -50, -1], \"u\": [100, 0, 0], "
                   "\"v\": [0, 100, 0], \"reflectance\": ",
             rho, "}", light, outputs, method, TARGET);
    return fixture_solve(json, scene, sol, 1);
}

/* The sampled samples' bound: a pilot, then 1 / (1e-3 target) for the
 * unseen variance; each sample traces a few rays (a direction, the panel
 * from either side; a path's bounces): 16 rays a sample is generous, and a
 * million samples would trace several million. */
static const double rays_bound = 16.0 * (256.0 + 1.0 / (1e-3 * TARGET));

static void test_cylindrical(void)
{
    cdl_scene *open_scene, *scene;
    cdl_solution open_sol, sol;
    if (!solve_probe(0, 0.0, panel, "direct", "\"cylindrical\"", &open_scene, &open_sol)) return;
    if (!solve_probe(1, 0.0, panel, "direct", "\"cylindrical\"", &scene, &sol)) {
        fixture_release(open_scene, &open_sol);
        return;
    }
    const cdl_grid_solution *lit = &open_sol.grids[0], *dark = &sol.grids[0];
    /* The unshadowed panel: some light reaches the probe's cylinder. */
    CHECK(lit->Ez && lit->Ez[0] > 1.0);
    /* Exactly dark, and said to be uncertain: not zero ... */
    CHECK(dark->Ez && dark->Ez[0] == 0.0);
    CHECK_MSG(dark->Ez_stderr && dark->Ez_stderr[0] > 0.0, "a dark point's cylindrical error is %g",
              dark->Ez_stderr ? dark->Ez_stderr[0] : -1.0);
    /* ... and held to the dark point's target: target x 1e-3 x what the
     * samples could carry (about the unshadowed Ez; the panel's two
     * half-spaces and the pilot's mean potential make it up to twice that,
     * so a factor 2.5). */
    CHECK_MSG(dark->Ez_stderr[0] <= 2.5 * TARGET * 1e-3 * lit->Ez[0], "stated %.3g against a dark target of %.3g",
              dark->Ez_stderr[0], TARGET * 1e-3 * lit->Ez[0]);
    CHECK_MSG((double)sol.rays <= rays_bound, "a dark point took %.0f rays (at most %.0f expected)", (double)sol.rays,
              rays_bound);
    fixture_release(open_scene, &open_sol);
    fixture_release(scene, &sol);
}

static void test_pathtrace(void)
{
    cdl_scene *scene;
    cdl_solution sol;
    /* A point source: every path's every vertex is exactly dark (a shadow
     * ray either way), so every sample is 0. (A panel's light at the walls
     * is estimated as its exact value less its hidden part, zero-mean
     * noise rather than zeros: not a dark pilot.) */
    if (!solve_probe(1, 0.5, point, "pathtrace", "", &scene, &sol)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK_MSG(g->E[0] == 0.0 && g->E_indirect[0] == 0.0, "E %g indirect %g stderr %g", g->E[0], g->E_indirect[0], g->E_stderr[0]);
    /* The source is outside and the walls reflect: paths could have
     * carried light had a wall been lit, so the error is not zero. */
    CHECK_MSG(g->E_stderr[0] > 0.0, "a dark point's error is %g", g->E_stderr[0]);
    CHECK_MSG((double)sol.rays <= rays_bound, "a dark point took %.0f rays (at most %.0f expected)", (double)sol.rays,
              rays_bound);
    fixture_release(scene, &sol);
}

int main(void)
{
    test_cylindrical();
    test_pathtrace();
    return check_finish();
}
