/* bench_exact_route.c - time per point of partly hidden skies: sampled to a
 * target against the exact visible-polygon route, in the same process.
 *
 *   bench_exact_route [--quality Q] [--threads K]
 *
 * Solves two scenes of the direct-light issue (data/daylight/) with the route turned off
 * (every point sampled until its relative standard error meets the quality's
 * target; default "high", 0.1 %) and on (exact), and prints seconds per
 * point, shadow rays, the ratio of the two times, and how the sampled
 * values sit against the exact ones (share within 2 stated sigma, the
 * largest error in sigmas and relative). Scenes: a black light well (1 x 1
 * x 3 m, open at the top, 10 x 10 floor points) and the window room (5 x 4
 * x 3 m, a 2 x 1.2 m window in the +x facade, 16 x 12 work-plane points),
 * both under a uniform 5000 cd/m2 sky. Ratios, never wall-clock limits,
 * are what to compare between versions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solve_internal.h"

static const char *arg_str(int argc, char **argv, const char *name, const char *dflt)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], name) == 0) return argv[i + 1];
    return dflt;
}

/* Solve the scene with the route off (sampled) and on (exact). */
static int run(const char *label, const char *file, const char *quality, int threads)
{
    static const char *names[4] = {"draft", "normal", "high", "reference"};
    int q = 0;
    while (q < 4 && strcmp(names[q], quality) != 0) q++;
    if (q == 4) {
        fprintf(stderr, "bench_exact_route: --quality is draft, normal, high or reference\n");
        return 1;
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/data/daylight/%s", CANDELA_SOURCE_DIR, file);
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    if (cdl_scene_load(path, &scene, &err) != CDL_OK) {
        fprintf(stderr, "bench_exact_route: %s\n", err.message);
        return 1;
    }
    scene->settings.quality = (cdl_quality)q;
    cdl_solution sol[2];
    for (int r = 0; r < 2; ++r) {
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        o.threads = threads;
        cdl_solve_debug dbg = CDL_SOLVE_DEBUG_NONE;
        dbg.no_exact_route = r == 0;
        if (cdl_solve_scene_into(scene, &o, &dbg, &sol[r], &err) != CDL_OK) {
            fprintf(stderr, "bench_exact_route: %s\n", err.message);
            if (r == 1) cdl_solution_clear(&sol[0]);
            cdl_scene_release(scene);
            return 1;
        }
    }
    const cdl_grid_solution *s = &sol[0].grids[0], *x = &sol[1].grids[0];
    size_t n = s->grid.count, within = 0;
    double worst_sigma = 0.0, worst_rel = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double d = fabs(s->E[i] - x->E[i]);
        within += d <= 2.0 * s->E_stderr[i];
        if (s->E_stderr[i] > 0.0) worst_sigma = fmax(worst_sigma, d / s->E_stderr[i]);
        else if (d > 0.0) worst_sigma = INFINITY;
        if (x->E[i] > 0.0) worst_rel = fmax(worst_rel, d / x->E[i]);
    }
    double ts = sol[0].compute_seconds / (double)n, tx = sol[1].compute_seconds / (double)n;
    printf("%s (%zu points, quality %s, %d thread(s)):\n", label, n, quality, threads);
    printf("  sampled: %.4g s per point, %llu shadow rays\n", ts, (unsigned long long)sol[0].rays);
    printf("  exact:   %.4g s per point, %llu shadow rays\n", tx, (unsigned long long)sol[1].rays);
    printf("  ratio sampled / exact time: %.1f\n", ts / tx);
    printf("  sampled against exact: %zu of %zu within 2 stated sigma, worst %.3g sigma, worst %.3g relative\n",
           within, n, worst_sigma, worst_rel);
    cdl_solution_clear(&sol[0]);
    cdl_solution_clear(&sol[1]);
    cdl_scene_release(scene);
    return 0;
}

int main(int argc, char **argv)
{
    const char *quality = arg_str(argc, argv, "--quality", "high");
    int threads = atoi(arg_str(argc, argv, "--threads", "1"));
    if (threads < 1) threads = 1;
    if (run("black light well", "light_well.json", quality, threads)) return 1;
    if (run("window room", "window_room.json", quality, threads)) return 1;
    return 0;
}
