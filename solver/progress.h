/* progress.h - what a long call reports while it works, and how its caller
 * cancels it.
 *
 * A long call (cdl_solve_scene, the bench ladder) takes a cdl_progress_sink.
 * Between chunks of work it calls the sink's function with how far it got;
 * the function returns 0 to go on or non-zero to stop, and the call then
 * ends with CDL_ERR_CANCELLED once the work under way is finished.
 *
 * Units: counts of items (points, records or rungs as `stage` says) and
 * seconds. Ownership: the sink and its `user` pointer are the caller's and
 * are only borrowed for the call; the cdl_progress handed to the function
 * and its `stage` string live only during that call. Thread safety: the
 * function is only ever called from the thread that made the long call
 * (never from a worker), so it needs no locking of its own.
 */
#ifndef CANDELA_SOLVER_PROGRESS_H
#define CANDELA_SOLVER_PROGRESS_H

#include <stddef.h>

/* What a long call reports. `stage` names the work ("grid workplane",
 * "cache records"); items are points, records or rungs as the stage says. */
typedef struct cdl_progress {
    const char *stage;
    size_t done, total;       /* items of this stage */
    size_t records;           /* irradiance-cache records so far (0 when there is no cache) */
    double elapsed_seconds;   /* since the stage began */
} cdl_progress;

/* Returns 0 to go on, non-zero to cancel. */
typedef int (*cdl_progress_fn)(void *user, const cdl_progress *progress);

typedef struct cdl_progress_sink {
    cdl_progress_fn fn;       /* NULL: no reports, no cancelling */
    void *user;
} cdl_progress_sink;

#endif
