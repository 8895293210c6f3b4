/* rank_group.h - the ranks of a shared solve as the solver uses them: blocks of items, exchanges, agreement (not public).
 *
 * A cdl_rank_group wraps the caller's cdl_ranks (solve_ranks.h) with what
 * the solve keeps about it: whether a failure it returned was agreed by
 * every rank, and this rank's bytes received and seconds of work, for
 * summary.json. Every function takes a group that may be NULL or of one
 * rank: then nothing is exchanged and everything is this process's.
 *
 * Items (grid points, records to gather) are split in contiguous blocks:
 * rank r gets units [U r / N, U (r + 1) / N) of the U = ceil(count / align)
 * units of `align` items, so that a block begins at a multiple of `align`
 * (the worker pool's chunks, which decide some per-chunk work, are then the
 * same as in one process). Exchanges of per-item arrays go in windows of at
 * most CDL_RANK_WINDOW_BYTES, so that no message, and no buffer a transport
 * may need for one, grows with the grid.
 *
 * The functions here are collectives: every rank calls them in the same
 * order with the same counts. Errors: CDL_ERR_INTERNAL when an exchange
 * fails or memory runs out (not agreed: the other ranks may be waiting);
 * cdl_rank_agree returns the agreed failure of whichever rank failed.
 */
#ifndef CANDELA_SOLVER_RANK_GROUP_H
#define CANDELA_SOLVER_RANK_GROUP_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/solve_ranks.h"

/* The largest exchange of per-item arrays in one collective call: 8 MiB. */
#define CDL_RANK_WINDOW_BYTES ((size_t)8 << 20)

/* Blocks of items kept by their ranks (rank 0 gathers them later) begin at
 * multiples of this: every worker-pool task over a grid's points uses a
 * chunk that divides it (direct light 16, paths and vertical outputs 2),
 * so a point's parts computed by different tasks are on the same rank. */
#define CDL_RANK_KEEP_ALIGN 16

typedef struct cdl_rank_group {
    cdl_ranks ranks;                  /* the caller's, copied (its size field read) */
    int rank, count;
    int failure_agreed;               /* 1: the last failure cdl_rank_agree returned is every rank's */
    uint64_t bytes_received;          /* by this rank in exchanges of results and records */
    double work_seconds;              /* this rank computing its shares (exchanges and waits excluded) */
    double work_cpu_seconds;          /* its worker threads' CPU time in those shares */
} cdl_rank_group;

/* A group for `ranks` (NULL: one process). CDL_ERR_USAGE for a group of
 * several ranks without its callbacks, or a rank out of range. */
cdl_status cdl_rank_group_init(cdl_rank_group *group, const cdl_ranks *ranks, cdl_error *err);

/* This rank and the group's count (0 and 1 for NULL). */
int cdl_rank_group_rank(const cdl_rank_group *group);
int cdl_rank_group_count(const cdl_rank_group *group);

/* Rank `rank` of `count`'s block of items [*begin, *end) of `items`, cut at
 * multiples of `align` (>= 1). */
void cdl_rank_block(size_t items, size_t align, int rank, int count, size_t *begin, size_t *end);

/* Every rank's status made one (cdl_ranks_agree, solve_ranks.h); sets
 * failure_agreed when it returns a failure. */
cdl_status cdl_rank_agree(cdl_rank_group *group, cdl_status status, cdl_error *err);

/* items[0 .. count - 1] of `stride` bytes at `base`, each rank holding its
 * block (cdl_rank_block with `align`): afterwards every rank holds all of
 * them (allgather) or rank 0 does (gather). */
cdl_status cdl_rank_allgather_items(cdl_rank_group *group, void *base, size_t stride, size_t count, size_t align,
                                    cdl_error *err);
cdl_status cdl_rank_gather_items(cdl_rank_group *group, void *base, size_t stride, size_t count, size_t align,
                                 cdl_error *err);

/* Each rank's list of `mine` items of `stride` bytes joined in rank order,
 * on every rank: *all (malloc'd, the caller frees; NULL when empty) and
 * *all_count. */
cdl_status cdl_rank_allgather_list(cdl_rank_group *group, const void *mine, size_t mine_count, size_t stride,
                                   void **all, size_t *all_count, cdl_error *err);

/* Items dealt among the ranks like cards: units of `unit` consecutive
 * items, unit k to rank k mod count, so that each rank's share samples the
 * whole range (items whose cost varies along the range, a room's points
 * from its window inwards, are shared evenly, as contiguous blocks would
 * not). A dealt task writes item i's outputs at row cdl_rank_deal_row(i):
 * rank 0 holds a row for every item (i itself), each other rank only rows
 * for its own items, in their order (cdl_rank_deal_rows of them), which
 * cdl_rank_gather_dealt sends to rank 0's rows. With one rank every item is
 * its own row. */
typedef struct cdl_rank_deal {
    size_t count;             /* items */
    size_t unit;              /* items a unit, >= 1 */
    int rank, ranks;          /* this rank and the group's count */
} cdl_rank_deal;

/* The deal of `count` items in units of `unit` (0 taken as 1) among `group`'s ranks (NULL: one). */
cdl_rank_deal cdl_rank_deal_make(const cdl_rank_group *group, size_t count, size_t unit);

/* Items rank `rank` is dealt. */
size_t cdl_rank_deal_share(const cdl_rank_deal *deal, int rank);

/* This rank's `local`-th item (local < its share): its index among all items. */
size_t cdl_rank_deal_item(const cdl_rank_deal *deal, int rank, size_t local);

/* Rows this rank's outputs need: every item's on rank 0, its share elsewhere. */
size_t cdl_rank_deal_rows(const cdl_rank_deal *deal);

/* The row of item i (one of this rank's items, or any on rank 0). */
size_t cdl_rank_deal_row(const cdl_rank_deal *deal, size_t item);

/* The rows of `stride` bytes at `base` (cdl_rank_deal_rows of them) of
 * every rank's items into rank 0's rows, in windows of at most
 * CDL_RANK_WINDOW_BYTES (one row when a row is larger): afterwards rank 0
 * holds every item's row at its index; the others' rows are unchanged. */
cdl_status cdl_rank_gather_dealt(cdl_rank_group *group, const cdl_rank_deal *deal, void *base, size_t stride,
                                 cdl_error *err);

/* Rank 0's `bytes` bytes at `buffer` copied to every rank's. */
cdl_status cdl_rank_broadcast(cdl_rank_group *group, void *buffer, size_t bytes, cdl_error *err);

/* values[0 .. n - 1] summed, or their maximum taken, over the ranks. */
cdl_status cdl_rank_sum_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err);
cdl_status cdl_rank_max_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err);

/* One rank of a solve (or an annual study) shared by ranks, for
 * summary.json; a run in one process has one. */
typedef struct cdl_rank_report {
    uint64_t threads;                 /* its worker threads */
    uint64_t bytes_received;          /* in the exchanges of results and records */
    double seconds;                   /* from the start of its run to the end of the last exchange */
    double work_seconds;              /* computing its shares of the work (waits and exchanges excluded) */
    double work_cpu_seconds;          /* its worker threads' CPU time computing its shares: the work split,
                                         whatever else the machine runs */
    double cpu_seconds;               /* CPU time of its run, all its threads together (MPI's waits
                                         included: they spin) */
    uint64_t peak_rss_bytes;          /* the most memory its process held resident, up to the end of the run */
} cdl_rank_report;

/* Every rank's report gathered on rank 0: each rank's `threads`, its
 * seconds since `t0` and CPU seconds since `cpu0` (cdl_pool_now_seconds,
 * cdl_pool_cpu_seconds), the group's bytes received and work seconds
 * (`work_seconds` where the group is NULL), its peak memory. On rank 0
 * *reports (malloc'd, the caller frees) holds cdl_rank_group_count of
 * them; elsewhere *reports is NULL. A collective. */
cdl_status cdl_rank_reports_gather(cdl_rank_group *group, int threads, double t0, double cpu0, double work_seconds,
                                   cdl_rank_report **reports, cdl_error *err);

#endif
