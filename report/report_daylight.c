/* report_daylight.c - an annual daylight study's report (report_daylight.h). */
#include "report/report_daylight.h"

#include <cairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/strings.h"
#include "report/report_builder.h"

/* A map's pixel in points: a 700-pixel map fills a page's width. */
#define CDL_REPORT_IMAGE_SCALE 0.6

struct cdl_report_image {
    cairo_surface_t *surface;
    char title[160];
};

void cdl_report_images_release(cdl_report_image **images, size_t count)
{
    for (size_t k = 0; images && k < count; ++k) {
        cairo_surface_destroy(images[k]->surface);
        free(images[k]);
    }
    free(images);
}

int cdl_report_is_annual(const cJSON *summary)
{
    return cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(summary, "annual"));
}

static const cJSON *at(const cJSON *o, const char *dotted)
{
    char key[64];
    while (o && dotted) {
        const char *dot = strchr(dotted, '.');
        size_t n = dot ? (size_t)(dot - dotted) : strlen(dotted);
        snprintf(key, sizeof key, "%.*s", (int)n, dotted);
        o = cJSON_GetObjectItemCaseSensitive(o, key);
        dotted = dot ? dot + 1 : NULL;
    }
    return o;
}

static double num(const cJSON *o, const char *key)
{
    const cJSON *v = at(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : 0.0;
}

static const char *str(const cJSON *o, const char *key)
{
    const cJSON *v = at(o, key);
    return cJSON_IsString(v) ? v->valuestring : "?";
}

/* ---- pictures --------------------------------------------------------------------- */

static void draw_image(cairo_t *cr, const void *user)
{
    const cdl_report_image *im = user;
    cairo_save(cr);
    cairo_scale(cr, CDL_REPORT_IMAGE_SCALE, CDL_REPORT_IMAGE_SCALE);
    cairo_set_source_surface(cr, im->surface, 0.0, 0.0);
    cairo_paint(cr);
    cairo_restore(cr);
}

/* The folder's PNG NAME SUFFIX.png, kept by the document; NULL when there is
 * none (points grids have no maps) or memory ran out (b->failed). */
static cdl_report_image *load_picture(cdl_report_builder *b, const char *out_dir, const char *name,
                                      const char *suffix, const char *what)
{
    char file[160];
    snprintf(file, sizeof file, "%s%s", name, suffix);
    char *path = cdl_path_join(out_dir, file, ".png");
    if (!path) {
        b->failed = 1;
        return NULL;
    }
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    free(path);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return NULL;
    }
    cdl_report_document *d = b->doc;
    cdl_report_image **more = realloc(d->images, (d->image_count + 1) * sizeof *more);
    cdl_report_image *im = more ? malloc(sizeof *im) : NULL;
    if (more) d->images = more;
    if (!im) {
        cairo_surface_destroy(s);
        b->failed = 1;
        return NULL;
    }
    d->images[d->image_count++] = im;
    im->surface = s;
    snprintf(im->title, sizeof im->title, "%s: %s", name, what);
    return im;
}

static void add_picture(cdl_report_builder *b, const cdl_report_image *im)
{
    cdl_figure f = {CDL_REPORT_IMAGE_SCALE * cairo_image_surface_get_width(im->surface),
                    CDL_REPORT_IMAGE_SCALE * cairo_image_surface_get_height(im->surface), im->title, draw_image, im};
    cdl_report_figure(b, f, 1.0);
}

/* ---- sections ---------------------------------------------------------------------- */

static void cover(cdl_report_builder *b, const char *out_dir, const cJSON *s)
{
    const cJSON *a = at(s, "annual");
    cdl_report_text(b, CDL_BLOCK_HEADING, 1, "%s", b->doc->title);
    cdl_report_block *t = cdl_report_table(b, 2, 10, 0);
    size_t r = 0;
    cdl_report_cell(b, t, r, 0, "Scene");
    cdl_report_cell(b, t, r++, 1, "%s", str(s, "scene"));
    cdl_report_cell(b, t, r, 0, "Results");
    cdl_report_cell(b, t, r++, 1, "%s", out_dir);
    cdl_report_cell(b, t, r, 0, "Weather");
    cdl_report_cell(b, t, r++, 1, "%s: %s, %s; latitude %.4g, longitude %.4g, UTC%+.3g h, %.4g m; %.0f hours, the sun "
                    "placed in %.0f",
                    str(a, "weather.file"), str(a, "weather.city"), str(a, "weather.country"),
                    num(a, "weather.latitude_deg"), num(a, "weather.longitude_deg"), num(a, "weather.time_zone_h"),
                    num(a, "weather.elevation_m"), num(a, "weather.hours"), num(a, "weather.sun_year"));
    cdl_report_cell(b, t, r, 0, "Sky");
    cdl_report_cell(b, t, r++, 1, "%s", str(a, "sky.words"));
    cdl_report_cell(b, t, r, 0, "Patches");
    cdl_report_cell(b, t, r++, 1, "MF %.0f: %.0f sky patches and the ground", num(a, "sky.patches.mf"),
                    num(a, "sky.patches.sky_patches"));
    cdl_report_cell(b, t, r, 0, "Occupancy");
    cdl_report_cell(b, t, r++, 1, "%s", str(a, "occupancy"));
    cdl_report_cell(b, t, r, 0, "Daylight hours");
    cdl_report_cell(b, t, r++, 1, "%.0f (%s)", num(a, "daylight_hours"), str(a, "daylight_hours_words"));
    cdl_report_cell(b, t, r, 0, "Coefficients");
    cdl_report_cell(b, t, r++, 1, "target %.3g %% (relative standard error), seed %.0f, %.0f threads",
                    100.0 * num(a, "coefficients.target_error"), num(a, "coefficients.seed"),
                    num(a, "coefficients.threads"));
    cdl_report_cell(b, t, r, 0, "Candela");
    cdl_report_cell(b, t, r++, 1, "%s", str(s, "candela_version"));
    cdl_report_cell(b, t, r, 0, "Time");
    cdl_report_cell(b, t, r++, 1, "skies %.3g s, coefficients %.3g s, direct sun %.3g s, hours %.3g s, metrics %.3g s",
                    num(a, "seconds.skies"), num(a, "seconds.coefficients"), num(a, "seconds.direct_sun"),
                    num(a, "seconds.hours"), num(a, "seconds.metrics"));
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
}

static size_t child_count(const cJSON *o)
{
    size_t n = 0;
    for (const cJSON *c = o ? o->child : NULL; c; c = c->next) ++n;
    return n;
}

static void summary(cdl_report_builder *b, const cJSON *s)
{
    const cJSON *grids = at(s, "grids");
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Daylight");
    cdl_report_block *t = cdl_report_table(b, 9, child_count(grids) + 1, 1);
    static const char *const head[9] = {"Grid", "Points", "sDA300/50%", "ASE1000,250h", "DA300 mean",
                                        "UDI 100-3000", "fell short / exceeded", "EN 17037", "stated error"};
    for (size_t c = 0; c < 9; ++c) cdl_report_cell(b, t, 0, c, "%s", head[c]);
    size_t r = 1;
    for (const cJSON *g = grids ? grids->child : NULL; g; g = g->next, ++r) {
        cdl_report_cell(b, t, r, 0, "%s", g->string);
        cdl_report_cell(b, t, r, 1, "%.0f", num(g, "count"));
        cdl_report_cell(b, t, r, 2, "%.1f %%", num(g, "sDA300_percent"));
        cdl_report_cell(b, t, r, 3, "%.1f %%", num(g, "ASE1000_percent"));
        cdl_report_cell(b, t, r, 4, "%.1f %%", num(g, "DA300_mean_percent"));
        cdl_report_cell(b, t, r, 5, "%.1f %%", num(g, "UDI_percent"));
        cdl_report_cell(b, t, r, 6, "%.1f %% / %.1f %%", num(g, "UDI_fell_short_percent"),
                        num(g, "UDI_exceeded_percent"));
        cdl_report_cell(b, t, r, 7, "%s", str(g, "EN17037.level"));
        cdl_report_cell(b, t, r, 8, "%.2g %% (worst %.2g %%)", 100.0 * num(g, "coefficients.stderr_mean_rel"),
                        100.0 * num(g, "coefficients.stderr_max_rel"));
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Shares of the grid are weighted by the area each point stands for. sDA300/50%% is the share "
                    "whose daylight autonomy DA300 reaches 50 %% of the occupied hours (IES LM-83-12); "
                    "ASE1000,250h the share with direct sunlight of 1000 lx or more for more than 250 occupied "
                    "hours; UDI the mean share of occupied hours between 100 and 3000 lx. The stated error is "
                    "each point's relative one-sigma error of the daylight coefficients (their sampling and the "
                    "sky patches' discretisation), its mean over the grid and its worst.");
    for (const cJSON *g = grids ? grids->child : NULL; g; g = g->next) {
        cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s: EN 17037 daylight provision", g->string);
        cdl_report_block *e = cdl_report_table(b, 5, 4, 1);
        static const char *const cols[5] = {"Level", "E_T / E_TM", "hours at E_T over 50 %", "hours at E_TM over 95 %",
                                            "met"};
        for (size_t c = 0; c < 5; ++c) cdl_report_cell(b, e, 0, c, "%s", cols[c]);
        static const char *const levels[3] = {"minimum", "medium", "high"};
        for (size_t l = 0; l < 3; ++l) {
            char key[64];
            snprintf(key, sizeof key, "EN17037.%s", levels[l]);
            const cJSON *lv = at(g, key);
            const cJSON *met = at(lv, "met");
            cdl_report_cell(b, e, l + 1, 0, "%s", levels[l]);
            cdl_report_cell(b, e, l + 1, 1, "%.0f / %.0f lx", num(lv, "target_lx"), num(lv, "minimum_target_lx"));
            cdl_report_cell(b, e, l + 1, 2, "%.1f %%", num(lv, "target_hours_percent"));
            cdl_report_cell(b, e, l + 1, 3, "%.1f %%", num(lv, "minimum_hours_percent"));
            cdl_report_cell(b, e, l + 1, 4, "%s", cJSON_IsTrue(met) ? "pass" : "FAIL");
        }
    }
}

static void maps(cdl_report_builder *b, const char *out_dir, const cJSON *s)
{
    const cJSON *grids = at(s, "grids");
    static const char *const suffix[4] = {"_DA300", "_UDI", "_ASE", "_EN17037"};
    static const char *const what[4] = {"daylight autonomy DA300", "useful daylight illuminance 100-3000 lx",
                                        "hours of direct sun at 1000 lx or more", "EN 17037: daylight hours at 300 lx"};
    for (const cJSON *g = grids ? grids->child : NULL; g; g = g->next)
        for (int k = 0; k < 4; ++k) {
            const cdl_report_image *im = load_picture(b, out_dir, g->string, suffix[k], what[k]);
            if (!im) continue;
            if (k == 0) {
                cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
                cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s: maps", g->string);
            }
            add_picture(b, im);
        }
}

static void method(cdl_report_builder *b, const cJSON *s)
{
    const cJSON *a = at(s, "annual");
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Method and accuracy");
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Every hour of the weather file was computed at every point: %s. The coefficients give each "
                    "point's illuminance per unit luminance of each sky patch (direct light exact where the exact "
                    "route can say what the point sees, through glass weighed by the panes' transmittance, "
                    "interreflection by paths with next-event estimation of the sky each reflection sees); the "
                    "hours are one matrix product. Stated error: %s.",
                    str(a, "sky.words"), str(a, "coefficients.stderr_words"));
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Left out: shading devices and their operation (LM-83's blinds), the sun disk's half-degree "
                    "penumbra in the direct sun, and any light of the %.0f hours whose sun is below the horizon at "
                    "the hour's middle (%.4g Wh/m2 of irradiation in the file); %.0f hours had their Perez inputs "
                    "clamped to the model's range.",
                    num(a, "sky.left_out_hours"), num(a, "sky.left_out_irradiation_wh_m2"),
                    num(a, "sky.clamped_hours"));
}

cdl_status cdl_report_daylight_build(const char *out_dir, const cJSON *summary_json, const char *title,
                                     cdl_report_document **out, cdl_error *err)
{
    *out = NULL;
    cdl_report_document *d = calloc(1, sizeof *d);
    if (!d) return cdl_error_out_of_memory(err);
    cdl_report_builder b = {d, 0};
    if (title) {
        d->title = cdl_string_copy(title);
    } else {
        const char *scene = str(summary_json, "scene");
        size_t n = strlen(scene) + 32;
        d->title = malloc(n);
        if (d->title) snprintf(d->title, n, "Daylight report: %s", scene);
    }
    if (!d->title) b.failed = 1;
    if (!b.failed) {
        cover(&b, out_dir, summary_json);
        summary(&b, summary_json);
        maps(&b, out_dir, summary_json);
        method(&b, summary_json);
    }
    if (b.failed) {
        cdl_report_document_release(d);
        return cdl_error_out_of_memory(err);
    }
    *out = d;
    return CDL_OK;
}
