/* text.c - pango layouts of one style on a cairo context. */
#include "graphics/text.h"

#include <pango/pangocairo.h>
#include <stdlib.h>
#include <string.h>

/* A copy of text that pango accepts: itself when valid UTF-8, else with
 * every non-ASCII byte replaced by '?'. Free with g_free. */
static char *valid_utf8(const char *text)
{
    if (!text) return g_strdup("");
    if (g_utf8_validate(text, -1, NULL)) return g_strdup(text);
    char *copy = g_strdup(text);
    for (char *c = copy; *c; ++c)
        if ((unsigned char)*c >= 0x80) *c = '?';
    return copy;
}

static PangoLayout *layout_for(cairo_t *cr, const char *text, const cdl_text_style *style)
{
    PangoLayout *layout = pango_cairo_create_layout(cr);
    PangoFontDescription *font = pango_font_description_from_string("sans-serif");
    pango_font_description_set_absolute_size(font, style->size * PANGO_SCALE);
    if (style->bold) pango_font_description_set_weight(font, PANGO_WEIGHT_BOLD);
    pango_layout_set_font_description(layout, font);
    pango_font_description_free(font);
    if (style->wrap_width > 0.0) {
        pango_layout_set_width(layout, (int)(style->wrap_width * PANGO_SCALE));
        pango_layout_set_wrap(layout, PANGO_WRAP_WORD_CHAR);
        /* centred text wrapped: each line centred in the block */
        if (style->align == CDL_TEXT_CENTRE) pango_layout_set_alignment(layout, PANGO_ALIGN_CENTER);
    }
    char *valid = valid_utf8(text);
    pango_layout_set_text(layout, valid, -1);
    g_free(valid);
    return layout;
}

static void layout_size(PangoLayout *layout, double *width, double *height)
{
    PangoRectangle logical;
    pango_layout_get_extents(layout, NULL, &logical);
    if (width) *width = (double)logical.width / PANGO_SCALE;
    if (height) *height = (double)logical.height / PANGO_SCALE;
}

double cdl_text_draw(cairo_t *cr, double x, double y, const char *text, const cdl_text_style *style)
{
    if (!text || !*text) return 0.0;
    PangoLayout *layout = layout_for(cr, text, style);
    double w = 0.0, h = 0.0;
    layout_size(layout, &w, &h);
    /* a wrapped centred block is wrap_width wide, its lines centred in it */
    double block = style->align == CDL_TEXT_CENTRE && style->wrap_width > 0.0 ? style->wrap_width : w;
    double left = style->align == CDL_TEXT_CENTRE ? x - block / 2.0 : style->align == CDL_TEXT_RIGHT ? x - w : x;
    cairo_move_to(cr, left, y);
    pango_cairo_show_layout(cr, layout);
    cairo_new_path(cr);
    g_object_unref(layout);
    return h;
}

void cdl_text_measure(cairo_t *cr, const char *text, const cdl_text_style *style, double *width, double *height)
{
    if (!text || !*text) {
        if (width) *width = 0.0;
        if (height) *height = 0.0;
        return;
    }
    PangoLayout *layout = layout_for(cr, text, style);
    layout_size(layout, width, height);
    g_object_unref(layout);
}

void cdl_text_measure_alone(const char *text, const cdl_text_style *style, double *width, double *height)
{
    cairo_surface_t *scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    cairo_t *cr = cairo_create(scratch);
    cdl_text_measure(cr, text, style, width, height);
    cairo_destroy(cr);
    cairo_surface_destroy(scratch);
}
