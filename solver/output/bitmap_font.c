/* bitmap_font.c - the glyphs of bitmap_font.h, drawn by hand on a 5 x 7 grid. */
#include "solver/output/bitmap_font.h"

#include <string.h>

typedef struct glyph {
    char c;
    uint8_t rows[CDL_BITMAP_FONT_GLYPH_HEIGHT]; /* bit 4 = left column */
} glyph;

/* Each row reads as five pixels, left to right: 0x0E = .###. */
static const glyph glyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'k', {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12}},
    {'l', {0x08, 0x08, 0x08, 0x08, 0x08, 0x08, 0x06}}, /* a foot unlike '1' */
    {'x', {0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11}},
    {' ', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},
};

/* Drawn for a character the font lacks. */
static const uint8_t missing_rows[CDL_BITMAP_FONT_GLYPH_HEIGHT] = {0x1F, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1F};

static const uint8_t *find_rows(char c)
{
    for (size_t i = 0; i < sizeof glyphs / sizeof glyphs[0]; ++i)
        if (glyphs[i].c == c) return glyphs[i].rows;
    return NULL;
}

int cdl_bitmap_font_has_glyph(char c)
{
    return find_rows(c) != NULL;
}

uint8_t cdl_bitmap_font_glyph_row(char c, int row)
{
    if (row < 0 || row >= CDL_BITMAP_FONT_GLYPH_HEIGHT) return 0;
    const uint8_t *rows = find_rows(c);
    return (rows ? rows : missing_rows)[row];
}

int cdl_bitmap_font_text_width(const char *text, int scale)
{
    size_t n = strlen(text);
    if (n == 0 || scale <= 0) return 0;
    return ((int)n * CDL_BITMAP_FONT_ADVANCE - (CDL_BITMAP_FONT_ADVANCE - CDL_BITMAP_FONT_GLYPH_WIDTH)) * scale;
}

static void fill_square(uint8_t *rgb, int width, int height, int x0, int y0, int size, const uint8_t colour[3])
{
    for (int y = y0 < 0 ? 0 : y0; y < y0 + size && y < height; ++y)
        for (int x = x0 < 0 ? 0 : x0; x < x0 + size && x < width; ++x)
            memcpy(rgb + 3 * ((size_t)y * (size_t)width + (size_t)x), colour, 3);
}

void cdl_bitmap_font_draw_text(uint8_t *rgb, int width, int height, int x, int y, const char *text, int scale,
                               const uint8_t colour[3])
{
    if (scale <= 0) return;
    for (size_t i = 0; text[i]; ++i) {
        int origin = x + (int)i * CDL_BITMAP_FONT_ADVANCE * scale;
        for (int row = 0; row < CDL_BITMAP_FONT_GLYPH_HEIGHT; ++row) {
            uint8_t bits = cdl_bitmap_font_glyph_row(text[i], row);
            for (int col = 0; col < CDL_BITMAP_FONT_GLYPH_WIDTH; ++col)
                if (bits & (0x10 >> col))
                    fill_square(rgb, width, height, origin + col * scale, y + row * scale, scale, colour);
        }
    }
}
