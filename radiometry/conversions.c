/* conversions.c - named conversions between quantities.
 *
 * The formulas are the definitions of the quantities (CIE S 017:2020, ILV:
 * intensity I = dPhi/dOmega, illuminance E = dPhi/dA, luminance
 * L = d^2Phi/(dA cos(theta) dOmega), exitance M = dPhi/dA leaving) and their
 * standard consequences, derived in every photometry text (e.g. DiLaura et
 * al., The Lighting Handbook, 10th ed., IES 2011;
 * McCluney, Introduction to Radiometry and Photometry, 2nd ed. 2014). */
#include "radiometry/conversions.h"

#include "radiometry/constants.h"

cdl_luminous_flux cdl_isotropic_flux_from_intensity(cdl_luminous_intensity intensity)
{
    /* Isotropic source: Phi = integral of I dOmega over the sphere = 4 pi I. */
    return cdl_lumens(CDL_FOUR_PI * intensity.cd);
}

cdl_luminous_intensity cdl_isotropic_intensity_from_flux(cdl_luminous_flux flux)
{
    return cdl_candelas(flux.lm / CDL_FOUR_PI);
}

cdl_radiant_flux cdl_isotropic_radiant_flux_from_intensity(cdl_radiant_intensity intensity)
{
    return cdl_watts(CDL_FOUR_PI * intensity.W_sr);
}

cdl_radiant_intensity cdl_isotropic_radiant_intensity_from_flux(cdl_radiant_flux flux)
{
    return cdl_watts_per_sr(flux.W / CDL_FOUR_PI);
}

cdl_luminous_exitance cdl_lambertian_exitance_from_luminance(cdl_luminance luminance)
{
    /* Lambertian surface (L independent of direction): M = integral over the
     * hemisphere of L cos(theta) d(omega) = L * 2 pi * 1/2 = pi L. */
    return cdl_luminous_exitance_lm_m2(CDL_PI * luminance.cd_m2);
}

cdl_luminance cdl_lambertian_luminance_from_exitance(cdl_luminous_exitance exitance)
{
    return cdl_nits(exitance.lm_m2 / CDL_PI);
}

cdl_radiant_exitance cdl_lambertian_radiant_exitance_from_radiance(cdl_radiance radiance)
{
    return cdl_radiant_exitance_w_m2(CDL_PI * radiance.W_m2_sr);
}

cdl_radiance cdl_lambertian_radiance_from_radiant_exitance(cdl_radiant_exitance exitance)
{
    return cdl_radiance_w_m2_sr(exitance.W_m2 / CDL_PI);
}

/* Inverse-square and cosine law for a point source: the solid angle of a
 * small receiving area dA at distance d is dA cos(theta) / d^2, so
 * E = I dOmega / dA = I cos(theta) / d^2. Dividing by d twice instead of by
 * d*d keeps the result finite for d down to ~1e-154 m and up to ~1e154 m. */
static double inverse_square_cosine(double intensity, double cos_theta, double d)
{
    if (cos_theta <= 0.0) return 0.0;
    return intensity * cos_theta / d / d;
}

cdl_illuminance cdl_illuminance_from_intensity(cdl_luminous_intensity intensity, double cos_theta,
                                               cdl_length distance)
{
    return cdl_lux(inverse_square_cosine(intensity.cd, cos_theta, distance.m));
}

cdl_irradiance cdl_irradiance_from_intensity(cdl_radiant_intensity intensity, double cos_theta,
                                             cdl_length distance)
{
    return cdl_irradiance_w_m2(inverse_square_cosine(intensity.W_sr, cos_theta, distance.m));
}

/* lux per foot-candle: 1 lm / (0.3048 m)^2. */
#define LUX_PER_FOOTCANDLE (1.0 / (CDL_METRES_PER_FOOT * CDL_METRES_PER_FOOT))
/* nits per foot-lambert: (1/pi) cd / (0.3048 m)^2. */
#define NITS_PER_FOOTLAMBERT (1.0 / (CDL_PI * CDL_METRES_PER_FOOT * CDL_METRES_PER_FOOT))

double cdl_illuminance_to_footcandles(cdl_illuminance illuminance)
{
    return illuminance.lx / LUX_PER_FOOTCANDLE;
}

cdl_illuminance cdl_footcandles(double footcandles)
{
    return cdl_lux(footcandles * LUX_PER_FOOTCANDLE);
}

double cdl_luminance_to_footlamberts(cdl_luminance luminance)
{
    return luminance.cd_m2 / NITS_PER_FOOTLAMBERT;
}

cdl_luminance cdl_footlamberts(double footlamberts)
{
    return cdl_nits(footlamberts * NITS_PER_FOOTLAMBERT);
}

/* Luminous efficacy of radiation: K = Phi_v / Phi_e for the spectrum the
 * efficacy was computed from (spectrum.h), so Phi_v = K Phi_e. */
cdl_luminous_flux cdl_luminous_flux_from_radiant(cdl_radiant_flux flux, cdl_luminous_efficacy efficacy)
{
    return cdl_lumens(flux.W * efficacy.lm_W);
}

/* Phi_e = Phi_v / K, the inverse of the above. */
cdl_radiant_flux cdl_radiant_flux_from_luminous(cdl_luminous_flux flux, cdl_luminous_efficacy efficacy)
{
    return cdl_watts(flux.lm / efficacy.lm_W);
}

/* Luminous efficacy of a source: eta = Phi_v / P_electric (lm/W). */
cdl_luminous_efficacy cdl_luminaire_efficacy(cdl_luminous_flux flux, cdl_electric_power power)
{
    return cdl_lumens_per_watt(flux.lm / power.W);
}

/* Q_v = K Q_e: energy is flux integrated over time, so the same K applies. */
cdl_luminous_energy cdl_luminous_energy_from_radiant(cdl_radiant_energy energy, cdl_luminous_efficacy efficacy)
{
    return cdl_lumen_seconds(energy.J * efficacy.lm_W);
}

/* M_v = K M_e: every luminous quantity is Km int V(lambda) X_e,lambda
 * d(lambda) of its radiant counterpart X_e (CIE S 017 ILV), so for one
 * spectrum the ratio is that spectrum's K. */
cdl_luminous_exitance cdl_luminous_exitance_from_radiant(cdl_radiant_exitance exitance,
                                                         cdl_luminous_efficacy efficacy)
{
    return cdl_luminous_exitance_lm_m2(exitance.W_m2 * efficacy.lm_W);
}

/* L_v = K L_e, E_v = K E_e, I_v = K I_e: the densities of one spectrum
 * share its efficacy K (see the flux conversion above). */
cdl_luminance cdl_luminance_from_radiance(cdl_radiance radiance, cdl_luminous_efficacy efficacy)
{
    return cdl_nits(radiance.W_m2_sr * efficacy.lm_W);
}

cdl_illuminance cdl_illuminance_from_irradiance(cdl_irradiance irradiance, cdl_luminous_efficacy efficacy)
{
    return cdl_lux(irradiance.W_m2 * efficacy.lm_W);
}

cdl_luminous_intensity cdl_luminous_intensity_from_radiant(cdl_radiant_intensity intensity,
                                                           cdl_luminous_efficacy efficacy)
{
    return cdl_candelas(intensity.W_sr * efficacy.lm_W);
}
