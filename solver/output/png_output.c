/* png_output.c - NAME.png: false-colour map of a grid's illuminance with a lux legend. */
#include "solver/output/grid_result.h"

#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "solver/output/bitmap_font.h"
#include "solver/output/display_transform.h"
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
    FONT_SCALE = 2,
    LABEL_HEIGHT = CDL_BITMAP_FONT_GLYPH_HEIGHT * FONT_SCALE,
    LABEL_SPACING = LABEL_HEIGHT + 10, /* least distance between two labelled ticks */
    MAX_IMAGE_PIXELS = 1 << 26        /* 64 Mpixel: a larger map is a caller's mistake */
};

static const uint8_t white[3] = {255, 255, 255};
static const uint8_t black[3] = {0, 0, 0};

static int clamp_int(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static int max_label_width(const cdl_lux_scale *scale)
{
    char label[64];
    int widest = 0;
    for (int k = scale->lo_step; k <= scale->hi_step; ++k) {
        cdl_lux_scale_step_label(k, label, sizeof label);
        int w = cdl_bitmap_font_text_width(label, FONT_SCALE);
        if (w > widest) widest = w;
    }
    return widest;
}

void cdl_grid_result_png_layout(const cdl_grid_result *result, cdl_png_layout *layout)
{
    const cdl_grid *grid = result->grid;
    memset(layout, 0, sizeof *layout);
    layout->scale = cdl_lux_scale_for_values(result->E, grid->count);
    int long_side = grid->raster_width > grid->raster_height ? grid->raster_width : grid->raster_height;
    if (long_side <= 0) long_side = 1;
    layout->cell = (MAP_LONG_SIDE + long_side - 1) / long_side;
    if (layout->cell < 1) layout->cell = 1;
    int map_w = grid->raster_width * layout->cell, map_h = grid->raster_height * layout->cell;
    layout->map_x = MARGIN;
    layout->map_y = MARGIN;
    layout->bar_width = BAR_WIDTH;
    layout->bar_height = clamp_int(map_h, BAR_MIN_HEIGHT, BAR_MAX_HEIGHT);
    layout->bar_x = layout->map_x + map_w + MAP_TO_BAR + 1; /* + 1: the frame */
    layout->bar_y = MARGIN;
    layout->label_x = layout->bar_x + BAR_WIDTH + 1 + TICK_LENGTH + TICK_TO_LABEL;
    layout->width = layout->label_x + max_label_width(&layout->scale) + MARGIN;
    layout->height = MARGIN + (map_h > layout->bar_height ? map_h : layout->bar_height) + MARGIN;
}

static void fill_rect(uint8_t *img, int width, int x0, int y0, int w, int h, const uint8_t colour[3])
{
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) memcpy(img + 3 * ((size_t)y * (size_t)width + (size_t)x), colour, 3);
}

/* Display-referred float in [0, 1] to an 8-bit code value, rounded to nearest. */
static uint8_t to_8bit(float v)
{
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (uint8_t)(v * 255.0f + 0.5f);
}

/* Colours of n positions t in [0, 1] through the false-colour view, as 8-bit RGB. */
static cdl_status false_colours(const cdl_display_transform *view, const double *t, size_t n, uint8_t *out,
                                cdl_error *err)
{
    float *rgb = malloc((n ? n : 1) * 3 * sizeof(float));
    if (!rgb) return cdl_error_out_of_memory(err);
    /* The view's input is a grey value; its 1D LUT gives each channel its own ramp. */
    for (size_t i = 0; i < n; ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = (float)t[i];
    cdl_status st = cdl_display_transform_apply(view, rgb, n, err);
    for (size_t i = 0; st == CDL_OK && i < 3 * n; ++i) out[i] = to_8bit(rgb[i]);
    free(rgb);
    return st;
}

/* Row of the bar where position t sits (top = 1, bottom = 0). */
static int bar_row(const cdl_png_layout *L, double t)
{
    return L->bar_y + (int)lround((1.0 - t) * (L->bar_height - 1));
}

/* Ticks at 1-2-5 values, the ends first, then decades, fives and twos, each
 * kept only if its label clears those already placed. */
static void draw_ticks(uint8_t *img, const cdl_png_layout *L)
{
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
            int y = bar_row(L, t);
            int clear = 1;
            for (int j = 0; j < placed; ++j)
                if (abs(placed_y[j] - y) < LABEL_SPACING) clear = 0;
            if (!clear) continue;
            placed_y[placed++] = y;
            fill_rect(img, L->width, L->bar_x + L->bar_width + 1, y, TICK_LENGTH, 1, black);
            char label[64];
            cdl_lux_scale_step_label(k, label, sizeof label);
            cdl_bitmap_font_draw_text(img, L->width, L->height, L->label_x, y - LABEL_HEIGHT / 2, label, FONT_SCALE,
                                      black);
        }
    }
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
    cdl_status st = false_colours(view, t, n + bar_n, colour, err);
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
        draw_ticks(img, L);
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

    char lo[64], hi[64], description[200];
    cdl_lux_scale_step_label(L.scale.lo_step, lo, sizeof lo);
    cdl_lux_scale_step_label(L.scale.hi_step, hi, sizeof hi);
    snprintf(description, sizeof description,
             "Illuminance in lux, false colour on a logarithmic scale from %s to %s", lo, hi);
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
