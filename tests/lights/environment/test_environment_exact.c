/* Image environments, exact illuminance: E(n) = sum over pixels of L times
 * the pixel's projected solid angle on n's hemisphere, against closed forms
 * that do not use pixels (pi L for a uniform sphere, a polar cap's
 * projected solid angle from the sphere formula of projected_solid_angle.h,
 * the uniform upper-hemisphere sky), and one pixel the horizon crosses
 * against a fine numerical integration. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "lights/environment/environment_pixels.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"

static cdl_emitter *make_image(const float *img, int w, int h, double scale, int upper, cdl_vec3 up)
{
    return make_environment(0.0, img, w, h, scale, upper, up);
}

static double exact_E(const cdl_emitter *e, cdl_vec3 n)
{
    cdl_illuminance E;
    cdl_error err;
    CHECK_OK(cdl_emitter_exact_illuminance(e, cdl_vec3_make(4, -2, 7), n, &E, &err), &err);
    return E.lx;
}

/* Normals that put the horizon along pixel edges (n = +-up: the equator is
 * a row boundary for even heights; n horizontal at azimuth 0 or 90: the
 * horizon runs along column edges when 4 divides the width), through
 * pixel corners, and anywhere. */
static const cdl_vec3 normals[] = {
    {0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0.3, -0.5, 0.1}, {-0.2, 0.1, -0.9},
    {0.70710678118654752, 0.70710678118654752, 0}, {0.001, 0, 1}, {1, 1e-9, 1e-9}, {0.5, 0.5, 0.70710678118654752},
};
enum { NORMALS = sizeof normals / sizeof normals[0] };

/* A uniform image is a uniform sphere: pi L on every plane, for any size
 * (1 x 1 and 2 x 1 images exercise the cells wider than pi in azimuth).
 * Every term is exact; summing up to 2048 pixels of rounding-level errors
 * stays below 1e-13. */
static void test_uniform_map(void)
{
    const int sizes[][2] = {{64, 32}, {7, 5}, {1, 1}, {2, 1}, {3, 2}, {360, 181}, {4, 4}};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        int W = sizes[s][0], H = sizes[s][1];
        float *img = malloc((size_t)W * H * sizeof *img);
        for (int k = 0; k < W * H; ++k) img[k] = 250.0f;
        cdl_emitter *e = make_image(img, W, H, 2.0, 0, cdl_vec3_make(0, 0, 1));
        cdl_emitter *tilted = make_image(img, W, H, 2.0, 0, cdl_vec3_make(0.2, -0.4, 1));
        for (int k = 0; k < NORMALS; ++k) {
            cdl_vec3 n = cdl_vec3_normalize(normals[k]);
            CHECK_REL(exact_E(e, n), CDL_PI * 500.0, 1e-13);
            CHECK_REL(exact_E(tilted, n), CDL_PI * 500.0, 1e-13);
        }
        /* Upper hemisphere only: pi L (1 + cos beta) / 2 (the uniform sky's
         * closed form, emitter_environment.c); odd heights clip a row. */
        cdl_emitter *sky = make_image(img, W, H, 2.0, 1, cdl_vec3_make(0, 0, 1));
        for (int k = 0; k < NORMALS; ++k) {
            cdl_vec3 n = cdl_vec3_normalize(normals[k]);
            double expected = CDL_PI * 500.0 * 0.5 * (1.0 + n.z);
            CHECK_ABS(exact_E(sky, n), expected, 1e-13 * CDL_PI * 500.0);
        }
        CHECK(cdl_emitter_has_exact_illuminance(e));
        cdl_emitter_release(e);
        cdl_emitter_release(tilted);
        cdl_emitter_release(sky);
        free(img);
    }
}

/* Rows j < J lit (a polar cap of half-angle a = pi J / H about up), the rest
 * dark; rows j >= H - J lit (the cap of half-angle a about -up); rows
 * j >= J lit (the sphere less the first cap: pi less its value). A cap of
 * half-angle a about axis c is what a sphere of radius sin a at distance 1
 * along c subtends, so its projected solid angle is that sphere's
 * (cdl_projected_solid_angle_sphere: the tangent disk's contour integral,
 * clipped at the receiver's plane): for a vertical n, pi sin^2 a; for a
 * tilted n that puts part of the cap below the horizon, the clipped value.
 * Independent of the pixel sums; both exact, compared to 1e-12. */
static void test_polar_caps(void)
{
    enum { W = 48, H = 24 };
    static float top[W * H], bottom[W * H], others[W * H];
    const int J = 7;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            top[j * W + i] = j < J ? 1000.0f : 0.0f;
            bottom[j * W + i] = j >= H - J ? 1000.0f : 0.0f;
            others[j * W + i] = j >= J ? 1000.0f : 0.0f;
        }
    double a = CDL_PI * J / H;
    cdl_vec3 up = cdl_vec3_normalize(cdl_vec3_make(0.1, 0.3, 1.0));
    cdl_emitter *cap = make_image(top, W, H, 1.0, 0, up), *low = make_image(bottom, W, H, 1.0, 0, up);
    cdl_emitter *rest = make_image(others, W, H, 1.0, 0, up);
    /* Vertical receiver: the whole cap, pi sin^2 a. */
    CHECK_REL(exact_E(cap, up), 1000.0 * CDL_PI * sin(a) * sin(a), 1e-13);
    double betas[] = {0.0, 0.4, 1.2, 1.5707963267948966, 1.9, 2.6, 3.0};
    for (size_t k = 0; k < sizeof betas / sizeof betas[0]; ++k) {
        /* n at angle beta from up, turned about an axis in the horizon. */
        cdl_vec3 side = cdl_vec3_normalize(cdl_vec3_cross(up, cdl_vec3_make(1, 0, 0)));
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_scale(up, cos(betas[k])), cdl_vec3_scale(side, sin(betas[k]))));
        double q_top = cdl_projected_solid_angle_sphere(up, sin(a), n);
        double q_bottom = cdl_projected_solid_angle_sphere(cdl_vec3_neg(up), sin(a), n);
        CHECK_ABS(exact_E(cap, n), 1000.0 * q_top, 1e-12 * 1000.0 * CDL_PI);
        CHECK_ABS(exact_E(low, n), 1000.0 * q_bottom, 1e-12 * 1000.0 * CDL_PI);
        CHECK_ABS(exact_E(rest, n), 1000.0 * (CDL_PI - q_top), 1e-12 * 1000.0 * CDL_PI);
    }
    cdl_emitter_release(cap);
    cdl_emitter_release(low);
    cdl_emitter_release(rest);
}

/* int over the cell of max(0, n.w) dw by the midpoint rule on K x K
 * sub-cells equal in solid angle (uniform in cos theta and phi). The
 * integrand is smooth but for the kink along the horizon; the rule's error
 * goes as 1/K^2 (measured on the corner cases below: 1e-5, 2.5e-6, 6e-7,
 * 1.6e-7 relative at K = 500 .. 4000), so one Richardson step,
 * (4 Q_2K - Q_K) / 3, leaves below 1e-9 at K = 600. */
static double cell_midpoint(double ta, double tb, double pa, double pb, cdl_vec3 n, int K)
{
    double ca = cos(ta), cb = cos(tb), sum = 0.0;
    for (int r = 0; r < K; ++r) {
        double mu = ca - (r + 0.5) * (ca - cb) / K, s = sqrt(fmax(0.0, 1.0 - mu * mu));
        double row = 0.0;
        for (int c = 0; c < K; ++c) {
            double phi = pa + (c + 0.5) * (pb - pa) / K;
            row += fmax(0.0, n.x * s * cos(phi) + n.y * s * sin(phi) + n.z * mu);
        }
        sum += row;
    }
    return sum * (ca - cb) * (pb - pa) / ((double)K * K);
}

static double cell_quadrature(double ta, double tb, double pa, double pb, cdl_vec3 n, int K)
{
    return (4.0 * cell_midpoint(ta, tb, pa, pb, n, 2 * K) - cell_midpoint(ta, tb, pa, pb, n, K)) / 3.0;
}

/* One bright pixel, the horizon of n through it in several ways (near its
 * middle, near a corner: slivers), against the extrapolated quadrature;
 * the emitter's E is that pixel's L Q (nothing else lit). Tolerance 2e-8
 * relative (20 x the quadrature's own error) plus 1e-9 of the pixel's solid
 * angle: for slivers near a corner the kink keeps the extrapolated rule at
 * ~1e-11 sr (1e-10 of the pixel). */
static void test_single_pixel(void)
{
    enum { W = 16, H = 8 };
    static float img[W * H];
    const int pi_ = 5, pj = 2; /* theta in [pi/4, 3pi/8], u in [5/16, 6/16) */
    img[pj * W + pi_] = 4000.0f;
    cdl_emitter *e = make_image(img, W, H, 1.0, 0, cdl_vec3_make(0, 0, 1));
    double ta = CDL_PI * pj / H, tb = CDL_PI * (pj + 1) / H;
    double pa = CDL_PI + CDL_TWO_PI * pi_ / W, pb = CDL_PI + CDL_TWO_PI * (pi_ + 1) / W;
    /* Directions of the cell's middle and a corner; normals almost
     * perpendicular to them put the horizon through the cell. */
    double tm = 0.5 * (ta + tb), pm = 0.5 * (pa + pb);
    cdl_vec3 mid = {sin(tm) * cos(pm), sin(tm) * sin(pm), cos(tm)};
    cdl_vec3 corner = {sin(ta) * cos(pa), sin(ta) * sin(pa), cos(ta)};
    cdl_vec3 axes[] = {{0, 0, 1}, {1, 0, 0}, {0.3, 0.8, -0.2}};
    int tested = 0;
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side)
            for (int k = 0; k < 3; ++k) {
                cdl_vec3 through = side ? corner : mid;
                cdl_vec3 perp = cdl_vec3_normalize(cdl_vec3_cross(through, axes[a]));
                double gamma = (k - 1) * 0.05; /* horizon shifted off the point */
                cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_scale(perp, cos(gamma)), cdl_vec3_scale(through, sin(gamma))));
                double q = cell_quadrature(ta, tb, pa, pb, n, 600);
                double direct = cdl_env_cell_projected_solid_angle(ta, tb, pa, pb, n);
                double omega = (cos(ta) - cos(tb)) * (pb - pa);
                CHECK_MSG(fabs(direct - q) <= 2e-8 * q + 1e-9 * omega, "axis %d side %d k %d: Q = %.12g, quadrature %.12g", a, side, k,
                          direct, q);
                CHECK_REL(exact_E(e, n), 4000.0 * direct, 1e-15);
                tested++;
            }
    CHECK(tested == 18);
    cdl_emitter_release(e);
}

/* For any cell, crossed by the horizon or not, max(0, x) - max(0, -x) = x
 * gives Q(n) - Q(-n) = n . V, V = int w dw in closed form; both Q by the
 * contour integral, independently. Rounding: 1e-14 on values up to ~2. */
static void test_cell_identities(void)
{
    double cells[][4] = {{0.0, 0.4, 0.0, 0.5}, {1.2, 1.5707963267948966, 2.0, 2.3}, {2.9, CDL_PI, -1.0, 0.2},
                         {0.3, 2.8, 1.0, 3.2}};
    for (size_t c = 0; c < sizeof cells / sizeof cells[0]; ++c) {
        double ta = cells[c][0], tb = cells[c][1], pa = cells[c][2], pb = cells[c][3];
        /* V = int w dw in closed form (environment_pixels.h). */
        double S = 0.5 * ((tb - ta) - sin(tb - ta) * cos(ta + tb)), Z = 0.5 * sin(ta + tb) * sin(tb - ta);
        cdl_vec3 V = {S * (sin(pb) - sin(pa)), S * (cos(pa) - cos(pb)), Z * (pb - pa)};
        for (int k = 0; k < NORMALS; ++k) {
            cdl_vec3 n = cdl_vec3_normalize(normals[k]);
            double up = cdl_env_cell_projected_solid_angle(ta, tb, pa, pb, n);
            double down = cdl_env_cell_projected_solid_angle(ta, tb, pa, pb, cdl_vec3_neg(n));
            CHECK(up >= 0.0 && down >= 0.0);
            CHECK_ABS(up - down, cdl_vec3_dot(n, V), 1e-14);
        }
    }
}

/* The "flux" (E on a disk facing up) is E(up). */
static void test_flux_is_upward_E(void)
{
    enum { W = 20, H = 9 };
    static float img[W * H];
    for (int k = 0; k < W * H; ++k) img[k] = (float)(100 + (k * 37) % 211);
    for (int upper = 0; upper <= 1; ++upper) {
        cdl_emitter *e = make_image(img, W, H, 1.5, upper, cdl_vec3_make(0, 0, 1));
        CHECK_REL(cdl_emitter_flux(e).lm, exact_E(e, cdl_vec3_make(0, 0, 1)), 1e-15);
        cdl_emitter_release(e);
    }
}

int main(void)
{
    test_uniform_map();
    test_polar_caps();
    test_single_pixel();
    test_cell_identities();
    test_flux_is_upward_E();
    return check_finish();
}
