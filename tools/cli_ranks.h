/* cli_ranks.h - the ranks a command runs on: the world of an MPI launcher, or this process alone.
 *
 * `candela solve`, `candela bench` and `candela annual` share their work among the ranks
 * when started by an MPI launcher (mpirun, mpiexec, srun with PMI or
 * PMIx: their environment says so), in a build with MPI (CMake option
 * CANDELA_MPI); otherwise, and for every other command, a process is alone
 * and MPI is never initialised. Rank 0 prints and writes: the other ranks'
 * standard output and error go to /dev/null once MPI has started, but for
 * a failure one of them meets alone (cdl_cli_ranks_abort). Every rank
 * exits with the status the ranks agreed on.
 */
#ifndef CANDELA_TOOLS_CLI_RANKS_H
#define CANDELA_TOOLS_CLI_RANKS_H

#include "base/error.h"
#include "solver/rank_group.h"

typedef struct cdl_cli_ranks {
    cdl_rank_group group;     /* the ranks, for the solver (one: this process alone) */
    int mpi;                  /* 1: MPI was initialised by cdl_cli_ranks_begin */
    void *transport;          /* the MPI communicator's cdl_mpi_ranks (owned), or NULL */
    int stderr_copy;          /* on ranks but 0: the standard error they had, for cdl_cli_ranks_abort; else -1 */
} cdl_cli_ranks;

/* Join the launcher's ranks when there is one. Returns 0, or an exit
 * status after saying on stderr why MPI could not start. */
int cdl_cli_ranks_begin(const char *command, cdl_cli_ranks *ranks);

/* 1 on rank 0 (the one that prints and writes). */
int cdl_cli_ranks_root(const cdl_cli_ranks *ranks);

/* Every rank's status made one (cdl_rank_agree): each rank's own steps
 * (loading the scene, rank 0's folder and files). */
cdl_status cdl_cli_ranks_agree(cdl_cli_ranks *ranks, cdl_status status, cdl_error *err);

/* Rank 0's `bytes` at `value` on every rank: what rank 0 decided from its
 * own clock or files (a budget, a reference to reuse). A failed exchange
 * ends every rank (cdl_cli_ranks_abort). */
void cdl_cli_ranks_follow(cdl_cli_ranks *ranks, const char *command, void *value, size_t bytes);

/* A failure this rank met alone while the others wait for it in an
 * exchange: say so on stderr and end every rank with `status` (MPI_Abort);
 * does not return under MPI. Without ranks it only returns. */
void cdl_cli_ranks_abort(cdl_cli_ranks *ranks, const char *command, int status, const cdl_error *err);

/* Leave MPI (when it was initialised here). */
void cdl_cli_ranks_end(cdl_cli_ranks *ranks);

#endif
