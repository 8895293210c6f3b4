/* direct_extended.c - area emitters and skies: closed form where nothing
 * hides them, the hidden part sampled where something may. */
#include "solver/direct/direct_internal.h"

#include <math.h>

#include "radiometry/rng.h"

/* Stratified Monte-Carlo over the light: the mean of f = L cos / pdf over
 * visible samples (or, with `hidden_only`, of f over hidden samples) and the
 * variance of that mean; returns the number of samples. */
static double sample_light(const cdl_direct_context *ctx, const cdl_scene_light *light, uint64_t stream, cdl_vec3 p,
                           cdl_vec3 n, int hidden_only, double *mean, double *variance, cdl_direct_sample_stats *stats)
{
    /* 64-bit counts: k x k overflows an int from 2^31 samples on. */
    int64_t k = (int64_t)ceil(sqrt((double)(ctx->samples > 0 ? ctx->samples : 1)));
    double count = (double)(k * k);
    cdl_rng_key key = {ctx->seed, stream};
    double sum = 0.0, sum2 = 0.0;
    for (int64_t j = 0; j < k; ++j)
        for (int64_t i = 0; i < k; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)(j * k + i), u);
            cdl_light_sample s;
            double f = 0.0;
            if (cdl_emitter_sample(light->emitter, p, n, (i + u[0]) / k, (j + u[1]) / k, &s) && s.pdf > 0.0) {
                double c = cdl_vec3_dot(n, s.to_light);
                if (c > 0.0) {
                    double contribution = s.L.cd_m2 * c / s.pdf;
                    int occluded = ctx->geometry ? cdl_direct_shadowed(ctx, p, n, s.to_light, s.distance, stats) : 0;
                    if (hidden_only ? occluded : !occluded) f = contribution;
                }
            }
            sum += f;
            sum2 += f * f;
        }
    double m = sum / count;
    double var = count > 1 ? fmax(0.0, (sum2 - count * m * m) / (count - 1)) / count : 0.0;
    *mean = m;
    *variance = var;
    return count;
}

/* Illuminance from an area emitter or environment: closed form where nothing
 * hides it, closed form minus the sampled hidden part where something does,
 * plain sampling where there is no closed form. Adds to *E and *var. */
void cdl_direct_extended_contribution(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy st,
                                  uint64_t stream, cdl_vec3 p, cdl_vec3 n, double *E, double *var,
                                  cdl_direct_sample_stats *stats)
{
    cdl_illuminance exact;
    if (st != CDL_STRATEGY_SAMPLED && cdl_emitter_exact_illuminance(light->emitter, p, n, &exact, NULL) == CDL_OK) {
        if (!(exact.lx > 0.0)) return; /* behind the emitter or below the horizon */
        if (st == CDL_STRATEGY_EXTENDED_EXACT || cdl_direct_light_fully_visible(ctx, light, p, n)) {
            *E += exact.lx;
            stats->exact_evaluations++;
            return;
        }
        /* E = E_exact - E_hidden: a control variate that is exact when nothing
         * is hidden and whose variance comes only from the hidden part. */
        double hidden, v;
        double c = sample_light(ctx, light, stream, p, n, 1, &hidden, &v, stats);
        if (hidden == 0.0) {
            /* No sample was hidden, so the sample variance is 0, yet a surface
             * lies in the way and may hide less than the samples resolve. The
             * error reported is the posterior standard deviation of a hidden
             * fraction h seen in none of c samples (uniform prior:
             * h ~ Beta(1, c + 1), variance (c + 1) / ((c + 2)^2
             * (c + 3))), times the unhidden illuminance. */
            v = exact.lx * exact.lx * (c + 1.0) / ((c + 2.0) * (c + 2.0) * (c + 3.0));
        }
        *E += fmax(0.0, exact.lx - hidden);
        *var += v;
        stats->sampled_evaluations++;
        return;
    }
    double m, v;
    sample_light(ctx, light, stream, p, n, 0, &m, &v, stats);
    *E += m;
    *var += v;
    stats->sampled_evaluations++;
}
