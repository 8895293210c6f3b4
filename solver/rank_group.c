/* rank_group.c - blocks of items, windowed exchanges and agreement among the ranks of a solve (rank_group.h). */
#include "solver/rank_group.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
#include "solver/pool.h"

cdl_status cdl_rank_group_init(cdl_rank_group *group, const cdl_ranks *ranks, cdl_error *err)
{
    memset(group, 0, sizeof *group);
    cdl_ranks one = CDL_RANKS_INIT;
    group->ranks = one;
    cdl_sized_struct_read(&group->ranks, sizeof group->ranks, ranks);
    const cdl_ranks *r = &group->ranks;
    if (r->count < 1 || r->rank < 0 || r->rank >= r->count)
        return cdl_error_set(err, CDL_ERR_USAGE, "ranks: expected a rank from 0 to count - 1 of a count >= 1, found "
                                                 "rank %d of %d", r->rank, r->count);
    if (r->count > 1 && (!r->allgather || !r->gather || !r->reduce_u64 || !r->broadcast))
        return cdl_error_set(err, CDL_ERR_USAGE, "ranks: a group of %d ranks needs all four callbacks (allgather, "
                                                 "gather, reduce_u64, broadcast)", r->count);
    if (group->ranks.local_count < 1) group->ranks.local_count = 1;
    group->rank = r->rank;
    group->count = r->count;
    return CDL_OK;
}

int cdl_rank_group_rank(const cdl_rank_group *group)
{
    return group ? group->rank : 0;
}

int cdl_rank_group_count(const cdl_rank_group *group)
{
    return group ? group->count : 1;
}

static int several(const cdl_rank_group *group)
{
    return group && group->count > 1;
}

void cdl_rank_block(size_t items, size_t align, int rank, int count, size_t *begin, size_t *end)
{
    if (align < 1) align = 1;
    size_t units = items / align + (items % align != 0);
    size_t u0 = units * (size_t)rank / (size_t)count, u1 = units * (size_t)(rank + 1) / (size_t)count;
    *begin = u0 * align < items ? u0 * align : items;
    *end = u1 * align < items ? u1 * align : items;
}

static cdl_status exchange_failed(const char *what, const char *message, cdl_error *err)
{
    return cdl_error_set(err, CDL_ERR_INTERNAL, "exchange among ranks (%s): %s", what,
                         message[0] ? message : "the transport failed without a message");
}

cdl_status cdl_rank_agree(cdl_rank_group *group, cdl_status status, cdl_error *err)
{
    if (!several(group)) {
        if (group && status != CDL_OK) group->failure_agreed = 1;
        return status;
    }
    const cdl_ranks *r = &group->ranks;
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    /* [0]: the lowest failing rank as count - rank (0: none failed); [1]: 1 where a rank succeeded. */
    uint64_t v[2] = {status != CDL_OK ? (uint64_t)(group->count - group->rank) : 0, status == CDL_OK};
    if (r->reduce_u64(r->user, v, 2, CDL_RANKS_MAX, message) != 0) return exchange_failed("agreement", message, err);
    if (v[0] == 0) return CDL_OK;
    int failed = group->count - (int)v[0];
    struct {
        uint64_t status;
        char message[CDL_ERROR_MESSAGE_SIZE];
    } what;
    memset(&what, 0, sizeof what);
    if (failed == group->rank) {
        what.status = (uint64_t)status;
        snprintf(what.message, sizeof what.message, "%s", err ? err->message : "(no message)");
    }
    if (r->broadcast(r->user, &what, sizeof what, failed, message) != 0)
        return exchange_failed("agreement", message, err);
    what.message[sizeof what.message - 1] = '\0';
    cdl_status agreed = (cdl_status)what.status;
    if (v[1]) cdl_error_set(err, agreed, "rank %d of %d: %s", failed, group->count, what.message);
    else cdl_error_set(err, agreed, "%s", what.message);
    group->failure_agreed = 1;
    return agreed;
}

/* Bytes starts[r] .. starts[r + 1] - 1 of `buffer` are rank r's (starts
 * has count + 1 entries); exchanged window by window. */
static cdl_status exchange_ranges(cdl_rank_group *group, unsigned char *buffer, const size_t *starts, int to_all,
                                  cdl_error *err)
{
    const cdl_ranks *r = &group->ranks;
    int n = group->count;
    size_t total = starts[n];
    size_t *offsets = malloc(((size_t)n + 1) * sizeof *offsets);
    if (!offsets) return cdl_error_out_of_memory(err);
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    cdl_status st = CDL_OK;
    size_t mine = starts[group->rank + 1] - starts[group->rank];
    for (size_t a = 0; a < total && st == CDL_OK; a += CDL_RANK_WINDOW_BYTES) {
        size_t b = total - a > CDL_RANK_WINDOW_BYTES ? a + CDL_RANK_WINDOW_BYTES : total;
        for (int k = 0; k <= n; ++k) {
            size_t s = starts[k] < a ? a : starts[k] > b ? b : starts[k];
            offsets[k] = s - a;
        }
        int failed = to_all ? r->allgather(r->user, buffer + a, offsets, message)
                            : r->gather(r->user, buffer + a, offsets, message);
        if (failed) st = exchange_failed(to_all ? "allgather" : "gather", message, err);
    }
    if (st == CDL_OK && (to_all || group->rank == 0)) group->bytes_received += total - mine;
    free(offsets);
    return st;
}

static cdl_status exchange_items(cdl_rank_group *group, void *base, size_t stride, size_t count, size_t align,
                                 int to_all, cdl_error *err)
{
    if (!several(group) || count == 0) return CDL_OK;
    size_t *starts = malloc(((size_t)group->count + 1) * sizeof *starts);
    if (!starts) return cdl_error_out_of_memory(err);
    for (int k = 0; k < group->count; ++k) {
        size_t begin, end;
        cdl_rank_block(count, align, k, group->count, &begin, &end);
        starts[k] = begin * stride;
    }
    starts[group->count] = count * stride;
    cdl_status st = exchange_ranges(group, base, starts, to_all, err);
    free(starts);
    return st;
}

cdl_status cdl_rank_allgather_items(cdl_rank_group *group, void *base, size_t stride, size_t count, size_t align,
                                    cdl_error *err)
{
    return exchange_items(group, base, stride, count, align, 1, err);
}

cdl_status cdl_rank_gather_items(cdl_rank_group *group, void *base, size_t stride, size_t count, size_t align,
                                 cdl_error *err)
{
    return exchange_items(group, base, stride, count, align, 0, err);
}

cdl_status cdl_rank_allgather_list(cdl_rank_group *group, const void *mine, size_t mine_count, size_t stride,
                                   void **all, size_t *all_count, cdl_error *err)
{
    *all = NULL;
    *all_count = 0;
    int n = cdl_rank_group_count(group);
    uint64_t *counts = calloc((size_t)n, sizeof *counts);
    size_t *starts = malloc(((size_t)n + 1) * sizeof *starts);
    cdl_status st = counts && starts ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) counts[cdl_rank_group_rank(group)] = mine_count;
    if (st == CDL_OK && several(group)) st = cdl_rank_sum_u64(group, counts, (size_t)n, err);
    size_t total = 0;
    for (int k = 0; st == CDL_OK && k < n; ++k) {
        starts[k] = total * stride;
        total += (size_t)counts[k];
    }
    unsigned char *joined = NULL;
    if (st == CDL_OK && total > 0) {
        starts[n] = total * stride;
        joined = malloc(total * stride);
        if (!joined) st = cdl_error_out_of_memory(err);
        if (st == CDL_OK && mine_count) memcpy(joined + starts[cdl_rank_group_rank(group)], mine, mine_count * stride);
        if (st == CDL_OK && several(group)) st = exchange_ranges(group, joined, starts, 1, err);
    }
    free(counts);
    free(starts);
    if (st != CDL_OK) {
        free(joined);
        return st;
    }
    *all = joined;
    *all_count = total;
    return CDL_OK;
}

/* ---- items dealt in units ------------------------------------------------------- */

cdl_rank_deal cdl_rank_deal_make(const cdl_rank_group *group, size_t count, size_t unit)
{
    cdl_rank_deal d = {count, unit ? unit : 1, cdl_rank_group_rank(group), cdl_rank_group_count(group)};
    return d;
}

size_t cdl_rank_deal_share(const cdl_rank_deal *d, int rank)
{
    size_t units = d->count / d->unit + (d->count % d->unit != 0), r = (size_t)rank, n = (size_t)d->ranks;
    if (units <= r) return 0;
    size_t mine = (units - r + n - 1) / n, items = mine * d->unit;
    /* the last unit, short when the items do not fill it, may be this rank's */
    if ((units - 1) % n == r) items -= units * d->unit - d->count;
    return items;
}

size_t cdl_rank_deal_item(const cdl_rank_deal *d, int rank, size_t local)
{
    size_t unit = (size_t)rank + (size_t)d->ranks * (local / d->unit);
    return unit * d->unit + local % d->unit;
}

size_t cdl_rank_deal_rows(const cdl_rank_deal *d)
{
    return d->rank == 0 ? d->count : cdl_rank_deal_share(d, d->rank);
}

size_t cdl_rank_deal_row(const cdl_rank_deal *d, size_t item)
{
    if (d->rank == 0) return item;
    /* item = (rank + ranks j) unit + k: this rank's j-th unit */
    return item / d->unit / (size_t)d->ranks * d->unit + item % d->unit;
}

/* The dealt rows laid end to end in rank order (rank r's from starts[r])
 * travel in windows; rank 0 puts the others' rows of each window at their
 * items' indices. */
cdl_status cdl_rank_gather_dealt(cdl_rank_group *group, const cdl_rank_deal *deal, void *base, size_t stride,
                                 cdl_error *err)
{
    if (!several(group) || deal->count == 0 || stride == 0) return CDL_OK;
    int n = group->count, me = group->rank;
    size_t *starts = malloc(((size_t)n + 1) * sizeof *starts), *offsets = malloc(((size_t)n + 1) * sizeof *offsets);
    size_t rows = CDL_RANK_WINDOW_BYTES / stride ? CDL_RANK_WINDOW_BYTES / stride : 1;
    unsigned char *window = malloc(rows * stride);
    cdl_status st = starts && offsets && window ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) starts[0] = 0;
    for (int k = 0; st == CDL_OK && k < n; ++k) starts[k + 1] = starts[k] + cdl_rank_deal_share(deal, k);
    unsigned char *rows_at = base;
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    for (size_t a = 0; st == CDL_OK && a < deal->count; a += rows) {
        size_t b = deal->count - a > rows ? a + rows : deal->count;
        for (int k = 0; k <= n; ++k) offsets[k] = ((starts[k] < a ? a : starts[k] > b ? b : starts[k]) - a) * stride;
        /* this rank's rows of the window (rank 0's stay where they are) */
        if (me != 0 && offsets[me + 1] > offsets[me])
            memcpy(window + offsets[me], rows_at + (a + offsets[me] / stride - starts[me]) * stride,
                   offsets[me + 1] - offsets[me]);
        if (group->ranks.gather(group->ranks.user, window, offsets, message) != 0) {
            st = exchange_failed("gather", message, err);
            break;
        }
        for (int k = 1; me == 0 && k < n; ++k)
            for (size_t s = offsets[k] / stride; s < offsets[k + 1] / stride; ++s) {
                size_t item = cdl_rank_deal_item(deal, k, a + s - starts[k]);
                memcpy(rows_at + item * stride, window + s * stride, stride);
            }
    }
    if (st == CDL_OK && me == 0) group->bytes_received += (deal->count - starts[1]) * stride;
    free(starts);
    free(offsets);
    free(window);
    return st;
}

cdl_status cdl_rank_broadcast(cdl_rank_group *group, void *buffer, size_t bytes, cdl_error *err)
{
    if (!several(group) || bytes == 0) return CDL_OK;
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    for (size_t a = 0; a < bytes; a += CDL_RANK_WINDOW_BYTES) {
        size_t n = bytes - a > CDL_RANK_WINDOW_BYTES ? CDL_RANK_WINDOW_BYTES : bytes - a;
        if (group->ranks.broadcast(group->ranks.user, (unsigned char *)buffer + a, n, 0, message) != 0)
            return exchange_failed("broadcast", message, err);
    }
    if (group->rank != 0) group->bytes_received += bytes;
    return CDL_OK;
}

static cdl_status reduce(cdl_rank_group *group, uint64_t *values, size_t n, cdl_ranks_op op, cdl_error *err)
{
    if (!several(group) || n == 0) return CDL_OK;
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    if (group->ranks.reduce_u64(group->ranks.user, values, n, (int)op, message) != 0)
        return exchange_failed(op == CDL_RANKS_SUM ? "sum" : "maximum", message, err);
    return CDL_OK;
}

cdl_status cdl_rank_sum_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err)
{
    return reduce(group, values, n, CDL_RANKS_SUM, err);
}

cdl_status cdl_rank_max_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err)
{
    return reduce(group, values, n, CDL_RANKS_MAX, err);
}

cdl_status cdl_rank_reports_gather(cdl_rank_group *group, int threads, double t0, double cpu0, double work_seconds,
                                   cdl_rank_report **out, cdl_error *err)
{
    *out = NULL;
    size_t n = (size_t)cdl_rank_group_count(group);
    int rank = cdl_rank_group_rank(group);
    cdl_rank_report *reports = calloc(n, sizeof *reports);
    if (!reports) return cdl_error_out_of_memory(err);
    cdl_rank_report *mine = &reports[rank];
    mine->threads = (uint64_t)threads;
    mine->bytes_received = group ? group->bytes_received : 0;
    mine->seconds = cdl_pool_now_seconds() - t0;
    mine->work_seconds = group ? group->work_seconds : work_seconds;
    mine->work_cpu_seconds = group ? group->work_cpu_seconds : 0.0;
    mine->cpu_seconds = cdl_pool_cpu_seconds() - cpu0;
    mine->peak_rss_bytes = cdl_pool_peak_rss_bytes();
    cdl_status st = cdl_rank_gather_items(group, reports, sizeof *reports, n, 1, err);
    if (st != CDL_OK || rank != 0) {
        free(reports);
        return st;
    }
    *out = reports;
    return CDL_OK;
}
