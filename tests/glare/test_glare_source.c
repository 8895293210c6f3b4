/* A luminaire seen from an eye (glare/glare_source.h): a Lambertian
 * opening's luminance I0 / A, the exact solid angle of rectangles, disks
 * and boxes against closed forms and quadrature, the observer's R, T, H,
 * the position index there and the rating of one source by hand. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "gauss_legendre.h"
#include "file_fixture.h"
#include "glare/glare_source.h"
#include "radiometry/constants.h"

/* I0 cos(gamma) below the horizontal every 0.5 degree on an opening given
 * by LM-63's width, length, height (m). */
static cdl_photometry *lambertian(const char *folder, const char *name, double I0, double w, double l, double h)
{
    char path[700];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    FILE *f = fopen(path, "w");
    if (!f) return NULL;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] lambertian\nTILT=NONE\n1 -1 1 181 1 1 2 %g %g %g\n1 1 0\n", w, l, h);
    for (int k = 0; k <= 180; ++k) fprintf(f, "%g\n", 0.5 * k);
    fprintf(f, "0\n");
    for (int k = 0; k <= 180; ++k) fprintf(f, "%.17g\n", I0 * cos(0.5 * k * CDL_DEG_TO_RAD));
    fclose(f);
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *p = NULL;
    cdl_error err;
    if (cdl_photometry_read_file(path, &ro, &p, &err) != CDL_OK) fprintf(stderr, "%s\n", err.message);
    return p;
}

/* Solid angle of the rectangle [0, x] x [0, y] in a plane at distance d,
 * seen from the point above its corner (odd in x and y), and of any
 * rectangle [x1, x2] x [y1, y2] (relative to the eye's foot on the plane)
 * by inclusion and exclusion. */
static double corner(double x, double y, double d)
{
    return atan(x * y / (d * sqrt(x * x + y * y + d * d)));
}
static double rect_omega(double x1, double x2, double y1, double y2, double d)
{
    return corner(x2, y2, d) - corner(x1, y2, d) - corner(x2, y1, d) + corner(x1, y1, d);
}

static cdl_glare_luminaire placed(const cdl_photometry *p, cdl_vec3 at)
{
    cdl_glare_luminaire l = {p, at, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1.0};
    return l;
}

static void test_rectangle(const char *folder)
{
    const double I0 = 1200.0, w = 0.3, len = 0.6; /* LM-63 width along C90 (y), length along C0 (x) */
    cdl_photometry *p = lambertian(folder, "rect.ies", I0, w, len, 0.0);
    CHECK(p != NULL);
    if (!p) return;
    /* eye at 1.2 m looking along +y; the opening at 3.0 m, R 3.6, T 1.8 to the right, H 1.8 */
    cdl_glare_observer eye = {{0.0, 0.0, 1.2}, {0.0, 1.0, 0.0}};
    cdl_glare_luminaire l = placed(p, cdl_vec3_make(1.8, 3.6, 3.0));
    cdl_glare_source s;
    cdl_glare_source_evaluate(&l, &eye, &s);
    /* looking along +y, +x is to the right */
    CHECK_ABS(s.R_m, 3.6, 1e-12);
    CHECK_ABS(s.T_m, 1.8, 1e-12);
    CHECK_ABS(s.H_m, 1.8, 1e-12);
    CHECK(s.zone == CDL_GLARE_IN_VIEW);
    /* T/R 0.5, H/R 0.5: 2.91 in Table 4.1 */
    CHECK_ABS(s.p, 2.91, 1e-12);
    /* the eye from the luminaire: (-1.8, -3.6, -1.8): gamma = atan(sqrt(1.8^2 + 3.6^2) / 1.8), C = atan2(-3.6, -1.8) */
    CHECK_ABS(s.gamma_deg, atan(hypot(1.8, 3.6) / 1.8) * CDL_RAD_TO_DEG, 1e-9);
    CHECK_ABS(s.c_deg, atan2(-3.6, -1.8) * CDL_RAD_TO_DEG + 360.0, 1e-9);
    /* Lambertian: L = I0 cos(gamma) / (A cos(gamma)) = I0 / A; the table's
     * 0.5-degree interpolation of the cosine is within 1e-5 of it */
    CHECK_REL(s.luminance.cd_m2, I0 / (w * len), 1e-5);
    CHECK_REL(s.projected_area_m2, w * len * cos(s.gamma_deg * CDL_DEG_TO_RAD), 1e-12);
    /* the rectangle [1.5, 2.1] x [3.45, 3.75] at 1.8 m above the eye */
    double omega = rect_omega(1.8 - 0.5 * len, 1.8 + 0.5 * len, 3.6 - 0.5 * w, 3.6 + 0.5 * w, 1.8);
    CHECK(s.omega_exact);
    /* two closed forms of the same solid angle: rounding only */
    CHECK_REL(s.omega_sr, omega, 1e-12);
    /* and not CIE 117's approximation A_p / r^2, which differs at this size */
    double r2 = 1.8 * 1.8 + 3.6 * 3.6 + 1.8 * 1.8;
    CHECK(fabs(s.omega_sr - s.projected_area_m2 / r2) > 1e-9 * omega);
    /* one source, by hand: UGR = 8 log10(0.25 / Lb L^2 omega / p^2), Lb 30 */
    double L = I0 / (w * len), expected = 8.0 * log10(0.25 / 30.0 * L * L * omega / (2.91 * 2.91));
    cdl_ugr_sum sum = {0.0, 0.0, 0};
    cdl_ugr_sum_add(&sum, s.term);
    cdl_ugr u;
    cdl_error err;
    CHECK_OK(cdl_ugr_evaluate(&sum, cdl_nits(30.0), 0.0, &u, &err), &err);
    /* L to 1e-5: 2e-5 on L^2, 8 / ln 10 of it on UGR */
    CHECK_ABS(u.value, expected, 1e-4);
    /* turned 90 degrees about its axis the rectangle lies the other way */
    cdl_glare_luminaire turned = {p, l.position, {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, 1.0};
    cdl_glare_source_evaluate(&turned, &eye, &s);
    CHECK_REL(s.omega_sr, rect_omega(1.8 - 0.5 * w, 1.8 + 0.5 * w, 3.6 - 0.5 * len, 3.6 + 0.5 * len, 1.8), 1e-12);
    /* scale (maintenance, multiplier) scales the luminance */
    l.scale = 0.8;
    cdl_glare_source_evaluate(&l, &eye, &s);
    CHECK_REL(s.luminance.cd_m2, 0.8 * I0 / (w * len), 1e-5);
    /* out of view: behind the eye, beyond T/R 3, steeply above: no term,
     * the luminance and solid angle still given */
    cdl_glare_luminaire behind = placed(p, cdl_vec3_make(0.5, -1.0, 3.0));
    cdl_glare_source_evaluate(&behind, &eye, &s);
    CHECK(s.zone == CDL_GLARE_BEHIND && s.term.value == 0.0 && s.omega_sr > 0.0 && s.luminance.cd_m2 > 0.0);
    cdl_glare_luminaire aside = placed(p, cdl_vec3_make(-10.0, 1.0, 3.0));
    cdl_glare_source_evaluate(&aside, &eye, &s);
    CHECK(s.zone == CDL_GLARE_BEYOND_T && s.term.value == 0.0);
    CHECK_ABS(s.T_m, -10.0, 1e-12);
    cdl_glare_luminaire above = placed(p, cdl_vec3_make(0.0, 0.5, 3.0));
    cdl_glare_source_evaluate(&above, &eye, &s);
    CHECK(s.zone == CDL_GLARE_ABOVE && s.term.value == 0.0);
    /* seen edge-on (the eye in the opening's plane): nothing */
    cdl_glare_luminaire level = placed(p, cdl_vec3_make(0.0, 4.0, 1.2));
    cdl_glare_source_evaluate(&level, &eye, &s);
    CHECK(s.projected_area_m2 == 0.0 && s.omega_sr == 0.0 && s.term.value == 0.0);
    cdl_photometry_release(p);
}

/* A disk of radius a: on its axis 2 pi (1 - d / sqrt(d^2 + a^2)); off its
 * axis the integral of cos(theta) / r^2 over it by polar Gauss-Legendre. */
static double disk_omega_quadrature(double a, double dx, double dy, double d)
{
    double sum = 0.0;
    const int nr = 16, nt = 64;
    for (int i = 0; i < nr; ++i)
        for (int gi = 0; gi < 8; ++gi)
            for (int j = 0; j < nt; ++j)
                for (int gj = 0; gj < 8; ++gj) {
                    double r = a * (i + gl8_x[gi]) / nr, t = CDL_TWO_PI * (j + gl8_x[gj]) / nt;
                    double px = r * cos(t) - dx, py = r * sin(t) - dy, q = px * px + py * py + d * d;
                    sum += gl8_w[gi] * gl8_w[gj] * (a / nr) * (CDL_TWO_PI / nt) * r * d / (q * sqrt(q));
                }
    return sum;
}

static void test_disk_box_sphere(const char *folder)
{
    /* a circle of diameter 0.4 (LM-63-2002: width = length, negative) */
    cdl_photometry *disk = lambertian(folder, "disk.ies", 800.0, -0.4, -0.4, 0.0);
    CHECK(disk != NULL);
    if (!disk) return;
    cdl_glare_observer eye = {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
    cdl_glare_source s;
    cdl_glare_luminaire below = placed(disk, cdl_vec3_make(0.0, 0.0, 1.5));
    cdl_glare_source_evaluate(&below, &eye, &s);
    /* the equal-area 256-gon: within 1e-6 of the circle's solid angle */
    CHECK_REL(s.omega_sr, CDL_TWO_PI * (1.0 - 1.5 / hypot(1.5, 0.2)), 1e-6);
    cdl_glare_luminaire ahead = placed(disk, cdl_vec3_make(0.3, 1.0, 0.5));
    cdl_glare_source_evaluate(&ahead, &eye, &s);
    /* the quadrature of a smooth integrand: 1e-9; the polygon: 1e-6 */
    CHECK_REL(s.omega_sr, disk_omega_quadrature(0.2, -0.3, -1.0, 0.5), 1e-6);
    CHECK(s.omega_exact);
    CHECK_REL(s.luminance.cd_m2, 800.0 / (CDL_PI * 0.04), 1e-5);
    cdl_photometry_release(disk);

    /* a box 0.6 (x, length) x 0.4 (y, width) x 0.2 high, every side luminous:
     * from (1, 2, -1) off its corner the eye sees the bottom, the +x side
     * and the +y side, each a rectangle in its own plane */
    cdl_photometry *bx = lambertian(folder, "box.ies", 500.0, 0.4, 0.6, 0.2);
    CHECK(bx != NULL);
    if (!bx) return;
    cdl_glare_observer e2 = {{1.0, 2.0, -1.0}, {-1.0, 0.0, 0.0}};
    cdl_glare_luminaire at0 = placed(bx, cdl_vec3_make(0.0, 0.0, 0.0));
    cdl_glare_source_evaluate(&at0, &e2, &s);
    double bottom = rect_omega(-0.3 - 1.0, 0.3 - 1.0, -0.2 - 2.0, 0.2 - 2.0, 1.0 - 0.1);
    double side_x = rect_omega(-0.2 - 2.0, 0.2 - 2.0, -0.1 + 1.0, 0.1 + 1.0, 1.0 - 0.3);
    double side_y = rect_omega(-0.3 - 1.0, 0.3 - 1.0, -0.1 + 1.0, 0.1 + 1.0, 2.0 - 0.2);
    CHECK(s.omega_exact);
    CHECK_REL(s.omega_sr, bottom + side_x + side_y, 1e-12);
    cdl_photometry_release(bx);

    /* a sphere of diameter 0.5: its cap; far away it tends to A / r^2 */
    cdl_photometry *sp = lambertian(folder, "sphere.ies", 300.0, -0.5, -0.5, -0.5);
    CHECK(sp != NULL);
    if (!sp) return;
    cdl_glare_luminaire far = placed(sp, cdl_vec3_make(0.0, 25.0, 0.0));
    cdl_glare_source_evaluate(&far, &eye, &s);
    /* (pi a^2 / d^2)(1 + a^2 / (4 d^2)) to order (a/d)^4: 1e-8 here */
    double a = 0.25, d = 25.0;
    CHECK_REL(s.omega_sr, CDL_PI * a * a / (d * d) * (1.0 + a * a / (4.0 * d * d)), 1e-8);
    cdl_photometry_release(sp);

    /* a vertical cylinder (LM-63-2002: -, -, +): CIE 117's A_p / r^2, said
     * so (omega_exact 0) */
    cdl_photometry *cyl = lambertian(folder, "cylinder.ies", 300.0, -0.2, -0.2, 0.3);
    CHECK(cyl != NULL);
    if (!cyl) return;
    cdl_glare_luminaire c = placed(cyl, cdl_vec3_make(0.5, 4.0, 2.0));
    cdl_glare_source_evaluate(&c, &eye, &s);
    double r2 = 0.25 + 16.0 + 4.0;
    CHECK(!s.omega_exact);
    /* the disk of area A_p facing the eye (radius rho) subtends A_p / r^2
     * (1 - 3/4 (rho / r)^2 + ...): 7e-4 below it here */
    CHECK_REL(s.omega_sr, s.projected_area_m2 / r2, 1e-3);
    cdl_photometry_release(cyl);
}

int main(void)
{
    char folder[512];
    CHECK(fixture_folder("glare_source", folder, sizeof folder));
    test_rectangle(folder);
    test_disk_box_sphere(folder);
    return check_finish();
}
