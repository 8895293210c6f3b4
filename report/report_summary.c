/* report_summary.c - the summary: every grid's E and every other quantity
 * asked, with their stated errors, and the installed power (report_sections.h). */
#include "report/report_sections.h"

#include <stdio.h>

#include "report/report_numbers.h"
#include "report/summary_table.h"

static void illuminance_table(cdl_report_builder *b, const cdl_report_input *in)
{
    int any_requirements = 0;
    for (size_t g = 0; g < in->grid_count; ++g)
        any_requirements |= in->grids[g].required_Em_lx > 0.0 || in->grids[g].required_U0 > 0.0;
    size_t columns = any_requirements ? 11 : 10;
    cdl_report_block *t = cdl_report_table(b, columns, in->grid_count + 1, 1);
    cdl_report_cell(b, t, 0, 0, "grid");
    for (size_t c = 0; c + 1 < columns; ++c) cdl_report_cell(b, t, 0, c + 1, "%s", cdl_report_row_headings[c]);
    for (size_t g = 0; g < in->grid_count; ++g) {
        cdl_report_row row;
        cdl_report_row_of(&in->grids[g], &row);
        const char *values[9] = {row.Em,    row.Emin,    row.Emax,       row.U0,       row.Ud,
                                 row.count, row.spacing, row.error_mean, row.error_max};
        cdl_report_cell(b, t, g + 1, 0, "%s", in->grids[g].spec->name);
        for (size_t c = 0; c < 9; ++c) cdl_report_cell(b, t, g + 1, c + 1, "%s", values[c]);
        if (!any_requirements) continue;
        if (row.has_requirements) cdl_report_cell(b, t, g + 1, 10, "%s; %s", row.verdict, row.requirements);
        else cdl_report_cell(b, t, g + 1, 10, "none given");
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Em is the area-weighted mean illuminance, U0 = Emin / Em the uniformity and Ud = Emin / Emax "
                    "the diversity (EN 12464-1), all as summary.json gives them. The errors are the stated one-sigma "
                    "relative standard errors of E per point (mean and worst over the points); every number is "
                    "printed to the decimal place of its own stated error (Em: Em x the mean error, Emin and Emax: x "
                    "the worst, U0 and Ud: the sum of their parts' relative errors), so no digit is shown that the "
                    "error does not support.%s%s%s%s",
                    any_requirements ? " Requirements (maintained illuminance Em and uniformity U0 for the task "
                                       "area) come from the scene's grids"
                                     : "",
                    any_requirements && in->requirements_path ? " and from " : "",
                    any_requirements && in->requirements_path ? in->requirements_path : "",
                    any_requirements ? "." : "");
}

/* "Ez (lx)", "AO". */
static void quantity_name(char *out, size_t size, const cdl_report_field *f)
{
    snprintf(out, size, "%s%s%s%s", f->symbol, f->unit[0] ? " (" : "", f->unit, f->unit[0] ? ")" : "");
}

/* A row per grid and quantity beyond E: its mean, extremes and min / mean,
 * printed as E's are. */
static void outputs_table(cdl_report_builder *b, const cdl_report_input *in)
{
    size_t rows = 0;
    for (size_t g = 0; g < in->grid_count; ++g) rows += in->grids[g].field_count - 1;
    if (rows == 0) return;
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "The other quantities the grids ask for, beside E:");
    cdl_report_block *t = cdl_report_table(b, 9, rows + 1, 1);
    static const char *const headings[9] = {"grid",    "quantity", "mean", "min", "max", "min / mean",
                                            "meaning", "error mean", "error worst"};
    for (size_t c = 0; c < 9; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    size_t r = 1;
    for (size_t g = 0; g < in->grid_count; ++g)
        for (size_t k = 1; k < in->grids[g].field_count; ++k, ++r) {
            const cdl_report_field *f = &in->grids[g].fields[k];
            char name[48], mean_error[32], worst_error[32];
            quantity_name(name, sizeof name, f);
            cdl_report_field_text v;
            cdl_report_field_text_of(f, &v);
            cdl_report_cell(b, t, r, 0, "%s", in->grids[g].spec->name);
            cdl_report_cell(b, t, r, 1, "%s", name);
            cdl_report_cell(b, t, r, 2, "%s", v.mean);
            cdl_report_cell(b, t, r, 3, "%s", v.min);
            cdl_report_cell(b, t, r, 4, "%s", v.max);
            cdl_report_cell(b, t, r, 5, "%s", v.ratio);
            cdl_report_cell(b, t, r, 6, "%s", f->what);
            cdl_report_format_percent(mean_error, sizeof mean_error, f->stderr_mean_rel);
            cdl_report_format_percent(worst_error, sizeof worst_error, f->stderr_max_rel);
            cdl_report_cell(b, t, r, 7, "%s", mean_error);
            cdl_report_cell(b, t, r, 8, "%s", worst_error);
        }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Ez: cylindrical illuminance, the mean vertical illuminance around the point (EN 12464-1); Esz: "
                    "semicylindrical illuminance towards the point's normal; L: the luminance rho E / pi of the "
                    "surface the grid lies on; AO: the cosine-weighted share of the hemisphere no surface hides. "
                    "Each is printed to the decimal place of its stated error as E is (min and max to their points' "
                    "own; L's error is E's, relative); a quantity computed exactly states none.");
}

static void power_table(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_text(b, CDL_BLOCK_HEADING, 3, "Installed power");
    const char *why = cdl_report_summary_string(in, "power.why");
    double installed = cdl_report_summary_number(in, "power.installed_w", -1.0);
    double known = cdl_report_summary_number(in, "power.known_w", -1.0);
    if (installed >= 0.0)
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Installed power: %.4g W (%s).", installed, why ? why : "");
    else if (known > 0.0)
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Installed power: not known: %s (%.4g W from the files that give it).",
                        why ? why : "", known);
    else
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Installed power: not known: %s.", why ? why : "");
    size_t rows = 0;
    for (size_t g = 0; g < in->grid_count; ++g) rows += in->grids[g].area_m2 > 0.0;
    if (rows == 0) return;
    cdl_report_block *t = cdl_report_table(b, 6, rows + 1, 1);
    static const char *const headings[6] = {"grid", "area (m2)", "luminaires over it", "power (W)",
                                            "density (W/m2)", "W/m2 per 100 lx"};
    for (size_t c = 0; c < 6; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    size_t r = 1;
    for (size_t g = 0; g < in->grid_count; ++g) {
        const cdl_report_grid *grid = &in->grids[g];
        if (!(grid->area_m2 > 0.0)) continue;
        cdl_report_cell(b, t, r, 0, "%s", grid->spec->name);
        cdl_report_cell(b, t, r, 1, "%.4g", grid->area_m2);
        cdl_report_cell(b, t, r, 2, "%zu", grid->luminaires_over);
        int has = grid->power_density_w_m2 > 0.0;
        for (size_t c = 3; c < 6; ++c) cdl_report_cell(b, t, r, c, "-");
        if (has) {
            cdl_report_cell(b, t, r, 3, "%.4g", grid->power_w);
            cdl_report_cell(b, t, r, 4, "%.3g", grid->power_density_w_m2);
        }
        /* the normalised power density: W/m2 for each 100 lx of Em */
        if (has && grid->Em > 0.0) cdl_report_cell(b, t, r, 5, "%.3g", grid->power_density_w_m2 / (grid->Em / 100.0));
        ++r;
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "The power over a grid is the input power its luminaires' files state, summed over the "
                    "luminaires whose positions, projected along the grid's normal, fall within it, and divided by "
                    "the grid's area (its points' areas summed): a density for the area the grid covers, not for "
                    "the room. A grid over which any luminaire's file gives no wattage has none. W/m2 per 100 lx "
                    "is the density over Em / 100 lx (the normalised power density).");
}

void cdl_report_summary_section(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Summary");
    illuminance_table(b, in);
    outputs_table(b, in);
    power_table(b, in);
}
