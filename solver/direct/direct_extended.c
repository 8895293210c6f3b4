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
 * takes a pilot round that only plans: from the pilots' variances the
 * point's samples are shared among its lights (cdl_estimate_allocate_
 * samples) to meet the target with the fewest in all, at most
 * CDL_DIRECT_MAX_SAMPLES a light; then each light takes that many in one
 * stage, and only the stage is reported, whatever it shows. Stopping when
 * a light's own rounds look quiet would bias both the value and its error
 * (radiometry/estimate.h): a point that happened to miss the bright part
 * stops early with a small stated error. Should the pilot have judged
 * badly, the stated error is above the target and says so.
 *
 * A light whose samples were all hidden, or none, is not certain: what the
 * samples could have missed is the light's unhidden value times the
 * posterior spread of a fraction seen in none of N samples
 * (cdl_estimate_unseen_variance), and that is its variance at the least.
 */
#include "solver/direct/direct_internal.h"

#include <math.h>
#include <stdlib.h>

#include "lights/environment_sampler.h"
#include "radiometry/estimate.h"
#include "radiometry/rng.h"

/* Most samples per light and point when sampling to a target (an explicit
 * direct_samples may ask for more). 2^18 shadow rays take about 30 ms. */
#define CDL_DIRECT_MAX_SAMPLES 262144.0

/* Strata per side of a light's pilot round, and the least of a reported
 * stage: 6 x 6 strata, 72 samples. */
#define PILOT_SIDE 6

/* How fast a stage's variance falls with its samples when planned from the
 * pilot, Var ~ N^-alpha (cdl_estimate_allocate_samples). What is sampled
 * here is mostly a step (a light seen or hidden): of k x k strata only the
 * ~k along the edge vary, so Var = O(k / k^4) = O(N^-1.5), not the N^-1
 * of independent samples. Planned with alpha = 1, the black well at
 * "normal" was sampled to 0.23-0.40 of its target (every point at the cap
 * of samples); with 1.5 the points spread about the target. */
#define PLAN_ALPHA 1.5

/* How a light's contribution is formed at a point. */
enum { TERM_EXACT, TERM_HIDDEN, TERM_PLAIN };

typedef struct term {
    const cdl_scene_light *light;
    uint64_t stream;
    int mode;
    double exact;            /* E_0 (TERM_EXACT, TERM_HIDDEN) */
    double potential;        /* what the light gives with nothing in the way */
    cdl_estimate est;        /* of H (hidden) or of E (plain) */
    double carrying;         /* samples whose direction carries light at all */
    double jump;             /* the largest unoccluded sample value: the step at a visibility edge */
    uint64_t drawn;          /* samples drawn so far (pilot and stage), the next sample's index */
    cdl_environment_sampler *sky; /* image environments: sampled for this normal (NULL: the emitter's sampler) */
} term;

/* A sample of the light: an image sky by luminance x each pixel's projected
 * solid angle on n's hemisphere (lights/environment_sampler.h; its mean of
 * L cos / pdf with nothing in the way is the exact sum, as the emitter's
 * sampler's is), anything else by the emitter's own sampler. */
static int term_sample(term *t, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *ls)
{
    if (!t->sky && cdl_environment_sampler_applies(t->light->emitter))
        cdl_environment_sampler_create(t->light->emitter, n, &t->sky, NULL); /* NULL on failure: the emitter's */
    if (t->sky) return cdl_environment_sampler_sample(t->sky, u1, u2, ls);
    return cdl_emitter_sample(t->light->emitter, p, n, u1, u2, ls);
}

/* One round of k x k strata, two samples each, added to t->est. */
static void sample_round(const cdl_direct_context *ctx, term *t, int k, cdl_vec3 p, cdl_vec3 n,
                         cdl_direct_sample_stats *stats)
{
    cdl_rng_key key = {ctx->seed, t->stream};
    uint64_t base = t->drawn;
    cdl_round round = {0.0, 0.0, 0.0, 0};
    double unoccluded = 0.0;
    for (int64_t j = 0; j < k; ++j)
        for (int64_t i = 0; i < k; ++i) {
            double f[2];
            for (int s = 0; s < 2; ++s) {
                double u[2];
                cdl_rng_uniform2(key, base + (uint64_t)(2 * (j * k + i) + s), u);
                f[s] = 0.0;
                cdl_light_sample ls;
                if (!term_sample(t, p, n, (i + u[0]) / k, (j + u[1]) / k, &ls) ||
                    !(ls.pdf > 0.0))
                    continue;
                double c = cdl_vec3_dot(n, ls.to_light);
                if (!(c > 0.0)) continue;
                double value = ls.L.cd_m2 * c / ls.pdf;
                t->carrying += 1.0;
                unoccluded += value;
                t->jump = fmax(t->jump, value);
                int hidden = ctx->geometry ? cdl_direct_shadowed(ctx, p, n, ls.to_light, ls.distance, stats) : 0;
                if (t->mode == TERM_HIDDEN ? hidden : !hidden) f[s] = value;
            }
            cdl_round_add_pair(&round, f[0], f[1]);
        }
    cdl_estimate_add_round(&t->est, &round);
    t->drawn += 2u * (uint64_t)k * (uint64_t)k;
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
    default: return cdl_estimate_mean(&t->est);
    }
}

static double term_variance(const term *t)
{
    if (t->mode == TERM_EXACT) return 0.0;
    /* The pairs' variance plus one phantom differing pair (estimate.h). */
    double v = cdl_estimate_bound_variance(&t->est, t->jump);
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
    t->est = (cdl_estimate){0.0, 0.0, 0.0, 0};
    t->sky = NULL;
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
            int route = cdl_direct_exact_term(ctx, t->light, st, p, n, &visible, stats);
            if (route >= 0) {
                if (route == 1) t->exact = visible;
                stats->exact_evaluations++;
                return;
            }
            t->mode = TERM_HIDDEN;
        } else {
            t->mode = TERM_PLAIN;
        }
    } else {
        t->mode = TERM_PLAIN;
    }
    int side = ctx->samples > 0 ? (int)ceil(sqrt(ctx->samples / 2.0)) : PILOT_SIDE;
    sample_round(ctx, t, side, p, n, stats);
}

/* Forget a term's pilot (its drawn samples stay drawn) before its stage. */
static void term_restart(term *t)
{
    t->est = (cdl_estimate){0.0, 0.0, 0.0, 0};
    t->carrying = t->jump = 0.0;
}

/* The stage of every sampled light at p, planned from their pilots: the
 * point's variance target (t R)^2 with R from the pilots' values, shared
 * out by cdl_estimate_allocate_samples; each light's stage replaces its
 * pilot. */
static void plan_stage(const cdl_direct_context *ctx, term *terms, size_t count, double known, cdl_vec3 p,
                       cdl_vec3 n, cdl_direct_sample_stats *stats)
{
    double E = known, potential = 0.0;
    double local[32] = {0};
    double *v = count <= 16 ? local : malloc(2 * count * sizeof *v);
    if (!v) return; /* out of memory: the pilots stand, with their honest errors */
    double *want = v + (count <= 16 ? 16 : count);
    int sampled = 0;
    double V = 0.0;
    for (size_t j = 0; j < count; ++j) {
        E += term_value(&terms[j]);
        potential += terms[j].potential;
        v[sampled] = term_variance(&terms[j]);
        V += v[sampled];
        if (terms[j].mode != TERM_EXACT) sampled++;
    }
    /* The pilot's E may be well off (a point that sees the light through a
     * small opening, E = E_0 - H with H from 72 samples): planned on E it
     * would hold the stage to a target up to twice too loose. Planned on
     * E less one pilot sigma, the stage meets the target also then. */
    double R = fmax(E - sqrt(V), 1e-3 * potential);
    double pilot = 2.0 * PILOT_SIDE * PILOT_SIDE;
    cdl_estimate_allocate_samples(v, want, sampled, pilot, PLAN_ALPHA, ctx->target * ctx->target * R * R, pilot,
                                  CDL_DIRECT_MAX_SAMPLES - pilot);
    sampled = 0;
    for (size_t j = 0; j < count; ++j) {
        if (terms[j].mode == TERM_EXACT) continue;
        int side = cdl_estimate_side_for(want[sampled++], PILOT_SIDE, 1 << 15);
        while (side > PILOT_SIDE && 2.0 * side * side > CDL_DIRECT_MAX_SAMPLES - pilot) side--;
        term_restart(&terms[j]);
        sample_round(ctx, &terms[j], side, p, n, stats);
    }
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
    }
    *variance = var_sum;
    if (terms != local) free(terms);
}
