/* text.h - a line of text drawn with pango onto any cairo surface.
 *
 * Every label Candela draws (map legends and axes, polar diagrams, the
 * report's pages) goes through here, so all figures share one face:
 * fontconfig's "sans-serif" (DejaVu Sans on Debian), at a size in the
 * surface's user units (pixels on an image, points on PDF and SVG).
 * Positions name the top of the line and its left edge, centre or right
 * edge. Text that is not valid UTF-8 (names from photometric files in an
 * unknown encoding) is drawn with every byte outside ASCII shown as '?',
 * never handed to pango invalid (pango would print a warning). Thread
 * safety: the caller's cairo context only; no state here.
 */
#ifndef CANDELA_GRAPHICS_TEXT_H
#define CANDELA_GRAPHICS_TEXT_H

#include <cairo.h>

typedef enum cdl_text_align { CDL_TEXT_LEFT, CDL_TEXT_CENTRE, CDL_TEXT_RIGHT } cdl_text_align;

typedef struct cdl_text_style {
    double size;           /* em size in user units */
    int bold;
    cdl_text_align align;
    double wrap_width;     /* > 0: wrap into lines no wider than this */
} cdl_text_style;

/* Draw `text` in the current source colour with its top at y and x as the
 * style aligns it; returns the height of what was drawn (all lines). */
double cdl_text_draw(cairo_t *cr, double x, double y, const char *text, const cdl_text_style *style);

/* Width and height `text` would take (0 for NULL or empty text). */
void cdl_text_measure(cairo_t *cr, const char *text, const cdl_text_style *style, double *width, double *height);

/* The same, with no surface at hand (a scratch image surface is used). */
void cdl_text_measure_alone(const char *text, const cdl_text_style *style, double *width, double *height);

#endif
