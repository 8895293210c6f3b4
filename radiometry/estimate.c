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

double cdl_estimate_plan_unseen(double potential, double target_variance, double least)
{
    if (!(target_variance > 0.0) || !(potential > 0.0)) return least;
    double n = ceil(potential / sqrt(target_variance));
    return n > least ? n : least;
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

/* N_j for log lambda = t (estimate.h), held to [least, most]. */
static double allocated(double t, double log_c, double alpha, double least, double most)
{
    double n = exp((t + log_c) / (1.0 + alpha));
    return n < least ? least : n > most ? most : n;
}

typedef struct allocation {
    const double *variance, *pilot, *alpha, *log_c;
    int count;
    double target;
} allocation;

/* The modelled variance of the stage at log lambda = t, N_j held to
 * [least, most], less the target. */
static double allocation_excess(const allocation *a, double t, double least, double most)
{
    double sum = 0.0;
    for (int j = 0; j < a->count; ++j)
        if (a->variance[j] > 0.0)
            sum += a->variance[j] * pow(a->pilot[j] / allocated(t, a->log_c[j], a->alpha[j], least, most), a->alpha[j]);
    return sum - a->target;
}

/* log lambda where the excess changes sign, N_j held to [least, most]:
 * bisection between every N_j at the least and every N_j at the most (the
 * excess falls as t grows), halved until the bracket is two neighbouring
 * doubles. */
static double allocation_solve(const allocation *a, double least, double most)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < a->count; ++j)
        if (a->variance[j] > 0.0) {
            lo = fmin(lo, (1.0 + a->alpha[j]) * log(least) - a->log_c[j]);
            hi = fmax(hi, (1.0 + a->alpha[j]) * log(most) - a->log_c[j]);
        }
    if (!(allocation_excess(a, lo, least, most) > 0.0)) return lo;
    for (;;) {
        double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (allocation_excess(a, mid, least, most) > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

void cdl_estimate_allocate_samples(const double *variance, const double *pilot, const double *alpha, double *samples,
                                   int count, double target_variance, double least, double most)
{
    /* samples[] holds log c_j = log(alpha_j v_j pilot_j^alpha_j) until the
     * end, so that N_j = exp((log lambda + log c_j) / (1 + alpha_j)). */
    int any = 0;
    for (int j = 0; j < count; ++j)
        if (variance[j] > 0.0) {
            any = 1;
            samples[j] = log(alpha[j] * variance[j]) + alpha[j] * log(pilot[j]);
        }
    allocation a = {variance, pilot, alpha, samples, count, target_variance};
    double t = 0.0;
    if (any) {
        /* A target out of reach even with every N_j at the most: planned as
         * if there were no bounds, then bounded. */
        int reachable = target_variance > 0.0 && allocation_excess(&a, INFINITY, least, most) <= 0.0;
        t = reachable ? allocation_solve(&a, least, most) : allocation_solve(&a, 1e-300, 1e300);
    }
    for (int j = 0; j < count; ++j)
        samples[j] = variance[j] > 0.0 ? allocated(t, samples[j], alpha[j], least, most) : least;
}
