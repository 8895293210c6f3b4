/* Triangle solid angles and Arvo's spherical-triangle sampling: the solid
 * angle against independent references, and uniformity (the fraction of
 * samples landing in each of the four midpoint sub-triangles equals its
 * share of the solid angle). */
#include <math.h>

#include "check.h"
#include "lights/emitters/spherical_triangle.h"
#include "radiometry/constants.h"
#include "base/rng.h"

/* Girard's theorem in long double from the vertex directions (an
 * independent formula): Omega = alpha + beta + gamma - pi. */
static double girard(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    long double v[3][3] = {{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}}, sum = 0;
    for (int k = 0; k < 3; ++k) {
        long double l = sqrtl(v[k][0] * v[k][0] + v[k][1] * v[k][1] + v[k][2] * v[k][2]);
        for (int i = 0; i < 3; ++i) v[k][i] /= l;
    }
    for (int k = 0; k < 3; ++k) {
        long double *A = v[k], *B = v[(k + 1) % 3], *C = v[(k + 2) % 3];
        long double dab = A[0] * B[0] + A[1] * B[1] + A[2] * B[2], dac = A[0] * C[0] + A[1] * C[1] + A[2] * C[2];
        long double tb[3], tc[3];
        for (int i = 0; i < 3; ++i) {
            tb[i] = B[i] - dab * A[i];
            tc[i] = C[i] - dac * A[i];
        }
        long double cr[3] = {tb[1] * tc[2] - tb[2] * tc[1], tb[2] * tc[0] - tb[0] * tc[2], tb[0] * tc[1] - tb[1] * tc[0]};
        sum += atan2l(sqrtl(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), tb[0] * tc[0] + tb[1] * tc[1] + tb[2] * tc[2]);
    }
    return (double)(sum - CDL_PI);
}

static void test_solid_angle(void)
{
    /* The octant triangle (x, y, z axes) subtends exactly 4 pi / 8. */
    CHECK_REL(cdl_triangle_solid_angle(cdl_vec3_make(1, 0, 0), cdl_vec3_make(0, 2, 0), cdl_vec3_make(0, 0, 3)), CDL_PI / 2, 1e-15);
    /* Half of a square's solid angle, by symmetry: the square [-1,1]^2 at
     * height 1 subtends 4 atan(1 / sqrt(3)) = 2 pi / 3; its diagonal halves it. */
    CHECK_REL(cdl_triangle_solid_angle(cdl_vec3_make(-1, -1, 1), cdl_vec3_make(1, -1, 1), cdl_vec3_make(1, 1, 1)), CDL_PI / 3, 1e-15);
    /* Random triangles against Girard in long double (good to ~1e-17 sr
     * absolute here): 1e-14 absolute + 1e-12 relative. */
    cdl_rng_key key = {13, 13};
    for (int t = 0; t < 200; ++t) {
        double u[2], w[2], x[2];
        cdl_rng_uniform2(key, 3 * (uint64_t)t, u);
        cdl_rng_uniform2(key, 3 * (uint64_t)t + 1, w);
        cdl_rng_uniform2(key, 3 * (uint64_t)t + 2, x);
        double d = pow(10.0, 2.0 * u[0] - 1.0);
        cdl_vec3 c0 = {0.3 * w[0], -0.2, d};
        cdl_vec3 a = cdl_vec3_add(c0, cdl_vec3_make(-0.5, -0.3 * x[0], 0.1));
        cdl_vec3 b = cdl_vec3_add(c0, cdl_vec3_make(0.6, -0.1, 0.2 * u[1]));
        cdl_vec3 c = cdl_vec3_add(c0, cdl_vec3_make(0.1 * x[1], 0.7, -0.1 * w[1]));
        double g = girard(a, b, c);
        CHECK_ABS(cdl_triangle_solid_angle(a, b, c), g, 1e-14 + 1e-12 * g);
        CHECK_ABS(cdl_triangle_solid_angle(a, c, b), g, 1e-14 + 1e-12 * g); /* orientation does not matter */
    }
    /* Degenerate: nothing. */
    CHECK(cdl_triangle_solid_angle(cdl_vec3_make(0, 0, 1), cdl_vec3_make(1, 0, 1), cdl_vec3_make(2, 0, 1)) == 0.0);
}

static void test_uniform_in_solid_angle(void)
{
    /* Three triangles: near and large, oblique, small (~2e-3 sr); both
     * orientations. 120000 samples; counts in the four midpoint
     * sub-triangles are multinomial with p = Omega_sub / Omega: 5 sigma. */
    cdl_vec3 tris[][3] = {{{-2, -1, 0.3}, {2, -1.5, 0.3}, {0.2, 2, 0.3}},
                          {{1, 0, 1}, {3, 0.5, 2}, {1.5, 2, 0.5}},
                          {{0.9, 1, 10}, {1.6, 1, 10}, {1, 1.7, 10.2}}};
    for (int k = 0; k < 3; ++k)
        for (int flip = 0; flip <= 1; ++flip) {
            cdl_vec3 a = tris[k][0], b = flip ? tris[k][2] : tris[k][1], c = flip ? tris[k][1] : tris[k][2];
            cdl_spherical_triangle st;
            double S = cdl_spherical_triangle_init(&st, a, b, c);
            CHECK(S > 1e-3);
            cdl_vec3 mab = cdl_vec3_scale(cdl_vec3_add(a, b), 0.5), mbc = cdl_vec3_scale(cdl_vec3_add(b, c), 0.5),
                     mca = cdl_vec3_scale(cdl_vec3_add(c, a), 0.5);
            cdl_vec3 sub[4][3] = {{a, mab, mca}, {mab, b, mbc}, {mca, mbc, c}, {mab, mbc, mca}};
            /* The plane of the triangle: hits are found by ray-plane intersection. */
            cdl_vec3 nrm = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a));
            int counts[4] = {0}, N = 120000, misses = 0;
            cdl_rng_key key = {41, (uint64_t)(2 * k + flip)};
            for (int i = 0; i < N; ++i) {
                double u[2];
                cdl_rng_uniform2(key, (uint64_t)i, u);
                cdl_vec3 w = cdl_spherical_triangle_sample(&st, u[0], u[1]);
                cdl_vec3 x = cdl_vec3_scale(w, cdl_vec3_dot(nrm, a) / cdl_vec3_dot(nrm, w));
                /* Which sub-triangle holds x: barycentrics in the big triangle. */
                cdl_vec3 e1 = cdl_vec3_sub(b, a), e2 = cdl_vec3_sub(c, a), r = cdl_vec3_sub(x, a);
                double d11 = cdl_vec3_dot(e1, e1), d12 = cdl_vec3_dot(e1, e2), d22 = cdl_vec3_dot(e2, e2);
                double r1 = cdl_vec3_dot(r, e1), r2 = cdl_vec3_dot(r, e2), det = d11 * d22 - d12 * d12;
                double bb = (r1 * d22 - r2 * d12) / det, bc = (r2 * d11 - r1 * d12) / det, ba = 1 - bb - bc;
                if (ba < -1e-9 || bb < -1e-9 || bc < -1e-9) misses++;
                int which = ba >= 0.5 ? 0 : bb >= 0.5 ? 1 : bc >= 0.5 ? 2 : 3;
                counts[which]++;
            }
            CHECK_MSG(misses == 0, "triangle %d: %d samples outside", k, misses);
            for (int j = 0; j < 4; ++j) {
                double p = cdl_triangle_solid_angle(sub[j][0], sub[j][1], sub[j][2]) / S;
                double mean = N * p, sigma = sqrt(N * p * (1 - p));
                CHECK_MSG(fabs(counts[j] - mean) <= 5 * sigma, "triangle %d flip %d sub %d: %d vs %.1f", k, flip, j,
                          counts[j], mean);
            }
        }
}

int main(void)
{
    test_solid_angle();
    test_uniform_in_solid_angle();
    return check_finish();
}
