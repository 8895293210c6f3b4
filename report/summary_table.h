/* summary_table.h - the per-grid summary table as text, for every format.
 *
 * One row per grid: Em, Emin, Emax (lux), U0, Ud, points, spacing, the
 * mean and worst stated error (relative standard error of E per point),
 * each printed as report_numbers.h says, and the check against the grid's
 * requirements: "pass" when Em >= Em_req and U0 >= U0_req, else "FAIL",
 * with the margins (Em in percent of the requirement, U0 as a difference)
 * and, when a margin is smaller than the value's stated uncertainty,
 * "within the stated error" (the verdict could go either way).
 */
#ifndef CANDELA_REPORT_SUMMARY_TABLE_H
#define CANDELA_REPORT_SUMMARY_TABLE_H

#include "report/report_input.h"

typedef struct cdl_report_row {
    char Em[32], Emin[32], Emax[32], U0[32], Ud[32];
    char count[32], spacing[32], error_mean[32], error_max[32];
    int has_requirements;
    int pass;                 /* with has_requirements */
    char requirements[96];    /* "Em >= 500 lx, U0 >= 0.60" */
    char verdict[200];        /* "pass: Em +4.2 %, U0 +0.04" */
} cdl_report_row;

void cdl_report_row_of(const cdl_report_grid *grid, cdl_report_row *row);

/* Any quantity of a grid (report_input.h's fields: E, Ez, Esz, L, AO)
 * as text: its mean, min, max and min / mean, each to its stated error as
 * the grid's row prints E's (min and max to their points' own errors, the
 * mean to the mean relative error, min / mean to the sum of both relative
 * errors). */
typedef struct cdl_report_field_text {
    char mean[32], min[32], max[32], ratio[32];
} cdl_report_field_text;

void cdl_report_field_text_of(const cdl_report_field *field, cdl_report_field_text *out);

/* The stated errors (absolute) of a field's min and max: their points' own. */
void cdl_report_field_extreme_errors(const cdl_report_field *field, double *u_min, double *u_max);

/* The columns' headings, in the order of the row's fields above. */
extern const char *const cdl_report_row_headings[10];

#endif
