/* surface_view.c - the room in 3D (surface_view.h). */
#include "report/surface_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graphics/text.h"
#include "radiometry/constants.h"
#include "solver/geometry/key_table.h"
#include "graphics/palette.h"
#include "solver/output/surface_output.h"
#include "solver/output/solution_write.h"
#include "base/error_report.h"

/* Layout, points: panels of at most this size each, side by side. */
#define PANEL_MAX_W 250.0
#define PANEL_MAX_H 260.0
#define MARGIN 14.0
#define TITLE_H 22.0
#define CAPTION_H 16.0
#define PANEL_GAP 22.0
#define LEGEND_GAP 14.0
#define LEGEND_H 10.0
#define LEGEND_LABELS_H 16.0
/* How far down the view looks, degrees below the horizon: the usual
 * elevation of a designer's room view, the floor and walls both large. */
#define ELEVATION_DEG 35.0
#define LUMINAIRE_RADIUS 2.6

static cdl_vec3 vertex(const cdl_view_mesh *m, uint32_t v)
{
    return cdl_vec3_make(m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2]);
}

/* A view looking along the horizontal direction (cos a, sin a, 0) and
 * down (or up, from below) at the elevation: the screen's right is
 * horizontal, its up the world's z as far as the view shows it. */
static void set_direction(cdl_view_panel *p, double azimuth_deg, int from_below)
{
    double a = azimuth_deg * CDL_DEG_TO_RAD, e = ELEVATION_DEG * CDL_DEG_TO_RAD;
    p->towards = cdl_vec3_make(cos(e) * cos(a), cos(e) * sin(a), from_below ? sin(e) : -sin(e));
    p->right = cdl_vec3_normalize(cdl_vec3_cross(p->towards, cdl_vec3_make(0, 0, 1)));
    p->up = cdl_vec3_cross(p->right, p->towards);
}

void cdl_surface_view_project(const cdl_surface_view *v, int panel, cdl_vec3 q, double *x, double *y)
{
    const cdl_view_panel *p = &v->panel[panel];
    *x = p->x + (cdl_vec3_dot(q, p->right) - p->lo_right) * v->metres_to_points;
    *y = p->y + (p->hi_up - cdl_vec3_dot(q, p->up)) * v->metres_to_points;
}

static cdl_status make_colours(cdl_surface_view *v, cdl_error *err)
{
    size_t mapped = 0;
    for (size_t m = 0; m < v->mesh_count; ++m)
        if (v->meshes[m].E_lx) mapped += v->meshes[m].vertex_count;
    double *E = malloc((mapped + 1) * sizeof *E), *t = malloc((mapped + 256) * sizeof *t);
    double *area = malloc((mapped + 1) * sizeof *area);
    uint8_t *rgb = malloc((mapped + 256) * 3);
    v->rgb = calloc(v->mesh_count + 1, sizeof *v->rgb);
    cdl_status st = E && t && area && rgb && v->rgb ? CDL_OK : cdl_error_out_of_memory(err);
    size_t k = 0;
    for (size_t m = 0; st == CDL_OK && m < v->mesh_count; ++m) {
        const cdl_view_mesh *mesh = &v->meshes[m];
        if (!mesh->E_lx) continue;
        cdl_mesh_vertex_areas(mesh->xyz, mesh->vertex_count, mesh->triangles, mesh->triangle_count, area + k);
        for (size_t i = 0; i < mesh->vertex_count; ++i) E[k++] = mesh->E_lx[i];
    }
    /* The colours of scene.glb: the top at 99 % of the area (lux_scale.h). */
    v->scale = cdl_lux_scale_linear_for_areas(E, area, st == CDL_OK ? mapped : 0);
    for (size_t i = 0; i < mapped; ++i) t[i] = cdl_lux_scale_position(&v->scale, cdl_lux(E[i]));
    for (int i = 0; i < 256; ++i) t[mapped + (size_t)i] = i / 255.0;
    /* the report's perceptually uniform scale (palette.h) */
    for (size_t i = 0; st == CDL_OK && i < mapped + 256; ++i) cdl_palette_rgb8(t[i], rgb + 3 * i);
    k = 0;
    for (size_t m = 0; st == CDL_OK && m < v->mesh_count; ++m) {
        if (!v->meshes[m].E_lx) continue;
        size_t n = v->meshes[m].vertex_count;
        v->rgb[m] = malloc(3 * n + 1);
        if (!v->rgb[m]) {
            st = cdl_error_out_of_memory(err);
            break;
        }
        memcpy(v->rgb[m], rgb + 3 * k, 3 * n);
        k += n;
    }
    if (st == CDL_OK) memcpy(v->legend_rgb, rgb + 3 * mapped, sizeof v->legend_rgb);
    free(E);
    free(t);
    free(area);
    free(rgb);
    return st;
}

/* Each mesh's edges that only one triangle has (a vertex pair seen once). */
static cdl_status find_outlines(cdl_surface_view *v, cdl_error *err)
{
    v->outline = calloc(v->mesh_count + 1, sizeof *v->outline);
    v->outline_count = calloc(v->mesh_count + 1, sizeof *v->outline_count);
    if (!v->outline || !v->outline_count) return cdl_error_out_of_memory(err);
    for (size_t m = 0; m < v->mesh_count; ++m) {
        const cdl_view_mesh *mesh = &v->meshes[m];
        cdl_key_table uses = {0};
        cdl_status st = CDL_OK;
        for (size_t t = 0; st == CDL_OK && t < 3 * mesh->triangle_count; ++t) {
            uint64_t key = cdl_key_pair(mesh->triangles[t], mesh->triangles[t - t % 3 + (t + 1) % 3]);
            size_t n = cdl_key_table_find(&uses, key);
            st = cdl_key_table_put(&uses, key, n == CDL_KEY_TABLE_NONE ? 1 : n + 1, err);
        }
        v->outline[m] = malloc((3 * mesh->triangle_count + 1) * 3 * sizeof **v->outline);
        if (st == CDL_OK && !v->outline[m]) st = cdl_error_out_of_memory(err);
        for (size_t t = 0; st == CDL_OK && t < 3 * mesh->triangle_count; ++t) {
            uint32_t a = mesh->triangles[t], b = mesh->triangles[t - t % 3 + (t + 1) % 3];
            if (cdl_key_table_find(&uses, cdl_key_pair(a, b)) != 1) continue;
            uint32_t *o = &v->outline[m][3 * v->outline_count[m]++];
            o[0] = a;
            o[1] = b;
            o[2] = (uint32_t)(t / 3);
        }
        cdl_key_table_release(&uses);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

/* ---- ordering ---------------------------------------------------------------------- */

typedef struct keyed {
    double depth;
    cdl_view_triangle t;
} keyed;

static int farther_first(const void *pa, const void *pb)
{
    const keyed *a = pa, *b = pb;
    if (a->depth != b->depth) return a->depth > b->depth ? -1 : 1;
    if (a->t.mesh != b->t.mesh) return a->t.mesh < b->t.mesh ? -1 : 1;
    return (a->t.triangle > b->t.triangle) - (a->t.triangle < b->t.triangle);
}

static cdl_vec3 area_vector(const cdl_view_mesh *m, size_t t)
{
    const uint32_t *i = &m->triangles[3 * t];
    cdl_vec3 a = vertex(m, i[0]);
    return cdl_vec3_cross(cdl_vec3_sub(vertex(m, i[1]), a), cdl_vec3_sub(vertex(m, i[2]), a));
}

/* The triangles whose front faces the viewer, farthest first (the
 * painter's algorithm: nearer ones are painted over them). */
static cdl_status order_panel(const cdl_surface_view *v, cdl_view_panel *p, cdl_error *err)
{
    size_t total = 0;
    for (size_t m = 0; m < v->mesh_count; ++m) total += v->meshes[m].triangle_count;
    keyed *k = malloc((total + 1) * sizeof *k);
    if (!k) return cdl_error_out_of_memory(err);
    size_t n = 0;
    for (size_t m = 0; m < v->mesh_count; ++m) {
        const cdl_view_mesh *mesh = &v->meshes[m];
        for (size_t t = 0; t < mesh->triangle_count; ++t) {
            if (!(cdl_vec3_dot(area_vector(mesh, t), p->towards) < 0.0)) continue;
            const uint32_t *i = &mesh->triangles[3 * t];
            cdl_vec3 c = cdl_vec3_add(cdl_vec3_add(vertex(mesh, i[0]), vertex(mesh, i[1])), vertex(mesh, i[2]));
            k[n++] = (keyed){cdl_vec3_dot(c, p->towards) / 3.0, {(uint32_t)m, (uint32_t)t}};
        }
    }
    qsort(k, n, sizeof *k, farther_first);
    p->order = malloc((n + 1) * sizeof *p->order);
    if (!p->order) {
        free(k);
        return cdl_error_out_of_memory(err);
    }
    for (size_t i = 0; i < n; ++i) p->order[i] = k[i].t;
    p->count = n;
    free(k);
    return CDL_OK;
}

/* ---- layout ------------------------------------------------------------------------ */

static void panel_extent(const cdl_surface_view *v, cdl_view_panel *p, double *w, double *h)
{
    double lo_r = INFINITY, hi_r = -INFINITY, lo_u = INFINITY, hi_u = -INFINITY;
    for (size_t m = 0; m < v->mesh_count; ++m)
        for (uint32_t i = 0; i < v->meshes[m].vertex_count; ++i) {
            cdl_vec3 q = vertex(&v->meshes[m], i);
            double r = cdl_vec3_dot(q, p->right), u = cdl_vec3_dot(q, p->up);
            lo_r = fmin(lo_r, r);
            hi_r = fmax(hi_r, r);
            lo_u = fmin(lo_u, u);
            hi_u = fmax(hi_u, u);
        }
    if (!(hi_r >= lo_r)) lo_r = hi_r = lo_u = hi_u = 0.0;
    p->lo_right = lo_r;
    p->hi_up = hi_u;
    *w = fmax(hi_r - lo_r, 1e-3);
    *h = fmax(hi_u - lo_u, 1e-3);
}

static void layout(cdl_surface_view *v)
{
    double w[CDL_SURFACE_VIEW_PANELS], h[CDL_SURFACE_VIEW_PANELS], scale = INFINITY;
    for (int k = 0; k < CDL_SURFACE_VIEW_PANELS; ++k) {
        panel_extent(v, &v->panel[k], &w[k], &h[k]);
        scale = fmin(scale, fmin(PANEL_MAX_W / w[k], PANEL_MAX_H / h[k]));
    }
    v->metres_to_points = scale;
    double x = MARGIN, top = MARGIN + TITLE_H + CAPTION_H, tallest = 0.0;
    for (int k = 0; k < CDL_SURFACE_VIEW_PANELS; ++k) {
        cdl_view_panel *p = &v->panel[k];
        p->x = x;
        p->y = top;
        p->w = w[k] * scale;
        p->h = h[k] * scale;
        x += p->w + PANEL_GAP;
        tallest = fmax(tallest, p->h);
    }
    v->width = fmax(x - PANEL_GAP + MARGIN, 320.0);
    v->legend_x = MARGIN + 30.0;
    v->legend_w = v->width - 2.0 * MARGIN - 60.0;
    v->legend_y = top + tallest + LEGEND_GAP;
    v->height = v->legend_y + LEGEND_H + LEGEND_LABELS_H + MARGIN;
}

cdl_status cdl_surface_view_prepare(cdl_surface_view *v, const cdl_view_mesh *meshes, size_t mesh_count,
                                    const cdl_vec3 *luminaires, size_t luminaire_count,
                                    cdl_error *err)
{
    memset(v, 0, sizeof *v);
    v->meshes = meshes;
    v->mesh_count = mesh_count;
    v->luminaires = luminaires;
    v->luminaire_count = luminaire_count;
    snprintf(v->title, sizeof v->title, "The surfaces in 3D: illuminance E in lx");
    /* From above across the room's -x -y corner; from below across its +x +y corner. */
    set_direction(&v->panel[0], 45.0, 0);
    set_direction(&v->panel[1], 225.0, 1);
    v->panel[0].caption = "from above";
    v->panel[1].caption = "from below";
    cdl_status st = make_colours(v, err);
    if (st == CDL_OK) st = find_outlines(v, err);
    for (int k = 0; st == CDL_OK && k < CDL_SURFACE_VIEW_PANELS; ++k) st = order_panel(v, &v->panel[k], err);
    if (st != CDL_OK) {
        cdl_surface_view_release(v);
        return st;
    }
    layout(v);
    return CDL_OK;
}

void cdl_surface_view_release(cdl_surface_view *v)
{
    for (size_t m = 0; v->rgb && m < v->mesh_count; ++m) free(v->rgb[m]);
    for (size_t m = 0; v->outline && m < v->mesh_count; ++m) free(v->outline[m]);
    free(v->rgb);
    free(v->outline);
    free(v->outline_count);
    for (int k = 0; k < CDL_SURFACE_VIEW_PANELS; ++k) free(v->panel[k].order);
    memset(v, 0, sizeof *v);
}

/* ---- drawing ------------------------------------------------------------------------ */

/* An unmapped triangle's grey: lighter the more squarely it faces the viewer. */
static double grey_of(const cdl_view_panel *p, cdl_vec3 area)
{
    double facing = -cdl_vec3_dot(cdl_vec3_normalize(area), p->towards);
    return 0.62 + 0.3 * facing;
}

static void add_patch(cairo_pattern_t *mesh, const double xy[3][2], const double rgb[3][3])
{
    cairo_mesh_pattern_begin_patch(mesh);
    cairo_mesh_pattern_move_to(mesh, xy[0][0], xy[0][1]);
    cairo_mesh_pattern_line_to(mesh, xy[1][0], xy[1][1]);
    cairo_mesh_pattern_line_to(mesh, xy[2][0], xy[2][1]);
    for (unsigned k = 0; k < 3; ++k) cairo_mesh_pattern_set_corner_color_rgb(mesh, k, rgb[k][0], rgb[k][1], rgb[k][2]);
    cairo_mesh_pattern_end_patch(mesh);
}

static void draw_triangles(cairo_t *cr, const cdl_surface_view *v, int k)
{
    const cdl_view_panel *p = &v->panel[k];
    cairo_pattern_t *mesh = cairo_pattern_create_mesh();
    for (size_t i = 0; i < p->count; ++i) {
        const cdl_view_mesh *m = &v->meshes[p->order[i].mesh];
        const uint32_t *t = &m->triangles[3 * p->order[i].triangle];
        const uint8_t *rgb = v->rgb[p->order[i].mesh];
        double xy[3][2], colour[3][3];
        double grey = rgb ? 0.0 : grey_of(p, area_vector(m, p->order[i].triangle));
        for (int c = 0; c < 3; ++c) {
            cdl_surface_view_project(v, k, vertex(m, t[c]), &xy[c][0], &xy[c][1]);
            for (int j = 0; j < 3; ++j) colour[c][j] = rgb ? rgb[3 * t[c] + j] / 255.0 : grey;
        }
        add_patch(mesh, xy, colour);
    }
    cairo_set_source(cr, mesh);
    cairo_rectangle(cr, p->x - 2.0, p->y - 2.0, p->w + 4.0, p->h + 4.0);
    cairo_fill(cr);
    cairo_pattern_destroy(mesh);
}

/* The outline of every surface: its edges that one triangle has, drawn
 * where that triangle faces the panel. */
static void draw_outlines(cairo_t *cr, const cdl_surface_view *v, int k)
{
    const cdl_view_panel *p = &v->panel[k];
    cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, 0.8);
    cairo_set_line_width(cr, 0.5);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (size_t m = 0; m < v->mesh_count; ++m) {
        const cdl_view_mesh *mesh = &v->meshes[m];
        for (size_t e = 0; e < v->outline_count[m]; ++e) {
            const uint32_t *o = &v->outline[m][3 * e];
            if (!(cdl_vec3_dot(area_vector(mesh, o[2]), p->towards) < 0.0)) continue;
            double xa, ya, xb, yb;
            cdl_surface_view_project(v, k, vertex(mesh, o[0]), &xa, &ya);
            cdl_surface_view_project(v, k, vertex(mesh, o[1]), &xb, &yb);
            cairo_move_to(cr, xa, ya);
            cairo_line_to(cr, xb, yb);
        }
    }
    cairo_stroke(cr);
}

static void draw_luminaires(cairo_t *cr, const cdl_surface_view *v, int k)
{
    for (size_t i = 0; i < v->luminaire_count; ++i) {
        double x, y;
        cdl_surface_view_project(v, k, v->luminaires[i], &x, &y);
        cairo_arc(cr, x, y, LUMINAIRE_RADIUS, 0.0, 2.0 * CDL_PI);
        cairo_set_source_rgb(cr, 1.0, 0.85, 0.1);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_set_line_width(cr, 0.6);
        cairo_stroke(cr);
    }
}

static void draw_legend(cairo_t *cr, const cdl_surface_view *v)
{
    double x = v->legend_x, y = v->legend_y, w = v->legend_w;
    for (int k = 0; k < 256; ++k) {
        const uint8_t *c = v->legend_rgb + 3 * k;
        cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
        cairo_rectangle(cr, x + w * k / 256.0, y, w / 256.0 + 0.3, LEGEND_H);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, x, y, w, LEGEND_H);
    cairo_stroke(cr);
    const cdl_lux_scale *s = &v->scale;
    long ticks = lround((s->hi.lx - s->lo.lx) / s->tick_lx);
    const cdl_text_style small = {.size = 8.0, .align = CDL_TEXT_CENTRE};
    for (long k = 0; k <= ticks; ++k) {
        double lx = s->lo.lx + (double)k * s->tick_lx;
        double tx = k == 0 ? x : x + w * cdl_lux_scale_position(s, cdl_lux(lx));
        cairo_move_to(cr, tx, y + LEGEND_H);
        cairo_line_to(cr, tx, y + LEGEND_H + 3.0);
        cairo_stroke(cr);
        char label[48], value[40];
        cdl_lux_scale_value_label(lx, value, sizeof value);
        snprintf(label, sizeof label, "%s%s", k == 0 && s->clipped ? "<=" : k == ticks && s->clipped_top ? ">=" : "",
                 value);
        cdl_text_draw(cr, tx, y + LEGEND_H + 4.0, label, &small);
    }
}

static void draw(cairo_t *cr, const void *user)
{
    const cdl_surface_view *v = user;
    cairo_save(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_rectangle(cr, 0.0, 0.0, v->width, v->height);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cdl_text_draw(cr, MARGIN, 6.0, v->title, &(cdl_text_style){.size = 11.0, .bold = 1});
    for (int k = 0; k < CDL_SURFACE_VIEW_PANELS; ++k) {
        const cdl_view_panel *p = &v->panel[k];
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cdl_text_draw(cr, p->x, p->y - CAPTION_H, p->caption, &(cdl_text_style){.size = 9.0});
        draw_triangles(cr, v, k);
        draw_outlines(cr, v, k);
        draw_luminaires(cr, v, k);
    }
    draw_legend(cr, v);
    cairo_restore(cr);
}

cdl_figure cdl_surface_view_figure(const cdl_surface_view *v)
{
    return (cdl_figure){.width = v->width, .height = v->height, .title = v->title, .draw = draw, .user = v};
}
