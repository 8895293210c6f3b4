/* report_luminaires.c - every luminaire placed, the schedule of types and
 * their polar diagrams (report_sections.h). */
#include "report/report_sections.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/emitters/emitter_internal.h"
#include "lights/photometry/photometry_metadata.h"
#include "lights/photometry/photometry_polar.h"
#include "radiometry/constants.h"

/* Most rows of the luminaire list; a larger scene's list says how many more. */
#define LIST_ROWS_MAX 2000

const char *cdl_report_file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

void cdl_report_luminaire_label(const cdl_luminaire_spec *l, char *out, size_t size)
{
    const char *name = l->name ? l->name : l->json_path;
    if (l->copy_count > 1) snprintf(out, size, "%s, %zu of %zu", name, l->copy + 1, l->copy_count);
    else snprintf(out, size, "%s", name);
}

/* ---- where each luminaire is ------------------------------------------------------ */

/* (x, y) inside the ring's projection on the horizontal plane (crossing number). */
static int inside_plan(const cdl_ring3 *r, double x, double y)
{
    int in = 0;
    for (size_t i = 0, j = r->count - 1; i < r->count; j = i++) {
        cdl_vec3 a = r->points[i], b = r->points[j];
        if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

/* The height of a horizontal surface right below p (its plane's z), or NAN. */
static double horizontal_below(const cdl_surface_spec *s, cdl_vec3 p)
{
    const double flat = 1.0 - 1e-9;
    switch (s->kind) {
    case CDL_SURFACE_BOX:
        return p.x >= s->box_min.x && p.x <= s->box_max.x && p.y >= s->box_min.y && p.y <= s->box_max.y &&
                       s->box_min.z <= p.z
                   ? s->box_min.z
                   : NAN;
    case CDL_SURFACE_RECT: {
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_cross(s->u, s->v));
        if (fabs(n.z) < flat || s->origin.z > p.z) return NAN;
        /* p - origin = a u + b v in plan, 0 <= a, b <= 1 */
        double det = s->u.x * s->v.y - s->u.y * s->v.x, dx = p.x - s->origin.x, dy = p.y - s->origin.y;
        double a = (dx * s->v.y - dy * s->v.x) / det, b = (s->u.x * dy - s->u.y * dx) / det;
        return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0 ? s->origin.z : NAN;
    }
    case CDL_SURFACE_POLYGON: {
        double z = s->outer.points[0].z;
        for (size_t k = 0; k < s->outer.count; ++k)
            if (fabs(s->outer.points[k].z - z) > 1e-9 * (1.0 + fabs(z))) return NAN;
        if (z > p.z || !inside_plan(&s->outer, p.x, p.y)) return NAN;
        for (size_t h = 0; h < s->hole_count; ++h)
            if (inside_plan(&s->holes[h], p.x, p.y)) return NAN;
        return z;
    }
    case CDL_SURFACE_DISK: {
        cdl_vec3 n = cdl_vec3_normalize(s->normal);
        double dx = p.x - s->center.x, dy = p.y - s->center.y;
        return fabs(n.z) >= flat && s->center.z <= p.z && dx * dx + dy * dy <= s->radius * s->radius ? s->center.z
                                                                                                        : NAN;
    }
    default: return NAN;
    }
}

/* The floor under p: the lowest horizontal surface below it, or NAN. */
static double floor_below(const cdl_scene *scene, cdl_vec3 p)
{
    double z = NAN;
    for (size_t k = 0; k < scene->surface_count; ++k) {
        double h = horizontal_below(&scene->surfaces[k], p);
        if (!isnan(h) && (isnan(z) || h < z)) z = h;
    }
    return z;
}

/* Where a luminaire is: its position, or its shape's centre (area). */
static int luminaire_position(const cdl_luminaire_spec *l, cdl_vec3 *p)
{
    const cdl_surface_spec *s = &l->shape;
    switch (l->kind) {
    case CDL_LUMINAIRE_POINT:
    case CDL_LUMINAIRE_SPOT:
    case CDL_LUMINAIRE_GONIOMETRIC: *p = l->position; return 1;
    case CDL_LUMINAIRE_AREA:
        if (s->kind == CDL_SURFACE_RECT) *p = cdl_vec3_madd(s->origin, 0.5, cdl_vec3_add(s->u, s->v));
        else if (s->kind == CDL_SURFACE_DISK) *p = s->center;
        else if (s->kind == CDL_SURFACE_POLYGON && s->outer.count > 0) {
            *p = cdl_vec3_make(0.0, 0.0, 0.0);
            for (size_t k = 0; k < s->outer.count; ++k) *p = cdl_vec3_add(*p, s->outer.points[k]);
            *p = cdl_vec3_scale(*p, 1.0 / (double)s->outer.count);
        } else if (s->kind == CDL_SURFACE_MESH && s->mesh_vertex_count > 0) {
            *p = cdl_vec3_make(0.0, 0.0, 0.0);
            for (size_t k = 0; k < s->mesh_vertex_count; ++k)
                *p = cdl_vec3_add(*p, cdl_vec3_make(s->mesh_vertices[3 * k], s->mesh_vertices[3 * k + 1],
                                                    s->mesh_vertices[3 * k + 2]));
            *p = cdl_vec3_scale(*p, 1.0 / (double)s->mesh_vertex_count);
        } else {
            return 0;
        }
        return 1;
    default: return 0;
    }
}

/* How it is turned: the aim point, the rotation, the direction. */
static void orientation(const cdl_luminaire_spec *l, char *out, size_t size)
{
    if (l->kind == CDL_LUMINAIRE_GONIOMETRIC) {
        cdl_vec3 col[3];
        cdl_emitter_rotation_columns(l->rotation_deg, col);
        /* the nadir, -z of the luminaire, turned: its angle from straight down */
        double tilt = acos(fmax(-1.0, fmin(1.0, col[2].z))) * CDL_RAD_TO_DEG;
        if (l->has_aim && l->spin_deg != 0.0)
            snprintf(out, size, "aim (%.4g, %.4g, %.4g), spin %.3g deg, tilt %.3g deg", l->aim.x, l->aim.y, l->aim.z,
                     l->spin_deg, tilt);
        else if (l->has_aim)
            snprintf(out, size, "aim (%.4g, %.4g, %.4g), tilt %.3g deg", l->aim.x, l->aim.y, l->aim.z, tilt);
        else if (l->rotation_deg[0] == 0.0 && l->rotation_deg[1] == 0.0 && l->rotation_deg[2] == 0.0)
            snprintf(out, size, "nadir down, C0 along +x");
        else
            snprintf(out, size, "rotation (%.4g, %.4g, %.4g) deg, tilt %.3g deg", l->rotation_deg[0],
                     l->rotation_deg[1], l->rotation_deg[2], tilt);
        return;
    }
    if (l->kind == CDL_LUMINAIRE_SPOT && l->has_aim) {
        snprintf(out, size, "aim (%.4g, %.4g, %.4g)", l->aim.x, l->aim.y, l->aim.z);
    } else if (l->kind == CDL_LUMINAIRE_SPOT || l->kind == CDL_LUMINAIRE_DIRECTIONAL) {
        snprintf(out, size, "direction (%.3g, %.3g, %.3g)", l->direction.x, l->direction.y, l->direction.z);
    } else if (l->kind == CDL_LUMINAIRE_AREA) {
        cdl_vec3 n = l->shape.kind == CDL_SURFACE_DISK ? cdl_vec3_normalize(l->shape.normal)
                                                       : cdl_vec3_normalize(cdl_vec3_cross(l->shape.u, l->shape.v));
        if (l->shape.kind == CDL_SURFACE_RECT || l->shape.kind == CDL_SURFACE_DISK)
            snprintf(out, size, "emits towards (%.3g, %.3g, %.3g)", n.x, n.y, n.z);
        else
            snprintf(out, size, "-");
    } else {
        snprintf(out, size, "-");
    }
}

/* What it is: the file's product name and catalogue number, or its kind. */
static void product(const cdl_report_input *in, const cdl_luminaire_spec *l, char *name, char *catalogue,
                    size_t size)
{
    static const char *const kinds[] = {"point source", "spot",        "goniometric",
                                        "area emitter", "directional", "sky or environment"};
    snprintf(name, size, "%s", (unsigned)l->kind < 6 ? kinds[l->kind] : "?");
    snprintf(catalogue, size, "-");
    const cdl_report_luminaire_type *t = cdl_report_type_of(in, l);
    if (!t || !t->photometry) return;
    const char *text = cdl_photometry_get_text(t->photometry, CDL_PHOTOMETRY_LUMINAIRE);
    const char *number = cdl_photometry_get_text(t->photometry, CDL_PHOTOMETRY_CATALOGUE);
    if (text && text[0]) snprintf(name, size, "%.*s", (int)strcspn(text, "\r\n"), text);
    else snprintf(name, size, "%s", cdl_report_file_name(l->file));
    if (number && number[0]) snprintf(catalogue, size, "%.*s", (int)strcspn(number, "\r\n"), number);
}

static void list_row(cdl_report_builder *b, cdl_report_block *t, size_t r, const cdl_report_input *in,
                     const cdl_luminaire_spec *l)
{
    char text[256], catalogue[160];
    cdl_report_luminaire_label(l, text, sizeof text);
    cdl_report_cell(b, t, r, 0, "%s", text);
    product(in, l, text, catalogue, 160);
    cdl_report_cell(b, t, r, 1, "%s", text);
    cdl_report_cell(b, t, r, 2, "%s", catalogue);
    for (size_t c = 3; c < 7; ++c) cdl_report_cell(b, t, r, c, "-");
    cdl_vec3 p;
    if (luminaire_position(l, &p)) {
        cdl_report_cell(b, t, r, 3, "%.3f", p.x);
        cdl_report_cell(b, t, r, 4, "%.3f", p.y);
        cdl_report_cell(b, t, r, 5, "%.3f", p.z);
        double floor = floor_below(in->scene, p);
        if (!isnan(floor)) cdl_report_cell(b, t, r, 6, "%.3f", p.z - floor);
    }
    orientation(l, text, sizeof text);
    cdl_report_cell(b, t, r, 7, "%s", text);
    cdl_report_cell(b, t, r, 8, "%.3g", l->maintenance_factor);
}

static void luminaire_list(cdl_report_builder *b, const cdl_report_input *in)
{
    const cdl_scene *scene = in->scene;
    cdl_report_text(b, CDL_BLOCK_HEADING, 3, "Luminaire list");
    if (scene->luminaire_count == 0) {
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "The scene places no luminaire.");
        return;
    }
    size_t rows = scene->luminaire_count < LIST_ROWS_MAX ? scene->luminaire_count : LIST_ROWS_MAX;
    cdl_report_block *t = cdl_report_table(b, 9, rows + 1, 1);
    static const char *const headings[9] = {"luminaire", "product", "catalogue no.",   "x (m)", "y (m)",
                                            "z (m)",     "height (m)", "rotation or aim", "MF"};
    for (size_t c = 0; c < 9; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    for (size_t k = 0; k < rows; ++k) list_row(b, t, k + 1, in, &scene->luminaires[k]);
    if (rows < scene->luminaire_count)
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "And %zu more luminaires (the scene places %zu).",
                        scene->luminaire_count - rows, scene->luminaire_count);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Every luminaire the scene places, in its order (copies of an array or a list of positions as "
                    "\"k of n\"). Product and catalogue number are the photometric file's ([LUMINAIRE] and "
                    "[LUMCAT], or EULUMDAT's lines 9 and 10). The position is the photometric centre (an area "
                    "emitter's centre); the height is above the floor: the lowest horizontal surface under it. "
                    "Tilt is the angle of the luminaire's nadir from straight down. MF: the maintenance factor, "
                    "which multiplies the luminaire's output in every result.");
}

/* ---- the schedule of types ---------------------------------------------------------- */

static const char *kind_name(cdl_luminaire_kind k)
{
    static const char *const names[] = {"point", "spot", "goniometric", "area", "directional", "environment"};
    return (unsigned)k < 6 ? names[k] : "?";
}

/* A keyword's text up to its first line end, or "" (file text of any encoding). */
static void first_line(char *out, size_t size, const char *s)
{
    snprintf(out, size, "%.*s", s ? (int)strcspn(s, "\r\n") : 0, s ? s : "");
}

static void schedule_row(cdl_report_builder *b, cdl_report_block *t, size_t r, const cdl_report_luminaire_type *type)
{
    const cdl_luminaire_spec *l = type->first;
    char mf[48];
    if (type->maintenance_min == type->maintenance_max) snprintf(mf, sizeof mf, "%.3g", type->maintenance_min);
    else snprintf(mf, sizeof mf, "%.3g to %.3g", type->maintenance_min, type->maintenance_max);
    if (!type->photometry) {
        cdl_report_cell(b, t, r, 0, "%s %s%s%s", l->json_path, kind_name(l->kind), l->name ? ": " : "",
                        l->name ? l->name : "");
        for (int c = 1; c < 8; ++c) cdl_report_cell(b, t, r, (size_t)c, "-");
        if (l->kind == CDL_LUMINAIRE_POINT || l->kind == CDL_LUMINAIRE_SPOT || l->kind == CDL_LUMINAIRE_AREA) {
            if (l->has_flux) cdl_report_cell(b, t, r, 4, "%.4g lm", l->flux_lm);
            else if (l->has_intensity) cdl_report_cell(b, t, r, 4, "%.4g cd", l->intensity_cd);
            else if (l->has_luminance) cdl_report_cell(b, t, r, 4, "%.4g cd/m2", l->luminance_cd_m2);
        }
        cdl_report_cell(b, t, r, 8, "%s", mf);
        cdl_report_cell(b, t, r, 9, "%zu", type->count);
        return;
    }
    const cdl_photometry *p = type->photometry;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    char maker[160], catalogue[160], lamp[160];
    first_line(maker, sizeof maker, cdl_photometry_get_text(p, CDL_PHOTOMETRY_MANUFACTURER));
    first_line(catalogue, sizeof catalogue, cdl_photometry_get_text(p, CDL_PHOTOMETRY_CATALOGUE));
    first_line(lamp, sizeof lamp, cdl_photometry_get_text(p, CDL_PHOTOMETRY_LAMP));
    cdl_report_cell(b, t, r, 0, "%s", cdl_report_file_name(l->file));
    cdl_report_cell(b, t, r, 1, "%s", maker[0] ? maker : "-");
    cdl_report_cell(b, t, r, 2, "%s", catalogue[0] ? catalogue : "-");
    cdl_report_cell(b, t, r, 3, "%s", lamp[0] ? lamp : "-");
    /* the luminaire's flux as the solve used it: the table times its ballast (output) factor */
    if (s.radiometric) cdl_report_cell(b, t, r, 4, "%.4g W (radiant)", s.radiant_flux.W * s.output_factor);
    else cdl_report_cell(b, t, r, 4, "%.4g lm", s.luminaire_flux.lm);
    if (m->input_watts > 0.0) cdl_report_cell(b, t, r, 5, "%.4g W", m->input_watts);
    else cdl_report_cell(b, t, r, 5, "-");
    if (s.efficacy_known) cdl_report_cell(b, t, r, 6, "%.4g lm/W", s.efficacy.lm_W);
    else cdl_report_cell(b, t, r, 6, "-");
    cdl_report_cell(b, t, r, 7, "%s", s.lamp_flux_known ? "relative" : "absolute");
    cdl_report_cell(b, t, r, 8, "%s", mf);
    cdl_report_cell(b, t, r, 9, "%zu", type->count);
}

static cdl_status schedule(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    cdl_report_document *d = b->doc;
    cdl_report_text(b, CDL_BLOCK_HEADING, 3, "Luminaire schedule");
    cdl_report_block *t = cdl_report_table(b, 10, in->type_count + 1, 1);
    static const char *const headings[10] = {"luminaire", "manufacturer", "catalogue",     "lamp",
                                             "flux",      "input power",  "efficacy",      "photometry",
                                             "maint. factor", "count"};
    for (size_t c = 0; c < 10; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    for (size_t k = 0; k < in->type_count; ++k) schedule_row(b, t, k + 1, &in->types[k]);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Flux is the exact integral of the file's interpolated table (before the maintenance factor and "
                    "any scene multiplier); input power and efficacy as the file states them. Polar diagrams: "
                    "C0-C180 solid, C90-C270 dashed (and, for an asymmetric luminaire, the plane through its peak), "
                    "in cd/klm (intensity per 1000 lm of the rated lamp flux, or of the luminaire's flux for "
                    "absolute photometry).");
    d->diagrams = calloc(in->type_count ? in->type_count : 1, sizeof *d->diagrams);
    if (!d->diagrams) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < in->type_count; ++k) {
        if (!in->types[k].photometry) continue;
        cdl_polar_diagram *pd = &d->diagrams[d->diagram_count++];
        pd->photometry = in->types[k].photometry;
        pd->title = cdl_report_file_name(in->types[k].first->file);
        cdl_report_figure(b, cdl_polar_diagram_figure(pd), 0.6); /* two to an A4 page */
    }
    return CDL_OK;
}

cdl_status cdl_report_luminaire_section(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Luminaires");
    luminaire_list(b, in);
    return schedule(b, in, err);
}
