/* direct_throughput.h - the direct solver's shadow-ray throughput against plain
 * Embree occlusion queries on the same rays. Used by tools/bench/bench_direct. */
#ifndef CANDELA_SOLVER_BENCH_DIRECT_THROUGHPUT_H
#define CANDELA_SOLVER_BENCH_DIRECT_THROUGHPUT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

typedef struct cdl_bench_direct_config {
    size_t points;        /* grid points (rounded to a square grid) */
    size_t luminaires;    /* goniometric downlights */
    size_t triangles;     /* scene triangles (approximately) */
    int threads;
    const char *ies_path; /* the downlight's photometric file */
} cdl_bench_direct_config;

typedef struct cdl_bench_direct_result {
    size_t points, triangles;
    double solver_seconds;          /* grid computation only, setup excluded, `threads` threads */
    uint64_t solver_rays;
    double embree_seconds;          /* the same rays replayed, one thread */
    double stream_seconds;          /* the same rays replayed as ray streams (cdl_ray_scene_occluded_many), one thread */
    uint64_t embree_rays;
    double occluded_fraction;       /* of those rays */
} cdl_bench_direct_result;

cdl_status cdl_bench_direct_run(const cdl_bench_direct_config *config, cdl_bench_direct_result *result,
                                cdl_error *err);

#endif
