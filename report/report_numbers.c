/* report_numbers.c - decimals from stated errors (report_numbers.h). */
#include "report/report_numbers.h"

#include <math.h>
#include <stdio.h>

int cdl_report_decimals(double value, double u)
{
    double magnitude = fabs(value);
    int lead = magnitude > 0.0 ? (int)floor(log10(magnitude)) : 0;
    int d = u > 0.0 && isfinite(u) ? -(int)floor(log10(u)) : 3 - lead;
    if (d > 5 - lead) d = 5 - lead;   /* at most 6 significant digits */
    if (d < 0) d = 0;
    return d;
}

void cdl_report_format(char *buf, size_t size, double value, double u)
{
    snprintf(buf, size, "%.*f", cdl_report_decimals(value, u), value);
}

void cdl_report_format_percent(char *buf, size_t size, double fraction)
{
    double p = 100.0 * fraction;
    if (fabs(p) >= 10.0) snprintf(buf, size, "%.0f %%", p);
    else snprintf(buf, size, "%.2g %%", p);
}
