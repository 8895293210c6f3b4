/* The CIE standard general skies' illuminance (sky_distribution.h: a
 * quadrature about the sun) against an independent quadrature of the
 * ISO 15469 formula written apart here: in zenith angle Z and azimuth,
 *     L / L_z = f(chi) phi(Z) / (f(Z_s) phi(0)),
 *     cos chi = cos Z_s cos Z + sin Z_s sin Z cos(az - az_s)   (the standard's eq. for chi),
 * on the horizontal plane and on vertical planes facing the four
 * quarters, for every type, with the sun high, low and behind a vertical
 * plane; plus the luminance itself at a few directions, the zenith and
 * the horizon, and the bounds over regions.
 *
 * The reference quadrature: product Gauss-Legendre rules in Z and
 * azimuth, the azimuth range cut at the sun's azimuth (where chi has its
 * cone) and, for a vertical plane, limited to the half the plane faces
 * (so the cosine's kink lies on the edge), Z cut at the sun's zenith
 * angle. 96 x 96 points a panel give it to about 1e-8 (measured: the sky's
 * quadrature stands within 2.1e-8 of it, and within 3.2e-8 of the same
 * rule on 144 x 144 points, 1.6e-7 of 64 x 64); the sky's quadrature is
 * checked to 1e-7.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "gauss16.h"
#include "lights/environment/sky_distribution.h"
#include "radiometry/constants.h"

/* ---- the standard's formula, independently ------------------------------------- */

static const double table[15][5] = {
    {4.0, -0.70, 0, -1.0, 0},      {4.0, -0.70, 2, -1.5, 0.15},  {1.1, -0.8, 0, -1.0, 0},
    {1.1, -0.8, 2, -1.5, 0.15},    {0, -1.0, 0, -1.0, 0},        {0, -1.0, 2, -1.5, 0.15},
    {0, -1.0, 5, -2.5, 0.30},      {0, -1.0, 10, -3.0, 0.45},    {-1, -0.55, 2, -1.5, 0.15},
    {-1, -0.55, 5, -2.5, 0.30},    {-1, -0.55, 10, -3.0, 0.45},  {-1, -0.32, 10, -3.0, 0.45},
    {-1, -0.32, 16, -3.0, 0.30},   {-1, -0.15, 16, -3.0, 0.30},  {-1, -0.15, 24, -2.8, 0.15},
};

static double phi(const double *p, double Z)
{
    return Z >= 0.5 * CDL_PI ? 1.0 : 1.0 + p[0] * exp(p[1] / cos(Z));
}

static double f(const double *p, double chi)
{
    return 1.0 + p[2] * (exp(p[3] * chi) - exp(p[3] * CDL_PI / 2.0)) + p[4] * cos(chi) * cos(chi);
}

/* L / L_z at (Z, az), sun at (Zs, azs); azimuths in radians */
static double relative(const double *p, double Z, double az, double Zs, double azs)
{
    double c = cos(Zs) * cos(Z) + sin(Zs) * sin(Z) * cos(az - azs);
    double chi = acos(fmax(-1.0, fmin(1.0, c)));
    return f(p, chi) * phi(p, Z) / (f(p, Zs) * phi(p, 0.0));
}

/* The reference rule: the 16-point Gauss-Legendre rule composed over 6
 * equal parts, 96 points on [0, 1] (gauss16.h). */
#define REF_PARTS 6
#define REF_N (16 * REF_PARTS)
static double gx[REF_N], gw[REF_N];

/* int over Z in [z0, z1], az in [a0, a1] of L/L_z (n.w) sin Z, n = (nz, facing azimuth an, horizontal part nh) */
static double panel(const double *p, double z0, double z1, double a0, double a1, double Zs, double azs, double nz,
                    double nh, double an)
{
    double sum = 0;
    for (int i = 0; i < REF_N; ++i) {
        double Z = z0 + (z1 - z0) * gx[i];
        for (int j = 0; j < REF_N; ++j) {
            double az = a0 + (a1 - a0) * gx[j];
            double cosn = nz * cos(Z) + nh * sin(Z) * cos(az - an);
            if (cosn <= 0) continue;
            sum += gw[i] * gw[j] * relative(p, Z, az, Zs, azs) * cosn * sin(Z);
        }
    }
    return sum * (z1 - z0) * (a1 - a0);
}

/* E / L_z on a horizontal plane (vertical = 0) or a vertical one facing azimuth an */
static double reference(const double *p, double Zs, double azs, int vertical, double an)
{
    double a0 = vertical ? an - 0.5 * CDL_PI : azs - CDL_PI, a1 = vertical ? an + 0.5 * CDL_PI : azs + CDL_PI;
    double cuts[3] = {a0, a1, a1};
    int nc = 2;
    /* the sun's azimuth (or its copy a turn away) within the range */
    for (int k = -1; k <= 1; ++k) {
        double s = azs + k * CDL_TWO_PI;
        if (s > a0 + 1e-12 && s < a1 - 1e-12) {
            cuts[1] = s;
            cuts[2] = a1;
            nc = 3;
        }
    }
    double total = 0;
    for (int c = 0; c + 1 < nc; ++c) {
        total += panel(p, 0, Zs, cuts[c], cuts[c + 1], Zs, azs, vertical ? 0 : 1, vertical ? 1 : 0, an);
        total += panel(p, Zs, 0.5 * CDL_PI, cuts[c], cuts[c + 1], Zs, azs, vertical ? 0 : 1, vertical ? 1 : 0, an);
    }
    return total;
}

/* ---- the sky under test ------------------------------------------------------------ */

/* World: up +z, north +y, east +x; azimuth az (from north, eastward) is
 * the direction (sin az, cos az) in x, y. */
static cdl_vec3 dir_of(double Z, double az)
{
    return cdl_vec3_make(sin(Z) * sin(az), sin(Z) * cos(az), cos(Z));
}

static int make(cdl_sky_distribution *s, int type, double Zs, double azs, double Lz)
{
    double p[5];
    cdl_error err;
    if (!cdl_sky_cie_parameters(type, p)) return 0;
    cdl_status st = cdl_sky_distribution_init(s, cdl_vec3_make(0, 0, 1), cdl_vec3_make(1, 0, 0), dir_of(Zs, azs), p,
                                              exp(p[3] * CDL_PI / 2.0), 0, &err);
    if (st == CDL_OK) st = cdl_sky_distribution_scale_to(s, Lz, -1.0, &err);
    CHECK_MSG(st == CDL_OK, "type %d: %s", type, err.message);
    return st == CDL_OK;
}

static void test_illuminance(void)
{
    const double suns[3][2] = {{30.0, 160.0}, {75.0, 250.0}, {60.0, 10.0}};
    double worst = 0;
    for (int type = 1; type <= 15; ++type)
        for (int k = 0; k < 3; ++k) {
            double Zs = suns[k][0] * CDL_DEG_TO_RAD, azs = suns[k][1] * CDL_DEG_TO_RAD, Lz = 5000.0;
            cdl_sky_distribution s;
            if (!make(&s, type, Zs, azs, Lz)) continue;
            /* horizontal */
            double want = Lz * reference(table[type - 1], Zs, azs, 0, 0);
            double got = cdl_sky_distribution_illuminance(&s, cdl_vec3_make(0, 0, 1));
            CHECK_REL(got, want, 1e-7);
            worst = fmax(worst, fabs(got / want - 1));
            /* vertical, facing north, east, south, west */
            for (int q = 0; q < 4; ++q) {
                double an = q * 0.5 * CDL_PI;
                want = Lz * reference(table[type - 1], Zs, azs, 1, an);
                got = cdl_sky_distribution_illuminance(&s, cdl_vec3_make(sin(an), cos(an), 0));
                CHECK_MSG(fabs(got / want - 1) <= 1e-7, "type %d sun %d facing %d: %.12g vs %.12g", type, k, q, got,
                          want);
                worst = fmax(worst, fabs(got / want - 1));
            }
        }
    fprintf(stderr, "CIE skies: worst relative difference from the independent quadrature %.3g\n", worst);
}

/* The luminance at a few directions, the zenith's, and type 1's closeness
 * to (and difference from) the traditional overcast sky. */
static void test_luminance(void)
{
    cdl_sky_distribution s;
    double Zs = 40 * CDL_DEG_TO_RAD, azs = 200 * CDL_DEG_TO_RAD;
    for (int type = 1; type <= 15; ++type) {
        if (!make(&s, type, Zs, azs, 1000.0)) continue;
        CHECK_REL(cdl_sky_distribution_luminance(&s, cdl_vec3_make(0, 0, 1)), 1000.0, 1e-12);
        CHECK_REL(cdl_sky_distribution_zenith(&s), 1000.0, 1e-12);
        const double at[4][2] = {{10, 30}, {55, 200}, {80, 300}, {41, 199}};
        for (int i = 0; i < 4; ++i) {
            double Z = at[i][0] * CDL_DEG_TO_RAD, az = at[i][1] * CDL_DEG_TO_RAD;
            CHECK_REL(cdl_sky_distribution_luminance(&s, dir_of(Z, az)), 1000.0 * relative(table[type - 1], Z, az, Zs, azs),
                      1e-12);
        }
        CHECK(cdl_sky_distribution_luminance(&s, dir_of(95 * CDL_DEG_TO_RAD, 0)) == 0.0);
    }
    /* Type 1 at the horizon: L_z / (1 + 4 e^-0.7) = 0.3349 L_z, the
     * traditional overcast sky's L_z / 3 within 0.5 %; at 45 degrees
     * 0.8327 L_z against (1 + sqrt 2) / 3 = 0.8047: close, not the same
     * (3.5 % apart). */
    make(&s, 1, Zs, azs, 1.0);
    CHECK_REL(cdl_sky_distribution_luminance(&s, dir_of(0.5 * CDL_PI - 1e-9, 1.0)), 1.0 / (1.0 + 4.0 * exp(-0.7)), 1e-6);
    double l45 = cdl_sky_distribution_luminance(&s, dir_of(0.25 * CDL_PI, 1.0));
    CHECK_REL(l45, (1.0 + 4.0 * exp(-0.7 * sqrt(2.0))) / (1.0 + 4.0 * exp(-0.7)), 1e-12);
    CHECK(fabs(l45 - (1.0 + sqrt(2.0)) / 3.0) > 0.02 && fabs(l45 - (1.0 + sqrt(2.0)) / 3.0) < 0.05);
}

/* Bounds over regions hold every luminance sampled inside them. */
static void test_bounds(void)
{
    cdl_sky_distribution s;
    make(&s, 12, 35 * CDL_DEG_TO_RAD, 180 * CDL_DEG_TO_RAD, 3000.0);
    const double regions[4][4][2] = {
        {{30, 170}, {30, 190}, {40, 190}, {40, 170}},  /* holds the sun */
        {{60, 0}, {60, 40}, {85, 40}, {85, 0}},        /* far from it, near the horizon */
        {{1, 0}, {1, 120}, {1, 240}, {1, 359}},        /* about the zenith */
        {{80, 90}, {80, 100}, {100, 100}, {100, 90}},  /* across the horizon */
    };
    for (int r = 0; r < 4; ++r) {
        cdl_vec3 d[4];
        for (int v = 0; v < 4; ++v) d[v] = dir_of(regions[r][v][0] * CDL_DEG_TO_RAD, regions[r][v][1] * CDL_DEG_TO_RAD);
        double lo, hi;
        cdl_sky_distribution_bounds(&s, d, 4, &lo, &hi);
        CHECK(lo <= hi && lo >= 0.0);
        int inside = 0;
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j) {
                /* bilinear in the corners' directions, normalised: inside the convex region */
                cdl_vec3 a = cdl_vec3_add(cdl_vec3_scale(d[0], 1 - i / 20.0), cdl_vec3_scale(d[1], i / 20.0));
                cdl_vec3 b = cdl_vec3_add(cdl_vec3_scale(d[3], 1 - i / 20.0), cdl_vec3_scale(d[2], i / 20.0));
                cdl_vec3 w = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_scale(a, 1 - j / 20.0), cdl_vec3_scale(b, j / 20.0)));
                double L = cdl_sky_distribution_luminance(&s, w);
                inside += L >= lo * (1 - 1e-12) && L <= hi * (1 + 1e-12);
            }
        CHECK_MSG(inside == 21 * 21, "region %d: %d of 441 within [%g, %g]", r, inside, lo, hi);
    }
}

/* The mixture sampler: the mean of L cos / pdf is E (unbiased) for a
 * sky with a corona, to the estimate's own error. */
static void test_sampling(void)
{
    cdl_sky_distribution s;
    make(&s, 13, 50 * CDL_DEG_TO_RAD, 120 * CDL_DEG_TO_RAD, 2000.0);
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.4, -0.2, 0.8));
    double E = cdl_sky_distribution_illuminance(&s, n), sum = 0, sum2 = 0;
    const int N = 400;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            double pdf;
            cdl_vec3 w = cdl_sky_distribution_sample(&s, n, (i + 0.5) / N, (j + 0.5) / N, &pdf);
            double c = cdl_vec3_dot(n, w);
            double v = c > 0 && pdf > 0 ? cdl_sky_distribution_luminance(&s, w) * c / pdf : 0;
            CHECK_MSG(isfinite(v), "sample %d %d", i, j);
            CHECK_REL(cdl_sky_distribution_pdf(&s, n, w), pdf, 1e-9);
            sum += v;
            sum2 += v * v;
        }
    double mean = sum / (N * N), sd = sqrt(fmax(0, sum2 / (N * N) - mean * mean) / (N * N));
    /* stratified midpoints: the plain sd overstates the error; 4 of it */
    CHECK_MSG(fabs(mean - E) <= 4 * sd + 1e-9 * E, "mean %.9g vs E %.9g (sd %.3g)", mean, E, sd);
}

int main(void)
{
    gauss16_composite(REF_PARTS, gx, gw);
    test_illuminance();
    test_luminance();
    test_bounds();
    test_sampling();
    return check_finish();
}
