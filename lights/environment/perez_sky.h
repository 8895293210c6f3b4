/* perez_sky.h - the Perez all-weather sky from weather data, as Radiance's
 * gendaylit does.
 *
 * From the direct normal and diffuse horizontal irradiance (W/m^2) or
 * illuminance (lx), the sun's zenith angle, the day of the year and the
 * dew point:
 *  - sky clearness epsilon = ((E_dh + E_dn) / E_dh + kappa Z^3) / (1 + kappa
 *    Z^3), kappa = 1.041, Z in radians, and sky brightness Delta = E_dh m /
 *    E_0n (m the relative air mass of Kasten 1966, E_0n = 1367 W/m^2 times
 *    the eccentricity factor of Spencer 1971): Perez, Ineichen, Seals,
 *    Michalsky and Stewart, "Modeling daylight availability and irradiance
 *    components from direct and global irradiance", Solar Energy 44(5),
 *    1990, eqs. 1-2; epsilon picks one of 8 categories (its Table 1);
 *  - precipitable water W = exp(0.07 T_d - 0.075) cm (eq. 3, T_d the dew
 *    point in degrees C);
 *  - luminous efficacies of the diffuse light, a + b W + c cos Z + d ln
 *    Delta, and of the direct light, max(0, a + b W + c exp(5.73 Z - 5) +
 *    d Delta), lm/W (eqs. 7-8, Table 4), giving the illuminances from the
 *    irradiances; from illuminances, the irradiances are found by iterating
 *    (first guess E / (127.5 klx / 1367 W/m^2), then E / K with the
 *    efficacies of the category found) until they move by less than 1e-6
 *    W/m^2, as gendaylit's illu_to_irra_index does a few times;
 *  - the sky's coefficients a..e (Perez, Seals and Michalsky, "All-weather
 *    model for sky luminance distribution", Solar Energy 50(3), 1993, Table
 *    1 with the erratum, Solar Energy 51(5), 423): x = x1 + x2 Z + Delta
 *    (x3 + x4 Z) in every category but the first, where c = exp((Delta (c1
 *    + c2 Z))^c3) - c4 and d = -exp(Delta (d1 + d2 Z)) + d3 + Delta d4;
 *    Delta is taken as at least 0.2 for 1.065 < epsilon < 2.8, as gendaylit
 *    does.
 * The sky is then scaled so that it gives E_dh on an unobstructed
 * horizontal plane (emitter.h, CDL_SKY_PEREZ with scale_to_horizontal), and
 * the sun is a disk of 0.533 degrees giving E_dn normal to its rays.
 *
 * Inputs outside the model's range are refused (unless `clamp` asks to take
 * them at the range's edge, as an annual study must, hour by hour):
 * the sun at or below the horizon, E_dh <= 0, E_dn < 0 or above the solar
 * constant (1367 W/m^2, 127.5 klx), epsilon above 12.01, Delta outside
 * (0.01, 0.6], and coefficients for which the model's luminance grows
 * without bound towards the horizon (b >= 0) or is 0 everywhere.
 *
 * Thread safety: pure. Errors: CDL_ERR_INPUT naming the quantity.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_PEREZ_SKY_H
#define CANDELA_LIGHTS_ENVIRONMENT_PEREZ_SKY_H

#include "base/error.h"

typedef struct cdl_perez_input {
    double sun_zenith_deg;                /* (0, 90) */
    int day_of_year;                      /* 1..366, for the Earth's distance from the sun */
    int photometric;                      /* 1: the two values are lx; 0: W/m^2 */
    double direct_normal;                 /* >= 0 */
    double diffuse_horizontal;            /* > 0 */
    double dew_point_c;                   /* the surface dew point, degrees C (gendaymtx's default: 11) */
    int clamp;                            /* 1: a clearness or brightness outside the model's range is taken at
                                           * its nearest edge (epsilon in [1, 12.01], Delta in [0.01, 0.6]),
                                           * and a direct normal above the solar constant as the constant, as
                                           * gendaylit and gendaymtx do hour by hour; 0 (default): refused */
} cdl_perez_input;

typedef struct cdl_perez_sky {
    double clearness;                     /* epsilon */
    double brightness;                    /* Delta (as given to the efficacies, before the 0.2 floor) */
    int category;                         /* 1..8 */
    double air_mass;
    double precipitable_water_cm;
    double diffuse_efficacy_lm_w, direct_efficacy_lm_w;
    double diffuse_horizontal_w_m2, direct_normal_w_m2;
    double diffuse_horizontal_lx, direct_normal_lx;
    double coefficients[5];               /* a, b, c, d, e */
    int clamped;                          /* 1: an input was brought to the model's range (clamp) */
} cdl_perez_sky;

/* The Perez sky of the weather `in` (above): its clearness, brightness and
 * category, the efficacies and both illuminances and irradiances, and the
 * sky's coefficients a..e for CDL_SKY_PEREZ (emitter.h). CDL_ERR_INPUT, the
 * message naming the quantity, for inputs outside the model. */
cdl_status cdl_perez_sky_compute(const cdl_perez_input *in, cdl_perez_sky *out, cdl_error *err);

#endif
