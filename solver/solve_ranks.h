/* solve_ranks.h - one solve shared by several processes (ranks), the same bytes as one process.
 *
 * cdl_solve_scene_ranks is cdl_solve_scene (solve.h) run by every rank of
 * a group at once, each with the same scene (loaded by each) and options;
 * the ranks talk through the four collective callbacks of a cdl_ranks,
 * which the caller implements over whatever it runs on. With MPI,
 * candela/candela_mpi.h implements them over an MPI_Comm (cdl_solve_scene_mpi),
 * compiled into the caller's program: the library itself needs no MPI.
 *
 * What is split among the ranks, each rank using its own threads on its
 * share: a grid's points and a surface map's vertices in contiguous
 * blocks, the irradiance cache's gathers (each record gathered once, by
 * one rank, then every rank gets every record in the same order, so that
 * every rank interpolates the same). Every item's random numbers are keyed
 * by the item, never by who computes it, so the results are those of one
 * process, bit for bit, for any number of ranks and threads. Rank 0
 * gathers the grids' results from the others in chunks (no rank holds
 * another's share of a grid but rank 0, which writes the outputs) and is
 * the only rank that gets a solution.
 *
 * All ranks must run the same build of the library on the same kind of
 * machine (records and results travel as bytes) and read the same scene
 * and photometric files: the solve checks a hash of them and refuses
 * ranks that differ.
 *
 * Units: bytes, seconds. Ownership: a cdl_ranks and its `user` are the
 * caller's, borrowed for the call. Thread safety: the callbacks are only
 * called from the thread that called cdl_solve_scene_ranks, and every rank
 * calls them in the same order (they are collectives).
 */
#ifndef CANDELA_SOLVER_SOLVE_RANKS_H
#define CANDELA_SOLVER_SOLVE_RANKS_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"
#include "solver/solve_options.h"

/* The reductions of cdl_ranks.reduce_u64. */
typedef enum cdl_ranks_op {
    CDL_RANKS_SUM = 0,                /* element-wise sum over the ranks */
    CDL_RANKS_MAX = 1                 /* element-wise maximum over the ranks */
} cdl_ranks_op;

/* The group of processes a solve is shared by, and how they exchange
 * bytes. Start from CDL_RANKS_INIT (one process, no callbacks) and set
 * every field. Each callback is a collective: every rank calls it with the
 * same arguments but for its own data, and it returns 0 on success or,
 * on failure, non-zero with a message written into `message` (room for
 * CDL_ERROR_MESSAGE_SIZE bytes). No call moves more than 2^30 bytes in
 * all, so counts fit an MPI int. */
typedef struct cdl_ranks {
    size_t size;                      /* sizeof(cdl_ranks) */
    int rank;                         /* this process: 0 .. count - 1; rank 0 gets the solution */
    int count;                        /* processes in the group, >= 1 */
    int local_count;                  /* of those, how many share this machine's cores (>= 1): threads
                                       * left to the default are the cores over this count */
    void *user;                       /* passed to every callback */
    /* Bytes offsets[r] .. offsets[r + 1] - 1 of `buffer` are rank r's
     * (offsets has count + 1 entries, the same on every rank): on return
     * every rank's buffer holds every rank's bytes (MPI_Allgatherv in
     * place). */
    int (*allgather)(void *user, void *buffer, const size_t *offsets, char *message);
    /* The same, but only rank 0's buffer receives the others' bytes
     * (MPI_Gatherv in place at rank 0); the others' buffers are unchanged. */
    int (*gather)(void *user, void *buffer, const size_t *offsets, char *message);
    /* values[0 .. n - 1] reduced element-wise over the ranks by `op` (a
     * cdl_ranks_op), the result on every rank (MPI_Allreduce in place). */
    int (*reduce_u64)(void *user, uint64_t *values, size_t n, int op, char *message);
    /* `bytes` bytes of rank `root`'s buffer copied to every rank's (MPI_Bcast). */
    int (*broadcast)(void *user, void *buffer, size_t bytes, int root, char *message);
} cdl_ranks;

#define CDL_RANKS_INIT                                                                                                \
    {.size = sizeof(cdl_ranks), .rank = 0, .count = 1, .local_count = 1, .user = NULL, .allgather = NULL,             \
     .gather = NULL, .reduce_u64 = NULL, .broadcast = NULL}

/* Solve `scene` on every rank of `ranks` at once (each rank passes its own
 * copy of the same scene and the same options; `ranks` NULL or of count 1
 * is cdl_solve_scene). On rank 0, on success, *out is the solution (freed
 * with cdl_solution_release), as cdl_solve_scene gives it, but for the
 * ranks it records (summary.json "ranks": per rank its threads, seconds,
 * seconds computing its share and bytes received); on the other ranks *out
 * is NULL. The progress callback of `options` is called on rank 0 only (it
 * reports rank 0's share); a cancel there cancels every rank.
 *
 * Failures: a failure any rank meets at planning (a photometric file it
 * cannot read), while computing its share or at finishing (on rank 0) is
 * returned by every rank with the same status and message, which begins
 * "rank R of N: " when not every rank failed; *agreed (when not NULL) is
 * then 1. A failure one rank meets between two exchanges (memory or a
 * failed exchange) is returned by that rank alone with *agreed = 0, while
 * the others wait for it at the next exchange: the caller must then end
 * the whole job (MPI_Abort), as the `candela` command does. Errors besides
 * cdl_solve_scene's: CDL_ERR_INPUT when the ranks' scenes, settings or
 * luminaire files differ, or a cache file is seen by some ranks and not
 * others; CDL_ERR_USAGE for a cdl_ranks without its callbacks or with a
 * rank out of range; CDL_ERR_INTERNAL when an exchange fails (the
 * callback's message). */
cdl_status cdl_solve_scene_ranks(const cdl_scene *scene, const cdl_solve_options *options, const cdl_ranks *ranks,
                                 cdl_solution **out, int *agreed, cdl_error *err);

/* Every rank's `status` (and message in err) made one: on every rank, the
 * status of the lowest rank that failed, with its message prefixed "rank
 * R of N: " unless every rank failed; CDL_OK when none did. A collective:
 * for agreeing on what happened outside a solve (a scene one rank could not
 * load, a folder rank 0 could not write). CDL_ERR_INTERNAL when the
 * exchange itself fails. */
cdl_status cdl_ranks_agree(const cdl_ranks *ranks, cdl_status status, cdl_error *err);

#endif
