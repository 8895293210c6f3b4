/* report.c - read, build, write both files (report.h). */
#include "report/report.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/file_bytes.h"
#include "base/strings.h"
#include "report/report_daylight.h"
#include "report/report_html.h"
#include "report/report_input.h"
#include "report/report_pdf.h"

/* The folder's summary.json when it is an annual study's (else NULL: a solve's, or none). */
static cJSON *annual_summary(const char *out_dir)
{
    char *path = cdl_path_join(out_dir, "summary", ".json");
    char *text = NULL;
    size_t size = 0;
    cdl_error ignored;
    cJSON *s = NULL;
    if (path && cdl_file_read_bytes(path, "summary", (size_t)64 << 20, &text, &size, &ignored) == CDL_OK)
        s = cJSON_ParseWithLength(text, size);
    free(text);
    free(path);
    if (s && !cdl_report_is_annual(s)) {
        cJSON_Delete(s);
        s = NULL;
    }
    return s;
}

cdl_status cdl_report_write(const char *out_dir, const cdl_report_options *options, cdl_error *err)
{
    cdl_report_input *input = NULL;
    cdl_report_document *doc = NULL;
    /* an annual study's folder: its daylight report; else a solve's */
    cJSON *annual = annual_summary(out_dir);
    cdl_status st = annual ? cdl_report_daylight_build(out_dir, annual, options ? options->title : NULL, &doc, err)
                           : cdl_report_input_read(out_dir, options, &input, err);
    if (st == CDL_OK && !annual) st = cdl_report_document_build(input, options, &doc, err);
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
    cJSON_Delete(annual);
    return st;
}
