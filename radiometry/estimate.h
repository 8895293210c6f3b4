/* estimate.h - Monte-Carlo estimates in rounds, with an honest standard error.
 *
 * A round is a stratified estimate of an integral over the unit square: H
 * strata of equal measure (a k x k grid), two independent uniform samples
 * in each. Its mean is
 *     m = 1/(2H) sum_h (f_h1 + f_h2),
 * and, with two samples a stratum, the variance of m has an unbiased
 * estimate from the within-stratum differences alone:
 *     Var(m) = 1/H^2 sum_h sigma_h^2 / 2,  sigma_h^2 ~ (f_h1 - f_h2)^2 / 2
 *     => v = 1/(4 H^2) sum_h (f_h1 - f_h2)^2
 * (Cochran, "Sampling Techniques", 3rd ed., 1977, 5A.12: stratified
 * sampling with n_h = 2 is the smallest design with an unbiased variance
 * estimate). The plain sample variance of stratified samples would count
 * the between-strata spread the strata remove, and overstate the error
 * several times over.
 *
 * Rounds are independent; they are pooled with weights fixed by their
 * sample counts n_r (not by their estimated variances, which would bias
 * the mean): M = sum n_r m_r / N, Var(M) = sum n_r^2 v_r / N^2.
 *
 * A round in which every sample is 0 gives v = 0 although light could have
 * been missed; callers that know what a missed sample could have carried
 * add that to the variance themselves (cdl_estimate_unseen_variance).
 *
 * Sampling "until the error is small enough" biases both the mean and the
 * stated error when the decision to stop reads the very samples that are
 * reported: for a skewed integrand (a rare bright path, a small hidden
 * part) a low mean comes with a low variance estimate, so runs that happen
 * low stop early and are reported with too small an error. Candela samples
 * in two stages instead: a pilot round only decides how many samples the
 * point needs (cdl_estimate_plan); the samples taken then, whose number no
 * longer depends on them, are the ones reported, whatever they show (any
 * further choice made from them would bias them again). The pilot is
 * small, so discarding it costs little.
 */
#ifndef CANDELA_RADIOMETRY_ESTIMATE_H
#define CANDELA_RADIOMETRY_ESTIMATE_H

#include <stdint.h>

/* One round being summed. */
typedef struct cdl_round {
    double sum;        /* of all samples */
    double sum_d2;     /* of (f_h1 - f_h2)^2 over strata */
    double strata;     /* H */
    uint64_t nonzero;  /* samples != 0 */
} cdl_round;

/* Add the two samples of a stratum of w times the average measure (a
 * round whose strata differ in size, their w summing to H): with weights
 * W_h = w_h / H the stratified mean is sum_h W_h (f_h1 + f_h2) / 2 and
 * Var(m) = sum_h W_h^2 sigma_h^2 / 2 (Cochran 1977, 5.3 and 5A.12), so the
 * pair's terms are w (f1 + f2) and w^2 d^2. */
static inline void cdl_round_add_weighted_pair(cdl_round *r, double f1, double f2, double w)
{
    double d = f1 - f2;
    r->sum += w * (f1 + f2);
    r->sum_d2 += w * w * d * d;
    r->strata += 1.0;
    r->nonzero += (uint64_t)(f1 != 0.0) + (uint64_t)(f2 != 0.0);
}

/* Add the two samples of one stratum (of the average measure). */
static inline void cdl_round_add_pair(cdl_round *r, double f1, double f2)
{
    cdl_round_add_weighted_pair(r, f1, f2, 1.0);
}

/* The pooled estimate of all rounds so far. */
typedef struct cdl_estimate {
    double samples;    /* N = sum n_r */
    double weighted;   /* sum n_r m_r (= the sum of all samples) */
    double var_num;    /* sum n_r^2 v_r */
    uint64_t nonzero;
} cdl_estimate;

void cdl_estimate_add_round(cdl_estimate *e, const cdl_round *r);
double cdl_estimate_mean(const cdl_estimate *e);
/* Variance of the mean (0 before any round). */
double cdl_estimate_variance(const cdl_estimate *e);

/* The variance of an estimate whose N samples were all 0, when each sample
 * could have carried up to `potential` (the value of a sample with nothing
 * in the way): the fraction of the integrand hidden from the samples, under
 * a uniform prior, is Beta(1, N + 1) after N misses, with variance
 * (N + 1) / ((N + 2)^2 (N + 3)); times potential^2. */
double cdl_estimate_unseen_variance(double samples, double potential);

/* Samples that, all seen dark, leave an unseen variance of at most
 * `target_variance` (at least `least`): the plan for a point whose pilot
 * saw nothing. The unseen variance falls as potential^2 / N^2, not as 1 / N
 * like a variance per sample, so planning it with cdl_estimate_plan would
 * ask (pilot / N_needed) times too many samples (a dark point's pilot of
 * 128 then asked for millions); N = potential / sqrt(target_variance)
 * suffices, as (N + 1) / ((N + 2)^2 (N + 3)) < 1 / N^2. */
double cdl_estimate_plan_unseen(double potential, double target_variance, double least);

/* The variance of the mean with one phantom disagreeing pair added:
 * (sum d^2 + jump^2) / N^2, `jump` the largest difference a stratum's two
 * samples could show (for a visibility edge, the unoccluded value of a
 * sample). Why: where the integrand is a step of height a (a light seen or
 * hidden), a stratum straddling the edge with a fraction p on one side
 * gives a differing pair with probability 2p(1 - p), and then d^2 = a^2;
 * so sum d^2 = a^2 D, D the number of differing pairs, and the true
 * Var(m) = a^2 mu / N^2 with mu = E[D] = sum_h 2 p_h (1 - p_h). When few
 * strata straddle the edge, or each only by a sliver, mu is small and
 * D = 0 is likely (P = e^-mu): the pair estimate says 0 although the mean
 * may be off by several strata's worth. D is a sum of independent rare
 * events, Poisson in mu; with a uniform prior on mu, the posterior after
 * observing D is Gamma(D + 1, 1), of mean D + 1 (the same argument as the
 * unseen fraction's Beta(1, N + 1) below). So the honest estimate is
 * a^2 (D + 1) / N^2: the pair estimate plus one phantom pair, which costs
 * nothing where many pairs differ (D >> 1) and is never near zero where
 * the estimate could be far off. Over pooled rounds every pair carries the
 * same weight 1 / N^2, so one phantom pair covers them all. */
double cdl_estimate_bound_variance(const cdl_estimate *e, double jump);

/* Samples for each of `count` estimates sampled together (the sampled
 * lights of one point) so that the sum of their variances reaches
 * `target_variance` with the fewest samples in all. Estimate j was last
 * measured by a round of pilot[j] samples with variance of the mean
 * variance[j], and is modelled as Var_j(N) = variance[j] (pilot[j] /
 * N)^alpha[j] (alpha = 1 for independent samples; stratified samples of a
 * step fall as N^-1.5). Minimising sum N_j subject to sum Var_j(N_j) = V
 * by a Lagrange multiplier lambda gives
 *     1 = lambda alpha_j variance[j] pilot[j]^alpha_j N_j^-(1 + alpha_j),
 *     N_j = (lambda alpha_j variance[j] pilot[j]^alpha_j)^(1 / (1 + alpha_j))
 * (for alpha = 1, Neyman's allocation: N_j proportional to the per-sample
 * standard deviation; Cochran 1977, 5.5). Each N_j is held to
 * [least, most] and lambda found by bisection (the sum of the modelled
 * variances falls as lambda grows) to the resolution of doubles. An
 * estimate of variance 0 gets `least`. A target out of reach even with
 * every N_j at `most` is planned as if there were no bounds, then each N_j
 * bounded (the others are not pushed to `most` by one that cannot meet
 * its share). */
void cdl_estimate_allocate_samples(const double *variance, const double *pilot, const double *alpha, double *samples,
                                   int count, double target_variance, double least, double most);

/* Samples needed for the variance of the mean to reach `target_variance`,
 * from a pilot's variance per sample (Var = c / N), twice as many as that
 * says, for the pilot's own uncertainty (a 128-sample pilot of skewed path
 * values misjudged the variance per sample by up to 2.6x in the furnace
 * test: with a factor 1.5 stated errors reached 1.63 x the target, with 2
 * at most 1.46 x); at least `least`. */
double cdl_estimate_plan(const cdl_estimate *pilot, double target_variance, double least);

/* Strata per side of a round of about `samples` samples (2 k^2 >= samples),
 * at least k_min, at most k_max. */
int cdl_estimate_side_for(double samples, int k_min, int k_max);

/* Strata per side of the next round: enough, at the variance per sample
 * seen so far, to bring the pooled variance down to `target_variance`
 * (with 10 % to spare), but at least half the samples taken so far (rounds
 * grow geometrically) and never more than 4 times them (an early variance
 * estimate may be low); at least k_min and at most k_max. */
int cdl_estimate_next_side(const cdl_estimate *e, double target_variance, int k_min, int k_max);

#endif
