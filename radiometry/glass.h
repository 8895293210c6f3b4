/* glass.h - the transmittance of a thin pane of glass, by angle of incidence.
 *
 * A pane of refractive index n = 1.52 in air, its two faces smooth and
 * parallel, its thickness far above the coherence length of daylight (no
 * interference), transmits at incidence theta
 *     T(theta) = 1/2 sum over s and p polarisation of
 *                tau (1 - r)^2 / (1 - r^2 tau^2),
 * the sum of the light passing straight through and after every even
 * number of reflections inside the pane (a geometric series), where
 *  - r is the Fresnel reflectance of one face for that polarisation,
 *    r_s = ((cos theta - n cos theta_t) / (cos theta + n cos theta_t))^2,
 *    r_p = ((cos theta_t - n cos theta) / (cos theta_t + n cos theta))^2,
 *    sin theta_t = sin theta / n (Snell) (Born and Wolf, "Principles of
 *    Optics", 7th ed., 1.5.2);
 *  - tau = a^(1 / cos theta_t) is the pane's internal transmittance along
 *    the slanted path, a the one at normal incidence (Bouguer-Lambert);
 * (Duffie and Beckman, "Solar Engineering of Thermal Processes", 4th ed.,
 * 2013, 5.1-5.3; Radiance's `glass` material computes the same, Ward,
 * "The RADIANCE Lighting Simulation and Rendering System", SIGGRAPH 1994,
 * and the Radiance reference manual). A pane is given by its normal
 * transmittance T_n, as glazing data sheets give it; a follows from
 *     T_n = a (1 - r0)^2 / (1 - r0^2 a^2),  r0 = ((n - 1) / (n + 1))^2,
 * the positive root of r0^2 T_n a^2 + (1 - r0)^2 a - T_n = 0 (Radiance's
 * transmissivity from transmittance). T_n is at most (1 - r0) / (1 + r0)
 * = 0.9183 (clear glass without absorption).
 *
 * Only the transmitted part is modelled: the light a pane reflects
 * (specularly, 8 % at normal incidence) is not followed.
 *
 * Thread safety: pure. Errors: CDL_ERR_INPUT for a T_n outside (0, 0.9183].
 */
#ifndef CANDELA_RADIOMETRY_GLASS_H
#define CANDELA_RADIOMETRY_GLASS_H

#include "base/error.h"

/* The refractive index of soda-lime glass that Radiance's `glass` takes. */
#define CDL_GLASS_INDEX 1.52

typedef struct cdl_glass {
    double normal_transmittance;          /* T_n */
    double internal;                      /* a: the internal transmittance at normal incidence */
} cdl_glass;

/* The largest normal transmittance of a pane of index CDL_GLASS_INDEX. */
double cdl_glass_max_transmittance(void);

/* A pane of normal transmittance T_n (0 < T_n <= cdl_glass_max_transmittance()). */
cdl_status cdl_glass_from_transmittance(double normal_transmittance, cdl_glass *out, cdl_error *err);

/* T at incidence cos_theta = |cos| of the angle to the pane's normal, in
 * [0, 1] (either side); 0 at grazing incidence, T_n at normal. */
double cdl_glass_transmittance(const cdl_glass *glass, double cos_theta);

#endif
