/* The legend font: every needed character has a distinct, non-empty glyph;
 * drawing scales, clips at the image edges and never writes outside. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "solver/output/bitmap_font.h"

static const char needed[] = "0123456789.-klx" "ABCDEFGHIJKLMNOPQRSTUVWXYZ+:=,>[]";

/* Pixels set to `colour` in an RGB image. */
static int count_colour(const uint8_t *rgb, int w, int h, const uint8_t colour[3])
{
    int n = 0;
    for (int i = 0; i < w * h; ++i) n += memcmp(rgb + 3 * i, colour, 3) == 0;
    return n;
}

static int glyph_pixels(char c)
{
    int n = 0;
    for (int r = 0; r < CDL_BITMAP_FONT_GLYPH_HEIGHT; ++r)
        for (uint8_t bits = cdl_bitmap_font_glyph_row(c, r); bits; bits &= (uint8_t)(bits - 1)) ++n;
    return n;
}

int main(void)
{
    /* Each character of the labels has its own glyph, within 5 columns. */
    for (const char *c = needed; *c; ++c) {
        CHECK_MSG(cdl_bitmap_font_has_glyph(*c), "'%c'", *c);
        CHECK_MSG(glyph_pixels(*c) > 0, "'%c' is blank", *c);
        for (int r = 0; r < CDL_BITMAP_FONT_GLYPH_HEIGHT; ++r) CHECK(cdl_bitmap_font_glyph_row(*c, r) < 0x20);
    }
    CHECK(cdl_bitmap_font_has_glyph(' ') && glyph_pixels(' ') == 0);
    CHECK(!cdl_bitmap_font_has_glyph('~'));
    CHECK(glyph_pixels('~') > 0); /* a missing glyph shows as a box */

    /* No two glyphs alike (a copy-paste slip would make two digits read the same). */
    for (const char *a = needed; *a; ++a)
        for (const char *b = a + 1; *b; ++b) {
            int same = 1;
            for (int r = 0; r < CDL_BITMAP_FONT_GLYPH_HEIGHT; ++r)
                same = same && cdl_bitmap_font_glyph_row(*a, r) == cdl_bitmap_font_glyph_row(*b, r);
            CHECK_MSG(!same, "'%c' and '%c' share a glyph", *a, *b);
        }

    /* Width: n advances of 6 less the blank column after the last glyph. */
    CHECK(cdl_bitmap_font_text_width("500 lx", 1) == 6 * 6 - 1);
    CHECK(cdl_bitmap_font_text_width("500 lx", 2) == 2 * (6 * 6 - 1));
    CHECK(cdl_bitmap_font_text_width("", 2) == 0);

    /* Drawing at scale s sets s^2 image pixels per font pixel, all inside the
     * text's box. */
    const int w = 80, h = 30;
    uint8_t *img = calloc((size_t)w * h * 3, 1);
    const uint8_t ink[3] = {255, 0, 0};
    CHECK(img != NULL);
    if (!img) return check_finish();
    const char *text = "0.25 lx";
    int font_pixels = 0;
    for (const char *c = text; *c; ++c) font_pixels += glyph_pixels(*c);
    cdl_bitmap_font_draw_text(img, w, h, 3, 4, text, 1, ink);
    CHECK(count_colour(img, w, h, ink) == font_pixels);
    int tw = cdl_bitmap_font_text_width(text, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (memcmp(img + 3 * (y * w + x), ink, 3) == 0)
                CHECK(x >= 3 && x < 3 + tw && y >= 4 && y < 4 + CDL_BITMAP_FONT_GLYPH_HEIGHT);
    memset(img, 0, (size_t)w * h * 3);
    cdl_bitmap_font_draw_text(img, w, h, 0, 0, "8", 3, ink);
    CHECK(count_colour(img, w, h, ink) == 9 * glyph_pixels('8'));

    /* Clipping: text hanging off every edge draws only what is inside (ASan
     * would catch a write outside the buffer). */
    memset(img, 0, (size_t)w * h * 3);
    cdl_bitmap_font_draw_text(img, w, h, -7, -5, "888", 2, ink);
    cdl_bitmap_font_draw_text(img, w, h, w - 4, h - 3, "888", 2, ink);
    int inside = count_colour(img, w, h, ink);
    CHECK(inside > 0 && inside < 2 * 3 * 4 * glyph_pixels('8'));
    /* A top-left corner fully outside draws nothing. */
    memset(img, 0, (size_t)w * h * 3);
    cdl_bitmap_font_draw_text(img, w, h, w + 10, 0, "1", 1, ink);
    cdl_bitmap_font_draw_text(img, w, h, 0, -100, "1", 4, ink);
    CHECK(count_colour(img, w, h, ink) == 0);
    free(img);
    return check_finish();
}
