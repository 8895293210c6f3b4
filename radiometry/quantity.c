/* quantity.c - parsing "<number> <unit>" text into base-unit values. */
#include "radiometry/quantity.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

typedef struct unit_entry {
    const char *symbol;
    cdl_dimension dimension;
    double to_base;   /* base value = number * to_base */
    int spelled_out;  /* word units match case-insensitively */
} unit_entry;

#define FT2 (CDL_METRES_PER_FOOT * CDL_METRES_PER_FOOT)

static const unit_entry units[] = {
    {"lx", CDL_DIM_ILLUMINANCE, 1.0, 0},
    {"lux", CDL_DIM_ILLUMINANCE, 1.0, 1},
    {"klx", CDL_DIM_ILLUMINANCE, 1e3, 0},
    {"fc", CDL_DIM_ILLUMINANCE, 1.0 / FT2, 0},           /* lm/ft^2 */
    {"lm/m2", CDL_DIM_ILLUMINANCE, 1.0, 0},
    {"lm/m^2", CDL_DIM_ILLUMINANCE, 1.0, 0},
    {"lm/m\xc2\xb2", CDL_DIM_ILLUMINANCE, 1.0, 0},

    {"lm", CDL_DIM_LUMINOUS_FLUX, 1.0, 0},
    {"klm", CDL_DIM_LUMINOUS_FLUX, 1e3, 0},
    {"mlm", CDL_DIM_LUMINOUS_FLUX, 1e-3, 0},
    {"lumen", CDL_DIM_LUMINOUS_FLUX, 1.0, 1},
    {"lumens", CDL_DIM_LUMINOUS_FLUX, 1.0, 1},

    {"cd", CDL_DIM_LUMINOUS_INTENSITY, 1.0, 0},
    {"kcd", CDL_DIM_LUMINOUS_INTENSITY, 1e3, 0},
    {"mcd", CDL_DIM_LUMINOUS_INTENSITY, 1e-3, 0},
    {"candela", CDL_DIM_LUMINOUS_INTENSITY, 1.0, 1},
    {"candelas", CDL_DIM_LUMINOUS_INTENSITY, 1.0, 1},

    {"cd/m2", CDL_DIM_LUMINANCE, 1.0, 0},
    {"cd/m^2", CDL_DIM_LUMINANCE, 1.0, 0},
    {"cd/m\xc2\xb2", CDL_DIM_LUMINANCE, 1.0, 0},
    {"kcd/m2", CDL_DIM_LUMINANCE, 1e3, 0},
    {"nit", CDL_DIM_LUMINANCE, 1.0, 1},
    {"nits", CDL_DIM_LUMINANCE, 1.0, 1},
    {"fL", CDL_DIM_LUMINANCE, 1.0 / (CDL_PI * FT2), 0},   /* (1/pi) cd/ft^2 */

    {"lm s", CDL_DIM_LUMINOUS_ENERGY, 1.0, 0},
    {"lm\xc2\xb7s", CDL_DIM_LUMINOUS_ENERGY, 1.0, 0},
    {"lm*s", CDL_DIM_LUMINOUS_ENERGY, 1.0, 0},
    {"lms", CDL_DIM_LUMINOUS_ENERGY, 1.0, 0},

    {"W", CDL_DIM_POWER, 1.0, 0},
    {"mW", CDL_DIM_POWER, 1e-3, 0},
    {"kW", CDL_DIM_POWER, 1e3, 0},
    {"watt", CDL_DIM_POWER, 1.0, 1},
    {"watts", CDL_DIM_POWER, 1.0, 1},

    {"W/m2", CDL_DIM_IRRADIANCE, 1.0, 0},
    {"W/m^2", CDL_DIM_IRRADIANCE, 1.0, 0},
    {"W/m\xc2\xb2", CDL_DIM_IRRADIANCE, 1.0, 0},
    {"mW/m2", CDL_DIM_IRRADIANCE, 1e-3, 0},

    {"W/sr", CDL_DIM_RADIANT_INTENSITY, 1.0, 0},
    {"mW/sr", CDL_DIM_RADIANT_INTENSITY, 1e-3, 0},

    {"W/(m2 sr)", CDL_DIM_RADIANCE, 1.0, 0},
    {"W/(m2\xc2\xb7sr)", CDL_DIM_RADIANCE, 1.0, 0},
    {"W/(m^2 sr)", CDL_DIM_RADIANCE, 1.0, 0},
    {"W/m2/sr", CDL_DIM_RADIANCE, 1.0, 0},
    {"W/m^2/sr", CDL_DIM_RADIANCE, 1.0, 0},

    {"J", CDL_DIM_RADIANT_ENERGY, 1.0, 0},
    {"kJ", CDL_DIM_RADIANT_ENERGY, 1e3, 0},
    {"Wh", CDL_DIM_RADIANT_ENERGY, 3600.0, 0},
    {"kWh", CDL_DIM_RADIANT_ENERGY, 3.6e6, 0},

    {"lm/W", CDL_DIM_LUMINOUS_EFFICACY, 1.0, 0},

    {"m", CDL_DIM_LENGTH, 1.0, 0},
    {"mm", CDL_DIM_LENGTH, 1e-3, 0},
    {"cm", CDL_DIM_LENGTH, 1e-2, 0},
    {"km", CDL_DIM_LENGTH, 1e3, 0},
    {"ft", CDL_DIM_LENGTH, CDL_METRES_PER_FOOT, 0},
    {"in", CDL_DIM_LENGTH, CDL_METRES_PER_INCH, 0},

    {"sr", CDL_DIM_SOLID_ANGLE, 1.0, 0},
    {"K", CDL_DIM_TEMPERATURE, 1.0, 0},
    {"nm", CDL_DIM_WAVELENGTH, 1.0, 0},
    {"um", CDL_DIM_WAVELENGTH, 1e3, 0},
    {"\xc2\xb5m", CDL_DIM_WAVELENGTH, 1e3, 0},
};

static const char *dimension_names[CDL_DIM_COUNT] = {
    "illuminance", "luminous flux", "luminous intensity", "luminance", "luminous energy",
    "power", "irradiance", "radiant intensity", "radiance", "radiant energy",
    "luminous efficacy", "length", "solid angle", "temperature", "wavelength",
};

/* Units listed in messages, the common ones first. */
static const char *dimension_examples[CDL_DIM_COUNT] = {
    "lx, fc, lm/m2", "lm, klm", "cd, kcd", "cd/m2, nit, fL", "lm s",
    "W, mW, kW", "W/m2", "W/sr", "W/(m2 sr)", "J, Wh",
    "lm/W", "m, mm, cm, ft, in", "sr", "K", "nm, um",
};

const char *cdl_dimension_name(cdl_dimension dimension)
{
    return (unsigned)dimension < CDL_DIM_COUNT ? dimension_names[dimension] : "unknown dimension";
}

static const char *article(const char *word)
{
    return strchr("aeiou", word[0]) ? "an" : "a";
}

static const unit_entry *find_unit(const char *symbol)
{
    for (size_t i = 0; i < sizeof units / sizeof units[0]; ++i) {
        const unit_entry *u = &units[i];
        if (u->spelled_out ? strcasecmp(symbol, u->symbol) == 0 : strcmp(symbol, u->symbol) == 0)
            return u;
    }
    return NULL;
}

cdl_status cdl_quantity_parse(const char *text, cdl_dimension dimension, double *value, cdl_error *err)
{
    if ((unsigned)dimension >= CDL_DIM_COUNT)
        return cdl_error_set(err, CDL_ERR_USAGE, "unknown dimension %d", (int)dimension);
    const char *dim = cdl_dimension_name(dimension);
    if (!text)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected %s %s such as \"500 %s\", found nothing",
                             article(dim), dim, dimension_examples[dimension]);
    const char *p = text;
    while (isspace((unsigned char)*p)) ++p;
    /* strtod would accept "nan", "inf" and hexadecimal ("0x1p4"): refuse
     * anything but a plain decimal number. */
    const char *digits = p + (*p == '-' || *p == '+');
    int hexadecimal = digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X');
    if (!(isdigit((unsigned char)*digits) || *digits == '.') || hexadecimal)
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': expected a decimal number followed by a unit of %s (%s)",
                             text, dim, dimension_examples[dimension]);
    errno = 0;
    char *end = NULL;
    double number = strtod(p, &end);
    /* ERANGE on a result of magnitude below 1 is underflow: the number is
     * (close to) zero and strtod returns it; only overflow is refused. */
    if (end == p || !isfinite(number) || (errno == ERANGE && fabs(number) >= 1.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': expected a finite number followed by a unit of %s (%s)",
                             text, dim, dimension_examples[dimension]);
    if (*end == ',' && isdigit((unsigned char)end[1]))
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': expected a decimal point, found a comma (write '%.*s.%s')",
                             text, (int)(end - text), text, end + 1);

    /* The unit: the rest, without surrounding blanks. */
    while (isspace((unsigned char)*end)) ++end;
    char symbol[64];
    size_t n = strlen(end);
    while (n > 0 && isspace((unsigned char)end[n - 1])) --n;
    if (n == 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': missing unit; expected a unit of %s (%s)", text, dim,
                             dimension_examples[dimension]);
    if (n >= sizeof symbol)
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': unknown unit; expected a unit of %s (%s)", text, dim,
                             dimension_examples[dimension]);
    memcpy(symbol, end, n);
    symbol[n] = '\0';

    const unit_entry *u = find_unit(symbol);
    if (!u)
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': unknown unit '%s'; expected a unit of %s (%s)", text,
                             symbol, dim, dimension_examples[dimension]);
    if (u->dimension != dimension) {
        const char *found = cdl_dimension_name(u->dimension);
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s' is %s %s; expected %s %s (%s)", text, article(found), found,
                             article(dim), dim, dimension_examples[dimension]);
    }
    double v = number * u->to_base;
    if (!isfinite(v))
        return cdl_error_set(err, CDL_ERR_INPUT, "'%s': value out of range", text);
    *value = v;
    return CDL_OK;
}

#define TYPED_PARSER(fn, type, dim, ctor)                                         \
    cdl_status fn(const char *text, type *out, cdl_error *err)                     \
    {                                                                              \
        double v;                                                                  \
        cdl_status st = cdl_quantity_parse(text, dim, &v, err);                    \
        if (st == CDL_OK) *out = ctor(v);                                          \
        return st;                                                                 \
    }

TYPED_PARSER(cdl_parse_illuminance, cdl_illuminance, CDL_DIM_ILLUMINANCE, cdl_lux)
TYPED_PARSER(cdl_parse_luminous_flux, cdl_luminous_flux, CDL_DIM_LUMINOUS_FLUX, cdl_lumens)
TYPED_PARSER(cdl_parse_luminous_intensity, cdl_luminous_intensity, CDL_DIM_LUMINOUS_INTENSITY, cdl_candelas)
TYPED_PARSER(cdl_parse_luminance, cdl_luminance, CDL_DIM_LUMINANCE, cdl_nits)
TYPED_PARSER(cdl_parse_radiant_flux, cdl_radiant_flux, CDL_DIM_POWER, cdl_watts)
TYPED_PARSER(cdl_parse_electric_power, cdl_electric_power, CDL_DIM_POWER, cdl_electric_watts)
TYPED_PARSER(cdl_parse_length, cdl_length, CDL_DIM_LENGTH, cdl_metres)
