/* direct.c - direct illuminance: exact where possible, sampled where hidden. */
#include "solver/direct/direct.h"
#include "solver/direct/direct_internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "base/rng.h"
#include "radiometry/sampling.h"

const char *cdl_light_strategy_describe(cdl_light_strategy s, const cdl_scene_light *light)
{
    /* A luminaire spread over its opening: its own words (its exact value
     * is Lambert's or the opening's cubature, never an image sky's sum). */
    int opening = light && cdl_emitter_get_kind(light->emitter) == CDL_EMITTER_GONIOMETRIC_OPENING;
    if (opening && s == CDL_STRATEGY_EXTENDED_EXACT)
        return "exact (Lambert's closed form for a Lambertian table, else an adaptive cubature of the opening to "
               "1/50 of the target error), nothing can hide it";
    if (opening && s == CDL_STRATEGY_EXTENDED_TESTED)
        return "exact where fully visible (Lambert's closed form or the opening's cubature), the visible part of "
               "the opening past few planar occluders integrated the same way, else sampled where partly hidden "
               "(the exact value less the hidden part): surfaces may hide part of this opening";
    if (opening && s == CDL_STRATEGY_SAMPLED)
        return "sampled with shadow rays: no exact value for this luminous solid's light while surfaces may hide it";
    /* The sun as a disk: its own words (direct_exact_route.c). */
    if (light && light->is_sun_disk && s == CDL_STRATEGY_EXTENDED_EXACT)
        return "exact (E_n cos theta, the disk clipped by the receiving plane where it crosses it), nothing can "
               "hide it";
    if (light && light->is_sun_disk && s == CDL_STRATEGY_EXTENDED_TESTED)
        return "exact where the sun's disk is in full view, its visible part past few planar occluders (the disk as "
               "a 240-gon: the penumbra to 1e-4), else sampled within the disk with shadow rays: surfaces may hide "
               "the sun";
    return cdl_light_strategy_name(s);
}

const char *cdl_light_strategy_name(cdl_light_strategy s)
{
    switch (s) {
    /* What was modelled, and after the colon why (summary.json's plan). */
    case CDL_STRATEGY_DELTA_EXACT: return "exact, no shadow rays: no surface can come between this light and the grid";
    case CDL_STRATEGY_DELTA_SHADOWED:
        return "exact, one shadow ray per point: surfaces may come between this light and the grid";
    case CDL_STRATEGY_EXTENDED_EXACT:
        return "closed form (an image sky: the exact sum over its pixels), nothing can hide it";
    case CDL_STRATEGY_EXTENDED_TESTED:
        /* (no "luminance" here: tests scan summary.json for "nan") */
        return "closed form where fully visible, exact visible polygon past few planar occluders, else sampled where "
               "partly hidden (the closed form less the hidden part; an image sky drawn by L x each pixel's "
               "projected solid angle): surfaces may hide part of this emitter";
    case CDL_STRATEGY_SAMPLED:
        return "sampled with shadow rays: no exact test of this emitter's visibility (a non-planar mesh) while "
               "surfaces may hide it";
    }
    return "unknown";
}

void cdl_direct_plan_grid(const cdl_direct_context *ctx, const cdl_vec3 *points, size_t count,
                          cdl_light_strategy *strategies)
{
    cdl_bounds3 grid = cdl_bounds3_empty();
    for (size_t i = 0; i < count; ++i) cdl_bounds3_grow(&grid, points[i]);

    for (size_t l = 0; l < ctx->light_count; ++l) {
        const cdl_scene_light *light = &ctx->lights[l];
        int delta = cdl_emitter_is_delta(light->emitter);
        /* Can any surface lie between this light and any point of the grid?
         * Conservative test: the box around the grid and the light. Unbounded
         * lights (directional, environment) can be occluded by anything. */
        int may_occlude;
        if (!ctx->occluders || count == 0) {
            may_occlude = 0;
        } else if (!light->bounded) {
            may_occlude = cdl_occluder_index_primitive_count(ctx->occluders) > 0;
        } else {
            cdl_bounds3 both = grid;
            cdl_bounds3_merge(&both, light->bounds);
            cdl_vec3 lo = both.lo, hi = both.hi;
            double tol = fmin(cdl_direct_region_tolerance(ctx, lo), cdl_direct_region_tolerance(ctx, hi));
            /* The test shrinks the box by tol so that surfaces which only
             * touch it (the floor under a grid) do not count. Along an axis
             * where the box is thinner than that (a probe straight below its
             * luminaire, a grid level with it) shrinking would empty the box
             * and hide every surface in between: widen such an axis to 3 tol
             * either side of its middle first. */
            double *axis_lo[3] = {&lo.x, &lo.y, &lo.z}, *axis_hi[3] = {&hi.x, &hi.y, &hi.z};
            for (int a = 0; a < 3; ++a)
                if (*axis_hi[a] - *axis_lo[a] < 4.0 * tol) {
                    double mid = 0.5 * (*axis_lo[a] + *axis_hi[a]);
                    *axis_lo[a] = fmin(*axis_lo[a], mid - 3.0 * tol);
                    *axis_hi[a] = fmax(*axis_hi[a], mid + 3.0 * tol);
                }
            cdl_convex_region box;
            cdl_region_box(&box, lo, hi);
            may_occlude = cdl_occluder_index_intersects(ctx->occluders, &box, tol, cdl_scene_light_own_piece(light));
        }
        if (delta)
            strategies[l] = may_occlude ? CDL_STRATEGY_DELTA_SHADOWED : CDL_STRATEGY_DELTA_EXACT;
        else if (!light->has_closed_form)
            strategies[l] = CDL_STRATEGY_SAMPLED;
        else if (!may_occlude)
            strategies[l] = CDL_STRATEGY_EXTENDED_EXACT;
        else if (light->outline_count == 0 && !light->outline_is_sphere && !light->is_environment &&
                 !light->is_sun_disk)
            strategies[l] = CDL_STRATEGY_SAMPLED;
        else
            strategies[l] = CDL_STRATEGY_EXTENDED_TESTED;
    }
}

size_t cdl_direct_select_lights(const cdl_direct_context *ctx, cdl_vec3 center, double radius, uint32_t *active)
{
    size_t count = 0;
    for (size_t l = 0; l < ctx->light_count; ++l) {
        const cdl_scene_light *light = &ctx->lights[l];
        /* The near-field part of a luminaire lights only its ball. */
        if (light->near_part > 0 && cdl_vec3_distance(center, light->near_center) > radius + light->near_radius) continue;
        if (light->has_cone && light->cone_angle < 0.5 * CDL_PI) {
            /* The ball, seen from the light under the half-angle b with
             * sin b = r / d, meets the cone (half-angle a) iff the angle t
             * from the axis to the ball's centre is below a + b, i.e. iff
             * cos t > cos(a + b) = cos a cos b - sin a sin b; a and b are
             * both below pi / 2, so a + b < pi and the cosine decides. */
            cdl_vec3 v = cdl_vec3_sub(center, light->cone_position);
            double d = sqrt(cdl_vec3_dot(v, v));
            if (d > radius) {
                double sin_b = radius / d, cos_b = sqrt(1.0 - sin_b * sin_b);
                double cos_ab = light->cone_cos * cos_b - light->cone_sin * sin_b;
                if (cdl_vec3_dot(v, light->cone_axis) <= cos_ab * d) continue;
            }
        }
        active[count++] = (uint32_t)l;
    }
    return count;
}

/* Exact unshadowed illuminance from a delta light, and the direction and
 * distance its shadow ray needs; 0 when the light does not reach p. */
static double delta_unshadowed(const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *d)
{
    if (!cdl_scene_light_applies(light, p)) return 0.0;
    if (light->has_cone) {
        /* Outside the emission cone: no light, no lookup. For cones up to a
         * hemisphere (cos >= 0) the test needs no square root:
         * along <= cos |v|  <=>  along <= 0 or along^2 <= cos^2 |v|^2. */
        cdl_vec3 v = cdl_vec3_sub(p, light->cone_position);
        double along = cdl_vec3_dot(v, light->cone_axis);
        if (light->cone_cos >= 0.0) {
            if (along <= 0.0 || along * along <= light->cone_cos2 * cdl_vec3_dot(v, v)) return 0.0;
        } else if (along <= light->cone_cos * sqrt(cdl_vec3_dot(v, v))) {
            return 0.0;
        }
    }
    if (!cdl_emitter_eval_delta(light->emitter, p, n, d) || !(d->E.lx > 0.0)) return 0.0;
    return d->E.lx;
}

/* Exact illuminance from a delta light, 0 if it is shadowed. */
static double delta_contribution(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy st,
                                 cdl_vec3 p, cdl_vec3 n, cdl_direct_sample_stats *stats)
{
    cdl_delta_light d;
    double E = delta_unshadowed(light, p, n, &d);
    if (E > 0.0 && st == CDL_STRATEGY_DELTA_SHADOWED)
        E *= cdl_direct_transmission(ctx, p, n, d.to_light, d.distance, cdl_scene_light_own_piece(light), stats);
    return E;
}

static int is_delta(cdl_light_strategy st)
{
    return st == CDL_STRATEGY_DELTA_EXACT || st == CDL_STRATEGY_DELTA_SHADOWED;
}

void cdl_direct_illuminance(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                            const uint32_t *active, size_t active_count, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                            double *E_out, double *var_out, cdl_direct_sample_stats *stats)
{
    size_t count = active ? active_count : ctx->light_count;
    /* Per light: its contribution, and for the extended ones their index,
     * their place among the lights and their value, in one block. */
    size_t each = 2 * sizeof(double) + sizeof(size_t) + sizeof(uint32_t);
    char *block = malloc((count ? count : 1) * each);
    if (!block) {
        *E_out = NAN; /* refused by the solve's finite check, never a silent number */
        *var_out = NAN;
        return;
    }
    double *contribution = (double *)block, *values = contribution + count;
    size_t *slot = (size_t *)(values + count);
    uint32_t *extended = (uint32_t *)(slot + count);
    /* The same steps, in the same order, as cdl_direct_illuminance_chunk. */
    double known = 0.0, var = 0.0;
    size_t n_ext = 0;
    for (size_t a = 0; a < count; ++a) {
        size_t l = active ? active[a] : a;
        contribution[a] = 0.0;
        if (is_delta(strategies[l])) {
            contribution[a] = delta_contribution(ctx, &ctx->lights[l], strategies[l], p, n, stats);
        } else {
            slot[n_ext] = a;
            extended[n_ext++] = (uint32_t)l;
        }
    }
    for (size_t a = 0; a < count; ++a) known += contribution[a];
    if (n_ext) cdl_direct_extended_point(ctx, strategies, extended, n_ext, stream, p, n, known, values, &var, stats);
    for (size_t j = 0; j < n_ext; ++j) contribution[slot[j]] = values[j];
    double E = 0.0;
    for (size_t a = 0; a < count; ++a) E += contribution[a];
    *E_out = E;
    *var_out = var;
    free(block);
}

/* One sample of an extended light at p: f = L cos / pdf towards the point
 * drawn with the random numbers of index l, and V, the transmission along
 * its shadow ray (0 or 1 but through glass); f = 0 when the sample carries
 * nothing. */
static double sample_extended(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_rng_key key, size_t l,
                              cdl_vec3 p, cdl_vec3 n, double *visible, cdl_direct_sample_stats *stats)
{
    double u[2];
    cdl_rng_uniform2(key, (uint64_t)l, u);
    cdl_light_sample s;
    *visible = 1.0;
    if (!cdl_emitter_sample(light->emitter, p, n, u[0], u[1], &s) || !(s.pdf > 0.0)) return 0.0;
    double c = cdl_vec3_dot(n, s.to_light);
    if (!(c > 0.0)) return 0.0;
    *visible = cdl_direct_transmission(ctx, p, n, s.to_light, s.distance, cdl_scene_light_own_piece(light), stats);
    return s.L.cd_m2 * c / s.pdf;
}

/* One sample's estimate of an extended light at p (light number l): with a
 * closed form E_0, E_0 - f (1 - V) (exact where the sample is not hidden);
 * without, f V. *free_E += what it gives unhidden. 0 without a sample when
 * the closed form says no light arrives. */
static double extended_term(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_rng_key key, size_t l,
                            cdl_vec3 p, cdl_vec3 n, double *free_E, cdl_direct_sample_stats *stats)
{
    cdl_illuminance exact;
    /* (a cubature per path vertex would cost more than the sample) */
    int closed = !light->costly_exact && cdl_emitter_exact_illuminance(light->emitter, p, n, &exact, NULL) == CDL_OK;
    if (closed && !(exact.lx > 0.0)) return 0.0;
    double visible, f = sample_extended(ctx, light, key, l, p, n, &visible, stats);
    *free_E += closed ? exact.lx : f;
    return closed ? exact.lx - f * (1.0 - visible) : f * visible;
}

/* A sky at p seen through the scene's panes (sky_portals.h): one direction
 * from the sky's own sampler (random numbers of index l) and one towards a
 * point of the panes (index `pane_index`), each counting
 * L cos T / (p_sky + p_pane), the balance heuristic of multiple importance
 * sampling. *free_E += the same without T. */
static double sky_through_portals(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_rng_key key,
                                  size_t l, uint64_t pane_index, cdl_vec3 p, cdl_vec3 n, double *free_E,
                                  cdl_direct_sample_stats *stats)
{
    double E = 0.0, u[2];
    for (int k = 0; k < 2; ++k) {
        cdl_vec3 w;
        double p_sky = 0.0, p_pane = 0.0;
        cdl_luminance L = cdl_nits(0.0);
        if (k == 0) {
            cdl_rng_uniform2(key, (uint64_t)l, u);
            cdl_light_sample s;
            if (!cdl_emitter_sample(light->emitter, p, n, u[0], u[1], &s) || !(s.pdf > 0.0)) continue;
            w = s.to_light;
            L = s.L;
            p_sky = s.pdf;
            p_pane = cdl_sky_portals_pdf(ctx->portals, p, w);
        } else {
            cdl_rng_uniform2(key, pane_index, u);
            if (!cdl_sky_portals_sample(ctx->portals, p, u[0], u[1], &w, &p_pane)) continue;
            L = cdl_emitter_radiance(light->emitter, p, n, w, &p_sky);
        }
        double c = cdl_vec3_dot(n, w);
        if (!(c > 0.0) || !(L.cd_m2 > 0.0)) continue;
        double f = L.cd_m2 * c / (p_sky + p_pane);
        *free_E += f;
        E += f * cdl_direct_transmission(ctx, p, n, w, INFINITY, cdl_scene_light_own_piece(light), stats);
    }
    return E;
}

/* A light that is neither delta nor drawn: a sky (through the panes, where
 * there are some) or an extended light taken apart (extended_term). */
static double apart_term(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_rng_key key, size_t l,
                         cdl_vec3 p, cdl_vec3 n, double *free_E, cdl_direct_sample_stats *stats)
{
    if (light->is_environment && ctx->portals && ctx->portals->count > 0)
        return sky_through_portals(ctx, light, key, l, (uint64_t)(ctx->light_count + 1 + l), p, n, free_E, stats);
    return extended_term(ctx, light, key, l, p, n, free_E, stats);
}

double cdl_direct_estimate_point(const cdl_direct_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n,
                                 double *unoccluded, cdl_direct_sample_stats *stats)
{
    double E = 0.0, free_E = 0.0;
    for (size_t l = 0; l < ctx->light_count; ++l) {
        const cdl_scene_light *light = &ctx->lights[l];
        if (light->sealed_by) continue;
        if (cdl_emitter_is_delta(light->emitter)) {
            cdl_delta_light d;
            double e = delta_unshadowed(light, p, n, &d);
            if (!(e > 0.0)) continue;
            free_E += e;
            E += e * cdl_direct_transmission(ctx, p, n, d.to_light, d.distance, cdl_scene_light_own_piece(light), stats);
            continue;
        }
        if (!cdl_scene_light_applies(light, p)) continue;
        E += apart_term(ctx, light, key, l, p, n, &free_E, stats);
    }
    if (unoccluded) *unoccluded = free_E;
    return E;
}

/* ---- one light drawn at a path vertex ------------------------------------------------------ */

/* Lights a vertex's one-light estimate keeps on the stack; more take the heap. */
#define ONE_LIGHT_STACK 64

/* The share of the draw spread evenly over the lights whose weight is only
 * a far-field guess, whatever the guesses: a light the guess says nothing
 * of (the point model seen from beside a luminous opening) is still
 * drawn, so the estimate stays unbiased wherever any light can reach. */
#define ONE_LIGHT_GUESS_SHARE 0.1

/* What a light is at a vertex for the one-light estimate, and what it
 * gives when drawn:
 *   delta    X = e V   (e its exact unshadowed value: its weight)
 *   guessed  X = f V   (an extended light; weight: the far-field guess)
 * with f = L cos / pdf of one sample and V its shadow ray's transmission.
 * A point every light's shadow ray misses reads exactly 0. */
enum { TERM_NONE = 0, TERM_DELTA, TERM_GUESSED };

/* The far-field guess of an extended light's unoccluded illuminance at p: its
 * intensity towards p from its centre, I cos / d^2 (the inverse-square
 * cosine law), 0 behind p's plane. Only a weight: the estimate stays
 * unbiased whatever it is. I comes from the light's coarse map over the
 * sphere (intensity_map.h: no trigonometry, where the exact lookup of a
 * photometric table took a fifth of the example office's solve). */
static double far_field_guess(const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n)
{
    /* every bounded extended light has its map (scene_lights.c); a light
     * made without one is guessed from its exact intensity */
    int mapped = light->guess_map != NULL;
    cdl_vec3 c = mapped ? light->guess_origin : cdl_bounds3_centre(light->bounds);
    cdl_vec3 d = cdl_vec3_sub(c, p);
    double d2 = cdl_vec3_dot(d, d), along = cdl_vec3_dot(n, d); /* along = |d| cos */
    if (!(d2 > 0.0) || !(along > 0.0)) return 0.0;
    /* the direction from the light towards p: -d (the map takes any length) */
    double I = mapped ? cdl_intensity_map_lookup(light->guess_map, cdl_vec3_neg(d)).cd
                      : cdl_emitter_intensity(light->emitter, cdl_vec3_neg(d)).cd;
    if (!(I > 0.0) || !isfinite(I)) return 0.0;
    /* I cos / d^2 = I along / |d|^3: one square root and one division, and
     * only for the lights that shine towards p */
    double inv_d2 = 1.0 / d2;
    return I * along * sqrt(inv_d2) * inv_d2;
}

/* A light with a closed form is taken apart from the draw where it looms
 * large: its bounds' half-diagonal more than LOOM_RATIO of its distance
 * from p. There its far-field guess says little and its closed form much
 * (a furnace's walls, a luminous ceiling overhead: drawn, the closed
 * furnace's stated errors grew 1.5 times); further away the guess is good
 * and the draw cheaper (the example office's panel: 22 % less time a
 * path). */
#define LOOM_RATIO 0.5

static int looms(const cdl_scene_light *light, cdl_vec3 p)
{
    cdl_vec3 c = cdl_bounds3_centre(light->bounds), h = cdl_vec3_sub(light->bounds.hi, c);
    double d2 = cdl_vec3_length_squared(cdl_vec3_sub(c, p));
    return cdl_vec3_length_squared(h) > LOOM_RATIO * LOOM_RATIO * d2;
}

/* The lights of a vertex with their weights: W of the weighted ones, G
 * lights guessed. */
typedef struct light_draw {
    double W;
    size_t guessed;
} light_draw;

/* The probability of drawing light l: in proportion to the weights, but
 * for ONE_LIGHT_GUESS_SHARE spread evenly over the guessed lights (all of
 * it when no weight is above 0). */
static double draw_probability(const light_draw *d, double weight, int kind)
{
    double even = d->guessed == 0 ? 0.0 : d->W > 0.0 ? ONE_LIGHT_GUESS_SHARE : 1.0;
    double q = d->W > 0.0 ? (1.0 - even) * weight / d->W : 0.0;
    return kind == TERM_GUESSED ? q + even / (double)d->guessed : q;
}

double cdl_direct_estimate_one_light(const cdl_direct_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n,
                                     int closed_apart, double *unoccluded, cdl_direct_sample_stats *stats)
{
    size_t count = ctx->light_count;
    double stack[2 * ONE_LIGHT_STACK];
    unsigned char kinds_stack[ONE_LIGHT_STACK];
    double *buf = count <= ONE_LIGHT_STACK ? stack : malloc(2 * count * sizeof *buf);
    unsigned char *kind = count <= ONE_LIGHT_STACK ? kinds_stack : malloc(count);
    if (!buf || !kind) {
        if (buf != stack) free(buf);
        if (kind != kinds_stack) free(kind);
        return cdl_direct_estimate_point(ctx, key, p, n, unoccluded, stats);
    }
    double *weight = buf, *apart = buf + count;
    double E = 0.0, free_E = 0.0;
    light_draw draw = {0.0, 0};
    for (size_t l = 0; l < count; ++l) {
        const cdl_scene_light *light = &ctx->lights[l];
        kind[l] = TERM_NONE;
        weight[l] = apart[l] = 0.0;
        if (light->sealed_by) continue;
        if (cdl_emitter_is_delta(light->emitter)) {
            cdl_delta_light d;
            double e = delta_unshadowed(light, p, n, &d);
            if (!(e > 0.0)) continue;
            kind[l] = TERM_DELTA;
            weight[l] = e;
            free_E += e;
        } else if (!cdl_scene_light_applies(light, p)) {
            continue;
        } else if (!light->bounded || (!light->costly_exact && light->has_closed_form &&
                                       (closed_apart || looms(light, p)))) {
            /* skies and the sun, and the lights with a cheap closed form
             * that loom large (or all of them, with closed_apart): a sample
             * each, as cdl_direct_estimate_point takes (E_0 - f (1 - V)
             * where the closed form exists) */
            apart[l] = apart_term(ctx, light, key, l, p, n, &free_E, stats);
            continue;
        } else {
            /* no closed form here, even where there is one: the guess and a
             * sample cost less, and the estimate is no noisier (with the
             * closed form's known part a hidden sample took -f (1 - V) / q,
             * large where the guess drew the light seldom: on the example
             * office's gathers 22 % more time per path and 1.6 times the
             * cost to a given error) */
            kind[l] = TERM_GUESSED;
            weight[l] = far_field_guess(light, p, n);
            draw.guessed++;
        }
        draw.W += weight[l];
    }
    /* The lights taken apart, in light order. */
    for (size_t l = 0; l < count; ++l) E += apart[l];
    if (draw.W > 0.0 || draw.guessed > 0) {
        /* Light k drawn with probability q_k counts X_k / q_k (the
         * one-sample estimate of a sum over lights: Shirley, Wang and
         * Zimmerman, "Monte Carlo techniques for direct lighting
         * calculations", ACM TOG 15, 1996). */
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)count, u);
        double target = u[0], q = 0.0;
        size_t k = SIZE_MAX, last = SIZE_MAX;
        for (size_t l = 0; l < count && k == SIZE_MAX; ++l) {
            if (kind[l] == TERM_NONE) continue;
            double ql = draw_probability(&draw, weight[l], kind[l]);
            if (!(ql > 0.0)) continue;
            last = l;
            q = ql;
            if (target < ql) k = l;
            else target -= ql;
        }
        if (k == SIZE_MAX) k = last; /* rounding left u past the last share: q is last's */
        const cdl_scene_light *light = &ctx->lights[k];
        double X;
        if (kind[k] == TERM_DELTA) {
            cdl_delta_light d;
            double e = delta_unshadowed(light, p, n, &d);
            X = e * cdl_direct_transmission(ctx, p, n, d.to_light, d.distance, cdl_scene_light_own_piece(light), stats);
        } else {
            double visible, f = sample_extended(ctx, light, key, k, p, n, &visible, stats);
            X = f * visible;
            free_E += f / q;
        }
        E += X / q;
    }
    if (buf != stack) free(buf);
    if (kind != kinds_stack) free(kind);
    if (unoccluded) *unoccluded = free_E;
    return E;
}

void cdl_direct_scratch_release(cdl_direct_scratch *scratch)
{
    free(scratch->contribution);
    free(scratch->rays);
    free(scratch->ray_slot);
    free(scratch->ray_blocked);
    free(scratch->ray_fraction);
    free(scratch->ext_light);
    free(scratch->ext_slot);
    free(scratch->ext_value);
    memset(scratch, 0, sizeof *scratch);
}

static cdl_status scratch_reserve(cdl_direct_scratch *s, size_t slots, size_t lights, cdl_error *err)
{
    if (lights > s->light_capacity) {
        uint32_t *el = realloc(s->ext_light, lights * sizeof *el);
        if (el) s->ext_light = el;
        size_t *es = realloc(s->ext_slot, lights * sizeof *es);
        if (es) s->ext_slot = es;
        double *ev = realloc(s->ext_value, lights * sizeof *ev);
        if (ev) s->ext_value = ev;
        if (!el || !es || !ev) return cdl_error_out_of_memory(err);
        s->light_capacity = lights;
    }
    if (slots <= s->capacity) return CDL_OK;
    double *c = realloc(s->contribution, slots * sizeof *c);
    if (c) s->contribution = c;
    cdl_ray_record *r = realloc(s->rays, slots * sizeof *r);
    if (r) s->rays = r;
    uint32_t *k = realloc(s->ray_slot, slots * sizeof *k);
    if (k) s->ray_slot = k;
    unsigned char *b = realloc(s->ray_blocked, slots * sizeof *b);
    if (b) s->ray_blocked = b;
    double *f = realloc(s->ray_fraction, slots * sizeof *f);
    if (f) s->ray_fraction = f;
    if (!c || !r || !k || !b || !f) return cdl_error_out_of_memory(err);
    s->capacity = slots;
    return CDL_OK;
}

cdl_status cdl_direct_illuminance_chunk(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                                        const uint32_t *active, size_t active_count, const uint64_t *streams,
                                        const cdl_vec3 *points, const cdl_vec3 *normals, size_t count, double *E,
                                        double *variance, cdl_direct_sample_stats *stats,
                                        cdl_direct_scratch *scratch, cdl_error *err)
{
    size_t lights = active ? active_count : ctx->light_count;
    if (count > CDL_DIRECT_CHUNK_MAX)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "direct chunk of %zu points (at most %d)", count,
                             CDL_DIRECT_CHUNK_MAX);
    cdl_status st = scratch_reserve(scratch, count * lights + 1, lights + 1, err);
    if (st != CDL_OK) return st;
    size_t pending = 0;
    /* 1. Every light's contribution to every point, light by light (one
     *    dispatch per light); delta lights' shadow rays wait. */
    cdl_delta_light delta[CDL_DIRECT_CHUNK_MAX];
    for (size_t i = 0; i < count; ++i) variance[i] = 0.0;
    for (size_t a = 0; a < lights; ++a) {
        size_t l = active ? active[a] : a;
        cdl_light_strategy strategy = strategies[l];
        for (size_t i = 0; i < count; ++i) scratch->contribution[i * lights + a] = 0.0;
        if (is_delta(strategy)) {
            cdl_emitter_eval_delta_many(ctx->lights[l].emitter, points, normals, count, delta);
            for (size_t i = 0; i < count; ++i) {
                double e = delta[i].E.lx > 0.0 && cdl_scene_light_applies(&ctx->lights[l], points[i]) ? delta[i].E.lx
                                                                                                       : 0.0;
                scratch->contribution[i * lights + a] = e;
                if (e > 0.0 && strategy == CDL_STRATEGY_DELTA_SHADOWED &&
                    cdl_direct_shadow_segment(ctx, points[i], normals[i], delta[i].to_light, delta[i].distance,
                                              cdl_scene_light_own_piece(&ctx->lights[l]), &scratch->rays[pending],
                                              stats))
                    scratch->ray_slot[pending++] = (uint32_t)(i * lights + a);
            }
        }
    }
    /* 2. The shadow rays, light by light from the chunk's neighbouring
     *    points: as Embree packets (the same answers as one by one), through
     *    glass one after another, each with the panes' transmittance. */
    cdl_direct_transmit_many(ctx, scratch->rays, pending, scratch->ray_blocked, scratch->ray_fraction);
    for (size_t k = 0; k < pending; ++k) scratch->contribution[scratch->ray_slot[k]] *= scratch->ray_fraction[k];
    /* 3. Per point, the extended lights, sampled together to the point's
     *    target given its exact terms; then the sum in light order, as
     *    cdl_direct_illuminance forms it (adding the zeros of dark lights
     *    changes no bit). */
    size_t n_ext = 0;
    for (size_t a = 0; a < lights; ++a) {
        size_t l = active ? active[a] : a;
        if (!is_delta(strategies[l])) {
            scratch->ext_slot[n_ext] = a;
            scratch->ext_light[n_ext++] = (uint32_t)l;
        }
    }
    for (size_t i = 0; i < count; ++i) {
        double *c = &scratch->contribution[i * lights];
        if (n_ext) {
            double known = 0.0;
            for (size_t a = 0; a < lights; ++a) known += c[a];
            cdl_direct_extended_point(ctx, strategies, scratch->ext_light, n_ext, streams[i], points[i], normals[i],
                                      known, scratch->ext_value, &variance[i], stats);
            for (size_t j = 0; j < n_ext; ++j) c[scratch->ext_slot[j]] = scratch->ext_value[j];
        }
        double sum = 0.0;
        for (size_t a = 0; a < lights; ++a) sum += c[a];
        E[i] = sum;
    }
    return CDL_OK;
}

double cdl_direct_ambient_occlusion(const cdl_direct_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                                    double *stderr_out, cdl_direct_sample_stats *stats)
{
    if (stderr_out) *stderr_out = 0.0;
    if (!ctx->geometry) return 1.0; /* nothing can hide the sky: certain */
    int64_t k = (int64_t)ceil(sqrt((double)(ctx->ao_samples > 0 ? ctx->ao_samples : 1)));
    cdl_rng_key key = {ctx->seed, cdl_rng_stream_id(stream, 0x616f /* "ao" */, 0)};
    cdl_frame frame = cdl_frame_from_normal(n);
    int64_t open = 0;
    for (int64_t j = 0; j < k; ++j)
        for (int64_t i = 0; i < k; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)(j * k + i), u);
            cdl_vec3 w = cdl_frame_to_world(&frame, cdl_sample_cosine_hemisphere_stratified((int)j, (int)i, (int)k, (int)k, u[0], u[1]));
            if (!cdl_direct_shadowed(ctx, p, n, w, INFINITY, UINT32_MAX, stats)) open++;
        }
    double N = (double)(k * k);
    /* The stated error: the spread of the open fraction given `open` of N
     * rays left, under a uniform prior, Beta(open + 1, N - open + 1), whose
     * variance a b / ((a + b)^2 (a + b + 1)) is never 0 (all rays open, or
     * none, could still have missed a sliver) and is the binomial
     * p (1 - p) / N in between; stratifying the rays only lowers the true
     * error below it. */
    if (stderr_out) {
        double a = (double)open + 1.0, b = N - (double)open + 1.0;
        *stderr_out = sqrt(a * b / ((a + b) * (a + b) * (a + b + 1.0)));
    }
    return (double)open / N;
}
