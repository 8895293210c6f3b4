/* bench_annual.c - the annual study's hours once the coefficients exist: a
 * year of sky vectors times a grid's coefficients (one BLAS sgemm,
 * daylight/annual.h) and the metrics, on one core.
 *
 *   bench_annual [--hours 8760] [--points 10000] [--mf 1|2|4]
 *
 * The coefficients and skies are made up (a counter-based random number per
 * entry, the shapes of real ones: a point's coefficients sum to about pi,
 * a sky's patches to some thousand cd/m^2); the work does not depend on
 * their values. Reports the seconds of the product and of the metrics
 * (DA300, UDI, EN 17037 over the 8-18 schedule), their sum against the
 * issue's figure of a minute for 8760 hours x 10^4 points ("ratio to one
 * minute"), and the ratio of a plain triple loop's time per hour (over a
 * sample of hours) to the product's; a few entries of the product checked
 * against that loop's (a relative 1e-5: float sums of 146 to 2306 terms).
 * One core: when OPENBLAS_NUM_THREADS is not set the program runs itself
 * again with it set to 1 (OpenBLAS reads it when loaded). Ratios, not
 * limits, are what to compare between versions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/rng.h"
#include "daylight/annual.h"
#include "daylight/annual_metrics.h"
#include "lights/environment/reinhart_patches.h"
#include "solver/pool.h"

static long arg_long(int argc, char **argv, const char *name, long dflt)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], name) == 0) return strtol(argv[i + 1], NULL, 10);
    return dflt;
}

static float uniform(uint64_t stream, uint64_t index)
{
    double u[2];
    cdl_rng_uniform2((cdl_rng_key){1, stream}, index, u);
    return (float)u[0];
}

int main(int argc, char **argv)
{
    if (!getenv("OPENBLAS_NUM_THREADS")) {
        setenv("OPENBLAS_NUM_THREADS", "1", 1);
        execv("/proc/self/exe", argv);
        fprintf(stderr, "bench_annual: could not run itself again with OPENBLAS_NUM_THREADS=1\n");
    }
    size_t H = (size_t)arg_long(argc, argv, "--hours", 8760), N = (size_t)arg_long(argc, argv, "--points", 10000);
    int mf = (int)arg_long(argc, argv, "--mf", 1);
    cdl_reinhart_patches p;
    cdl_error err;
    if (cdl_reinhart_init(&p, mf, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 1, 0), &err) != CDL_OK) {
        fprintf(stderr, "bench_annual: %s\n", err.message);
        return 2;
    }
    size_t K = (size_t)p.count;
    float *C = malloc(N * K * sizeof *C), *S = malloc(H * K * sizeof *S), *E = malloc(H * N * sizeof *E);
    unsigned char *occ = malloc(H), *day = malloc(H);
    cdl_point_metrics *pm = malloc(N * sizeof *pm);
    if (!C || !S || !E || !occ || !day || !pm) {
        fprintf(stderr, "bench_annual: out of memory\n");
        return 3;
    }
    for (size_t i = 0; i < N * K; ++i) C[i] = (float)(2.0 * 3.14159265 / (double)K) * uniform(1, i);
    for (size_t i = 0; i < H * K; ++i) S[i] = 3000.0f * uniform(2, i);
    for (size_t h = 0; h < H; ++h) {
        occ[h] = h % 24 >= 8 && h % 24 < 18;
        day[h] = h % 24 >= 6 && h % 24 < 18;
    }

    double t0 = cdl_pool_now_seconds();
    if (cdl_annual_product(S, H, C, N, K, E, 1, &err) != CDL_OK) {
        fprintf(stderr, "bench_annual: %s\n", err.message);
        return 3;
    }
    double t_product = cdl_pool_now_seconds() - t0;
    t0 = cdl_pool_now_seconds();
    cdl_annual_input in = {H, N, E, NULL, NULL, occ, day, NULL};
    cdl_grid_annual_metrics gm;
    if (cdl_annual_metrics_compute(&in, pm, &gm, &err) != CDL_OK) {
        fprintf(stderr, "bench_annual: %s\n", err.message);
        return 3;
    }
    double t_metrics = cdl_pool_now_seconds() - t0;

    /* a plain loop over a sample of hours, in double: the time per hour, and the product's entries checked */
    size_t sample = H < 24 ? H : 24, bad = 0;
    double *row = malloc(N * sizeof *row);
    t0 = cdl_pool_now_seconds();
    for (size_t q = 0; q < sample; ++q) {
        size_t h = q * (H / sample);
        for (size_t i = 0; i < N; ++i) {
            double sum = 0.0;
            for (size_t k = 0; k < K; ++k) sum += (double)S[h * K + k] * (double)C[i * K + k];
            row[i] = sum;
        }
        for (size_t i = 0; i < N; i += 97) bad += fabs(E[h * N + i] - row[i]) > 1e-5 * fabs(row[i]);
    }
    double t_loop = (cdl_pool_now_seconds() - t0) / (double)sample * (double)H;
    free(row);

    double total = t_product + t_metrics;
    printf("bench_annual: %zu hours x %zu points x %zu patches (MF %d), OPENBLAS_NUM_THREADS=%s\n", H, N, K, mf,
           getenv("OPENBLAS_NUM_THREADS"));
    printf("  product (sgemm) %.3f s, metrics %.3f s, together %.3f s; sDA300 %.1f %% (made-up data)\n", t_product,
           t_metrics, total, gm.sDA300);
    printf("  ratio to one minute (8760 hours x 10^4 points scaled): %.3f\n",
           total * (8760.0 / (double)H) * (1e4 / (double)N) / 60.0);
    printf("  ratio (plain loop / sgemm): %.1f\n", t_loop / t_product);
    printf("  entries off the loop's by more than 1e-5: %zu\n", bad);
    free(C);
    free(S);
    free(E);
    free(occ);
    free(day);
    free(pm);
    return bad ? 1 : 0;
}
