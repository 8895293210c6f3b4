/* direct_throughput.c - shadow-ray throughput of the direct solver against plain
 * Embree occlusion queries on the same rays (the physical limit).
 *
 *   bench_direct [--points N] [--luminaires L] [--triangles T] [--threads K]
 *
 * Builds a scene of T triangles (a floor and a field of tessellated spheres
 * between the luminaires and the grid), L goniometric downlights under the
 * ceiling and a workplane grid of about N points, solves it with the direct
 * method, and reports rays per second per core, points per second, and the
 * ratio to an Embree-only loop over exactly the rays the solver cast.
 * Defaults: N = 100000, L = 50, T = 1000000, K = 1. Ratios, never wall-clock
 * limits, are what to compare between versions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "solver/bench/direct_throughput.h"

static long arg_long(int argc, char **argv, const char *name, long dflt)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], name) == 0) return strtol(argv[i + 1], NULL, 10);
    return dflt;
}

int main(int argc, char **argv)
{
    cdl_bench_direct_config cfg;
    cfg.points = (size_t)arg_long(argc, argv, "--points", 100000);
    cfg.luminaires = (size_t)arg_long(argc, argv, "--luminaires", 50);
    cfg.triangles = (size_t)arg_long(argc, argv, "--triangles", 1000000);
    cfg.threads = (int)arg_long(argc, argv, "--threads", 1);
    cfg.ies_path = CANDELA_SOURCE_DIR "/data/office/downlight.ies";
    cdl_bench_direct_result r;
    cdl_error err;
    cdl_error_clear(&err);
    if (cdl_bench_direct_run(&cfg, &r, &err) != CDL_OK) {
        fprintf(stderr, "bench_direct: %s\n", err.message);
        return 1;
    }
    double solver_per_core = (double)r.solver_rays / r.solver_seconds / (double)cfg.threads;
    double embree_per_core = (double)r.embree_rays / r.embree_seconds;
    printf("scene: %zu triangles, %zu goniometric luminaires, %zu grid points; solver on %d thread(s)\n",
           r.triangles, cfg.luminaires, r.points, cfg.threads);
    printf("direct solver: %.3f s, %llu shadow rays: %.4g rays/s per core, %.4g points/s\n", r.solver_seconds,
           (unsigned long long)r.solver_rays, solver_per_core, (double)r.points / r.solver_seconds);
    printf("plain Embree:  %.3f s for the same %llu rays on one thread: %.4g rays/s\n", r.embree_seconds,
           (unsigned long long)r.embree_rays, embree_per_core);
    printf("as streams:    %.3f s for the same rays on one thread: %.4g rays/s (%.2f x single rays)\n",
           r.stream_seconds, (double)r.embree_rays / r.stream_seconds, r.embree_seconds / r.stream_seconds);
    printf("ratio (solver / Embree, per core): %.3f   (goal >= 1.00: streams beat single rays); %.1f %% of the rays are blocked\n",
           solver_per_core / embree_per_core, 100.0 * r.occluded_fraction);
    return 0;
}
