/* The annual hours' product E = S C^T (daylight/annual.h,
 * cdl_annual_product) on drawn skies and coefficients, 1100 hours (two
 * blocks of 512 and a short one) by 1000 points by 146 patches:
 *  - every entry against the sum in double precision: float32 products of
 *    146 terms, all positive, each rounded to 2^-24 relative and summed
 *    with at most 146 further roundings, are within 146 x 2^-24 = 8.7e-6 of
 *    the exact sum; 1e-5 relative is held;
 *  - the same bytes on 1 and 3 of Candela's threads, and with OpenBLAS
 *    (when it is the BLAS) set beforehand to 1 and to 2 threads of its own:
 *    a threaded BLAS rounds as its split of the product falls, so the
 *    product must not let it split (mpirun's binding of ranks to cores
 *    would otherwise change the bytes of `candela annual`).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "daylight/annual.h"

extern void openblas_set_num_threads(int threads) __attribute__((weak));

enum { R = 1100, N = 1000, K = 146 };

/* A fixed draw in [0, 1). */
static float draw(unsigned long long *state)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (float)((*state >> 40) * 0x1p-24);
}

int main(void)
{
    float *S = malloc((size_t)R * K * sizeof *S), *C = malloc((size_t)N * K * sizeof *C);
    float *E[3];
    for (int k = 0; k < 3; ++k) E[k] = malloc((size_t)R * N * sizeof *E[k]);
    unsigned long long state = 7;
    /* skies of up to 3000 cd/m2, coefficients of up to the projected solid angle of a patch */
    for (size_t i = 0; i < (size_t)R * K; ++i) S[i] = 3000.0f * draw(&state);
    for (size_t i = 0; i < (size_t)N * K; ++i) C[i] = 0.04f * draw(&state);
    cdl_error err;
    if (openblas_set_num_threads) openblas_set_num_threads(2);
    CHECK_OK(cdl_annual_product(S, R, C, N, K, E[0], 1, &err), &err);
    CHECK_OK(cdl_annual_product(S, R, C, N, K, E[1], 3, &err), &err);
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    CHECK_OK(cdl_annual_product(S, R, C, N, K, E[2], 2, &err), &err);
    CHECK_MSG(memcmp(E[0], E[1], (size_t)R * N * sizeof *E[0]) == 0, "1 and 3 threads: other bytes");
    CHECK_MSG(memcmp(E[0], E[2], (size_t)R * N * sizeof *E[0]) == 0, "OpenBLAS at 2 and 1 threads: other bytes");
    double worst = 0.0;
    for (size_t r = 0; r < R; ++r)
        for (size_t i = 0; i < N; ++i) {
            double exact = 0.0;
            for (size_t k = 0; k < K; ++k) exact += (double)S[r * K + k] * (double)C[i * K + k];
            worst = fmax(worst, fabs(E[0][r * N + i] - exact) / exact);
        }
    /* 146 roundings of 2^-24 at most (header) */
    CHECK_MSG(worst < 1e-5, "worst relative error %.3g", worst);
    for (int k = 0; k < 3; ++k) free(E[k]);
    free(S);
    free(C);
    return check_finish();
}
