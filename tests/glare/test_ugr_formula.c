/* The UGR formula and its error (glare/ugr.h) by hand, its scaling laws,
 * the delta-method error against finite differences, and bad input. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "glare/ugr.h"

static double rate(const cdl_ugr_sum *s, double Lb)
{
    cdl_ugr u;
    cdl_error err;
    if (cdl_ugr_evaluate(s, cdl_nits(Lb), 0.0, &u, &err) != CDL_OK || !u.defined) return NAN;
    return u.value;
}

static void test_by_hand(void)
{
    /* one source: L 10000 cd/m2, omega 0.001 sr, p 2, Lb 40 cd/m2:
     * sum = 1e8 1e-3 / 4 = 25000; UGR = 8 log10(0.25 25000 / 40) =
     * 8 log10(156.25) = 17.5505... */
    cdl_ugr_sum s = {0.0, 0.0, 0};
    cdl_ugr_term t = cdl_ugr_term_make(cdl_nits(10000.0), 0.0, 0.001, 0.0, 2.0);
    CHECK_ABS(t.value, 25000.0, 1e-9);
    CHECK(t.sigma == 0.0);
    cdl_ugr_sum_add(&s, t);
    CHECK(s.count == 1);
    /* log10(156.25) = 2.193820026016112 */
    CHECK_ABS(rate(&s, 40.0), 8.0 * 2.193820026016112, 1e-12);
    /* two alike: + 8 log10 2; twice the background: - 8 log10 2 */
    cdl_ugr_sum_add(&s, t);
    CHECK_ABS(rate(&s, 40.0), 8.0 * (2.193820026016112 + log10(2.0)), 1e-12);
    CHECK_ABS(rate(&s, 80.0), 8.0 * 2.193820026016112, 1e-12);
    /* sources outside the table (p 0) and dark ones add nothing */
    cdl_ugr_sum_add(&s, cdl_ugr_term_make(cdl_nits(1e6), 0.0, 0.1, 0.0, 0.0));
    cdl_ugr_sum_add(&s, cdl_ugr_term_make(cdl_nits(0.0), 0.0, 0.1, 0.0, 1.0));
    CHECK(s.count == 2);
    /* nothing in view: no rating, not a number */
    cdl_ugr_sum none = {0.0, 0.0, 0};
    cdl_ugr u = {1, 5.0, 5.0};
    cdl_error err;
    CHECK_OK(cdl_ugr_evaluate(&none, cdl_nits(10.0), 0.0, &u, &err), &err);
    CHECK(u.defined == 0 && u.value == 0.0 && u.sigma == 0.0);
}

/* The stated error against the finite-difference derivatives of the
 * rating in each input, combined in quadrature (the delta method done
 * numerically): terms with stated errors of L and omega, and Lb's. */
static void test_error_propagation(void)
{
    const double L[3] = {20000.0, 8000.0, 3000.0}, w[3] = {2e-3, 5e-4, 1e-2}, p[3] = {1.3, 2.5, 4.0};
    const double sL[3] = {200.0, 40.0, 90.0}, sw[3] = {4e-5, 2e-5, 1e-4};
    const double Lb = 35.0, sLb = 0.7;
    cdl_ugr_sum s = {0.0, 0.0, 0};
    for (int i = 0; i < 3; ++i) cdl_ugr_sum_add(&s, cdl_ugr_term_make(cdl_nits(L[i]), sL[i], w[i], sw[i], p[i]));
    cdl_ugr u;
    cdl_error err;
    CHECK_OK(cdl_ugr_evaluate(&s, cdl_nits(Lb), sLb, &u, &err), &err);
    /* numerically: UGR(inputs) recomputed with each input moved by a
     * small step h, slope times its sigma, summed in quadrature */
    double var = 0.0;
    for (int k = 0; k < 7; ++k) {
        double Lk[3], wk[3], Lbk = Lb, h = 1e-6, sigma;
        memcpy(Lk, L, sizeof Lk);
        memcpy(wk, w, sizeof wk);
        if (k < 3) Lk[k] *= 1.0 + h, sigma = sL[k] / L[k];
        else if (k < 6) wk[k - 3] *= 1.0 + h, sigma = sw[k - 3] / w[k - 3];
        else Lbk *= 1.0 + h, sigma = sLb / Lb;
        cdl_ugr_sum sk = {0.0, 0.0, 0};
        for (int i = 0; i < 3; ++i) cdl_ugr_sum_add(&sk, cdl_ugr_term_make(cdl_nits(Lk[i]), 0.0, wk[i], 0.0, p[i]));
        double slope = (rate(&sk, Lbk) - u.value) / h; /* per relative change */
        var += slope * slope * sigma * sigma;
    }
    /* forward differences of a log at h = 1e-6: relative error about h */
    CHECK_REL(u.sigma, sqrt(var), 1e-5);
    CHECK(u.sigma > 0.05 && u.sigma < 0.5);
}

static void test_bad_input(void)
{
    cdl_ugr_sum s = {100.0, 0.0, 1};
    cdl_ugr u = {7, 7.0, 7.0};
    cdl_error err;
    CHECK(cdl_ugr_evaluate(&s, cdl_nits(0.0), 0.0, &u, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "background luminance") != NULL);
    CHECK(u.defined == 7); /* untouched */
    CHECK(cdl_ugr_evaluate(&s, cdl_nits(NAN), 0.0, &u, &err) == CDL_ERR_INPUT);
    CHECK(cdl_ugr_evaluate(&s, cdl_nits(-3.0), 0.0, &u, &err) == CDL_ERR_INPUT);
    CHECK(cdl_ugr_evaluate(&s, cdl_nits(10.0), -1.0, &u, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "standard error") != NULL);
    cdl_ugr_sum bad = {INFINITY, 0.0, 1};
    CHECK(cdl_ugr_evaluate(&bad, cdl_nits(10.0), 0.0, &u, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "glare sources") != NULL);
    CHECK(cdl_ugr_evaluate(&s, cdl_nits(10.0), 0.0, &u, NULL) == CDL_OK);
}

int main(void)
{
    test_by_hand();
    test_error_propagation();
    test_bad_input();
    return check_finish();
}
