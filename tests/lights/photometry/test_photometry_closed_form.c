/* Closed forms through the file readers: IES and EULUMDAT tables of known
 * distributions, written as text here, integrate to their closed-form
 * flux, and the same distribution written as type A, B and C integrates
 * alike and gives the same intensity in every direction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry_checks.h"
#include "radiometry/constants.h"

/* An IES file: nh horizontal x nv vertical angles, value = f(h, v). */
static char *ies_text(int type, const double *h, int nh, const double *v, int nv, double (*f)(double, double))
{
    size_t cap = 4u << 20, n = 0;
    char *t = malloc(cap);
#define OUT(...) n += (size_t)snprintf(t + n, cap - n, __VA_ARGS__)
    OUT("IESNA:LM-63-2002\n[TEST] closed form\nTILT=NONE\n1 -1 1 %d %d %d 2 0 0 0\n1 1 0\n", nv, nh, type);
    for (int j = 0; j < nv; ++j) OUT("%.17g%s", v[j], (j + 1) % 10 ? " " : "\n");
    OUT("\n");
    for (int i = 0; i < nh; ++i) OUT("%.17g%s", h[i], (i + 1) % 10 ? " " : "\n");
    OUT("\n");
    for (int i = 0; i < nh; ++i) {
        for (int j = 0; j < nv; ++j) OUT("%.17g%s", f(h[i], v[j]), (j + 1) % 10 ? " " : "\n");
        OUT("\n");
    }
#undef OUT
    return t;
}

static int steps(double *a, double first, double last, double step)
{
    int n = 0;
    for (double x = first; x <= last + 1e-9; x += step) a[n++] = x;
    a[n - 1] = last;
    return n;
}

static double d2r(double x) { return x * CDL_DEG_TO_RAD; }
static const double I0 = 1500.0;

/* I0 cos(alpha), alpha the angle to the beam axis (-z), in each type's angles */
static double cos_c(double c, double g) { return (void)c, I0 * cos(d2r(g)); }
static double cos_ab(double h, double v) { return I0 * cos(d2r(h)) * cos(d2r(v)); }
static double iso(double h, double v) { return (void)h, (void)v, 1000.0; }
static double cone(double h, double v) { return (void)h, (void)v, I0; }

static cdl_photometry *read(const char *text, cdl_error *err)
{
    cdl_photometry *p = pc_read_text("closed.ies", text, strlen(text), 1, err);
    CHECK_MSG(p != NULL, "%s", err->message);
    return p;
}

static void test_isotropic_and_cone(void)
{
    static double g[181], c[37];
    int ng = steps(g, 0.0, 180.0, 5.0), nc = steps(c, 0.0, 360.0, 10.0);
    cdl_error err;
    /* a full 0..360 table of 1000 cd: 4000 pi lm (round-off only) */
    char *t = ies_text(1, c, nc, g, ng, iso);
    cdl_photometry *p = read(t, &err);
    if (p) CHECK_REL(cdl_photometry_flux(p).lm, 4000.0 * CDL_PI, 1e-12);
    cdl_photometry_release(p);
    free(t);
    /* a cone of constant I0 out to tau = 30 deg, nothing beyond: EULUMDAT
     * allows the partial gamma range. 2 pi I0 (1 - cos tau), round-off only */
    char ldt[4096];
    size_t n = (size_t)snprintf(ldt, sizeof ldt,
                                "cone\n1\n1\n1\n0\n7\n5\nr\nn\nn\nf\nd\n0\n0\n0\n0\n0\n0\n0\n0\n0\n100\n100\n1\n0\n1\n1\n"
                                "L\n1000\nc\nr\n1\n0\n0\n0\n0\n0\n0\n0\n0\n0\n0\n0\n");
    for (int j = 0; j <= 6; ++j) n += (size_t)snprintf(ldt + n, sizeof ldt - n, "%d\n", 5 * j);
    for (int j = 0; j <= 6; ++j) n += (size_t)snprintf(ldt + n, sizeof ldt - n, "%g\n", I0);
    p = pc_read_text("cone.ldt", ldt, n, 0, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) CHECK_REL(cdl_photometry_flux(p).lm, 2.0 * CDL_PI * I0 * (1.0 - cos(d2r(30.0))), 1e-12);
    cdl_photometry_release(p);
}

/* The same I0 cos(alpha) as type C (gamma 0..90), type B and type A
 * (H, V in -90..90): each flux is pi I0 within its interpolation error
 * (1 degree steps: the linear interpolant of cos lies within h^2/8 = 3.8e-5
 * of it, twice for the products of types A/B: tolerance 1e-4), and the
 * three agree direction by direction within the same error. */
static void test_types_agree(void)
{
    static double g[91], hv[181];
    int ng = steps(g, 0.0, 90.0, 1.0), nhv = steps(hv, -90.0, 90.0, 1.0);
    double zero = 0.0;
    cdl_error err;
    char *tc = ies_text(1, &zero, 1, g, ng, cos_c);
    char *tb = ies_text(2, hv, nhv, hv, nhv, cos_ab);
    char *ta = ies_text(3, hv, nhv, hv, nhv, cos_ab);
    cdl_photometry *c = read(tc, &err), *b = read(tb, &err), *a = read(ta, &err);
    if (a && b && c) {
        CHECK_REL(cdl_photometry_flux(c).lm, CDL_PI * I0, 1e-4);
        CHECK_REL(cdl_photometry_flux(b).lm, CDL_PI * I0, 1e-4);
        CHECK_REL(cdl_photometry_flux(a).lm, CDL_PI * I0, 1e-4);
        CHECK_REL(cdl_photometry_flux(a).lm, cdl_photometry_flux(b).lm, 1e-12); /* the same table, transposed roles */
        /* both hemispheres: all of it below the horizon */
        CHECK_REL(cdl_photometry_zone_flux(b, 0.0, 90.0).lm, cdl_photometry_flux(b).lm, 1e-12);
        double worst = fmax(pc_max_difference(c, b), pc_max_difference(c, a));
        CHECK_MSG(worst < 2e-4 * I0, "types disagree by %g cd", worst);
    }
    cdl_photometry_release(a);
    cdl_photometry_release(b);
    cdl_photometry_release(c);
    free(ta);
    free(tb);
    free(tc);
    /* a laterally symmetric type B half (H 0..90) is the full set */
    static double half[91];
    int nhalf = steps(half, 0.0, 90.0, 1.0);
    char *th = ies_text(2, half, nhalf, hv, nhv, cos_ab);
    cdl_photometry *h = read(th, &err);
    if (h) CHECK_REL(cdl_photometry_flux(h).lm, CDL_PI * I0, 1e-4);
    cdl_photometry_release(h);
    free(th);
    /* constant I0 over the front hemisphere as type B and type A: 2 pi I0
     * exactly (the interpolant of a constant is that constant; the cos
     * latitude weight is integrated in closed form) */
    for (int type = 2; type <= 3; ++type) {
        char *tf = ies_text(type, hv, nhv, hv, nhv, cone);
        cdl_photometry *f = read(tf, &err);
        if (f) {
            CHECK_REL(cdl_photometry_flux(f).lm, 2.0 * CDL_PI * I0, 1e-12);
            CHECK(cdl_photometry_intensity(f, cdl_vec3_make(0.0, 0.0, 1.0)).cd == 0.0); /* behind: nothing */
        }
        cdl_photometry_release(f);
        free(tf);
    }
}

/* Quadrant table: I0 cos(gamma) in the H0 (frame C0) plane, I0 cos^2(gamma) in the
 * H90 plane (frame C270, the same as C90 by symmetry), blended by C in between. */
static double cos_cos2(double h, double v)
{
    double s = sin(d2r(h)), c = cos(d2r(v));
    return I0 * ((1.0 - s * s) * c + s * s * c * c);
}

/* I0 max(0, d . a), a tilted 30 degrees from nadir toward C0: d . a =
 * sin(gamma) cos(C) sin 30 + cos(gamma) cos 30, and cos C = cos H. */
static double tilted(double h, double v)
{
    double x = sin(d2r(v)) * cos(d2r(h)) * 0.5 + cos(d2r(v)) * cos(d2r(30.0));
    return x > 0.0 ? I0 * x : 0.0;
}

/* Beam (50 %) and field (10 %) angles against closed forms, each plane on
 * its own. Tables step 0.5 degree in gamma; the linear interpolant of a
 * smooth f lies within h^2/8 max|f''| of it (h = 8.7e-3 rad: 9.5e-6 I0 for
 * cos, 1.9e-5 I0 for cos^2), which moves a crossing by that over the slope
 * there (at least 0.7 I0 per radian at every crossing below): under 3e-5 rad
 * = 0.0016 degree per side. Tolerance 0.005 degree on the full angle. */
/* The summary of a type C table of f (H every dh up to h_last, gamma every
 * 0.5 degree up to g_last) read through the IES reader; 0 if it did not read. */
static int summary_of(double h_last, double dh, double g_last, double (*f)(double, double),
                      cdl_photometry_summary *s, double *spread_c90_half)
{
    static double g[361], c[25];
    int ng = steps(g, 0.0, g_last, 0.5), nc = steps(c, 0.0, h_last, dh);
    cdl_error err;
    char *t = ies_text(1, c, nc, g, ng, f);
    cdl_photometry *p = read(t, &err);
    if (p) {
        cdl_photometry_summarize(p, s);
        *spread_c90_half = cdl_photometry_spread_angle(p, CDL_PLANE_C90_C270, 0.5);
    }
    cdl_photometry_release(p);
    free(t);
    return p != NULL;
}

/* A batwing, rotationally symmetric: I0 (0.3 + 0.7 sin^2(2 gamma)) up to
 * 90 degrees, peak at gamma 45 with 0.3 I0 at nadir (test_spreads_about_peak). */
static double batwing(double h, double v)
{
    (void)h;
    double s2 = sin(2.0 * d2r(v));
    return v <= 90.0 ? I0 * (0.3 + 0.7 * s2 * s2) : 0.0;
}

/* Wide and flat: I0 (0.2 + 0.8 (1 + cos gamma) / 2) falls to half only at
 * cos gamma = -0.25 (104.5 degrees from nadir): a 209 degree "beam", more
 * than a half-space, so none. */
static double wide(double h, double v)
{
    (void)h;
    return I0 * (0.2 + 0.4 * (1.0 + cos(d2r(v))));
}

/* Beam (50 %) and field (10 %) angles against closed forms, each plane on
 * its own. Tables step 0.5 degree in gamma; the linear interpolant of a
 * smooth f lies within h^2/8 max|f''| of it (h = 8.7e-3 rad: 9.5e-6 I0 for
 * cos, 1.9e-5 I0 for cos^2), which moves a crossing by that over the slope
 * there (at least 0.7 I0 per radian at every crossing below): under 3e-5 rad
 * = 0.0016 degree per side. Tolerance 0.005 degree on the full angle. */
static void test_beam_and_field(void)
{
    cdl_photometry_summary s = CDL_PHOTOMETRY_SUMMARY_INIT;
    double half90;
    if (summary_of(90.0, 15.0, 90.0, cos_cos2, &s, &half90)) {
        /* C0-C180: cos gamma = 0.5 at 60, = 0.1 at acos 0.1 on either side of nadir */
        CHECK_ABS(s.beam_angle_deg[CDL_PLANE_C0_C180], 120.0, 0.005);
        CHECK_ABS(s.field_angle_deg[CDL_PLANE_C0_C180], 2.0 * acos(0.1) * CDL_RAD_TO_DEG, 0.005);
        /* C90-C270: cos^2 gamma = 0.5 at 45, = 0.1 at acos(sqrt 0.1) */
        CHECK_ABS(s.beam_angle_deg[CDL_PLANE_C90_C270], 90.0, 0.005);
        CHECK_ABS(s.field_angle_deg[CDL_PLANE_C90_C270], 2.0 * acos(sqrt(0.1)) * CDL_RAD_TO_DEG, 0.005);
        CHECK_ABS(half90, 90.0, 0.005);
        /* the maximum: I0 at nadir, so the planes through nadir */
        CHECK_REL(s.max_intensity.cd, I0, 1e-15);
        CHECK(s.max_gamma_deg == 0.0 && s.spread_about_peak == 0);
    }
    /* An off-axis beam: I0 cos(theta - 30) in the C0-C180 plane (theta from
     * nadir, positive toward C0), peak at C0, gamma 30, nadir at cos 30 =
     * 0.87 of it: measured about the peak. In the vertical plane through
     * the peak (the C0-C180 plane) half of it at theta = -30 and 90: a 120
     * degree beam that crosses nadir into the C180 half; the field spans
     * 30 +- acos 0.1. Across the peak, I = I0 cos(angle from the peak):
     * 120 degrees again; that circle cuts the 15 degree C planes between
     * their samples, where the linear interpolant of cos C lies within
     * h^2/8 = 0.0086 of it (h = 0.26 rad), which moves each crossing (slope
     * 0.87 I0 per radian) by up to 0.57 degree; measured 0.025 per side:
     * tolerance 0.1 degree on the full angle. */
    if (summary_of(360.0, 15.0, 180.0, tilted, &s, &half90)) {
        CHECK(s.spread_about_peak == 1 && s.spread_axis_c_deg == 0.0 && s.spread_axis_gamma_deg == 30.0);
        CHECK_ABS(s.beam_angle_deg[0], 120.0, 0.005);
        CHECK_ABS(s.field_angle_deg[0], 2.0 * acos(0.1) * CDL_RAD_TO_DEG, 0.005);
        CHECK_ABS(s.beam_angle_deg[1], 120.0, 0.1);
        CHECK(s.max_c_deg == 0.0 && s.max_gamma_deg == 30.0);
        CHECK_REL(s.max_intensity.cd, I0, 1e-15);
        /* the flux of a clipped cosine lobe is pi I0 whatever its tilt: the trapezoid rule
         * in C integrates cos C exactly over the circle, and in gamma the 0.5 degree
         * interpolation (and the clipped kink) leave under 1e-5 */
        CHECK_REL(s.flux.lm, CDL_PI * I0, 2e-5);
    }
}

/* A rotationally symmetric batwing: measured in the planes through nadir,
 * the same in both; a beam wider than 180 degrees: none. */
static void test_spreads_about_peak(void)
{
    cdl_photometry_summary s = CDL_PHOTOMETRY_SUMMARY_INIT;
    double half90;
    if (summary_of(0.0, 15.0, 90.0, batwing, &s, &half90)) {
        CHECK(s.spread_about_peak == 0);
        /* Walking from the peak at 45 degrees the half level 0.5 I0 comes
         * where sin^2(2 g) = 2/7, g = asin(sqrt(2/7)) / 2 and 90 - that,
         * before nadir (0.3 I0): one lobe, beam = 90 - asin(sqrt(2/7))
         * degrees, in either plane. Gamma steps of 0.5 degree: the
         * interpolant of the smooth f lies within h^2/8 max|f''| = 2.7e-5
         * I0 (f'' <= 2.8 I0 per rad^2), over a slope of at least 1.3 I0 per
         * radian at the crossings: 1.2e-3 degree each side. */
        double beam = 90.0 - asin(sqrt(2.0 / 7.0)) * CDL_RAD_TO_DEG;
        CHECK_ABS(s.beam_angle_deg[0], beam, 0.005);
        CHECK_ABS(s.beam_angle_deg[1], beam, 0.005);
    }
    if (summary_of(0.0, 15.0, 180.0, wide, &s, &half90)) {
        CHECK(s.spread_about_peak == 0);
        CHECK(s.beam_angle_deg[0] == -1.0 && s.beam_angle_deg[1] == -1.0);
        /* the field (10 %) never closes at all: 0.2 I0 everywhere at least */
        CHECK(s.field_angle_deg[0] == -1.0);
    }
}

int main(void)
{
    test_isotropic_and_cone();
    test_types_agree();
    test_beam_and_field();
    test_spreads_about_peak();
    return check_finish();
}
