/* sky_distribution.h - skies whose luminance is a gradation times an
 * indicatrix: the CIE standard general skies and the Perez all-weather sky
 * (private to lights/; the emitter is emitter_environment.c).
 *
 * Both describe the luminance of a sky element at zenith angle Z and at
 * angular distance chi from the sun (sun at zenith angle Z_s) as
 *     L(Z, chi) = L_z phi(Z) f(chi) / (phi(0) f(Z_s)),
 *     phi(Z)   = 1 + a exp(b / cos Z)                       (gradation),
 *     f(chi)   = 1 + c (exp(d chi) - k) + e cos^2 chi        (indicatrix),
 * L_z the zenith luminance:
 *  - the CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003,
 *    Kittler, Darula and Perez 1998): 15 types, each a row (a, b, c, d, e)
 *    of the standard's Table 1 (cdl_sky_cie_parameters), k = exp(d pi / 2)
 *    so that f(pi / 2) = 1 + e cos^2(pi / 2) = 1; nothing below the horizon
 *    (phi(90 deg) = 1 as b < 0);
 *  - the Perez all-weather sky (Perez, Seals and Michalsky, Solar Energy
 *    50(3), 1993, eq. 1), k = 0, its coefficients from perez_sky.h. Its
 *    luminance can come out negative for some coefficients; it is taken
 *    as 0 there, as Radiance's gendaylit and gendaymtx do.
 *
 * Illuminance on a plane of unit normal n, nothing in the way:
 *     E(n) = int over {up.w > 0, n.w > 0} of L(w) (n.w) dw,
 * by Gauss-Legendre quadrature in coordinates about the sun (chi its polar
 * angle, psi its azimuth), where the integrand is smooth: along each
 * meridian from the sun, up.w and n.w are each A cos chi + B sin chi and
 * change sign once, so the domain is one interval [chi_lo(psi),
 * chi_hi(psi)] found in closed form, and the peak of exp(d chi) at the
 * sun is no kink there. The intervals' ends are smooth in psi except where
 * the binding constraint changes (the directions +-(up x n), where the
 * horizon and the plane's edge cross) and where a constraint's meridian
 * component B changes sign; psi is cut into panels at those angles, each
 * in parts of at most pi / 4. Each chi interval is mapped by the smoothstep
 * chi = lo + (hi - lo)(3 t^2 - 2 t^3), whose Jacobian vanishes at both
 * ends (the gradation's exp(b / cos Z) is flat but not analytic at the
 * horizon), and cut in 3 parts (6 where longer than 1 rad). Every part
 * takes a CDL_SKY_QUADRATURE_POINTS-point Gauss-Legendre rule: within
 * 3.2e-8 of an independent quadrature in zenith and azimuth for every CIE
 * type, horizontal and vertical planes (tests/lights/environment/
 * test_sky_distribution.c), in about 0.19 ms a plane (against 4e-6 with
 * equal parts and no map at 0.13 ms).
 *
 * Thread safety: immutable after cdl_sky_distribution_init; every query is
 * pure. No allocation.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_SKY_DISTRIBUTION_H
#define CANDELA_LIGHTS_ENVIRONMENT_SKY_DISTRIBUTION_H

#include "base/error.h"
#include "radiometry/frame.h"
#include "radiometry/vec3.h"

#define CDL_SKY_QUADRATURE_POINTS 12

/* The standard's 15 types (1 .. 15). */
#define CDL_SKY_CIE_TYPES 15

typedef struct cdl_sky_distribution {
    cdl_frame frame;                      /* n: up; s: azimuth reference */
    cdl_vec3 sun;                         /* unit, towards the sun */
    cdl_frame sun_frame;                  /* n: sun */
    double a, b, c, d, e, k;              /* gradation and indicatrix */
    double scale;                         /* cd/m^2 per unit of phi f: L_z / (phi(0) f(Z_s)) */
    int clamp;                            /* 1: negative values are 0 (Perez) */
    double sun_weight;                    /* share of samples drawn about the sun (cdl_sky_distribution_sample) */
    double gl_x[CDL_SKY_QUADRATURE_POINTS], gl_w[CDL_SKY_QUADRATURE_POINTS]; /* on [0, 1] */
} cdl_sky_distribution;

/* The ISO 15469 Table 1 row of a type (1 .. 15) as {a, b, c, d, e};
 * 0 for a type out of range. */
int cdl_sky_cie_parameters(int type, double out[5]);

/* A CIE type uses the sun's place (its indicatrix is not constant): every
 * type but 1, 3 and 5 (c = e = 0). */
int cdl_sky_cie_type_uses_sun(int type);

/* Set up a sky of scale 1 (then cdl_sky_distribution_scale_to): up and
 * sun unit (the sun above the horizon, up.sun > 0, unless the indicatrix
 * is constant, c = e = 0), azimuth reference (unit, perpendicular to up),
 * coefficients {a, b, c, d, e}, k and clamp as above. CDL_ERR_INPUT (the
 * caller prefixes the JSON path) when the sun is below the horizon where
 * it matters, b >= 0 (the luminance would grow without bound towards the
 * horizon), or the sky gives no light at all. */
cdl_status cdl_sky_distribution_init(cdl_sky_distribution *sky, cdl_vec3 up, cdl_vec3 azimuth_ref, cdl_vec3 sun,
                                     const double coefficients[5], double k, int clamp, cdl_error *err);

/* Scale the sky to a zenith luminance (zenith_cd_m2 >= 0, horizontal_lx
 * < 0) or to an unobstructed horizontal illuminance (horizontal_lx >= 0):
 * scale = L_z / (phi(0) f(Z_s)), or E_h / int phi f cos Z dw.
 * CDL_ERR_INPUT when a zenith luminance is asked of a sky whose formula is
 * 0 or below at the zenith. */
cdl_status cdl_sky_distribution_scale_to(cdl_sky_distribution *sky, double zenith_cd_m2, double horizontal_lx,
                                         cdl_error *err);

/* The zenith luminance, cd/m^2. */
double cdl_sky_distribution_zenith(const cdl_sky_distribution *sky);

/* L(w), cd/m^2, towards unit world w (0 below the horizon). */
double cdl_sky_distribution_luminance(const cdl_sky_distribution *sky, cdl_vec3 w);

/* E on the plane of unit normal n with nothing in the way, lx. */
double cdl_sky_distribution_illuminance(const cdl_sky_distribution *sky, cdl_vec3 n);

/* Bounds on L over a convex spherical polygon of unit world directions
 * (count >= 3): from the polygon's range of cos Z and of chi (its extent
 * in the frames of up and of the sun), each factor bounded over them. */
void cdl_sky_distribution_bounds(const cdl_sky_distribution *sky, const cdl_vec3 *dirs, int count, double *lo,
                                 double *hi);

/* A direction for a receiver of unit normal n from (u1, u2) in [0, 1)^2: a
 * mixture of the cosine-weighted hemisphere about n and, with probability
 * sun_weight, a density falling as exp(-lambda chi) about the sun
 * (lambda = max(1, |d|)), and the mixture's pdf in solid angle (> 0 where
 * either part can draw the direction). */
cdl_vec3 cdl_sky_distribution_sample(const cdl_sky_distribution *sky, cdl_vec3 n, double u1, double u2, double *pdf);

/* The pdf of cdl_sky_distribution_sample drawing w for normal n. */
double cdl_sky_distribution_pdf(const cdl_sky_distribution *sky, cdl_vec3 n, cdl_vec3 w);

#endif
