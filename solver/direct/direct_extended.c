/* direct_extended.c - area emitters and skies: closed form where nothing
 * hides them, the hidden part sampled where something may, each point
 * sampled to its own target (a pilot that plans, a stage that is reported).
 *
 * A light with a closed form E_0 (area emitters, skies; cdl_emitter_exact_
 * illuminance) that may be partly hidden is first tried on the exact route
 * (direct_exact_route.c: the visible polygon past few planar occluders,
 * variance 0); where that is refused it is estimated as
 *     E = E_0 - H,   H = int over the emitter of f (1 - V),
 * f = L cos / pdf the unoccluded integrand and V the visibility: a control
 * variate that is exact when nothing is hidden, whose variance comes from
 * the hidden part alone. A light without a closed form is sampled plainly
 * (E = int f V). Samples come in rounds of k x k strata with two samples
 * each (radiometry/estimate.h), so that each round's variance has an
 * unbiased estimate; that estimate is raised by one phantom differing pair
 * (cdl_estimate_bound_variance), since pairs that all agree say little
 * about strata that straddle an edge by a sliver.
 *
 * A point's target: the variance of its direct illuminance (the sum over
 * its sampled lights) at most (t R)^2, t = ctx->target, R = max(E, floor):
 * E the point's direct illuminance (exact terms included), floor a
 * thousandth of what its sampled lights would give with nothing in the way
 * (a point almost wholly shadowed is held to an error relative to the light
 * it could have had, not to the nothing it has). Each sampled light first
 * takes pilot rounds that only plan (plan_stage): from the pilots'
 * variances the point's samples are shared among its lights (cdl_estimate_
 * allocate_samples) to meet the target with the fewest in all, each light's
 * variance modelled as falling with its samples as N^-alpha, alpha by the
 * light's sampler; a light whose plan reaches far beyond its pilot, or
 * whose pilot saw too few strata differ to judge, takes a larger pilot
 * round and the point is planned again. Then each light takes its planned
 * samples (at most CDL_DIRECT_MAX_SAMPLES with its pilots) in one stage,
 * and only the stage is reported, whatever it shows. Stopping when a
 * light's own rounds look quiet would bias both the value and its error
 * (radiometry/estimate.h): a point that happened to miss the bright part
 * stops early with a small stated error. Should the pilot have judged
 * badly, the stated error is off the target and says so; where the cap
 * held a stage short of its plan the route tally counts the point and the
 * plan names it.
 *
 * A light whose samples were all hidden, or none, is not certain: what the
 * samples could have missed is the light's unhidden value times the
 * posterior spread of a fraction seen in none of N samples
 * (cdl_estimate_unseen_variance), and that is its variance at the least.
 */
#include "solver/direct/direct_internal.h"

#include <math.h>
#include <stdlib.h>

#include "lights/environment/environment_sampler.h"
#include "radiometry/estimate.h"
#include "base/rng.h"

/* Strata per side of a light's first pilot round, and the least of a
 * reported stage: 6 x 6 strata, 72 samples. Further pilot rounds double
 * the side (4 times the samples) up to PILOT_MAX_SIDE. */
#define PILOT_SIDE 6
#define PILOT_MAX_SIDE 96

/* A stage is planned from a pilot round of at least 1 / PLAN_REACH of its
 * samples; a pilot round smaller than that is followed by a larger one
 * first. Why: the plan extrapolates the pilot's variance, Var(N) = v
 * (n / N)^alpha, and an error d in alpha moves the planned variance by
 * (N / n)^d: over the 3600-fold reach of a 72-sample pilot to 2^18
 * samples, d = 0.15 is a factor 3.4, over 16-fold a factor 1.5. And a
 * 72-sample pilot sees few strata straddle an edge, a larger one many.
 * The pilots cost about 1/12 to 1/3 of a stage beyond the first (their
 * sum is 4/3 of the last, which is 1/16 to 1/4 of the stage). */
#define PLAN_REACH 16.0

/* ... but from a pilot round of fewer than PLAN_SMALL_PILOT samples (sides
 * 6 to 48: "draft" and the first rounds of the others) at most
 * PLAN_REACH_SMALL times beyond it. Why: the stated sigma scatters about
 * its plan by the pilot's error and the stage's own (each a count of
 * differing pairs, a few dozen at these sizes), and a 16-fold reach from a
 * small pilot adds the error in alpha on top. 4 keeps the stated sigma of
 * far more points within 1.5 of the target than 16, for a few per cent
 * more samples (docs/tuning.md). */
#define PLAN_REACH_SMALL 4.0
#define PLAN_SMALL_PILOT 18432.0

/* A stage is planned from a pilot round that measured its variance from
 * at least PLAN_PAIRS differing pairs in effect (term.pairs), unless the
 * next pilot round would be larger than the stage. The variance of a step
 * is a count of differing pairs (estimate.h), Poisson, so known to
 * 1 / sqrt(D) relative: 35 % at 8, its sigma to 18 %. With 8 the spread of
 * sigma / target narrows where few strata cross an edge; 16 gains little
 * more for far more rays (docs/tuning.md). */
#define PLAN_PAIRS 8.0

/* How fast a light's stage variance falls with its samples, Var ~ N^-alpha,
 * by sampler. Area emitters and uniform skies are sampled by maps that
 * keep strata compact, so that a visibility edge crosses ~k of k x k
 * strata: Var = O(k / k^4) = O(N^-1.5) (stratified sampling of a step in
 * two dimensions, N^-1-1/d: Owen, "Monte Carlo theory, methods and
 * examples", 2013, ch. 10). An image sky's sampler (lights/environment_
 * sampler.h) turns u1 into a run of pixels along rows, u1's fraction
 * placing the direction within each pixel: a stratum is a comb of slivers
 * over many pixels that an edge crosses nearly all of, until strata are
 * narrower than a pixel in u1: measured, the variance falls as about
 * N^-1.2 (docs/tuning.md, with what 1 and 1.5 gave).
 *
 * Why by sampler and not measured point by point: the exponent can be
 * measured from one round (the variance of its 2 x 2 blocks of strata
 * against that of its strata, 2^(2 alpha - 2)), and was, over 20 seeds of
 * the test scenes. Where an edge decides the variance only the few strata
 * it crosses carry the measurement, and it scattered by 0.1-0.3 between
 * seeds however large the round; on image skies it was tight but followed
 * the scale of the pilot's strata (1.0-1.7 by round size), not the slope
 * out to the stage; a planner that used the measured exponent did worse
 * (docs/tuning.md). */
#define ALPHA_STEP 1.5
#define ALPHA_IMAGE 1.2

/* How a light's contribution is formed at a point: exact, E_0 less a
 * sampled hidden part, sampled plainly, or (an image or overcast sky whose
 * visible part the exact route found) L_ref Omega_p(R), plus an image's
 * sun summed exactly over that part, plus the sampled integral of
 * (L' - L_ref) cos over it, L' the sky without its sun (sky_region.h). */
enum { TERM_EXACT, TERM_HIDDEN, TERM_PLAIN, TERM_REGION };

typedef struct term {
    const cdl_scene_light *light;
    uint64_t stream;
    int mode;
    double exact;            /* E_0 (TERM_EXACT, TERM_HIDDEN) */
    double potential;        /* what the light gives with nothing in the way */
    cdl_estimate est;        /* of H (hidden) or of E (plain) */
    double carrying;         /* samples whose direction carries light at all */
    double jump;             /* the largest unoccluded sample value: the step at a visibility edge */
    uint64_t drawn;          /* samples drawn so far (pilots and stage), the next sample's index */
    int side;                /* strata per side of the latest round */
    double pairs;            /* differing pairs of the latest round in effect: (sum d^2)^2 / sum d^4 */
    cdl_environment_sampler *sky; /* image environments: sampled for this normal (NULL: the emitter's sampler) */
    cdl_sky_region *region;  /* TERM_REGION: the visible sky */
    double L_ref;            /* TERM_REGION: the control variate's luminance */
    double L_spread;         /* TERM_REGION: greatest less least luminance over the region */
} term;

/* A sample of the light: an image sky by luminance x each pixel's projected
 * solid angle on n's hemisphere (lights/environment/environment_sampler.h; its mean of
 * L cos / pdf with nothing in the way is the exact sum, as the emitter's
 * sampler's is), anything else by the emitter's own sampler. u1 is the
 * coordinate whose strata are staggered row by row (sample_round): it
 * goes to the sampler's coordinate that the edges common in buildings run
 * along. A uniform sky's cosine-weighted hemisphere takes its azimuth from
 * its second coordinate, and a vertical edge (a window's jamb, a wall's
 * corner) is a line of constant azimuth: it gets (u2, u1), a swap that
 * keeps the measure. An area emitter's rectangle sampler (lights/
 * spherical_rectangle.h) takes the position along the rectangle's u side
 * from its first: an occluder's edge parallel to the v side is a line of
 * constant u1. */
static int term_sample(term *t, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *ls)
{
    if (!t->sky && cdl_environment_sampler_applies(t->light->emitter))
        cdl_environment_sampler_create(t->light->emitter, n, &t->sky, NULL); /* NULL on failure: the emitter's */
    if (t->sky) return cdl_environment_sampler_sample(t->sky, u1, u2, ls);
    if (t->light->is_environment) return cdl_emitter_sample(t->light->emitter, p, n, u2, u1, ls);
    return cdl_emitter_sample(t->light->emitter, p, n, u1, u2, ls);
}

/* One sample in [u1_lo, u1_hi) x [u2_lo, u2_hi), index `index` of the
 * term's stream, up to its shadow ray: its value f for t->est before
 * visibility (0 where it carries nothing), *unoccluded what it would carry
 * with nothing in the way, and 1 when its shadow ray is in *ray (to trace
 * with the round's others), 0 when f is final (nothing to trace: a region
 * sample, a sample that carries nothing, or one seen for certain). */
static int stratum_draw(const cdl_direct_context *ctx, term *t, const double lo[2], const double hi[2],
                        uint64_t index, cdl_vec3 p, cdl_vec3 n, double *f, double *unoccluded, cdl_ray_segment *ray,
                        cdl_direct_sample_stats *stats)
{
    cdl_rng_key key = {ctx->seed, t->stream};
    double u[2];
    cdl_rng_uniform2(key, index, u);
    *f = *unoccluded = 0.0;
    if (t->mode == TERM_REGION) {
        /* (L - L_ref) cos / pdf; what a feature the samples missed could
         * change a sample by, (L_hi - L_lo) cos / pdf, stands as the jump. */
        cdl_vec3 w;
        double weight;
        if (!cdl_sky_region_sample(t->region, lo[0] + u[0] * (hi[0] - lo[0]), lo[1] + u[1] * (hi[1] - lo[1]), &w,
                                   &weight))
            return 0;
        *unoccluded = t->L_spread * weight;
        *f = (cdl_sky_region_luminance(t->region, w) - t->L_ref) * weight;
        return 0;
    }
    cdl_light_sample ls;
    if (!term_sample(t, p, n, lo[0] + u[0] * (hi[0] - lo[0]), lo[1] + u[1] * (hi[1] - lo[1]), &ls) ||
        !(ls.pdf > 0.0))
        return 0;
    double c = cdl_vec3_dot(n, ls.to_light);
    if (!(c > 0.0)) return 0;
    double value = ls.L.cd_m2 * c / ls.pdf;
    *unoccluded = value;
    *f = t->mode == TERM_HIDDEN ? 0.0 : value; /* seen for certain (V = 1) unless its ray says otherwise */
    return cdl_direct_shadow_segment(ctx, p, n, ls.to_light, ls.distance, cdl_scene_light_own_piece(t->light), ray,
                                     stats);
}

/* A round's strata are drawn ROUND_BATCH at a time: their samples, then
 * their shadow rays together (as Embree packets: from one point towards
 * one light, the most coherent rays there are), then each stratum's pair
 * in order, so that the round's sums are those of drawing and tracing
 * sample by sample, to the bit. */
#define ROUND_BATCH 64

typedef struct round_batch {
    double f[2 * ROUND_BATCH], unoccluded[2 * ROUND_BATCH];
    cdl_ray_segment rays[2 * ROUND_BATCH];
    uint16_t ray_of[2 * ROUND_BATCH]; /* the sample whose ray each is */
    unsigned char blocked[2 * ROUND_BATCH];
    double V[2 * ROUND_BATCH];
} round_batch;

/* The fractional part of j times the golden ratio: offsets that stay
 * evenly spread for every run of rows (Weyl's equidistribution theorem;
 * of all irrationals the golden ratio, whose continued fraction is all
 * ones, leaves the most even gaps: the three-distance theorem, Sos 1958). */
static double golden_offset(int64_t j)
{
    const double phi = 0.61803398874989484820; /* (sqrt 5 - 1) / 2 */
    double x = phi * (double)j;
    return x - floor(x);
}

/* One round of k x k strata, two samples each, added to t->est. Rows are
 * strata along u2; along u1 each row's boundaries are staggered by a
 * fraction s_j of a stratum (golden_offset: bricks), its first stratum
 * (1 + s_j) / k wide and its last (1 - s_j) / k, weighted by their widths
 * (cdl_round_add_weighted_pair). Why: a sampler maps edges common in
 * buildings onto lines u1 = c (term_sample). On an unstaggered grid such
 * a line crosses one column of strata, each cut at the same fraction
 * p = frac(k c), and the round's variance, proportional to 2 p (1 - p), is
 * a lottery in k and c: the pilot's (at one k) cannot predict the
 * stage's (at another). Staggered, the rows are cut at fractions spread
 * evenly over [0, 1), whatever k and c, and the variance is that of an
 * edge in general position. On the partition scene of test_direct_
 * calibration (the wall's hidden part ends at a line of constant u1)
 * sigma / target spread over 0.34-2.05 at "normal" and 0.22-2.35 at
 * "high" without the bricks, 0.65-1.28 and 0.76-1.22 with them.
 *
 * Also the round's differing pairs in effect, t->pairs = (sum w^2 d^2)^2
 * / sum w^4 d^4: D for a step (every differing pair alike), more where
 * many pairs differ a little. */
static void sample_round(const cdl_direct_context *ctx, term *t, int k, cdl_vec3 p, cdl_vec3 n,
                         cdl_direct_sample_stats *stats)
{
    uint64_t base = t->drawn;
    cdl_round round = {0.0, 0.0, 0.0, 0};
    double unoccluded = 0.0, d4 = 0.0;
    round_batch b;
    int64_t strata = (int64_t)k * k;
    for (int64_t first = 0; first < strata; first += ROUND_BATCH) {
        int64_t last = first + ROUND_BATCH < strata ? first + ROUND_BATCH : strata;
        size_t rays = 0;
        double lo[ROUND_BATCH][2], hi[ROUND_BATCH][2];
        for (int64_t s = first; s < last; ++s) {
            int64_t j = s / k, i = s % k, m = s - first;
            double shift = k > 1 ? golden_offset(j) : 0.0;
            lo[m][0] = i == 0 ? 0.0 : (i + shift) / k;
            lo[m][1] = (double)j / k;
            hi[m][0] = i == k - 1 ? 1.0 : (i + 1 + shift) / k;
            hi[m][1] = (double)(j + 1) / k;
            for (int r = 0; r < 2; ++r)
                if (stratum_draw(ctx, t, lo[m], hi[m], base + (uint64_t)(2 * s + r), p, n, &b.f[2 * m + r],
                                 &b.unoccluded[2 * m + r], &b.rays[rays], stats))
                    b.ray_of[rays++] = (uint16_t)(2 * m + r);
        }
        /* V: 1 seen, 0 hidden, between through glass */
        cdl_direct_transmit_many(ctx, b.rays, rays, b.blocked, b.V);
        for (size_t q = 0; q < rays; ++q) {
            size_t at = b.ray_of[q];
            double value = b.unoccluded[at];
            b.f[at] = t->mode == TERM_HIDDEN ? value * (1.0 - b.V[q]) : value * b.V[q];
        }
        for (int64_t s = first; s < last; ++s) {
            int64_t m = s - first;
            double w = (hi[m][0] - lo[m][0]) * k, *f = &b.f[2 * m];
            for (int r = 0; r < 2; ++r) {
                double u = b.unoccluded[2 * m + r];
                if (u > 0.0) {
                    t->carrying += 1.0;
                    unoccluded += w * u;
                    t->jump = fmax(t->jump, u);
                }
            }
            cdl_round_add_weighted_pair(&round, f[0], f[1], w);
            double wd2 = w * w * (f[0] - f[1]) * (f[0] - f[1]);
            d4 += wd2 * wd2;
        }
    }
    cdl_estimate_add_round(&t->est, &round);
    t->drawn += 2u * (uint64_t)k * (uint64_t)k;
    t->side = k;
    t->pairs = d4 > 0.0 ? round.sum_d2 * round.sum_d2 / d4 : 0.0;
    if (t->mode == TERM_PLAIN) {
        /* No closed form: the mean unoccluded sample stands for what the
         * light could give (pooled over rounds by sample count). */
        double n_before = t->est.samples - 2.0 * round.strata;
        t->potential = (t->potential * n_before + unoccluded) / t->est.samples;
    }
    stats->sampled_evaluations++;
}

static double term_value(const term *t)
{
    switch (t->mode) {
    case TERM_EXACT: return t->exact;
    case TERM_HIDDEN: return fmax(0.0, t->exact - cdl_estimate_mean(&t->est));
    case TERM_REGION: return fmax(0.0, t->exact + cdl_estimate_mean(&t->est));
    default: return cdl_estimate_mean(&t->est);
    }
}

static double term_variance(const term *t)
{
    if (t->mode == TERM_EXACT) return 0.0;
    /* The pairs' variance plus one phantom differing pair (estimate.h). */
    double v = cdl_estimate_bound_variance(&t->est, t->jump);
    /* Every sample is a direction the point sees: nothing is hidden. */
    if (t->mode == TERM_REGION) return v;
    /* Every sample hidden, or none (or, sampled plainly, none lit): the
     * samples could have missed the other kind. */
    int one_sided = t->mode == TERM_HIDDEN ? t->est.nonzero == 0 || (double)t->est.nonzero >= t->carrying
                                           : t->est.nonzero == 0;
    if (one_sided) {
        double unseen = cdl_estimate_unseen_variance(t->est.samples, t->potential);
        if (unseen > v) v = unseen;
    }
    return v;
}

/* Set up a light's term at p: exact when nothing can hide it, else a first
 * round of samples. */
static void term_start(const cdl_direct_context *ctx, term *t, cdl_light_strategy st, cdl_vec3 p, cdl_vec3 n,
                       cdl_direct_sample_stats *stats)
{
    cdl_illuminance exact;
    t->exact = t->potential = t->carrying = t->jump = 0.0;
    t->drawn = 0;
    t->side = 0;
    t->pairs = 0.0;
    t->est = (cdl_estimate){0.0, 0.0, 0.0, 0};
    t->sky = NULL;
    t->region = NULL;
    t->L_ref = t->L_spread = 0.0;
    if (!cdl_scene_light_applies(t->light, p)) {
        t->mode = TERM_EXACT; /* the other part of a near-field split lights p */
        return;
    }
    if (st != CDL_STRATEGY_SAMPLED || cdl_emitter_has_exact_illuminance(t->light->emitter)) {
        if (cdl_emitter_exact_illuminance(t->light->emitter, p, n, &exact, NULL) == CDL_OK) {
            t->exact = t->potential = exact.lx > 0.0 ? exact.lx : 0.0;
            t->mode = TERM_EXACT;
            if (!(exact.lx > 0.0)) return; /* behind the emitter or below the horizon */
            if (st == CDL_STRATEGY_EXTENDED_EXACT) {
                stats->exact_evaluations++;
                return;
            }
            /* In full view, or few planar occluders: exact (direct_exact_route.c). */
            double visible;
            int route = cdl_direct_exact_term(ctx, t->light, st, p, n, t->potential, &visible, &t->region, stats);
            if (route == 2) {
                double lo, hi;
                cdl_sky_region_luminance_bounds(t->region, &lo, &hi);
                t->mode = TERM_REGION;
                t->L_ref = cdl_sky_region_reference_luminance(t->region);
                t->L_spread = hi - lo;
                t->exact = cdl_sky_region_exact_part(t->region);
            } else if (route >= 0) {
                if (route == 1) t->exact = visible;
                stats->exact_evaluations++;
                return;
            } else {
                t->mode = TERM_HIDDEN;
            }
        } else {
            t->mode = TERM_PLAIN;
        }
    } else {
        t->mode = TERM_PLAIN;
    }
    int side = ctx->samples > 0 ? (int)ceil(sqrt(ctx->samples / 2.0)) : PILOT_SIDE;
    sample_round(ctx, t, side, p, n, stats);
}

/* Forget a term's latest round (its drawn samples stay drawn) before the
 * next: a pilot round only plans, and only the stage is reported. */
static void term_restart(term *t)
{
    t->est = (cdl_estimate){0.0, 0.0, 0.0, 0};
    t->carrying = t->jump = 0.0;
}

/* Most samples a light's stage may take after the rounds it has drawn. */
static double stage_room(const term *t)
{
    return fmax(2.0 * PILOT_SIDE * PILOT_SIDE, CDL_DIRECT_MAX_SAMPLES - (double)t->drawn);
}

/* Plan every sampled light's stage at p from its latest pilot round: the
 * point's variance target (t R)^2 shared out by cdl_estimate_allocate_
 * samples, each light's variance modelled from its own pilot and
 * convergence exponent. Lights whose plan reaches more than PLAN_REACH
 * times their pilot take a pilot round of twice the side first and the
 * point is planned again; then each light takes its stage, which replaces
 * its pilots. A light whose stage the cap of samples held below its plan
 * is counted in the route tally (the plan says so). */
static void plan_stage(const cdl_direct_context *ctx, term *terms, size_t count, double known, cdl_vec3 p,
                       cdl_vec3 n, cdl_direct_sample_stats *stats)
{
    enum { LOCAL = 16 };
    double local[5 * LOCAL];
    size_t cap = count <= LOCAL ? LOCAL : count;
    double *v = count <= LOCAL ? local : malloc(5 * cap * sizeof *v);
    if (!v) return; /* out of memory: the pilots stand, with their honest errors */
    double *pilot = v + cap, *alpha = v + 2 * cap, *want = v + 3 * cap, *room = v + 4 * cap;
    term *sampled_terms[LOCAL], **st = count <= LOCAL ? sampled_terms : malloc(count * sizeof *st);
    if (!st) {
        if (v != local) free(v);
        return;
    }
    int sampled = 0;
    for (size_t j = 0; j < count; ++j)
        if (terms[j].mode != TERM_EXACT) st[sampled++] = &terms[j];
    for (;;) {
        double E = known, potential = 0.0, V = 0.0;
        for (size_t j = 0; j < count; ++j) {
            E += term_value(&terms[j]);
            potential += terms[j].potential;
        }
        for (int j = 0; j < sampled; ++j) {
            v[j] = term_variance(st[j]);
            V += v[j];
            pilot[j] = st[j]->est.samples;
            alpha[j] = st[j]->sky && st[j]->mode != TERM_REGION ? ALPHA_IMAGE : ALPHA_STEP;
            room[j] = stage_room(st[j]);
        }
        /* The pilot's E may be well off (a point that sees the light through
         * a small opening, E = E_0 - H with H from 72 samples): planned on E
         * it would hold the stage to a target up to twice too loose. Planned
         * on E less one pilot sigma, the stage meets the target also then. */
        double R = fmax(E - sqrt(V), 1e-3 * potential);
        cdl_estimate_allocate_samples(v, pilot, alpha, want, sampled, ctx->target * ctx->target * R * R,
                                      2.0 * PILOT_SIDE * PILOT_SIDE, CDL_DIRECT_MAX_SAMPLES);
        /* A light planned beyond its pilot's reach takes a larger pilot,
         * unless that reach already passes the cap (the stage is then held
         * by the cap whatever a larger pilot would say). */
        int more = 0;
        for (int j = 0; j < sampled; ++j) {
            int next = 2 * st[j]->side;
            double reach = pilot[j] < PLAN_SMALL_PILOT ? PLAN_REACH_SMALL : PLAN_REACH;
            int far = want[j] > reach * pilot[j] && reach * pilot[j] < CDL_DIRECT_MAX_SAMPLES;
            int thin = st[j]->pairs < PLAN_PAIRS && want[j] >= 2.0 * next * next;
            if ((far || thin) && next <= PILOT_MAX_SIDE) {
                term_restart(st[j]);
                sample_round(ctx, st[j], next, p, n, stats);
                more = 1;
            }
        }
        if (!more) break;
    }
    for (int j = 0; j < sampled; ++j) {
        int side = cdl_estimate_side_for(want[j], PILOT_SIDE, 1 << 15);
        while (side > PILOT_SIDE && 2.0 * side * side > room[j]) side--;
        if (want[j] > room[j] && stats->routes) stats->routes[st[j]->light - ctx->lights].capped++;
        term_restart(st[j]);
        sample_round(ctx, st[j], side, p, n, stats);
    }
    if (st != sampled_terms) free(st);
    if (v != local) free(v);
}

void cdl_direct_extended_point(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                               const uint32_t *lights, size_t count, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                               double known, double *contribution, double *variance, cdl_direct_sample_stats *stats)
{
    term local[16];
    term *terms = count <= 16 ? local : malloc(count * sizeof *terms);
    if (!terms) {
        /* Out of memory for a point with many lights: one light at a time
         * (each to the point's whole target), never a wrong number. */
        double var_sum = 0.0;
        for (size_t j = 0; j < count; ++j) {
            double v = 0.0;
            cdl_direct_extended_point(ctx, strategies, &lights[j], 1, stream, p, n, known, &contribution[j], &v,
                                      stats);
            var_sum += v;
        }
        *variance = var_sum;
        return;
    }
    for (size_t j = 0; j < count; ++j) {
        terms[j].light = &ctx->lights[lights[j]];
        terms[j].stream = cdl_rng_stream_id(stream, (uint64_t)lights[j], 0x6c69676874ull /* "light" */);
        term_start(ctx, &terms[j], strategies[lights[j]], p, n, stats);
    }
    /* Plan from the pilots and take the stage, unless the scene fixed the
     * sample count (then the one round taken is what is reported). */
    if (ctx->samples <= 0) plan_stage(ctx, terms, count, known, p, n, stats);
    double var_sum = 0.0;
    for (size_t j = 0; j < count; ++j) {
        contribution[j] = term_value(&terms[j]);
        var_sum += term_variance(&terms[j]);
        cdl_environment_sampler_release(terms[j].sky);
        cdl_sky_region_release(terms[j].region);
    }
    *variance = var_sum;
    if (terms != local) free(terms);
}
