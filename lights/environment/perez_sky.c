/* perez_sky.c - the Perez all-weather sky's parameters from weather data
 * (perez_sky.h). */
#include "lights/environment/perez_sky.h"

#include <math.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

/* The solar constant as gendaylit takes it, W/m^2 and lx (Radiance
 * gendaylit.c: 1367 W/m^2, 127.5 klx). */
#define PEREZ_SOLAR_CONSTANT_W_M2 1367.0
#define PEREZ_SOLAR_CONSTANT_LX 127500.0

/* kappa of the clearness (Perez et al. 1990, eq. 1), Z in radians */
#define PEREZ_KAPPA 1.041

/* Upper bounds of the clearness categories (Perez et al. 1990, Table 1);
 * the first starts at 1. */
static const double category_top[8] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 12.01};

/* Luminous efficacy coefficients a, b, c, d per category (Perez et al.
 * 1990, Table 4): diffuse (eq. 7) and direct (eq. 8), lm/W. */
static const double diffuse_efficacy[8][4] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},    {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98},
};
static const double direct_efficacy[8][4] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29},
};

/* The sky's coefficients per category (Perez, Seals and Michalsky 1993,
 * Table 1, with the erratum): for each of a, b, c, d, e its x1, x2, x3, x4. */
static const double sky_coefficients[8][5][4] = {
    {{1.3525, -0.2576, -0.2690, -1.4366},
     {-0.7670, 0.0007, 1.2734, -0.1233},
     {2.8000, 0.6004, 1.2375, 1.0000},
     {1.8734, 0.6297, 0.9738, 0.2809},
     {0.0356, -0.1246, -0.5718, 0.9938}},
    {{-1.2219, -0.7730, 1.4148, 1.1016},
     {-0.2054, 0.0367, -3.9128, 0.9156},
     {6.9750, 0.1774, 6.4477, -0.1239},
     {-1.5798, -0.5081, -1.7812, 0.1080},
     {0.2624, 0.0672, -0.2190, -0.4285}},
    {{-1.1000, -0.2515, 0.8952, 0.0156},
     {0.2782, -0.1812, -4.5000, 1.1766},
     {24.7219, -13.0812, -37.7000, 34.8438},
     {-5.0000, 1.5218, 3.9229, -2.6204},
     {-0.0156, 0.1597, 0.4199, -0.5562}},
    {{-0.5484, -0.6654, -0.2672, 0.7117},
     {0.7234, -0.6219, -5.6812, 2.6297},
     {33.3389, -18.3000, -62.2500, 52.0781},
     {-3.5000, 0.0016, 1.1477, 0.1062},
     {0.4659, -0.3296, -0.0876, -0.0329}},
    {{-0.6000, -0.3566, -2.5000, 2.3250},
     {0.2937, 0.0496, -5.6812, 1.8415},
     {21.0000, -4.7656, -21.5906, 7.2492},
     {-3.5000, -0.1554, 1.4062, 0.3988},
     {0.0032, 0.0766, -0.0656, -0.1294}},
    {{-1.0156, -0.3670, 1.0078, 1.4051},
     {0.2875, -0.5328, -3.8500, 3.3750},
     {14.0000, -0.9999, -7.1406, 7.5469},
     {-3.4000, -0.1078, -1.0750, 1.5702},
     {-0.0672, 0.4016, 0.3017, -0.4844}},
    {{-1.0000, 0.0211, 0.5025, -0.5119},
     {-0.3000, 0.1922, 0.7023, -1.6317},
     {19.0000, -5.0000, 1.2438, -1.9094},
     {-4.0000, 0.0250, 0.3844, 0.2656},
     {1.0468, -0.3788, -2.4517, 1.4656}},
    {{-1.0500, 0.0289, 0.4260, 0.3590},
     {-0.3250, 0.1156, 0.7781, 0.0025},
     {31.0625, -14.5000, -46.1148, 55.3750},
     {-7.2312, 0.4050, 13.3500, 0.6234},
     {1.5000, -0.6426, 1.8564, 0.5636}},
};

/* Relative optical air mass (Kasten, "A new table and approximation
 * formula for the relative optical air mass", Arch. Meteorol. Geophys.
 * Bioklimatol. B 14, 1966), Z in degrees. */
static double air_mass(double z_deg)
{
    return 1.0 / (cos(z_deg * CDL_DEG_TO_RAD) + 0.15 * pow(93.885 - z_deg, -1.253));
}

/* The Earth's eccentricity correction (R0 / R)^2 on a day of the year
 * (Spencer, "Fourier series representation of the position of the sun",
 * Search 2(5), 1971). */
static double eccentricity(int day)
{
    double g = CDL_TWO_PI * (day - 1) / 365.0;
    return 1.00011 + 0.034221 * cos(g) + 0.00128 * sin(g) + 0.000719 * cos(2.0 * g) + 0.000077 * sin(2.0 * g);
}

static int category_of(double clearness)
{
    for (int k = 0; k < 8; ++k)
        if (clearness < category_top[k]) return k;
    return 7;
}

/* epsilon and Delta from the irradiances */
static void clearness_brightness(const cdl_perez_input *in, double dh, double dn, double *eps, double *delta)
{
    double z = in->sun_zenith_deg * CDL_DEG_TO_RAD, z3 = PEREZ_KAPPA * z * z * z;
    *eps = ((dh + dn) / dh + z3) / (1.0 + z3);
    *delta = dh * air_mass(in->sun_zenith_deg) / (PEREZ_SOLAR_CONSTANT_W_M2 * eccentricity(in->day_of_year));
}

static void efficacies(int k, double W, double z_rad, double delta, double *diffuse, double *direct)
{
    const double *d = diffuse_efficacy[k], *b = direct_efficacy[k];
    *diffuse = d[0] + d[1] * W + d[2] * cos(z_rad) + d[3] * log(delta);
    *direct = fmax(0.0, b[0] + b[1] * W + b[2] * exp(5.73 * z_rad - 5.0) + b[3] * delta);
}

static cdl_status check_input(const cdl_perez_input *in, cdl_error *err)
{
    const char *unit = in->photometric ? "lx" : "W/m^2";
    double top = in->photometric ? PEREZ_SOLAR_CONSTANT_LX : PEREZ_SOLAR_CONSTANT_W_M2;
    if (!(in->sun_zenith_deg >= 0.0 && in->sun_zenith_deg < 90.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "sun: expected the sun above the horizon for the Perez sky (its air mass and "
                             "efficacies), found a zenith angle of %.6g degrees",
                             in->sun_zenith_deg);
    if (in->day_of_year < 1 || in->day_of_year > 366)
        return cdl_error_set(err, CDL_ERR_INPUT, "day of the year: expected 1 to 366, found %d", in->day_of_year);
    if (!(isfinite(in->diffuse_horizontal) && in->diffuse_horizontal > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "diffuse horizontal: expected a value above 0 %s, found %g", unit,
                             in->diffuse_horizontal);
    if (!(isfinite(in->direct_normal) && in->direct_normal >= 0.0 && (in->clamp || in->direct_normal <= top)))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "direct normal: expected a value from 0 to the solar constant, %g %s, found %g", top, unit,
                             in->direct_normal);
    if (!(isfinite(in->dew_point_c) && in->dew_point_c > -100.0 && in->dew_point_c < 60.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "dew point: expected degrees C in (-100, 60), found %g",
                             in->dew_point_c);
    return CDL_OK;
}

/* Irradiances from illuminances: divided by the efficacies of the category
 * they fall in, until they settle. */
static void irradiances_from_illuminances(const cdl_perez_input *in, double W, double *dh, double *dn)
{
    double z = in->sun_zenith_deg * CDL_DEG_TO_RAD;
    *dh = in->diffuse_horizontal * PEREZ_SOLAR_CONSTANT_W_M2 / PEREZ_SOLAR_CONSTANT_LX;
    *dn = in->direct_normal * PEREZ_SOLAR_CONSTANT_W_M2 / PEREZ_SOLAR_CONSTANT_LX;
    for (int it = 0; it < 50; ++it) {
        double eps, delta, kd, kb;
        clearness_brightness(in, *dh, *dn, &eps, &delta);
        efficacies(category_of(eps), W, z, fmax(delta, 1e-6), &kd, &kb);
        double dh2 = kd > 0.0 ? in->diffuse_horizontal / kd : *dh;
        double dn2 = kb > 0.0 ? in->direct_normal / kb : 0.0;
        int settled = fabs(dh2 - *dh) < 1e-6 && fabs(dn2 - *dn) < 1e-6;
        *dh = dh2;
        *dn = dn2;
        if (settled) break;
    }
}

cdl_status cdl_perez_sky_compute(const cdl_perez_input *in, cdl_perez_sky *out, cdl_error *err)
{
    cdl_status st = check_input(in, err);
    if (st != CDL_OK) return st;
    memset(out, 0, sizeof *out);
    double z = in->sun_zenith_deg * CDL_DEG_TO_RAD;
    double W = exp(0.07 * in->dew_point_c - 0.075);
    double dh, dn;
    cdl_perez_input clamped = *in;
    double top = in->photometric ? PEREZ_SOLAR_CONSTANT_LX : PEREZ_SOLAR_CONSTANT_W_M2;
    if (in->direct_normal > top) {
        clamped.direct_normal = top;
        out->clamped = 1;
        in = &clamped;
    }
    if (in->photometric) {
        irradiances_from_illuminances(in, W, &dh, &dn);
    } else {
        dh = in->diffuse_horizontal;
        dn = in->direct_normal;
    }
    double eps, delta;
    clearness_brightness(in, dh, dn, &eps, &delta);
    if (in->clamp && (!(eps <= 12.01) || !(delta > 0.01 && delta <= 0.6))) {
        /* gendaylit's check_parametrization: to the nearest edge */
        eps = fmin(fmax(eps, 1.0), 12.01);
        delta = fmin(fmax(delta, 0.01), 0.6);
        out->clamped = 1;
    }
    if (!(eps <= 12.01) || !(delta >= 0.01 && delta <= 0.6) || (!in->clamp && !(delta > 0.01)))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a sky within the Perez model's range (clearness epsilon 1 to 12.01, brightness "
                             "Delta in (0.01, 0.6]), found epsilon = %.6g, Delta = %.6g from %g W/m^2 diffuse "
                             "horizontal and %g W/m^2 direct normal with the sun %.4g degrees from the zenith",
                             eps, delta, dh, dn, in->sun_zenith_deg);
    int k = category_of(eps);
    double kd, kb;
    efficacies(k, W, z, delta, &kd, &kb);
    out->clearness = eps;
    out->brightness = delta;
    out->category = k + 1;
    out->air_mass = air_mass(in->sun_zenith_deg);
    out->precipitable_water_cm = W;
    out->diffuse_efficacy_lm_w = kd;
    out->direct_efficacy_lm_w = kb;
    out->diffuse_horizontal_w_m2 = dh;
    out->direct_normal_w_m2 = dn;
    out->diffuse_horizontal_lx = in->photometric ? in->diffuse_horizontal : dh * kd;
    out->direct_normal_lx = in->photometric ? in->direct_normal : dn * kb;
    /* the sky's coefficients; Delta at least 0.2 in categories 2-5 (gendaylit) */
    double D = eps > 1.065 && eps < 2.8 ? fmax(delta, 0.2) : delta;
    const double(*x)[4] = sky_coefficients[k];
    for (int i = 0; i < 5; ++i) out->coefficients[i] = x[i][0] + x[i][1] * z + D * (x[i][2] + x[i][3] * z);
    if (k == 0) {
        out->coefficients[2] = exp(pow(D * (x[2][0] + x[2][1] * z), x[2][2])) - x[2][3];
        out->coefficients[3] = -exp(D * (x[3][0] + x[3][1] * z)) + x[3][2] + D * x[3][3];
    }
    if (!(out->coefficients[1] < 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "the Perez sky's gradation coefficient b = %.6g is not below 0 for epsilon = %.6g, Delta "
                             "= %.6g and the sun %.4g degrees from the zenith: its luminance would grow without bound "
                             "towards the horizon",
                             out->coefficients[1], eps, delta, in->sun_zenith_deg);
    return CDL_OK;
}
