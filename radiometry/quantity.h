/* quantity.h - parse quantities as people type them: "500 lx", "46.45 fc",
 * "3000 lm", "1200 cd/m2", "2 nit", "25 W".
 *
 * A field asks for a physical dimension; the text must carry a unit of that
 * dimension. The value is returned in the SI / CIE base unit of the dimension
 * (lx, lm, cd, cd/m^2, W, m, ...). Units are case-sensitive as in SI (mW is
 * not MW), except the spelled-out words (lux, nit, candela, lumen, watt...).
 *
 *   dimension              base unit   accepted units
 *   illuminance            lx          lx lux klx fc lm/m2 lm/m^2 lm/m²
 *   luminous flux          lm          lm klm mlm lumen lumens
 *   luminous intensity     cd          cd kcd mcd candela candelas
 *   luminance              cd/m2       cd/m2 cd/m^2 cd/m² nit nits kcd/m2 fL
 *   luminous energy        lm s        lm·s lm s lms lm*s
 *   power / radiant flux   W           W mW kW watt watts
 *   irradiance             W/m2        W/m2 W/m^2 W/m² mW/m2
 *   radiant intensity      W/sr        W/sr mW/sr
 *   radiance               W/(m2 sr)   W/(m2 sr) W/m2/sr W/(m2·sr) W/m^2/sr
 *   radiant energy         J           J kJ Wh kWh
 *   luminous efficacy      lm/W        lm/W
 *   length                 m           m mm cm km ft in
 *   solid angle            sr          sr
 *   temperature            K           K
 *   wavelength             nm          nm um µm
 *
 * Ownership: the text is borrowed for the call; results go to the
 * caller's variables; dimension names are static. Thread safety: no state:
 * thread-safe. Errors: CDL_ERR_INPUT with a message saying what was found
 * and which units fit (below); *value and *out are unchanged on failure.
 */
#ifndef CANDELA_RADIOMETRY_QUANTITY_H
#define CANDELA_RADIOMETRY_QUANTITY_H

#include "base/error.h"
#include "radiometry/units.h"

typedef enum cdl_dimension {
    CDL_DIM_ILLUMINANCE,        /* also luminous exitance: lm/m^2 */
    CDL_DIM_LUMINOUS_FLUX,
    CDL_DIM_LUMINOUS_INTENSITY,
    CDL_DIM_LUMINANCE,
    CDL_DIM_LUMINOUS_ENERGY,
    CDL_DIM_POWER,              /* radiant flux and electric power */
    CDL_DIM_IRRADIANCE,         /* also radiant exitance: W/m^2 */
    CDL_DIM_RADIANT_INTENSITY,
    CDL_DIM_RADIANCE,
    CDL_DIM_RADIANT_ENERGY,
    CDL_DIM_LUMINOUS_EFFICACY,
    CDL_DIM_LENGTH,
    CDL_DIM_SOLID_ANGLE,
    CDL_DIM_TEMPERATURE,
    CDL_DIM_WAVELENGTH,
    CDL_DIM_COUNT
} cdl_dimension;

/* "illuminance", "luminous flux", ... */
const char *cdl_dimension_name(cdl_dimension dimension);

/* Parse "<number> <unit>" (space optional) expecting `dimension`; on success
 * *value is in the dimension's base unit. Errors (CDL_ERR_INPUT) say what was
 * found and list the accepted units: no number, no unit, unknown unit, or a
 * unit of another dimension ("'3000 lm' is a luminous flux; expected an
 * illuminance (lx, fc, lm/m2)"). The number is a plain decimal ("1e3" and
 * ".5" are fine): NaN, infinities, hexadecimal and overflowing numbers are
 * rejected, a decimal comma ("1,5 lx") gets a hint, and a number too small
 * for a double reads as (close to) zero. */
cdl_status cdl_quantity_parse(const char *text, cdl_dimension dimension, double *value, cdl_error *err);

/* Typed forms for the most common fields. */
cdl_status cdl_parse_illuminance(const char *text, cdl_illuminance *out, cdl_error *err);
cdl_status cdl_parse_luminous_flux(const char *text, cdl_luminous_flux *out, cdl_error *err);
cdl_status cdl_parse_luminous_intensity(const char *text, cdl_luminous_intensity *out, cdl_error *err);
cdl_status cdl_parse_luminance(const char *text, cdl_luminance *out, cdl_error *err);
cdl_status cdl_parse_radiant_flux(const char *text, cdl_radiant_flux *out, cdl_error *err);
cdl_status cdl_parse_electric_power(const char *text, cdl_electric_power *out, cdl_error *err);
cdl_status cdl_parse_length(const char *text, cdl_length *out, cdl_error *err);

#endif
