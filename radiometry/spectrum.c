/* spectrum.c - sampled spectra, Planck's law, luminous efficacy. */
#include "radiometry/spectrum.h"

#include <math.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

cdl_status cdl_spectrum_validate(const cdl_spectrum *s, cdl_error *err)
{
    if (!s || s->count < 2 || !s->wavelengths_nm || !s->values)
        return cdl_error_set(err, CDL_ERR_INPUT, "a spectrum needs at least two samples");
    for (size_t i = 0; i < s->count; ++i) {
        double w = s->wavelengths_nm[i], v = s->values[i];
        if (!isfinite(w) || w <= 0.0)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "spectrum sample %zu: expected a positive wavelength in nm, found %g", i, w);
        if (!isfinite(v) || v < 0.0)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "spectrum sample %zu: expected a finite value >= 0, found %g", i, v);
        if (i > 0 && !(w > s->wavelengths_nm[i - 1]))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "spectrum sample %zu: wavelengths must increase (%g nm after %g nm)", i, w,
                                 s->wavelengths_nm[i - 1]);
    }
    return CDL_OK;
}

cdl_luminous_efficacy cdl_vision_max_efficacy(cdl_vision vision)
{
    return cdl_lumens_per_watt(vision == CDL_VISION_SCOTOPIC ? CDL_KM_SCOTOPIC_LM_PER_W
                                                             : CDL_KM_PHOTOPIC_LM_PER_W);
}

/* Piecewise-linear value of the spectrum at lambda (zero outside). */
static double spectrum_value(const cdl_spectrum *s, double lambda)
{
    const double *w = s->wavelengths_nm;
    if (lambda < w[0] || lambda > w[s->count - 1]) return 0.0;
    size_t lo = 0, hi = s->count - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (w[mid] <= lambda) lo = mid; else hi = mid;
    }
    double t = (lambda - w[lo]) / (w[hi] - w[lo]);
    return s->values[lo] + t * (s->values[hi] - s->values[lo]);
}

double cdl_spectrum_integral(const cdl_spectrum *s)
{
    double sum = 0.0;
    for (size_t i = 1; i < s->count; ++i)
        sum += 0.5 * (s->values[i] + s->values[i - 1]) * (s->wavelengths_nm[i] - s->wavelengths_nm[i - 1]);
    return sum;
}

double cdl_spectrum_weighted_integral(const cdl_spectrum *s, cdl_vision vision)
{
    const cdl_cie_table *t = cdl_cie_luminous_efficiency_table(vision);
    double table_last = t->first_nm + t->step_nm * (double)(t->count - 1);
    double lo = fmax(s->wavelengths_nm[0], t->first_nm);
    double hi = fmin(s->wavelengths_nm[s->count - 1], table_last);
    if (!(hi > lo)) return 0.0;

    /* Walk the merged knot sequence of the spectrum and the table. */
    size_t si = 0;
    while (si < s->count && s->wavelengths_nm[si] <= lo) ++si;
    double tk = ceil((lo - t->first_nm) / t->step_nm);
    double next_table = t->first_nm + tk * t->step_nm;
    if (next_table <= lo) next_table += t->step_nm;

    double sum = 0.0, a = lo;
    while (a < hi) {
        double b = hi;
        if (si < s->count && s->wavelengths_nm[si] < b) b = s->wavelengths_nm[si];
        if (next_table < b) b = next_table;
        /* Simpson's rule, exact for the quadratic product on [a, b]. */
        double m = 0.5 * (a + b);
        double fa = spectrum_value(s, a) * cdl_cie_table_value(t, a);
        double fm = spectrum_value(s, m) * cdl_cie_table_value(t, m);
        double fb = spectrum_value(s, b) * cdl_cie_table_value(t, b);
        sum += (b - a) / 6.0 * (fa + 4.0 * fm + fb);
        a = b;
        while (si < s->count && s->wavelengths_nm[si] <= a) ++si;
        while (next_table <= a) next_table += t->step_nm;
    }
    return sum;
}

cdl_luminous_efficacy cdl_spectrum_luminous_efficacy(const cdl_spectrum *s, cdl_vision vision)
{
    double total = cdl_spectrum_integral(s);
    if (!(total > 0.0)) return cdl_lumens_per_watt(0.0);
    double km = cdl_vision_max_efficacy(vision).lm_W;
    return cdl_lumens_per_watt(km * cdl_spectrum_weighted_integral(s, vision) / total);
}

cdl_luminous_flux cdl_spectrum_luminous_flux(const cdl_spectrum *s, cdl_vision vision)
{
    return cdl_lumens(cdl_vision_max_efficacy(vision).lm_W * cdl_spectrum_weighted_integral(s, vision));
}

cdl_radiant_flux cdl_spectrum_radiant_flux(const cdl_spectrum *s)
{
    return cdl_watts(cdl_spectrum_integral(s));
}

cdl_luminous_efficacy cdl_monochromatic_efficacy(cdl_wavelength wavelength, cdl_vision vision)
{
    return cdl_lumens_per_watt(cdl_vision_max_efficacy(vision).lm_W *
                               cdl_cie_luminous_efficiency(vision, wavelength));
}

double cdl_planck_spectral_radiance(cdl_wavelength wavelength, cdl_temperature temperature)
{
    double lambda = wavelength.nm * 1e-9; /* m */
    double T = temperature.K;
    if (!(lambda > 0.0) || !(T > 0.0)) return 0.0;
    double x = CDL_PLANCK_H * CDL_SPEED_OF_LIGHT / (lambda * CDL_BOLTZMANN_K * T);
    /* expm1 keeps the Rayleigh-Jeans end (x -> 0) accurate. */
    double denom = expm1(x);
    if (!isfinite(denom)) return 0.0;
    double l5 = lambda * lambda * lambda * lambda * lambda;
    double per_metre = 2.0 * CDL_PLANCK_H * CDL_SPEED_OF_LIGHT * CDL_SPEED_OF_LIGHT / l5 / denom;
    return per_metre * 1e-9; /* per metre of wavelength -> per nanometre */
}

cdl_status cdl_spectrum_sample_planck(cdl_temperature temperature, double first_nm, double last_nm,
                                      size_t count, double *wavelengths_nm, double *values,
                                      cdl_spectrum *out, cdl_error *err)
{
    if (count < 2 || !(first_nm > 0.0) || !(last_nm > first_nm))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "Planck sampling needs count >= 2 and 0 < first_nm < last_nm");
    if (!(temperature.K > 0.0) || !isfinite(temperature.K))
        return cdl_error_set(err, CDL_ERR_INPUT, "Planck temperature must be > 0 K, found %g K", temperature.K);
    for (size_t i = 0; i < count; ++i) {
        double w = first_nm + (last_nm - first_nm) * (double)i / (double)(count - 1);
        wavelengths_nm[i] = w;
        values[i] = cdl_planck_spectral_radiance(cdl_nanometres(w), temperature);
    }
    out->count = count;
    out->wavelengths_nm = wavelengths_nm;
    out->values = values;
    return CDL_OK;
}
