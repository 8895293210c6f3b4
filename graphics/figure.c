/* figure.c - cairo's SVG surface into a growing buffer. */
#include "graphics/figure.h"

#include <cairo-svg.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/error_report.h"

typedef struct svg_buffer {
    char *data;
    size_t size, capacity;
    int failed;
} svg_buffer;

static cairo_status_t append(void *closure, const unsigned char *data, unsigned int length)
{
    svg_buffer *b = closure;
    if (b->size + length + 1 > b->capacity) {
        size_t cap = b->capacity ? b->capacity : 4096;
        while (cap < b->size + length + 1) cap *= 2;
        char *grown = realloc(b->data, cap);
        if (!grown) {
            b->failed = 1;
            return CAIRO_STATUS_NO_MEMORY;
        }
        b->data = grown;
        b->capacity = cap;
    }
    memcpy(b->data + b->size, data, length);
    b->size += length;
    b->data[b->size] = '\0';
    return CAIRO_STATUS_SUCCESS;
}

/* The title, XML-escaped (bytes outside ASCII dropped: their encoding is
 * unknown), as <title> right after the <svg ...> start tag. */
static cdl_status insert_title(svg_buffer *b, const char *title)
{
    char *svg_tag = strstr(b->data, "<svg");
    char *tag_end = svg_tag ? strchr(svg_tag, '>') : NULL;
    if (!tag_end) return CDL_OK;
    size_t at = (size_t)(tag_end + 1 - b->data);
    size_t n = strlen(title);
    char *text = malloc(6 * n + 32);
    if (!text) return CDL_ERR_INTERNAL;
    size_t k = (size_t)sprintf(text, "\n<title>");
    for (const char *c = title; *c; ++c) {
        unsigned char u = (unsigned char)*c;
        if (u == '&') k += (size_t)sprintf(text + k, "&amp;");
        else if (u == '<') k += (size_t)sprintf(text + k, "&lt;");
        else if (u == '>') k += (size_t)sprintf(text + k, "&gt;");
        else if (u >= 0x20 && u < 0x7F) text[k++] = (char)u;
    }
    k += (size_t)sprintf(text + k, "</title>");
    cairo_status_t grown = append(b, (const unsigned char *)text, (unsigned int)k); /* room at the end */
    if (grown != CAIRO_STATUS_SUCCESS) {
        free(text);
        return CDL_ERR_INTERNAL;
    }
    size_t tail = b->size - k - at;
    memmove(b->data + at + k, b->data + at, tail);
    memcpy(b->data + at, text, k);
    b->data[b->size] = '\0';
    free(text);
    return CDL_OK;
}

cdl_status cdl_figure_svg(const cdl_figure *figure, char **svg, size_t *size, cdl_error *err)
{
    *svg = NULL;
    *size = 0;
    svg_buffer b = {0};
    cairo_surface_t *surface = cairo_svg_surface_create_for_stream(append, &b, figure->width, figure->height);
    cairo_t *cr = cairo_create(surface);
    figure->draw(cr, figure->user);
    cairo_status_t drawn = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    cairo_status_t finished = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (b.failed) {
        free(b.data);
        return cdl_error_out_of_memory(err);
    }
    if (drawn != CAIRO_STATUS_SUCCESS || finished != CAIRO_STATUS_SUCCESS || !b.data) {
        free(b.data);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "drawing an SVG figure failed: %s",
                             cairo_status_to_string(drawn != CAIRO_STATUS_SUCCESS ? drawn : finished));
    }
    if (figure->title && *figure->title) {
        cdl_status st = insert_title(&b, figure->title);
        if (st != CDL_OK) {
            free(b.data);
            return cdl_error_out_of_memory(err);
        }
    }
    *svg = b.data;
    *size = b.size;
    return CDL_OK;
}

cdl_status cdl_figure_write_svg(const cdl_figure *figure, const char *path, cdl_error *err)
{
    char *svg = NULL;
    size_t size = 0;
    cdl_status st = cdl_figure_svg(figure, &svg, &size, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", path);
    st = cdl_atomic_file_write_all(path, svg, size, err);
    free(svg);
    return st;
}
