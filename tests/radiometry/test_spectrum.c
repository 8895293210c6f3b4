/* CIE tables, spectra, Planck's law and luminous efficacy against published
 * values and closed forms. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "radiometry/cie_tables.h"
#include "radiometry/constants.h"
#include "radiometry/spectrum.h"

static void test_tables(void)
{
    /* Published anchor values of V(lambda) and V'(lambda). */
    CHECK(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(555.0)) == 1.0);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(360.0)), 3.917e-6, 1e-12);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(830.0)), 4.5181e-7, 1e-12);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(500.0)), 0.323, 1e-12);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(650.0)), 0.107, 1e-12);
    CHECK(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(359.0)) == 0.0);
    CHECK(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(831.0)) == 0.0);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_SCOTOPIC, cdl_nanometres(380.0)), 5.89e-4, 1e-12);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_SCOTOPIC, cdl_nanometres(505.0)), 0.998, 1e-12);
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_SCOTOPIC, cdl_nanometres(555.0)), 0.402, 1e-12);
    CHECK(cdl_cie_luminous_efficiency(CDL_VISION_SCOTOPIC, cdl_nanometres(790.0)) == 0.0);
    /* Interpolation is linear between 1 nm samples. */
    CHECK_REL(cdl_cie_luminous_efficiency(CDL_VISION_PHOTOPIC, cdl_nanometres(555.5)), 0.5 * (1.0 + 0.9998567), 1e-12);

    /* Integral of V(lambda) over 360-830 nm = 106.857 nm (the colorimetric
     * normalising constant, given to 3 decimals): the trapezoid rule on the
     * 1 nm table gives 106.85691; tolerance half a unit in the last place. */
    double wl[2] = {360.0, 830.0}, flat[2] = {1.0, 1.0};
    cdl_spectrum equal_energy = {2, wl, flat};
    CHECK_ABS(cdl_spectrum_weighted_integral(&equal_energy, CDL_VISION_PHOTOPIC), 106.857, 5e-4);
}

static void test_efficacy(void)
{
    /* Monochromatic 555 nm: 683 lm/W (V = 1 there). */
    CHECK_REL(cdl_monochromatic_efficacy(cdl_nanometres(555.0), CDL_VISION_PHOTOPIC).lm_W, 683.0, 1e-15);
    /* And a narrow triangle spectrum centred on 555 nm (width 0.2 nm): V is
     * linear across it, so K = 683 * average V = 683 * (V(554.9)+V(555.1))/2...
     * exactly 683 * V at the centroid of each half; close to 683 within the
     * curvature of V over 0.1 nm (< 1e-5 relative). */
    double wl[3] = {554.9, 555.0, 555.1}, tri[3] = {0.0, 1.0, 0.0};
    cdl_spectrum narrow = {3, wl, tri};
    CHECK_REL(cdl_spectrum_luminous_efficacy(&narrow, CDL_VISION_PHOTOPIC).lm_W, 683.0, 1e-5);

    /* Equal-energy spectrum over 360-830 nm: K = 683 * int V / 470 nm, with
     * int V = 106.857 nm -> 155.29 lm/W; exact for the piecewise-linear forms. */
    double e_wl[2] = {360.0, 830.0}, flat[2] = {2.5, 2.5};
    cdl_spectrum equal_energy = {2, e_wl, flat};
    double K = cdl_spectrum_luminous_efficacy(&equal_energy, CDL_VISION_PHOTOPIC).lm_W;
    CHECK_REL(K, 683.0 * 106.857 / 470.0, 5e-6);
    /* Its flux: 2.5 W/nm over 470 nm = 1175 W, times K. */
    CHECK_REL(cdl_spectrum_radiant_flux(&equal_energy).W, 1175.0, 1e-14);
    CHECK_REL(cdl_spectrum_luminous_flux(&equal_energy, CDL_VISION_PHOTOPIC).lm, 1175.0 * K, 1e-12);

    /* Scotopic peak region: K'(505) = 1700 * 0.998. */
    CHECK_REL(cdl_monochromatic_efficacy(cdl_nanometres(505.0), CDL_VISION_SCOTOPIC).lm_W, 1700.0 * 0.998, 1e-14);

    /* A spectrum entirely outside the visible has no luminous flux. */
    double ir_wl[2] = {900.0, 1000.0}, ir[2] = {1.0, 1.0};
    cdl_spectrum infrared = {2, ir_wl, ir};
    CHECK(cdl_spectrum_luminous_efficacy(&infrared, CDL_VISION_PHOTOPIC).lm_W == 0.0);
}

static void test_planck(void)
{
    /* Stefan-Boltzmann: pi * int L(lambda, T) d(lambda) = sigma T^4. The
     * integral is taken numerically over 50 nm .. 1 mm on a log grid (10^5
     * intervals, Simpson); outside that range the tails hold < 1e-9 of the
     * power at 3000 K, so 1e-6 is a comfortable tolerance. */
    const double T = 3000.0;
    const int n = 100000;
    double a = log(50.0), b = log(1e6), h = (b - a) / n, sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        double x = a + h * i, lambda = exp(x);
        double f = cdl_planck_spectral_radiance(cdl_nanometres(lambda), cdl_kelvin(T)) * lambda;
        double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * f;
    }
    double radiance = sum * h / 3.0;
    CHECK_REL(CDL_PI * radiance, CDL_STEFAN_BOLTZMANN * T * T * T * T, 1e-6);

    /* Wien's displacement law: the peak lies at b / T (966 nm at 3000 K).
     * Golden-section search to 1e-6 nm. */
    double lo = 500.0, hi = 1500.0;
    const double g = 0.6180339887498949;
    while (hi - lo > 1e-6) {
        double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
        if (cdl_planck_spectral_radiance(cdl_nanometres(m1), cdl_kelvin(T)) <
            cdl_planck_spectral_radiance(cdl_nanometres(m2), cdl_kelvin(T)))
            lo = m1;
        else
            hi = m2;
    }
    CHECK_REL(0.5 * (lo + hi), CDL_WIEN_B / T * 1e9, 1e-7);

    /* Sampling into a spectrum and taking its efficacy. A blackbody at
     * 6500 K has a luminous efficacy of radiation near 95 lm/W and at
     * 2856 K (CIE illuminant A) near 15-16 lm/W over all wavelengths; here
     * only 360-830 nm is sampled, so efficacies are of the visible part:
     * they must sit between the full-spectrum value and 683 lm/W. */
    double wl[471], val[471];
    cdl_spectrum s;
    cdl_error err;
    CHECK_OK(cdl_spectrum_sample_planck(cdl_kelvin(2856.0), 360.0, 830.0, 471, wl, val, &s, &err), &err);
    double K_visible = cdl_spectrum_luminous_efficacy(&s, CDL_VISION_PHOTOPIC).lm_W;
    CHECK_MSG(K_visible > 100.0 && K_visible < 683.0, "K_visible = %g", K_visible);
    CHECK(cdl_spectrum_sample_planck(cdl_kelvin(-1.0), 360.0, 830.0, 471, wl, val, &s, &err) == CDL_ERR_INPUT);
}

static void test_validation(void)
{
    cdl_error err;
    double wl[3] = {400.0, 500.0, 450.0}, v[3] = {1.0, 1.0, 1.0};
    cdl_spectrum bad = {3, wl, v};
    CHECK(cdl_spectrum_validate(&bad, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "sample 2") != NULL, "%s", err.message);
    double wl2[2] = {400.0, 500.0}, v2[2] = {1.0, NAN};
    cdl_spectrum nan_value = {2, wl2, v2};
    CHECK(cdl_spectrum_validate(&nan_value, &err) == CDL_ERR_INPUT);
    double v3[2] = {1.0, 2.0};
    cdl_spectrum good = {2, wl2, v3};
    CHECK_OK(cdl_spectrum_validate(&good, &err), &err);
}

int main(void)
{
    test_tables();
    test_efficacy();
    test_planck();
    test_validation();
    return check_finish();
}
