/* figure.h - a figure drawn by a function onto a cairo SVG surface.
 *
 * A figure is a size (in points: 1/72 inch, SVG user units) and a function
 * that draws it on a cairo context whose origin is the figure's top-left
 * corner. The same function draws it on a report's PDF page (translated
 * there) and into SVG: as a file written atomically, or as text in memory
 * for an HTML page. Cairo draws text as glyph outlines, so the figure's
 * title is also written as the SVG's <title> element: what screen readers
 * say and what a search finds. Errors: CDL_ERR_INTERNAL naming what cairo reported,
 * or the atomic file's errors. Thread safety: none needed (no state).
 */
#ifndef CANDELA_GRAPHICS_FIGURE_H
#define CANDELA_GRAPHICS_FIGURE_H

#include <cairo.h>
#include <stddef.h>

#include "base/error.h"

typedef struct cdl_figure {
    double width, height;                 /* points */
    const char *title;                    /* the SVG's <title> (its accessible name), or NULL */
    void (*draw)(cairo_t *cr, const void *user);
    const void *user;
} cdl_figure;

/* The figure as an SVG document in memory: *svg (NUL-terminated, *size
 * bytes without the NUL) is the caller's to free. */
cdl_status cdl_figure_svg(const cdl_figure *figure, char **svg, size_t *size, cdl_error *err);

/* The figure as the SVG file at path, written atomically. */
cdl_status cdl_figure_write_svg(const cdl_figure *figure, const char *path, cdl_error *err);

#endif
