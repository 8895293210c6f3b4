/* NAME.png decoded back with libpng: size, map colours against the OCIO
 * transform of hand-computed log and linear positions, legend bar, ticks
 * and labels, the title (name and statistics) and axes in metres. */
#include <math.h>
#include <png.h>
#include <string.h>

#include "check.h"
#include "grid_result_fixture.h"
#include "graphics/raster_canvas.h"
#include "solver/output/display_transform.h"

#define CONFIG CANDELA_SOURCE_DIR "/data/ocio/config.ocio"

typedef struct decoded {
    int width, height;
    uint8_t *rgb;
} decoded;

static int decode(const char *path, decoded *out)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    out->rgb = NULL;
    if (!png_image_begin_read_from_file(&image, path)) return 0;
    image.format = PNG_FORMAT_RGB;
    out->width = (int)image.width;
    out->height = (int)image.height;
    out->rgb = malloc(PNG_IMAGE_SIZE(image));
    if (!out->rgb || !png_image_finish_read(&image, NULL, out->rgb, 0, NULL)) {
        png_image_free(&image);
        free(out->rgb);
        out->rgb = NULL;
        return 0;
    }
    return 1;
}

static const uint8_t *pixel(const decoded *d, int x, int y)
{
    return d->rgb + 3 * ((size_t)y * (size_t)d->width + (size_t)x);
}

/* The colour the project's false-colour view gives position t, in 8 bits,
 * computed here through OCIO independently of the writer. */
static void expected_colour(const cdl_display_transform *view, double t, int out[3])
{
    float rgb[3] = {(float)t, (float)t, (float)t};
    cdl_error err;
    if (cdl_display_transform_apply(view, rgb, 1, &err) != CDL_OK) rgb[0] = rgb[1] = rgb[2] = -1.0f;
    for (int c = 0; c < 3; ++c) out[c] = (int)lround(fmin(fmax(rgb[c], 0.0f), 1.0f) * 255.0);
}

/* 8-bit colours agree within one code value (float rounding in OCIO). */
static int same_colour(const uint8_t *got, const int want[3])
{
    for (int c = 0; c < 3; ++c)
        if (abs((int)got[c] - want[c]) > 1) return 0;
    return 1;
}

/* Centre pixel of raster cell (c, r). */
static const uint8_t *cell_centre(const decoded *d, const cdl_png_layout *L, int c, int r)
{
    return pixel(d, L->map_x + c * L->cell + L->cell / 2, L->map_y + r * L->cell + L->cell / 2);
}

/* Every cell of the map shows the colour of its point's position t(E). */
static void check_map(const decoded *d, const cdl_png_layout *L, const fixture *f, const cdl_display_transform *view,
                      double lo, double hi)
{
    for (int r = 0; r < f->grid.raster_height; ++r)
        for (int c = 0; c < f->grid.raster_width; ++c) {
            int32_t idx = f->grid.raster_index[(size_t)r * (size_t)f->grid.raster_width + (size_t)c];
            const uint8_t *got = cell_centre(d, L, c, r);
            int want[3] = {255, 255, 255}; /* outside the grid: white */
            if (idx >= 0) {
                /* log position between the hand-chosen ends, clamped */
                double E = f->E[idx];
                double t = E <= lo ? 0.0 : E >= hi ? 1.0 : log(E / lo) / log(hi / lo);
                expected_colour(view, t, want);
            }
            CHECK_MSG(same_colour(got, want), "cell (%d, %d): got %d %d %d, expected %d %d %d", c, r, got[0], got[1],
                      got[2], want[0], want[1], want[2]);
        }
}

/* The maps' labels: 12 px DejaVu Sans (png_output.c's FONT_PX), a line 14 px high. */
static const cdl_text_style label_style = {.size = 12.0};

static int text_width(const char *label)
{
    double w = 0.0;
    cdl_text_measure_alone(label, &label_style, &w, NULL);
    return (int)ceil(w);
}

/* Is `label` drawn (black on white) with its top-left corner at (x, y)?
 * The same text drawn alone at the origin of a white image must match
 * pixel for pixel (cairo renders glyphs alike at any whole-pixel offset),
 * and must have ink (a label that draws nothing proves nothing). */
static int label_drawn(const decoded *d, int x, int y, const char *label)
{
    int w = text_width(label), h = 14;
    if (x < 0 || y < 0 || x + w > d->width || y + h > d->height) return 0;
    uint8_t *ref = malloc((size_t)w * (size_t)h * 3);
    if (!ref) return 0;
    memset(ref, 255, (size_t)w * (size_t)h * 3);
    const uint8_t black[3] = {0, 0, 0};
    cdl_raster_canvas *canvas = NULL;
    cdl_error err;
    if (cdl_raster_canvas_begin(ref, w, h, &canvas, &err) != CDL_OK) {
        free(ref);
        return 0;
    }
    cdl_raster_canvas_text(canvas, 0, 0, label, &label_style, black);
    cdl_raster_canvas_end(canvas);
    size_t ink = 0;
    for (size_t k = 0; k < (size_t)w * (size_t)h * 3; ++k) ink += ref[k] < 128;
    if (ink == 0) {
        free(ref);
        return 0;
    }
    int same = 1;
    for (int j = 0; j < h && same; ++j)
        same = memcmp(ref + (size_t)j * (size_t)w * 3, pixel(d, x, y + j), (size_t)w * 3) == 0;
    free(ref);
    return same;
}

static int bar_row(const cdl_png_layout *L, double t)
{
    return L->bar_y + (int)lround((1.0 - t) * (L->bar_height - 1));
}

/* Write f's PNG on the logarithmic scale, check that its scale is lo .. hi
 * lx (worked by hand by the caller), that it decodes to the layout's size
 * and that every cell has the colour of its point. The decoded image stays
 * in *d (NULL pixels if not). */
static void write_and_check(const fixture *f, const char *path, const cdl_display_transform *view, double lo,
                            double hi, cdl_png_layout *L, decoded *d)
{
    cdl_error err;
    d->rgb = NULL;
    cdl_grid_result r = f->result;
    r.map_log_scale = 1;
    CHECK_OK(cdl_grid_result_write_png(&r, path, CONFIG, &err), &err);
    cdl_grid_result_png_layout(&r, L);
    CHECK_MSG(L->scale.lo.lx == lo && L->scale.hi.lx == hi, "scale %g .. %g lx, expected %g .. %g", L->scale.lo.lx,
              L->scale.hi.lx, lo, hi);
    CHECK_MSG(decode(path, d), "%s decodes", path);
    if (!d->rgb) return;
    CHECK(d->width == L->width && d->height == L->height);
    check_map(d, L, f, view, lo, hi);
}

/* The default linear scale: an 8 x 8 grid of 480 .. 520 lx with one point
 * at 0 lx (a dark corner) keeps its range, 480 .. 520 lx in steps of 10
 * (about six intervals of a 1-2-5 step), instead of being flattened to
 * 0 .. 520; the dark point shows the bottom colour and the bottom label
 * says "<=". Title and axes are drawn. */
static void test_linear(const char *path, const cdl_display_transform *view)
{
    fixture f;
    decoded d;
    cdl_png_layout L;
    cdl_error err;
    CHECK(fixture_rect(&f, 8, 8, 4.0, 4.0, 0.8));
    for (size_t k = 0; k < f.grid.count; ++k) f.E[k] = 480.0 + 40.0 * (double)k / 63.0;
    f.E[9] = 0.0;
    for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 8; ++c) f.grid.raster_index[r * 8 + c] = (7 - r) * 8 + c;
    f.result.name = "Hall_B";
    CHECK_OK(cdl_grid_result_write_png(&f.result, path, CONFIG, &err), &err);
    cdl_grid_result_png_layout(&f.result, &L);
    CHECK(L.scale.kind == CDL_LUX_SCALE_LINEAR);
    CHECK_MSG(L.scale.lo.lx == 480.0 && L.scale.hi.lx == 520.0 && L.scale.tick_lx == 10.0 && L.scale.clipped,
              "scale %g .. %g step %g", L.scale.lo.lx, L.scale.hi.lx, L.scale.tick_lx);
    CHECK(decode(path, &d));
    if (!d.rgb) {
        fixture_free(&f);
        return;
    }
    CHECK(d.width == L.width && d.height == L.height);
    for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 8; ++c) {
            double E = f.E[(7 - r) * 8 + c];
            double t = E <= 480.0 ? 0.0 : E >= 520.0 ? 1.0 : (E - 480.0) / 40.0;
            int want[3];
            expected_colour(view, t, want);
            const uint8_t *got = cell_centre(&d, &L, c, r);
            CHECK_MSG(same_colour(got, want), "linear cell (%d, %d): got %d %d %d, want %d %d %d", c, r, got[0],
                      got[1], got[2], want[0], want[1], want[2]);
        }
    CHECK(label_drawn(&d, L.label_x, bar_row(&L, 0.0) - 7, "<=480 lx"));
    CHECK(label_drawn(&d, L.label_x, L.bar_y - 7, "520 lx"));
    CHECK(label_drawn(&d, L.label_x, bar_row(&L, 0.5) - 7, "500 lx"));
    /* Title: the name, then Em (the mean, equal weights), Emin, Emax and
     * U0 = Emin / Em, worked out here. */
    double sum = 0.0, hi = 0.0;
    for (size_t k = 0; k < f.grid.count; ++k) {
        sum += f.E[k];
        hi = fmax(hi, f.E[k]);
    }
    char stats[160];
    snprintf(stats, sizeof stats, "Em %.4g lx  Emin %.4g lx  Emax %.4g lx  U0 %.3f", sum / 64.0, 0.0, hi, 0.0);
    CHECK(label_drawn(&d, 16, L.title_y, "Hall_B"));
    CHECK_MSG(label_drawn(&d, 16, L.stats_y, stats), "stats line %s", stats);
    /* Axes: the horizontal one named "+x (m)" under the map's right end,
     * ticks from 0 to 4 m; the vertical one "+y (m)" above the map. */
    int map_w = 8 * L.cell, map_h = 8 * L.cell;
    int name_w = text_width("+x (m)");
    CHECK(label_drawn(&d, L.map_x + map_w - name_w, L.map_y + map_h + 6 + 4 + 14 + 8, "+x (m)"));
    CHECK(label_drawn(&d, 16, L.map_y - 7 - 8 - 14, "+y (m)"));
    int zero_w = text_width("0"), four_w = text_width("4");
    CHECK(label_drawn(&d, L.map_x - zero_w / 2, L.map_y + map_h + 6 + 4, "0"));
    CHECK(label_drawn(&d, L.map_x + map_w - four_w / 2, L.map_y + map_h + 6 + 4, "4"));
    free(d.rgb);
    fixture_free(&f);
}

int main(void)
{
    char dir[512], path[600], missing[600];
    CHECK(fixture_folder("test_png_output", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/workplane.png", dir);
    cdl_error err;
    cdl_display_transform *view = NULL;
    CHECK_OK(cdl_display_transform_open(CONFIG, "linear", "sRGB", "False colour", &view, &err), &err);
    if (!view) return check_finish();
    fixture f;
    decoded d;
    cdl_png_layout L;

    /* 3 x 3 grid from 10 to 1000 lx: the scale is exactly 10 .. 1000 lx
     * (both ends are 1-2-5 values), so 100 lx sits at t = 0.5. */
    const double values[9] = {10, 20, 50, 100, 200, 500, 1000, 100, 10};
    CHECK(fixture_rect(&f, 3, 3, 3.0, 3.0, 0.8));
    for (int k = 0; k < 9; ++k) f.E[k] = values[k];
    f.grid.raster_index[4] = -1; /* the centre pixel lies outside the grid */
    write_and_check(&f, path, view, 10.0, 1000.0, &L, &d);
    CHECK(fixture_count_entries(dir) == 1);
    if (d.rgb) {
        /* small grids are enlarged: the map's long side reaches 400 px */
        CHECK(L.cell * 3 >= 400 && L.cell * 3 < 400 + 3);
        /* 100 lx in the false-colour ramp is pure green */
        int green[3];
        expected_colour(view, 0.5, green);
        CHECK(green[0] <= 1 && green[1] >= 254 && green[2] <= 1);
        /* point 3 (i = 0, j = 1: 100 lx) is raster row 1, column 0 */
        CHECK(same_colour(cell_centre(&d, &L, 0, 1), green));

        /* Legend bar: red at the top (1000 lx), the bottom colour at 10 lx. */
        int top[3], bottom[3];
        expected_colour(view, 1.0, top);
        expected_colour(view, 0.0, bottom);
        int mid_x = L.bar_x + L.bar_width / 2;
        CHECK(same_colour(pixel(&d, mid_x, L.bar_y), top));
        CHECK(same_colour(pixel(&d, mid_x, L.bar_y + L.bar_height - 1), bottom));
        CHECK(top[0] >= 254 && top[1] <= 1 && top[2] <= 1);
        /* the frame around the bar is black */
        const uint8_t *frame = pixel(&d, L.bar_x - 1, L.bar_y + 10);
        CHECK(frame[0] == 0 && frame[1] == 0 && frame[2] == 0);

        /* Ticks and labels: ends and decades at least; "100 lx" at t = 0.5.
         * A label is centred on its tick: its top is half its line (14 px) above. */
        const struct {
            double t;
            const char *label;
        } ticks[3] = {{1.0, "1000 lx"}, {0.5, "100 lx"}, {0.0, "10 lx"}};
        for (int i = 0; i < 3; ++i) {
            int y = bar_row(&L, ticks[i].t);
            const uint8_t *tick = pixel(&d, L.bar_x + L.bar_width + 3, y);
            CHECK_MSG(tick[0] == 0 && tick[1] == 0 && tick[2] == 0, "tick of %s", ticks[i].label);
            CHECK_MSG(label_drawn(&d, L.label_x, y - 7, ticks[i].label), "label %s",
                      ticks[i].label);
        }
        /* The legend region holds plenty of non-background pixels. */
        int inked = 0;
        for (int y = 0; y < d.height; ++y)
            for (int x = L.label_x; x < d.width; ++x) inked += pixel(&d, x, y)[0] != 255;
        CHECK_MSG(inked > 200, "%d inked legend pixels", inked);
        free(d.rgb);
    }

    /* Refusals leave the existing PNG untouched and no temporary file. */
    size_t before_len = 0;
    char *before = fixture_read_file(path, &before_len);
    f.E[8] = NAN;
    CHECK(cdl_grid_result_write_png(&f.result, path, CONFIG, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "workplane.png") && strstr(err.message, "E_lx of point 8"), "%s", err.message);
    f.E[8] = 10.0;
    CHECK(cdl_grid_result_write_png(&f.result, path, "/nonexistent/config.ocio", &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "workplane.png") && strstr(err.message, "/nonexistent/config.ocio"), "%s",
              err.message);
    CHECK(fixture_file_is(path, before, before_len));
    free(before);
    CHECK(fixture_count_entries(dir) == 1);
    snprintf(missing, sizeof missing, "%s/missing/workplane.png", dir);
    CHECK(cdl_grid_result_write_png(&f.result, missing, CONFIG, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "missing/workplane.png"), "%s", err.message);
    f.grid.raster_width = f.grid.raster_height = 0;
    CHECK(cdl_grid_result_write_png(&f.result, path, CONFIG, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "no raster"), "%s", err.message);
    fixture_free(&f);

    /* Constant 500 lx (a round value): the scale opens to 200 .. 1000 lx and
     * every cell shows t = log(500/200) / log(1000/200) = 0.5693. */
    CHECK(fixture_rect(&f, 5, 2, 5.0, 2.0, 0.0));
    for (size_t k = 0; k < f.grid.count; ++k) f.E[k] = 500.0;
    write_and_check(&f, path, view, 200.0, 1000.0, &L, &d);
    if (d.rgb) {
        /* a flat map still gets a legend tall enough for its labels */
        CHECK(L.bar_height >= 200 && d.height >= L.bar_height);
        CHECK(label_drawn(&d, L.label_x, bar_row(&L, 1.0) - 7, "1000 lx"));
        CHECK(label_drawn(&d, L.label_x, bar_row(&L, 0.0) - 7, "200 lx"));
        free(d.rgb);
    }

    /* All dark: 1 .. 10 lx, every cell the bottom colour; decimals and
     * thousands in labels ("0.5 lx", "20k lx") come from the lux scale test. */
    for (size_t k = 0; k < f.grid.count; ++k) f.E[k] = 0.0;
    write_and_check(&f, path, view, 1.0, 10.0, &L, &d);
    free(d.rgb);
    fixture_free(&f);

    /* A long thin grid (400 x 1 points, 1 .. 400 lx) is drawn at one pixel a point. */
    CHECK(fixture_rect(&f, 400, 1, 40.0, 0.1, 0.0));
    for (size_t k = 0; k < f.grid.count; ++k) f.E[k] = 1.0 + (double)k;
    write_and_check(&f, path, view, 1.0, 500.0, &L, &d);
    CHECK(L.cell == 1);
    free(d.rgb);
    fixture_free(&f);

    test_linear(path, view);
    cdl_display_transform_release(view);
    unlink(path);
    return check_finish();
}
