/* solve_options.h - the options of a solve (cdl_solve_scene, solve.h).
 *
 * Start from CDL_SOLVE_OPTIONS_INIT and set fields by name. The struct
 * begins with its own size (set by the macro), so that fields added later
 * keep their defaults for a program built before them.
 *
 * Plain data: the caller's, copied by cdl_solve_scene at its start.
 * Thread safety: an options struct is only read; one may serve solves on
 * several threads at once (its progress callback is then called from each
 * solve's calling thread).
 */
#ifndef CANDELA_SOLVER_SOLVE_OPTIONS_H
#define CANDELA_SOLVER_SOLVE_OPTIONS_H

#include <stddef.h>

#include "solver/progress.h"

typedef struct cdl_solve_options {
    size_t size;                      /* sizeof(cdl_solve_options) */
    int threads;                      /* < 0 (default): as the scene says (0 there = all cores) */
    cdl_progress_sink progress;       /* stages, points done; may cancel (CDL_ERR_CANCELLED) */
    /* A file of irradiance-cache records, NULL for none (the default). When
     * it exists it must have been made for this scene, these settings and
     * this Candela: its records are then used and none is gathered;
     * otherwise the solve is refused (CDL_ERR_INPUT, naming the file and
     * what differs) before any grid is computed. When it does not exist,
     * the records are gathered and the file written (atomically) after the
     * solve succeeds; its folder must exist. */
    const char *cache_path;
    /* The scene's solver settings, overridden for this solve: a cdl_method
     * or cdl_quality value, or -1 (the default) for the scene's own; a
     * target relative standard error in [1e-5, 0.5], or 0 (the default) for
     * the scene's. A quality given here replaces the scene's target_error
     * too (unless target_error is given here as well). */
    int method;
    int quality;
    double target_error;
} cdl_solve_options;
#define CDL_SOLVE_OPTIONS_INIT                                                                                        \
    {.size = sizeof(cdl_solve_options), .threads = -1, .progress = {.fn = NULL, .user = NULL}, .cache_path = NULL,  \
     .method = -1, .quality = -1, .target_error = 0.0}

#endif
