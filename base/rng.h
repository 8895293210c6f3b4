/* rng.h - a counter-based random number generator.
 *
 * Philox-4x32-10 (Salmon, Moraes, Dror & Shaw, "Parallel random numbers: as
 * easy as 1, 2, 3", SC'11). A random value is a pure function of
 * (seed, stream, index): the solver keys streams by grid point or record and
 * indexes by sample, so results never depend on thread scheduling or on how
 * work is split. There is no generator state to share or to seed per thread.
 */
#ifndef CANDELA_BASE_RNG_H
#define CANDELA_BASE_RNG_H

#include <stdint.h>

typedef struct cdl_rng_key {
    uint64_t seed;   /* the scene's seed */
    uint64_t stream; /* e.g. grid point id, record id, purpose tag */
} cdl_rng_key;

/* Four independent 32-bit words for counter `index`. */
void cdl_rng_words(cdl_rng_key key, uint64_t index, uint32_t out[4]);

/* Two independent uniform doubles in [0, 1) with 53 random bits each. */
void cdl_rng_uniform2(cdl_rng_key key, uint64_t index, double out[2]);

/* A stream id mixing several integers (e.g. purpose, point, light). */
uint64_t cdl_rng_stream_id(uint64_t a, uint64_t b, uint64_t c);

#endif
