/* pool.c - worker threads over a range of items (see pool.h). */
#include "base/error_report.h"
#include "solver/pool.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

int cdl_pool_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

double cdl_pool_now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cdl_progress_report(const cdl_progress_sink *sink, const cdl_progress *progress)
{
    if (!sink || !sink->fn) return 0;
    return sink->fn(sink->user, progress);
}

typedef struct pool_run {
    const cdl_pool_task *task;
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
} pool_worker;

static void *worker_main(void *arg)
{
    pool_worker *w = arg;
    pool_run *r = w->run;
    const cdl_pool_task *t = r->task;
    while (!atomic_load(&r->stop)) {
        size_t begin = atomic_fetch_add(&r->next, t->chunk);
        if (begin >= t->count) break;
        size_t end = t->count - begin > t->chunk ? begin + t->chunk : t->count;
        w->status = t->run(t->shared, w->local, begin, end, &w->err);
        if (w->status != CDL_OK) {
            atomic_store(&r->stop, 1);
            break;
        }
        size_t done = atomic_fetch_add(&r->done, end - begin) + (end - begin);
        if (w->progress) {
            cdl_progress p = {t->stage, done, t->count, t->records, cdl_pool_now_seconds() - w->started};
            if (cdl_progress_report(w->progress, &p) != 0) {
                w->cancelled = 1;
                atomic_store(&r->stop, 1);
            }
        }
    }
    return NULL;
}

cdl_status cdl_pool_run(const cdl_pool_task *task, int threads, const cdl_progress_sink *progress, cdl_error *err)
{
    if (threads < 1) threads = 1;
    if (task->chunk < 1) return cdl_error_set(err, CDL_ERR_INTERNAL, "pool: a chunk of 0 items");
    /* No more threads than chunks: the others would only start and stop. */
    size_t chunks = task->count / task->chunk + 1;
    if ((size_t)threads > chunks) threads = (int)chunks;
    pool_run run;
    run.task = task;
    atomic_init(&run.next, 0);
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
        cdl_progress p = {task->stage, task->count, task->count, task->records, cdl_pool_now_seconds() - started};
        if (cdl_progress_report(progress, &p) != 0)
            st = cdl_error_set(err, CDL_ERR_CANCELLED, "%s: cancelled by the caller",
                               task->stage ? task->stage : "work");
    }
    free(workers);
    free(ids);
    return st;
}
