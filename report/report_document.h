/* report_document.h - the report's content, once, for every format.
 *
 * The report is built as a list of blocks (headings, paragraphs, tables,
 * figures, page breaks) from a checked input (report_input.h), in the order
 * a reviewer reads it:
 *   1. cover: the title (the scene's name), the project block (project,
 *      client, designer, date, notes), the calculation's facts (scene
 *      file, solve date, Candela version, method, quality, seed, threads,
 *      the time it took);
 *   2. summary (report_summary.c): a row per grid with the check against
 *      its requirements, a row per other quantity asked (Ez, Esz, L, AO),
 *      installed power and power density per grid;
 *   3. room and surfaces (report_room.c): dimensions, areas, reflectances;
 *   4. luminaires (report_luminaires.c): every luminaire placed, the
 *      schedule of types, a polar diagram per photometric file, and with
 *      observers each file's UGR table;
 *   5. a map per quantity of each rect and polygon grid (grid_map.h), then
 *      the surface maps (report_surfaces.h);
 *   6. glare, with observers (report_glare.h);
 *   7. on request, the values at each grid's points (report_values.c);
 *   8. method and accuracy (report_method.c): what the plan modelled and
 *      why, each light and grid by name, the error statement, the solve's
 *      warnings.
 * report_html.c and report_pdf.c lay the same blocks out, so the HTML and
 * the PDF carry the same text and figures.
 *
 * Ownership: the document owns its text, maps and diagrams; it borrows the
 * input, which must outlive it. Errors: memory, and the maps' (OCIO).
 */
#ifndef CANDELA_REPORT_DOCUMENT_H
#define CANDELA_REPORT_DOCUMENT_H

#include <stddef.h>

#include "graphics/figure.h"
#include "report/report.h"
#include "report/report_input.h"

typedef enum cdl_report_block_kind {
    CDL_BLOCK_HEADING,      /* level 1 (the title), 2 (a section) or 3 */
    CDL_BLOCK_PARAGRAPH,
    CDL_BLOCK_TABLE,        /* cells row by row; with `header`, row 0 names the columns */
    CDL_BLOCK_FIGURE,
    CDL_BLOCK_PAGE_BREAK
} cdl_report_block_kind;

typedef struct cdl_report_block {
    cdl_report_block_kind kind;
    int level;
    char *text;
    size_t columns, rows;
    char **cells;
    int header;
    cdl_figure figure;
    double figure_scale;    /* the figure shown at this fraction of its size (at most 1) */
} cdl_report_block;

typedef struct cdl_report_document {
    char *title;
    cdl_report_block *blocks;
    size_t count, capacity;
    /* what the figures draw from */
    struct cdl_grid_map *maps;
    size_t map_count;
    struct cdl_polar_diagram *diagrams;
    size_t diagram_count;
    struct cdl_report_surfaces *surfaces; /* the surface maps' section (report_surfaces.h), or NULL */
    struct cdl_glare_plan *glare_plan; /* the observers on the plan (report_glare.c), or NULL */
    struct cdl_report_image **images;  /* pictures read from the folder (report_daylight.c) */
    size_t image_count;
} cdl_report_document;

/* Build the report of `input` with the options' title (NULL: the scene's
 * name, else its file's) and, with `values`, the tables of values. */
cdl_status cdl_report_document_build(const cdl_report_input *input, const cdl_report_options *options,
                                     cdl_report_document **out, cdl_error *err);
void cdl_report_document_release(cdl_report_document *document);

/* A cell's emphasis: +1 for a passed check ("pass..."), -1 for a failed
 * one ("FAIL..."), 0 otherwise. */
int cdl_report_cell_verdict(const char *cell);

#endif
