/* The counter-based generator: Philox-4x32-10 known answers and the
 * properties the solver relies on. */
#include <stdint.h>

#include "check.h"
#include "base/rng.h"

int main(void)
{
    /* Known-answer vectors published with Random123 (Salmon et al. 2011,
     * tests/kat_vectors). Counter (c0..c3) = (index lo, index hi, stream lo,
     * stream hi); key (k0, k1) = (seed lo, seed hi). */
    uint32_t w[4];
    cdl_rng_words((cdl_rng_key){0, 0}, 0, w);
    CHECK(w[0] == 0x6627e8d5u && w[1] == 0xe169c58du && w[2] == 0xbc57ac4cu && w[3] == 0x9b00dbd8u);
    cdl_rng_words((cdl_rng_key){UINT64_MAX, UINT64_MAX}, UINT64_MAX, w);
    CHECK(w[0] == 0x408f276du && w[1] == 0x41c83b0eu && w[2] == 0xa20bc7c6u && w[3] == 0x6d5451fdu);
    cdl_rng_words((cdl_rng_key){0x299f31d0a4093822ull, 0x0370734413198a2eull}, 0x85a308d3243f6a88ull, w);
    CHECK(w[0] == 0xd16cfe09u && w[1] == 0x94fdccebu && w[2] == 0x5001e420u && w[3] == 0x24126ea1u);

    /* A pure function of (seed, stream, index). */
    double a[2], b[2];
    cdl_rng_uniform2((cdl_rng_key){7, 3}, 11, a);
    cdl_rng_uniform2((cdl_rng_key){7, 3}, 11, b);
    CHECK(a[0] == b[0] && a[1] == b[1]);
    cdl_rng_uniform2((cdl_rng_key){7, 4}, 11, b);
    CHECK(a[0] != b[0]);
    cdl_rng_uniform2((cdl_rng_key){8, 3}, 11, b);
    CHECK(a[0] != b[0]);

    /* Uniform on [0, 1): mean 1/2 and variance 1/12 over 2^18 draws
     * (tolerances: 5 standard errors). */
    const int n = 1 << 18;
    double sum = 0.0, sum2 = 0.0, lo = 1.0, hi = 0.0;
    for (int i = 0; i < n; ++i) {
        double u[2];
        cdl_rng_uniform2((cdl_rng_key){1, 2}, (uint64_t)i, u);
        for (int k = 0; k < 2; ++k) {
            CHECK(u[k] >= 0.0 && u[k] < 1.0);
            sum += u[k];
            sum2 += u[k] * u[k];
            if (u[k] < lo) lo = u[k];
            if (u[k] > hi) hi = u[k];
        }
    }
    double mean = sum / (2.0 * n), var = sum2 / (2.0 * n) - mean * mean;
    CHECK_ABS(mean, 0.5, 5.0 * sqrt(1.0 / 12.0 / (2.0 * n)));
    CHECK_ABS(var, 1.0 / 12.0, 5.0 * sqrt(1.0 / 180.0 / (2.0 * n)));
    CHECK(lo < 1e-4 && hi > 1.0 - 1e-4);

    /* Stream ids from different tuples differ. */
    CHECK(cdl_rng_stream_id(1, 2, 3) != cdl_rng_stream_id(1, 3, 2));
    CHECK(cdl_rng_stream_id(0, 0, 0) != cdl_rng_stream_id(0, 0, 1));
    return check_finish();
}
