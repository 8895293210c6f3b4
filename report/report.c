/* report.c - read, build, write both files (report.h). */
#include "report/report.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "report/report_html.h"
#include "report/report_input.h"
#include "report/report_pdf.h"

cdl_status cdl_report_write(const char *out_dir, const cdl_report_options *options, cdl_error *err)
{
    cdl_report_input *input = NULL;
    cdl_status st = cdl_report_input_read(out_dir, options ? options->requirements_path : NULL, &input, err);
    if (st != CDL_OK) return st;
    cdl_report_document *doc = NULL;
    st = cdl_report_document_build(input, options ? options->title : NULL, &doc, err);
    size_t n = strlen(out_dir) + 16;
    char *html_path = malloc(n), *pdf_path = malloc(n);
    if (st == CDL_OK && (!html_path || !pdf_path)) st = cdl_error_out_of_memory(err);
    cdl_atomic_file html = {0}, pdf = {0};
    if (st == CDL_OK) {
        snprintf(html_path, n, "%s/report.html", out_dir);
        snprintf(pdf_path, n, "%s/report.pdf", out_dir);
        st = cdl_atomic_file_open(&html, html_path, err);
    }
    if (st == CDL_OK) st = cdl_atomic_file_open(&pdf, pdf_path, err);
    if (st == CDL_OK) st = cdl_report_html_write(doc, &html, err);
    if (st == CDL_OK) st = cdl_report_pdf_write(doc, &pdf, err);
    /* Both complete: rename them into place, the HTML first. */
    if (st == CDL_OK) st = cdl_atomic_file_commit(&html, err);
    if (st == CDL_OK) st = cdl_atomic_file_commit(&pdf, err);
    cdl_atomic_file_abort(&html);
    cdl_atomic_file_abort(&pdf);
    free(html_path);
    free(pdf_path);
    cdl_report_document_release(doc);
    cdl_report_input_release(input);
    return st;
}
