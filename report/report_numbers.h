/* report_numbers.h - numbers printed with the precision their stated error justifies.
 *
 * A value v with standard uncertainty u > 0 is printed to the decimal
 * place of u's leading digit: 10^floor(log10 u) is the last unit printed,
 * so the rounding (half that unit) stays below half the stated error, and
 * no digit is printed that the error makes meaningless. Never more than 6
 * significant digits, never fewer than 0 decimals (lux are not rounded to
 * tens: the table says the error beside them). A value computed exactly
 * (u = 0: closed forms, exact direct light) gets 4 significant digits.
 *
 * The uncertainty of the statistics of a grid with relative stated errors
 * r_mean (area-weighted mean over the points) and r_max (worst point):
 *   Em:        u = Em r_mean   (the points' errors taken fully correlated,
 *                               as an interpolating cache makes them: an
 *                               upper bound on the error of the mean)
 *   Emin, Emax: u = E r_max
 *   U0 = Emin / Em:   u = U0 (r_max + r_mean)  (relative errors of a ratio
 *   Ud = Emin / Emax: u = Ud (2 r_max)          add, at worst)
 */
#ifndef CANDELA_REPORT_NUMBERS_H
#define CANDELA_REPORT_NUMBERS_H

#include <stddef.h>

/* Decimal places for v with uncertainty u (>= 0). */
int cdl_report_decimals(double value, double uncertainty);

/* v printed with those decimals into buf ("%.*f"). */
void cdl_report_format(char *buf, size_t size, double value, double uncertainty);

/* A relative error as a percentage of two significant digits, never in
 * exponent form: "0.63 %", "11 %", "130 %". */
void cdl_report_format_percent(char *buf, size_t size, double fraction);

#endif
