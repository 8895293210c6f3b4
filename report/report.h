/* report.h - `candela report`: a lighting-design report from a solve's folder.
 *
 * Reads OUTDIR (report_input.h), builds the document (report_document.h)
 * and writes OUTDIR/report.html (self-contained, report_html.h) and
 * OUTDIR/report.pdf (A4, report_pdf.h). Both are written to temporary
 * files first and renamed only when both are complete: a failure leaves
 * neither half-written (an earlier report stays as it was).
 *
 * Not a public header: the report is the command's, and cairo, pango and
 * OpenColorIO stay private to libcandela. Errors: CDL_ERR_INPUT naming the
 * file and what is missing or stale; CDL_ERR_INTERNAL for memory and
 * write failures.
 */
#ifndef CANDELA_REPORT_H
#define CANDELA_REPORT_H

#include "base/error.h"

typedef struct cdl_report_options {
    const char *title;               /* NULL: the scene's "name", else its file name without the extension */
    const char *requirements_path;   /* NULL: the scene's own requirements only */
    const char *project_path;        /* NULL: the scene's own "project" only; else a JSON file of the same
                                      * object, whose fields replace the scene's one by one */
    int values;                      /* 1: a table of the values at each grid's points */
} cdl_report_options;

cdl_status cdl_report_write(const char *out_dir, const cdl_report_options *options, cdl_error *err);

#endif
