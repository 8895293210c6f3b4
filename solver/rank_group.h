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

/* Rank 0's `bytes` bytes at `buffer` copied to every rank's. */
cdl_status cdl_rank_broadcast(cdl_rank_group *group, void *buffer, size_t bytes, cdl_error *err);

/* values[0 .. n - 1] summed, or their maximum taken, over the ranks. */
cdl_status cdl_rank_sum_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err);
cdl_status cdl_rank_max_u64(cdl_rank_group *group, uint64_t *values, size_t n, cdl_error *err);

#endif
