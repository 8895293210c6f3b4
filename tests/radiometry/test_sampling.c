/* Solid angles and samplers, checked by integrating functions with known
 * integrals over the hemisphere. */
#include <math.h>

#include "check.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "base/rng.h"
#include "radiometry/sampling.h"

/* Cosine-weighted estimate of int f(w) cos(theta) dw with an M x N stratified set. */
typedef double (*hemisphere_fn)(cdl_vec3 w);

static double cosine_weighted_integral(hemisphere_fn f, int M, int N, uint64_t seed)
{
    cdl_rng_key key = {seed, 7};
    double sum = 0.0;
    for (int j = 0; j < M; ++j)
        for (int k = 0; k < N; ++k) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)(j * N + k), u);
            cdl_vec3 w = cdl_sample_cosine_hemisphere_stratified(j, k, M, N, u[0], u[1]);
            sum += f(w);
        }
    return CDL_PI * sum / (M * N);
}

static double cos_theta(cdl_vec3 w) { return w.z; }
static double x_squared(cdl_vec3 w) { return w.x * w.x; }
static double cap_30deg(cdl_vec3 w) { return w.z > cos(30.0 * CDL_DEG_TO_RAD) ? 1.0 : 0.0; }
static double in_first_quadrant(cdl_vec3 w) { return (w.x > 0 && w.y > 0) ? 1.0 : 0.0; }

static void test_stratified_cosine_sampler(void)
{
    /* Every direction is a unit vector in the upper hemisphere. */
    for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k) {
            cdl_vec3 w = cdl_sample_cosine_hemisphere_stratified(j, k, 8, 8, 0.37, 0.91);
            CHECK_ABS(cdl_vec3_length(w), 1.0, 1e-15);
            CHECK(w.z >= 0.0);
        }
    /* int cos(theta) dw over the hemisphere = pi, taken over the strata the
     * sampler draws from. Stratum (j, k) is the cell swept by u1, u2 in
     * [0, 1]; its corners come from the sampler itself, and its cosine-weighted
     * solid angle is, in closed form,
     *   int_phi0^phi1 int_theta0^theta1 cos(t) sin(t) dt dphi
     *     = (phi1 - phi0) (cos^2(theta0) - cos^2(theta1)) / 2.
     * The cells must tile the hemisphere (their sum is pi, the integral of
     * cos(theta)) with equal measure pi / (M N) each, which is what makes the
     * estimator (pi / (M N)) sum L unbiased. A uniform-in-cos(theta) or
     * uniform-in-theta mapping fails both by tens of percent. Tolerance: each
     * cell is a sqrt, an atan2 and a few products away from the sampler's
     * output, so a few ulps; 1e-13 leaves margin. */
    const int M = 12, N = 7;
    double total = 0.0;
    for (int j = 0; j < M; ++j)
        for (int k = 0; k < N; ++k) {
            cdl_vec3 lo = cdl_sample_cosine_hemisphere_stratified(j, k, M, N, 0.0, 0.0);
            cdl_vec3 hi = cdl_sample_cosine_hemisphere_stratified(j, k, M, N, 1.0, 1.0);
            /* Azimuth swept across the stratum, measured on the last theta band
             * (at the pole the xy projection vanishes); N > 2 keeps it below pi. */
            cdl_vec3 a = cdl_sample_cosine_hemisphere_stratified(M - 1, k, M, N, 0.0, 0.0);
            cdl_vec3 b = cdl_sample_cosine_hemisphere_stratified(M - 1, k, M, N, 0.0, 1.0);
            double dphi = atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
            double cell = dphi * (lo.z * lo.z - hi.z * hi.z) / 2.0;
            CHECK_REL(cell, CDL_PI / (M * N), 1e-13);
            total += cell;
        }
    CHECK_REL(total, CDL_PI, 1e-13);
    /* The theta bands: cos^2(theta) falls by 1/M per band, from 1 at the
     * normal to 0 at the horizon. */
    CHECK_ABS(cdl_sample_cosine_hemisphere_stratified(0, 0, M, N, 0.0, 0.0).z, 1.0, 1e-15);
    CHECK_ABS(cdl_sample_cosine_hemisphere_stratified(M - 1, 0, M, N, 1.0, 0.0).z, 0.0, 1e-15);

    /* The distribution itself: integrals of cos(theta) times
         *   cos(theta)     -> 2 pi / 3
     *   x^2            -> pi / 4       (sin^2 cos^2 phi)
     *   [theta < 30]   -> pi sin^2(30) = pi / 4   (strata aligned in cos^2)
     *   [x > 0, y > 0] -> pi / 4       (strata aligned in phi)
     * With 64 x 64 jittered strata, a smooth integrand varies by ~2/64 across
     * a stratum, so each stratum contributes variance ~(2/64)^2/12 and the
     * estimate has a standard error of ~1.4e-4 (1.8e-4 relative); 1e-3 is
     * about 5 standard errors. The indicator
     * functions whose edges coincide with stratum edges are exact to 1e-12. */
    CHECK_REL(cosine_weighted_integral(cos_theta, 64, 64, 1), 2.0 * CDL_PI / 3.0, 1e-3);
    CHECK_REL(cosine_weighted_integral(x_squared, 64, 64, 1), CDL_PI / 4.0, 1e-3);
    CHECK_REL(cosine_weighted_integral(cap_30deg, 64, 64, 1), CDL_PI / 4.0, 1e-12);
    CHECK_REL(cosine_weighted_integral(in_first_quadrant, 64, 64, 1), CDL_PI / 4.0, 1e-12);
}

static void test_other_samplers(void)
{
    /* Uniform sphere: E[z^2] = 1/3; uniform cone: E[cos] = (1 + cos_max)/2;
     * 2^16 samples, tolerance 5 standard errors (sd(z^2) ~ 0.3). */
    const int n = 1 << 16;
    cdl_rng_key key = {42, 1};
    double z2 = 0.0, cone = 0.0, cos_max = cos(20.0 * CDL_DEG_TO_RAD);
    for (int i = 0; i < n; ++i) {
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)i, u);
        cdl_vec3 w = cdl_sample_uniform_sphere(u[0], u[1]);
        z2 += w.z * w.z;
        cdl_vec3 c = cdl_sample_uniform_cone(cos_max, u[0], u[1]);
        CHECK(c.z >= cos_max - 1e-15);
        cone += c.z;
    }
    CHECK_ABS(z2 / n, 1.0 / 3.0, 5.0 * 0.3 / sqrt((double)n));
    CHECK_ABS(cone / n, 0.5 * (1.0 + cos_max), 5.0 * 0.02 / sqrt((double)n));

    /* Triangle sampling: barycentrics are in the triangle and the mean is the centroid. */
    double m0 = 0.0, m1 = 0.0;
    for (int i = 0; i < n; ++i) {
        double u[2], b0, b1;
        cdl_rng_uniform2(key, (uint64_t)(i + n), u);
        cdl_sample_uniform_triangle(u[0], u[1], &b0, &b1);
        CHECK(b0 >= 0.0 && b1 >= 0.0 && b0 + b1 <= 1.0 + 1e-15);
        m0 += b0;
        m1 += b1;
    }
    CHECK_ABS(m0 / n, 1.0 / 3.0, 5.0 * 0.24 / sqrt((double)n));
    CHECK_ABS(m1 / n, 1.0 / 3.0, 5.0 * 0.24 / sqrt((double)n));
}

static void test_cone_solid_angle(void)
{
    /* Omega = 2 pi (1 - cos a): the hemisphere is 2 pi, the sphere 4 pi. */
    CHECK_REL(cdl_cone_solid_angle(CDL_PI / 2).sr, CDL_TWO_PI, 1e-15);
    CHECK_REL(cdl_cone_solid_angle(CDL_PI).sr, CDL_FOUR_PI, 1e-15);
    CHECK_REL(cdl_cone_solid_angle(60.0 * CDL_DEG_TO_RAD).sr, CDL_PI, 1e-14);
    /* Tiny cones keep full precision: Omega -> pi a^2 (1 - a^2/12). */
    double a = 1e-6;
    CHECK_REL(cdl_cone_solid_angle(a).sr, CDL_PI * a * a * (1.0 - a * a / 12.0), 1e-14);
}

static void test_frame(void)
{
    const cdl_vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0.3, -0.4, 0.866}, {0.6, 0.0, -0.8}};
    for (size_t i = 0; i < sizeof normals / sizeof normals[0]; ++i) {
        cdl_vec3 n = cdl_vec3_normalize(normals[i]);
        cdl_frame f = cdl_frame_from_normal(n);
        CHECK_ABS(cdl_vec3_dot(f.s, f.t), 0.0, 1e-15);
        CHECK_ABS(cdl_vec3_dot(f.s, f.n), 0.0, 1e-15);
        CHECK_ABS(cdl_vec3_length(f.s), 1.0, 1e-15);
        CHECK_ABS(cdl_vec3_length(f.t), 1.0, 1e-15);
        /* right-handed: s x t = n */
        cdl_vec3 c = cdl_vec3_cross(f.s, f.t);
        CHECK_ABS(cdl_vec3_distance(c, n), 0.0, 1e-15);
        cdl_vec3 v = cdl_vec3_make(0.2, -0.7, 0.5);
        CHECK_ABS(cdl_vec3_distance(cdl_frame_to_local(&f, cdl_frame_to_world(&f, v)), v), 0.0, 1e-15);
    }
    /* Length without overflow for huge components. */
    CHECK_REL(cdl_vec3_length(cdl_vec3_make(3e200, 4e200, 0)), 5e200, 1e-15);
    /* ... and without underflow for tiny ones, on both sides of the bounds
     * of the plain square root (sums of squares 2^-1000 and 2^1000): a
     * 3-4-5 triangle scaled by 2^k has length 5 x 2^k to rounding */
    const int scales[] = {-1074 + 3, -600, -501, -500, -499, 0, 499, 500, 501, 1019};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; ++k) {
        double u = ldexp(1.0, scales[k]);
        CHECK_REL(cdl_vec3_length(cdl_vec3_make(0.0, 3.0 * u, -4.0 * u)), 5.0 * u, 1e-15);
        CHECK_REL(cdl_vec3_length(cdl_vec3_normalize(cdl_vec3_make(3.0 * u, 4.0 * u, 0.0))), 1.0, 1e-15);
    }
    CHECK(isinf(cdl_vec3_length(cdl_vec3_make(INFINITY, 1.0, 0.0))));
    CHECK(isnan(cdl_vec3_length(cdl_vec3_make(NAN, 1.0, 0.0))));
}

int main(void)
{
    test_stratified_cosine_sampler();
    test_other_samplers();
    test_cone_solid_angle();
    test_frame();
    return check_finish();
}
