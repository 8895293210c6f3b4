/* report_pdf.h - the report as a PDF, laid out by cairo and pango.
 *
 * A4 pages (595 x 842 points), margins of 42 points, a footer with the
 * title and the page number. The document's blocks flow down the page:
 * headings, paragraphs wrapped to the width, tables whose wide columns
 * wrap so the table fits the width (rows never split across pages), and
 * the figures drawn as vectors by the very functions that draw the HTML's
 * SVG, scaled down to fit where needed. Page breaks where the document
 * says, and wherever the next block does not fit. Text is real text (the
 * fonts embedded by cairo), so it can be searched and copied.
 */
#ifndef CANDELA_REPORT_PDF_H
#define CANDELA_REPORT_PDF_H

#include "base/atomic_file.h"
#include "report/report_document.h"

/* Write the document into an open atomic file (the caller commits). */
cdl_status cdl_report_pdf_write(const cdl_report_document *document, cdl_atomic_file *file, cdl_error *err);

#endif
