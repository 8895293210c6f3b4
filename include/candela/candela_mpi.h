/* candela/candela_mpi.h - a Candela solve shared by the ranks of an MPI communicator.
 *
 * A program that runs under MPI (mpirun, srun) solves a scene on all its
 * ranks at once with cdl_solve_scene_mpi: every rank loads the same scene
 * and calls it with the same options; each computes its share with its
 * own threads, and rank 0 gets the solution, bit for bit what one process
 * would get (solver/solve_ranks.h says what is split and how failures
 * end every rank).
 *
 * This header is not part of candela/candela.h, so that programs without
 * MPI never need mpi.h, and libcandela itself has no MPI in it: the
 * functions below implement the four collectives of a cdl_ranks over an
 * MPI_Comm as static inline functions, compiled into the program that
 * includes this header with its own MPI (`mpicc`, or CMake's MPI::MPI_C
 * beside Candela::candela). Any MPI-3 implementation will do.
 *
 *     #include <mpi.h>
 *     #include <candela/candela_mpi.h>
 *     ...
 *     MPI_Init(&argc, &argv);
 *     cdl_scene_load(path, &scene, &err);           (on every rank; agree with cdl_mpi_agree)
 *     int agreed;
 *     st = cdl_solve_scene_mpi(scene, &options, MPI_COMM_WORLD, &solution, &agreed, &err);
 *     if (st != CDL_OK && !agreed) MPI_Abort(MPI_COMM_WORLD, st);   (this rank failed alone)
 *     if (solution) ... (rank 0)
 *
 * The communicator is duplicated for the solve (its messages never meet
 * the caller's) and its errors are returned, not fatal. Units: none.
 * Ownership: the communicator stays the caller's. Thread safety: call from
 * the thread that initialised MPI (MPI_THREAD_FUNNELED is enough: the
 * solve's worker threads never call MPI).
 */
#ifndef CANDELA_CANDELA_MPI_H
#define CANDELA_CANDELA_MPI_H

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "candela.h"

/* A cdl_ranks over an MPI communicator: open it, use `ranks`, close it.
 * `ranks.user` points at this struct, which must stay where it was opened
 * until it is closed. */
typedef struct cdl_mpi_ranks {
    cdl_ranks ranks;
    MPI_Comm comm;            /* a duplicate of the caller's, errors returned */
} cdl_mpi_ranks;

static inline void cdl_mpi_message_(int code, const char *what, char *message)
{
    char text[MPI_MAX_ERROR_STRING] = "";
    int length = 0;
    if (MPI_Error_string(code, text, &length) != MPI_SUCCESS) snprintf(text, sizeof text, "MPI error %d", code);
    snprintf(message, CDL_ERROR_MESSAGE_SIZE, "%s: %s", what, text);
}

/* The byte ranges of a cdl_ranks exchange as MPI's counts and displacements. */
static inline int cdl_mpi_exchange_(void *user, void *buffer, const size_t *offsets, char *message, int to_all)
{
    cdl_mpi_ranks *r = (cdl_mpi_ranks *)user;
    int n = r->ranks.count, me = r->ranks.rank;
    int *counts = (int *)malloc(2 * (size_t)n * sizeof *counts);
    if (!counts) {
        snprintf(message, CDL_ERROR_MESSAGE_SIZE, "out of memory for %d ranks' counts", n);
        return 1;
    }
    int *displs = counts + n;
    for (int k = 0; k < n; ++k) {
        counts[k] = (int)(offsets[k + 1] - offsets[k]);
        displs[k] = (int)offsets[k];
    }
    int code;
    if (to_all)
        code = MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, buffer, counts, displs, MPI_BYTE, r->comm);
    else if (me == 0)
        code = MPI_Gatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, buffer, counts, displs, MPI_BYTE, 0, r->comm);
    else
        code = MPI_Gatherv((char *)buffer + offsets[me], counts[me], MPI_BYTE, NULL, counts, displs, MPI_BYTE, 0,
                           r->comm);
    free(counts);
    if (code != MPI_SUCCESS) cdl_mpi_message_(code, to_all ? "MPI_Allgatherv" : "MPI_Gatherv", message);
    return code != MPI_SUCCESS;
}

static inline int cdl_mpi_allgather_(void *user, void *buffer, const size_t *offsets, char *message)
{
    return cdl_mpi_exchange_(user, buffer, offsets, message, 1);
}

static inline int cdl_mpi_gather_(void *user, void *buffer, const size_t *offsets, char *message)
{
    return cdl_mpi_exchange_(user, buffer, offsets, message, 0);
}

static inline int cdl_mpi_reduce_u64_(void *user, uint64_t *values, size_t n, int op, char *message)
{
    cdl_mpi_ranks *r = (cdl_mpi_ranks *)user;
    int code = MPI_Allreduce(MPI_IN_PLACE, values, (int)n, MPI_UINT64_T, op == CDL_RANKS_MAX ? MPI_MAX : MPI_SUM,
                             r->comm);
    if (code != MPI_SUCCESS) cdl_mpi_message_(code, "MPI_Allreduce", message);
    return code != MPI_SUCCESS;
}

static inline int cdl_mpi_broadcast_(void *user, void *buffer, size_t bytes, int root, char *message)
{
    cdl_mpi_ranks *r = (cdl_mpi_ranks *)user;
    int code = MPI_Bcast(buffer, (int)bytes, MPI_BYTE, root, r->comm);
    if (code != MPI_SUCCESS) cdl_mpi_message_(code, "MPI_Bcast", message);
    return code != MPI_SUCCESS;
}

/* Open *out over `comm` (a collective of comm): its rank and size, how many
 * of its ranks share this machine, and the callbacks. CDL_ERR_INTERNAL,
 * with MPI's message, when MPI fails. */
static inline cdl_status cdl_mpi_ranks_open(MPI_Comm comm, cdl_mpi_ranks *out, cdl_error *err)
{
    cdl_ranks init = CDL_RANKS_INIT;
    memset(out, 0, sizeof *out);
    out->ranks = init;
    out->comm = MPI_COMM_NULL;
    char message[CDL_ERROR_MESSAGE_SIZE] = "";
    int code = MPI_Comm_dup(comm, &out->comm);
    if (code == MPI_SUCCESS) code = MPI_Comm_set_errhandler(out->comm, MPI_ERRORS_RETURN);
    if (code == MPI_SUCCESS) code = MPI_Comm_rank(out->comm, &out->ranks.rank);
    if (code == MPI_SUCCESS) code = MPI_Comm_size(out->comm, &out->ranks.count);
    MPI_Comm node = MPI_COMM_NULL;
    if (code == MPI_SUCCESS) code = MPI_Comm_split_type(out->comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    if (code == MPI_SUCCESS) code = MPI_Comm_size(node, &out->ranks.local_count);
    if (node != MPI_COMM_NULL) MPI_Comm_free(&node);
    if (code != MPI_SUCCESS) {
        cdl_mpi_message_(code, "opening the ranks of a communicator", message);
        if (out->comm != MPI_COMM_NULL) MPI_Comm_free(&out->comm);
        if (err) {
            err->status = CDL_ERR_INTERNAL;
            snprintf(err->message, sizeof err->message, "%s", message);
        }
        return CDL_ERR_INTERNAL;
    }
    out->ranks.user = out;
    out->ranks.allgather = cdl_mpi_allgather_;
    out->ranks.gather = cdl_mpi_gather_;
    out->ranks.reduce_u64 = cdl_mpi_reduce_u64_;
    out->ranks.broadcast = cdl_mpi_broadcast_;
    return CDL_OK;
}

/* Free the duplicate communicator (a collective). */
static inline void cdl_mpi_ranks_close(cdl_mpi_ranks *r)
{
    if (r->comm != MPI_COMM_NULL) MPI_Comm_free(&r->comm);
}

/* cdl_solve_scene_ranks (solver/solve_ranks.h) over `comm`: on rank 0 *out
 * is the solution, elsewhere NULL; *agreed (may be NULL) 0 when this rank
 * failed alone (then end the job: MPI_Abort). */
static inline cdl_status cdl_solve_scene_mpi(const cdl_scene *scene, const cdl_solve_options *options, MPI_Comm comm,
                                             cdl_solution **out, int *agreed, cdl_error *err)
{
    *out = NULL;
    if (agreed) *agreed = 0;
    cdl_mpi_ranks r;
    cdl_status st = cdl_mpi_ranks_open(comm, &r, err);
    if (st != CDL_OK) return st;
    int all = 0;
    st = cdl_solve_scene_ranks(scene, options, &r.ranks, out, &all, err);
    if (agreed) *agreed = all;
    /* Freeing a communicator is a collective: not while the others wait
     * for this rank elsewhere (the caller is to end the job). */
    if (all) cdl_mpi_ranks_close(&r);
    return st;
}

/* Every rank's status made one (cdl_ranks_agree): after what each rank did
 * on its own, such as loading the scene. */
static inline cdl_status cdl_mpi_agree(MPI_Comm comm, cdl_status status, cdl_error *err)
{
    cdl_mpi_ranks r;
    cdl_error opening;
    if (cdl_mpi_ranks_open(comm, &r, &opening) != CDL_OK) {
        if (err) *err = opening;
        return CDL_ERR_INTERNAL;
    }
    cdl_status st = cdl_ranks_agree(&r.ranks, status, err);
    cdl_mpi_ranks_close(&r);
    return st;
}

#endif
