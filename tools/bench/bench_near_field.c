/* bench_near_field.c - what spreading luminaires over their openings costs.
 *
 *   bench_near_field [--quality Q] [--threads K] [--direct]
 *
 * Solves the example office (data/office/: four 0.15 m downlights at the
 * ceiling, two 1.2 m linear pendants 1.4 m above the desks, an area panel)
 * three times in one process: every goniometric luminaire a point
 * ("near_field": "never", the far-field baseline), as the scene file says
 * ("auto": the opening within 5 opening sizes) and spread everywhere
 * ("always"); at quality "normal" by default, with the scene's
 * interreflection unless --direct. Prints seconds, shadow rays and the
 * work plane's average and extremes per mode, and the ratio of each mode's
 * compute time to the point model's (the goal: at most 3 with "auto" at
 * "normal"). Ratios, never wall-clock limits, are what to compare
 * between versions.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solve_internal.h"

int main(int argc, char **argv)
{
    static const char *qualities[4] = {"draft", "normal", "high", "reference"};
    const char *quality = "normal";
    int threads = 1, direct_only = 0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--direct") == 0) direct_only = 1;
        else if (strcmp(argv[i], "--quality") == 0 && i + 1 < argc) quality = argv[++i];
        else if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc) threads = atoi(argv[++i]);
        else {
            fprintf(stderr, "bench_near_field: usage: bench_near_field [--quality Q] [--threads K] [--direct]\n");
            return 1;
        }
    }
    int q = 0;
    while (q < 4 && strcmp(qualities[q], quality) != 0) q++;
    if (q == 4 || threads < 1) {
        fprintf(stderr, "bench_near_field: --quality is draft, normal, high or reference; --threads at least 1\n");
        return 1;
    }
    static const cdl_near_field_mode modes[3] = {CDL_NEAR_FIELD_NEVER, CDL_NEAR_FIELD_AUTO, CDL_NEAR_FIELD_ALWAYS};
    static const char *names[3] = {"never (point)", "auto", "always"};
    double base = 0.0;
    printf("example office, quality %s, %d thread(s), %s\n", quality, threads,
           direct_only ? "direct light only" : "with interreflection");
    for (int m = 0; m < 3; ++m) {
        cdl_error err;
        cdl_error_clear(&err);
        cdl_scene *scene = NULL;
        if (cdl_scene_load(CANDELA_SOURCE_DIR "/data/office/office.json", &scene, &err) != CDL_OK) {
            fprintf(stderr, "bench_near_field: %s\n", err.message);
            return 1;
        }
        scene->settings.quality = (cdl_quality)q;
        if (direct_only) scene->settings.method = CDL_METHOD_DIRECT;
        for (size_t k = 0; k < scene->luminaire_count; ++k) scene->luminaires[k].near_field = modes[m];
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        o.threads = threads;
        cdl_solution sol;
        if (cdl_solve_scene_into(scene, &o, NULL, &sol, &err) != CDL_OK) {
            fprintf(stderr, "bench_near_field: %s\n", err.message);
            cdl_scene_release(scene);
            return 1;
        }
        const cdl_grid_solution *wp = &sol.grids[0];
        double sum = 0.0, lo = wp->E[0], hi = wp->E[0];
        for (size_t i = 0; i < wp->grid.count; ++i) {
            sum += wp->E[i];
            lo = wp->E[i] < lo ? wp->E[i] : lo;
            hi = wp->E[i] > hi ? wp->E[i] : hi;
        }
        if (m == 0) base = sol.compute_seconds;
        printf("  %-14s %8.3f s  %10llu shadow rays  work plane avg %.2f lx (min %.2f, max %.2f)  time / point "
               "model %.2f\n",
               names[m], sol.compute_seconds, (unsigned long long)sol.rays, sum / (double)wp->grid.count, lo, hi,
               base > 0.0 ? sol.compute_seconds / base : 1.0);
        cdl_solution_clear(&sol);
        cdl_scene_release(scene);
    }
    return 0;
}
