/* png_output.c - NAME.png: false-colour map of a grid's illuminance with a lux legend. */
#include "solver/output/grid_result.h"

#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "graphics/raster_canvas.h"
#include "solver/output/display_transform.h"
#include "solver/output/false_colour.h"
#include "solver/output/png_write.h"

/* Layout, in image pixels. */
enum {
    MAP_LONG_SIDE = 400,   /* small rasters are enlarged until their long side reaches this */
    MARGIN = 16,           /* around everything */
    MAP_TO_BAR = 24,       /* between the map and the legend */
    BAR_WIDTH = 24,
    BAR_MIN_HEIGHT = 240,  /* room for a handful of labels even beside a flat map */
    BAR_MAX_HEIGHT = 600,
    TICK_LENGTH = 6,
    TICK_TO_LABEL = 4,
    FONT_PX = 12,          /* labels' em size (pango, DejaVu Sans) */
    LABEL_HEIGHT = 14,     /* the height of a line of FONT_PX text */
    LABEL_SPACING = LABEL_HEIGHT + 10, /* least distance between two labelled ticks */
    TITLE_GAP = 8,                     /* between the lines of text above and below the map */
    MAX_IMAGE_PIXELS = 1 << 26        /* 64 Mpixel: a larger map is a caller's mistake */
};

static const uint8_t white[3] = {255, 255, 255};
static const cdl_text_style label_style = {.size = FONT_PX};
static const uint8_t black[3] = {0, 0, 0};

static int clamp_int(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Width in pixels of a label, rounded up. */
static int text_width(const char *text)
{
    double w = 0.0;
    cdl_text_measure_alone(text, &label_style, &w, NULL);
    return (int)ceil(w);
}

static void put_text(cdl_raster_canvas *c, int x, int y, const char *text)
{
    cdl_raster_canvas_text(c, x, y, text, &label_style, black);
}

/* The legend's label of a linear scale's value (the bottom one "<=" when clipped). */
static void linear_label(const cdl_lux_scale *scale, const char *unit, double lx, int bottom, char *buf, size_t size)
{
    char v[48];
    if (unit[0]) snprintf(v, sizeof v, "%.6g %s", lx, unit); /* another quantity (cdl_map_quantity) */
    else cdl_lux_scale_value_label(lx, v, sizeof v);
    snprintf(buf, size, "%s%s", bottom && scale->clipped ? "<=" : "", v);
}

static int max_label_width(const cdl_lux_scale *scale, const char *unit)
{
    char label[64];
    int widest = 0;
    if (scale->kind == CDL_LUX_SCALE_LINEAR) {
        long ticks = lround((scale->hi.lx - scale->lo.lx) / scale->tick_lx);
        for (long m = 0; m <= ticks; ++m) {
            linear_label(scale, unit, scale->lo.lx + (double)m * scale->tick_lx, m == 0, label, sizeof label);
            int w = text_width(label);
            if (w > widest) widest = w;
        }
        return widest;
    }
    for (int k = scale->lo_step; k <= scale->hi_step; ++k) {
        cdl_lux_scale_step_label(k, label, sizeof label);
        int w = text_width(label);
        if (w > widest) widest = w;
    }
    return widest;
}

/* ---- axes in metres ------------------------------------------------------------- */

/* One edge of the map as an axis: its world direction's name when it runs
 * along a world axis ("+x"), and the coordinate its ticks count from. */
typedef struct map_axis {
    char name[16];            /* "+x (m)" or "u (m)" */
    double start;             /* the coordinate at the map's lower-left corner */
    double sign;              /* +1 or -1: how the coordinate grows along the edge */
    double length_m;          /* the edge's length */
    double step_m;            /* between ticks: a 1-2-5 value */
} map_axis;

static void axis_describe(map_axis *a, cdl_vec3 dir, cdl_vec3 corner, double length_m, const char *fallback,
                          double min_ticks_apart_m)
{
    const double c[3] = {dir.x, dir.y, dir.z}, o[3] = {corner.x, corner.y, corner.z};
    snprintf(a->name, sizeof a->name, "%s (m)", fallback);
    a->start = 0.0;
    a->sign = 1.0;
    for (int k = 0; k < 3; ++k)
        if (fabs(c[k]) > 1.0 - 1e-9) {
            snprintf(a->name, sizeof a->name, "%cx (m)", c[k] > 0.0 ? '+' : '-');
            a->name[1] = (char)('x' + k);
            a->start = o[k];
            a->sign = c[k] > 0.0 ? 1.0 : -1.0;
        }
    a->length_m = length_m;
    double raw = fmax(min_ticks_apart_m, length_m / 8.0);
    a->step_m = raw > 0.0 ? cdl_lux_scale_step_value(cdl_lux_scale_step_at_or_above(cdl_lux(raw))).lx : 1.0;
}

/* Tick values along an axis: the multiples of step within the edge, as
 * coordinates; calls tick(user, distance along the edge, value). */
static void axis_ticks(const map_axis *a, void (*tick)(void *, double, double), void *user)
{
    double first = a->sign > 0 ? ceil(a->start / a->step_m - 1e-9) : floor(a->start / a->step_m + 1e-9);
    for (int m = 0; m < 1000; ++m) {
        double value = (first + a->sign * m) * a->step_m;
        double along = (value - a->start) * a->sign;
        if (along > a->length_m * (1.0 + 1e-9)) break;
        /* Print 0 rather than -0 for a coordinate of zero. */
        tick(user, along, value == 0.0 ? 0.0 : value);
    }
}

static void axes_of(const cdl_grid *grid, const cdl_png_layout *L, map_axis *h, map_axis *v)
{
    double w_m = grid->raster_width * grid->pixel_width_m, h_m = grid->raster_height * grid->pixel_height_m;
    /* Labels need about 60 pixels apart across, 30 up. */
    double mpp_x = grid->pixel_width_m / L->cell, mpp_y = grid->pixel_height_m / L->cell;
    axis_describe(h, grid->raster_right, grid->raster_corner, w_m, "u", 60.0 * mpp_x);
    axis_describe(v, grid->raster_up, grid->raster_corner, h_m, "v", 30.0 * mpp_y);
}

static void tick_label(double value, char *buf, size_t size)
{
    snprintf(buf, size, "%.6g", value);
}

typedef struct widest_tick {
    int width;
} widest_tick;

static void measure_tick(void *user, double along, double value)
{
    (void)along;
    widest_tick *w = user;
    char label[32];
    tick_label(value, label, sizeof label);
    int width = text_width(label);
    if (width > w->width) w->width = width;
}

void cdl_grid_result_png_layout(const cdl_grid_result *result, cdl_png_layout *layout)
{
    const cdl_grid *grid = result->grid;
    memset(layout, 0, sizeof *layout);
    if (result->quantity) {
        /* another quantity: its fixed linear range */
        const cdl_map_quantity *q = result->quantity;
        layout->scale.kind = CDL_LUX_SCALE_LINEAR;
        layout->scale.lo = cdl_lux(q->lo);
        layout->scale.hi = cdl_lux(q->hi);
        layout->scale.tick_lx = q->tick;
        for (size_t i = 0; i < grid->count; ++i) layout->scale.clipped |= result->E[i] < q->lo;
        snprintf(layout->unit, sizeof layout->unit, "%s", q->unit);
    } else {
        layout->scale = result->map_log_scale ? cdl_lux_scale_for_values(result->E, grid->count)
                                              : cdl_lux_scale_linear_for_values(result->E, grid->count);
    }
    int long_side = grid->raster_width > grid->raster_height ? grid->raster_width : grid->raster_height;
    if (long_side <= 0) long_side = 1;
    layout->cell = (MAP_LONG_SIDE + long_side - 1) / long_side;
    if (layout->cell < 1) layout->cell = 1;
    int map_w = grid->raster_width * layout->cell, map_h = grid->raster_height * layout->cell;
    /* Title: the name, then the statistics; then the vertical axis' name. */
    layout->title_y = MARGIN;
    layout->stats_y = layout->title_y + LABEL_HEIGHT + TITLE_GAP;
    int axis_name_y = layout->stats_y + LABEL_HEIGHT + TITLE_GAP;
    map_axis h, v;
    axes_of(grid, layout, &h, &v); /* reads the cell size */
    widest_tick w = {0};
    axis_ticks(&v, measure_tick, &w);
    layout->axis_label_width = w.width + TICK_LENGTH + TICK_TO_LABEL;
    layout->map_x = MARGIN + layout->axis_label_width;
    layout->map_y = axis_name_y + LABEL_HEIGHT + TITLE_GAP + LABEL_HEIGHT / 2; /* clear of the top tick's label */
    layout->bar_width = BAR_WIDTH;
    layout->bar_height = clamp_int(map_h, BAR_MIN_HEIGHT, BAR_MAX_HEIGHT);
    layout->bar_x = layout->map_x + map_w + MAP_TO_BAR + 1; /* + 1: the frame */
    layout->bar_y = layout->map_y;
    layout->label_x = layout->bar_x + BAR_WIDTH + 1 + TICK_LENGTH + TICK_TO_LABEL;
    layout->width = layout->label_x + max_label_width(&layout->scale, layout->unit) + MARGIN;
    /* Below the map: ticks, their labels, the horizontal axis' name. */
    int below = map_h + TICK_LENGTH + TICK_TO_LABEL + LABEL_HEIGHT + TITLE_GAP + LABEL_HEIGHT;
    layout->height = layout->map_y + (below > layout->bar_height ? below : layout->bar_height) + MARGIN;
    /* The title may be wider than the map and legend. */
    char title[256];
    snprintf(title, sizeof title, "%s", result->name ? result->name : "");
    int title_w = MARGIN + text_width(title) + MARGIN;
    int stats_w = MARGIN +
                  text_width(result->quantity ? result->quantity->stats
                                              : "Em 0000000 lx  Emin 0000000 lx  Emax 0000000 lx  U0 0.000") +
                  MARGIN;
    if (title_w > layout->width) layout->width = title_w;
    if (stats_w > layout->width) layout->width = stats_w;
}

static void fill_rect(uint8_t *img, int width, int x0, int y0, int w, int h, const uint8_t colour[3])
{
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) memcpy(img + 3 * ((size_t)y * (size_t)width + (size_t)x), colour, 3);
}

/* Row of the bar where position t sits (top = 1, bottom = 0). */
static int bar_row(const cdl_png_layout *L, double t)
{
    return L->bar_y + (int)lround((1.0 - t) * (L->bar_height - 1));
}

/* Ticks at 1-2-5 values, the ends first, then decades, fives and twos, each
 * kept only if its label clears those already placed. */
static void draw_linear_ticks(cdl_raster_canvas *img, const cdl_png_layout *L);

/* A tick at row y of the bar with its label, unless the label would come
 * closer than LABEL_SPACING to one already placed (placed_y[0 .. *placed)). */
static void place_tick(cdl_raster_canvas *img, const cdl_png_layout *L, int y, const char *label, int *placed_y, int *placed)
{
    for (int j = 0; j < *placed; ++j)
        if (abs(placed_y[j] - y) < LABEL_SPACING) return;
    placed_y[(*placed)++] = y;
    cdl_raster_canvas_fill_rect(img, L->bar_x + L->bar_width + 1, y, TICK_LENGTH, 1, black);
    put_text(img, L->label_x, y - LABEL_HEIGHT / 2, label);
}

static void draw_ticks(cdl_raster_canvas *img, const cdl_png_layout *L)
{
    if (L->scale.kind == CDL_LUX_SCALE_LINEAR) {
        draw_linear_ticks(img, L);
        return;
    }
    int rank_count = L->scale.hi_step - L->scale.lo_step + 1;
    int placed_y[CDL_LUX_SCALE_MAX_STEP - CDL_LUX_SCALE_MIN_STEP + 1];
    int placed = 0;
    static const int mantissa_order[3] = {0, 2, 1}; /* step mod 3: 1, then 5, then 2 */
    for (int pass = 0; pass < 4; ++pass) {
        for (int i = 0; i < rank_count; ++i) {
            int k = L->scale.lo_step + i;
            int is_end = k == L->scale.lo_step || k == L->scale.hi_step;
            int kind = ((k % 3) + 3) % 3;
            if (pass == 0 ? !is_end : (is_end || kind != mantissa_order[pass - 1])) continue;
            double t = cdl_lux_scale_position(&L->scale, cdl_lux_scale_step_value(k));
            char label[64];
            cdl_lux_scale_step_label(k, label, sizeof label);
            place_tick(img, L, bar_row(L, t), label, placed_y, &placed);
        }
    }
}

/* Linear ticks at multiples of the scale's tick: the ends first, then the
 * others from the bottom, each kept if its label clears those placed. */
static void draw_linear_ticks(cdl_raster_canvas *img, const cdl_png_layout *L)
{
    long count = lround((L->scale.hi.lx - L->scale.lo.lx) / L->scale.tick_lx);
    int placed_y[64];
    int placed = 0;
    for (int pass = 0; pass < 2; ++pass)
        for (long m = 0; m <= count && placed < 64; ++m) {
            int is_end = m == 0 || m == count;
            if (pass == 0 ? !is_end : is_end) continue;
            double lx = L->scale.lo.lx + (double)m * L->scale.tick_lx;
            int y = m == count ? L->bar_y : bar_row(L, cdl_lux_scale_position(&L->scale, cdl_lux(lx)));
            char label[64];
            linear_label(&L->scale, L->unit, lx, m == 0, label, sizeof label);
            place_tick(img, L, y, label, placed_y, &placed);
        }
}

/* ---- title and axes ------------------------------------------------------------- */

typedef struct axis_draw {
    cdl_raster_canvas *img;
    const cdl_png_layout *L;
    const cdl_grid *grid;
    int horizontal;
} axis_draw;

static void draw_tick(void *user, double along, double value)
{
    axis_draw *a = user;
    const cdl_png_layout *L = a->L;
    char label[32];
    tick_label(value, label, sizeof label);
    int w = text_width(label);
    int map_w = a->grid->raster_width * L->cell, map_h = a->grid->raster_height * L->cell;
    if (a->horizontal) {
        int x = L->map_x + (int)lround(along / a->grid->pixel_width_m * L->cell);
        if (x > L->map_x + map_w) x = L->map_x + map_w;
        cdl_raster_canvas_fill_rect(a->img, x, L->map_y + map_h, 1, TICK_LENGTH, black);
        int lx = clamp_int(x - w / 2, 0, L->width - w);
        put_text(a->img, lx, L->map_y + map_h + TICK_LENGTH + TICK_TO_LABEL, label);
    } else {
        int y = L->map_y + map_h - (int)lround(along / a->grid->pixel_height_m * L->cell);
        if (y < L->map_y) y = L->map_y;
        cdl_raster_canvas_fill_rect(a->img, L->map_x - TICK_LENGTH, y, TICK_LENGTH, 1, black);
        put_text(a->img, L->map_x - TICK_LENGTH - TICK_TO_LABEL - w,
                 clamp_int(y - LABEL_HEIGHT / 2, 0, L->height - LABEL_HEIGHT), label);
    }
}

static void draw_title_and_axes(const cdl_grid_result *result, const cdl_png_layout *L, cdl_raster_canvas *img)
{
    const cdl_grid *grid = result->grid;
    cdl_grid_stats st;
    cdl_grid_result_stats(result, &st);
    char line[256];
    snprintf(line, sizeof line, "%s", result->name ? result->name : "");
    put_text(img, MARGIN, L->title_y, line);
    if (result->quantity) snprintf(line, sizeof line, "%s", result->quantity->stats);
    else
        snprintf(line, sizeof line, "Em %.4g lx  Emin %.4g lx  Emax %.4g lx  U0 %.3f", st.E_avg_lx, st.E_min_lx,
                 st.E_max_lx, st.U0);
    put_text(img, MARGIN, L->stats_y, line);
    map_axis h, v;
    axes_of(grid, L, &h, &v);
    int map_w = grid->raster_width * L->cell, map_h = grid->raster_height * L->cell;
    /* The axes' lines, then their ticks and names. */
    cdl_raster_canvas_fill_rect(img, L->map_x - 1, L->map_y, 1, map_h + 1, black);
    cdl_raster_canvas_fill_rect(img, L->map_x - 1, L->map_y + map_h, map_w + 1, 1, black);
    axis_draw hd = {img, L, grid, 1}, vd = {img, L, grid, 0};
    axis_ticks(&h, draw_tick, &hd);
    axis_ticks(&v, draw_tick, &vd);
    int name_w = text_width(h.name);
    put_text(img, L->map_x + map_w - name_w,
             L->map_y + map_h + TICK_LENGTH + TICK_TO_LABEL + LABEL_HEIGHT + TITLE_GAP, h.name);
    put_text(img, MARGIN, L->map_y - LABEL_HEIGHT / 2 - TITLE_GAP - LABEL_HEIGHT, v.name);
}

/* Map and legend into img (L->width x L->height, RGB8). */
static cdl_status render(const cdl_grid_result *result, const cdl_png_layout *L, const cdl_display_transform *view,
                         uint8_t *img, cdl_error *err)
{
    const cdl_grid *grid = result->grid;
    size_t n = grid->count;
    size_t bar_n = (size_t)L->bar_height;
    double *t = malloc((n + bar_n) * sizeof(double));
    uint8_t *colour = malloc((n + bar_n) * 3);
    if (!t || !colour) {
        free(t);
        free(colour);
        return cdl_error_out_of_memory(err);
    }
    for (size_t i = 0; i < n; ++i) t[i] = cdl_lux_scale_position(&L->scale, cdl_lux(result->E[i]));
    for (size_t r = 0; r < bar_n; ++r) t[n + r] = bar_n > 1 ? 1.0 - (double)r / (double)(bar_n - 1) : 1.0;
    cdl_status st = cdl_false_colour_rgb8(view, t, n + bar_n, colour, err);
    if (st == CDL_OK) {
        fill_rect(img, L->width, 0, 0, L->width, L->height, white);
        for (int r = 0; r < grid->raster_height; ++r)
            for (int c = 0; c < grid->raster_width; ++c) {
                int32_t idx = grid->raster_index[(size_t)r * (size_t)grid->raster_width + (size_t)c];
                if (idx < 0) continue;
                fill_rect(img, L->width, L->map_x + c * L->cell, L->map_y + r * L->cell, L->cell, L->cell,
                          colour + 3 * (size_t)idx);
            }
        fill_rect(img, L->width, L->bar_x - 1, L->bar_y - 1, L->bar_width + 2, L->bar_height + 2, black);
        for (size_t r = 0; r < bar_n; ++r)
            fill_rect(img, L->width, L->bar_x, L->bar_y + (int)r, L->bar_width, 1, colour + 3 * (n + r));
        /* Ticks, labels and axes through cairo (text laid out by pango). */
        cdl_raster_canvas *canvas = NULL;
        st = cdl_raster_canvas_begin(img, L->width, L->height, &canvas, err);
        if (st == CDL_OK) {
            draw_ticks(canvas, L);
            draw_title_and_axes(result, L, canvas);
            cdl_raster_canvas_end(canvas);
        }
    }
    free(t);
    free(colour);
    return st;
}

/* libpng reports errors by calling this, which must not return: keep the
 * message and jump back to encode_png. Warnings are dropped (never printed). */
typedef struct png_failure {
    char message[256];
} png_failure;

static void png_error_to_message(png_structp png, png_const_charp msg)
{
    png_failure *f = png_get_error_ptr(png);
    if (f) snprintf(f->message, sizeof f->message, "%s", msg ? msg : "unknown error");
    png_longjmp(png, 1);
}

static void png_ignore_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static cdl_status encode_png(FILE *fp, const uint8_t *img, int width, int height, const char *description,
                             const char *path, cdl_error *err)
{
    png_failure failure = {"unknown error"};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, png_error_to_message, png_ignore_warning);
    if (!png) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot start the PNG encoder (out of memory)", path);
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot start the PNG encoder (out of memory)", path);
    }
    png_text text[2];
    memset(text, 0, sizeof text);
    text[0].compression = PNG_TEXT_COMPRESSION_NONE;
    text[0].key = "Software";
    text[0].text = "Candela " CANDELA_VERSION;
    text[1].compression = PNG_TEXT_COMPRESSION_NONE;
    text[1].key = "Description";
    text[1].text = (char *)description;

    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: PNG encoding failed: %s", path, failure.message);
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    /* The pixels are sRGB-encoded (the maps by the OCIO display transform): say so. */
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_set_text(png, info, text, 2);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, img + (size_t)y * (size_t)width * 3);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return CDL_OK;
}

cdl_status cdl_grid_result_write_png(const cdl_grid_result *result, const char *path, const char *ocio_config,
                                     cdl_error *err)
{
    cdl_status st = cdl_grid_result_check_with_raster(result, path, err);
    if (st != CDL_OK) return st;
    const cdl_grid *grid = result->grid;
    if (!ocio_config) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: no OpenColorIO config given", path);

    cdl_png_layout L;
    cdl_grid_result_png_layout(result, &L);
    if ((double)L.width * (double)L.height > (double)MAX_IMAGE_PIXELS)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: a map of %d x %d pixels is too large (raster %d x %d)", path,
                             L.width, L.height, grid->raster_width, grid->raster_height);

    cdl_display_transform *view = NULL;
    st = cdl_display_transform_open(ocio_config, "linear", "sRGB", "False colour", &view, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", path);
    uint8_t *img = malloc((size_t)L.width * (size_t)L.height * 3);
    if (!img) {
        cdl_display_transform_release(view);
        return cdl_error_out_of_memory(err);
    }
    st = render(result, &L, view, img, err);
    cdl_display_transform_release(view);
    if (st != CDL_OK) {
        free(img);
        return cdl_error_prefix(err, "%s: ", path);
    }

    char lo[64], hi[64], description[300];
    if (result->quantity) {
        snprintf(lo, sizeof lo, "%.6g %s", L.scale.lo.lx, L.unit);
        snprintf(hi, sizeof hi, "%.6g %s", L.scale.hi.lx, L.unit);
    } else if (L.scale.kind == CDL_LUX_SCALE_LINEAR) {
        cdl_lux_scale_value_label(L.scale.lo.lx, lo, sizeof lo);
        cdl_lux_scale_value_label(L.scale.hi.lx, hi, sizeof hi);
    } else {
        cdl_lux_scale_step_label(L.scale.lo_step, lo, sizeof lo);
        cdl_lux_scale_step_label(L.scale.hi_step, hi, sizeof hi);
    }
    snprintf(description, sizeof description, "%s: %s, false colour on a %s scale from %s to %s",
             result->name ? result->name : "grid", result->quantity ? result->quantity->what : "illuminance in lux",
             L.scale.kind == CDL_LUX_SCALE_LINEAR ? "linear" : "logarithmic", lo, hi);
    st = cdl_png_write_rgb(path, img, L.width, L.height, description, err);
    free(img);
    return st;
}

cdl_status cdl_png_write_rgb(const char *path, const uint8_t *rgb, int width, int height, const char *description,
                             cdl_error *err)
{
    cdl_atomic_file file;
    cdl_status st = cdl_atomic_file_open(&file, path, err);
    if (st != CDL_OK) return st;
    st = encode_png(file.fp, rgb, width, height, description, path, err);
    if (st == CDL_OK) return cdl_atomic_file_commit(&file, err);
    cdl_atomic_file_abort(&file);
    return st;
}
