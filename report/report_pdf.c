/* report_pdf.c - the document on A4 pages (report_pdf.h). */
#include "report/report_pdf.h"

#include <cairo-pdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "graphics/text.h"

#define PAGE_W 595.276   /* A4, points */
#define PAGE_H 841.890
#define MARGIN 42.0
#define CONTENT_W (PAGE_W - 2.0 * MARGIN)
#define FOOTER_H 20.0
#define CELL_PAD 3.0

typedef struct page_flow {
    cairo_t *cr;
    const char *title;
    int page;
    double y;
} page_flow;

static double bottom(void)
{
    return PAGE_H - MARGIN - FOOTER_H;
}

static void footer(page_flow *f)
{
    char text[64];
    snprintf(text, sizeof text, "page %d", f->page);
    cairo_set_source_rgb(f->cr, 0.35, 0.35, 0.35);
    cdl_text_style small = {.size = 7.5, .wrap_width = CONTENT_W - 60.0};
    cdl_text_draw(f->cr, MARGIN, PAGE_H - MARGIN - 8.0, f->title, &small);
    cdl_text_draw(f->cr, PAGE_W - MARGIN, PAGE_H - MARGIN - 8.0, text,
                  &(cdl_text_style){.size = 7.5, .align = CDL_TEXT_RIGHT});
    cairo_set_source_rgb(f->cr, 0.0, 0.0, 0.0);
}

static void new_page(page_flow *f)
{
    cairo_show_page(f->cr);
    ++f->page;
    f->y = MARGIN;
    footer(f);
}

/* Room for h more points on this page, else a new page (unless already at its top). */
static void need(page_flow *f, double h)
{
    if (f->y + h > bottom() && f->y > MARGIN + 1e-9) new_page(f);
}

static double paragraph_height(page_flow *f, const cdl_report_block *b);
static double figure_scale(const cdl_report_block *b);

/* The height of what must stay with a heading: the paragraph and the
 * figure right after it (a map's caption and the map), or a table's first
 * rows. */
static double kept_with(page_flow *f, const cdl_report_block *next, const cdl_report_block *end)
{
    double h = 0.0;
    for (; next < end; ++next) {
        if (next->kind == CDL_BLOCK_PARAGRAPH) {
            h += paragraph_height(f, next);
            continue;
        }
        if (next->kind == CDL_BLOCK_FIGURE) h += next->figure.height * figure_scale(next);
        else if (next->kind == CDL_BLOCK_TABLE) h += 60.0;
        break;
    }
    return h;
}

static void heading(page_flow *f, const cdl_report_block *b, const cdl_report_block *end)
{
    double size = b->level == 1 ? 22.0 : b->level == 2 ? 15.0 : 11.5;
    cdl_text_style style = {.size = size, .bold = 1, .wrap_width = CONTENT_W};
    if (b->level == 1) f->y += 150.0;   /* the cover's title stands low */
    double w = 0.0, h = 0.0;
    cdl_text_measure(f->cr, b->text, &style, &w, &h);
    need(f, h + 14.0 + fmin(kept_with(f, b + 1, end), bottom() - MARGIN - h - 14.0)); /* never a heading alone */
    f->y += b->level == 1 ? 0.0 : 8.0;
    f->y += cdl_text_draw(f->cr, MARGIN, f->y, b->text, &style) + (b->level == 1 ? 24.0 : 6.0);
}

static const cdl_text_style paragraph_style = {.size = 9.0, .wrap_width = CONTENT_W};

static double paragraph_height(page_flow *f, const cdl_report_block *b)
{
    double w = 0.0, h = 0.0;
    cdl_text_measure(f->cr, b->text, &paragraph_style, &w, &h);
    return h + 7.0;
}

static void paragraph(page_flow *f, const cdl_report_block *b)
{
    const cdl_text_style style = paragraph_style;
    need(f, paragraph_height(f, b) - 7.0);
    f->y += cdl_text_draw(f->cr, MARGIN, f->y, b->text, &style) + 7.0;
}

/* Column widths that fit CONTENT_W: each its natural width when all fit;
 * else narrow columns keep theirs and the wide ones share the rest in
 * proportion to their natural widths (and wrap). */
static void column_widths(page_flow *f, const cdl_report_block *b, const cdl_text_style *style, double *width)
{
    for (size_t c = 0; c < b->columns; ++c) {
        width[c] = 0.0;
        for (size_t r = 0; r < b->rows; ++r) {
            double w = 0.0;
            cdl_text_measure(f->cr, b->cells[r * b->columns + c], style, &w, NULL);
            width[c] = fmax(width[c], w + 2.0 * CELL_PAD + 1.0);
        }
    }
    for (int pass = 0; pass < 8; ++pass) {
        double total = 0.0;
        for (size_t c = 0; c < b->columns; ++c) total += width[c];
        if (total <= CONTENT_W) return;
        double fair = CONTENT_W / (double)b->columns, narrow = 0.0, wide = 0.0;
        for (size_t c = 0; c < b->columns; ++c) {
            if (width[c] <= fair) narrow += width[c];
            else wide += width[c];
        }
        double room = CONTENT_W - narrow;
        for (size_t c = 0; c < b->columns; ++c)
            if (width[c] > fair) width[c] = fmax(fair, width[c] * room / wide);
    }
}

/* Headings, a facts table's first column and verdicts in bold; wrapped to the column. */
static cdl_text_style cell_style(const cdl_report_block *b, size_t r, size_t c, const cdl_text_style *plain,
                                 const cdl_text_style *bold, double width)
{
    int strong = (b->header && r == 0) || (!b->header && c == 0) ||
                 cdl_report_cell_verdict(b->cells[r * b->columns + c]) != 0;
    cdl_text_style s = strong ? *bold : *plain;
    s.wrap_width = width - 2.0 * CELL_PAD;
    return s;
}

static void table(page_flow *f, const cdl_report_block *b)
{
    double size = b->columns >= 8 ? 7.0 : 8.5;
    cdl_text_style plain = {.size = size}, bold = {.size = size, .bold = 1};
    double *width = calloc(b->columns, sizeof *width);
    if (!width) return;
    column_widths(f, b, &bold, width);
    for (size_t r = 0; r < b->rows; ++r) {
        int head_row = b->header && r == 0;
        /* the row's height: its tallest wrapped cell */
        double h = 0.0;
        for (size_t c = 0; c < b->columns; ++c) {
            cdl_text_style s = cell_style(b, r, c, &plain, &bold, width[c]);
            double w = 0.0, ch = 0.0;
            cdl_text_measure(f->cr, b->cells[r * b->columns + c], &s, &w, &ch);
            h = fmax(h, ch + 2.0 * CELL_PAD);
        }
        need(f, h);
        double x = MARGIN;
        for (size_t c = 0; c < b->columns; ++c) {
            const char *text = b->cells[r * b->columns + c];
            int verdict = cdl_report_cell_verdict(text);
            if (head_row) {
                cairo_set_source_rgb(f->cr, 0.92, 0.92, 0.92);
                cairo_rectangle(f->cr, x, f->y, width[c], h);
                cairo_fill(f->cr);
            }
            cairo_set_source_rgb(f->cr, 0.7, 0.7, 0.7);
            cairo_set_line_width(f->cr, 0.5);
            cairo_rectangle(f->cr, x, f->y, width[c], h);
            cairo_stroke(f->cr);
            cdl_text_style s = cell_style(b, r, c, &plain, &bold, width[c]);
            if (verdict > 0) cairo_set_source_rgb(f->cr, 0.0, 0.4, 0.2);
            else if (verdict < 0) cairo_set_source_rgb(f->cr, 0.7, 0.0, 0.0);
            else cairo_set_source_rgb(f->cr, 0.0, 0.0, 0.0);
            cdl_text_draw(f->cr, x + CELL_PAD, f->y + CELL_PAD, text, &s);
            x += width[c];
        }
        f->y += h;
    }
    cairo_set_source_rgb(f->cr, 0.0, 0.0, 0.0);
    f->y += 8.0;
    free(width);
}

/* Figures are drawn at the size the document asks, or smaller to fit the page's width and height. */
static double figure_scale(const cdl_report_block *b)
{
    const cdl_figure *fig = &b->figure;
    return fmin(fmin(b->figure_scale, CONTENT_W / fig->width), (bottom() - MARGIN) / fig->height);
}

static void figure(page_flow *f, const cdl_report_block *b)
{
    const cdl_figure *fig = &b->figure;
    double scale = figure_scale(b);
    need(f, fig->height * scale);
    cairo_save(f->cr);
    cairo_translate(f->cr, MARGIN + 0.5 * (CONTENT_W - fig->width * scale), f->y);
    cairo_scale(f->cr, scale, scale);
    cairo_rectangle(f->cr, 0.0, 0.0, fig->width, fig->height);
    cairo_clip(f->cr);
    fig->draw(f->cr, fig->user);
    cairo_restore(f->cr);
    f->y += fig->height * scale + 10.0;
}

static cairo_status_t write_to_file(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, closure) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

cdl_status cdl_report_pdf_write(const cdl_report_document *d, cdl_atomic_file *file, cdl_error *err)
{
    cairo_surface_t *surface = cairo_pdf_surface_create_for_stream(write_to_file, file->fp, PAGE_W, PAGE_H);
    /* The document's metadata; no creation date, so the same folder gives the same bytes. */
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, d->title);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Candela " CANDELA_VERSION);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "");
    page_flow f = {cairo_create(surface), d->title, 1, MARGIN};
    footer(&f);
    for (size_t k = 0; k < d->count; ++k) {
        const cdl_report_block *b = &d->blocks[k];
        switch (b->kind) {
        case CDL_BLOCK_PAGE_BREAK:
            if (f.y > MARGIN + 1e-9) new_page(&f);
            break;
        case CDL_BLOCK_HEADING:
            heading(&f, b, d->blocks + d->count);
            break;
        case CDL_BLOCK_PARAGRAPH:
            paragraph(&f, b);
            break;
        case CDL_BLOCK_TABLE:
            table(&f, b);
            break;
        case CDL_BLOCK_FIGURE:
            figure(&f, b);
            break;
        }
    }
    cairo_status_t drawn = cairo_status(f.cr);
    cairo_destroy(f.cr);
    cairo_surface_finish(surface);
    cairo_status_t finished = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (drawn != CAIRO_STATUS_SUCCESS || finished != CAIRO_STATUS_SUCCESS)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: drawing the PDF failed: %s", file->final_path,
                             cairo_status_to_string(drawn != CAIRO_STATUS_SUCCESS ? drawn : finished));
    return CDL_OK;
}
