/* conversions.h - named conversions between quantities, each with its physics.
 *
 * Radiometric <-> photometric conversion exists only through an explicit
 * luminous efficacy (here) or an explicit spectrum (spectrum.h): there is no
 * hidden 683, 179 or 177.83 anywhere in Candela.
 *
 * Units: in the types (units.h) and, for plain doubles, in the names.
 * Ownership: values only. Thread safety: pure functions, thread-safe.
 * Errors: none reported; inputs outside a formula's domain (a distance
 * <= 0, a zero efficacy) are not checked and give what the formula gives
 * (an infinity or NaN).
 */
#ifndef CANDELA_RADIOMETRY_CONVERSIONS_H
#define CANDELA_RADIOMETRY_CONVERSIONS_H

#include "radiometry/units.h"

/* --- Isotropic point source: Phi = 4 pi I (the sphere subtends 4 pi sr). */
cdl_luminous_flux cdl_isotropic_flux_from_intensity(cdl_luminous_intensity intensity);
cdl_luminous_intensity cdl_isotropic_intensity_from_flux(cdl_luminous_flux flux);
cdl_radiant_flux cdl_isotropic_radiant_flux_from_intensity(cdl_radiant_intensity intensity);
cdl_radiant_intensity cdl_isotropic_radiant_intensity_from_flux(cdl_radiant_flux flux);

/* --- Lambertian surface: M = pi L (integral of L cos(theta) over the hemisphere). */
cdl_luminous_exitance cdl_lambertian_exitance_from_luminance(cdl_luminance luminance);
cdl_luminance cdl_lambertian_luminance_from_exitance(cdl_luminous_exitance exitance);
cdl_radiant_exitance cdl_lambertian_radiant_exitance_from_radiance(cdl_radiance radiance);
cdl_radiance cdl_lambertian_radiance_from_radiant_exitance(cdl_radiant_exitance exitance);

/* --- Inverse-square and cosine law for a point source:
 *     E = I cos(theta) / d^2, theta the angle between the incoming direction
 *     and the receiving surface's normal. cos_theta <= 0 (light from behind)
 *     gives 0. d must be > 0. */
cdl_illuminance cdl_illuminance_from_intensity(cdl_luminous_intensity intensity, double cos_theta,
                                               cdl_length distance);
cdl_irradiance cdl_irradiance_from_intensity(cdl_radiant_intensity intensity, double cos_theta,
                                             cdl_length distance);

/* --- Imperial photometric units.
 * 1 fc = 1 lm/ft^2 = 1/0.3048^2 lx = 10.763910416709722 lx.
 * 1 fL = (1/pi) cd/ft^2 = 1/(pi 0.3048^2) cd/m^2 = 3.4262590996353905 cd/m^2. */
double cdl_illuminance_to_footcandles(cdl_illuminance illuminance);
cdl_illuminance cdl_footcandles(double footcandles);
double cdl_luminance_to_footlamberts(cdl_luminance luminance);
cdl_luminance cdl_footlamberts(double footlamberts);

/* --- Efficacy.
 * Luminous efficacy of radiation K = Phi_v / Phi_e (lm/W), from a spectrum
 * (spectrum.h) or stated. Luminaire (source) efficacy = Phi_v / P_electric. */
cdl_luminous_flux cdl_luminous_flux_from_radiant(cdl_radiant_flux flux, cdl_luminous_efficacy efficacy);
cdl_radiant_flux cdl_radiant_flux_from_luminous(cdl_luminous_flux flux, cdl_luminous_efficacy efficacy);
cdl_luminous_efficacy cdl_luminaire_efficacy(cdl_luminous_flux flux, cdl_electric_power power);

/* Same conversions for energy and the densities, with the same efficacy K
 * (each photometric quantity is the V-weighted integral of its radiometric
 * counterpart, so one K serves for a given spectrum):
 * Q_v = K Q_e, L_v = K L_e, E_v = K E_e, M_v = K M_e, I_v = K I_e. */
cdl_luminous_energy cdl_luminous_energy_from_radiant(cdl_radiant_energy energy, cdl_luminous_efficacy efficacy);
cdl_luminous_exitance cdl_luminous_exitance_from_radiant(cdl_radiant_exitance exitance,
                                                         cdl_luminous_efficacy efficacy);
cdl_luminance cdl_luminance_from_radiance(cdl_radiance radiance, cdl_luminous_efficacy efficacy);
cdl_illuminance cdl_illuminance_from_irradiance(cdl_irradiance irradiance, cdl_luminous_efficacy efficacy);
cdl_luminous_intensity cdl_luminous_intensity_from_radiant(cdl_radiant_intensity intensity,
                                                           cdl_luminous_efficacy efficacy);

#endif
