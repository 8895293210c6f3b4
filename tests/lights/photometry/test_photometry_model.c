/* The photometric model: construction, interpolation, symmetry expansion,
 * wrap-around, and flux against closed forms. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_internal.h"
#include "radiometry/constants.h"

/* gamma = 0, step, ..., last */
static size_t fill_angles(double *a, double first, double last, double step)
{
    size_t n = 0;
    for (double x = first; x <= last + 1e-9; x += step) a[n++] = x;
    a[n - 1] = last;
    return n;
}

static void test_isotropic(void)
{
    /* A constant 1000 cd in every direction: Phi = 4 pi I = 4000 pi lm.
     * The interpolant of a constant is that constant, so the only error is
     * floating-point summation over 37 angles: 1e-12 is generous. */
    double g[37], cd[37];
    size_t ng = fill_angles(g, 0.0, 180.0, 5.0);
    for (size_t j = 0; j < ng; ++j) cd[j] = 1000.0;
    double c = 0.0;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(&c, 1, g, ng, cd, &p, &err), &err);
    if (!p) return;
    CHECK_REL(cdl_photometry_flux(p).lm, 4000.0 * CDL_PI, 1e-12);
    CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0.3, -0.2, 0.5)).cd, 1000.0, 1e-12);
    CHECK_REL(cdl_photometry_max_intensity(p).cd, 1000.0, 0.0);
    /* each hemisphere holds half */
    CHECK_REL(cdl_photometry_zone_flux(p, 0.0, 90.0).lm, 2000.0 * CDL_PI, 1e-12);
    /* a 10-degree zone: 2 pi I (cos 20 - cos 30) */
    CHECK_REL(cdl_photometry_zone_flux(p, 20.0, 30.0).lm,
              2.0 * CDL_PI * 1000.0 * (cos(20.0 * CDL_DEG_TO_RAD) - cos(30.0 * CDL_DEG_TO_RAD)), 1e-12);
    CHECK(cdl_photometry_output_factor(p) == 1.0);
    CHECK(cdl_photometry_tilt_factor(p, 30.0) == 1.0);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL && t.horizontal_count == 1 && t.vertical_count == 37);
    cdl_photometry_release(p);
}

static void test_cosine(void)
{
    /* I0 cos(gamma) in the lower hemisphere: Phi = pi I0. The table samples
     * cos at 0.5 degree steps; the linear interpolant of cos lies below it by
     * at most h^2/8 (h = 0.5 deg = 8.7e-3 rad), so the relative flux error is
     * below 1e-5: tolerance 2e-5. */
    const double i0 = 2500.0;
    static double g[181], cd[181];
    size_t ng = fill_angles(g, 0.0, 90.0, 0.5);
    for (size_t j = 0; j < ng; ++j) cd[j] = i0 * cos(g[j] * CDL_DEG_TO_RAD);
    double c = 0.0;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(&c, 1, g, ng, cd, &p, &err), &err);
    if (!p) return;
    CHECK_REL(cdl_photometry_flux(p).lm, CDL_PI * i0, 2e-5);
    CHECK_ABS(cdl_photometry_zone_flux(p, 90.0, 180.0).lm, 0.0, 1e-9);
    /* nothing above the measured range */
    CHECK(cdl_photometry_intensity_c_gamma(p, 0.0, 120.0).cd == 0.0);
    cdl_photometry_release(p);
}

static void test_cone(void)
{
    /* Constant I0 inside a cone of half-angle tau, nothing outside: the
     * table ends at tau (zero beyond the measured range), so the
     * interpolant is exactly the cone: Phi = 2 pi I0 (1 - cos tau), to
     * round-off. */
    const double i0 = 800.0, tau = 35.0;
    double g[8], cd[8];
    size_t ng = fill_angles(g, 0.0, tau, 5.0);
    for (size_t j = 0; j < ng; ++j) cd[j] = i0;
    double c[3] = {0.0, 45.0, 90.0}, cd3[3 * 8];
    for (size_t i = 0; i < 3; ++i) memcpy(cd3 + i * ng, cd, ng * sizeof *cd);
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(c, 3, g, ng, cd3, &p, &err), &err);
    if (!p) return;
    CHECK_REL(cdl_photometry_flux(p).lm, 2.0 * CDL_PI * i0 * (1.0 - cos(tau * CDL_DEG_TO_RAD)), 1e-12);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_QUADRANT);
    cdl_photometry_release(p);
}

/* A table whose value encodes the plane: I(C, gamma) = 100 + C + gamma/10. */
static cdl_photometry *plane_table(const double *c, size_t nc)
{
    double g[3] = {0.0, 90.0, 180.0}, cd[64 * 3];
    for (size_t i = 0; i < nc; ++i)
        for (size_t j = 0; j < 3; ++j) cd[i * 3 + j] = 100.0 + c[i] + g[j] / 10.0;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(c, nc, g, 3, cd, &p, &err), &err);
    return p;
}

static double at(const cdl_photometry *p, double c, double g) { return cdl_photometry_intensity_c_gamma(p, c, g).cd; }

static void test_symmetry_and_wrap(void)
{
    /* Quadrant (0..90): I(C) = I(360 - C) = I(180 - C). */
    double cq[4] = {0.0, 30.0, 60.0, 90.0};
    cdl_photometry *q = plane_table(cq, 4);
    if (q) {
        CHECK_REL(at(q, 30.0, 90.0), 139.0, 1e-12);
        CHECK_REL(at(q, 150.0, 90.0), 139.0, 1e-12);
        CHECK_REL(at(q, 210.0, 90.0), 139.0, 1e-12);
        CHECK_REL(at(q, 330.0, 90.0), 139.0, 1e-12);
        CHECK_REL(at(q, -30.0, 90.0), 139.0, 1e-12);
        /* linear between planes 30 and 60, mirrored from 315 = 45 */
        CHECK_REL(at(q, 315.0, 90.0), 154.0, 1e-12);
        cdl_photometry_release(q);
    }
    /* Bilateral about C90-C270 (planes 90..270): I(C) = I(180 - C). */
    double cb[3] = {90.0, 180.0, 270.0};
    cdl_photometry *b = plane_table(cb, 3);
    if (b) {
        cdl_photometry_table t;
        cdl_photometry_get_table(b, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270);
        CHECK_REL(at(b, 0.0, 0.0), at(b, 180.0, 0.0), 1e-12);
        CHECK_REL(at(b, 45.0, 0.0), at(b, 135.0, 0.0), 1e-12);
        CHECK_REL(at(b, 315.0, 0.0), at(b, 225.0, 0.0), 1e-12);
        cdl_photometry_release(b);
    }
    /* Full circle without the closing plane (0..350): 355 lies halfway
     * between the 350 plane and the 0 plane. */
    double cf[36];
    for (size_t i = 0; i < 36; ++i) cf[i] = 10.0 * (double)i;
    cdl_photometry *f = plane_table(cf, 36);
    if (f) {
        CHECK_REL(at(f, 355.0, 90.0), 0.5 * ((100.0 + 350.0 + 9.0) + (100.0 + 0.0 + 9.0)), 1e-12);
        CHECK_REL(at(f, 5.0, 90.0), 114.0, 1e-12);
        /* direction (0, 1, 0) is C = 90, gamma = 90 in the frame */
        CHECK_REL(cdl_photometry_intensity(f, cdl_vec3_make(0.0, 2.0, 0.0)).cd, 199.0, 1e-12);
        /* nadir and zenith */
        CHECK_REL(cdl_photometry_intensity(f, cdl_vec3_make(0.0, 0.0, -1.0)).cd, 100.0, 1e-12);
        CHECK_REL(cdl_photometry_intensity(f, cdl_vec3_make(0.0, 0.0, 1.0)).cd, 118.0, 1e-12);
        CHECK(cdl_photometry_intensity(f, cdl_vec3_make(0.0, 0.0, 0.0)).cd == 0.0);
        cdl_photometry_release(f);
    }
    /* 0..360 with a closing plane equal to the first: no warning, 360 dropped. */
    double cc[5] = {0.0, 90.0, 180.0, 270.0, 360.0};
    double g[2] = {0.0, 180.0}, cd[10] = {1, 2, 3, 4, 5, 6, 7, 8, 1, 2};
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(cc, 5, g, 2, cd, &p, &err), &err);
    if (p) {
        cdl_photometry_table t;
        cdl_photometry_get_table(p, &t);
        CHECK(t.horizontal_count == 4);
        CHECK(cdl_photometry_warning_count(p) == 0);
        CHECK_REL(at(p, 315.0, 0.0), 4.0, 1e-12);
        cdl_photometry_release(p);
    }
    /* ... and a differing one: warned, the 0 row wins. */
    cd[8] = 9.0;
    CHECK_OK(cdl_photometry_create_type_c(cc, 5, g, 2, cd, &p, &err), &err);
    if (p) {
        CHECK(cdl_photometry_warning_count(p) == 1);
        CHECK_REL(at(p, 359.999999, 0.0), 1.0, 1e-6);
        cdl_photometry_release(p);
    }
}

static void test_bad_tables(void)
{
    cdl_photometry *p = NULL;
    cdl_error err;
    double c2[2] = {0.0, 90.0}, g[3] = {0.0, 45.0, 90.0}, cd[6] = {1, 2, 3, 4, 5, 6};
    double gbad[3] = {0.0, 45.0, 45.0};
    CHECK(cdl_photometry_create_type_c(c2, 2, gbad, 3, cd, &p, &err) == CDL_ERR_INPUT && !p);
    CHECK_MSG(strstr(err.message, "increasing") != NULL, "%s", err.message);
    double cdneg[6] = {1, 2, 3, 4, -5, 6};
    CHECK(cdl_photometry_create_type_c(c2, 2, g, 3, cdneg, &p, &err) == CDL_ERR_INPUT && !p);
    CHECK_MSG(strstr(err.message, "-5") != NULL, "%s", err.message);
    double cdnan[6] = {1, 2, NAN, 4, 5, 6};
    CHECK(cdl_photometry_create_type_c(c2, 2, g, 3, cdnan, &p, &err) == CDL_ERR_INPUT && !p);
    double gout[3] = {0.0, 90.0, 190.0};
    CHECK(cdl_photometry_create_type_c(c2, 2, gout, 3, cd, &p, &err) == CDL_ERR_INPUT && !p);
    CHECK(cdl_photometry_create_type_c(c2, 2, g, 1, cd, &p, &err) == CDL_ERR_INPUT && !p);
}

/* Type B and type A tables of I0 cos(alpha), alpha the angle to the beam
 * axis, integrate like the type C table of I0 cos(gamma): pi I0. In B and A
 * coordinates cos(alpha) = cos V cos H, a product, so the bilinear
 * interpolant is the product of two 1-D linear interpolants of cos; with
 * 1-degree steps each lies within h^2/8 = 3.8e-5 of cos, tolerance 1e-4. */
static void test_types_a_b(void)
{
    const double i0 = 1000.0;
    static double hv[181], cd[181 * 181];
    size_t n = fill_angles(hv, -90.0, 90.0, 1.0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) cd[i * n + j] = i0 * cos(hv[i] * CDL_DEG_TO_RAD) * cos(hv[j] * CDL_DEG_TO_RAD);
    cdl_error err;
    for (int type = CDL_PHOTOMETRIC_TYPE_B; type <= CDL_PHOTOMETRIC_TYPE_A; ++type) {
        cdl_photometry *p = NULL;
        CHECK_OK(cdl_photometry_create((cdl_photometric_type)type, hv, n, hv, n, cd, &p, &err), &err);
        if (!p) continue;
        CHECK_REL(cdl_photometry_flux(p).lm, CDL_PI * i0, 1e-4);
        /* the beam axis is the frame's nadir */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, 0, -1)).cd, i0, 1e-12);
        /* the distribution is cos(alpha) about -z whatever the type: compare off-axis */
        cdl_vec3 d = cdl_vec3_normalize(cdl_vec3_make(0.3, -0.4, -0.8));
        CHECK_REL(cdl_photometry_intensity(p, d).cd, i0 * -d.z, 2e-4);
        /* everything is in the lower hemisphere */
        CHECK_REL(cdl_photometry_zone_flux(p, 0.0, 90.0).lm, cdl_photometry_flux(p).lm, 1e-12);
        /* zones by quadrature add up to the exact total (quadrature 1e-4) */
        double zones = 0.0;
        for (int z = 0; z < 18; ++z) zones += cdl_photometry_zone_flux(p, 10.0 * z, 10.0 * z + 10.0).lm;
        CHECK_REL(zones, cdl_photometry_flux(p).lm, 1e-4);
        /* a 0..30 zone: closed form pi I0 sin^2(30) within interpolation and quadrature error */
        CHECK_REL(cdl_photometry_zone_flux(p, 0.0, 30.0).lm, CDL_PI * i0 * 0.25, 2e-4);
        cdl_photometry_release(p);
    }
    /* Laterally symmetric half set (H 0..90) integrates like the full one. */
    size_t nh = 91;
    const double *hhalf = hv + 90;
    cdl_photometry *full = NULL, *half = NULL;
    CHECK_OK(cdl_photometry_create(CDL_PHOTOMETRIC_TYPE_B, hv, n, hv, n, cd, &full, &err), &err);
    CHECK_OK(cdl_photometry_create(CDL_PHOTOMETRIC_TYPE_B, hhalf, nh, hv, n, cd + 90 * n, &half, &err), &err);
    if (full && half) {
        cdl_photometry_table t;
        cdl_photometry_get_table(half, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_LATERAL);
        CHECK_REL(cdl_photometry_flux(half).lm, cdl_photometry_flux(full).lm, 1e-12);
        cdl_vec3 d = cdl_vec3_normalize(cdl_vec3_make(0.2, 0.5, -0.7));
        CHECK_REL(cdl_photometry_intensity(half, d).cd, cdl_photometry_intensity(full, d).cd, 1e-12);
    }
    cdl_photometry_release(full);
    cdl_photometry_release(half);
}

/* The direction of every table node maps back to that node's value, for
 * all three types (a table with distinct values everywhere). */
static void test_direction_roundtrip(void)
{
    double h[5] = {-60.0, -20.0, 0.0, 35.0, 80.0}, v[4] = {-70.0, -10.0, 25.0, 85.0}, cd[20];
    for (size_t k = 0; k < 20; ++k) cd[k] = 10.0 + (double)k;
    cdl_error err;
    for (int type = CDL_PHOTOMETRIC_TYPE_B; type <= CDL_PHOTOMETRIC_TYPE_A; ++type) {
        cdl_photometry *p = NULL;
        CHECK_OK(cdl_photometry_create((cdl_photometric_type)type, h, 5, v, 4, cd, &p, &err), &err);
        if (!p) continue;
        for (size_t i = 0; i < 5; ++i)
            for (size_t j = 0; j < 4; ++j) {
                cdl_vec3 d = cdl_photometry_direction((cdl_photometric_type)type, h[i], v[j]);
                CHECK_REL(cdl_photometry_intensity(p, d).cd, cd[i * 4 + j], 1e-9);
            }
        cdl_photometry_release(p);
    }
    double c[4] = {0.0, 100.0, 200.0, 300.0}, g[3] = {10.0, 50.0, 170.0}, cdc[12];
    for (size_t k = 0; k < 12; ++k) cdc[k] = 5.0 + (double)k;
    cdl_photometry *p = NULL;
    CHECK_OK(cdl_photometry_create_type_c(c, 4, g, 3, cdc, &p, &err), &err);
    if (p) {
        for (size_t i = 0; i < 4; ++i)
            for (size_t j = 0; j < 3; ++j) {
                cdl_vec3 d = cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, c[i], g[j]);
                CHECK_REL(cdl_photometry_intensity(p, d).cd, cdc[i * 3 + j], 1e-9);
            }
        /* below the first measured gamma: zero */
        CHECK(at(p, 0.0, 5.0) == 0.0);
        cdl_photometry_release(p);
    }
}

/* Tilt factors interpolate linearly in the TILT table and clamp at its ends. */
static void test_tilt(void)
{
    double g[2] = {0.0, 90.0}, cd[2] = {10.0, 5.0}, c = 0.0;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(&c, 1, g, 2, cd, &p, &err), &err);
    if (!p) return;
    double a[4] = {0.0, 45.0, 90.0, 180.0}, f[4] = {1.0, 0.9, 0.8, 1.0};
    CHECK_OK(cdl_photometry_set_tilt(p, 1, a, f, 4, &err), &err);
    CHECK_REL(cdl_photometry_tilt_factor(p, 0.0), 1.0, 1e-15);
    CHECK_REL(cdl_photometry_tilt_factor(p, 22.5), 0.95, 1e-15);
    CHECK_REL(cdl_photometry_tilt_factor(p, 135.0), 0.9, 1e-15);
    CHECK_REL(cdl_photometry_tilt_factor(p, -10.0), 1.0, 1e-15);
    CHECK_REL(cdl_photometry_tilt_factor(p, 200.0), 1.0, 1e-15);
    /* the tilt never touches the table or its flux */
    CHECK_REL(cdl_photometry_intensity_c_gamma(p, 0.0, 0.0).cd, 10.0, 1e-15);
    cdl_photometry_release(p);
}

int main(void)
{
    test_tilt();
    test_isotropic();
    test_cosine();
    test_cone();
    test_symmetry_and_wrap();
    test_bad_tables();
    test_types_a_b();
    test_direction_roundtrip();
    return check_finish();
}
