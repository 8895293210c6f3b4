/* raster_canvas.c - an RGB8 image as a cairo RGB24 surface while it is drawn on. */
#include "base/error_report.h"
#include "graphics/raster_canvas.h"

#include <cairo.h>
#include <stdlib.h>

struct cdl_raster_canvas {
    uint8_t *rgb;
    int width, height;
    cairo_surface_t *surface;
    cairo_t *cr;
};

cdl_status cdl_raster_canvas_begin(uint8_t *rgb, int width, int height, cdl_raster_canvas **out, cdl_error *err)
{
    *out = NULL;
    cdl_raster_canvas *t = calloc(1, sizeof *t);
    if (!t) return cdl_error_out_of_memory(err);
    t->rgb = rgb;
    t->width = width;
    t->height = height;
    t->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    if (cairo_surface_status(t->surface) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(t->surface);
        free(t);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "cannot make a %d x %d drawing surface", width, height);
    }
    /* RGB24 keeps each pixel in a native-endian 32-bit word, 0x00RRGGBB. */
    unsigned char *data = cairo_image_surface_get_data(t->surface);
    int stride = cairo_image_surface_get_stride(t->surface);
    for (int y = 0; y < height; ++y) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        const uint8_t *src = rgb + (size_t)y * (size_t)width * 3;
        for (int x = 0; x < width; ++x)
            row[x] = (uint32_t)src[3 * x] << 16 | (uint32_t)src[3 * x + 1] << 8 | (uint32_t)src[3 * x + 2];
    }
    cairo_surface_mark_dirty(t->surface);
    t->cr = cairo_create(t->surface);
    *out = t;
    return CDL_OK;
}

void cdl_raster_canvas_text(cdl_raster_canvas *t, double x, double y, const char *text, const cdl_text_style *style,
                          const uint8_t colour[3])
{
    cairo_set_source_rgb(t->cr, colour[0] / 255.0, colour[1] / 255.0, colour[2] / 255.0);
    cdl_text_draw(t->cr, x, y, text, style);
}

void cdl_raster_canvas_fill_rect(cdl_raster_canvas *t, int x, int y, int w, int h, const uint8_t colour[3])
{
    cairo_set_source_rgb(t->cr, colour[0] / 255.0, colour[1] / 255.0, colour[2] / 255.0);
    cairo_rectangle(t->cr, x, y, w, h);
    cairo_fill(t->cr);
}

void cdl_raster_canvas_end(cdl_raster_canvas *t)
{
    if (!t) return;
    cairo_destroy(t->cr);
    cairo_surface_flush(t->surface);
    const unsigned char *data = cairo_image_surface_get_data(t->surface);
    int stride = cairo_image_surface_get_stride(t->surface);
    for (int y = 0; y < t->height; ++y) {
        const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
        uint8_t *dst = t->rgb + (size_t)y * (size_t)t->width * 3;
        for (int x = 0; x < t->width; ++x) {
            dst[3 * x] = (uint8_t)(row[x] >> 16);
            dst[3 * x + 1] = (uint8_t)(row[x] >> 8);
            dst[3 * x + 2] = (uint8_t)row[x];
        }
    }
    cairo_surface_destroy(t->surface);
    free(t);
}
