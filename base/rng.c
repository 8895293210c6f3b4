/* rng.c - Philox-4x32-10 counter-based generator (Salmon et al., SC'11). */
#include "base/rng.h"

/* Round multipliers and Weyl key increments from the Philox paper, table 2. */
#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u /* golden ratio */
#define PHILOX_W1 0xBB67AE85u /* sqrt(3) - 1 */

static void philox_round(uint32_t c[4], const uint32_t k[2])
{
    uint64_t p0 = (uint64_t)PHILOX_M0 * c[0];
    uint64_t p1 = (uint64_t)PHILOX_M1 * c[2];
    uint32_t hi0 = (uint32_t)(p0 >> 32), lo0 = (uint32_t)p0;
    uint32_t hi1 = (uint32_t)(p1 >> 32), lo1 = (uint32_t)p1;
    uint32_t n0 = hi1 ^ c[1] ^ k[0];
    uint32_t n1 = lo1;
    uint32_t n2 = hi0 ^ c[3] ^ k[1];
    uint32_t n3 = lo0;
    c[0] = n0; c[1] = n1; c[2] = n2; c[3] = n3;
}

void cdl_rng_words(cdl_rng_key key, uint64_t index, uint32_t out[4])
{
    /* counter = (index, stream), key = a 64-bit fold of the seed. */
    uint32_t c[4] = {(uint32_t)index, (uint32_t)(index >> 32), (uint32_t)key.stream,
                     (uint32_t)(key.stream >> 32)};
    uint32_t k[2] = {(uint32_t)key.seed, (uint32_t)(key.seed >> 32)};
    for (int round = 0; round < 10; ++round) {
        philox_round(c, k);
        k[0] += PHILOX_W0;
        k[1] += PHILOX_W1;
    }
    out[0] = c[0]; out[1] = c[1]; out[2] = c[2]; out[3] = c[3];
}

void cdl_rng_uniform2(cdl_rng_key key, uint64_t index, double out[2])
{
    uint32_t w[4];
    cdl_rng_words(key, index, w);
    /* 53 bits from two words each: (hi 32 bits << 21 | lo 21 bits) / 2^53. */
    const double inv = 1.0 / 9007199254740992.0; /* 2^-53 */
    uint64_t a = ((uint64_t)w[0] << 21) | (w[1] >> 11);
    uint64_t b = ((uint64_t)w[2] << 21) | (w[3] >> 11);
    out[0] = (double)a * inv;
    out[1] = (double)b * inv;
}

/* SplitMix64 finaliser (Steele, Lea & Flood, OOPSLA 2014) as a mixing step. */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t cdl_rng_stream_id(uint64_t a, uint64_t b, uint64_t c)
{
    return mix64(mix64(mix64(a) ^ b) ^ c);
}
