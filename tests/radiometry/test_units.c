/* Unit types and the named conversions, against closed forms and the
 * definitions of the units. */
#include <math.h>

#include "check.h"
#include "radiometry/constants.h"
#include "radiometry/conversions.h"
#include "radiometry/units.h"

/* Double arithmetic on a handful of operations: relative error a few ulps. */
#define EXACTISH 4e-16

static void test_same_dimension_arithmetic(void)
{
    cdl_illuminance a = cdl_lux(300.0), b = cdl_lux(200.0);
    CHECK(cdl_illuminance_add(a, b).lx == 500.0);
    CHECK(cdl_illuminance_sub(a, b).lx == 100.0);
    CHECK(cdl_illuminance_scale(a, 0.5).lx == 150.0);
    CHECK(cdl_illuminance_ratio(a, b) == 1.5);
    CHECK(cdl_luminous_flux_add(cdl_lumens(1.0), cdl_lumens(2.0)).lm == 3.0);
}

static void test_isotropic_point_source(void)
{
    /* Phi = 4 pi I: 1000 cd isotropic = 4000 pi lm. */
    cdl_luminous_flux phi = cdl_isotropic_flux_from_intensity(cdl_candelas(1000.0));
    CHECK_REL(phi.lm, 4000.0 * CDL_PI, EXACTISH);
    CHECK_REL(cdl_isotropic_intensity_from_flux(phi).cd, 1000.0, EXACTISH);
    cdl_radiant_flux w = cdl_isotropic_radiant_flux_from_intensity(cdl_watts_per_sr(2.0));
    CHECK_REL(w.W, 8.0 * CDL_PI, EXACTISH);
    CHECK_REL(cdl_isotropic_radiant_intensity_from_flux(w).W_sr, 2.0, EXACTISH);
}

static void test_lambertian(void)
{
    /* M = pi L. */
    cdl_luminous_exitance m = cdl_lambertian_exitance_from_luminance(cdl_nits(100.0));
    CHECK_REL(m.lm_m2, 100.0 * CDL_PI, EXACTISH);
    CHECK_REL(cdl_lambertian_luminance_from_exitance(m).cd_m2, 100.0, EXACTISH);
    cdl_radiant_exitance me = cdl_lambertian_radiant_exitance_from_radiance(cdl_radiance_w_m2_sr(3.0));
    CHECK_REL(me.W_m2, 3.0 * CDL_PI, EXACTISH);
    CHECK_REL(cdl_lambertian_radiance_from_radiant_exitance(me).W_m2_sr, 3.0, EXACTISH);
}

static void test_inverse_square_cosine(void)
{
    /* E = I cos(theta) / d^2 over the whole range the solver must handle:
     * angles 0 to 89.9 degrees, d from 1e-4 to 1e5 m, I from 1e-6 to 1e9 cd.
     * The expected value is computed independently in long double; the result
     * must keep full double relative precision (a few ulps). */
    const double angles_deg[] = {0.0, 10.0, 45.0, 60.0, 80.0, 89.0, 89.9};
    const double distances[] = {1e-4, 1e-2, 1.0, 3.7, 1e3, 1e5};
    const double intensities[] = {1e-6, 1.0, 1234.5, 1e9};
    for (size_t a = 0; a < sizeof angles_deg / sizeof angles_deg[0]; ++a)
        for (size_t d = 0; d < sizeof distances / sizeof distances[0]; ++d)
            for (size_t i = 0; i < sizeof intensities / sizeof intensities[0]; ++i) {
                double c = cos(angles_deg[a] * CDL_DEG_TO_RAD);
                long double expected = (long double)intensities[i] * c / ((long double)distances[d] * distances[d]);
                double e = cdl_illuminance_from_intensity(cdl_candelas(intensities[i]), c, cdl_metres(distances[d])).lx;
                CHECK_REL(e, (double)expected, 1e-15);
            }
    /* Light from behind the surface gives nothing. */
    CHECK(cdl_illuminance_from_intensity(cdl_candelas(100.0), -0.5, cdl_metres(1.0)).lx == 0.0);
    /* Halving the distance quadruples the illuminance exactly. */
    double e1 = cdl_illuminance_from_intensity(cdl_candelas(500.0), 1.0, cdl_metres(2.0)).lx;
    double e2 = cdl_illuminance_from_intensity(cdl_candelas(500.0), 1.0, cdl_metres(1.0)).lx;
    CHECK(e2 == 4.0 * e1);
    CHECK_REL(cdl_irradiance_from_intensity(cdl_watts_per_sr(8.0), 0.5, cdl_metres(2.0)).W_m2, 1.0, EXACTISH);
}

static void test_imperial_units(void)
{
    /* 1 fc = 1 lm/ft^2 = 10.763910416709722 lx (ft = 0.3048 m exactly). */
    CHECK_REL(cdl_footcandles(1.0).lx, 10.763910416709722, 1e-15);
    CHECK_REL(cdl_illuminance_to_footcandles(cdl_lux(500.0)), 46.451520000000001, 1e-12);
    /* 1 fL = (1/pi) cd/ft^2 = 3.4262590996353905 cd/m^2. */
    CHECK_REL(cdl_footlamberts(1.0).cd_m2, 3.4262590996353905, 1e-15);
    /* Round trips. */
    CHECK_REL(cdl_illuminance_to_footcandles(cdl_footcandles(46.45)), 46.45, EXACTISH);
    CHECK_REL(cdl_luminance_to_footlamberts(cdl_footlamberts(2.0)), 2.0, EXACTISH);
}

static void test_efficacy(void)
{
    /* A 10 W lamp of 683 lm/W radiation gives 6830 lm; and back. */
    cdl_luminous_flux phi = cdl_luminous_flux_from_radiant(cdl_watts(10.0), cdl_lumens_per_watt(683.0));
    CHECK_REL(phi.lm, 6830.0, EXACTISH);
    CHECK_REL(cdl_radiant_flux_from_luminous(phi, cdl_lumens_per_watt(683.0)).W, 10.0, EXACTISH);
    /* Luminaire efficacy: 3000 lm from 25 W = 120 lm/W. */
    CHECK_REL(cdl_luminaire_efficacy(cdl_lumens(3000.0), cdl_electric_watts(25.0)).lm_W, 120.0, EXACTISH);
    CHECK_REL(cdl_luminance_from_radiance(cdl_radiance_w_m2_sr(2.0), cdl_lumens_per_watt(100.0)).cd_m2, 200.0,
              EXACTISH);
    CHECK_REL(cdl_illuminance_from_irradiance(cdl_irradiance_w_m2(2.0), cdl_lumens_per_watt(100.0)).lx, 200.0,
              EXACTISH);
    CHECK_REL(cdl_luminous_intensity_from_radiant(cdl_watts_per_sr(2.0), cdl_lumens_per_watt(100.0)).cd, 200.0,
              EXACTISH);
    /* 1 kWh of radiation at 90 lm/W is 3.6e6 J * 90 lm/W = 3.24e8 lm s. */
    CHECK_REL(cdl_luminous_energy_from_radiant(cdl_joules(3.6e6), cdl_lumens_per_watt(90.0)).lm_s, 3.24e8, EXACTISH);
    CHECK_REL(cdl_luminous_exitance_from_radiant(cdl_radiant_exitance_w_m2(4.0), cdl_lumens_per_watt(250.0)).lm_m2,
              1000.0, EXACTISH);
    /* Consistency of the routes: a Lambertian emitter of radiance L_e at
     * efficacy K has M_v = pi K L_e whichever conversion comes first. */
    cdl_radiance le = cdl_radiance_w_m2_sr(3.0);
    cdl_luminous_efficacy k = cdl_lumens_per_watt(300.0);
    CHECK_REL(cdl_lambertian_exitance_from_luminance(cdl_luminance_from_radiance(le, k)).lm_m2,
              cdl_luminous_exitance_from_radiant(cdl_lambertian_radiant_exitance_from_radiance(le), k).lm_m2, EXACTISH);
}

int main(void)
{
    test_same_dimension_arithmetic();
    test_isotropic_point_source();
    test_lambertian();
    test_inverse_square_cosine();
    test_imperial_units();
    test_efficacy();
    return check_finish();
}
