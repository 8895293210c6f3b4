/* plan_symbols.c - luminaires on a plan: footprints, aiming lines, masts (plan_symbols.h). */
#include "report/plan_symbols.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"

#define SYMBOL_RADIUS 4.5   /* the ring of a small symbol, points */
#define SYMBOL_MIN 3.0      /* a footprint smaller than this on the page is drawn as the symbol */
#define AIM_MIN 6.0         /* an aiming line shorter than this is not drawn */
#define MAST_HALF 3.0       /* half the side of a mast's square */
#define ROUND_POINTS 24     /* points on a round outline */

/* ---- outlines in the luminaire's frame ---------------------------------------------- */

static size_t ring(cdl_vec3 *out, size_t n, double rx, double ry, double z, int vertical)
{
    for (int k = 0; k < ROUND_POINTS; ++k) {
        double a = 2.0 * CDL_PI * k / ROUND_POINTS;
        out[n++] = vertical ? cdl_vec3_make(0.0, rx * cos(a), ry * sin(a))
                            : cdl_vec3_make(rx * cos(a), ry * sin(a), z);
    }
    return n;
}

static size_t rectangle(cdl_vec3 *out, size_t n, double hx, double hy, double z)
{
    out[n++] = cdl_vec3_make(-hx, -hy, z);
    out[n++] = cdl_vec3_make(hx, -hy, z);
    out[n++] = cdl_vec3_make(hx, hy, z);
    out[n++] = cdl_vec3_make(-hx, hy, z);
    return n;
}

/* The corners of an opening (photometry.h's frame: x along the length,
 * y along the width, z up), top and bottom for a solid; 0 for a point. */
static size_t opening_points(const cdl_luminous_opening *o, cdl_vec3 *out)
{
    double l = o->length_m, w = o->width_m > 0.0 ? o->width_m : o->length_m, h = o->height_m;
    double hz = 0.5 * h;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE: return rectangle(out, 0, 0.5 * l, 0.5 * w, 0.0);
    case CDL_LUMINOUS_SHAPE_BOX:
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG:
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS:
        return rectangle(out, rectangle(out, 0, 0.5 * l, 0.5 * w, -hz), 0.5 * l, 0.5 * w, hz);
    case CDL_LUMINOUS_SHAPE_CIRCLE:
    case CDL_LUMINOUS_SHAPE_ELLIPSE: return ring(out, 0, 0.5 * l, 0.5 * w, 0.0, 0);
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER:
    case CDL_LUMINOUS_SHAPE_SPHERE:
    case CDL_LUMINOUS_SHAPE_ELLIPSOID: return ring(out, ring(out, 0, 0.5 * l, 0.5 * w, -hz, 0), 0.5 * l, 0.5 * w, hz, 0);
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: return ring(out, 0, 0.5 * w, 0.5 * (h > 0.0 ? h : w), 0.0, 1);
    default: return 0;
    }
}

/* An area luminaire's shape corners in the world. */
static size_t shape_points(const cdl_surface_spec *s, cdl_vec3 *out, size_t max)
{
    size_t n = 0;
    if (s->kind == CDL_SURFACE_RECT) {
        out[n++] = s->origin;
        out[n++] = cdl_vec3_add(s->origin, s->u);
        out[n++] = cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v);
        out[n++] = cdl_vec3_add(s->origin, s->v);
    } else if (s->kind == CDL_SURFACE_DISK) {
        cdl_frame f = cdl_frame_from_normal(cdl_vec3_normalize(s->normal));
        for (int k = 0; k < ROUND_POINTS; ++k) {
            double t = 2.0 * CDL_PI * k / ROUND_POINTS;
            out[n++] = cdl_vec3_add(s->center, cdl_vec3_add(cdl_vec3_scale(f.s, s->radius * cos(t)),
                                                            cdl_vec3_scale(f.t, s->radius * sin(t))));
        }
    } else if (s->kind == CDL_SURFACE_POLYGON) {
        for (size_t k = 0; k < s->outer.count && n < max; ++k) out[n++] = s->outer.points[k];
    } else if (s->kind == CDL_SURFACE_MESH) {
        /* a mesh's vertices, a few evenly spread when it has many */
        size_t stride = s->mesh_vertex_count / max + 1;
        for (size_t k = 0; k < s->mesh_vertex_count && n < max; k += stride)
            out[n++] = cdl_vec3_make(s->mesh_vertices[3 * k], s->mesh_vertices[3 * k + 1], s->mesh_vertices[3 * k + 2]);
    }
    return n;
}

/* ---- on the page ------------------------------------------------------------------ */

static double cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static int by_x(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    return a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : a[1] < b[1] ? -1 : a[1] > b[1];
}

/* The convex hull of n page points (Andrew's monotone chain, 1979) into
 * hull (room for 2 n points while it is built); returns its count. */
static size_t convex_hull(double *pts, size_t n, double *hull)
{
    if (n < 3) {
        memcpy(hull, pts, 2 * n * sizeof *pts);
        return n;
    }
    qsort(pts, n, 2 * sizeof *pts, by_x);
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) { /* lower chain */
        while (k >= 2 && cross2(hull + 2 * (k - 2), hull + 2 * (k - 1), pts + 2 * i) <= 0.0) --k;
        memcpy(hull + 2 * k++, pts + 2 * i, 2 * sizeof *pts);
    }
    for (size_t i = n - 1, lower = k + 1; i-- > 0;) { /* upper chain */
        while (k >= lower && cross2(hull + 2 * (k - 2), hull + 2 * (k - 1), pts + 2 * i) <= 0.0) --k;
        memcpy(hull + 2 * k++, pts + 2 * i, 2 * sizeof *pts);
    }
    return k - 1;
}

/* The footprint of world points: their projections' hull, when larger than
 * SYMBOL_MIN on the page. */
static void footprint(cdl_plan_symbol *s, const cdl_plan_view *view, const cdl_vec3 *world, size_t n)
{
    double pts[2 * 2 * CDL_PLAN_OUTLINE_MAX], hull[2 * 4 * CDL_PLAN_OUTLINE_MAX];
    if (n > 2 * CDL_PLAN_OUTLINE_MAX) n = 2 * CDL_PLAN_OUTLINE_MAX;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < n; ++k) {
        view->project(view->user, world[k], &pts[2 * k], &pts[2 * k + 1]);
        for (int c = 0; c < 2; ++c) {
            lo[c] = fmin(lo[c], pts[2 * k + c]);
            hi[c] = fmax(hi[c], pts[2 * k + c]);
        }
    }
    if (n == 0 || (hi[0] - lo[0] < SYMBOL_MIN && hi[1] - lo[1] < SYMBOL_MIN)) return;
    size_t h = convex_hull(pts, n, hull);
    if (h > CDL_PLAN_OUTLINE_MAX) h = CDL_PLAN_OUTLINE_MAX;
    memcpy(s->outline, hull, 2 * h * sizeof *hull);
    s->outline_count = h;
    s->box = (cdl_label_box){lo[0], lo[1], hi[0], hi[1]};
}

/* The luminaire's axis: a spot's direction, a goniometric luminaire's nadir. */
static int axis_of(const cdl_luminaire_spec *l, cdl_vec3 *axis, cdl_vec3 col[3])
{
    if (l->kind == CDL_LUMINAIRE_SPOT) {
        *axis = cdl_vec3_normalize(l->direction);
        return 1;
    }
    if (l->kind != CDL_LUMINAIRE_GONIOMETRIC) return 0;
    *axis = cdl_vec3_neg(col[2]);
    return 1;
}

/* Where the aiming line ends: the aim point, or the axis meeting the plane. */
static void aiming_line(cdl_plan_symbol *s, const cdl_plan_view *view, const cdl_luminaire_spec *l, cdl_vec3 axis)
{
    cdl_vec3 end = l->aim;
    if (!l->has_aim) {
        double across = cdl_vec3_dot(axis, view->plane_normal);
        double t = cdl_vec3_dot(cdl_vec3_sub(view->plane_point, l->position), view->plane_normal) / across;
        if (!(fabs(across) > 1e-9) || !(t > 0.0) || !isfinite(t)) return;
        end = cdl_vec3_madd(l->position, t, axis);
    }
    double x, y;
    view->project(view->user, end, &x, &y);
    if (hypot(x - s->x, y - s->y) < AIM_MIN) return;
    s->aimed = 1;
    s->aim_x = x;
    s->aim_y = y;
}

static void make_symbol(cdl_plan_symbol *s, const cdl_report_input *in, const cdl_plan_view *view,
                        const cdl_luminaire_spec *l)
{
    cdl_vec3 world[2 * CDL_PLAN_OUTLINE_MAX], col[3];
    memset(s, 0, sizeof *s);
    cdl_emitter_rotation_columns(l->rotation_deg, col);
    size_t n = 0;
    if (l->kind == CDL_LUMINAIRE_AREA) {
        s->area = 1;
        n = shape_points(&l->shape, world, 2 * CDL_PLAN_OUTLINE_MAX);
        cdl_vec3 c = cdl_vec3_make(0.0, 0.0, 0.0);
        for (size_t k = 0; k < n; ++k) c = cdl_vec3_add(c, world[k]);
        view->project(view->user, n ? cdl_vec3_scale(c, 1.0 / (double)n) : c, &s->x, &s->y);
    } else {
        view->project(view->user, l->position, &s->x, &s->y);
        const cdl_report_luminaire_type *t = cdl_report_type_of(in, l);
        if (l->kind == CDL_LUMINAIRE_GONIOMETRIC && t && t->photometry) {
            n = opening_points(cdl_photometry_opening(t->photometry), world);
            for (size_t k = 0; k < n; ++k) {
                cdl_vec3 p = world[k];
                world[k] = cdl_vec3_add(l->position, cdl_vec3_add(cdl_vec3_scale(col[0], p.x),
                                                                  cdl_vec3_add(cdl_vec3_scale(col[1], p.y),
                                                                               cdl_vec3_scale(col[2], p.z))));
            }
        }
        cdl_vec3 axis;
        if (axis_of(l, &axis, col)) aiming_line(s, view, l, axis);
    }
    s->box = (cdl_label_box){s->x - SYMBOL_RADIUS, s->y - SYMBOL_RADIUS, s->x + SYMBOL_RADIUS, s->y + SYMBOL_RADIUS};
    footprint(s, view, world, n);
}

cdl_status cdl_plan_symbols_make(const cdl_report_input *in, const cdl_plan_view *view, cdl_plan_symbol **out,
                                 size_t *count, cdl_error *err)
{
    const cdl_scene *scene = in->scene;
    *out = NULL;
    *count = 0;
    cdl_plan_symbol *symbols = malloc((scene->luminaire_count + 1) * sizeof *symbols);
    if (!symbols) return cdl_error_out_of_memory(err);
    size_t n = 0;
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        const cdl_luminaire_spec *l = &scene->luminaires[k];
        if (l->kind == CDL_LUMINAIRE_DIRECTIONAL || l->kind == CDL_LUMINAIRE_ENVIRONMENT) continue;
        make_symbol(&symbols[n++], in, view, l);
    }
    /* masts: luminaires (not area) at one plan position, within a point */
    for (size_t a = 0; a < n; ++a)
        for (size_t b = a + 1; b < n; ++b)
            if (!symbols[a].area && !symbols[b].area && fabs(symbols[a].x - symbols[b].x) < 1.0 &&
                fabs(symbols[a].y - symbols[b].y) < 1.0)
                symbols[a].mast = symbols[b].mast = 1;
    *out = symbols;
    *count = n;
    return CDL_OK;
}

void cdl_plan_symbols_draw(cairo_t *cr, const cdl_plan_symbol *symbols, size_t count)
{
    cairo_save(cr);
    const double dash[2] = {3.0, 2.0};
    /* aiming lines first, under the symbols: a line and a small ring at its end */
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 0.7);
    for (size_t k = 0; k < count; ++k) {
        const cdl_plan_symbol *s = &symbols[k];
        if (!s->aimed) continue;
        cairo_move_to(cr, s->x, s->y);
        cairo_line_to(cr, s->aim_x, s->aim_y);
        cairo_new_sub_path(cr);
        cairo_arc(cr, s->aim_x, s->aim_y, 1.8, 0.0, 2.0 * CDL_PI);
    }
    cairo_stroke(cr);
    for (size_t k = 0; k < count; ++k) {
        const cdl_plan_symbol *s = &symbols[k];
        if (s->outline_count > 0) {
            for (size_t i = 0; i < s->outline_count; ++i)
                (i ? cairo_line_to : cairo_move_to)(cr, s->outline[2 * i], s->outline[2 * i + 1]);
            cairo_close_path(cr);
            cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, s->area ? 0.0 : 0.9);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
            cairo_set_line_width(cr, s->area ? 1.0 : 0.8);
            cairo_set_dash(cr, s->area ? dash : NULL, s->area ? 2 : 0, 0.0);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0.0);
        } else if (!s->mast) {
            cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
            cairo_new_sub_path(cr);
            cairo_arc(cr, s->x, s->y, SYMBOL_RADIUS, 0.0, 2.0 * CDL_PI);
            cairo_fill(cr);
            cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
            cairo_set_line_width(cr, 1.0);
            cairo_new_sub_path(cr);
            cairo_arc(cr, s->x, s->y, SYMBOL_RADIUS, 0.0, 2.0 * CDL_PI);
            cairo_move_to(cr, s->x - SYMBOL_RADIUS, s->y);
            cairo_line_to(cr, s->x + SYMBOL_RADIUS, s->y);
            cairo_move_to(cr, s->x, s->y - SYMBOL_RADIUS);
            cairo_line_to(cr, s->x, s->y + SYMBOL_RADIUS);
            cairo_stroke(cr);
        }
    }
    /* masts over the luminaires they carry */
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    for (size_t k = 0; k < count; ++k)
        if (symbols[k].mast)
            cairo_rectangle(cr, symbols[k].x - MAST_HALF, symbols[k].y - MAST_HALF, 2.0 * MAST_HALF, 2.0 * MAST_HALF);
    cairo_fill(cr);
    cairo_restore(cr);
}
