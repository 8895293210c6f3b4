/* report_builder.h - adding blocks to the report's document, for the files
 * that write its sections (report_document.c, report_glare.c).
 *
 * A failed allocation sets `failed` and is checked once at the end: the
 * sections write on without testing each call. Not public.
 */
#ifndef CANDELA_REPORT_BUILDER_H
#define CANDELA_REPORT_BUILDER_H

#include "report/report_document.h"

typedef struct cdl_report_builder {
    cdl_report_document *doc;
    int failed;                  /* out of memory somewhere: checked once at the end */
} cdl_report_builder;

/* A new block of `kind` at the end (NULL when out of memory). */
cdl_report_block *cdl_report_add_block(cdl_report_builder *b, cdl_report_block_kind kind);

/* A heading (level 1 to 3) or paragraph, printf-style. */
void cdl_report_text(cdl_report_builder *b, cdl_report_block_kind kind, int level, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* A table of columns x rows empty cells; with `header`, row 0 names the columns. */
cdl_report_block *cdl_report_table(cdl_report_builder *b, size_t columns, size_t rows, int header);

/* Write one cell, printf-style (a cell may be written again). */
void cdl_report_cell(cdl_report_builder *b, cdl_report_block *t, size_t row, size_t column, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* A figure shown at `scale` of its size (at most 1). */
void cdl_report_figure(cdl_report_builder *b, cdl_figure f, double scale);

#endif
