/* emitter_checks.h - numerical references shared by the emitter tests.
 *
 * Include after check.h. Everything is static: each test program gets its
 * own copy. Two independent ways to reach a number an emitter states in
 * closed form:
 *  - quadrature over the sphere of directions (midpoint rule in cos(theta)
 *    and phi, which is a product rule exact for constants and of order h^2
 *    for functions with kinks), in a frame tilted away from the world axes
 *    so that nothing lines up with the emitters' own symmetries by accident;
 *  - Monte-Carlo estimates with the emitter's own importance sampling,
 *    returning the mean and its standard error, and checking on the way that
 *    cdl_emitter_radiance reports the same luminance and pdf as each sample.
 */
#ifndef CANDELA_TESTS_LIGHTS_EMITTER_CHECKS_H
#define CANDELA_TESTS_LIGHTS_EMITTER_CHECKS_H

#include <math.h>
#include <stdint.h>

#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "base/rng.h"

typedef double (*direction_fn)(void *ctx, cdl_vec3 w);

/* An environment emitter from its parameters; a failed creation is a
 * failed check (and NULL). */
static inline cdl_emitter *create_environment(const cdl_environment_params *p)
{
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_environment(p, &e, &err), &err);
    return e;
}

/* An environment emitter: uniform (img NULL, luminance L) or a W x H image. */
static inline cdl_emitter *make_environment(double L, const float *img, int w, int h, double scale, int upper,
                                            cdl_vec3 up)
{
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    p.luminance = cdl_nits(L);
    p.image = img;
    p.width = w;
    p.height = h;
    p.scale = scale;
    p.upper_hemisphere_only = upper;
    p.up = up;
    return create_environment(&p);
}

/* Configuration factors from a plane element (Howell, "A Catalog of
 * Radiation Heat Transfer Configuration Factors", 3rd ed.), in long double
 * (64-bit significand on x86-64): the perpendicular one subtracts nearly
 * equal terms for distant rectangles (terms ~1e-3, result ~1e-10), which
 * costs ~7 of double's 16 digits but leaves long double's 19 enough.
 *  - B-2, parallel rectangle a x b at height c over a corner:
 *      F = 1/(2pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))],
 *      X = a/c, Y = b/c;
 *  - B-3, perpendicular rectangle of width a along the line the planes
 *    share and height c, element at distance b on the normal through its corner:
 *      F = 1/(2pi) [atan(1/Y) - Y/sqrt(X^2+Y^2) atan(1/sqrt(X^2+Y^2))],  X = c/a, Y = b/a.
 * (B-3's variable assignment was confirmed by brute-force quadrature.) */
static inline double howell_parallel_corner(double a, double b, double c)
{
    long double X = (long double)a / c, Y = (long double)b / c, sx = sqrtl(1 + X * X), sy = sqrtl(1 + Y * Y);
    return (double)((X / sx * atanl(Y / sx) + Y / sy * atanl(X / sy)) / (2.0L * CDL_PI));
}

static inline double howell_perpendicular_corner(double a, double b, double c)
{
    long double X = (long double)c / a, Y = (long double)b / a, s = sqrtl(X * X + Y * Y);
    return (double)((atanl(1.0L / Y) - Y / s * atanl(1.0L / s)) / (2.0L * CDL_PI));
}

/* A fixed frame tilted from the world axes (no special alignment). */
static inline cdl_frame tilted_frame(void)
{
    return cdl_frame_from_normal(cdl_vec3_normalize(cdl_vec3_make(0.3141, -0.2718, 0.9100)));
}

/* int f(w) dw over the directions with cos(theta) >= mu_lo about fr's axis:
 * n_theta x n_phi midpoint cells uniform in cos(theta) and phi, each of the
 * same solid angle. */
static inline double cap_quadrature(direction_fn f, void *ctx, const cdl_frame *fr, double mu_lo, int n_theta,
                                    int n_phi)
{
    double dmu = (1.0 - mu_lo) / n_theta, sum = 0.0;
    for (int j = 0; j < n_theta; ++j) {
        double mu = 1.0 - (j + 0.5) * dmu, s = sqrt(fmax(0.0, 1.0 - mu * mu));
        double row = 0.0;
        for (int k = 0; k < n_phi; ++k) {
            double phi = CDL_TWO_PI * (k + 0.5) / n_phi;
            row += f(ctx, cdl_frame_to_world(fr, cdl_vec3_make(s * cos(phi), s * sin(phi), mu)));
        }
        sum += row;
    }
    return sum * dmu * CDL_TWO_PI / n_phi;
}

/* Over the whole sphere, about the tilted frame. */
static inline double sphere_quadrature(direction_fn f, void *ctx, int n_theta)
{
    cdl_frame fr = tilted_frame();
    return cap_quadrature(f, ctx, &fr, -1.0, n_theta, 2 * n_theta);
}

/* Over the hemisphere about unit n. */
static inline double hemisphere_quadrature(direction_fn f, void *ctx, cdl_vec3 n, int n_theta)
{
    cdl_frame fr = cdl_frame_from_normal(n);
    return cap_quadrature(f, ctx, &fr, 0.0, n_theta, 4 * n_theta);
}

/* Intensity of an emitter as a direction function (for flux quadratures). */
static inline double intensity_of(void *ctx, cdl_vec3 w)
{
    return cdl_emitter_intensity((const cdl_emitter *)ctx, w).cd;
}

/* Receiver for radiance quadratures: L(p, w) max(0, n.w). */
typedef struct receiver_ctx {
    const cdl_emitter *emitter;
    cdl_vec3 p, n;
} receiver_ctx;

static inline double radiance_cosine(void *ctx, cdl_vec3 w)
{
    const receiver_ctx *r = ctx;
    double c = cdl_vec3_dot(r->n, w);
    if (!(c > 0.0)) return 0.0;
    return cdl_emitter_radiance(r->emitter, r->p, r->n, w, NULL).cd_m2 * c;
}

static inline double radiance_pdf(void *ctx, cdl_vec3 w)
{
    const receiver_ctx *r = ctx;
    double pdf = 0.0;
    cdl_emitter_radiance(r->emitter, r->p, r->n, w, &pdf);
    return pdf;
}

/* Phi of a delta emitter by Monte Carlo: points uniform on a sphere of
 * radius r about c, E from eval_delta with inward normals; every ray from
 * the light crosses the sphere once, so int E dA = Phi and
 * Phi ~ mean(E) 4 pi r^2. Returns the estimate and its standard error. */
static inline void delta_flux_on_sphere(const cdl_emitter *e, cdl_vec3 c, double r, int N, uint64_t seed, double *mean,
                                        double *se)
{
    cdl_rng_key key = {seed, 17};
    double m = 0.0, m2 = 0.0;
    for (int i = 0; i < N; ++i) {
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)i, u);
        double z = 1 - 2 * u[0], s = sqrt(fmax(0.0, 1 - z * z)), ph = CDL_TWO_PI * u[1];
        cdl_vec3 w = {s * cos(ph), s * sin(ph), z};
        cdl_delta_light dl;
        cdl_emitter_eval_delta(e, cdl_vec3_madd(c, r, w), cdl_vec3_neg(w), &dl);
        double v = dl.E.lx * CDL_FOUR_PI * r * r, delta = v - m;
        m += delta / (i + 1);
        m2 += delta * (v - m);
    }
    *mean = m;
    *se = sqrt(m2 / (N - 1) / N);
}

typedef struct mc_result {
    double mean, stderr_;   /* estimate of E (lx) and its standard error */
    int pdf_mismatches;     /* samples where radiance() disagreed with sample() */
    int bad_samples;        /* non-finite or non-positive pdf, or a non-unit direction */
} mc_result;

/* E = mean of L cos / pdf over k x k jittered strata (the sample variance of
 * stratified samples overestimates the estimator's variance, so the
 * standard error is conservative). With check_radiance, every sample is
 * looked up again through cdl_emitter_radiance: luminance and pdf must agree
 * to 1e-9 (they are the same formulas evaluated from a recomputed hit). */
static inline mc_result mc_illuminance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, int k, uint64_t seed,
                                       int check_radiance)
{
    mc_result r = {0.0, 0.0, 0, 0};
    cdl_rng_key key = {seed, 99};
    /* Welford's running mean and squared deviations: no cancellation when
     * the variance is tiny compared with the mean. */
    double mean = 0.0, m2 = 0.0;
    int count = 0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)(j * k + i), u);
            cdl_light_sample s;
            double f = 0.0;
            if (cdl_emitter_sample(e, p, n, (i + u[0]) / k, (j + u[1]) / k, &s)) {
                if (!(s.pdf > 0.0) || !isfinite(s.pdf) || fabs(cdl_vec3_length(s.to_light) - 1.0) > 1e-12 ||
                    !(s.distance > 0.0))
                    r.bad_samples++;
                double c = cdl_vec3_dot(n, s.to_light);
                if (c > 0.0) f = s.L.cd_m2 * c / s.pdf;
                if (check_radiance) {
                    double pdf = 0.0;
                    cdl_luminance L = cdl_emitter_radiance(e, p, n, s.to_light, &pdf);
                    if (fabs(L.cd_m2 - s.L.cd_m2) > 1e-9 * s.L.cd_m2 || fabs(pdf - s.pdf) > 1e-9 * s.pdf)
                        r.pdf_mismatches++;
                }
            }
            ++count;
            double delta = f - mean;
            mean += delta / count;
            m2 += delta * (f - mean);
        }
    r.mean = mean;
    r.stderr_ = sqrt(m2 / (count - 1) / count);
    return r;
}

#endif
