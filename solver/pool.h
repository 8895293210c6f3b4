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
 *
 * Ranks: cdl_pool_run_shared runs a task shared by the ranks of a solve
 * (rank_group.h): each rank runs its block of the items on its threads;
 * the ranks then agree on how it went (a failure on any rank is every
 * rank's), and the task's per-item outputs are exchanged so that every
 * rank holds every item's (`everywhere`), or left with the rank that
 * computed them, for rank 0 to gather later (cdl_rank_gather_items with
 * CDL_RANK_KEEP_ALIGN). Since each item's result depends on the item
 * alone, the results are those of one process. Anything a task adds up
 * in its workers' scratch (counts of rays) is the caller's to add up over
 * the ranks afterwards (cdl_rank_sum_u64).
 */
#ifndef CANDELA_SOLVER_POOL_H
#define CANDELA_SOLVER_POOL_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/progress.h"
#include "solver/rank_group.h"

/* Report through a sink (nothing when it has no function); returns the
 * callback's answer (0: go on). */
int cdl_progress_report(const cdl_progress_sink *sink, const cdl_progress *progress);

/* Items begin .. end - 1 of a task, on a worker whose own scratch space is
 * `local` (NULL when the task has none). A failure stops the whole run. */
typedef cdl_status (*cdl_pool_fn)(void *shared, void *local, size_t begin, size_t end, cdl_error *err);

/* A per-item array a task writes: item i's bytes at base + i * stride. */
typedef struct cdl_pool_output {
    void *base;
    size_t stride;
} cdl_pool_output;

#define CDL_POOL_OUTPUTS_MAX 8

typedef struct cdl_pool_task {
    size_t count;             /* items 0 .. count - 1 */
    size_t chunk;             /* items a worker takes at once, >= 1 */
    cdl_pool_fn run;
    void *shared;             /* passed to every call */
    void *locals;             /* `threads` blocks of local_size bytes, one per worker, or NULL */
    size_t local_size;
    const char *stage;        /* for progress reports */
    size_t records;           /* reported as cdl_progress.records */
    /* For cdl_pool_run_shared: the per-item arrays the task writes (NULL
     * bases are skipped). */
    cdl_pool_output outputs[CDL_POOL_OUTPUTS_MAX];
} cdl_pool_task;

/* Where a task's items run: `threads` workers in this process and, with
 * `ranks` of several, this rank's block of them. */
typedef struct cdl_workers {
    int threads;                      /* >= 1 */
    const cdl_progress_sink *progress;/* may be NULL */
    cdl_rank_group *ranks;            /* NULL: this process runs every item */
    int everywhere;                   /* with ranks: 1: every rank ends with every item's outputs; 0: each
                                       * rank keeps its block's (blocks cut at CDL_RANK_KEEP_ALIGN, which
                                       * the task's chunk must divide) */
} cdl_workers;

/* Run the task on `threads` >= 1 threads. Returns the first failure a
 * worker met (its message in err), CDL_ERR_CANCELLED when the progress
 * callback asked to stop, or CDL_OK. */
cdl_status cdl_pool_run(const cdl_pool_task *task, int threads, const cdl_progress_sink *progress, cdl_error *err);

/* The task on the workers: every item on `threads` threads (as
 * cdl_pool_run), or this rank's block of them followed by the agreement
 * and the exchange of the outputs (above). Progress counts this rank's
 * items. Errors: cdl_pool_run's, agreed over the ranks; CDL_ERR_INTERNAL
 * when an exchange fails; CDL_ERR_USAGE for a kept task whose chunk does
 * not divide CDL_RANK_KEEP_ALIGN. */
cdl_status cdl_pool_run_shared(const cdl_pool_task *task, const cdl_workers *workers, cdl_error *err);

/* The task's items dealt among the ranks of `workers` (rank_group.h's
 * cdl_rank_deal, in units of the task's chunk): each rank runs its share on
 * its threads, the ranks agree on how it went, and each of the task's
 * outputs, written at item i's row cdl_rank_deal_row(deal, i) (rows
 * cdl_rank_deal_rows of them), is gathered into rank 0's rows
 * (cdl_rank_gather_dealt). `deal` must be cdl_rank_deal_make(workers->ranks,
 * task->count, task->chunk). Without ranks (or of one), cdl_pool_run.
 * Errors as cdl_pool_run_shared's. */
cdl_status cdl_pool_run_dealt(const cdl_pool_task *task, const cdl_workers *workers, const cdl_rank_deal *deal,
                              cdl_error *err);

/* Cores online (at least 1). */
int cdl_pool_cpu_count(void);

/* The threads a process of a solve takes by default: the cores it may run
 * on (its affinity mask, which a launcher such as mpirun may narrow) when
 * that is fewer than the machine's, else the machine's cores over the
 * `local_ranks` processes sharing them; at least 1. */
int cdl_pool_default_threads(int local_ranks);

/* Seconds on a monotonic clock. */
double cdl_pool_now_seconds(void);

/* CPU seconds this process has used, all its threads together. */
double cdl_pool_cpu_seconds(void);

/* The most memory this process has held resident so far, in bytes (0
 * where the system does not say). */
uint64_t cdl_pool_peak_rss_bytes(void);

#endif
