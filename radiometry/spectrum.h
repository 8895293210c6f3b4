/* spectrum.h - sampled spectra, Planck's law, and luminous efficacy.
 *
 * A cdl_spectrum is a piecewise-linear spectral distribution: `values[i]` at
 * `wavelengths_nm[i]` (strictly increasing), zero outside. The values are a
 * spectral density per nanometre (e.g. W/nm for spectral radiant flux, or any
 * relative scale when only the shape matters). The spectrum does not own its
 * arrays.
 *
 * This is the only road from radiometric to photometric quantities besides
 * a stated efficacy: K = Km * integral(V S) / integral(S).
 *
 * Units: nanometres; values per nanometre as each function says; efficacy
 * in lm/W. Ownership: a cdl_spectrum borrows its arrays, which the caller
 * keeps alive while it is used; cdl_spectrum_sample_planck fills arrays
 * the caller provides. Thread safety: no state, thread-safe. Errors: only
 * cdl_spectrum_validate and cdl_spectrum_sample_planck report them
 * (CDL_ERR_INPUT); the other functions expect a valid spectrum (validate
 * it first) and do not check.
 */
#ifndef CANDELA_RADIOMETRY_SPECTRUM_H
#define CANDELA_RADIOMETRY_SPECTRUM_H

#include <stddef.h>

#include "radiometry/cie_tables.h"
#include "base/error.h"
#include "radiometry/units.h"

typedef struct cdl_spectrum {
    size_t count;                 /* >= 2 */
    const double *wavelengths_nm; /* strictly increasing, > 0 */
    const double *values;         /* spectral density per nm, >= 0 */
} cdl_spectrum;

/* Checks the invariants above; CDL_ERR_INPUT with a message naming the index. */
cdl_status cdl_spectrum_validate(const cdl_spectrum *spectrum, cdl_error *err);

/* Maximum luminous efficacy for a vision: Km = 683 lm/W, K'm = 1700 lm/W. */
cdl_luminous_efficacy cdl_vision_max_efficacy(cdl_vision vision);

/* Integral of S(lambda) d(lambda) in (value unit) x nm, exact for the
 * piecewise-linear spectrum (trapezoid rule). */
double cdl_spectrum_integral(const cdl_spectrum *spectrum);

/* Integral of V(lambda) S(lambda) d(lambda), exact for the piecewise-linear
 * product: both factors are linear between the union of their knots, so the
 * product is quadratic there and Simpson's rule is exact. */
double cdl_spectrum_weighted_integral(const cdl_spectrum *spectrum, cdl_vision vision);

/* Luminous efficacy of radiation K = Km * int(V S) / int(S), in lm/W.
 * Returns 0 lm/W for a spectrum with no power. */
cdl_luminous_efficacy cdl_spectrum_luminous_efficacy(const cdl_spectrum *spectrum, cdl_vision vision);

/* Luminous flux of a spectrum whose values are spectral radiant flux in W/nm:
 * Phi_v = Km * int(V(lambda) Phi_e,lambda d(lambda)). */
cdl_luminous_flux cdl_spectrum_luminous_flux(const cdl_spectrum *spectral_flux_w_per_nm, cdl_vision vision);

/* Radiant flux of a spectrum whose values are W/nm: int(Phi_e,lambda d(lambda)). */
cdl_radiant_flux cdl_spectrum_radiant_flux(const cdl_spectrum *spectral_flux_w_per_nm);

/* Efficacy of monochromatic radiation: K(lambda) = Km V(lambda). */
cdl_luminous_efficacy cdl_monochromatic_efficacy(cdl_wavelength wavelength, cdl_vision vision);

/* Planck's law, spectral radiance of a blackbody per unit wavelength:
 *   L(lambda, T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1)
 * returned in W m^-2 sr^-1 nm^-1 (Planck 1901; constants CODATA 2018). */
double cdl_planck_spectral_radiance(cdl_wavelength wavelength, cdl_temperature temperature);

/* Sample Planck's law at `count` wavelengths from first_nm to last_nm
 * (inclusive, evenly spaced) into caller-owned arrays, and describe them as a
 * spectrum of spectral radiance (W m^-2 sr^-1 nm^-1). count >= 2. */
cdl_status cdl_spectrum_sample_planck(cdl_temperature temperature, double first_nm, double last_nm,
                                      size_t count, double *wavelengths_nm, double *values,
                                      cdl_spectrum *out, cdl_error *err);

#endif
