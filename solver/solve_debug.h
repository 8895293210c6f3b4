/* solve_debug.h - knobs of a solve for benchmarks and the tests of the samplers (not public). */
#ifndef CANDELA_SOLVER_SOLVE_DEBUG_H
#define CANDELA_SOLVER_SOLVE_DEBUG_H

struct cdl_ray_log;

/* Knobs for benchmarks and the tests of the samplers. */
typedef struct cdl_solve_debug {
    struct cdl_ray_log *ray_log;      /* record every shadow ray (forces one thread) */
    int no_exact_route;               /* 1: sample partly hidden area emitters and skies even where the
                                       * visible polygon is exact */
    int no_cache_gradients;           /* 1: the irradiance cache interpolates without its records' gradients
                                       * (to measure what they buy) */
    int paths_as_one_over_n;          /* 1: path tracing plans every point as if its variance fell as 1/N,
                                       * the grid's exponent not measured (to measure what it buys) */
    int cache_own_alone;              /* 1: a record of a point's own stands alone, not joined with the
                                       * interpolation there (icache.c, own_gather: to measure what it buys) */
} cdl_solve_debug;
#define CDL_SOLVE_DEBUG_NONE {.ray_log = NULL, .no_exact_route = 0, .no_cache_gradients = 0, .paths_as_one_over_n = 0, .cache_own_alone = 0}

#endif
