/* Spot emitter: the smoothstep and cos^n profiles inside, in and beyond
 * the falloff, and the closed-form flux three ways. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"

static cdl_emitter *make_spot(cdl_vec3 pos, cdl_vec3 dir, double I0, double half, double falloff)
{
    cdl_spot_params p = {pos, dir, cdl_candelas(I0), 0, half, falloff, 0.0};
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_spot(&p, &e, &err), &err);
    return e;
}

static cdl_emitter *make_cos_spot(cdl_vec3 pos, cdl_vec3 dir, double I0, double n)
{
    cdl_spot_params p = {pos, dir, cdl_candelas(I0), 1, 0.0, 0.0, n};
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_spot(&p, &e, &err), &err);
    return e;
}

/* A unit direction at angle alpha (degrees) from unit axis a. */
static cdl_vec3 at_angle(cdl_vec3 a, double alpha_deg)
{
    cdl_frame f = cdl_frame_from_normal(a);
    double t = alpha_deg * CDL_DEG_TO_RAD;
    return cdl_frame_to_world(&f, cdl_vec3_make(sin(t) * cos(0.7), sin(t) * sin(0.7), cos(t)));
}

/* DESIGN.md's profile written out directly. */
static double smoothstep_expected(double alpha, double h, double f)
{
    if (alpha <= f) return 1.0;
    if (alpha >= h) return 0.0;
    double t = (cos(alpha * CDL_DEG_TO_RAD) - cos(h * CDL_DEG_TO_RAD)) / (cos(f * CDL_DEG_TO_RAD) - cos(h * CDL_DEG_TO_RAD));
    return 3 * t * t - 2 * t * t * t;
}

static void test_profiles(void)
{
    cdl_vec3 axis = cdl_vec3_normalize(cdl_vec3_make(0.2, -0.3, -1.0));
    cdl_emitter *e = make_spot(cdl_vec3_make(1, 2, 3), cdl_vec3_scale(axis, 7.0), 5000.0, 30.0, 25.0);
    /* Inside the falloff: full intensity; beyond the half angle: none;
     * between: the smoothstep. The formula's cosines differ by ~0.03, so
     * cancellation costs the written-out reference ~2 digits: 1e-12. */
    double alphas[] = {0.0, 10.0, 24.999, 25.0, 25.5, 27.5, 29.0, 29.999, 30.0, 30.001, 60.0, 120.0, 180.0};
    for (size_t k = 0; k < sizeof alphas / sizeof alphas[0]; ++k) {
        double I = cdl_emitter_intensity(e, at_angle(axis, alphas[k])).cd;
        double want = 5000.0 * smoothstep_expected(alphas[k], 30.0, 25.0);
        CHECK_ABS(I, want, 1e-12 * 5000.0);
    }
    /* Midway in cos: t = 1/2 gives exactly half. */
    double cm = 0.5 * (cos(25.0 * CDL_DEG_TO_RAD) + cos(30.0 * CDL_DEG_TO_RAD));
    CHECK_REL(cdl_emitter_intensity(e, at_angle(axis, acos(cm) * CDL_RAD_TO_DEG)).cd, 2500.0, 1e-12);
    /* Monotone non-increasing through the falloff. */
    double prev = 5000.0;
    for (int k = 0; k <= 100; ++k) {
        double I = cdl_emitter_intensity(e, at_angle(axis, 24.0 + 0.07 * k)).cd;
        CHECK(I <= prev + 1e-9);
        prev = I;
    }
    cdl_emitter_release(e);

    /* Hard edge: falloff_start = half_angle. */
    e = make_spot(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), 100.0, 20.0, 20.0);
    CHECK(cdl_emitter_intensity(e, at_angle(cdl_vec3_make(0, 0, -1), 19.99)).cd == 100.0);
    CHECK(cdl_emitter_intensity(e, at_angle(cdl_vec3_make(0, 0, -1), 20.01)).cd == 0.0);
    cdl_emitter_release(e);

    /* A very narrow beam (0.01 to 0.02 degrees): the profile must still be
     * the smoothstep, not rounding noise (cos differences of ~5e-8). */
    e = make_spot(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), 1e9, 0.02, 0.01);
    /* Reference in long double: its cosines' differences keep ~12 digits. */
    long double r = CDL_PI / 180.0L;
    double tt = (double)((cosl(0.015L * r) - cosl(0.02L * r)) / (cosl(0.01L * r) - cosl(0.02L * r)));
    CHECK_REL(cdl_emitter_intensity(e, at_angle(cdl_vec3_make(0, 0, -1), 0.015)).cd, 1e9 * tt * tt * (3 - 2 * tt), 1e-10);
    cdl_emitter_release(e);

    /* cos^n: I0 cos^n in front, nothing behind. */
    e = make_cos_spot(cdl_vec3_make(0, 0, 3), cdl_vec3_make(0, 0, -2), 400.0, 3.0);
    double as[] = {0.0, 30.0, 60.0, 89.0, 90.5, 135.0};
    for (size_t k = 0; k < sizeof as / sizeof as[0]; ++k) {
        double c = cos(as[k] * CDL_DEG_TO_RAD);
        CHECK_ABS(cdl_emitter_intensity(e, at_angle(cdl_vec3_make(0, 0, -1), as[k])).cd, c > 0 ? 400.0 * c * c * c : 0.0,
                  1e-12 * 400.0);
    }
    cdl_emitter_release(e);
}

static void test_illuminance_in_the_beam(void)
{
    /* Spot 3 m above the floor aiming down: E on the floor at horizontal
     * offset x is I(alpha) cos(alpha) / d^2 with tan(alpha) = x/3: inside
     * the falloff, in it and beyond it. */
    cdl_emitter *e = make_spot(cdl_vec3_make(0, 0, 3), cdl_vec3_make(0, 0, -1), 5000.0, 30.0, 25.0);
    double xs[] = {0.0, 1.0, 3 * tan(26.0 * CDL_DEG_TO_RAD), 3 * tan(29.0 * CDL_DEG_TO_RAD), 2.0, 5.0};
    for (size_t k = 0; k < sizeof xs / sizeof xs[0]; ++k) {
        double x = xs[k], d2 = x * x + 9.0, alpha = atan2(x, 3.0) * CDL_RAD_TO_DEG;
        double want = 5000.0 * smoothstep_expected(alpha, 30.0, 25.0) * (3.0 / sqrt(d2)) / d2;
        cdl_delta_light dl;
        cdl_emitter_eval_delta(e, cdl_vec3_make(x, 0, 0), cdl_vec3_make(0, 0, 1), &dl);
        CHECK_ABS(dl.E.lx, want, 1e-12 * 5000.0 / 9.0);
    }
    cdl_emitter_release(e);
}

/* Gauss-Legendre on [a, b] of f(mu) for the axisymmetric profile. */
typedef struct profile_ctx { cdl_emitter *e; cdl_vec3 axis; } profile_ctx;
static double profile_at(const profile_ctx *c, double mu)
{
    cdl_frame f = cdl_frame_from_normal(c->axis);
    double s = sqrt(fmax(0.0, 1 - mu * mu));
    return cdl_emitter_intensity(c->e, cdl_frame_to_world(&f, cdl_vec3_make(s, 0, mu))).cd;
}

static double gauss_mu(const profile_ctx *c, double a, double b)
{
    /* 5-point Gauss-Legendre on 2000 panels: exact for the polynomial (in
     * mu) smoothstep; the error on cos^n is far below 1e-13. */
    static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                0.2369268850561891};
    double sum = 0.0, hpanel = (b - a) / 2000;
    for (int k = 0; k < 2000; ++k) {
        double m = a + (k + 0.5) * hpanel;
        for (int i = 0; i < 5; ++i) sum += w[i] * profile_at(c, m + 0.5 * hpanel * x[i]) * 0.5 * hpanel;
    }
    return sum;
}

static void test_flux_three_ways(void)
{
    struct { double half, falloff; } cases[] = {{30, 25}, {60, 10}, {45, 45}, {180, 90}, {2, 1}, {90, 0}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double h = cases[k].half, f = cases[k].falloff, I0 = 777.0;
        cdl_vec3 axis = cdl_vec3_normalize(cdl_vec3_make(0.5, 0.1, -0.8));
        cdl_emitter *e = make_spot(cdl_vec3_make(0, 0, 0), axis, I0, h, f);
        double Phi = cdl_emitter_flux(e).lm;
        /* 1. Closed form: 2 pi I0 [(1 - cos f) + (cos f - cos h)/2]. */
        double hr = h * CDL_DEG_TO_RAD, fr = f * CDL_DEG_TO_RAD;
        CHECK_REL(Phi, CDL_TWO_PI * I0 * ((1 - cos(fr)) + 0.5 * (cos(fr) - cos(hr))), 1e-12);
        /* 2a. 2 pi int I(mu) dmu with Gauss-Legendre split at cos f and cos h:
         * the profile is a cubic in mu on each piece, so this is exact. */
        profile_ctx pc = {e, axis};
        double q = CDL_TWO_PI * (gauss_mu(&pc, cos(fr), 1.0) + gauss_mu(&pc, cos(hr), cos(fr)));
        CHECK_REL(q, Phi, 1e-12);
        /* 2b. Brute force over the sphere in a frame not aligned with the
         * axis: the hard edge (45/45) makes the midpoint rule O(h) there:
         * with 1200 x 2400 cells the edge band holds ~1e-3 of the flux. */
        double tol = (h == f) ? 2e-3 : 2e-5;
        CHECK_REL(sphere_quadrature(intensity_of, e, 1200), Phi, tol);
        /* 3. Monte Carlo, importance sampled: directions uniform in the cone
         * of half angle h (pdf 1 / Omega_cone), E from eval_delta on a sphere
         * of radius 2 m around the light: Phi = E[E r^2 / pdf]. 4096 samples:
         * tolerance 5 standard errors. */
        double cos_h = cos(hr), omega = CDL_TWO_PI * (1 - cos_h), r = 2.0, sum = 0, sum2 = 0;
        cdl_frame fa = cdl_frame_from_normal(axis);
        cdl_rng_key key = {11, (uint64_t)k};
        int N = 4096;
        for (int i = 0; i < N; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)i, u);
            double mu = 1 - u[0] * (1 - cos_h), s = sqrt(fmax(0, 1 - mu * mu)), ph = CDL_TWO_PI * u[1];
            cdl_vec3 w = cdl_frame_to_world(&fa, cdl_vec3_make(s * cos(ph), s * sin(ph), mu));
            cdl_delta_light dl;
            cdl_emitter_eval_delta(e, cdl_vec3_scale(w, r), cdl_vec3_neg(w), &dl);
            double v = dl.E.lx * r * r * omega;
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / N, se = sqrt(fmax(0, sum2 / N - mean * mean) / (N - 1));
        CHECK_MSG(fabs(mean - Phi) <= 5 * se + 1e-12 * Phi, "MC %g vs %g (se %g)", mean, Phi, se);
        cdl_emitter_release(e);
    }
    /* cos^n: 2 pi I0 / (n + 1), against Gauss-Legendre in mu and by Monte Carlo. */
    double ns[] = {0.0, 1.0, 2.5, 30.0};
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; ++k) {
        cdl_vec3 axis = cdl_vec3_make(0, 0, -1);
        cdl_emitter *e = make_cos_spot(cdl_vec3_make(0, 0, 0), axis, 50.0, ns[k]);
        double Phi = cdl_emitter_flux(e).lm;
        CHECK_REL(Phi, CDL_TWO_PI * 50.0 / (ns[k] + 1), 1e-15);
        profile_ctx pc = {e, axis};
        CHECK_REL(CDL_TWO_PI * gauss_mu(&pc, 0.0, 1.0), Phi, 1e-12);
        /* 3. Monte Carlo: eval_delta at points uniform on a sphere of radius
         * 1.5 m around the light (emitter_checks.h), 65536 samples, 5
         * standard errors; the peaked n = 30 lobe has the largest error (its
         * per-sample deviation is ~5.5 Phi: about 2 % standard error). */
        double mean, se;
        delta_flux_on_sphere(e, cdl_vec3_make(0, 0, 0), 1.5, 65536, 21 + (uint64_t)k, &mean, &se);
        CHECK_MSG(fabs(mean - Phi) <= 5 * se && se < 0.05 * Phi, "cos^%g: MC %g vs %g (se %g)", ns[k], mean, Phi, se);
        /* Nothing behind. */
        CHECK(cdl_emitter_intensity(e, cdl_vec3_make(0.3, 0, 0.2)).cd == 0.0);
        cdl_emitter_release(e);
    }
    /* flux_lm -> I0 as the header says: Phi / (flux at 1 cd). */
    cdl_emitter *unit = make_spot(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), 1.0, 40.0, 30.0);
    double I0 = 1500.0 / cdl_emitter_flux(unit).lm;
    cdl_emitter *e = make_spot(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), I0, 40.0, 30.0);
    CHECK_REL(cdl_emitter_flux(e).lm, 1500.0, 1e-14);
    cdl_emitter_release(unit);
    cdl_emitter_release(e);
}

static void test_bad_parameters(void)
{
    cdl_emitter *e = NULL;
    cdl_error err;
    cdl_spot_params p = {{0, 0, 0}, {0, 0, -1}, cdl_candelas(10.0), 0, 30.0, 35.0, 0.0};
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "falloff_start") && strstr(err.message, "35"), "%s", err.message);
    p.falloff_start_deg = 10.0;
    p.half_angle_deg = 0.0;
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "half_angle"), "%s", err.message);
    p.half_angle_deg = 190.0;
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    p.half_angle_deg = 30.0;
    p.direction = cdl_vec3_make(0, 0, 0);
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "direction"), "%s", err.message);
    p.direction = cdl_vec3_make(0, 0, -1);
    p.use_exponent = 1;
    p.exponent = -1.0;
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "exponent"), "%s", err.message);
    p.exponent = NAN;
    CHECK(cdl_emitter_create_spot(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK(e == NULL);
}

int main(void)
{
    test_profiles();
    test_illuminance_in_the_beam();
    test_flux_three_ways();
    test_bad_parameters();
    return check_finish();
}
