/* report_html.h - the report as one self-contained HTML file.
 *
 * Everything inline: the style sheet, and every figure as an SVG image in
 * a data: URI (base64), so the file opens offline, in any browser, alone.
 * Each figure's <img> has the figure's title as its alt text. Printing
 * gives A4 pages, breaking where the document says (CSS @page and
 * break-before). Written atomically to `path`; errors name it.
 */
#ifndef CANDELA_REPORT_HTML_H
#define CANDELA_REPORT_HTML_H

#include "base/atomic_file.h"
#include "report/report_document.h"

/* Write the document into an open atomic file (the caller commits). */
cdl_status cdl_report_html_write(const cdl_report_document *document, cdl_atomic_file *file, cdl_error *err);

#endif
