/* raster_canvas.h - cairo drawing (text by pango, rectangles) into a packed RGB8 image.
 *
 * The PNG writers build their images as 8-bit RGB rows (png_write.h); their
 * labels are laid out by pango. Between begin and end the image is held as
 * a cairo surface (draw into it only through the canvas); end copies it
 * back into the caller's pixels.
 *
 *   cdl_raster_canvas *t;
 *   if (cdl_raster_canvas_begin(rgb, width, height, &t, err) != CDL_OK) ...
 *   cdl_raster_canvas_text(t, x, y, "500 lx", &style, black);
 *   cdl_raster_canvas_end(t);               // rgb now carries the text
 *
 * Errors: CDL_ERR_INTERNAL when cairo cannot make the surface (memory).
 * Thread safety: one image per object.
 */
#ifndef CANDELA_GRAPHICS_RASTER_CANVAS_H
#define CANDELA_GRAPHICS_RASTER_CANVAS_H

#include <stdint.h>

#include "graphics/text.h"
#include "base/error.h"

typedef struct cdl_raster_canvas cdl_raster_canvas;

cdl_status cdl_raster_canvas_begin(uint8_t *rgb, int width, int height, cdl_raster_canvas **out, cdl_error *err);

/* Draw `text` (top at y, aligned on x by the style) in colour. */
void cdl_raster_canvas_text(cdl_raster_canvas *t, double x, double y, const char *text, const cdl_text_style *style,
                          const uint8_t colour[3]);

/* Fill the w x h pixels whose top-left pixel is (x, y) with colour. */
void cdl_raster_canvas_fill_rect(cdl_raster_canvas *t, int x, int y, int w, int h, const uint8_t colour[3]);

/* Copy the drawing back into the image and free the object (NULL is fine). */
void cdl_raster_canvas_end(cdl_raster_canvas *t);

#endif
