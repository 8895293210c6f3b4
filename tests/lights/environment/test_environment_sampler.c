/* The per-normal image environment sampler: its pdf integrates to 1, it
 * reports the pdf it samples with, its estimator's mean is the exact pixel
 * sum, and that estimator is nearly constant where the emitter's own
 * sampler (by L x solid angle) is not. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "lights/environment/environment_sampler.h"
#include "radiometry/constants.h"
#include "base/rng.h"

enum { W = 48, H = 25 };

/* A sky with a gradient, a dark band and a small bright sun. */
static void make_sky(float *img)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double v = 900.0 + 400.0 * cos(CDL_TWO_PI * i / W) + 120.0 * j;
            if (i >= 30 && i < 34) v = 0.0;
            if (i == 13 && j == 6) v = 1e5;
            img[j * W + i] = (float)v;
        }
}

static cdl_environment_sampler *make_sampler(const cdl_emitter *e, cdl_vec3 n)
{
    cdl_environment_sampler *s = NULL;
    cdl_error err;
    CHECK_OK(cdl_environment_sampler_create(e, n, &s, &err), &err);
    return s;
}

typedef struct stats {
    double mean, sd; /* of L cos / pdf per sample (zeros counted) */
    int mismatches;  /* samples whose pdf() disagrees */
} stats;

/* N = k x k stratified samples from the new sampler (use_emitter 0) or the
 * emitter's own (1). */
static stats estimate(const cdl_emitter *e, const cdl_environment_sampler *s, cdl_vec3 n, int k, int use_emitter)
{
    cdl_rng_key key = {7, use_emitter ? 2u : 1u};
    double sum = 0.0, sum2 = 0.0;
    stats r = {0.0, 0.0, 0};
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)(j * k + i), u);
            cdl_light_sample ls;
            double f = 0.0;
            int ok = use_emitter ? cdl_emitter_sample(e, cdl_vec3_make(0, 0, 0), n, (j + u[0]) / k, (i + u[1]) / k, &ls)
                                 : cdl_environment_sampler_sample(s, (j + u[0]) / k, (i + u[1]) / k, &ls);
            if (ok) {
                f = ls.L.cd_m2 * cdl_vec3_dot(n, ls.to_light) / ls.pdf;
                if (!use_emitter && fabs(cdl_environment_sampler_pdf(s, ls.to_light) - ls.pdf) > 1e-12 * ls.pdf)
                    r.mismatches++;
            }
            sum += f;
            sum2 += f * f;
        }
    double N = (double)k * k;
    r.mean = sum / N;
    r.sd = sqrt(fmax(0.0, sum2 / N - r.mean * r.mean));
    return r;
}

/* int over the sphere of pdf(w) dw, with K x K cells per pixel (uniform in
 * cos theta and phi, so each cell's solid angle is exact): the pdf is
 * constant on each pixel, so the rule is exact up to rounding (1e-12). */
static double pdf_integral(const cdl_environment_sampler *s, int K)
{
    double total = 0.0;
    for (int j = 0; j < H; ++j) {
        double ca = cos(CDL_PI * j / H), cb = cos(CDL_PI * (j + 1) / H), row = 0.0;
        for (int a = 0; a < K; ++a) {
            double mu = ca - (a + 0.5) * (ca - cb) / K, r = sqrt(fmax(0.0, 1.0 - mu * mu));
            for (int i = 0; i < W * K; ++i) {
                double phi = CDL_PI + CDL_TWO_PI * (i + 0.5) / (W * K);
                row += cdl_environment_sampler_pdf(s, cdl_vec3_make(r * cos(phi), r * sin(phi), mu));
            }
        }
        total += row * (ca - cb) / K * CDL_TWO_PI / (W * K);
    }
    return total;
}

static void test_pdf_and_mean(void)
{
    static float img[W * H];
    make_sky(img);
    cdl_vec3 normals[] = {{0, 0, 1}, {1, 0, 0}, {0.3, -0.5, 0.1}, {-0.2, 0.1, -0.9}, {0.6, 0.6, 0.5}};
    for (int upper = 0; upper <= 1; ++upper) {
        cdl_emitter *e = make_environment(0.0, img, W, H, 1.5, upper, cdl_vec3_make(0, 0, 1));
        for (size_t k = 0; k < sizeof normals / sizeof normals[0]; ++k) {
            cdl_vec3 n = cdl_vec3_normalize(normals[k]);
            cdl_environment_sampler *s = make_sampler(e, n);
            if (!s) continue;
            cdl_illuminance exact;
            CHECK_OK(cdl_emitter_exact_illuminance(e, cdl_vec3_make(0, 0, 0), n, &exact, NULL), &(cdl_error){0});
            /* 1e-13: both are the sum over the 1200 pixels of the same terms,
             * each rounded on its own route (a few ulp each, up to about
             * 1e-14 summed), far below any one lit pixel's share */
            CHECK_REL(cdl_environment_sampler_illuminance(s).lx, exact.lx, 1e-13);
            if (!(exact.lx > 0.0)) {
                cdl_environment_sampler_release(s);
                continue;
            }
            CHECK_REL(pdf_integral(s, 2), 1.0, 1e-12);
            /* 256^2 stratified samples: the mean within 4 standard errors of
             * the exact sum (the sd of the mean of N stratified samples is
             * at most sd / sqrt(N)); pdf() agrees with every sample. */
            stats r = estimate(e, s, n, 256, 0);
            double se = r.sd / 256.0;
            CHECK_MSG(fabs(r.mean - exact.lx) <= 4.0 * se + 1e-13 * exact.lx, "upper %d n %zu: %.12g vs %.12g (se %g)",
                      upper, k, r.mean, exact.lx, se);
            CHECK(r.mismatches == 0);
            /* What is left varies with cos across a pixel of 7.5 x 7.2
             * degrees, and pixels the horizon crosses give zeros; the
             * emitter's own sampler, blind to cos and to the horizon of n,
             * has a per-sample sd at least 4 times larger (measured 6.6 to
             * 17 times on these normals). */
            stats old = estimate(e, NULL, n, 256, 1);
            CHECK_MSG(old.sd > 4.0 * r.sd, "upper %d n %zu: sd %g, emitter's sampler %g", upper, k, r.sd, old.sd);
            cdl_environment_sampler_release(s);
        }
        cdl_emitter_release(e);
    }
}

/* A uniform map and an upward receiver with an even height: no pixel
 * straddles the horizon, every sample lands above it, and the estimator
 * varies only with cos within a pixel. */
static void test_uniform_nearly_constant(void)
{
    static float img[48 * 24];
    for (int k = 0; k < 48 * 24; ++k) img[k] = 300.0f;
    cdl_emitter *e = make_environment(0.0, img, 48, 24, 1.0, 0, cdl_vec3_make(0, 0, 1));
    cdl_vec3 n = {0, 0, 1};
    cdl_environment_sampler *s = make_sampler(e, n);
    if (s) {
        CHECK_REL(cdl_environment_sampler_illuminance(s).lx, CDL_PI * 300.0, 1e-13);
        int zeros = 0;
        double lo = INFINITY, hi = 0.0;
        for (int k = 0; k < 4096; ++k) {
            cdl_light_sample ls;
            if (!cdl_environment_sampler_sample(s, (k + 0.5) / 4096.0, fmod(k * 0.618034, 1.0), &ls)) {
                zeros++;
                continue;
            }
            double f = ls.L.cd_m2 * ls.to_light.z / ls.pdf;
            lo = fmin(lo, f);
            hi = fmax(hi, f);
        }
        CHECK(zeros == 0);
        /* Within a pixel cos varies by at most the pixel's height in angle
         * (7.5 degrees) relative to its mean: f within [0.5, 1.5] pi L at
         * the horizon row, far tighter elsewhere. */
        /* f / (pi L) = cos / (the pixel's mean cos): near 1 in most rows,
         * [0, 2) in the row along the horizon, where cos falls to 0. */
        CHECK(lo > 0.0 && hi < 2.0 * CDL_PI * 300.0);
        /* And the mean of 4096 stratified samples, within 4 standard
         * errors (sd / 64 bounds that of a stratified mean). */
        stats r = estimate(e, s, n, 64, 0);
        CHECK_MSG(fabs(r.mean - CDL_PI * 300.0) <= 4.0 * r.sd / 64.0, "%g vs %g (sd %g)", r.mean, CDL_PI * 300.0, r.sd);
        cdl_environment_sampler_release(s);
    }
    cdl_emitter_release(e);
}

static void test_errors(void)
{
    cdl_emitter *sky = make_environment(1000.0, NULL, 0, 0, 1.0, 1, cdl_vec3_make(0, 0, 1));
    cdl_environment_sampler *s = NULL;
    cdl_error err;
    CHECK(!cdl_environment_sampler_applies(sky));
    CHECK(cdl_environment_sampler_create(sky, cdl_vec3_make(0, 0, 1), &s, &err) == CDL_ERR_USAGE && s == NULL);
    CHECK_MSG(strstr(err.message, "image environment"), "%s", err.message);
    float img[4] = {1, 1, 1, 1};
    cdl_emitter *e = make_environment(0.0, img, 2, 2, 1.0, 0, cdl_vec3_make(0, 0, 1));
    CHECK(cdl_environment_sampler_applies(e));
    CHECK(cdl_environment_sampler_create(e, cdl_vec3_make(0, 0, 0), &s, &err) == CDL_ERR_INPUT && s == NULL);
    /* A dark image: E = 0 and no samples. */
    float dark[4] = {0, 0, 0, 0};
    cdl_emitter *d = make_environment(0.0, dark, 2, 2, 1.0, 0, cdl_vec3_make(0, 0, 1));
    s = make_sampler(d, cdl_vec3_make(0, 0, 1));
    if (s) {
        cdl_light_sample ls;
        CHECK(cdl_environment_sampler_illuminance(s).lx == 0.0);
        CHECK(!cdl_environment_sampler_sample(s, 0.3, 0.6, &ls));
        CHECK(cdl_environment_sampler_pdf(s, cdl_vec3_make(0, 0, 1)) == 0.0);
        cdl_environment_sampler_release(s);
    }
    cdl_emitter_release(d);
    cdl_emitter_release(e);
    cdl_emitter_release(sky);
}

int main(void)
{
    test_pdf_and_mean();
    test_uniform_nearly_constant();
    test_errors();
    return check_finish();
}
