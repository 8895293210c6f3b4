/* solve_options.h - the options of a solve (cdl_solve_scene, solve.h).
 *
 * Plain data: the caller's, copied by cdl_solve_scene at its start.
 * Thread safety: an options struct is only read; one may serve solves on
 * several threads at once (its progress callback is then called from each
 * solve's calling thread).
 */
#ifndef CANDELA_SOLVER_SOLVE_OPTIONS_H
#define CANDELA_SOLVER_SOLVE_OPTIONS_H

#include "solver/progress.h"

struct cdl_ray_log;

/* Options of a solve. Start from CDL_SOLVE_OPTIONS_DEFAULT and set fields by
 * name: fields added later get their defaults. */
typedef struct cdl_solve_options {
    int threads;                      /* < 0: as the scene says (0 there = all cores) */
    cdl_progress_sink progress;       /* stages, points done; may cancel (CDL_ERR_CANCELLED) */
    struct cdl_ray_log *ray_log;      /* benchmarks: record every shadow ray (forces one thread) */
    int no_exact_route;               /* 1: sample partly hidden area emitters and skies even where the
                                       * visible polygon is exact (tests of the sampler, benchmarks);
                                       * default 0 */
    int no_cache_gradients;           /* 1: the irradiance cache interpolates without its records' gradients
                                         (to measure what they buy) */
    /* A file of irradiance-cache records (icache/icache_file.h), NULL for
     * none (the default). When it exists it must have been made for this
     * scene, these settings and this Candela: its records are then used and
     * none is gathered; otherwise the solve is refused (CDL_ERR_INPUT,
     * naming the file and what differs) before any grid is computed. When
     * it does not exist, the records are gathered and the file written
     * (atomically) after the solve succeeds; its folder must exist. */
    const char *cache_path;
} cdl_solve_options;
#define CDL_SOLVE_OPTIONS_DEFAULT                                                                                     \
    {.threads = -1, .progress = {.fn = NULL, .user = NULL}, .ray_log = NULL, .no_exact_route = 0,                    \
     .no_cache_gradients = 0, .cache_path = NULL}

#endif
