/* estimate.c - pooling rounds of paired stratified samples (see estimate.h). */
#include "radiometry/estimate.h"

#include <math.h>

void cdl_estimate_add_round(cdl_estimate *e, const cdl_round *r)
{
    double n = 2.0 * r->strata;
    if (!(n > 0.0)) return;
    /* v = sum d^2 / (4 H^2); n^2 v = (2H)^2 v = sum d^2. */
    e->samples += n;
    e->weighted += r->sum;
    e->var_num += r->sum_d2;
    e->nonzero += r->nonzero;
}

double cdl_estimate_mean(const cdl_estimate *e)
{
    return e->samples > 0.0 ? e->weighted / e->samples : 0.0;
}

double cdl_estimate_variance(const cdl_estimate *e)
{
    return e->samples > 0.0 ? e->var_num / (e->samples * e->samples) : 0.0;
}

double cdl_estimate_unseen_variance(double samples, double potential)
{
    double n = samples > 0.0 ? samples : 0.0;
    return potential * potential * (n + 1.0) / ((n + 2.0) * (n + 2.0) * (n + 3.0));
}

int cdl_estimate_next_side(const cdl_estimate *e, double target_variance, int k_min, int k_max)
{
    double n = e->samples;
    double v = cdl_estimate_variance(e);
    double want;
    if (!(n > 0.0)) {
        want = 2.0 * k_min * k_min;
    } else if (!(target_variance > 0.0)) {
        want = 4.0 * n;
    } else {
        /* Var ~ c / N: N_total = N v / target; the round adds the difference. */
        double total = 1.1 * n * v / target_variance;
        want = total - n;
        /* At least half as many again: rounds grow geometrically, so a point
         * takes a few rounds, not thousands of tiny ones. */
        if (want < 0.5 * n) want = 0.5 * n;
        if (want > 4.0 * n) want = 4.0 * n;
    }
    double k = ceil(sqrt(want / 2.0));
    if (k < k_min) k = k_min;
    if (k > k_max) k = k_max;
    return (int)k;
}

double cdl_estimate_plan(const cdl_estimate *pilot, double target_variance, double least)
{
    double c = cdl_estimate_variance(pilot) * pilot->samples;
    if (!(target_variance > 0.0) || !(c > 0.0)) return least;
    double n = 2.0 * c / target_variance;
    return n > least ? n : least;
}

int cdl_estimate_side_for(double samples, int k_min, int k_max)
{
    double k = ceil(sqrt(samples / 2.0));
    if (k < k_min) k = k_min;
    if (k > k_max) k = k_max;
    return (int)k;
}

double cdl_estimate_bound_variance(const cdl_estimate *e, double jump)
{
    if (!(e->samples > 0.0)) return 0.0;
    /* Poisson posterior of the differing pairs (estimate.h): D + 1. */
    return (e->var_num + jump * jump) / (e->samples * e->samples);
}

void cdl_estimate_allocate_samples(const double *variance, double *samples, int count, double pilot_samples,
                                   double alpha, double target_variance, double least, double most)
{
    /* Lagrange: N_j = pilot s v_j^(1/(1+alpha)), s from the constraint
     * sum v_j (pilot / N_j)^alpha = V (estimate.h). */
    double e = 1.0 / (1.0 + alpha), sum = 0.0;
    for (int j = 0; j < count; ++j)
        if (variance[j] > 0.0) sum += pow(variance[j], e);
    double s = target_variance > 0.0 ? pow(sum / target_variance, 1.0 / alpha) : INFINITY;
    for (int j = 0; j < count; ++j) {
        double n = variance[j] > 0.0 ? pilot_samples * s * pow(variance[j], e) : least;
        if (!(n >= least)) n = least;
        if (n > most) n = most;
        samples[j] = n;
    }
}
