/* pool.c - worker threads over a range of items (see pool.h). */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "base/error_report.h"
#include "solver/pool.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

int cdl_pool_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

int cdl_pool_default_threads(int local_ranks)
{
    int online = cdl_pool_cpu_count();
    cpu_set_t mask;
    if (sched_getaffinity(0, sizeof mask, &mask) == 0) {
        int allowed = CPU_COUNT(&mask);
        if (allowed >= 1 && allowed < online) return allowed;
    }
    if (local_ranks < 1) local_ranks = 1;
    return online / local_ranks > 1 ? online / local_ranks : 1;
}

double cdl_pool_now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double cdl_pool_cpu_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

uint64_t cdl_pool_peak_rss_bytes(void)
{
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss < 0) return 0;
    return (uint64_t)usage.ru_maxrss * 1024u; /* Linux: kilobytes */
}

int cdl_progress_report(const cdl_progress_sink *sink, const cdl_progress *progress)
{
    if (!sink || !sink->fn) return 0;
    return sink->fn(sink->user, progress);
}

typedef struct pool_run {
    const cdl_pool_task *task;
    size_t first, last;       /* the items this run hands out: first .. last - 1 */
    atomic_size_t next;       /* first item not yet handed out */
    atomic_size_t done;       /* items finished */
    atomic_int stop;          /* a worker failed or the caller cancelled */
} pool_run;

typedef struct pool_worker {
    pool_run *run;
    void *local;
    cdl_status status;
    cdl_error err;
    /* The calling thread's worker reports progress; the others pass NULL. */
    const cdl_progress_sink *progress;
    double started;
    int cancelled;
    double cpu_seconds;       /* this worker's thread's CPU time in the run */
} pool_worker;

static double thread_cpu_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *worker_main(void *arg)
{
    pool_worker *w = arg;
    double cpu0 = thread_cpu_seconds();
    pool_run *r = w->run;
    const cdl_pool_task *t = r->task;
    while (!atomic_load(&r->stop)) {
        size_t begin = atomic_fetch_add(&r->next, t->chunk);
        if (begin >= r->last) break;
        size_t end = r->last - begin > t->chunk ? begin + t->chunk : r->last;
        w->status = t->run(t->shared, w->local, begin, end, &w->err);
        if (w->status != CDL_OK) {
            atomic_store(&r->stop, 1);
            break;
        }
        size_t done = atomic_fetch_add(&r->done, end - begin) + (end - begin);
        if (w->progress) {
            cdl_progress p = {t->stage, done, r->last - r->first, t->records, cdl_pool_now_seconds() - w->started};
            if (cdl_progress_report(w->progress, &p) != 0) {
                w->cancelled = 1;
                atomic_store(&r->stop, 1);
            }
        }
    }
    w->cpu_seconds = thread_cpu_seconds() - cpu0;
    return NULL;
}

/* Items first .. last - 1 of the task; *cpu (when not NULL) gains the
 * CPU seconds its workers spent. */
static cdl_status run_items(const cdl_pool_task *task, size_t first, size_t last, int threads,
                            const cdl_progress_sink *progress, double *cpu, cdl_error *err)
{
    if (threads < 1) threads = 1;
    if (task->chunk < 1) return cdl_error_set(err, CDL_ERR_INTERNAL, "pool: a chunk of 0 items");
    /* No more threads than chunks: the others would only start and stop. */
    size_t chunks = (last - first) / task->chunk + 1;
    if ((size_t)threads > chunks) threads = (int)chunks;
    pool_run run;
    run.task = task;
    run.first = first;
    run.last = last;
    atomic_init(&run.next, first);
    atomic_init(&run.done, 0);
    atomic_init(&run.stop, 0);
    pool_worker *workers = calloc((size_t)threads, sizeof *workers);
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    if (!workers || !ids) {
        free(workers);
        free(ids);
        return cdl_error_out_of_memory(err);
    }
    double started = cdl_pool_now_seconds();
    for (int i = 0; i < threads; ++i) {
        workers[i].run = &run;
        workers[i].local = task->locals ? (char *)task->locals + (size_t)i * task->local_size : NULL;
        workers[i].status = CDL_OK;
        workers[i].started = started;
    }
    workers[0].progress = progress;
    int started_threads = 1;
    for (int i = 1; i < threads; ++i) {
        if (pthread_create(&ids[i], NULL, worker_main, &workers[i]) != 0) break;
        started_threads = i + 1;
    }
    worker_main(&workers[0]);
    for (int i = 1; i < started_threads; ++i) pthread_join(ids[i], NULL);
    for (int i = 0; cpu && i < started_threads; ++i) *cpu += workers[i].cpu_seconds;
    cdl_status st = CDL_OK;
    for (int i = 0; i < started_threads && st == CDL_OK; ++i)
        if (workers[i].status != CDL_OK) {
            st = workers[i].status;
            if (err) *err = workers[i].err;
        }
    if (st == CDL_OK && workers[0].cancelled)
        st = cdl_error_set(err, CDL_ERR_CANCELLED, "%s: cancelled by the caller", task->stage ? task->stage : "work");
    if (st == CDL_OK) {
        /* The last chunks may have been other threads': say it is all done. */
        cdl_progress p = {task->stage, last - first, last - first, task->records, cdl_pool_now_seconds() - started};
        if (cdl_progress_report(progress, &p) != 0)
            st = cdl_error_set(err, CDL_ERR_CANCELLED, "%s: cancelled by the caller",
                               task->stage ? task->stage : "work");
    }
    free(workers);
    free(ids);
    return st;
}

cdl_status cdl_pool_run(const cdl_pool_task *task, int threads, const cdl_progress_sink *progress, cdl_error *err)
{
    return run_items(task, 0, task->count, threads, progress, NULL, err);
}

cdl_status cdl_pool_run_shared(const cdl_pool_task *task, const cdl_workers *workers, cdl_error *err)
{
    cdl_rank_group *group = workers->ranks;
    if (cdl_rank_group_count(group) == 1) {
        double t0 = cdl_pool_now_seconds();
        cdl_status st = run_items(task, 0, task->count, workers->threads, workers->progress,
                                  group ? &group->work_cpu_seconds : NULL, err);
        if (group) group->work_seconds += cdl_pool_now_seconds() - t0;
        return st;
    }
    if (!workers->everywhere && (task->chunk < 1 || CDL_RANK_KEEP_ALIGN % task->chunk != 0))
        return cdl_error_set(err, CDL_ERR_USAGE, "pool: a task kept by ranks needs a chunk dividing %d, found %zu",
                             CDL_RANK_KEEP_ALIGN, task->chunk);
    /* Shared outputs are exchanged at once: blocks at the task's own chunks
     * balance best. Kept ones stay for rank 0 to gather: blocks at the
     * alignment every task over the points shares. */
    size_t align = workers->everywhere ? task->chunk : CDL_RANK_KEEP_ALIGN;
    size_t begin, end;
    cdl_rank_block(task->count, align, group->rank, group->count, &begin, &end);
    double t0 = cdl_pool_now_seconds();
    cdl_status st = begin < end ? run_items(task, begin, end, workers->threads, workers->progress,
                                            &group->work_cpu_seconds, err)
                                : CDL_OK;
    group->work_seconds += cdl_pool_now_seconds() - t0;
    st = cdl_rank_agree(group, st, err);
    for (int k = 0; st == CDL_OK && workers->everywhere && k < CDL_POOL_OUTPUTS_MAX; ++k)
        if (task->outputs[k].base)
            st = cdl_rank_allgather_items(group, task->outputs[k].base, task->outputs[k].stride, task->count, align,
                                          err);
    return st;
}

/* A rank's dealt share as a task of its own: its local items, a unit a
 * chunk, each run as the unit's items. */
typedef struct dealt_run {
    const cdl_pool_task *task;
    const cdl_rank_deal *deal;
} dealt_run;

static cdl_status run_dealt_unit(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    const dealt_run *d = shared;
    size_t first = cdl_rank_deal_item(d->deal, d->deal->rank, begin);
    return d->task->run(d->task->shared, local, first, first + (end - begin), err);
}

cdl_status cdl_pool_run_dealt(const cdl_pool_task *task, const cdl_workers *workers, const cdl_rank_deal *deal,
                              cdl_error *err)
{
    cdl_rank_group *group = workers->ranks;
    if (cdl_rank_group_count(group) == 1) return cdl_pool_run_shared(task, workers, err);
    if (deal->count != task->count || deal->unit != (task->chunk ? task->chunk : 1) || deal->ranks != group->count ||
        deal->rank != group->rank)
        return cdl_error_set(err, CDL_ERR_USAGE, "pool: a dealt task's deal is not of its items, chunk and ranks");
    dealt_run d = {task, deal};
    cdl_pool_task mine = *task;
    mine.count = cdl_rank_deal_share(deal, group->rank);
    mine.run = run_dealt_unit;
    mine.shared = &d;
    double t0 = cdl_pool_now_seconds();
    cdl_status st = mine.count ? run_items(&mine, 0, mine.count, workers->threads, workers->progress,
                                           &group->work_cpu_seconds, err)
                               : CDL_OK;
    group->work_seconds += cdl_pool_now_seconds() - t0;
    st = cdl_rank_agree(group, st, err);
    for (int k = 0; st == CDL_OK && k < CDL_POOL_OUTPUTS_MAX; ++k)
        if (task->outputs[k].base)
            st = cdl_rank_gather_dealt(group, deal, task->outputs[k].base, task->outputs[k].stride, err);
    return st;
}
