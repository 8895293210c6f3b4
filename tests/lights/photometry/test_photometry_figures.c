/* Figures for lighting design against independent computations:
 *  - direct ratios (lights/photometry/direct_ratios.c) of a Lambertian
 *    table against the configuration factor between the square of
 *    luminaires and the work plane, two parallel coaxial squares (the
 *    closed form for parallel rectangles, itself checked here against
 *    Hottel's formula for directly opposed ones), and of a table of equal
 *    intensity in every downward direction against the closed-form solid
 *    angle of the work plane averaged over the luminaires' square by
 *    Gauss-Legendre quadrature;
 *  - direct ratios and TM-15-11 zones of spots narrower than the
 *    quadrature's step (0.3 and 0.01 degree cones at nadir): all of the
 *    flux lands on the work plane (DR = 1: every direction within 26.6
 *    degrees of nadir does, for every room index) and in the FL and BL
 *    zones, half each;
 *  - the CIE flux code and the 10 degree zones of type A and B spots
 *    narrower than a degree (0.3 and 0.7 degrees about nadir): all of the
 *    downward flux lies within 41.4 degrees (N1 = N2 = N3 = 100 %) and in
 *    the first zone;
 *  - the CIE flux code of a Lambertian table (the flux within a cone of
 *    half angle t is pi I0 sin^2 t) with and without a lamp flux;
 *  - TM-15-11 zone lumens and BUG rating of an asymmetric table,
 *    I = I0 cos(gamma) (1 + cos C / 2) below the horizon and I1 |cos gamma|
 *    above it, whose zones integrate in closed form, rated by the limits of
 *    TM-15-11 Addendum A transcribed here on their own. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "lights/photometry/photometry.h"
#include "radiometry/constants.h"

/* ---- configuration factors (Howell, A Catalog of Radiation Heat Transfer Configuration Factors) ---- */

/* B-9 (Hottel): directly opposed parallel rectangles a x b at distance c. */
static double hottel_opposed(double a, double b, double c)
{
    double x = a / c, y = b / c, sx = sqrt(1.0 + x * x), sy = sqrt(1.0 + y * y);
    return 2.0 / (CDL_PI * x * y) *
           (log(sqrt((1.0 + x * x) * (1.0 + y * y) / (1.0 + x * x + y * y))) + x * sy * atan(x / sy) +
            y * sx * atan(y / sx) - x * atan(x) - y * atan(y));
}

/* C-12's kernel for parallel rectangles with parallel edges, distance z. */
static double parallel_kernel(double x, double y, double z)
{
    double a = sqrt(y * y + z * z), b = sqrt(x * x + z * z);
    return (x * a * atan(x / a) + y * b * atan(y / b) - 0.5 * z * z * log(x * x + y * y + z * z)) / CDL_TWO_PI;
}

/* From rectangle 1 ([x1, x2] x [y1, y2]) to rectangle 2 ([u1, u2] x [v1, v2]), parallel at distance z. */
static double parallel_factor(const double x[2], const double y[2], const double u[2], const double v[2], double z)
{
    double sum = 0.0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int l = 0; l < 2; ++l)
                    sum += ((i + j + k + l) % 2 ? -1.0 : 1.0) * parallel_kernel(x[i] - u[k], y[j] - v[l], z);
    return sum / ((x[1] - x[0]) * (y[1] - y[0]));
}

/* Solid angle of the rectangle [0, a] x [0, a] at distance 1 below (x0, y0). */
static double square_solid_angle(double x0, double y0, double a)
{
    double s = 0.0;
    const double xs[2] = {-x0, a - x0}, ys[2] = {-y0, a - y0};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            /* the corner term of a rectangle's solid angle: atan(x y / (z r)) with z = 1 */
            s += ((i + j) % 2 ? -1.0 : 1.0) * atan(xs[i] * ys[j] / sqrt(xs[i] * xs[i] + ys[j] * ys[j] + 1.0));
    return s;
}

static cdl_photometry *rotational(double (*f)(double), double step, double last)
{
    size_t n = (size_t)llround(last / step) + 1;
    double *g = malloc(n * sizeof *g), *cd = malloc(n * sizeof *cd), c = 0.0;
    for (size_t j = 0; j < n; ++j) {
        g[j] = step * (double)j;
        cd[j] = f(g[j]);
    }
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(&c, 1, g, n, cd, &p, &err), &err);
    free(g);
    free(cd);
    return p;
}

static double lambert(double g) { return g <= 90.0 ? 1000.0 * cos(g * CDL_DEG_TO_RAD) : 0.0; }
static double even(double g) { (void)g; return 1000.0; }

static void test_direct_ratios(void)
{
    const double a = 2.0, b = 3.0, c = 1.5;
    double xs[2] = {0.0, a}, ys[2] = {0.0, b};
    /* the general formula reproduces Hottel's for opposed rectangles (both closed forms: 1e-12) */
    CHECK_REL(parallel_factor(xs, ys, xs, ys, c), hottel_opposed(a, b, c), 1e-12);

    cdl_photometry *p = rotational(lambert, 0.5, 180.0);
    double dr[CDL_DIRECT_RATIO_COUNT];
    cdl_error err;
    CHECK_OK(cdl_photometry_direct_ratios(p, dr, &err), &err);
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k) {
        /* luminaires over [h/2, a - h/2]^2 (spacing h = 1), the work plane [0, a]^2, a = 2 k h */
        double side = 2.0 * cdl_direct_ratio_room_index(k), in[2] = {0.5, side - 0.5}, room[2] = {0.0, side};
        /* 2e-5: the table samples cos every 0.5 degree (linear interpolation
         * errs by up to 1e-5 of the flux) and the quadrature adds 3e-6 */
        CHECK_REL(dr[k], parallel_factor(in, in, room, room, 1.0), 2e-5);
        if (k) CHECK(dr[k] > dr[k - 1]);
    }
    cdl_photometry_release(p);

    /* Equal intensity in every downward direction, none upward: DR is the
     * work plane's solid angle / 2 pi, averaged over the luminaires' square
     * (Gauss-Legendre, 20 nodes per axis in each of 8 x 8 cells, whose
     * error is far below the tolerance for this smooth integrand). */
    p = rotational(even, 1.0, 90.0);
    CHECK_OK(cdl_photometry_direct_ratios(p, dr, &err), &err);
    static const double gx[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                 0.9739065285171717};
    static const double gw[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                 0.0666713443086881};
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k) {
        double side = 2.0 * cdl_direct_ratio_room_index(k), lo = 0.5, w = side - 1.0, sum = 0.0;
        const int cells = 8;
        double h = w / cells;
        for (int ci = 0; ci < cells; ++ci)
            for (int cj = 0; cj < cells; ++cj)
                for (int i = 0; i < 10; ++i)
                    for (int j = 0; j < 10; ++j) {
                        double ti = i < 5 ? -gx[i] : gx[i - 5], wi = gw[i < 5 ? i : i - 5];
                        double tj = j < 5 ? -gx[j] : gx[j - 5], wj = gw[j < 5 ? j : j - 5];
                        double x = lo + h * (ci + 0.5 + 0.5 * ti), y = lo + h * (cj + 0.5 + 0.5 * tj);
                        sum += wi * wj * 0.25 * square_solid_angle(x, y, side);
                    }
        double want = sum / (cells * cells) / CDL_TWO_PI;
        /* 1e-5: the library's quadrature over gamma and C (the table is exact here) */
        CHECK_REL(dr[k], want, 1e-5);
    }
    cdl_photometry_release(p);
}

/* A cone of 1000 cd at nadir falling linearly to 0 at `edge` degrees (no light beyond). */
static cdl_photometry *narrow_spot(double edge)
{
    double c = 0.0, g[3] = {0.0, edge, 180.0}, cd[3] = {1000.0, 0.0, 0.0};
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(&c, 1, g, 3, cd, &p, &err), &err);
    return p;
}

static void test_narrow_spots(void)
{
    const double edges[2] = {0.3, 0.01};
    for (int e = 0; e < 2; ++e) {
        cdl_photometry *p = narrow_spot(edges[e]);
        if (!p) return;
        double dr[CDL_DIRECT_RATIO_COUNT], flux = cdl_photometry_flux(p).lm;
        cdl_error err;
        CHECK(flux > 0.0);
        CHECK_OK(cdl_photometry_direct_ratios(p, dr, &err), &err);
        /* 1e-12: DR is (downward share) x (a ratio of equal sums), both 1 to rounding */
        for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k)
            CHECK_MSG(fabs(dr[k] - 1.0) <= 1e-12, "%g degree spot: DR(k = %g) = %.12g, expected 1", edges[e],
                      cdl_direct_ratio_room_index(k), dr[k]);
        cdl_bug_rating r;
        CHECK_OK(cdl_photometry_bug_rating(p, &r, &err), &err);
        /* 1e-6 of the flux: two Gauss-Legendre nodes on [0, e] leave the
         * quartic term g^4 / (6 e) of (1 - g / e) sin g, 1.5e-7 of the cone's
         * flux at e = 0.3 degree; the exact flux's closed form loses about
         * 1e-16 / (1 - cos e) to cancellation, 2.5e-8 at e = 0.01 degree */
        CHECK_MSG(fabs(r.zone_lm[0] - 0.5 * flux) <= 1e-6 * flux && fabs(r.zone_lm[4] - 0.5 * flux) <= 1e-6 * flux,
                  "%g degree spot: FL %.9g and BL %.9g lm, expected half of %.9g each", edges[e], r.zone_lm[0],
                  r.zone_lm[4], flux);
        cdl_photometry_release(p);
    }
}

/* A type A or B table of 1000 cd at nadir (H = V = 0) falling linearly to 0
 * at `edge` degrees along either angle, none elsewhere. */
static cdl_photometry *narrow_ab_spot(cdl_photometric_type type, double edge)
{
    double a[5] = {-90.0, -edge, 0.0, edge, 90.0}, cd[25] = {0};
    cd[2 * 5 + 2] = 1000.0;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create(type, a, 5, a, 5, cd, &p, &err), &err);
    return p;
}

static void test_narrow_ab_spots(void)
{
    const cdl_photometric_type types[2] = {CDL_PHOTOMETRIC_TYPE_A, CDL_PHOTOMETRIC_TYPE_B};
    const double edges[2] = {0.3, 0.7};
    for (int t = 0; t < 2; ++t)
        for (int e = 0; e < 2; ++e) {
            cdl_photometry *p = narrow_ab_spot(types[t], edges[e]);
            if (!p) return;
            double n[5], flux = cdl_photometry_flux(p).lm;
            CHECK(flux > 0.0);
            cdl_photometry_cie_flux_code(p, n);
            /* 1e-9 percentage points: each N is the downward hemisphere's
             * exact flux times a ratio of sums over the same rings, all of
             * them in the first cone here */
            for (int k = 0; k < 5; ++k)
                CHECK_MSG(fabs(n[k] - 100.0) <= 1e-9, "type %c %g degree spot: N%d = %.12g %%, expected 100",
                          t ? 'B' : 'A', edges[e], k + 1, n[k]);
            cdl_photometry_summary s = {.size = sizeof s};
            cdl_photometry_summarize(p, &s);
            CHECK_REL(s.zone_flux[0].lm, flux, 1e-12);
            for (int z = 1; z < 18; ++z) CHECK_ABS(s.zone_flux[z].lm, 0.0, 1e-12 * flux);
            /* a window inside the first zone's cone holds it all; one beyond the spot nothing */
            CHECK_REL(cdl_photometry_zone_flux(p, 0.0, 2.0 * edges[e]).lm, flux, 1e-12);
            CHECK_ABS(cdl_photometry_zone_flux(p, 2.0 * edges[e], 90.0).lm, 0.0, 1e-12 * flux);
            cdl_photometry_release(p);
        }
}

static void test_flux_code(void)
{
    cdl_photometry *p = rotational(lambert, 0.5, 180.0);
    double n[5];
    cdl_photometry_cie_flux_code(p, n);
    /* pi I0 sin^2 t of pi I0: 1 - cos^2 t, cos t = 3/4, 1/2, 1/4; absolute photometry: 100, 100.
     * 2e-3 percentage points: the table's linear interpolation of cos (1e-5 of the flux) */
    CHECK_ABS(n[0], 100.0 * (1.0 - 0.5625), 2e-3);
    CHECK_ABS(n[1], 75.0, 2e-3);
    CHECK_ABS(n[2], 100.0 * (1.0 - 0.0625), 2e-3);
    CHECK_ABS(n[3], 100.0, 1e-9);
    CHECK_ABS(n[4], 100.0, 1e-9);
    cdl_photometry_release(p);
}

/* ---- TM-15-11 ---- */

#define I0 5000.0 /* cd at nadir of the lower part */
#define I1 4.0    /* cd at zenith of the upper part */

static double tm15_table(double c_deg, double g_deg)
{
    double g = g_deg * CDL_DEG_TO_RAD, c = c_deg * CDL_DEG_TO_RAD;
    return g_deg <= 90.0 ? I0 * cos(g) * (1.0 + 0.5 * cos(c)) : I1 * fabs(cos(g));
}

/* integral of cos(g) sin(g) over [g1, g2] degrees: (sin^2 g2 - sin^2 g1) / 2 */
static double cos_sin(double g1, double g2)
{
    double a = sin(g1 * CDL_DEG_TO_RAD), b = sin(g2 * CDL_DEG_TO_RAD);
    return 0.5 * fabs(b * b - a * a);
}

/* The lowest rating 0..5 whose limits (lumens, ratings 0..4) every zone keeps. */
static int rating(const double *lumens, const double limits[][5], int count)
{
    for (int r = 0; r < 5; ++r) {
        int ok = 1;
        for (int z = 0; z < count; ++z) ok &= lumens[z] <= limits[z][r];
        if (ok) return r;
    }
    return 5;
}

static void test_bug(void)
{
    enum { NC = 360, NG = 361 };
    double *c = malloc(NC * sizeof *c), *g = malloc(NG * sizeof *g), *cd = malloc(NC * NG * sizeof *cd);
    for (int i = 0; i < NC; ++i) c[i] = i;
    for (int j = 0; j < NG; ++j) g[j] = 0.5 * j;
    for (int i = 0; i < NC; ++i)
        for (int j = 0; j < NG; ++j) cd[i * NG + j] = tm15_table(c[i], g[j]);
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(c, NC, g, NG, cd, &p, &err), &err);
    free(c);
    free(g);
    free(cd);
    if (!p) return;
    /* front (towards C0): integral of (1 + cos C / 2) over |C| < 90 = pi + 1; back pi - 1 */
    const double edges[5] = {0.0, 30.0, 60.0, 80.0, 90.0};
    double want[10];
    for (int z = 0; z < 4; ++z) {
        want[z] = I0 * (CDL_PI + 1.0) * cos_sin(edges[z], edges[z + 1]);
        want[4 + z] = I0 * (CDL_PI - 1.0) * cos_sin(edges[z], edges[z + 1]);
    }
    want[8] = I1 * CDL_TWO_PI * cos_sin(90.0, 100.0);
    want[9] = I1 * CDL_TWO_PI * cos_sin(100.0, 180.0);
    cdl_bug_rating r;
    CHECK_OK(cdl_photometry_bug_rating(p, &r, &err), &err);
    for (int z = 0; z < 10; ++z)
        /* 2e-4: the table samples the distribution every degree of C and
         * half degree of gamma (linear interpolation of cos C errs by 4e-5),
         * and the zones' quadrature adds 1e-5 */
        CHECK_MSG(fabs(r.zone_lm[z] - want[z]) <= 2e-4 * want[z], "%s: %.6g lm, expected %.6g",
                  cdl_bug_zone_name(z), r.zone_lm[z], want[z]);
    /* TM-15-11 Addendum A (Tables, as the IES/IDA Model Lighting
     * Ordinance 2011 reprints them), ratings 0..4 */
    const double backlight[3][5] = {{110, 500, 1000, 2500, 5000}, {220, 1000, 2500, 5000, 8500}, {110, 500, 1000, 2500, 5000}};
    const double uplight[2][5] = {{0, 10, 50, 500, 1000}, {0, 10, 50, 500, 1000}};
    const double glare[4][5] = {{10, 75, 150, 300, 500}, {10, 75, 150, 300, 500}, {660, 1800, 5000, 7500, 12000}, {110, 500, 1000, 2500, 5000}};
    double b_zones[3] = {want[6], want[5], want[4]};  /* BH, BM, BL */
    double u_zones[2] = {want[9], want[8]};           /* UH, UL */
    double g_zones[4] = {want[3], want[7], want[2], want[6]}; /* FVH, BVH, FH, BH */
    int b = rating(b_zones, backlight, 3), u = rating(u_zones, uplight, 2), gl = rating(g_zones, glare, 4);
    CHECK_MSG(r.b == b && r.u == u && r.g == gl, "B%d U%d G%d, expected B%d U%d G%d", r.b, r.u, r.g, b, u, gl);
    /* the case is not on a limit: the zones sit at least 3 % from every limit */
    for (int z = 0; z < 10; ++z)
        for (int k = 0; k < 5; ++k) {
            double lim[] = {backlight[0][k], backlight[1][k], glare[0][k], glare[2][k], uplight[0][k]};
            for (size_t m = 0; m < sizeof lim / sizeof *lim; ++m)
                CHECK_MSG(lim[m] == 0.0 || fabs(want[z] - lim[m]) > 0.03 * lim[m], "zone %d near limit %g", z, lim[m]);
        }
    CHECK(b == 3 && u == 2 && gl == 4); /* what the closed form says this table is */
    cdl_photometry_release(p);
}

int main(void)
{
    test_direct_ratios();
    test_narrow_spots();
    test_narrow_ab_spots();
    test_flux_code();
    test_bug();
    return check_finish();
}
