/* units.h - radiometric and photometric quantities whose units the compiler checks.
 *
 * Each quantity is a one-field struct. A function that takes a
 * cdl_luminous_intensity cannot be handed a cdl_illuminance: C does not
 * convert between distinct struct types, so the mistake is a compile error
 * (Candela's own tests compile such a mistake and require it to fail).
 *
 * Build a value with the constructor named after its unit, cdl_lux(500.0);
 * read it through the field named after its unit, e.lx. Arithmetic that keeps
 * the dimension is provided per type (add, sub, scale, ratio); everything that
 * changes the dimension is a named conversion in conversions.h, which says
 * what physics it assumes.
 *
 *   quantity                type                     field    constructor
 *   radiant energy          cdl_radiant_energy       J        cdl_joules
 *   radiant flux (power)    cdl_radiant_flux         W        cdl_watts
 *   irradiance              cdl_irradiance           W_m2     cdl_irradiance_w_m2
 *   radiant exitance        cdl_radiant_exitance     W_m2     cdl_radiant_exitance_w_m2
 *   radiant intensity       cdl_radiant_intensity    W_sr     cdl_watts_per_sr
 *   radiance                cdl_radiance             W_m2_sr  cdl_radiance_w_m2_sr
 *   luminous energy         cdl_luminous_energy      lm_s     cdl_lumen_seconds
 *   luminous flux           cdl_luminous_flux        lm       cdl_lumens
 *   illuminance             cdl_illuminance          lx       cdl_lux
 *   luminous exitance       cdl_luminous_exitance    lm_m2    cdl_luminous_exitance_lm_m2
 *   luminous intensity      cdl_luminous_intensity   cd       cdl_candelas
 *   luminance               cdl_luminance            cd_m2    cdl_nits
 *   luminous efficacy       cdl_luminous_efficacy    lm_W     cdl_lumens_per_watt
 *   electric power          cdl_electric_power       W        cdl_electric_watts
 *   solid angle             cdl_solid_angle          sr       cdl_steradians
 *   length                  cdl_length               m        cdl_metres
 *   wavelength              cdl_wavelength           nm       cdl_nanometres
 *   temperature             cdl_temperature          K        cdl_kelvin
 *
 * Irradiance and radiant exitance share a unit but not a meaning (arriving at
 * versus leaving a surface), so they are distinct types; likewise illuminance
 * and luminous exitance, radiant flux and electric power.
 *
 * Ownership: values only, nothing to free. Thread safety: every function
 * is a pure static inline function: thread-safe. Errors: none (plain IEEE
 * double arithmetic; a ratio by zero is an infinity or NaN).
 */
#ifndef CANDELA_RADIOMETRY_UNITS_H
#define CANDELA_RADIOMETRY_UNITS_H

/* Declares the struct, its constructor and its same-dimension arithmetic. */
#define CDL_DEFINE_QUANTITY(type, field, ctor)                                              \
    typedef struct type { double field; } type;                                             \
    static inline type ctor(double value) { type q; q.field = value; return q; }            \
    static inline type type##_add(type a, type b) { return ctor(a.field + b.field); }      \
    static inline type type##_sub(type a, type b) { return ctor(a.field - b.field); }      \
    static inline type type##_scale(type a, double k) { return ctor(a.field * k); }        \
    /* a / b, a pure number */                                                              \
    static inline double type##_ratio(type a, type b) { return a.field / b.field; }

CDL_DEFINE_QUANTITY(cdl_radiant_energy, J, cdl_joules)
CDL_DEFINE_QUANTITY(cdl_radiant_flux, W, cdl_watts)
CDL_DEFINE_QUANTITY(cdl_irradiance, W_m2, cdl_irradiance_w_m2)
CDL_DEFINE_QUANTITY(cdl_radiant_exitance, W_m2, cdl_radiant_exitance_w_m2)
CDL_DEFINE_QUANTITY(cdl_radiant_intensity, W_sr, cdl_watts_per_sr)
CDL_DEFINE_QUANTITY(cdl_radiance, W_m2_sr, cdl_radiance_w_m2_sr)

CDL_DEFINE_QUANTITY(cdl_luminous_energy, lm_s, cdl_lumen_seconds)
CDL_DEFINE_QUANTITY(cdl_luminous_flux, lm, cdl_lumens)
CDL_DEFINE_QUANTITY(cdl_illuminance, lx, cdl_lux)
CDL_DEFINE_QUANTITY(cdl_luminous_exitance, lm_m2, cdl_luminous_exitance_lm_m2)
CDL_DEFINE_QUANTITY(cdl_luminous_intensity, cd, cdl_candelas)
CDL_DEFINE_QUANTITY(cdl_luminance, cd_m2, cdl_nits)

CDL_DEFINE_QUANTITY(cdl_luminous_efficacy, lm_W, cdl_lumens_per_watt)
CDL_DEFINE_QUANTITY(cdl_electric_power, W, cdl_electric_watts)

CDL_DEFINE_QUANTITY(cdl_solid_angle, sr, cdl_steradians)
CDL_DEFINE_QUANTITY(cdl_length, m, cdl_metres)
CDL_DEFINE_QUANTITY(cdl_wavelength, nm, cdl_nanometres)
CDL_DEFINE_QUANTITY(cdl_temperature, K, cdl_kelvin)

#endif
