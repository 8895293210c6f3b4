/* Pooled paired-stratified estimates (radiometry/estimate.h): the phantom
 * pair of cdl_estimate_bound_variance and the allocation of samples among
 * estimates sampled together, against their closed forms. Tolerances:
 * 1e-12 relative, a few roundings of sums of a handful of terms. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "radiometry/estimate.h"

static cdl_estimate estimate_of_pairs(const double (*pairs)[2], int count)
{
    cdl_round r = {0.0, 0.0, 0.0, 0};
    for (int h = 0; h < count; ++h) cdl_round_add_pair(&r, pairs[h][0], pairs[h][1]);
    cdl_estimate e = {0.0, 0.0, 0.0, 0};
    cdl_estimate_add_round(&e, &r);
    return e;
}

/* One differing pair of a step of height 3 among four strata: the pair
 * estimate is 3^2 / 8^2, the bound counts D + 1 = 2 pairs: 2 x 9 / 64. */
static void test_bound_variance_counts_one_more_pair(void)
{
    const double pairs[4][2] = {{3, 3}, {0, 0}, {3, 0}, {0, 0}};
    cdl_estimate e = estimate_of_pairs(pairs, 4);
    CHECK_REL(cdl_estimate_variance(&e), 9.0 / 64.0, 1e-12);
    CHECK_REL(cdl_estimate_bound_variance(&e, 3.0), 18.0 / 64.0, 1e-12);
}

/* Every pair agreeing: the pair estimate is 0, the bound one step's worth,
 * jump^2 / N^2, never 0 while a step could hide in a stratum. */
static void test_bound_variance_of_agreeing_pairs(void)
{
    const double pairs[3][2] = {{2, 2}, {0, 0}, {2, 2}};
    cdl_estimate e = estimate_of_pairs(pairs, 3);
    CHECK(cdl_estimate_variance(&e) == 0.0);
    CHECK_REL(cdl_estimate_bound_variance(&e, 2.0), 4.0 / 36.0, 1e-12);
    cdl_estimate none = {0.0, 0.0, 0.0, 0};
    CHECK(cdl_estimate_bound_variance(&none, 2.0) == 0.0);
}

/* Strata of unequal measure: weights 1.5 and 0.5 of the average (H = 2),
 * pairs (4, 2) and (1, 5): the stratified mean sum W_h (f_h1 + f_h2) / 2
 * with W = {0.75, 0.25} is 0.75 x 3 + 0.25 x 3 = 3, and its variance
 * sum W_h^2 d_h^2 / 4 = (0.5625 x 4 + 0.0625 x 16) / 4 = 0.8125. */
static void test_weighted_pairs(void)
{
    cdl_round r = {0.0, 0.0, 0.0, 0};
    cdl_round_add_weighted_pair(&r, 4.0, 2.0, 1.5);
    cdl_round_add_weighted_pair(&r, 1.0, 5.0, 0.5);
    cdl_estimate e = {0.0, 0.0, 0.0, 0};
    cdl_estimate_add_round(&e, &r);
    CHECK_REL(cdl_estimate_mean(&e), 3.0, 1e-15);
    CHECK_REL(cdl_estimate_variance(&e), 0.8125, 1e-15);
}

/* Neyman (alpha = 1): N_j = pilot sqrt(v_j) sum sqrt(v) / V. Variances 4
 * and 1 of a 100-sample pilot, target 0.01: N = 100 x {2, 1} x 3 / 0.01 =
 * {60000, 30000}, and the modelled variances sum to the target. */
static void test_allocate_neyman(void)
{
    double v[2] = {4.0, 1.0}, pilot[2] = {100.0, 100.0}, alpha[2] = {1.0, 1.0}, n[2];
    cdl_estimate_allocate_samples(v, pilot, alpha, n, 2, 0.01, 10.0, 1e9);
    CHECK_REL(n[0], 60000.0, 1e-12);
    CHECK_REL(n[1], 30000.0, 1e-12);
    CHECK_REL(v[0] * 100.0 / n[0] + v[1] * 100.0 / n[1], 0.01, 1e-12);
}

/* alpha = 1.5 for all: N_j proportional to v_j^0.4, the modelled
 * variances sum v_j (pilot / N_j)^1.5 meeting the target. */
static void test_allocate_steeper(void)
{
    double v[3] = {8.0, 1.0, 0.5}, pilot[3] = {72.0, 72.0, 72.0}, alpha[3] = {1.5, 1.5, 1.5}, n[3];
    cdl_estimate_allocate_samples(v, pilot, alpha, n, 3, 1e-4, 1.0, 1e12);
    double sum = 0.0;
    for (int j = 0; j < 3; ++j) sum += v[j] * pow(72.0 / n[j], 1.5);
    CHECK_REL(sum, 1e-4, 1e-12);
    CHECK_REL(n[0] / n[1], pow(8.0, 0.4), 1e-12);
    CHECK_REL(n[2] / n[1], pow(0.5, 0.4), 1e-12);
}

/* One estimate: N = pilot (v / V)^(1 / alpha), the model solved for N. */
static void test_allocate_one(void)
{
    double v = 2.0, pilot = 288.0, alpha = 1.25, n;
    cdl_estimate_allocate_samples(&v, &pilot, &alpha, &n, 1, 1e-3, 72.0, 1e9);
    CHECK_REL(n, 288.0 * pow(2.0 / 1e-3, 1.0 / 1.25), 1e-12);
}

/* Exponents and pilots differing: the optimum has the same marginal cost
 * for every estimate, d Var_j / d N_j = -alpha_j Var_j(N_j) / N_j equal
 * (the Lagrange condition), and the variances sum to the target. */
static void test_allocate_mixed(void)
{
    double v[3] = {5.0, 0.3, 2.0}, pilot[3] = {72.0, 288.0, 1152.0}, alpha[3] = {1.0, 1.5, 2.0}, n[3];
    cdl_estimate_allocate_samples(v, pilot, alpha, n, 3, 1e-3, 1.0, 1e15);
    double sum = 0.0, marginal[3];
    for (int j = 0; j < 3; ++j) {
        double var = v[j] * pow(pilot[j] / n[j], alpha[j]);
        sum += var;
        marginal[j] = alpha[j] * var / n[j];
    }
    CHECK_REL(sum, 1e-3, 1e-12);
    CHECK_REL(marginal[1], marginal[0], 1e-10);
    CHECK_REL(marginal[2], marginal[0], 1e-10);
}

/* The bounds: a variance 0 gets the least, a plan above the most the most
 * (a target out of reach: each as planned without bounds, then bounded);
 * an estimate held at the most leaves the rest of the target to the
 * others. */
static void test_allocate_bounds(void)
{
    double v[3] = {0.0, 1e-12, 1e6}, pilot[3] = {72.0, 72.0, 72.0}, alpha[3] = {1.0, 1.0, 1.0}, n[3];
    cdl_estimate_allocate_samples(v, pilot, alpha, n, 3, 1.0, 72.0, 5000.0);
    CHECK(n[0] == 72.0);
    CHECK(n[1] == 72.0);
    CHECK(n[2] == 5000.0);
    /* Neyman would give the first 72 x 1000 x 1100 / 1.5e4 = 5280 > 5000:
     * held there, its variance is 1e6 x 72 / 5000 = 14400, and the second
     * takes the rest of the target: 72 x 1e4 / (1.5e4 - 14400) = 1200. */
    double w[2] = {1e6, 1e4}, m[2];
    cdl_estimate_allocate_samples(w, pilot, alpha, m, 2, 1.5e4, 72.0, 5000.0);
    CHECK(m[0] == 5000.0);
    CHECK_REL(m[1], 1200.0, 1e-12);
}

int main(void)
{
    test_bound_variance_counts_one_more_pair();
    test_bound_variance_of_agreeing_pairs();
    test_weighted_pairs();
    test_allocate_neyman();
    test_allocate_steeper();
    test_allocate_one();
    test_allocate_mixed();
    test_allocate_bounds();
    return check_finish();
}
