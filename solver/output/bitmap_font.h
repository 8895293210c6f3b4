/* bitmap_font.h - a tiny 5 x 7 pixel font for legend labels in PNG maps.
 *
 * Glyphs for the digits, the lower- and upper-case letters, '.', '-', '_',
 * '(', ')', '%', '/', '<', '>', '=', '+', ':', ',', '[', ']' and ' ':
 * enough for legend labels such as "0.05 lx", "500 lx" or "20k lx", map
 * titles ("Em 500 lx  U0 0.61") and axes ("+x (m)"), and the bench's plot
 * ("wall time (s)"). Text is drawn into packed 8-bit
 * RGB images (row-major, top row first), each font pixel as a scale x scale
 * square, clipped to the image. A character without a glyph is drawn as a
 * hollow box so that it shows rather than vanishes.
 */
#ifndef CANDELA_SOLVER_BITMAP_FONT_H
#define CANDELA_SOLVER_BITMAP_FONT_H

#include <stdint.h>

#define CDL_BITMAP_FONT_GLYPH_WIDTH 5
#define CDL_BITMAP_FONT_GLYPH_HEIGHT 7
/* Horizontal distance between character origins: the glyph and one blank column. */
#define CDL_BITMAP_FONT_ADVANCE 6

/* 1 when `c` has a glyph of its own. */
int cdl_bitmap_font_has_glyph(char c);

/* Row `row` (0 = top) of the glyph of `c`: bit 4 is the leftmost column. */
uint8_t cdl_bitmap_font_glyph_row(char c, int row);

/* Width in pixels of `text` drawn at `scale` (no trailing blank column). */
int cdl_bitmap_font_text_width(const char *text, int scale);

/* Draw `text` with its top-left corner at (x, y) in an RGB image of
 * width x height pixels. */
void cdl_bitmap_font_draw_text(uint8_t *rgb, int width, int height, int x, int y, const char *text, int scale,
                               const uint8_t colour[3]);

#endif
