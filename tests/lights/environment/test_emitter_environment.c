/* Environment emitters: the uniform sky's exact illuminance (pi L, pi L / 2
 * on a vertical plane under an upper-hemisphere sky, pi L (1 + cos beta) / 2
 * in general), the CIE overcast sky's (7 pi L_z / 9 on the horizontal, its
 * lune integral on tilted planes), the lat-long image mapping of
 * DESIGN.md, its closed-form "flux" three ways and its luminance-importance
 * sampling. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"

static cdl_emitter *make_uniform(double L, int upper, cdl_vec3 up)
{
    return make_environment(L, NULL, 0, 0, 1.0, upper, up);
}

static cdl_emitter *make_image(const float *img, int w, int h, double scale, int upper, cdl_vec3 up)
{
    return make_environment(0.0, img, w, h, scale, upper, up);
}

static double exact_E(const cdl_emitter *e, cdl_vec3 n)
{
    cdl_illuminance E;
    cdl_error err;
    CHECK_OK(cdl_emitter_exact_illuminance(e, cdl_vec3_make(1, 2, 3), n, &E, &err), &err);
    return E.lx;
}

static void test_uniform_sky(void)
{
    double L = 5000.0;
    cdl_vec3 z = {0, 0, 1};
    cdl_emitter *full = make_uniform(L, 0, z), *sky = make_uniform(L, 1, z);
    /* Full sphere: pi L on every plane. */
    cdl_vec3 ns[] = {{0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {0.3, -0.5, 0.1}};
    for (int k = 0; k < 4; ++k) CHECK_REL(exact_E(full, cdl_vec3_normalize(ns[k])), CDL_PI * L, 1e-15);
    /* Upper hemisphere: horizontal pi L, vertical pi L / 2, facing down 0. */
    CHECK_REL(exact_E(sky, z), CDL_PI * L, 1e-15);
    CHECK_REL(exact_E(sky, cdl_vec3_make(0, 1, 0)), CDL_PI * L / 2, 1e-15);
    CHECK_ABS(exact_E(sky, cdl_vec3_make(0, 0, -1)), 0.0, 1e-12 * L);
    /* General tilt against a quadrature of the radiance over the receiver's
     * hemisphere. L jumps to 0 at the horizon, so cells cut by it cost the
     * midpoint rule O(h): up to ~1e-4 with 800 rows; tolerance 3e-4. */
    double betas[] = {0.3, 1.0, 2.0, 2.8};
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 n = {sin(betas[k]), 0, cos(betas[k])};
        double E = exact_E(sky, n);
        CHECK_REL(E, CDL_PI * L * (1 + cos(betas[k])) / 2, 1e-14);
        receiver_ctx rc = {sky, cdl_vec3_make(0, 0, 0), n};
        CHECK_REL(hemisphere_quadrature(radiance_cosine, &rc, n, 800), E, 3e-4);
        /* Sampling (cos-weighted about n): 5 standard errors. */
        mc_result r = mc_illuminance(sky, cdl_vec3_make(0, 0, 0), n, 128, 77, 1);
        CHECK_MSG(fabs(r.mean - E) <= 5 * r.stderr_ + 1e-12 * E, "beta %g: %g vs %g (se %g)", betas[k], r.mean, E, r.stderr_);
        CHECK(r.pdf_mismatches == 0 && r.bad_samples == 0);
    }
    /* Full sky, cos-weighted sampling: every sample is exactly pi L. */
    mc_result r = mc_illuminance(full, cdl_vec3_make(0, 0, 0), cdl_vec3_normalize(ns[3]), 16, 3, 1);
    CHECK_REL(r.mean, CDL_PI * L, 1e-13);
    CHECK(r.stderr_ < 1e-10 * L);
    /* "Flux": on a 1 m^2 disk facing up, pi L, three ways. */
    CHECK_REL(cdl_emitter_flux(sky).lm, CDL_PI * L, 1e-15);
    CHECK_REL(cdl_emitter_flux(full).lm, CDL_PI * L, 1e-15);
    receiver_ctx rc = {sky, cdl_vec3_make(0, 0, 0), z};
    CHECK_REL(hemisphere_quadrature(radiance_cosine, &rc, z, 400), CDL_PI * L, 1e-12);
    r = mc_illuminance(sky, cdl_vec3_make(0, 0, 0), z, 16, 4, 1);
    CHECK_REL(r.mean, CDL_PI * L, 1e-13);
    /* A tilted sky: up 30 degrees from z; a horizontal plane gets pi L (1 + cos 30)/2. */
    cdl_emitter *tilted = make_uniform(L, 1, cdl_vec3_make(sin(CDL_PI / 6), 0, cos(CDL_PI / 6)));
    CHECK_REL(exact_E(tilted, z), CDL_PI * L * (1 + cos(CDL_PI / 6)) / 2, 1e-14);
    CHECK(!cdl_emitter_is_delta(sky) && cdl_emitter_has_exact_illuminance(sky));
    CHECK(cdl_emitter_get_kind(sky) == CDL_EMITTER_ENVIRONMENT);
    cdl_emitter_release(full);
    cdl_emitter_release(sky);
    cdl_emitter_release(tilted);
}

static cdl_emitter *make_overcast(double L_z, cdl_vec3 up)
{
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    p.luminance = cdl_nits(L_z);
    p.sky = CDL_SKY_CIE_OVERCAST;
    p.up = up;
    return create_environment(&p);
}

/* The CIE overcast sky, L(theta) = L_z (1 + 2 cos theta) / 3 above the
 * horizon (Moon and Spencer 1942): its luminance at the zenith, 60 degrees
 * and the horizon; 7 pi L_z / 9 on the horizontal (int (1 + 2 cos) cos
 * over the hemisphere = pi + 4 pi / 3, over 3) as exact illuminance and
 * "flux"; on tilted planes the closed form against a quadrature of the
 * luminance over the receiver's hemisphere (the kink at the horizon costs
 * the midpoint rule O(h), as for the uniform sky: 3e-4) and against its
 * own cosine-weighted sampling (5 standard errors), whose samples'
 * luminance and pdf cdl_emitter_radiance repeats. */
static void test_overcast_sky(void)
{
    double L_z = 9000.0;
    cdl_vec3 z = {0, 0, 1};
    cdl_emitter *sky = make_overcast(L_z, z);
    double pdf;
    CHECK_REL(cdl_emitter_radiance(sky, z, z, z, &pdf).cd_m2, L_z, 1e-15);
    cdl_vec3 w60 = {sin(CDL_PI / 3), 0, cos(CDL_PI / 3)};
    CHECK_REL(cdl_emitter_radiance(sky, z, z, w60, &pdf).cd_m2, 2.0 * L_z / 3.0, 1e-15);
    CHECK_REL(cdl_emitter_radiance(sky, z, z, cdl_vec3_make(1, 0, 1e-9), &pdf).cd_m2, L_z / 3.0, 1e-8);
    CHECK(cdl_emitter_radiance(sky, z, z, cdl_vec3_make(1, 0, -1e-9), &pdf).cd_m2 == 0.0);
    CHECK_REL(exact_E(sky, z), 7.0 * CDL_PI * L_z / 9.0, 1e-15);
    CHECK_REL(cdl_emitter_flux(sky).lm, 7.0 * CDL_PI * L_z / 9.0, 1e-15);
    receiver_ctx up_rc = {sky, cdl_vec3_make(0, 0, 0), z};
    CHECK_REL(hemisphere_quadrature(radiance_cosine, &up_rc, z, 400), 7.0 * CDL_PI * L_z / 9.0, 1e-6);
    CHECK_ABS(exact_E(sky, cdl_vec3_make(0, 0, -1)), 0.0, 1e-12 * L_z);
    double betas[] = {0.3, 1.0, CDL_PI / 2, 2.0, 2.8};
    for (int k = 0; k < 5; ++k) {
        cdl_vec3 n = {sin(betas[k]), 0, cos(betas[k])};
        double E = exact_E(sky, n);
        receiver_ctx rc = {sky, cdl_vec3_make(0, 0, 0), n};
        CHECK_REL(hemisphere_quadrature(radiance_cosine, &rc, n, 800), E, 3e-4);
        mc_result r = mc_illuminance(sky, cdl_vec3_make(0, 0, 0), n, 128, 78, 1);
        CHECK_MSG(fabs(r.mean - E) <= 5 * r.stderr_ + 1e-12 * E, "beta %g: %g vs %g (se %g)", betas[k], r.mean, E,
                  r.stderr_);
        CHECK(r.pdf_mismatches == 0 && r.bad_samples == 0);
    }
    /* A vertical plane by hand: beta = pi / 2 gives (L_z / 3)(pi / 2 + 4 / 3). */
    CHECK_REL(exact_E(sky, cdl_vec3_make(0, 1, 0)), L_z / 3.0 * (CDL_PI / 2.0 + 4.0 / 3.0), 1e-14);
    cdl_emitter_release(sky);
}

/* int f(w) dw with cells nested in the image's pixels: each pixel row's
 * cos(theta) range and each column's phi range split into K x K cells
 * uniform in (cos theta, phi). For functions constant per pixel times
 * cos(theta) about up, the midpoint rule is then exact (linear in cos theta
 * on every cell). Rows clipped at the horizon when upper_only. */
static double pixel_quadrature(direction_fn f, void *ctx, int W, int H, int K, int upper_only, cdl_vec3 up)
{
    cdl_frame fr = cdl_frame_from_normal(up);
    /* The emitter's azimuth reference for up = +z is world +x; this test
     * only uses up = +z here, where cdl_frame_from_normal gives s = +x. */
    double sum = 0.0;
    for (int j = 0; j < H; ++j) {
        double ct = cos(CDL_PI * j / H), cb = cos(CDL_PI * (j + 1) / H);
        if (upper_only) {
            if (ct <= 1e-15) break;
            cb = fmax(cb, 0.0);
        }
        for (int a = 0; a < K; ++a) {
            double mu = ct - (a + 0.5) * (ct - cb) / K, s = sqrt(fmax(0.0, 1 - mu * mu));
            for (int i = 0; i < W * K; ++i) {
                double phi = CDL_PI + CDL_TWO_PI * (i + 0.5) / (W * K);
                sum += f(ctx, cdl_frame_to_world(&fr, cdl_vec3_make(s * cos(phi), s * sin(phi), mu))) * (ct - cb) / K *
                       CDL_TWO_PI / (W * K);
            }
        }
    }
    return sum;
}

static void test_image_mapping(void)
{
    /* 8 x 4 image, every pixel its own value 1 + i + 10 j; scale 2. */
    float img[32];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) img[j * 8 + i] = (float)(1 + i + 10 * j);
    cdl_emitter *e = make_image(img, 8, 4, 2.0, 0, cdl_vec3_make(0, 0, 1));
    struct { double phi, theta_deg; int i, j; } probes[] = {
        {0.1, 73.0, 4, 1},                 /* just past +x (centre column u = 0.5) */
        {-0.1, 73.0, 3, 1},                /* just before +x */
        {CDL_PI - 0.1, 73.0, 7, 1},        /* just before -x: right edge */
        {-CDL_PI + 0.1, 73.0, 0, 1},       /* just past -x: left edge */
        {CDL_PI / 2 + 0.1, 20.0, 6, 0},    /* +y: u = 0.75 */
        {-CDL_PI / 2 + 0.1, 100.0, 2, 2},  /* -y: u = 0.25 */
        {1.0, 170.0, 5, 3},                /* near the nadir: bottom row */
    };
    for (size_t k = 0; k < sizeof probes / sizeof probes[0]; ++k) {
        double t = probes[k].theta_deg * CDL_DEG_TO_RAD;
        cdl_vec3 w = {sin(t) * cos(probes[k].phi), sin(t) * sin(probes[k].phi), cos(t)};
        double pdf;
        double L = cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), w, &pdf).cd_m2;
        CHECK_MSG(L == 2.0 * (1 + probes[k].i + 10 * probes[k].j), "probe %zu: L = %g, expected pixel (%d, %d)", k, L,
                  probes[k].i, probes[k].j);
    }
    /* Images have the exact pixel sum (test_environment_exact.c). */
    CHECK(cdl_emitter_has_exact_illuminance(e));
    cdl_emitter_release(e);

    /* up = +y: the top row looks along +y. */
    e = make_image(img, 8, 4, 1.0, 0, cdl_vec3_make(0, 3, 0));
    CHECK(cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 1, 0), cdl_vec3_make(0.01, 1, 0.02), NULL).cd_m2 <
          9.0);
    CHECK(cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 1, 0), cdl_vec3_make(0.01, -1, 0.02), NULL).cd_m2 >
          30.0);
    cdl_emitter_release(e);
}

/* A 32 x 15 sky: smooth gradient, a dark band, and a small bright "sun". */
static void make_sky(float *img, int W, int H)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double v = 800.0 + 400.0 * cos(CDL_TWO_PI * i / W) + 300.0 * j;
            if (i >= 20 && i < 23) v = 0.0;
            if (i == 9 && j == 3) v = 2e5;
            img[j * W + i] = (float)v;
        }
}

static void test_image_flux_and_sampling(void)
{
    enum { W = 32, H = 15 };
    float img[W * H];
    make_sky(img, W, H);
    cdl_vec3 z = {0, 0, 1};
    for (int upper = 0; upper <= 1; ++upper) {
        cdl_emitter *e = make_image(img, W, H, 1.5, upper, z);
        double Phi = cdl_emitter_flux(e).lm;
        /* 1. Closed form against the pixel-aligned quadrature of L cos over the
         * upper hemisphere (exact for this integrand up to rounding; row 7
         * straddles the horizon and is clipped). */
        receiver_ctx rc = {e, cdl_vec3_make(0, 0, 0), z};
        CHECK_REL(pixel_quadrature(radiance_cosine, &rc, W, H, 4, 1, z), Phi, 1e-12);
        /* The pdf integrates to 1 over the directions it covers (exact, it
         * is constant on each pixel). */
        CHECK_REL(pixel_quadrature(radiance_pdf, &rc, W, H, 2, upper, z), 1.0, 1e-12);
        /* 2. The same by a generic quadrature (not aligned: the pixel edges
         * cost it O(h) ~ 1e-3 with 600 rows). */
        CHECK_REL(hemisphere_quadrature(radiance_cosine, &rc, z, 600), Phi, 3e-3);
        /* 3. Importance sampled E on the upward face: 5 standard errors; it
         * must also agree sample by sample with radiance(). */
        mc_result r = mc_illuminance(e, cdl_vec3_make(0, 0, 0), z, 256, 5, 1);
        CHECK_MSG(fabs(r.mean - Phi) <= 5 * r.stderr_, "upper %d: %g vs %g (se %g)", upper, r.mean, Phi, r.stderr_);
        CHECK(r.stderr_ < 0.01 * Phi && r.pdf_mismatches == 0 && r.bad_samples == 0);
        /* A tilted receiver (sees part of the ground when the image has one). */
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.8, -0.3, 0.2));
        receiver_ctx rt = {e, cdl_vec3_make(0, 0, 0), n};
        double Eq = pixel_quadrature(radiance_cosine, &rt, W, H, 24, upper, z);
        r = mc_illuminance(e, cdl_vec3_make(0, 0, 0), n, 256, 6, 1);
        /* The cos kink inside pixels costs the aligned rule ~1e-4 here. */
        CHECK_MSG(fabs(r.mean - Eq) <= 5 * r.stderr_ + 1e-4 * Eq, "tilted, upper %d: %g vs %g (se %g)", upper, r.mean, Eq,
                  r.stderr_);
        CHECK(r.pdf_mismatches == 0 && r.bad_samples == 0);
        /* No sample below the horizon of an upper-hemisphere sky, none in the dark band. */
        int below = 0, dark = 0;
        for (int k = 0; k < 4096; ++k) {
            cdl_light_sample s;
            if (!cdl_emitter_sample(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), (k % 64 + 0.5) / 64,
                                    (k / 64 + 0.5) / 64, &s))
                continue;
            if (upper && s.to_light.z <= 0) below++;
            if (!(s.L.cd_m2 > 0)) dark++;
        }
        CHECK(below == 0 && dark == 0);
        cdl_emitter_release(e);
    }
    /* The flux's closed form by hand for a constant image: pi L whatever the
     * resolution (odd height: the clipped middle row counts its upper half). */
    float flat[7 * 5];
    for (int k = 0; k < 35; ++k) flat[k] = 100.0f;
    cdl_emitter *e = make_image(flat, 7, 5, 3.0, 1, z);
    CHECK_REL(cdl_emitter_flux(e).lm, CDL_PI * 300.0, 1e-14);
    cdl_emitter_release(e);
}

static void test_bad_parameters(void)
{
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    cdl_emitter *e = NULL;
    cdl_error err;
    p.luminance = cdl_nits(-1.0);
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "luminance"), "%s", err.message);
    p.luminance = cdl_nits(1.0);
    p.up = cdl_vec3_make(0, 0, 0);
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "up"), "%s", err.message);
    p.up = cdl_vec3_make(0, 0, 1);
    float img[6] = {1, 2, 3, 4, NAN, 6};
    p.image = img;
    p.width = 3;
    p.height = 2;
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "column 1, row 1"), "%s", err.message);
    img[4] = -2.0f;
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    img[4] = 5.0f;
    p.scale = 0.0;
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "scale"), "%s", err.message);
    p.scale = 1.0;
    p.sky = CDL_SKY_CIE_OVERCAST;
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "sky"), "%s", err.message);
    p.sky = CDL_SKY_UNIFORM;
    p.width = 0;
    CHECK(cdl_emitter_create_environment(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK(e == NULL);
}

int main(void)
{
    test_uniform_sky();
    test_overcast_sky();
    test_image_mapping();
    test_image_flux_and_sampling();
    test_bad_parameters();
    return check_finish();
}
