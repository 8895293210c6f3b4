/* Parsing quantities as users type them. */
#include <string.h>

#include "check.h"
#include "radiometry/conversions.h"
#include "radiometry/quantity.h"

static double parse_ok(const char *text, cdl_dimension dim)
{
    cdl_error err;
    double v = NAN;
    CHECK_OK(cdl_quantity_parse(text, dim, &v, &err), &err);
    return v;
}

static void expect_error(const char *text, cdl_dimension dim, const char *fragment)
{
    cdl_error err;
    double v = 123.0;
    cdl_status st = cdl_quantity_parse(text, dim, &v, &err);
    CHECK_MSG(st == CDL_ERR_INPUT, "'%s' gave status %d", text, (int)st);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "'%s': message '%s' lacks '%s'", text, err.message, fragment);
    CHECK(v == 123.0); /* untouched on failure */
}

int main(void)
{
    /* The examples from the issue, converted to base units. */
    CHECK(parse_ok("500 lx", CDL_DIM_ILLUMINANCE) == 500.0);
    /* 46.45 fc * 10.7639104 lx/fc = 499.98 lx. */
    CHECK_REL(parse_ok("46.45 fc", CDL_DIM_ILLUMINANCE), 46.45 / (0.3048 * 0.3048), 1e-15);
    CHECK(parse_ok("3000 lm", CDL_DIM_LUMINOUS_FLUX) == 3000.0);
    CHECK(parse_ok("1200 cd/m2", CDL_DIM_LUMINANCE) == 1200.0);
    CHECK(parse_ok("2 nit", CDL_DIM_LUMINANCE) == 2.0);
    CHECK(parse_ok("25 W", CDL_DIM_POWER) == 25.0);
    /* Spacing, prefixes, spelled-out words, exponents. */
    CHECK(parse_ok("500lx", CDL_DIM_ILLUMINANCE) == 500.0);
    CHECK(parse_ok("  1.5 klm  ", CDL_DIM_LUMINOUS_FLUX) == 1500.0);
    CHECK(parse_ok("1e3 cd", CDL_DIM_LUMINOUS_INTENSITY) == 1000.0);
    CHECK(parse_ok("12 Lux", CDL_DIM_ILLUMINANCE) == 12.0);
    CHECK(parse_ok("300 mm", CDL_DIM_LENGTH) == 0.3);
    CHECK_REL(parse_ok("10 ft", CDL_DIM_LENGTH), 3.048, 1e-15);
    CHECK_REL(parse_ok("1 fL", CDL_DIM_LUMINANCE), 3.4262590996353905, 1e-15);
    CHECK(parse_ok("120 lm/W", CDL_DIM_LUMINOUS_EFFICACY) == 120.0);
    CHECK(parse_ok("3 W/(m2 sr)", CDL_DIM_RADIANCE) == 3.0);
    CHECK(parse_ok("250 mW", CDL_DIM_POWER) == 0.25);
    CHECK(parse_ok("-3 m", CDL_DIM_LENGTH) == -3.0);

    /* Round trips through the typed conversions: what a user typed in
     * imperial units comes back unchanged (a few ulps). */
    CHECK_REL(cdl_illuminance_to_footcandles(cdl_lux(parse_ok("46.45 fc", CDL_DIM_ILLUMINANCE))), 46.45, 4e-16);
    CHECK_REL(cdl_luminance_to_footlamberts(cdl_nits(parse_ok("2.5 fL", CDL_DIM_LUMINANCE))), 2.5, 4e-16);
    CHECK_REL(parse_ok("2 nit", CDL_DIM_LUMINANCE), parse_ok("2 cd/m^2", CDL_DIM_LUMINANCE), 0.0);
    CHECK_REL(parse_ok("500 lx", CDL_DIM_ILLUMINANCE), parse_ok("0.5 klx", CDL_DIM_ILLUMINANCE), 0.0);

    /* Typed parsers deliver the typed value. */
    cdl_error err;
    cdl_illuminance e;
    CHECK_OK(cdl_parse_illuminance("750 lx", &e, &err), &err);
    CHECK(e.lx == 750.0);
    cdl_luminous_intensity i;
    CHECK_OK(cdl_parse_luminous_intensity("2 kcd", &i, &err), &err);
    CHECK(i.cd == 2000.0);

    /* Errors a person can act on. */
    expect_error("500 lxx", CDL_DIM_ILLUMINANCE, "unknown unit 'lxx'");
    expect_error("3000 lm", CDL_DIM_ILLUMINANCE, "is a luminous flux; expected an illuminance");
    expect_error("25 W", CDL_DIM_ILLUMINANCE, "is a power");
    expect_error("500", CDL_DIM_ILLUMINANCE, "missing unit");
    expect_error("lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    expect_error("nan lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    expect_error("inf lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    expect_error("1e999 lx", CDL_DIM_ILLUMINANCE, "finite number");
    expect_error("", CDL_DIM_LUMINANCE, "expected a decimal number");
    expect_error("5 MW", CDL_DIM_POWER, "unknown unit 'MW'");   /* case matters in SI */
    expect_error("5 LX", CDL_DIM_ILLUMINANCE, "unknown unit 'LX'");
    /* Only plain decimals: strtod's hexadecimal floats are not what people type. */
    expect_error("0x10 lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    expect_error("-0X1p4 lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    expect_error("+-5 lx", CDL_DIM_ILLUMINANCE, "expected a decimal number");
    /* A decimal comma gets a hint instead of "unknown unit ',5 lx'". */
    expect_error("1,5 lx", CDL_DIM_ILLUMINANCE, "expected a decimal point, found a comma (write '1.5 lx')");
    /* Underflow is a number close to zero, not an error; overflow is. */
    CHECK(parse_ok("1e-400 lx", CDL_DIM_ILLUMINANCE) == 0.0);
    CHECK(parse_ok("-1e-310 lx", CDL_DIM_ILLUMINANCE) <= 0.0);
    expect_error("-1e400 lx", CDL_DIM_ILLUMINANCE, "finite number");
    return check_finish();
}
