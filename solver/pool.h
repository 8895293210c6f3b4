/* pool.h - worker threads over a range of items (their progress: progress.h).
 *
 * cdl_pool_run hands out items [0, count) in chunks to `threads` workers
 * (the calling thread is one of them). Which thread takes which chunk varies
 * from run to run, so a task must make each item's result depend on the item
 * alone (random numbers keyed by the item, never by the thread): then the
 * results do not depend on the number of threads.
 *
 * Progress: the calling thread reports, between its chunks, how many items
 * are done; the callback may ask to stop by returning non-zero, and the run
 * then ends with CDL_ERR_CANCELLED once the chunks under way are finished.
 * The callback is only ever called from the thread that called
 * cdl_pool_run.
 */
#ifndef CANDELA_SOLVER_POOL_H
#define CANDELA_SOLVER_POOL_H

#include <stddef.h>

#include "base/error.h"
#include "solver/progress.h"

/* Report through a sink (nothing when it has no function); returns the
 * callback's answer (0: go on). */
int cdl_progress_report(const cdl_progress_sink *sink, const cdl_progress *progress);

/* Items begin .. end - 1 of a task, on a worker whose own scratch space is
 * `local` (NULL when the task has none). A failure stops the whole run. */
typedef cdl_status (*cdl_pool_fn)(void *shared, void *local, size_t begin, size_t end, cdl_error *err);

typedef struct cdl_pool_task {
    size_t count;             /* items 0 .. count - 1 */
    size_t chunk;             /* items a worker takes at once, >= 1 */
    cdl_pool_fn run;
    void *shared;             /* passed to every call */
    void *locals;             /* `threads` blocks of local_size bytes, one per worker, or NULL */
    size_t local_size;
    const char *stage;        /* for progress reports */
    size_t records;           /* reported as cdl_progress.records */
} cdl_pool_task;

/* Run the task on `threads` >= 1 threads. Returns the first failure a
 * worker met (its message in err), CDL_ERR_CANCELLED when the progress
 * callback asked to stop, or CDL_OK. */
cdl_status cdl_pool_run(const cdl_pool_task *task, int threads, const cdl_progress_sink *progress, cdl_error *err);

/* Cores online (at least 1). */
int cdl_pool_cpu_count(void);

/* Seconds on a monotonic clock. */
double cdl_pool_now_seconds(void);

#endif
