/* report_sections.h - the sections of the report, each written by its own
 * file into the document's blocks (report_builder.h), in the order
 * report_document.c calls them. Not public.
 *
 *   cover              report_document.c: the title (the scene's name), the
 *                      project block, the calculation's facts
 *   summary            report_summary.c: a row per grid and quantity asked
 *                      (E, Ez, Esz, L, AO) with their stated errors, the
 *                      requirements' verdicts, installed power and density
 *   room               report_room.c: every surface with its dimensions,
 *                      area and reflectances (per face for boxes)
 *   luminaires         report_luminaires.c: every luminaire placed (name,
 *                      product and catalogue number from its file, position,
 *                      mounting height, rotation or aim point, maintenance
 *                      factor), the schedule of types, polar diagrams
 *   values             report_values.c (on request): each grid's values at
 *                      its points, laid out as its map is
 *   method             report_method.c: what the plan modelled, each light
 *                      and grid by name with its direct route, the error
 *                      statement, the solve's warnings
 */
#ifndef CANDELA_REPORT_SECTIONS_H
#define CANDELA_REPORT_SECTIONS_H

#include "base/error.h"
#include "report/report_builder.h"
#include "report/report_input.h"

void cdl_report_summary_section(cdl_report_builder *b, const cdl_report_input *in);
void cdl_report_room_section(cdl_report_builder *b, const cdl_report_input *in);
cdl_status cdl_report_luminaire_section(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err);
void cdl_report_values_section(cdl_report_builder *b, const cdl_report_input *in);
void cdl_report_method_section(cdl_report_builder *b, const cdl_report_input *in);

/* A luminaire's label for tables: its name, else its JSON path, with "k
 * of n" for one copy of many. */
void cdl_report_luminaire_label(const cdl_luminaire_spec *l, char *out, size_t size);

/* A file's name without its folder. */
const char *cdl_report_file_name(const char *path);

#endif
