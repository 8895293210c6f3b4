/* grid_map.c - the report's map of a grid (grid_map.h). */
#include "report/grid_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "graphics/text.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "graphics/palette.h"
#include "report/plan_symbols.h"
#include "report/report_numbers.h"
#include "report/summary_table.h"

/* Layout, points. */
#define MAP_MAX_W 380.0
#define MAP_MAX_H 330.0
#define MAP_LEFT 16.0
#define MAP_TOP 30.0
#define LEGEND_GAP 18.0
#define LEGEND_W 14.0
#define LEGEND_MIN_H 160.0
#define LEGEND_LABELS_W 70.0
/* Below the map: the scale bar, then the key (two lines), which starts
 * below the legend too where that reaches lower than the map. */
#define KEY_BELOW_MAP 24.0
#define KEY_BELOW_LEGEND 8.0
#define KEY_H 30.0
/* The image: each raster pixel drawn as zoom x zoom pixels, zoom enough for
 * about 800 pixels on the long side (sharp edges in any viewer). */
#define IMAGE_LONG_SIDE 800
/* Labels: white around the text, the least room between two boxes, the
 * markers' half size, the most places tried along a contour line. */
#define LABEL_PAD 1.5
#define LABEL_GAP 1.0
#define MARK 4.0
#define LEVEL_CANDIDATES 48

void cdl_grid_map_raster_position(const cdl_grid *g, cdl_vec3 p, double *x, double *y)
{
    cdl_vec3 d = cdl_vec3_sub(p, g->raster_corner);
    *x = cdl_vec3_dot(d, g->raster_right) / g->pixel_width_m;
    *y = g->raster_height - cdl_vec3_dot(d, g->raster_up) / g->pixel_height_m;
}

/* Raster units to the figure's points. */
static void to_page(const cdl_grid_map *m, double x, double y, double *px, double *py)
{
    const cdl_grid *g = &m->grid->grid;
    *px = m->map_x + x * g->pixel_width_m * m->metres_to_points;
    *py = m->map_y + y * g->pixel_height_m * m->metres_to_points;
}

static void world_to_page(const cdl_grid_map *m, cdl_vec3 p, double *px, double *py)
{
    double x, y;
    cdl_grid_map_raster_position(&m->grid->grid, p, &x, &y);
    to_page(m, x, y, px, py);
}

/* The false colours: each point's place on the scale through the palette. */
static cdl_status make_image(cdl_grid_map *m, cdl_error *err)
{
    const cdl_grid *g = &m->grid->grid;
    size_t n = g->count;
    uint8_t *rgb = malloc((n + 1) * 3);
    if (!rgb) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < n; ++i)
        cdl_palette_rgb8(cdl_lux_scale_position(&m->scale, cdl_lux(m->field->values[i])), rgb + 3 * i);
    cdl_palette_ramp(m->legend_rgb);
    int long_side = g->raster_width > g->raster_height ? g->raster_width : g->raster_height;
    m->zoom = long_side > 0 ? (IMAGE_LONG_SIDE + long_side - 1) / long_side : 1;
    if (m->zoom < 1) m->zoom = 1;
    int w = g->raster_width * m->zoom, h = g->raster_height * m->zoom;
    m->image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cdl_status st = CDL_OK;
    if (cairo_surface_status(m->image) != CAIRO_STATUS_SUCCESS) {
        st = cdl_error_set(err, CDL_ERR_INTERNAL, "cannot make a %d x %d image for the map", w, h);
    } else {
        unsigned char *data = cairo_image_surface_get_data(m->image);
        int stride = cairo_image_surface_get_stride(m->image);
        for (int y = 0; y < h; ++y) {
            uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
            for (int x = 0; x < w; ++x) {
                size_t pixel = (size_t)(y / m->zoom) * (size_t)g->raster_width + (size_t)(x / m->zoom);
                int32_t idx = g->raster_index[pixel];
                const uint8_t *c = rgb + 3 * (size_t)(idx < 0 ? 0 : idx);
                /* ARGB32, premultiplied: transparent outside the grid. */
                row[x] = idx < 0 ? 0u : 0xFF000000u | (uint32_t)c[0] << 16 | (uint32_t)c[1] << 8 | c[2];
            }
        }
        cairo_surface_mark_dirty(m->image);
    }
    free(rgb);
    return st;
}

static cdl_status trace_contours(cdl_grid_map *m, cdl_error *err)
{
    m->level_count = cdl_contour_levels(m->field->min, m->field->max, m->levels, CDL_GRID_MAP_MAX_LEVELS);
    cdl_status st = CDL_OK;
    for (size_t k = 0; k < m->level_count && st == CDL_OK; ++k)
        st = cdl_contour_trace_grid(&m->grid->grid, m->field->values, m->levels[k], &m->segments[k],
                                    &m->segment_count[k], err);
    return st;
}

/* ---- the plan and the labels ------------------------------------------------------- */

static void project(const void *user, cdl_vec3 p, double *x, double *y)
{
    world_to_page(user, p, x, y);
}

/* A label's text and size, measured, with a little white around it. */
static void label_text(cdl_grid_map_label *l, double size, const char *text, double *w, double *h)
{
    snprintf(l->text, sizeof l->text, "%s", text);
    l->size = size;
    cdl_text_measure_alone(text, &(cdl_text_style){.size = size}, w, h);
    *w += 2.0 * LABEL_PAD;
}

/* Candidates around a marker at (x, y): right, left, above, below, then the corners. */
static void around(double x, double y, double w, double h, double *centres)
{
    const double dx = 0.5 * w + 6.0, dy = 0.5 * h + 6.0;
    const double offsets[8][2] = {{dx, 0}, {-dx, 0}, {0, -dy}, {0, dy}, {dx, -dy}, {-dx, -dy}, {dx, dy}, {-dx, dy}};
    for (int k = 0; k < 8; ++k) {
        centres[2 * k] = x + offsets[k][0];
        centres[2 * k + 1] = y + offsets[k][1];
    }
}

/* A level's candidates: its segments' midpoints on the page, at most
 * LEVEL_CANDIDATES of them spread evenly along the list, nearest the
 * middle of the list first (a label mid-line reads best). */
static size_t level_candidates(const cdl_grid_map *m, size_t level, double *centres)
{
    size_t n = m->segment_count[level], take = n < LEVEL_CANDIDATES ? n : LEVEL_CANDIDATES;
    size_t index[LEVEL_CANDIDATES];
    for (size_t j = 0; j < take; ++j) index[j] = j * n / take;
    /* by distance from the middle (insertion sort: a few dozen) */
    for (size_t j = 1; j < take; ++j)
        for (size_t i = j; i > 0; --i) {
            size_t a = index[i - 1], b = index[i], mid = n / 2;
            if ((a > mid ? a - mid : mid - a) <= (b > mid ? b - mid : mid - b)) break;
            index[i - 1] = b;
            index[i] = a;
        }
    for (size_t j = 0; j < take; ++j) {
        const cdl_contour_segment *seg = &m->segments[level][index[j]];
        to_page(m, 0.5 * (seg->x0 + seg->x1), 0.5 * (seg->y0 + seg->y1), &centres[2 * j], &centres[2 * j + 1]);
    }
    return take;
}

static cdl_status place_labels(cdl_grid_map *m, cdl_error *err)
{
    const cdl_report_field *f = m->field;
    const cdl_grid *g = &m->grid->grid;
    world_to_page(m, g->points[f->min_index], &m->min_x, &m->min_y);
    world_to_page(m, g->points[f->max_index], &m->max_x, &m->max_y);
    cdl_label_request requests[CDL_GRID_MAP_MAX_LABELS];
    double centres[CDL_GRID_MAP_MAX_LABELS][2 * LEVEL_CANDIDATES];
    const char *space = f->unit[0] ? " " : "";
    char text[64], v[32];
    double u[2];
    cdl_report_field_extreme_errors(f, &u[0], &u[1]);
    const double extreme[2] = {f->min, f->max}, ex[2] = {m->min_x, m->max_x}, ey[2] = {m->min_y, m->max_y};
    for (int k = 0; k < 2; ++k) {
        cdl_report_format(v, sizeof v, extreme[k], u[k]);
        snprintf(text, sizeof text, "%s %s%s%s", k ? "max" : "min", v, space, f->unit);
        label_text(&m->labels[k], 8.5, text, &requests[k].width, &requests[k].height);
        around(ex[k], ey[k], requests[k].width, requests[k].height, centres[k]);
        requests[k].centres = centres[k];
        requests[k].centre_count = 8;
    }
    m->label_count = 2;
    for (size_t k = 0; k < m->level_count; ++k) {
        size_t i = m->label_count++;
        snprintf(text, sizeof text, "%g%s%s", m->levels[k], space, f->unit);
        label_text(&m->labels[i], 8.0, text, &requests[i].width, &requests[i].height);
        requests[i].centres = centres[i];
        requests[i].centre_count = level_candidates(m, k, centres[i]);
    }
    /* keep clear of the luminaires and of both markers */
    cdl_label_box *obstacles = malloc((m->symbol_count + 2) * sizeof *obstacles);
    if (!obstacles) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < m->symbol_count; ++k) obstacles[k] = m->symbols[k].box;
    for (int k = 0; k < 2; ++k)
        obstacles[m->symbol_count + (size_t)k] = (cdl_label_box){ex[k] - MARK, ey[k] - MARK, ex[k] + MARK, ey[k] + MARK};
    cdl_label_box bounds = {m->map_x, m->map_y, m->map_x + m->map_w, m->map_y + m->map_h};
    cdl_label_box boxes[CDL_GRID_MAP_MAX_LABELS];
    int placed[CDL_GRID_MAP_MAX_LABELS];
    cdl_label_layout(requests, m->label_count, obstacles, m->symbol_count + 2, bounds, LABEL_GAP, boxes, placed);
    for (size_t k = 0; k < m->label_count; ++k) {
        m->labels[k].placed = placed[k];
        m->labels[k].box = boxes[k];
    }
    free(obstacles);
    return CDL_OK;
}

cdl_status cdl_grid_map_prepare(cdl_grid_map *m, const cdl_report_input *input, const cdl_report_grid *grid,
                                size_t field, cdl_error *err)
{
    memset(m, 0, sizeof *m);
    m->input = input;
    m->grid = grid;
    m->field = &grid->fields[field];
    const cdl_grid *g = &grid->grid;
    m->scale = cdl_lux_scale_linear_for_values(m->field->values, g->count);
    if (strcmp(m->field->column, "AO") == 0) /* a share: always 0 to 1 */
        m->scale = (cdl_lux_scale){.kind = CDL_LUX_SCALE_LINEAR, .lo = cdl_lux(0.0), .hi = cdl_lux(1.0), .tick_lx = 0.2};
    double w_m = g->raster_width * g->pixel_width_m, h_m = g->raster_height * g->pixel_height_m;
    m->metres_to_points = fmin(MAP_MAX_W / w_m, MAP_MAX_H / h_m);
    m->map_x = MAP_LEFT;
    m->map_y = MAP_TOP;
    m->map_w = w_m * m->metres_to_points;
    m->map_h = h_m * m->metres_to_points;
    m->width = m->map_x + m->map_w + LEGEND_GAP + LEGEND_W + LEGEND_LABELS_W;
    m->height = m->map_y + fmax(m->map_h + KEY_BELOW_MAP, LEGEND_MIN_H + KEY_BELOW_LEGEND) + KEY_H;
    const cdl_report_field *f = m->field;
    if (f->unit[0])
        snprintf(m->title, sizeof m->title, "%s: %s %s in %s, %s lines, plan and luminaires", grid->spec->name, f->what,
                 f->symbol, f->unit, strcmp(f->unit, "lx") == 0 ? "isolux" : "contour");
    else
        snprintf(m->title, sizeof m->title, "%s: %s %s, contour lines, plan and luminaires", grid->spec->name, f->what,
                 f->symbol);
    cdl_plan_view view = {project, m, g->count ? g->points[0] : cdl_vec3_make(0, 0, 0),
                          g->count ? g->normals[0] : cdl_vec3_make(0, 0, 1)};
    cdl_status st = make_image(m, err);
    if (st == CDL_OK) st = trace_contours(m, err);
    if (st == CDL_OK) st = cdl_plan_symbols_make(input, &view, &m->symbols, &m->symbol_count, err);
    if (st == CDL_OK) st = place_labels(m, err);
    if (st != CDL_OK) cdl_grid_map_release(m);
    return st;
}

void cdl_grid_map_release(cdl_grid_map *m)
{
    if (m->image) cairo_surface_destroy(m->image);
    m->image = NULL;
    for (size_t k = 0; k < CDL_GRID_MAP_MAX_LEVELS; ++k) {
        free(m->segments[k]);
        m->segments[k] = NULL;
    }
    free(m->symbols);
    m->symbols = NULL;
}

/* ---- drawing ---------------------------------------------------------------------- */

static void line_world(cairo_t *cr, const cdl_grid_map *m, cdl_vec3 a, cdl_vec3 b)
{
    double x0, y0, x1, y1;
    world_to_page(m, a, &x0, &y0);
    world_to_page(m, b, &x1, &y1);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
}

static void ring_world(cairo_t *cr, const cdl_grid_map *m, const cdl_vec3 *p, size_t n)
{
    for (size_t k = 0; k < n; ++k) line_world(cr, m, p[k], p[(k + 1) % n]);
}

/* The outline of a surface-like shape (surfaces and area luminaires' shapes). */
static void outline(cairo_t *cr, const cdl_grid_map *m, const cdl_surface_spec *s)
{
    switch (s->kind) {
    case CDL_SURFACE_RECT: {
        cdl_vec3 c[4] = {s->origin, cdl_vec3_add(s->origin, s->u), cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v),
                         cdl_vec3_add(s->origin, s->v)};
        ring_world(cr, m, c, 4);
        break;
    }
    case CDL_SURFACE_POLYGON:
        ring_world(cr, m, s->outer.points, s->outer.count);
        for (size_t h = 0; h < s->hole_count; ++h) ring_world(cr, m, s->holes[h].points, s->holes[h].count);
        break;
    case CDL_SURFACE_BOX: {
        cdl_vec3 lo = s->box_min, hi = s->box_max;
        for (int axis = 0; axis < 3; ++axis)
            for (int k = 0; k < 4; ++k) {
                /* the 4 edges along `axis`: the other two coordinates at lo or hi */
                double a[3] = {lo.x, lo.y, lo.z}, b[3] = {hi.x, hi.y, hi.z}, p[3], q[3];
                int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
                p[axis] = a[axis];
                q[axis] = b[axis];
                p[o1] = q[o1] = (k & 1) ? b[o1] : a[o1];
                p[o2] = q[o2] = (k & 2) ? b[o2] : a[o2];
                line_world(cr, m, cdl_vec3_make(p[0], p[1], p[2]), cdl_vec3_make(q[0], q[1], q[2]));
            }
        break;
    }
    case CDL_SURFACE_DISK: {
        cdl_frame f = cdl_frame_from_normal(cdl_vec3_normalize(s->normal));
        cdl_vec3 c[48];
        for (int k = 0; k < 48; ++k) {
            double a = 2.0 * CDL_PI * k / 48.0;
            c[k] = cdl_vec3_add(s->center, cdl_vec3_add(cdl_vec3_scale(f.s, s->radius * cos(a)),
                                                        cdl_vec3_scale(f.t, s->radius * sin(a))));
        }
        ring_world(cr, m, c, 48);
        break;
    }
    case CDL_SURFACE_SPHERE: {
        /* the silhouette: a circle of the radius about the projected centre */
        double x, y;
        world_to_page(m, s->center, &x, &y);
        cairo_new_sub_path(cr);
        cairo_arc(cr, x, y, s->radius * m->metres_to_points, 0.0, 2.0 * CDL_PI);
        break;
    }
    case CDL_SURFACE_MESH:
        /* every triangle's edges, for meshes small enough to read */
        if (s->mesh_triangle_count <= 5000)
            for (size_t t = 0; t < s->mesh_triangle_count; ++t) {
                cdl_vec3 c[3];
                for (int k = 0; k < 3; ++k) {
                    const double *v = s->mesh_vertices + 3 * (size_t)s->mesh_triangles[3 * t + (size_t)k];
                    c[k] = cdl_vec3_make(v[0], v[1], v[2]);
                }
                ring_world(cr, m, c, 3);
            }
        break;
    }
}

/* A box's open faces (windows, doors): their edges, for a blue line under the outline. */
static void open_faces(cairo_t *cr, const cdl_grid_map *m, const cdl_surface_spec *s)
{
    if (s->kind != CDL_SURFACE_BOX) return;
    const double lo[3] = {s->box_min.x, s->box_min.y, s->box_min.z}, hi[3] = {s->box_max.x, s->box_max.y, s->box_max.z};
    for (int f = 0; f < CDL_BOX_FACES; ++f) {
        if (!s->face_open[f]) continue;
        int axis = f / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
        cdl_vec3 c[4];
        for (int k = 0; k < 4; ++k) {
            double p[3];
            p[axis] = f % 2 ? hi[axis] : lo[axis];
            p[a] = (k == 1 || k == 2) ? hi[a] : lo[a];
            p[b] = k >= 2 ? hi[b] : lo[b];
            c[k] = cdl_vec3_make(p[0], p[1], p[2]);
        }
        ring_world(cr, m, c, 4);
    }
}

/* The surfaces' outlines (open faces in blue beneath), then the luminaires. */
static void draw_plan(cairo_t *cr, const cdl_grid_map *m)
{
    const cdl_scene *scene = m->input->scene;
    cairo_save(cr);
    cairo_rectangle(cr, m->map_x - 1.0, m->map_y - 1.0, m->map_w + 2.0, m->map_h + 2.0);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.2, 0.45, 0.95);
    cairo_set_line_width(cr, 3.0);
    for (size_t k = 0; k < scene->surface_count; ++k) open_faces(cr, m, &scene->surfaces[k]);
    cairo_stroke(cr);
    cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, 0.85);
    cairo_set_line_width(cr, 0.7);
    for (size_t k = 0; k < scene->surface_count; ++k) outline(cr, m, &scene->surfaces[k]);
    cairo_stroke(cr);
    cdl_plan_symbols_draw(cr, m->symbols, m->symbol_count);
    cairo_restore(cr);
}

static void draw_contours(cairo_t *cr, const cdl_grid_map *m)
{
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.8);
    for (size_t k = 0; k < m->level_count; ++k)
        for (size_t s = 0; s < m->segment_count[k]; ++s) {
            const cdl_contour_segment *seg = &m->segments[k][s];
            double x0, y0, x1, y1;
            to_page(m, seg->x0, seg->y0, &x0, &y0);
            to_page(m, seg->x1, seg->y1, &x1, &y1);
            cairo_move_to(cr, x0, y0);
            cairo_line_to(cr, x1, y1);
        }
    cairo_stroke(cr);
    cairo_restore(cr);
}

/* The min and max markers: a white-edged cross. */
static void draw_markers(cairo_t *cr, const cdl_grid_map *m)
{
    const double x[2] = {m->min_x, m->max_x}, y[2] = {m->min_y, m->max_y};
    for (int k = 0; k < 2; ++k) {
        cairo_move_to(cr, x[k] - MARK, y[k] - MARK);
        cairo_line_to(cr, x[k] + MARK, y[k] + MARK);
        cairo_move_to(cr, x[k] + MARK, y[k] - MARK);
        cairo_line_to(cr, x[k] - MARK, y[k] + MARK);
    }
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_set_line_width(cr, 2.5);
    cairo_stroke_preserve(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 1.2);
    cairo_stroke(cr);
}

/* The placed labels: a white box each, the text centred in it. */
static void draw_labels(cairo_t *cr, const cdl_grid_map *m)
{
    for (size_t k = 0; k < m->label_count; ++k) {
        const cdl_grid_map_label *l = &m->labels[k];
        if (!l->placed) continue;
        const cdl_label_box *b = &l->box;
        cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.88);
        cairo_rectangle(cr, b->x0, b->y0, b->x1 - b->x0, b->y1 - b->y0);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cdl_text_draw(cr, 0.5 * (b->x0 + b->x1), b->y0, l->text,
                      &(cdl_text_style){.size = l->size, .align = CDL_TEXT_CENTRE});
    }
}

static void draw_legend(cairo_t *cr, const cdl_grid_map *m)
{
    double x = m->map_x + m->map_w + LEGEND_GAP, y = m->map_y, h = fmax(m->map_h, LEGEND_MIN_H);
    for (int k = 0; k < 256; ++k) {
        const uint8_t *c = m->legend_rgb + 3 * k;
        cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
        /* t = k / 255 from the bottom */
        cairo_rectangle(cr, x, y + h * (1.0 - (k + 1) / 256.0), LEGEND_W, h / 256.0 + 0.3);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, x, y, LEGEND_W, h);
    cairo_stroke(cr);
    const cdl_lux_scale *s = &m->scale;
    long ticks = lround((s->hi.lx - s->lo.lx) / s->tick_lx);
    const cdl_text_style small = {.size = 8.5};
    for (long k = 0; k <= ticks; ++k) {
        double lx = s->lo.lx + (double)k * s->tick_lx;
        double ty = y + h * (1.0 - cdl_lux_scale_position(s, cdl_lux(lx)));
        if (k == 0) ty = y + h;
        cairo_move_to(cr, x + LEGEND_W, ty);
        cairo_line_to(cr, x + LEGEND_W + 4.0, ty);
        cairo_stroke(cr);
        /* the scale's round value ("480 lx", "12.5k lx") in the quantity's unit */
        char label[64], v[40];
        cdl_lux_scale_value_label(lx, v, sizeof v);
        size_t n = strlen(v);
        if (n > 3 && strcmp(v + n - 3, " lx") == 0) v[n - 3] = '\0';
        snprintf(label, sizeof label, "%s%s%s%s", k == 0 && s->clipped ? "<=" : "", v, m->field->unit[0] ? " " : "",
                 m->field->unit);
        cdl_text_draw(cr, x + LEGEND_W + 6.0, ty - 5.5, label, &small);
    }
}

/* The direction a map axis runs in the world: "+x" when along an axis. */
static void axis_name(cdl_vec3 dir, const char *fallback, char *out, size_t size)
{
    const double c[3] = {dir.x, dir.y, dir.z};
    snprintf(out, size, "%s", fallback);
    for (int k = 0; k < 3; ++k)
        if (fabs(c[k]) > 1.0 - 1e-9) snprintf(out, size, "%c%c", c[k] > 0.0 ? '+' : '-', 'x' + k);
}

static void draw_frame_and_scale(cairo_t *cr, const cdl_grid_map *m)
{
    const cdl_grid *g = &m->grid->grid;
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, m->map_x, m->map_y, m->map_w, m->map_h);
    cairo_stroke(cr);
    /* Scale bar: a 1-2-5 length near a quarter of the map's width. */
    double quarter = 0.25 * m->map_w / m->metres_to_points;
    double e = pow(10.0, floor(log10(quarter))), len = e;
    if (5.0 * e <= quarter) len = 5.0 * e;
    else if (2.0 * e <= quarter) len = 2.0 * e;
    double y = m->map_y + m->map_h + 14.0, x0 = m->map_x, x1 = x0 + len * m->metres_to_points;
    cairo_set_line_width(cr, 1.5);
    cairo_move_to(cr, x0, y);
    cairo_line_to(cr, x1, y);
    cairo_move_to(cr, x0, y - 3.0);
    cairo_line_to(cr, x0, y + 3.0);
    cairo_move_to(cr, x1, y - 3.0);
    cairo_line_to(cr, x1, y + 3.0);
    cairo_stroke(cr);
    char label[256], right[8], up[8];
    snprintf(label, sizeof label, "%g m", len);
    const cdl_text_style small = {.size = 8.5};
    cdl_text_draw(cr, x1 + 5.0, y - 6.0, label, &small);
    axis_name(g->raster_right, "u", right, sizeof right);
    axis_name(g->raster_up, "v", up, sizeof up);
    snprintf(label, sizeof label,
             "plan seen along -normal: %s to the right, %s up; luminaires as their luminous openings (a ring: none "
             "given), aiming lines to their aim, masts filled; blue: open faces; x min and max",
             right, up);
    double key_y = m->map_y + fmax(m->map_h + KEY_BELOW_MAP, LEGEND_MIN_H + KEY_BELOW_LEGEND);
    cdl_text_draw(cr, m->map_x, key_y, label,
                  &(cdl_text_style){.size = 8.0, .wrap_width = m->width - m->map_x - 4.0});
}

static void draw(cairo_t *cr, const void *user)
{
    const cdl_grid_map *m = user;
    const cdl_grid *g = &m->grid->grid;
    cairo_save(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_rectangle(cr, 0.0, 0.0, m->width, m->height);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cdl_text_draw(cr, m->map_x, 6.0, m->title, &(cdl_text_style){.size = 11.0, .bold = 1});
    /* The false colours, scaled from the image's pixels to the map's box. */
    cairo_save(cr);
    cairo_translate(cr, m->map_x, m->map_y);
    cairo_scale(cr, m->map_w / (g->raster_width * m->zoom), m->map_h / (g->raster_height * m->zoom));
    cairo_set_source_surface(cr, m->image, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    draw_contours(cr, m);
    draw_plan(cr, m);
    draw_markers(cr, m);
    draw_labels(cr, m);
    draw_frame_and_scale(cr, m);
    draw_legend(cr, m);
    cairo_restore(cr);
}

cdl_figure cdl_grid_map_figure(const cdl_grid_map *m)
{
    return (cdl_figure){.width = m->width, .height = m->height, .title = m->title, .draw = draw, .user = m};
}
