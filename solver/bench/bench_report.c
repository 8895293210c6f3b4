/* bench_report.c - bench.csv and bench.svg (see bench_report.h). */
#include "solver/bench/bench_report.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "graphics/raster_canvas.h"
#include "base/atomic_file.h"
#include "solver/output/png_write.h"
#include "solver/solve_internal.h"

cdl_status cdl_bench_report_write_csv(const char *path, const cdl_bench_row *rows, size_t count, cdl_error *err)
{
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st != CDL_OK) return st;
    fputs("label,method,quality,target_error,seconds,rays,records,rms_rel_error,max_rel_error,within_2_sigma\n", f.fp);
    for (size_t k = 0; k < count; ++k) {
        const cdl_bench_row *r = &rows[k];
        if (r->skipped) continue;
        char rms[32];
        if (r->below_reference)
            snprintf(rms, sizeof rms, "<ref");
        else
            snprintf(rms, sizeof rms, "%.6g", r->rung.rms);
        fprintf(f.fp, "%s,%s,%s,%.6g,%.3f,%llu,%llu,%s,%.6g,%.6g\n", r->label, cdl_method_name(r->rung.method),
                r->quality, r->rung.target, r->rung.seconds, (unsigned long long)r->rung.rays,
                (unsigned long long)r->rung.records, rms, r->rung.worst, r->rung.within2);
    }
    return cdl_atomic_file_commit(&f, err);
}

/* The plot's frame: pixels of the SVG, the axes' decades. */
typedef struct plot_frame {
    double left, right, top, bottom;   /* plot area, px */
    double x_lo, x_hi, y_lo, y_hi;     /* log10 of seconds and of RMS (%) at the edges */
} plot_frame;

static double plot_x(const plot_frame *f, double seconds)
{
    return f->left + (log10(seconds) - f->x_lo) / (f->x_hi - f->x_lo) * (f->right - f->left);
}

static double plot_y(const plot_frame *f, double percent)
{
    return f->bottom - (log10(percent) - f->y_lo) / (f->y_hi - f->y_lo) * (f->bottom - f->top);
}

/* The point a rung is drawn at: seconds and RMS in %, kept above 0 (an RMS
 * the reference cannot resolve sits at half the floor). */
static void rung_point(const cdl_bench_row *r, double floor_percent, double *s, double *p)
{
    *s = fmax(r->rung.seconds, 1e-4);
    *p = fmax(100.0 * r->rung.rms, 0.5 * floor_percent);
}

/* A rung's RMS +- its standard error as an estimate over all points (its
 * error bar, in %); 0 when it has none (a reference at every point, or a
 * rung the reference cannot resolve). The lower end is kept above 0 for
 * the log axis. */
static int rung_bar(const cdl_bench_row *r, double floor_percent, double *lo, double *hi)
{
    if (r->below_reference || !(r->rung.rms_sd > 0.0)) return 0;
    *hi = 100.0 * (r->rung.rms + r->rung.rms_sd);
    *lo = fmax(100.0 * (r->rung.rms - r->rung.rms_sd), 0.5 * floor_percent);
    return 1;
}

/* One colour a method, as hex for the SVG and as bytes for the PNG. */
static const char *method_colour(cdl_method m)
{
    return m == CDL_METHOD_ICACHE ? "#1f77b4" : m == CDL_METHOD_PATHTRACE ? "#d62728" : "#2ca02c";
}

static void method_rgb(cdl_method m, uint8_t rgb[3])
{
    unsigned v = (unsigned)strtoul(method_colour(m) + 1, NULL, 16);
    rgb[0] = (uint8_t)(v >> 16);
    rgb[1] = (uint8_t)(v >> 8);
    rgb[2] = (uint8_t)v;
}

static void write_axes(FILE *fp, const plot_frame *f)
{
    fprintf(fp, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#000\"/>\n", f->left,
            f->top, f->right - f->left, f->bottom - f->top);
    for (int k = (int)f->x_lo; k <= (int)f->x_hi; ++k) {
        double x = plot_x(f, pow(10.0, k));
        fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x, f->top, x,
                f->bottom);
        fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%g</text>\n", x, f->bottom + 18,
                pow(10.0, k));
    }
    for (int k = (int)f->y_lo; k <= (int)f->y_hi; ++k) {
        double y = plot_y(f, pow(10.0, k));
        fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", f->left, y, f->right,
                y);
        fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n", f->left - 6, y + 4, pow(10.0, k));
    }
    fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">wall time of the whole solve (s)</text>\n",
            0.5 * (f->left + f->right), f->bottom + 44);
    fprintf(fp,
            "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">RMS relative "
            "error of E against the reference (%%)</text>\n",
            f->left - 50, 0.5 * (f->top + f->bottom), f->left - 50, 0.5 * (f->top + f->bottom));
}

/* The frame that holds every measured rung and the floor, in whole
 * decades on both axes. */
static plot_frame frame_for(const cdl_bench_row *rows, size_t count, double floor_percent)
{
    double s_min = INFINITY, s_max = 0.0, p_min = floor_percent, p_max = floor_percent;
    for (size_t k = 0; k < count; ++k) {
        if (rows[k].skipped) continue;
        double s, p, lo, hi;
        rung_point(&rows[k], floor_percent, &s, &p);
        if (rung_bar(&rows[k], floor_percent, &lo, &hi)) p = hi;
        s_min = fmin(s_min, s);
        s_max = fmax(s_max, s);
        p_min = fmin(p_min, p);
        p_max = fmax(p_max, p);
    }
    if (!(s_max > 0.0)) s_min = s_max = 1.0;
    plot_frame f = {100.0, 620.0, 30.0, 420.0, floor(log10(s_min)), ceil(log10(s_max)), floor(log10(p_min)),
                    ceil(log10(p_max))};
    if (f.x_hi <= f.x_lo) f.x_hi = f.x_lo + 1.0;
    if (f.y_hi <= f.y_lo) f.y_hi = f.y_lo + 1.0;
    return f;
}

cdl_status cdl_bench_report_write_svg(const char *path, const cdl_bench_row *rows, size_t count,
                                      double reference_rms, cdl_error *err)
{
    double floor_percent = fmax(100.0 * reference_rms, 1e-6);
    plot_frame f = frame_for(rows, count, floor_percent);
    cdl_atomic_file file;
    cdl_status st = cdl_atomic_file_open(&file, path, err);
    if (st != CDL_OK) return st;
    FILE *fp = file.fp;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" height=\"500\" viewBox=\"0 0 760 500\" "
          "font-family=\"sans-serif\" font-size=\"12\">\n"
          "<title>candela bench: RMS error against time</title>\n"
          "<rect width=\"760\" height=\"500\" fill=\"#fff\"/>\n",
          fp);
    write_axes(fp, &f);
    double yf = plot_y(&f, floor_percent);
    fprintf(fp,
            "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#555\" stroke-dasharray=\"6 4\"/>\n"
            "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">reference's own error %.3g %%</text>\n",
            f.left, yf, f.right, yf, f.left + 6, yf - 5, floor_percent);
    const cdl_method methods[3] = {CDL_METHOD_DIRECT, CDL_METHOD_ICACHE, CDL_METHOD_PATHTRACE};
    int legend = 0;
    for (int m = 0; m < 3; ++m) {
        int any = 0;
        for (size_t k = 0; k < count; ++k) {
            if (rows[k].skipped || rows[k].rung.method != methods[m]) continue;
            double s, p;
            rung_point(&rows[k], floor_percent, &s, &p);
            if (!any) fprintf(fp, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" points=\"", method_colour(methods[m]));
            fprintf(fp, "%s%.1f,%.1f", any ? " " : "", plot_x(&f, s), plot_y(&f, p));
            any = 1;
        }
        if (!any) continue;
        fputs("\"/>\n", fp);
        for (size_t k = 0; k < count; ++k) {
            if (rows[k].skipped || rows[k].rung.method != methods[m]) continue;
            double s, p, lo, hi;
            rung_point(&rows[k], floor_percent, &s, &p);
            if (rung_bar(&rows[k], floor_percent, &lo, &hi))
                fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\n", plot_x(&f, s),
                        plot_y(&f, lo), plot_x(&f, s), plot_y(&f, hi), method_colour(methods[m]));
            fprintf(fp,
                    "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/>\n"
                    "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\">%s%s</text>\n",
                    plot_x(&f, s), plot_y(&f, p), method_colour(methods[m]), plot_x(&f, s) + 6, plot_y(&f, p) - 6,
                    rows[k].label, rows[k].below_reference ? " (below the reference)" : "");
        }
        fprintf(fp, "<text x=\"%d\" y=\"%d\" fill=\"%s\">%s</text>\n", 640, 50 + 18 * legend++,
                method_colour(methods[m]), cdl_method_name(methods[m]));
    }
    fputs("</svg>\n", fp);
    return cdl_atomic_file_commit(&file, err);
}

/* ---- the same plot as a PNG: lines pixel by pixel, text by pango ------- */

enum { PLOT_WIDTH = 760, PLOT_HEIGHT = 500 };

static void put_pixel(uint8_t *img, int x, int y, const uint8_t c[3])
{
    if (x < 0 || y < 0 || x >= PLOT_WIDTH || y >= PLOT_HEIGHT) return;
    memcpy(img + 3 * ((size_t)y * PLOT_WIDTH + (size_t)x), c, 3);
}

/* A line from (x0, y0) to (x1, y1), `thick` pixels wide, dashed when dash
 * > 0 (dash pixels on, dash off): Bresenham's algorithm (Bresenham 1965,
 * IBM Systems Journal 4(1)), all octants by the error term of both axes. */
static void draw_line(uint8_t *img, double fx0, double fy0, double fx1, double fy1, int thick, int dash,
                      const uint8_t c[3])
{
    int x0 = (int)lround(fx0), y0 = (int)lround(fy0), x1 = (int)lround(fx1), y1 = (int)lround(fy1);
    int dx = abs(x1 - x0), dy = -abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, e = dx + dy;
    for (int step = 0;; ++step) {
        if (dash <= 0 || (step / dash) % 2 == 0)
            for (int t = 0; t < thick; ++t) {
                put_pixel(img, x0, y0 + t, c);
                put_pixel(img, x0 + t, y0, c);
            }
        if (x0 == x1 && y0 == y1) break;
        int e2 = 2 * e;
        if (e2 >= dy) {
            e += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y0 += sy;
        }
    }
}

/* The labels, kept while the lines are drawn pixel by pixel and then laid
 * out by pango over them (at most one per rung, axis tick and legend line). */
enum { PLOT_LABELS_MAX = 128 };
typedef struct plot_label {
    double x, y;              /* y is the text's top */
    cdl_text_align align;
    uint8_t colour[3];
    char text[96];
} plot_label;
typedef struct plot_labels {
    plot_label item[PLOT_LABELS_MAX];
    int count;
} plot_labels;

static void draw_text(plot_labels *labels, double x, double y, const char *text, cdl_text_align align,
                      const uint8_t c[3])
{
    if (labels->count >= PLOT_LABELS_MAX) return;
    plot_label *l = &labels->item[labels->count++];
    l->x = x;
    l->y = y;
    l->align = align;
    memcpy(l->colour, c, 3);
    snprintf(l->text, sizeof l->text, "%s", text);
}

static cdl_status put_labels(uint8_t *img, const plot_labels *labels, cdl_error *err)
{
    cdl_raster_canvas *canvas = NULL;
    cdl_status st = cdl_raster_canvas_begin(img, PLOT_WIDTH, PLOT_HEIGHT, &canvas, err);
    if (st != CDL_OK) return st;
    for (int k = 0; k < labels->count; ++k) {
        const plot_label *l = &labels->item[k];
        cdl_text_style style = {.size = 10.0, .align = l->align};
        cdl_raster_canvas_text(canvas, l->x, l->y - 2.0, l->text, &style, l->colour);
    }
    cdl_raster_canvas_end(canvas);
    return CDL_OK;
}

static void draw_png_axes(uint8_t *img, plot_labels *labels, const plot_frame *f)
{
    static const uint8_t black[3] = {0, 0, 0}, grey[3] = {221, 221, 221};
    char label[32];
    for (int k = (int)f->x_lo; k <= (int)f->x_hi; ++k) {
        double x = plot_x(f, pow(10.0, k));
        draw_line(img, x, f->top, x, f->bottom, 1, 0, grey);
        snprintf(label, sizeof label, "%g", pow(10.0, k));
        draw_text(labels, x, f->bottom + 8, label, CDL_TEXT_CENTRE, black);
    }
    for (int k = (int)f->y_lo; k <= (int)f->y_hi; ++k) {
        double y = plot_y(f, pow(10.0, k));
        draw_line(img, f->left, y, f->right, y, 1, 0, grey);
        snprintf(label, sizeof label, "%g", pow(10.0, k));
        draw_text(labels, f->left - 6, y - 3, label, CDL_TEXT_RIGHT, black);
    }
    draw_line(img, f->left, f->top, f->right, f->top, 1, 0, black);
    draw_line(img, f->left, f->bottom, f->right, f->bottom, 1, 0, black);
    draw_line(img, f->left, f->top, f->left, f->bottom, 1, 0, black);
    draw_line(img, f->right, f->top, f->right, f->bottom, 1, 0, black);
    draw_text(labels, 0.5 * (f->left + f->right), f->bottom + 30, "wall time of the whole solve (s)", CDL_TEXT_CENTRE,
              black);
    draw_text(labels, f->left, f->top - 16, "rms relative error of E against the reference (%)", CDL_TEXT_LEFT, black);
}

cdl_status cdl_bench_report_write_png(const char *path, const cdl_bench_row *rows, size_t count,
                                      double reference_rms, cdl_error *err)
{
    double floor_percent = fmax(100.0 * reference_rms, 1e-6);
    plot_frame f = frame_for(rows, count, floor_percent);
    uint8_t *img = malloc((size_t)PLOT_WIDTH * PLOT_HEIGHT * 3);
    if (!img) return cdl_error_out_of_memory(err);
    plot_labels *labels = calloc(1, sizeof *labels);
    if (!labels) {
        free(img);
        return cdl_error_out_of_memory(err);
    }
    memset(img, 255, (size_t)PLOT_WIDTH * PLOT_HEIGHT * 3);
    draw_png_axes(img, labels, &f);
    static const uint8_t floor_grey[3] = {85, 85, 85};
    double yf = plot_y(&f, floor_percent);
    char label[96];
    draw_line(img, f.left, yf, f.right, yf, 1, 6, floor_grey);
    snprintf(label, sizeof label, "reference error %.3g %%", floor_percent);
    draw_text(labels, f.left + 6, yf - 11, label, CDL_TEXT_LEFT, floor_grey);
    const cdl_method methods[3] = {CDL_METHOD_DIRECT, CDL_METHOD_ICACHE, CDL_METHOD_PATHTRACE};
    int legend = 0;
    for (int m = 0; m < 3; ++m) {
        uint8_t c[3];
        method_rgb(methods[m], c);
        double px = 0.0, py = 0.0;
        int any = 0;
        for (size_t k = 0; k < count; ++k) {
            if (rows[k].skipped || rows[k].rung.method != methods[m]) continue;
            double s, p, lo, hi;
            rung_point(&rows[k], floor_percent, &s, &p);
            double x = plot_x(&f, s), y = plot_y(&f, p);
            if (any) draw_line(img, px, py, x, y, 2, 0, c);
            if (rung_bar(&rows[k], floor_percent, &lo, &hi))
                draw_line(img, x, plot_y(&f, lo), x, plot_y(&f, hi), 1, 0, c);
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx)
                    if (dx * dx + dy * dy <= 10) put_pixel(img, (int)lround(x) + dx, (int)lround(y) + dy, c);
            snprintf(label, sizeof label, "%s%s", rows[k].label, rows[k].below_reference ? " (<ref)" : "");
            draw_text(labels, x + 6, y - 12, label, CDL_TEXT_LEFT, c);
            px = x;
            py = y;
            any = 1;
        }
        if (any) draw_text(labels, 640, 45 + 14 * legend++, cdl_method_name(methods[m]), CDL_TEXT_LEFT, c);
    }
    cdl_status st = put_labels(img, labels, err);
    if (st == CDL_OK)
        st = cdl_png_write_rgb(path, img, PLOT_WIDTH, PLOT_HEIGHT,
                               "candela bench: RMS relative error of E (%) against wall seconds, log-log", err);
    free(labels);
    free(img);
    return st;
}
