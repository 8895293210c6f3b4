/* Spherical rectangle sampling: its solid angle against the closed form,
 * samples on the rectangle, and uniformity in solid angle (the fraction of
 * samples in each sub-rectangle equals its share of the solid angle).
 *
 * Closed form: a rectangle [x0,x1] x [y0,y1] in the plane at distance h
 * from the receiver, the receiver's foot at the origin, subtends
 *   Omega = F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0),
 *   F(x, y) = atan(x y / (h sqrt(x^2 + y^2 + h^2)))
 * (the solid angle of the corner rectangle [0,x] x [0,y], e.g. Van Oosterom
 * and Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983, applied to its two
 * triangles; signed by the corner's quadrant). */
#include <math.h>

#include "check.h"
#include "lights/emitters/spherical_rectangle.h"
#include "radiometry/constants.h"
#include "base/rng.h"

static double corner(double x, double y, double h)
{
    long double X = x, Y = y, H = h;
    return (double)atanl(X * Y / (H * sqrtl(X * X + Y * Y + H * H)));
}

static double rect_solid_angle(double x0, double x1, double y0, double y1, double h)
{
    return corner(x1, y1, h) - corner(x0, y1, h) - corner(x1, y0, h) + corner(x0, y0, h);
}

/* Receiver p above the rect origin + s ex + t ey in a rotated frame. */
typedef struct setup {
    cdl_vec3 p, s0, ex, ey;
    double x0, x1, y0, y1, h; /* the same in the rect's own frame, receiver's foot at 0 */
} setup;

static setup make_setup(double x0, double x1, double y0, double y1, double h)
{
    /* A rotated frame: ex along a, ey along b, normal c. */
    cdl_vec3 a = cdl_vec3_normalize(cdl_vec3_make(0.6, 0.8, 0.0));
    cdl_vec3 c = cdl_vec3_normalize(cdl_vec3_make(0.1, -0.075, 1.0));
    a = cdl_vec3_normalize(cdl_vec3_madd(a, -cdl_vec3_dot(a, c), c));
    cdl_vec3 b = cdl_vec3_cross(c, a);
    setup s;
    s.p = cdl_vec3_make(2.0, -1.0, 0.5);
    cdl_vec3 foot = cdl_vec3_madd(s.p, -h, c);
    s.s0 = cdl_vec3_add(foot, cdl_vec3_add(cdl_vec3_scale(a, x0), cdl_vec3_scale(b, y0)));
    s.ex = cdl_vec3_scale(a, x1 - x0);
    s.ey = cdl_vec3_scale(b, y1 - y0);
    s.x0 = x0; s.x1 = x1; s.y0 = y0; s.y1 = y1; s.h = h;
    return s;
}

static void test_solid_angle(void)
{
    double cases[][5] = {{-1, 1, -0.6, 0.6, 2.0},   {0.2, 1.3, 0.1, 0.8, 0.9}, {-0.5, 0.5, -0.5, 0.5, 1e-3},
                         {3, 4, -2, 5, 0.3},         {-1, 1, -0.6, 0.6, 50.0},  {-2, -1, 0.5, 1.5, 1.0},
                         {-1, 1, -0.6, 0.6, 1e-9}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        setup s = make_setup(cases[k][0], cases[k][1], cases[k][2], cases[k][3], cases[k][4]);
        cdl_spherical_rectangle r;
        double S = cdl_spherical_rectangle_init(&r, s.p, s.s0, s.ex, s.ey);
        double want = rect_solid_angle(s.x0, s.x1, s.y0, s.y1, s.h);
        /* Girard's angle excess keeps ~15 digits absolutely (atan2 angles):
         * 1e-14 sr absolute plus 1e-12 relative. */
        CHECK_ABS(S, want, 1e-14 + 1e-12 * want);
        /* Seen from the other side the same rectangle subtends the same S. */
        cdl_vec3 mirror = cdl_vec3_madd(s.p, -2.0 * s.h, cdl_vec3_normalize(cdl_vec3_cross(s.ex, s.ey)));
        cdl_spherical_rectangle rm;
        CHECK_ABS(cdl_spherical_rectangle_init(&rm, mirror, s.s0, s.ex, s.ey), want, 1e-14 + 1e-12 * want);
    }
    /* Exactly in the plane (at a corner): nothing. */
    setup s = make_setup(-1, 1, -1, 1, 1.0);
    cdl_spherical_rectangle r;
    CHECK(cdl_spherical_rectangle_init(&r, s.s0, s.s0, s.ex, s.ey) == 0.0);
}

static void test_uniform_in_solid_angle(void)
{
    /* Near field, receiver over a corner region: area sampling would be
     * badly non-uniform here. 4 x 4 sub-rectangles; 160000 samples; each
     * bin's count is binomial with p = Omega_bin / S: 5 sigma. */
    double cases[][5] = {{-1, 1, -0.6, 0.6, 0.2}, {0.2, 1.3, -0.1, 0.8, 0.5}, {-1, 1, -0.6, 0.6, 5.0}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        setup s = make_setup(cases[c][0], cases[c][1], cases[c][2], cases[c][3], cases[c][4]);
        cdl_spherical_rectangle r;
        double S = cdl_spherical_rectangle_init(&r, s.p, s.s0, s.ex, s.ey);
        int counts[16] = {0}, N = 160000, off_plane = 0, outside = 0;
        cdl_rng_key key = {31, c};
        cdl_vec3 ux = cdl_vec3_normalize(s.ex), uy = cdl_vec3_normalize(s.ey);
        double lx = cdl_vec3_length(s.ex), ly = cdl_vec3_length(s.ey);
        cdl_vec3 nrm = cdl_vec3_cross(ux, uy);
        for (int i = 0; i < N; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)i, u);
            cdl_vec3 q = cdl_vec3_sub(cdl_vec3_add(s.p, cdl_spherical_rectangle_sample(&r, u[0], u[1])), s.s0);
            double a = cdl_vec3_dot(q, ux) / lx, b = cdl_vec3_dot(q, uy) / ly;
            if (fabs(cdl_vec3_dot(q, nrm)) > 1e-12) off_plane++;
            if (a < -1e-12 || a > 1 + 1e-12 || b < -1e-12 || b > 1 + 1e-12) outside++;
            int ia = (int)fmin(3, fmax(0, floor(4 * a))), ib = (int)fmin(3, fmax(0, floor(4 * b)));
            counts[ib * 4 + ia]++;
        }
        CHECK(off_plane == 0 && outside == 0);
        double dx = (s.x1 - s.x0) / 4, dy = (s.y1 - s.y0) / 4;
        for (int ib = 0; ib < 4; ++ib)
            for (int ia = 0; ia < 4; ++ia) {
                double pb = rect_solid_angle(s.x0 + ia * dx, s.x0 + (ia + 1) * dx, s.y0 + ib * dy, s.y0 + (ib + 1) * dy, s.h) / S;
                double mean = N * pb, sigma = sqrt(N * pb * (1 - pb));
                CHECK_MSG(fabs(counts[ib * 4 + ia] - mean) <= 5 * sigma, "case %zu bin (%d,%d): %d vs %.1f", c, ia, ib,
                          counts[ib * 4 + ia], mean);
            }
        /* Monotone in u and v: stratified inputs stay stratified. */
        double prev_a = -1;
        for (int i = 0; i <= 100; ++i) {
            cdl_vec3 q = cdl_vec3_sub(cdl_vec3_add(s.p, cdl_spherical_rectangle_sample(&r, i / 100.0, 0.5)), s.s0);
            double a = cdl_vec3_dot(q, ux);
            CHECK(a >= prev_a - 1e-12);
            prev_a = a;
        }
    }
}

int main(void)
{
    test_solid_angle();
    test_uniform_in_solid_angle();
    return check_finish();
}
