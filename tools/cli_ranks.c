/* cli_ranks.c - the ranks a command runs on (cli_ranks.h). */
#include "cli_ranks.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/error_report.h"

/* A launcher's count of ranks, from its environment (0: none said):
 * Open MPI's mpirun, PMI's (MPICH's hydra, srun --mpi=pmi2), or srun's
 * step of several tasks (with or without an MPI plugin). */
static int launched_count(void)
{
    static const char *const names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"};
    for (size_t i = 0; i < sizeof names / sizeof *names; ++i) {
        const char *v = getenv(names[i]);
        if (v && atoi(v) > 0) return atoi(v);
    }
    return 0;
}

#ifdef CANDELA_WITH_MPI
#include "candela/candela_mpi.h"

/* Started by a launcher: Open MPI's mpirun, PMI (MPICH's hydra, Slurm's
 * srun --mpi=pmi2), PMIx (Slurm's srun --mpi=pmix, prterun), or srun
 * with several tasks. */
static int launched(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMIX_RANK") || getenv("PMI_RANK") || getenv("PMI_SIZE") ||
           launched_count() > 1;
}

/* Ranks but 0 say nothing: rank 0 prints what the ranks agreed on. */
static void silence(cdl_cli_ranks *ranks)
{
    fflush(stdout);
    fflush(stderr);
    ranks->stderr_copy = dup(STDERR_FILENO);
    int null = open("/dev/null", O_WRONLY);
    if (null < 0) return;
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    close(null);
}

int cdl_cli_ranks_begin(const char *command, cdl_cli_ranks *ranks)
{
    memset(ranks, 0, sizeof *ranks);
    ranks->stderr_copy = -1;
    cdl_rank_group_init(&ranks->group, NULL, NULL);
    if (!launched()) return 0;
    int provided = 0;
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "candela %s: MPI could not start under this launcher\n", command);
        return 3;
    }
    ranks->mpi = 1;
    cdl_mpi_ranks *r = malloc(sizeof *r);
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = r ? cdl_mpi_ranks_open(MPI_COMM_WORLD, r, &err) : cdl_error_out_of_memory(&err);
    if (st == CDL_OK) st = cdl_rank_group_init(&ranks->group, &r->ranks, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela %s: %s\n", command, err.message);
        free(r);
        MPI_Abort(MPI_COMM_WORLD, (int)st);
        return (int)st;
    }
    ranks->transport = r;
    /* srun without an MPI plugin starts lone processes that would each
     * solve everything into the same folder. */
    int tasks = launched_count();
    if (ranks->group.count == 1 && tasks > 1) {
        fprintf(stderr, "candela %s: started as one of %d tasks but MPI sees one: start them with mpirun, or srun "
                        "--mpi=pmix (or pmi2), as the README shows\n", command, tasks);
        MPI_Abort(MPI_COMM_WORLD, 2);
        return 2;
    }
    if (ranks->group.rank != 0) silence(ranks);
    return 0;
}

void cdl_cli_ranks_abort(cdl_cli_ranks *ranks, const char *command, int status, const cdl_error *err)
{
    char line[CDL_ERROR_MESSAGE_SIZE + 128];
    int n = snprintf(line, sizeof line, "candela %s: rank %d of %d: %s (ending every rank)\n", command,
                     ranks->group.rank, ranks->group.count, err ? err->message : "failed");
    int fd = ranks->stderr_copy >= 0 ? ranks->stderr_copy : STDERR_FILENO;
    if (n > 0 && write(fd, line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1) < 0) n = 0;
    if (ranks->mpi && ranks->group.count > 1) MPI_Abort(MPI_COMM_WORLD, status);
}

void cdl_cli_ranks_end(cdl_cli_ranks *ranks)
{
    if (ranks->transport) cdl_mpi_ranks_close(ranks->transport);
    free(ranks->transport);
    ranks->transport = NULL;
    if (ranks->stderr_copy >= 0) close(ranks->stderr_copy);
    ranks->stderr_copy = -1;
    if (ranks->mpi) MPI_Finalize();
    ranks->mpi = 0;
}

#else

int cdl_cli_ranks_begin(const char *command, cdl_cli_ranks *ranks)
{
    memset(ranks, 0, sizeof *ranks);
    ranks->stderr_copy = -1;
    cdl_rank_group_init(&ranks->group, NULL, NULL);
    /* Without MPI, N processes a launcher started would each solve all of
     * it into the same folder. */
    int n = launched_count();
    if (n > 1) {
        fprintf(stderr, "candela %s: started as one of %d ranks, but this candela was built without MPI "
                        "(CMake option CANDELA_MPI): run it alone, or build it with MPI\n", command, n);
        return 2;
    }
    return 0;
}

void cdl_cli_ranks_abort(cdl_cli_ranks *ranks, const char *command, int status, const cdl_error *err)
{
    (void)ranks;
    (void)status;
    fprintf(stderr, "candela %s: %s\n", command, err ? err->message : "failed");
}

void cdl_cli_ranks_end(cdl_cli_ranks *ranks)
{
    (void)ranks;
}

#endif

void cdl_cli_ranks_follow(cdl_cli_ranks *ranks, const char *command, void *value, size_t bytes)
{
    cdl_error err;
    cdl_error_clear(&err);
    if (cdl_rank_broadcast(&ranks->group, value, bytes, &err) != CDL_OK)
        cdl_cli_ranks_abort(ranks, command, (int)err.status, &err);
}

int cdl_cli_ranks_root(const cdl_cli_ranks *ranks)
{
    return ranks->group.rank == 0;
}

cdl_status cdl_cli_ranks_agree(cdl_cli_ranks *ranks, cdl_status status, cdl_error *err)
{
    return cdl_rank_agree(&ranks->group, status, err);
}
