/* The ranks of a shared solve without MPI: three threads of this process
 * stand in for three ranks, their collectives done through shared memory
 * and a barrier (the transport below), so that the sanitizers see the
 * library's side of every exchange. Checks: the blocks of items cover
 * every item once, in rank order, cut at multiples of the alignment and
 * balanced to one unit; per-item arrays larger than an exchange window
 * (8 MiB) end on every rank (allgather) or rank 0 (gather) and nowhere
 * else; lists of different lengths are joined in rank order; sums and
 * maxima; agreement gives every rank the lowest failing rank's status and
 * message, named unless every rank failed; a failing transport is an
 * internal error with its message; the worker pool shares a task's items
 * among the ranks, each item done once, its outputs everywhere or kept,
 * and a failure on one rank fails every rank. Items dealt in units (the
 * annual study's points and hours): every item dealt to one rank, the
 * shares within a unit of each other, each rank's rows in its items'
 * order; their rows gathered into rank 0's at the items' indices, in
 * windows (rows smaller and larger than a window), the others' rows
 * untouched; a dealt pool task done once per item, its outputs on rank 0,
 * a failure every rank's. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

#include "base/error_report.h"
#include "check.h"
#include "solver/pool.h"
#include "solver/rank_group.h"

#define RANKS 3
#include "solver/thread_ranks.h"

/* The bodies below take a rank group: made from the thread's ranks. */
typedef void (*group_body)(cdl_rank_group *group, void *user);

typedef struct group_call {
    group_body body;
    void *user;
} group_call;

static void with_group(const cdl_ranks *ranks, void *user)
{
    const group_call *call = user;
    cdl_rank_group group;
    cdl_error err;
    CHECK_OK(cdl_rank_group_init(&group, ranks, &err), &err);
    call->body(&group, call->user);
}

static void run_groups(thread_world *world, group_body body, void *user)
{
    group_call call = {body, user};
    run_ranks(world, with_group, &call);
}

/* ---- blocks ------------------------------------------------------------------------ */

static void check_blocks(size_t items, size_t align, int count)
{
    size_t next = 0, smallest = SIZE_MAX, largest = 0;
    for (int r = 0; r < count; ++r) {
        size_t b, e;
        cdl_rank_block(items, align, r, count, &b, &e);
        CHECK_MSG(b == next, "items %zu align %zu: rank %d begins at %zu, expected %zu", items, align, r, b, next);
        CHECK(b % align == 0 || b == items);
        CHECK(e >= b);
        next = e;
        size_t units = (e - b + align - 1) / align;
        if (units < smallest) smallest = units;
        if (units > largest) largest = units;
    }
    CHECK_MSG(next == items, "items %zu align %zu: the blocks end at %zu", items, align, next);
    CHECK(largest - smallest <= 1);
}

/* More than an exchange window: 1.5 M doubles, 12 MB. */
#define BIG ((size_t)3 << 19)
#define SENTINEL -1.0

/* ---- items dealt in units ---------------------------------------------------------- */

static void check_deal(size_t items, size_t unit, int count)
{
    unsigned char *seen = calloc(items ? items : 1, 1);
    size_t smallest = SIZE_MAX, largest = 0, total = 0;
    for (int r = 0; r < count; ++r) {
        cdl_rank_deal d = {items, unit, r, count};
        size_t share = cdl_rank_deal_share(&d, r);
        total += share;
        if (share < smallest) smallest = share;
        if (share > largest) largest = share;
        CHECK(cdl_rank_deal_rows(&d) == (r == 0 ? items : share));
        for (size_t t = 0; t < share; ++t) {
            size_t i = cdl_rank_deal_item(&d, r, t);
            CHECK_MSG(i < items && !seen[i], "items %zu unit %zu: rank %d's item %zu: %zu", items, unit, r, t, i);
            if (i >= items) continue;
            seen[i] = 1;
            /* unit k of the items goes to rank k mod count */
            CHECK((int)(i / unit % (size_t)count) == r);
            CHECK(cdl_rank_deal_row(&d, i) == (r == 0 ? i : t));
        }
    }
    CHECK_MSG(total == items, "items %zu unit %zu ranks %d: %zu dealt", items, unit, count, total);
    CHECK(largest - smallest <= unit);
    free(seen);
}

/* Rows of `stride` bytes, each a run of one value: item i's is (i + 1) * 0.5. */
typedef struct dealt_rows {
    size_t items, stride;
    unsigned char *rows[RANKS];
    int ok[RANKS];
} dealt_rows;

static double row_value(const dealt_rows *x, const unsigned char *row)
{
    double v;
    memcpy(&v, row, sizeof v);
    for (size_t b = sizeof v; b + sizeof v <= x->stride; b += sizeof v) {
        double w;
        memcpy(&w, row + b, sizeof w);
        if (w != v) return SENTINEL;
    }
    return v;
}

static void dealt_body(cdl_rank_group *g, void *user)
{
    dealt_rows *x = user;
    cdl_rank_deal d = cdl_rank_deal_make(g, x->items, 3);
    size_t rows = cdl_rank_deal_rows(&d), share = cdl_rank_deal_share(&d, g->rank);
    unsigned char *at = x->rows[g->rank] = malloc(rows * x->stride);
    int ok = at != NULL;
    const double none = SENTINEL;
    for (size_t r = 0; ok && r < rows; ++r)
        for (size_t b = 0; b + sizeof none <= x->stride; b += sizeof none) memcpy(at + r * x->stride + b, &none, sizeof none);
    for (size_t t = 0; ok && t < share; ++t) {
        size_t i = cdl_rank_deal_item(&d, g->rank, t);
        double v = ((double)i + 1.0) * 0.5;
        for (size_t b = 0; b + sizeof v <= x->stride; b += sizeof v)
            memcpy(at + cdl_rank_deal_row(&d, i) * x->stride + b, &v, sizeof v);
    }
    cdl_error err;
    cdl_error_clear(&err);
    uint64_t before = g->bytes_received;
    ok &= cdl_rank_gather_dealt(g, &d, at, x->stride, &err) == CDL_OK;
    for (size_t r = 0; ok && r < rows; ++r) {
        size_t i = g->rank == 0 ? r : cdl_rank_deal_item(&d, g->rank, r);
        ok &= row_value(x, at + r * x->stride) == ((double)i + 1.0) * 0.5;
    }
    ok &= g->bytes_received - before == (g->rank == 0 ? (x->items - share) * x->stride : 0);
    x->ok[g->rank] = ok;
    free(at);
}

static void check_dealt_rows(size_t items, size_t stride)
{
    dealt_rows x = {items, stride, {NULL}, {0}};
    thread_world world = {0};
    run_groups(&world, dealt_body, &x);
    for (int r = 0; r < RANKS; ++r)
        CHECK_MSG(x.ok[r], "%zu rows of %zu bytes: rank %d's rows wrong after the gather", items, stride, r);
}

/* ---- exchanges ------------------------------------------------------------------- */

typedef struct exchanges {
    double *data[RANKS];      /* per rank */
    int ok[RANKS];
} exchanges;

static void exchange_body(cdl_rank_group *g, void *user)
{
    exchanges *x = user;
    double *d = x->data[g->rank];
    cdl_error err;
    cdl_error_clear(&err);
    int ok = 1;
    size_t b, e;
    /* allgather: each rank fills its block, everyone ends with everything */
    cdl_rank_block(BIG, 16, g->rank, g->count, &b, &e);
    for (size_t i = 0; i < BIG; ++i) d[i] = i >= b && i < e ? (double)i * 0.5 : SENTINEL;
    ok &= cdl_rank_allgather_items(g, d, sizeof *d, BIG, 16, &err) == CDL_OK;
    for (size_t i = 0; i < BIG && ok; ++i) ok &= d[i] == (double)i * 0.5;
    ok &= g->bytes_received == (BIG - (e - b)) * sizeof *d;
    /* gather: rank 0 ends with everything, the others with their own block */
    cdl_rank_block(BIG, 7, g->rank, g->count, &b, &e);
    for (size_t i = 0; i < BIG; ++i) d[i] = i >= b && i < e ? (double)i + 1.0 : SENTINEL;
    ok &= cdl_rank_gather_items(g, d, sizeof *d, BIG, 7, &err) == CDL_OK;
    for (size_t i = 0; i < BIG && ok; ++i)
        ok &= d[i] == (g->rank == 0 || (i >= b && i < e) ? (double)i + 1.0 : SENTINEL);
    /* lists of different lengths: rank r gives r items (rank 0 none), r * 10 + k */
    uint32_t mine[RANKS];
    for (int k = 0; k < g->rank; ++k) mine[k] = (uint32_t)(g->rank * 10 + k);
    void *all = NULL;
    size_t total = 0;
    ok &= cdl_rank_allgather_list(g, mine, (size_t)g->rank, sizeof *mine, &all, &total, &err) == CDL_OK;
    const uint32_t want[] = {10, 20, 21};
    ok &= total == 3 && all && memcmp(all, want, sizeof want) == 0;
    free(all);
    /* sums and maxima */
    uint64_t v[2] = {(uint64_t)g->rank + 1, (uint64_t)(7 * g->rank) % 5};
    ok &= cdl_rank_sum_u64(g, v, 2, &err) == CDL_OK && v[0] == 6 && v[1] == 0 + 2 + 4;
    uint64_t m[2] = {(uint64_t)g->rank + 1, (uint64_t)(7 * g->rank) % 5};
    ok &= cdl_rank_max_u64(g, m, 2, &err) == CDL_OK && m[0] == 3 && m[1] == 4;
    /* rank 0's bytes everywhere */
    char word[16] = "";
    if (g->rank == 0) snprintf(word, sizeof word, "lumen");
    ok &= cdl_rank_broadcast(g, word, sizeof word, &err) == CDL_OK && strcmp(word, "lumen") == 0;
    x->ok[g->rank] = ok;
}

/* ---- agreement -------------------------------------------------------------------- */

typedef struct agreement {
    int failing_mask;         /* bit r: rank r fails */
    cdl_status got[RANKS];
    char message[RANKS][CDL_ERROR_MESSAGE_SIZE];
    int agreed[RANKS];
} agreement;

static void agree_body(cdl_rank_group *g, void *user)
{
    agreement *a = user;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = CDL_OK;
    if (a->failing_mask & (1 << g->rank))
        st = cdl_error_set(&err, g->rank == 2 ? CDL_ERR_INTERNAL : CDL_ERR_INPUT, "file %d unreadable", g->rank);
    a->got[g->rank] = cdl_rank_agree(g, st, &err);
    snprintf(a->message[g->rank], sizeof a->message[g->rank], "%s", err.message);
    a->agreed[g->rank] = g->failure_agreed;
}

static void check_agreement(void)
{
    thread_world world = {0};
    agreement a = {.failing_mask = 0};
    run_groups(&world, agree_body, &a);
    for (int r = 0; r < RANKS; ++r) CHECK(a.got[r] == CDL_OK && !a.agreed[r]);

    a = (agreement){.failing_mask = 1 << 1 | 1 << 2};
    run_groups(&world, agree_body, &a);
    for (int r = 0; r < RANKS; ++r) {
        CHECK(a.got[r] == CDL_ERR_INPUT && a.agreed[r]);
        CHECK_MSG(strcmp(a.message[r], "rank 1 of 3: file 1 unreadable") == 0, "rank %d: '%s'", r, a.message[r]);
    }
    a = (agreement){.failing_mask = 7};
    run_groups(&world, agree_body, &a);
    for (int r = 0; r < RANKS; ++r)
        CHECK_MSG(a.got[r] == CDL_ERR_INPUT && strcmp(a.message[r], "file 0 unreadable") == 0, "rank %d: '%s'", r,
                  a.message[r]);
}

/* A transport that fails on rank 1's first call: that rank returns an
 * internal error with the transport's message (not agreed: the others'
 * calls succeeded). */
typedef struct broken {
    cdl_status got[RANKS];
    char message[RANKS][CDL_ERROR_MESSAGE_SIZE];
} broken;

static void broken_body(cdl_rank_group *g, void *user)
{
    broken *b = user;
    cdl_error err;
    cdl_error_clear(&err);
    uint64_t v = 1;
    b->got[g->rank] = cdl_rank_sum_u64(g, &v, 1, &err);
    snprintf(b->message[g->rank], sizeof b->message[g->rank], "%s", err.message);
}

static void check_broken_transport(void)
{
    thread_world world = {.fail_call = 1, .fail_rank = 1};
    broken b;
    memset(&b, 0, sizeof b);
    run_groups(&world, broken_body, &b);
    CHECK(b.got[0] == CDL_OK && b.got[1] == CDL_ERR_INTERNAL && b.got[2] == CDL_OK);
    CHECK_MSG(strcmp(b.message[1], "exchange among ranks (sum): the wire is cut") == 0, "'%s'", b.message[1]);
}

/* ---- the worker pool over ranks ------------------------------------------------- */

#define ITEMS 1000

typedef struct shared_task {
    double *out[RANKS];
    atomic_int visits[ITEMS];
    int everywhere;
    size_t fail_at;
    cdl_status got[RANKS];
    char message[RANKS][CDL_ERROR_MESSAGE_SIZE];
} shared_task;

typedef struct square_job {
    double *out;
    shared_task *task;
} square_job;

static cdl_status square(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    square_job *job = shared;
    for (size_t i = begin; i < end; ++i) {
        if (i == job->task->fail_at) return cdl_error_set(err, CDL_ERR_INPUT, "item %zu refused", i);
        job->out[i] = (double)i * (double)i;
        atomic_fetch_add(&job->task->visits[i], 1);
    }
    return CDL_OK;
}

/* The dealt task writes item i at its row on this rank. */
typedef struct dealt_square_job {
    double *out;
    shared_task *task;
    const cdl_rank_deal *deal;
} dealt_square_job;

static cdl_status dealt_square(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    dealt_square_job *job = shared;
    for (size_t i = begin; i < end; ++i) {
        if (i == job->task->fail_at) return cdl_error_set(err, CDL_ERR_INPUT, "item %zu refused", i);
        job->out[cdl_rank_deal_row(job->deal, i)] = (double)i * (double)i;
        atomic_fetch_add(&job->task->visits[i], 1);
    }
    return CDL_OK;
}

static void dealt_pool_body(cdl_rank_group *g, void *user)
{
    shared_task *t = user;
    double *out = t->out[g->rank];
    for (size_t i = 0; i < ITEMS; ++i) out[i] = SENTINEL;
    cdl_rank_deal deal = cdl_rank_deal_make(g, ITEMS, 2);
    dealt_square_job job = {out, t, &deal};
    cdl_pool_task task = {.count = ITEMS, .chunk = 2, .run = dealt_square, .shared = &job,
                          .outputs = {{out, sizeof *out}}};
    cdl_workers workers = {.threads = 2, .ranks = g};
    cdl_error err;
    cdl_error_clear(&err);
    t->got[g->rank] = cdl_pool_run_dealt(&task, &workers, &deal, &err);
    snprintf(t->message[g->rank], sizeof t->message[g->rank], "%s", err.message);
}

static void check_dealt_pool(void)
{
    static shared_task t;
    memset(&t, 0, sizeof t);
    for (int r = 0; r < RANKS; ++r) t.out[r] = malloc(ITEMS * sizeof(double));
    t.fail_at = SIZE_MAX;
    thread_world world = {0};
    run_groups(&world, dealt_pool_body, &t);
    int once = 1;
    for (size_t i = 0; i < ITEMS; ++i) once &= atomic_load(&t.visits[i]) == 1;
    CHECK_MSG(once, "dealt: an item done other than once");
    size_t wrong = 0;
    for (size_t i = 0; i < ITEMS; ++i) wrong += t.out[0][i] != (double)i * (double)i;
    CHECK_MSG(wrong == 0 && t.got[0] == CDL_OK, "dealt: rank 0 holds %zu items wrong", wrong);
    for (int r = 1; r < RANKS; ++r) {
        cdl_rank_deal d = {ITEMS, 2, r, RANKS};
        size_t share = cdl_rank_deal_share(&d, r), bad = 0;
        for (size_t k = 0; k < share; ++k) {
            size_t i = cdl_rank_deal_item(&d, r, k);
            bad += t.out[r][k] != (double)i * (double)i;
        }
        for (size_t k = share; k < ITEMS; ++k) bad += t.out[r][k] != SENTINEL;
        CHECK_MSG(bad == 0 && t.got[r] == CDL_OK, "dealt: rank %d: %zu rows wrong", r, bad);
    }
    /* item 994 is in unit 497, rank 497 mod 3 = 2's: its failure is every rank's */
    memset(t.visits, 0, sizeof t.visits);
    t.fail_at = 994;
    run_groups(&world, dealt_pool_body, &t);
    for (int r = 0; r < RANKS; ++r)
        CHECK_MSG(t.got[r] == CDL_ERR_INPUT && strcmp(t.message[r], "rank 2 of 3: item 994 refused") == 0,
                  "rank %d: '%s'", r, t.message[r]);
    for (int r = 0; r < RANKS; ++r) free(t.out[r]);
}

static void pool_body(cdl_rank_group *g, void *user)
{
    shared_task *t = user;
    double *out = t->out[g->rank];
    for (size_t i = 0; i < ITEMS; ++i) out[i] = SENTINEL;
    square_job job = {out, t};
    cdl_pool_task task = {.count = ITEMS, .chunk = 2, .run = square, .shared = &job, .outputs = {{out, sizeof *out}}};
    cdl_workers workers = {.threads = 2, .ranks = g, .everywhere = t->everywhere};
    cdl_error err;
    cdl_error_clear(&err);
    t->got[g->rank] = cdl_pool_run_shared(&task, &workers, &err);
    snprintf(t->message[g->rank], sizeof t->message[g->rank], "%s", err.message);
}

static void check_pool(void)
{
    for (int everywhere = 0; everywhere <= 1; ++everywhere) {
        static shared_task t;
        memset(&t, 0, sizeof t);
        for (int r = 0; r < RANKS; ++r) t.out[r] = malloc(ITEMS * sizeof(double));
        t.everywhere = everywhere;
        t.fail_at = SIZE_MAX;
        thread_world world = {0};
        run_groups(&world, pool_body, &t);
        int once = 1;
        for (size_t i = 0; i < ITEMS; ++i) once &= atomic_load(&t.visits[i]) == 1;
        CHECK_MSG(once, "everywhere %d: an item done other than once", everywhere);
        for (int r = 0; r < RANKS; ++r) {
            CHECK(t.got[r] == CDL_OK);
            size_t b, e, wrong = 0;
            cdl_rank_block(ITEMS, CDL_RANK_KEEP_ALIGN, r, RANKS, &b, &e);
            for (size_t i = 0; i < ITEMS; ++i) {
                int held = everywhere || (i >= b && i < e);
                wrong += t.out[r][i] != (held ? (double)i * (double)i : SENTINEL);
            }
            CHECK_MSG(wrong == 0, "everywhere %d, rank %d: %zu items wrong", everywhere, r, wrong);
        }
        /* A failure on the rank that holds item 990 (the last) fails every rank. */
        memset(t.visits, 0, sizeof t.visits);
        t.fail_at = 990;
        run_groups(&world, pool_body, &t);
        for (int r = 0; r < RANKS; ++r) {
            CHECK(t.got[r] == CDL_ERR_INPUT);
            CHECK_MSG(strcmp(t.message[r], "rank 2 of 3: item 990 refused") == 0, "rank %d: '%s'", r, t.message[r]);
        }
        for (int r = 0; r < RANKS; ++r) free(t.out[r]);
    }
}

int main(void)
{
    for (size_t items = 0; items < 70; ++items)
        for (size_t align = 1; align <= 16; align *= 2)
            for (int count = 1; count <= 5; ++count) check_blocks(items, align, count);
    check_blocks(10000001, 16, 256);

    exchanges x;
    for (int r = 0; r < RANKS; ++r) x.data[r] = malloc(BIG * sizeof(double));
    thread_world world = {0};
    run_groups(&world, exchange_body, &x);
    for (int r = 0; r < RANKS; ++r) {
        CHECK_MSG(x.ok[r], "rank %d: an exchange gave the wrong bytes", r);
        free(x.data[r]);
    }
    check_agreement();
    check_broken_transport();
    check_pool();
    for (size_t items = 0; items < 40; ++items)
        for (size_t unit = 1; unit <= 8; unit *= 2)
            for (int count = 1; count <= 5; ++count) check_deal(items, unit, count);
    check_deal(10000001, 16, 256);
    check_dealt_rows(1000, 24);               /* several rows a window, one window */
    check_dealt_rows(BIG / 4, 4 * sizeof(double)); /* 12 MB: two windows */
    check_dealt_rows(5, ((size_t)9 << 20) / sizeof(double) * sizeof(double)); /* rows larger than a window */
    check_dealt_pool();

    /* One process: no exchange, every item here, a failure agreed at once. */
    cdl_rank_group alone;
    cdl_error err;
    CHECK_OK(cdl_rank_group_init(&alone, NULL, &err), &err);
    CHECK(cdl_rank_group_count(&alone) == 1 && cdl_rank_group_rank(NULL) == 0);
    size_t b, e;
    cdl_rank_block(100, 16, 0, 1, &b, &e);
    CHECK(b == 0 && e == 100);
    cdl_ranks bad = CDL_RANKS_INIT;
    bad.count = 2;
    CHECK(cdl_rank_group_init(&alone, &bad, &err) == CDL_ERR_USAGE && strstr(err.message, "four callbacks"));
    bad.rank = 2;
    CHECK(cdl_rank_group_init(&alone, &bad, &err) == CDL_ERR_USAGE && strstr(err.message, "rank 2 of 2"));
    return check_finish();
}
