/* summary_table.c - a grid's row of the summary table (summary_table.h). */
#include "report/summary_table.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/report_numbers.h"

const char *const cdl_report_row_headings[10] = {"Em (lx)", "Emin (lx)", "Emax (lx)", "U0", "Ud", "points",
                                                 "spacing (m)", "error mean", "error worst", "requirement"};

void cdl_report_row_of(const cdl_report_grid *g, cdl_report_row *row)
{
    memset(row, 0, sizeof *row);
    double r_mean = g->stderr_mean_rel, r_max = g->stderr_max_rel;
    /* Emin and Emax carry the stated errors of the points they come from
     * when the points are known (the worst relative error otherwise: a
     * surface map's vertex beside a hard shadow edge can state 13 times its
     * value, which says nothing of the darkest vertex elsewhere). U0 = Emin /
     * Em and Ud = Emin / Emax: relative errors add (first order, worst case). */
    double u_min = g->E_stderr ? g->E_stderr[g->min_index] : g->Emin * r_max;
    double u_max = g->E_stderr ? g->E_stderr[g->max_index] : g->Emax * r_max;
    double rel_min = g->Emin > 0.0 ? u_min / g->Emin : r_max, rel_max = g->Emax > 0.0 ? u_max / g->Emax : r_max;
    double u_Em = g->Em * r_mean, u_U0 = g->U0 * (rel_min + r_mean);
    cdl_report_format(row->Em, sizeof row->Em, g->Em, u_Em);
    cdl_report_format(row->Emin, sizeof row->Emin, g->Emin, u_min);
    cdl_report_format(row->Emax, sizeof row->Emax, g->Emax, u_max);
    cdl_report_format(row->U0, sizeof row->U0, g->U0, u_U0);
    cdl_report_format(row->Ud, sizeof row->Ud, g->Ud, g->Ud * (rel_min + rel_max));
    snprintf(row->count, sizeof row->count, "%zu", g->count);
    if (g->spec->kind == CDL_GRID_POINTS) snprintf(row->spacing, sizeof row->spacing, "-");
    else snprintf(row->spacing, sizeof row->spacing, "%.3g", g->spacing_m);
    cdl_report_format_percent(row->error_mean, sizeof row->error_mean, r_mean);
    cdl_report_format_percent(row->error_max, sizeof row->error_max, r_max);
    row->has_requirements = g->required_Em_lx > 0.0 || g->required_U0 > 0.0;
    if (!row->has_requirements) return;
    int pass = 1, close = 0;
    char em[80] = "", u0[80] = "", req_em[40] = "", req_u0[40] = "";
    if (g->required_Em_lx > 0.0) {
        double margin = g->Em / g->required_Em_lx - 1.0;
        pass &= g->Em >= g->required_Em_lx;
        close |= fabs(g->Em - g->required_Em_lx) <= u_Em;
        snprintf(em, sizeof em, "Em %+.1f %%", 100.0 * margin);
        snprintf(req_em, sizeof req_em, "Em >= %g lx", g->required_Em_lx);
    }
    if (g->required_U0 > 0.0) {
        char m[32];
        cdl_report_format(m, sizeof m, g->U0 - g->required_U0, u_U0);
        pass &= g->U0 >= g->required_U0;
        close |= fabs(g->U0 - g->required_U0) <= u_U0;
        snprintf(u0, sizeof u0, "U0 %s%s", g->U0 >= g->required_U0 ? "+" : "", m);
        snprintf(req_u0, sizeof req_u0, "U0 >= %g", g->required_U0);
    }
    row->pass = pass;
    snprintf(row->requirements, sizeof row->requirements, "%s%s%s", req_em, req_em[0] && req_u0[0] ? ", " : "",
             req_u0);
    snprintf(row->verdict, sizeof row->verdict, "%s: %s%s%s%s", pass ? "pass" : "FAIL", em, em[0] && u0[0] ? ", " : "",
             u0, close ? " (within the stated error)" : "");
}

void cdl_report_field_extreme_errors(const cdl_report_field *f, double *u_min, double *u_max)
{
    *u_min = f->stderr_values ? f->stderr_values[f->min_index] : f->min * f->stderr_max_rel;
    *u_max = f->stderr_values ? f->stderr_values[f->max_index] : f->max * f->stderr_max_rel;
}

void cdl_report_field_text_of(const cdl_report_field *f, cdl_report_field_text *out)
{
    double u_min, u_max;
    cdl_report_field_extreme_errors(f, &u_min, &u_max);
    double rel_min = f->min > 0.0 ? u_min / f->min : f->stderr_max_rel;
    cdl_report_format(out->mean, sizeof out->mean, f->avg, f->avg * f->stderr_mean_rel);
    cdl_report_format(out->min, sizeof out->min, f->min, u_min);
    cdl_report_format(out->max, sizeof out->max, f->max, u_max);
    cdl_report_format(out->ratio, sizeof out->ratio, f->U0, f->U0 * (rel_min + f->stderr_mean_rel));
}
