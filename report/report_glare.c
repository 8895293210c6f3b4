/* report_glare.c - the report's glare (report_glare.h). */
#include "report/report_glare.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file_bytes.h"
#include "base/strings.h"
#include "glare/ugr_table.h"
#include "glare/ugr_table_conditions.h"
#include "graphics/text.h"
#include "radiometry/constants.h"
#include "report/report_numbers.h"

#define GLARE_CSV_MAX_BYTES ((size_t)64 << 20)
#define PLAN_WIDTH 480.0
#define PLAN_LABELS_MAX 40 /* more observers than this: dots without labels */

/* ---- reading ---------------------------------------------------------------------- */

static cdl_status stale(const char *path, cdl_error *err, const char *what, size_t i, const char *name)
{
    return cdl_error_set(err, CDL_ERR_INPUT,
                         "%s: expected %s for observer %zu (%s) as the scene and summary.json have it: the folder "
                         "is not one solve's output (solve again)",
                         path, what, i, name);
}

/* The same double, as two writers print it: cJSON's shortest form may be
 * a unit in the last place off (it checks its round trip to within
 * DBL_EPSILON), the CSV's is exact. */
static int same_number(double a, double b)
{
    return fabs(a - b) <= 4.0 * DBL_EPSILON * fmax(fabs(a), fabs(b));
}

/* glare.csv against the observers read from summary.json: the same names
 * and numbers (both written from the same doubles). */
static cdl_status check_csv(const cdl_report_input *in, cdl_error *err)
{
    char *path = cdl_path_join(in->out_dir, "glare", ".csv");
    if (!path) return cdl_error_out_of_memory(err);
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "glare results", GLARE_CSV_MAX_BYTES, &text, &size, err);
    static const char header[] = "name,x,y,z,view_x,view_y,view_z,ugr,ugr_stderr,background_cd_m2,"
                                 "background_stderr_cd_m2\n";
    if (st == CDL_OK && strncmp(text, header, sizeof header - 1) != 0)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected the header %.*s, found another", path,
                           (int)sizeof header - 2, header);
    const char *line = text ? text + sizeof header - 1 : NULL;
    for (size_t i = 0; st == CDL_OK && i < in->observer_count; ++i) {
        const cdl_report_observer *o = &in->observers[i];
        size_t name_len = strlen(o->spec->name);
        if (strncmp(line, o->spec->name, name_len) != 0 || line[name_len] != ',') {
            st = stale(path, err, "a row", i, o->spec->name);
            break;
        }
        const char *p = line + name_len + 1;
        double v[10];
        int empty[10];
        for (int k = 0; k < 10; ++k) {
            char *end;
            empty[k] = *p == ',' || *p == '\n';
            v[k] = empty[k] ? 0.0 : strtod(p, &end);
            p = empty[k] ? p : end;
            if (*p == ',' || *p == '\n') ++p;
        }
        const double want[4] = {o->ugr, o->ugr_stderr, o->background_cd_m2, o->background_stderr_cd_m2};
        int same = empty[6] == !o->defined && empty[7] == !o->defined;
        for (int k = 0; k < 4 && same; ++k) same = (k < 2 && !o->defined) || same_number(v[6 + k], want[k]);
        if (!same) st = stale(path, err, "the UGR and background luminance of summary.json", i, o->spec->name);
        line = p;
    }
    free(text);
    free(path);
    return st;
}

cdl_status cdl_report_glare_read(cdl_report_input *in, cdl_error *err)
{
    const cdl_scene *scene = in->scene;
    size_t n = scene->observer_count;
    if (n == 0) return CDL_OK;
    const cJSON *glare = cJSON_GetObjectItemCaseSensitive(in->summary, "glare");
    if (!cJSON_IsArray(glare) || (size_t)cJSON_GetArraySize(glare) != n)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: glare: expected an entry for each of the scene's %zu observers, found %d: the "
                             "folder is not this scene's solve (solve again)",
                             in->summary_path, n, cJSON_IsArray(glare) ? cJSON_GetArraySize(glare) : 0);
    in->observers = calloc(n, sizeof *in->observers);
    if (!in->observers) return cdl_error_out_of_memory(err);
    in->observer_count = n;
    size_t i = 0;
    for (const cJSON *e = glare->child; e; e = e->next, ++i) {
        cdl_report_observer *o = &in->observers[i];
        o->spec = &scene->observers[i];
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(e, "observer");
        const cJSON *ugr = cJSON_GetObjectItemCaseSensitive(e, "ugr");
        const cJSON *ugr_err = cJSON_GetObjectItemCaseSensitive(e, "ugr_stderr");
        const cJSON *lb = cJSON_GetObjectItemCaseSensitive(e, "background_cd_m2");
        const cJSON *lb_err = cJSON_GetObjectItemCaseSensitive(e, "background_stderr_cd_m2");
        const cJSON *sources = cJSON_GetObjectItemCaseSensitive(e, "sources");
        if (!cJSON_IsString(name) || strcmp(name->valuestring, o->spec->name) != 0 ||
            !(cJSON_IsNumber(ugr) || cJSON_IsNull(ugr)) || !cJSON_IsNumber(lb) || !cJSON_IsNumber(lb_err) ||
            !cJSON_IsArray(sources))
            return stale(in->summary_path, err, "glare's entry", i, o->spec->name);
        o->defined = cJSON_IsNumber(ugr);
        o->ugr = o->defined ? ugr->valuedouble : 0.0;
        o->ugr_stderr = cJSON_IsNumber(ugr_err) ? ugr_err->valuedouble : 0.0;
        o->background_cd_m2 = lb->valuedouble;
        o->background_stderr_cd_m2 = lb_err->valuedouble;
        o->sources = (size_t)cJSON_GetArraySize(sources);
    }
    return check_csv(in, err);
}

/* ---- the verdict ------------------------------------------------------------------ */

/* "pass: 1.4 below" / "FAIL: 0.3 above (within the stated error)"; "" without a limit or a rating. */
static void verdict(const cdl_report_observer *o, char *out, size_t size)
{
    out[0] = '\0';
    double limit = o->spec->required_ugr;
    if (!(limit > 0.0) || !o->defined) return;
    char m[32];
    double margin = limit - o->ugr;
    cdl_report_format(m, sizeof m, fabs(margin), o->ugr_stderr);
    snprintf(out, size, "%s: %s %s%s", margin >= 0.0 ? "pass" : "FAIL", m, margin >= 0.0 ? "below" : "above",
             fabs(margin) <= o->ugr_stderr ? " (within the stated error)" : "");
}

/* ---- the plan --------------------------------------------------------------------- */

struct cdl_glare_plan {
    const cdl_report_input *input;
    double x0, y1, scale;           /* world (x0, y1) at the map's top-left, points per metre */
    double map_x, map_y, map_w, map_h, width, height;
    char title[200];
};

static void grow(double box[4], double x, double y)
{
    box[0] = fmin(box[0], x), box[1] = fmin(box[1], y), box[2] = fmax(box[2], x), box[3] = fmax(box[3], y);
}

/* The plan's extent: surfaces, luminaires and observers, from above. */
static void extent(const cdl_scene *s, double box[4])
{
    box[0] = box[1] = INFINITY, box[2] = box[3] = -INFINITY;
    for (size_t i = 0; i < s->observer_count; ++i) grow(box, s->observers[i].eye.x, s->observers[i].eye.y);
    for (size_t k = 0; k < s->luminaire_count; ++k) {
        const cdl_luminaire_spec *l = &s->luminaires[k];
        if (l->kind == CDL_LUMINAIRE_POINT || l->kind == CDL_LUMINAIRE_SPOT || l->kind == CDL_LUMINAIRE_GONIOMETRIC)
            grow(box, l->position.x, l->position.y);
    }
    for (size_t k = 0; k < s->surface_count; ++k) {
        const cdl_surface_spec *f = &s->surfaces[k];
        if (f->kind == CDL_SURFACE_BOX) {
            grow(box, f->box_min.x, f->box_min.y);
            grow(box, f->box_max.x, f->box_max.y);
        } else if (f->kind == CDL_SURFACE_RECT) {
            cdl_vec3 c[4] = {f->origin, cdl_vec3_add(f->origin, f->u), cdl_vec3_add(cdl_vec3_add(f->origin, f->u), f->v),
                             cdl_vec3_add(f->origin, f->v)};
            for (int m = 0; m < 4; ++m) grow(box, c[m].x, c[m].y);
        } else if (f->kind == CDL_SURFACE_POLYGON) {
            for (size_t m = 0; m < f->outer.count; ++m) grow(box, f->outer.points[m].x, f->outer.points[m].y);
        }
    }
    double pad = 0.05 * fmax(fmax(box[2] - box[0], box[3] - box[1]), 1.0);
    box[0] -= pad, box[1] -= pad, box[2] += pad, box[3] += pad;
}

static void to_page(const struct cdl_glare_plan *p, double x, double y, double *px, double *py)
{
    *px = p->map_x + (x - p->x0) * p->scale;
    *py = p->map_y + (p->y1 - y) * p->scale;
}

static void segment(cairo_t *cr, const struct cdl_glare_plan *p, cdl_vec3 a, cdl_vec3 b)
{
    double x, y;
    to_page(p, a.x, a.y, &x, &y);
    cairo_move_to(cr, x, y);
    to_page(p, b.x, b.y, &x, &y);
    cairo_line_to(cr, x, y);
}

static void draw_surfaces(cairo_t *cr, const struct cdl_glare_plan *p, const cdl_scene *s)
{
    cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
    cairo_set_line_width(cr, 0.8);
    for (size_t k = 0; k < s->surface_count; ++k) {
        const cdl_surface_spec *f = &s->surfaces[k];
        if (f->kind == CDL_SURFACE_BOX) {
            cdl_vec3 lo = f->box_min, hi = f->box_max;
            cdl_vec3 c[4] = {lo, {hi.x, lo.y, 0}, hi, {lo.x, hi.y, 0}};
            for (int m = 0; m < 4; ++m) segment(cr, p, c[m], c[(m + 1) % 4]);
        } else if (f->kind == CDL_SURFACE_RECT) {
            cdl_vec3 c[4] = {f->origin, cdl_vec3_add(f->origin, f->u), cdl_vec3_add(cdl_vec3_add(f->origin, f->u), f->v),
                             cdl_vec3_add(f->origin, f->v)};
            for (int m = 0; m < 4; ++m) segment(cr, p, c[m], c[(m + 1) % 4]);
        } else if (f->kind == CDL_SURFACE_POLYGON) {
            for (size_t m = 0; m < f->outer.count; ++m)
                segment(cr, p, f->outer.points[m], f->outer.points[(m + 1) % f->outer.count]);
        }
    }
    cairo_stroke(cr);
}

static void draw_luminaires(cairo_t *cr, const struct cdl_glare_plan *p, const cdl_scene *s)
{
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 0.9);
    for (size_t k = 0; k < s->luminaire_count; ++k) {
        const cdl_luminaire_spec *l = &s->luminaires[k];
        if (l->kind != CDL_LUMINAIRE_POINT && l->kind != CDL_LUMINAIRE_SPOT && l->kind != CDL_LUMINAIRE_GONIOMETRIC)
            continue;
        double x, y;
        to_page(p, l->position.x, l->position.y, &x, &y);
        cairo_move_to(cr, x - 3.5, y);
        cairo_line_to(cr, x + 3.5, y);
        cairo_move_to(cr, x, y - 3.5);
        cairo_line_to(cr, x, y + 3.5);
    }
    cairo_stroke(cr);
}

static void draw_observers(cairo_t *cr, const struct cdl_glare_plan *p, const cdl_report_input *in)
{
    int labels = in->observer_count <= PLAN_LABELS_MAX;
    const cdl_text_style style = {.size = 7.5, .align = CDL_TEXT_CENTRE};
    for (size_t i = 0; i < in->observer_count; ++i) {
        const cdl_report_observer *o = &in->observers[i];
        char v[128];
        verdict(o, v, sizeof v);
        int pass = cdl_report_cell_verdict(v);
        if (pass > 0) cairo_set_source_rgb(cr, 0.0, 0.5, 0.15);
        else if (pass < 0) cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
        else cairo_set_source_rgb(cr, 0.0, 0.2, 0.6);
        double x, y;
        to_page(p, o->spec->eye.x, o->spec->eye.y, &x, &y);
        cairo_arc(cr, x, y, 2.6, 0.0, CDL_TWO_PI);
        cairo_fill(cr);
        /* the line of sight: an arrow of 14 points */
        double dx = o->spec->view.x, dy = -o->spec->view.y;
        cairo_set_line_width(cr, 1.0);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 14.0 * dx, y + 14.0 * dy);
        cairo_line_to(cr, x + 10.0 * dx - 3.0 * dy, y + 10.0 * dy + 3.0 * dx);
        cairo_move_to(cr, x + 14.0 * dx, y + 14.0 * dy);
        cairo_line_to(cr, x + 10.0 * dx + 3.0 * dy, y + 10.0 * dy - 3.0 * dx);
        cairo_stroke(cr);
        if (!labels) continue;
        char label[32];
        if (o->defined) cdl_report_format(label, sizeof label, o->ugr, o->ugr_stderr);
        else snprintf(label, sizeof label, "-");
        /* behind the eye, opposite the arrow */
        cdl_text_draw(cr, x - 13.0 * dx, y - 13.0 * dy - 4.5, label, &style);
    }
}

static void draw_plan(cairo_t *cr, const void *user)
{
    const struct cdl_glare_plan *p = user;
    const cdl_scene *s = p->input->scene;
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cdl_text_draw(cr, p->map_x, 4.0, p->title, &(cdl_text_style){.size = 10.5, .bold = 1, .wrap_width = p->map_w});
    cairo_save(cr);
    cairo_rectangle(cr, p->map_x, p->map_y, p->map_w, p->map_h);
    cairo_clip(cr);
    draw_surfaces(cr, p, s);
    draw_luminaires(cr, p, s);
    draw_observers(cr, p, p->input);
    cairo_restore(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, p->map_x, p->map_y, p->map_w, p->map_h);
    cairo_stroke(cr);
    /* a scale bar: a round number of metres near a fifth of the width */
    double metres = pow(10.0, floor(log10(0.2 * p->map_w / p->scale)));
    double bar = metres * p->scale, y = p->map_y + p->map_h + 12.0;
    cairo_move_to(cr, p->map_x, y);
    cairo_line_to(cr, p->map_x + bar, y);
    cairo_stroke(cr);
    char label[160];
    snprintf(label, sizeof label, "%g m; from above, +x right, +y up; + a luminaire, dot and arrow an observer", metres);
    cdl_text_draw(cr, p->map_x + bar + 6.0, y - 5.0, label, &(cdl_text_style){.size = 8.0});
}

static struct cdl_glare_plan *plan_make(const cdl_report_input *in)
{
    struct cdl_glare_plan *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    double box[4];
    extent(in->scene, box);
    double w = box[2] - box[0], h = box[3] - box[1];
    p->input = in;
    p->map_x = 10.0;
    p->map_y = 34.0;
    p->map_w = PLAN_WIDTH - 20.0;
    p->scale = p->map_w / w;
    p->map_h = fmin(h * p->scale, 1.2 * p->map_w); /* a very deep plan is cut, not squeezed */
    p->x0 = box[0];
    p->y1 = box[1] + 0.5 * h + 0.5 * p->map_h / p->scale;
    p->width = PLAN_WIDTH;
    p->height = p->map_y + p->map_h + 28.0;
    snprintf(p->title, sizeof p->title, "Glare: the observers on the plan, each with its UGR (green: pass, red: "
                                        "FAIL, blue: no limit given)");
    return p;
}

void cdl_report_glare_plan_release(struct cdl_glare_plan *plan)
{
    free(plan);
}

/* ---- the section ------------------------------------------------------------------ */

/* One row: an observer, or an observer grid by its worst observer. */
static void observer_row(cdl_report_builder *b, cdl_report_block *t, size_t row, const cdl_report_observer *o,
                         size_t grid_count)
{
    char ugr[32] = "-", lb[32], v[128];
    if (o->defined) cdl_report_format(ugr, sizeof ugr, o->ugr, o->ugr_stderr);
    cdl_report_format(lb, sizeof lb, o->background_cd_m2, o->background_stderr_cd_m2);
    verdict(o, v, sizeof v);
    if (grid_count > 1) {
        size_t len = strcspn(o->spec->name, "[");
        cdl_report_cell(b, t, row, 0, "%.*s (%zu observers; the worst: %s)", (int)len, o->spec->name, grid_count,
                        o->spec->name);
    } else {
        cdl_report_cell(b, t, row, 0, "%s", o->spec->name);
    }
    cdl_report_cell(b, t, row, 1, "%.3g, %.3g, %.3g", o->spec->eye.x, o->spec->eye.y, o->spec->eye.z);
    cdl_report_cell(b, t, row, 2, "%.3g, %.3g", o->spec->view.x, o->spec->view.y);
    if (o->defined) cdl_report_cell(b, t, row, 3, "%s +- %.2g", ugr, o->ugr_stderr);
    else cdl_report_cell(b, t, row, 3, "%s", ugr);
    cdl_report_cell(b, t, row, 4, "%s", lb);
    cdl_report_cell(b, t, row, 5, "%zu", o->sources);
    if (o->spec->required_ugr > 0.0) cdl_report_cell(b, t, row, 6, "%g", o->spec->required_ugr);
    else cdl_report_cell(b, t, row, 6, "-");
    cdl_report_cell(b, t, row, 7, "%s", v[0] ? v : o->defined ? "no limit given" : "no rating");
}

/* The rows: single observers each, an observer grid by its worst. */
static size_t observer_rows(const cdl_report_input *in, size_t *first, size_t *count)
{
    size_t rows = 0;
    for (size_t i = 0; i < in->observer_count;) {
        const cdl_observer_spec *s = in->observers[i].spec;
        size_t n = s->from_grid ? s->copy_count : 1, worst = i;
        for (size_t k = i; k < i + n && k < in->observer_count; ++k) {
            const cdl_report_observer *o = &in->observers[k];
            if (o->defined && (!in->observers[worst].defined || o->ugr > in->observers[worst].ugr)) worst = k;
        }
        first[rows] = worst;
        count[rows++] = n;
        i += n;
    }
    return rows;
}

cdl_status cdl_report_glare_section(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    if (in->observer_count == 0) return CDL_OK;
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Glare (UGR)");
    size_t *first = calloc(in->observer_count, sizeof *first), *count = calloc(in->observer_count, sizeof *count);
    if (!first || !count) {
        free(first);
        free(count);
        return cdl_error_out_of_memory(err);
    }
    size_t rows = observer_rows(in, first, count);
    cdl_report_block *t = cdl_report_table(b, 8, rows + 1, 1);
    static const char *const headings[8] = {"observer", "eye (m)", "view", "UGR", "Lb (cd/m2)", "in view", "UGR_L",
                                            "requirement"};
    for (size_t c = 0; c < 8; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    for (size_t r = 0; r < rows; ++r) observer_row(b, t, r + 1, &in->observers[first[r]], count[r]);
    free(first);
    free(count);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "UGR = 8 log10((0.25 / Lb) sum L^2 omega / p^2) (CIE 117:1995) at each observer's eye, looking "
                    "horizontally along its line of sight: L the luminance of a luminaire's luminous parts towards "
                    "the eye (its intensity over their projected area), omega their solid angle less what surfaces "
                    "hide, p Guth's position index (CIE 117 Table 4.1); luminaires behind the eye or outside the "
                    "table add nothing, and point sources, which have no luminous area, cannot be rated. Lb = E / pi, "
                    "E the illuminance at the eye on the plane facing the line of sight from everything but the "
                    "luminaires' direct light (interreflected light, skies). UGR is printed to the decimal place of "
                    "its stated one-sigma error (from those of Lb and of sampled solid angles); a verdict within "
                    "that error could go either way. glare.csv lists every observer, summary.json's \"glare\" every "
                    "luminaire's term.");
    struct cdl_glare_plan *p = plan_make(in);
    if (!p) return cdl_error_out_of_memory(err);
    b->doc->glare_plan = p;
    cdl_figure f = {p->width, p->height, p->title, draw_plan, p};
    cdl_report_figure(b, f, 1.0);
    return CDL_OK;
}

/* ---- the UGR tables ----------------------------------------------------------------- */

static void ugr_table_block(cdl_report_builder *b, const cdl_ugr_table *u)
{
    cdl_report_block *t = cdl_report_table(b, 11, CDL_UGR_TABLE_ROOMS + 1, 1);
    cdl_report_cell(b, t, 0, 0, "room X x Y");
    for (int view = 0; view < 2; ++view)
        for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
            const double *r = cdl_ugr_table_reflectances[s];
            cdl_report_cell(b, t, 0, (size_t)(1 + 5 * view + s), "%s %.0f/%.0f/%.0f", view ? "end" : "cross",
                            100.0 * r[0], 100.0 * r[1], 100.0 * r[2]);
        }
    for (int i = 0; i < CDL_UGR_TABLE_ROOMS; ++i) {
        const cdl_ugr_table_room *r = &u->rooms[i];
        cdl_report_cell(b, t, (size_t)i + 1, 0, "%gH x %gH", r->x_h, r->y_h);
        for (int view = 0; view < 2; ++view)
            for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
                if (r->defined[view]) cdl_report_cell(b, t, (size_t)i + 1, (size_t)(1 + 5 * view + s), "%.1f", r->ugr[view][s]);
                else cdl_report_cell(b, t, (size_t)i + 1, (size_t)(1 + 5 * view + s), "-");
            }
    }
}

cdl_status cdl_report_glare_tables(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    if (in->observer_count == 0) return CDL_OK;
    int first = 1;
    for (size_t k = 0; k < in->type_count; ++k) {
        const cdl_photometry *ph = in->types[k].photometry;
        if (!ph || !cdl_luminous_opening_is_spread(cdl_photometry_opening(ph))) continue;
        cdl_ugr_table u = CDL_UGR_TABLE_INIT;
        cdl_status st = cdl_ugr_table_compute(ph, NULL, &u, err);
        if (st == CDL_ERR_INPUT) continue; /* not rated (radiant data, no light): the schedule says what it is */
        if (st != CDL_OK) return st;
        if (first) {
            cdl_report_text(b, CDL_BLOCK_HEADING, 3, "UGR tables");
            cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                            "Each luminaire's UGR table as catalogues print it (CIE 190:2010, `candela info --ugr`): "
                            "standard rooms X by Y in multiples of H = 2 m (the luminaires above the eye), the "
                            "luminaires at spacing 0.25 H over the ceiling, viewed crosswise (cross: their C0 plane "
                            "along the line of sight) and endwise (end), reflectances ceiling/walls/floor in per "
                            "cent; for the file's flux (the maintenance factor not applied).");
            first = 0;
        }
        const char *slash = strrchr(in->types[k].first->file, '/');
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "%s, %.5g lm:", slash ? slash + 1 : in->types[k].first->file,
                        u.flux_lm);
        ugr_table_block(b, &u);
    }
    return CDL_OK;
}
