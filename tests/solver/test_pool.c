/* The worker pool: every item done once whatever the thread count, a
 * worker's failure stops the run with its message, and the progress
 * callback sees the count rise to the total and can cancel. Also the solve's
 * progress and cancelling through cdl_solve_options. */
#include <stdatomic.h>
#include <string.h>

#include "base/error_report.h"
#include "check.h"
#include "solver/pool.h"
#include "solver/solve_internal.h"

typedef struct squares {
    double *out;
    atomic_int *visits;
    size_t fail_at;            /* an item whose chunk fails, or SIZE_MAX */
} squares;

static cdl_status square_items(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    squares *s = shared;
    size_t *chunks = local;
    if (chunks) ++*chunks;
    for (size_t i = begin; i < end; ++i) {
        if (i == s->fail_at) return cdl_error_set(err, CDL_ERR_INPUT, "item %zu refused", i);
        s->out[i] = (double)i * (double)i;
        atomic_fetch_add(&s->visits[i], 1);
    }
    return CDL_OK;
}

typedef struct seen {
    size_t calls, last_done, total;
    size_t cancel_after;       /* answer "stop" from this call on (0: never) */
} seen;

static int watch(void *user, const cdl_progress *p)
{
    seen *s = user;
    s->calls++;
    CHECK(p->done >= s->last_done); /* never falls (the final report may repeat the total) */
    CHECK(p->done <= p->total);
    CHECK(strcmp(p->stage, "squares") == 0);
    s->last_done = p->done;
    s->total = p->total;
    return s->cancel_after && s->calls >= s->cancel_after;
}

static void test_every_item_once(void)
{
    enum { N = 1003 };
    static double out[N];
    static atomic_int visits[N];
    for (int threads = 1; threads <= 8; threads *= 2) {
        memset(out, 0, sizeof out);
        for (int i = 0; i < N; ++i) atomic_init(&visits[i], 0);
        squares s = {out, visits, SIZE_MAX};
        size_t chunks[8] = {0};
        seen watched = {0, 0, 0, 0};
        cdl_progress_sink sink = {watch, &watched};
        cdl_pool_task task = {.count = N, .chunk = 7, .run = square_items, .shared = &s, .locals = chunks,
                              .local_size = sizeof chunks[0], .stage = "squares"};
        cdl_error err;
        CHECK_OK(cdl_pool_run(&task, threads, &sink, &err), &err);
        int once = 1;
        for (int i = 0; i < N; ++i) once &= atomic_load(&visits[i]) == 1 && out[i] == (double)i * i;
        CHECK_MSG(once, "%d threads: every item exactly once", threads);
        size_t total_chunks = 0;
        for (int t = 0; t < 8; ++t) total_chunks += chunks[t];
        CHECK(total_chunks == (N + 6) / 7);
        /* The calling thread reports after each of its own chunks and once
         * more at the end: the count it saw last is the total. */
        CHECK(watched.calls >= 1 && watched.total == N && watched.last_done == N);
    }
}

static void test_failure_stops(void)
{
    enum { N = 500 };
    static double out[N];
    static atomic_int visits[N];
    for (int i = 0; i < N; ++i) atomic_init(&visits[i], 0);
    squares s = {out, visits, 123};
    cdl_pool_task task = {.count = N, .chunk = 10, .run = square_items, .shared = &s, .stage = "squares"};
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_pool_run(&task, 2, NULL, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "item 123 refused") != NULL);
}

static void test_cancel(void)
{
    enum { N = 1000 };
    static double out[N];
    static atomic_int visits[N];
    for (int i = 0; i < N; ++i) atomic_init(&visits[i], 0);
    squares s = {out, visits, SIZE_MAX};
    seen watched = {0, 0, 0, 3};
    cdl_progress_sink sink = {watch, &watched};
    cdl_pool_task task = {.count = N, .chunk = 1, .run = square_items, .shared = &s, .stage = "squares"};
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_pool_run(&task, 1, &sink, &err) == CDL_ERR_CANCELLED);
    CHECK(watched.calls == 3);
    CHECK(watched.last_done == 3);
    int untouched = 0;
    for (int i = 0; i < N; ++i) untouched += atomic_load(&visits[i]) == 0;
    CHECK(untouched == N - 3); /* one thread, one item a chunk: stopped after three */
}

/* A solve reports its stages and stops when asked. */
static int count_and_cancel(void *user, const cdl_progress *p)
{
    seen *s = user;
    (void)p;
    s->calls++;
    return s->cancel_after && s->calls >= s->cancel_after;
}

static void test_solve_cancel(void)
{
    const char *json = "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 3], "
                       "\"intensity_cd\": 100}], \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", "
                       "\"origin\": [0, 0, 0], \"u\": [4, 0, 0], \"v\": [0, 4, 0], \"nu\": 40, \"nv\": 40}]}";
    cdl_scene *scene = NULL;
    cdl_error err;
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/pool_cancel.json", &scene, &err), &err);
    if (!scene) return;
    cdl_solution sol;
    seen all = {0, 0, 0, 0};
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = 1;
    o.progress.fn = count_and_cancel;
    o.progress.user = &all;
    CHECK_OK(cdl_solve_scene_into(scene, &o, NULL, &sol, &err), &err);
    CHECK(all.calls >= 2); /* the geometry stage and the grid */
    cdl_solution_clear(&sol);
    for (size_t stop_at = 1; stop_at <= 2; ++stop_at) {
        seen stop = {0, 0, 0, stop_at};
        o.progress.user = &stop;
        cdl_error_clear(&err);
        CHECK(cdl_solve_scene_into(scene, &o, NULL, &sol, &err) == CDL_ERR_CANCELLED);
        CHECK(strstr(err.message, "cancelled") != NULL);
        CHECK(sol.grids == NULL && sol.plan_json == NULL); /* nothing half-made is handed back */
    }
    cdl_scene_release(scene);
}

int main(void)
{
    test_every_item_once();
    test_failure_stops();
    test_cancel();
    test_solve_cancel();
    return check_finish();
}
