/* Piecewise-constant 2D sampling: cells are chosen in proportion to their
 * weights, zero cells never, stratification survives, bad weights are refused. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitters/distribution2d.h"
#include "base/rng.h"

static void test_frequencies(void)
{
    /* 5 x 3 cells with a zero row, zero cells and a row scale. */
    const float v[15] = {1, 2, 0, 4, 1, /**/ 0, 0, 0, 0, 0, /**/ 3, 0, 5, 1, 2};
    const double scale[3] = {0.5, 7.0, 2.0};
    cdl_distribution2d *d = NULL;
    cdl_error err;
    CHECK_OK(cdl_distribution2d_create(v, scale, 5, 3, &d, &err), &err);
    double total = 0.0;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) total += v[j * 5 + i] * scale[j];
    CHECK_REL(cdl_distribution2d_total(d), total, 1e-15);
    /* 200000 samples: each cell's count is binomial; 5 sigma bounds. */
    int N = 200000, counts[15] = {0};
    double fx_sum = 0, fy_sum = 0;
    int sampled = 0, in_unit = 0;
    cdl_rng_key key = {9, 9};
    for (int k = 0; k < N; ++k) {
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)k, u);
        size_t i, j;
        double fx, fy;
        sampled += cdl_distribution2d_sample(d, u[0], u[1], &i, &j, &fx, &fy) == 1;
        counts[j * 5 + i]++;
        fx_sum += fx;
        fy_sum += fy;
        in_unit += fx >= 0 && fx <= 1 && fy >= 0 && fy <= 1;
    }
    CHECK(sampled == N && in_unit == N);
    for (int c = 0; c < 15; ++c) {
        double p = v[c] * scale[c / 5] / total, mean = N * p, sigma = sqrt(N * p * (1 - p));
        if (p == 0.0) CHECK_MSG(counts[c] == 0, "zero cell %d chosen %d times", c, counts[c]);
        else CHECK_MSG(fabs(counts[c] - mean) <= 5 * sigma, "cell %d: %d vs %.1f", c, counts[c], mean);
    }
    /* Within a cell, the remapped coordinates are uniform: mean 1/2 (5 sigma of 1/sqrt(12 N)). */
    CHECK_ABS(fx_sum / N, 0.5, 5 / sqrt(12.0 * N));
    CHECK_ABS(fy_sum / N, 0.5, 5 / sqrt(12.0 * N));
    cdl_distribution2d_release(d);
}

static void test_inversion_edges(void)
{
    /* cdf of weights {0, 1, 0, 3}: {0, 0.25, 0.25, 1}. */
    const double cdf[4] = {0.0, 0.25, 0.25, 1.0};
    double f;
    CHECK(cdl_distribution_invert_cdf(cdf, 4, 0.0, &f) == 1 && f == 0.0);
    CHECK(cdl_distribution_invert_cdf(cdf, 4, 0.125, &f) == 1 && fabs(f - 0.5) < 1e-15);
    CHECK(cdl_distribution_invert_cdf(cdf, 4, 0.25, &f) == 3 && f == 0.0);
    CHECK(cdl_distribution_invert_cdf(cdf, 4, 0.999999, &f) == 3 && f < 1.0);
    /* Monotone in u: stratified u give stratified cells. */
    size_t prev = 0;
    for (int k = 0; k < 1000; ++k) {
        size_t c = cdl_distribution_invert_cdf(cdf, 4, k / 1000.0, &f);
        CHECK(c >= prev && c != 0 && c != 2);
        prev = c;
    }
}

static void test_zero_and_bad(void)
{
    const float zero[4] = {0, 0, 0, 0};
    cdl_distribution2d *d = NULL;
    cdl_error err;
    CHECK_OK(cdl_distribution2d_create(zero, NULL, 2, 2, &d, &err), &err);
    size_t i, j;
    double fx, fy;
    CHECK(cdl_distribution2d_total(d) == 0.0);
    CHECK(cdl_distribution2d_sample(d, 0.5, 0.5, &i, &j, &fx, &fy) == 0);
    cdl_distribution2d_release(d);
    const float bad[4] = {1, -1, 0, 0};
    CHECK(cdl_distribution2d_create(bad, NULL, 2, 2, &d, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "column 1, row 0"), "%s", err.message);
    const float ok[4] = {1, 1, 1, 1};
    const double nan_scale[2] = {1.0, NAN};
    CHECK(cdl_distribution2d_create(ok, nan_scale, 2, 2, &d, &err) == CDL_ERR_INPUT);
    CHECK(cdl_distribution2d_create(ok, NULL, 0, 2, &d, &err) == CDL_ERR_INPUT);
    CHECK(d == NULL);
    cdl_distribution2d_release(NULL);
}

int main(void)
{
    test_frequencies();
    test_inversion_edges();
    test_zero_and_bad();
    return check_finish();
}
