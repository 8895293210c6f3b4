/* thread_ranks.h - RANKS threads of one process standing in for RANKS ranks (tests).
 *
 * The four collectives of a cdl_ranks (solver/solve_ranks.h) done through
 * shared memory and a barrier, so that a shared solve runs, and the
 * sanitizers see every exchange, without MPI. The exchange checks what an
 * MPI transport needs of the library: byte ranges in rank order, each an
 * int count, no call beyond 2^30 bytes. A world may make one rank's
 * transport fail at its n-th collective (fail_call, fail_rank). Define
 * RANKS before including it.
 */
#ifndef CANDELA_TESTS_THREAD_RANKS_H
#define CANDELA_TESTS_THREAD_RANKS_H

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "solver/solve_ranks.h"


typedef struct thread_world {
    pthread_barrier_t barrier;
    void *published[RANKS];
    int fail_call;            /* the collective (counted from 1) at which rank fail_rank's transport fails; 0: none */
    int fail_rank;
} thread_world;

typedef struct thread_rank {
    thread_world *world;
    int rank, calls;
} thread_rank;

/* Whether this call fails on this rank (it still takes part in the
 * collective, so that the other threads are not left at the barrier). */
static int failing(thread_rank *t, char *message)
{
    ++t->calls;
    if (t->world->fail_call && t->calls == t->world->fail_call && t->rank == t->world->fail_rank) {
        snprintf(message, CDL_ERROR_MESSAGE_SIZE, "the wire is cut");
        return 1;
    }
    return 0;
}

/* Every rank shows its buffer to the others (NULL: nothing to show). */
static void publish(thread_rank *t, void *buffer)
{
    t->world->published[t->rank] = buffer;
    pthread_barrier_wait(&t->world->barrier);
}

static int exchange(void *user, void *buffer, const size_t *offsets, char *message, int to_all)
{
    thread_rank *t = user;
    int failed = failing(t, message);
    /* What an MPI transport needs: byte ranges in rank order, each an int
     * count, the whole call within the 2^30 bytes solve_ranks.h promises. */
    int sane = offsets[0] == 0 && offsets[RANKS] <= ((size_t)1 << 30);
    for (int k = 0; k < RANKS; ++k) sane &= offsets[k + 1] >= offsets[k];
    if (!sane) {
        snprintf(message, CDL_ERROR_MESSAGE_SIZE, "offsets out of order or too large");
        failed = 1;
        offsets = NULL;
    }
    thread_world *w = t->world;
    publish(t, offsets ? buffer : NULL);
    if (offsets && (to_all || t->rank == 0))
        for (int k = 0; k < RANKS; ++k)
            if (k != t->rank && w->published[k])
                memcpy((char *)buffer + offsets[k], (char *)w->published[k] + offsets[k], offsets[k + 1] - offsets[k]);
    pthread_barrier_wait(&w->barrier);
    return failed;
}

static int allgather(void *user, void *buffer, const size_t *offsets, char *message)
{
    return exchange(user, buffer, offsets, message, 1);
}

static int gather(void *user, void *buffer, const size_t *offsets, char *message)
{
    return exchange(user, buffer, offsets, message, 0);
}

static int reduce_u64(void *user, uint64_t *values, size_t n, int op, char *message)
{
    thread_rank *t = user;
    int failed = failing(t, message);
    thread_world *w = t->world;
    publish(t, values);
    uint64_t result[64];
    for (size_t i = 0; i < n && i < 64; ++i) {
        result[i] = 0;
        for (int k = 0; k < RANKS; ++k) {
            uint64_t v = ((const uint64_t *)w->published[k])[i];
            result[i] = op == CDL_RANKS_MAX ? (v > result[i] ? v : result[i]) : result[i] + v;
        }
    }
    pthread_barrier_wait(&w->barrier);
    memcpy(values, result, (n < 64 ? n : 64) * sizeof *values);
    return failed || n > 64;
}

static int broadcast(void *user, void *buffer, size_t bytes, int root, char *message)
{
    thread_rank *t = user;
    int failed = failing(t, message);
    thread_world *w = t->world;
    publish(t, buffer);
    if (t->rank != root) memcpy(buffer, w->published[root], bytes);
    pthread_barrier_wait(&w->barrier);
    return failed;
}

/* Run body(ranks, user) on RANKS threads, each with its rank's cdl_ranks. */
typedef void (*rank_body)(const cdl_ranks *ranks, void *user);

typedef struct rank_thread {
    thread_rank transport;
    cdl_ranks ranks;
    rank_body body;
    void *user;
} rank_thread;

static void *rank_main(void *arg)
{
    rank_thread *r = arg;
    r->body(&r->ranks, r->user);
    return NULL;
}

static void run_ranks(thread_world *world, rank_body body, void *user)
{
    rank_thread threads[RANKS];
    pthread_t ids[RANKS];
    pthread_barrier_init(&world->barrier, NULL, RANKS);
    for (int k = 0; k < RANKS; ++k) {
        threads[k].transport = (thread_rank){world, k, 0};
        cdl_ranks ranks = CDL_RANKS_INIT;
        ranks.rank = k;
        ranks.count = RANKS;
        ranks.user = &threads[k].transport;
        ranks.allgather = allgather;
        ranks.gather = gather;
        ranks.reduce_u64 = reduce_u64;
        ranks.broadcast = broadcast;
        threads[k].ranks = ranks;
        threads[k].body = body;
        threads[k].user = user;
    }
    for (int k = 0; k < RANKS; ++k) pthread_create(&ids[k], NULL, rank_main, &threads[k]);
    for (int k = 0; k < RANKS; ++k) pthread_join(ids[k], NULL);
    pthread_barrier_destroy(&world->barrier);
}

#endif
