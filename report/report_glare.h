/* report_glare.h - the report's glare: what it reads of a solve's folder,
 * its section, and the luminaires' UGR tables.
 *
 *  - cdl_report_glare_read: with observers in the scene, summary.json's
 *    "glare" (an entry per observer, by name, in order) and glare.csv,
 *    which must hold the same numbers (else the folder is stale: the
 *    message names the file and what differs);
 *  - cdl_report_glare_section: a table of the observers (UGR to the
 *    decimal place of its stated error, the background luminance, the
 *    luminaires in view, UGR_L and the verdict: "pass" when UGR <= UGR_L,
 *    else "FAIL", with the margin, "within the stated error" when the
 *    margin is smaller than the UGR's stated error; an observer grid as one
 *    row, its worst observer), and the plan seen from above with the
 *    surfaces, the luminaires and every observer (its eye, an arrow along
 *    the line of sight, its UGR, green where it passes and red where it
 *    fails);
 *  - cdl_report_glare_tables: each luminaire type whose file gives a
 *    luminous opening, its CIE 190 UGR table (glare/ugr_table.h) as
 *    catalogues print it, for the luminaire schedule.
 * Not public.
 */
#ifndef CANDELA_REPORT_GLARE_H
#define CANDELA_REPORT_GLARE_H

#include "base/error.h"
#include "report/report_builder.h"
#include "report/report_input.h"

cdl_status cdl_report_glare_read(cdl_report_input *in, cdl_error *err);

/* The section (nothing without observers); the plan figure is kept in the
 * document (released with it). */
cdl_status cdl_report_glare_section(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err);

/* The UGR tables of the luminaire types that have them. */
cdl_status cdl_report_glare_tables(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err);

/* Free the document's glare plan. */
void cdl_report_glare_plan_release(struct cdl_glare_plan *plan);

#endif
