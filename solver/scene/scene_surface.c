/* scene_surface.c - the scene file's surfaces and area-luminaire shapes.
 *
 * Keys by type (DESIGN.md, "Scene file"):
 *   all surfaces  type, name, reflectance (required; a number in [0, 1], for
 *                 box also per face), two_sided (default true),
 *                 luminance_cd_m2 (>= 0, default 0), requirements (as
 *                 grids': Em_lx and U0, for the surface's map)
 *   rect          origin, u, v            (u, v non-zero, not parallel)
 *   polygon       vertices, holes         (planar, simple, holes inside)
 *   box           min, max, inward (default false), open (list of faces)
 *   disk          center, normal, radius
 *   sphere        center, radius, inward (default false)
 *   mesh          file (OBJ, OFF, PLY) or vertices + triangles
 * An area luminaire's shape takes the geometric keys only (rect, disk,
 * polygon, mesh); its material keys belong to the luminaire.
 */
#include "radiometry/glass.h"
#include "solver/scene/scene_parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "solver/scene/mesh_file.h"
#include "solver/geometry/polygon.h"

/* u and v closer to parallel than this sine of their angle span no area. */
#define PARALLEL_SINE 1e-9

static const char *const surface_types[] = {"rect", "polygon", "box", "disk", "sphere", "mesh", NULL};

/* Geometric keys per cdl_surface_kind, in the order of surface_types. */
static const char *const geometry_keys[][5] = {
    {"origin", "u", "v", NULL},
    {"vertices", "holes", NULL},
    {"min", "max", "inward", "open", NULL},
    {"center", "normal", "radius", NULL},
    {"center", "radius", "inward", NULL},
    {"file", "vertices", "triangles", NULL},
};
static const char *const material_keys[] = {"name",          "reflectance",  "two_sided", "luminance_cd_m2",
                                            "transmittance", "requirements", NULL};

/* "transmittance": a thin pane of glass (radiometry/glass.h). It transmits
 * and reflects nothing diffusely, emits nothing: no "reflectance" or
 * "luminance_cd_m2" with it. */
static cdl_status read_glass(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_surface_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    const cJSON *t = cdl_scene_json_member(node, "transmittance");
    if (!t) return CDL_OK;
    cdl_scene_json_path_key(p, path, "transmittance");
    double T = 0.0;
    if (cdl_scene_json_read_number(ctx, t, p, CDL_RANGE_ANY, 1, &T) != CDL_OK) return CDL_ERR_INPUT;
    cdl_glass glass;
    cdl_error e;
    if (cdl_glass_from_transmittance(T, &glass, &e) != CDL_OK)
        return cdl_error_set(ctx->err, CDL_ERR_INPUT, "%s: %s: %s", ctx->file, p, e.message);
    static const char *const not_glass[] = {"reflectance", "luminance_cd_m2", NULL};
    for (int k = 0; not_glass[k]; ++k)
        if (cdl_scene_json_member(node, not_glass[k])) {
            cdl_scene_json_path_key(p, path, not_glass[k]);
            return cdl_scene_json_failf(ctx, p,
                                        "no \"reflectance\" or \"luminance_cd_m2\" on glass (\"transmittance\": a "
                                        "pane that transmits; the light it reflects, specularly, is not modelled)",
                                        "\"%s\"", not_glass[k]);
        }
    out->transmittance = T;
    out->reflectance = 0.0;
    for (int f = 0; f < CDL_BOX_FACES; ++f) out->face_reflectance[f] = 0.0;
    return CDL_OK;
}

void cdl_scene_rings_free(cdl_ring3 *outer, cdl_ring3 *holes, size_t hole_count)
{
    if (outer) {
        free(outer->points);
        outer->points = NULL;
        outer->count = 0;
    }
    for (size_t h = 0; h < hole_count; ++h) free(holes[h].points);
    free(holes);
}

void cdl_scene_surface_spec_free(cdl_surface_spec *spec)
{
    free(spec->name);
    free(spec->map_name);
    spec->map_name = NULL;
    cdl_scene_rings_free(&spec->outer, spec->holes, spec->hole_count);
    free(spec->file);
    free(spec->mesh_vertices);
    free(spec->mesh_triangles);
    spec->name = spec->file = NULL;
    spec->holes = NULL;
    spec->hole_count = 0;
    spec->mesh_vertices = NULL;
    spec->mesh_triangles = NULL;
}

/* ---- polygons ---------------------------------------------------------------- */

static void ring_vertex_path(char *out, const char *path, long ring, size_t vertex)
{
    char base[CDL_SCENE_PATH_MAX];
    if (ring < 0) {
        cdl_scene_json_path_key(base, path, "vertices");
    } else {
        char holes[CDL_SCENE_PATH_MAX];
        cdl_scene_json_path_key(holes, path, "holes");
        cdl_scene_json_path_index(base, holes, (size_t)ring);
    }
    cdl_scene_json_path_index(out, base, vertex);
}

static cdl_status report_polygon(const cdl_scene_parse *ctx, const char *path, const cdl_polygon_problem *pr)
{
    char where[CDL_SCENE_PATH_MAX], other[CDL_SCENE_PATH_MAX];
    ring_vertex_path(where, path, pr->ring, pr->vertex);
    switch (pr->defect) {
    case CDL_POLYGON_VALID: break;
    case CDL_POLYGON_REPEATED_VERTEX:
        if (pr->distance == 0.0)
            return cdl_scene_json_failf(ctx, where, "a point different from the one before it", "the same point again");
        return cdl_scene_json_failf(ctx, where, "a point different from the one before it (farther than 1e-9 of the "
                                    "polygon's size)", "one %.3g m from it", pr->distance);
    case CDL_POLYGON_SPIKE:
        return cdl_scene_json_failf(ctx, where, "a vertex where the outline turns",
                                    "one that folds the outline back onto an edge (or makes a spike thinner than "
                                    "1e-9 of the polygon's size)");
    case CDL_POLYGON_NO_AREA:
        cdl_scene_json_path_key(where, path, "vertices");
        return cdl_scene_json_failf(ctx, where, "a polygon with an area", "points that all lie on one line");
    case CDL_POLYGON_NOT_PLANAR:
        return cdl_scene_json_failf(ctx, where, "a point in the plane of the polygon's outer ring",
                                    "one %.6g m away from that plane", pr->distance);
    case CDL_POLYGON_CROSSING:
        ring_vertex_path(other, path, pr->other_ring, pr->other_vertex);
        return cdl_scene_json_failf(ctx, where,
                                    "a simple polygon (no two edges cross, touch or come within 1e-9 of its size)",
                                    "the edge starting here meets the edge starting at %s", other);
    case CDL_POLYGON_HOLE_OUTSIDE: {
        char holes[CDL_SCENE_PATH_MAX];
        cdl_scene_json_path_key(holes, path, "holes");
        cdl_scene_json_path_index(where, holes, (size_t)pr->ring);
        return cdl_scene_json_failf(ctx, where, "a hole inside the outer ring", "one outside it");
    }
    case CDL_POLYGON_HOLE_IN_HOLE: {
        char holes[CDL_SCENE_PATH_MAX];
        cdl_scene_json_path_key(holes, path, "holes");
        cdl_scene_json_path_index(where, holes, (size_t)pr->ring);
        cdl_scene_json_path_index(other, holes, (size_t)pr->other_ring);
        return cdl_scene_json_failf(ctx, where, "holes that do not lie inside each other", "one inside %s", other);
    }
    }
    return CDL_OK;
}

cdl_status cdl_scene_json_read_polygon(const cdl_scene_parse *ctx, const cJSON *object, const char *path,
                                       cdl_ring3 *outer, cdl_ring3 **holes, size_t *hole_count)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_scene_json_path_key(p, path, "vertices");
    if (cdl_scene_json_read_ring(ctx, cdl_scene_json_member(object, "vertices"), p, outer) != CDL_OK)
        return CDL_ERR_INPUT;
    const cJSON *hs = cdl_scene_json_member(object, "holes");
    cdl_scene_json_path_key(p, path, "holes");
    if (hs) {
        if (cdl_scene_json_check_array(ctx, hs, p, "a list of holes (each a list of points)", 0) != CDL_OK)
            return CDL_ERR_INPUT;
        size_t n = (size_t)cJSON_GetArraySize(hs);
        *holes = calloc(n ? n : 1, sizeof **holes);
        if (!*holes) return cdl_error_out_of_memory(ctx->err);
        *hole_count = n;
        size_t i = 0;
        char hp[CDL_SCENE_PATH_MAX];
        for (const cJSON *h = hs->child; h; h = h->next, ++i) {
            cdl_scene_json_path_index(hp, p, i);
            if (cdl_scene_json_read_ring(ctx, h, hp, &(*holes)[i]) != CDL_OK) return CDL_ERR_INPUT;
        }
    }
    cdl_polygon_plane plane;
    cdl_polygon_problem problem;
    if (!cdl_polygon_check(outer, *holes, *hole_count, &plane, &problem))
        return report_polygon(ctx, path, &problem);
    return CDL_OK;
}

/* ---- boxes ---------------------------------------------------------------------- */

static const char *const face_names[CDL_BOX_FACES] = {"-x", "+x", "-y", "+y", "-z", "+z"};
static const char *const room_names[] = {"floor", "walls", "ceiling", NULL};

/* Faces named by a room name: floor = -z, ceiling = +z, walls = the four others. */
static int room_faces(int room, int *faces)
{
    if (room == 0) return faces[0] = CDL_BOX_NEG_Z, 1;
    if (room == 2) return faces[0] = CDL_BOX_POS_Z, 1;
    faces[0] = CDL_BOX_NEG_X;
    faces[1] = CDL_BOX_POS_X;
    faces[2] = CDL_BOX_NEG_Y;
    faces[3] = CDL_BOX_POS_Y;
    return 4;
}

/* Which naming a name belongs to: 1 faces (-x ...), 2 rooms (floor ...), 0 none;
 * *faces receives the faces it names. */
static int box_name(const char *name, int *faces, int *count)
{
    for (int i = 0; i < CDL_BOX_FACES; ++i)
        if (strcmp(name, face_names[i]) == 0) return faces[0] = i, *count = 1, 1;
    for (int i = 0; room_names[i]; ++i)
        if (strcmp(name, room_names[i]) == 0) return *count = room_faces(i, faces), 2;
    return 0;
}

static const char *naming_text(int naming)
{
    return naming == 1 ? "-x, +x, -y, +y, -z, +z" : "floor, walls, ceiling";
}

/* "open": the faces left out, by either naming or both (a set of faces:
 * ["-y"] is the window wall of a room whose reflectances are given as
 * floor, walls and ceiling). */
static cdl_status read_box_open(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                cdl_surface_spec *out)
{
    if (!node) return CDL_OK;
    const char *expected = "a list of face names (-x, +x, -y, +y, -z, +z, or floor, walls, ceiling)";
    if (cdl_scene_json_check_array(ctx, node, path, expected, 0) != CDL_OK) return CDL_ERR_INPUT;
    size_t i = 0;
    char item[CDL_SCENE_PATH_MAX];
    for (const cJSON *e = node->child; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, path, i);
        int faces[4], count = 0, which = cJSON_IsString(e) ? box_name(e->valuestring, faces, &count) : 0;
        if (!which) return cdl_scene_json_fail(ctx, item, "a face name (-x, +x, -y, +y, -z, +z, floor, walls, ceiling)", e);
        for (int k = 0; k < count; ++k) out->face_open[faces[k]] = 1;
    }
    int all_open = 1;
    for (int f = 0; f < CDL_BOX_FACES; ++f) all_open &= out->face_open[f];
    if (all_open) return cdl_scene_json_failf(ctx, path, "at least one face left closed", "all six faces open");
    return CDL_OK;
}

/* "reflectance": one number, or per face by one naming within the object
 * (floor, walls and ceiling, or -x ... +z: "walls" and "-y" together would
 * say the same face twice). Whatever "open" names, every named part with a
 * closed face needs its number. */
static cdl_status read_box_reflectance(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                       cdl_surface_spec *out)
{
    int naming = 0;
    if (!cJSON_IsObject(node)) {
        if (cdl_scene_json_read_number(ctx, node, path, CDL_RANGE_UNIT, 1, &out->reflectance) != CDL_OK) {
            /* Say that an object is allowed too. */
            return cdl_scene_json_fail(ctx, path,
                                       "a number in [0, 1] or an object of per-face numbers (floor, walls, ceiling or "
                                       "-x, +x, -y, +y, -z, +z)",
                                       node);
        }
        for (int f = 0; f < CDL_BOX_FACES; ++f) out->face_reflectance[f] = out->reflectance;
        return CDL_OK;
    }
    char item[CDL_SCENE_PATH_MAX];
    for (const cJSON *e = node->child; e; e = e->next) {
        cdl_scene_json_path_key(item, path, e->string ? e->string : "");
        int faces[4], count = 0, which = box_name(e->string ? e->string : "", faces, &count);
        if (!which) return cdl_scene_json_failf(ctx, item, "a face name (-x, +x, -y, +y, -z, +z, or floor, walls, ceiling)", "an unknown key");
        if (naming && which != naming) {
            char exp[96];
            snprintf(exp, sizeof exp, "one naming per box (%s)", naming_text(naming));
            return cdl_scene_json_failf(ctx, item, exp, "the key \"%s\"", e->string);
        }
        naming = which;
        for (const cJSON *d = node->child; d != e; d = d->next)
            if (strcmp(d->string, e->string) == 0)
                return cdl_scene_json_failf(ctx, item, "each key once", "\"%s\" a second time", e->string);
        double rho = 0.0;
        if (cdl_scene_json_read_number(ctx, e, item, CDL_RANGE_UNIT, 1, &rho) != CDL_OK) return CDL_ERR_INPUT;
        for (int k = 0; k < count; ++k) out->face_reflectance[faces[k]] = rho;
    }
    if (!naming) naming = 2;
    /* Every name whose faces are not all open must be given. */
    int count = naming == 1 ? CDL_BOX_FACES : 3;
    for (int i = 0; i < count; ++i) {
        const char *name = naming == 1 ? face_names[i] : room_names[i];
        int faces[4], n = 0, closed = 0;
        box_name(name, faces, &n);
        for (int k = 0; k < n; ++k) closed |= !out->face_open[faces[k]];
        if (closed && !cdl_scene_json_member(node, name)) {
            cdl_scene_json_path_key(item, path, name);
            return cdl_scene_json_fail(ctx, item, "a number in [0, 1]", NULL);
        }
    }
    return CDL_OK;
}

/* ---- meshes ----------------------------------------------------------------------- */

static cdl_status read_inline_mesh(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                   cdl_surface_spec *out)
{
    char p[CDL_SCENE_PATH_MAX], item[CDL_SCENE_PATH_MAX];
    const cJSON *vs = cdl_scene_json_member(node, "vertices"), *ts = cdl_scene_json_member(node, "triangles");
    cdl_scene_json_path_key(p, path, "vertices");
    if (cdl_scene_json_check_array(ctx, vs, p, "a list of at least 3 points [x, y, z]", 3) != CDL_OK)
        return CDL_ERR_INPUT;
    size_t nv = (size_t)cJSON_GetArraySize(vs);
    out->mesh_vertices = malloc(nv * 3 * sizeof(double));
    if (!out->mesh_vertices) return cdl_error_out_of_memory(ctx->err);
    size_t i = 0;
    for (const cJSON *e = vs->child; e; e = e->next, ++i) {
        cdl_vec3 v;
        cdl_scene_json_path_index(item, p, i);
        if (cdl_scene_json_read_vec3(ctx, e, item, 0, 1, &v) != CDL_OK) return CDL_ERR_INPUT;
        out->mesh_vertices[3 * i] = v.x;
        out->mesh_vertices[3 * i + 1] = v.y;
        out->mesh_vertices[3 * i + 2] = v.z;
    }
    out->mesh_vertex_count = nv;
    cdl_scene_json_path_key(p, path, "triangles");
    if (cdl_scene_json_check_array(ctx, ts, p, "a list of at least 1 triangle [i, j, k]", 1) != CDL_OK)
        return CDL_ERR_INPUT;
    size_t nt = (size_t)cJSON_GetArraySize(ts);
    out->mesh_triangles = malloc(nt * 3 * sizeof(uint32_t));
    if (!out->mesh_triangles) return cdl_error_out_of_memory(ctx->err);
    i = 0;
    for (const cJSON *t = ts->child; t; t = t->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        if (!cJSON_IsArray(t) || cJSON_GetArraySize(t) != 3)
            return cdl_scene_json_fail(ctx, item, "a triangle [i, j, k] of 3 vertex indices", t);
        int k = 0;
        for (const cJSON *e = t->child; e; e = e->next, ++k) {
            char ip[CDL_SCENE_PATH_MAX];
            double idx = 0;
            cdl_scene_json_path_index(ip, item, (size_t)k);
            if (cdl_scene_json_read_integer(ctx, e, ip, 0, (double)nv - 1, 1, &idx) != CDL_OK) return CDL_ERR_INPUT;
            out->mesh_triangles[3 * i + (size_t)k] = (uint32_t)idx;
        }
        const uint32_t *tri = &out->mesh_triangles[3 * i];
        const double *a = &out->mesh_vertices[3 * tri[0]], *b = &out->mesh_vertices[3 * tri[1]],
                     *c = &out->mesh_vertices[3 * tri[2]];
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
                                    cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2]));
        if (!(cdl_vec3_length(n) > 0.0))
            return cdl_scene_json_failf(ctx, item, "a triangle with an area", "three points on one line");
    }
    out->mesh_triangle_count = nt;
    return CDL_OK;
}

static cdl_status read_mesh(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_surface_spec *out)
{
    const cJSON *file = cdl_scene_json_member(node, "file");
    int has_inline = cdl_scene_json_member(node, "vertices") || cdl_scene_json_member(node, "triangles");
    char p[CDL_SCENE_PATH_MAX];
    if (file && has_inline) {
        cdl_scene_json_path_key(p, path, "file");
        return cdl_scene_json_failf(ctx, p, "either a file or inline vertices and triangles",
                                    "both \"file\" and inline data");
    }
    if (!file) {
        if (!has_inline)
            return cdl_scene_json_failf(ctx, path, "a mesh \"file\" or \"vertices\" and \"triangles\"", "neither");
        return read_inline_mesh(ctx, node, path, out);
    }
    cdl_scene_json_path_key(p, path, "file");
    if (cdl_scene_json_read_path(ctx, file, p, 1, &out->file) != CDL_OK) return CDL_ERR_INPUT;
    cdl_mesh_data mesh;
    if (cdl_mesh_file_read(out->file, &mesh, ctx->err) != CDL_OK)
        return cdl_error_prefix(ctx->err, "%s: %s: ", ctx->file, p);
    /* The same bound as coordinates written in the scene: beyond it areas
     * overflow and the ray scene's single precision loses the room. */
    for (size_t i = 0; i < 3 * mesh.vertex_count; ++i)
        if (fabs(mesh.vertices[i]) > CDL_SCENE_MAX_MAGNITUDE) {
            const double *v = &mesh.vertices[i - i % 3];
            cdl_status st = cdl_error_set(ctx->err, CDL_ERR_INPUT,
                                          "%s: %s: %s: vertex %zu (from 1, in file order): expected coordinates of "
                                          "magnitude at most %g m, found [%.10g, %.10g, %.10g]",
                                          ctx->file, p, out->file, i / 3 + 1, CDL_SCENE_MAX_MAGNITUDE, v[0], v[1], v[2]);
            cdl_mesh_data_release(&mesh);
            return st;
        }
    out->mesh_vertices = mesh.vertices;
    out->mesh_vertex_count = mesh.vertex_count;
    out->mesh_triangles = mesh.triangles;
    out->mesh_triangle_count = mesh.triangle_count;
    return CDL_OK;
}

/* ---- parallelograms ---------------------------------------------------------------- */

cdl_status cdl_scene_json_read_span(const cdl_scene_parse *ctx, const cJSON *object, const char *path,
                                    cdl_vec3 *origin, cdl_vec3 *u, cdl_vec3 *v)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_scene_json_path_key(p, path, "origin");
    if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_member(object, "origin"), p, 0, 1, origin) != CDL_OK)
        return CDL_ERR_INPUT;
    cdl_scene_json_path_key(p, path, "u");
    if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_member(object, "u"), p, 1, 1, u) != CDL_OK) return CDL_ERR_INPUT;
    cdl_scene_json_path_key(p, path, "v");
    if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_member(object, "v"), p, 1, 1, v) != CDL_OK) return CDL_ERR_INPUT;
    /* The angle from the unit vectors: |u| |v| and u x v of tiny vectors
     * underflow, which made perpendicular 1e-200 m spans "parallel". */
    double sine = cdl_vec3_length(cdl_vec3_cross(cdl_vec3_normalize(*u), cdl_vec3_normalize(*v)));
    if (!(sine > PARALLEL_SINE)) return cdl_scene_json_failf(ctx, p, "a vector not parallel to u", "one parallel to u");
    double area = cdl_vec3_length(cdl_vec3_cross(*u, *v));
    if (!(area > 0.0))
        return cdl_scene_json_failf(ctx, path, "u and v spanning an area a double can hold (|u x v| > 0)",
                                    "|u| = %g m and |v| = %g m, whose area underflows to 0", cdl_vec3_length(*u),
                                    cdl_vec3_length(*v));
    return CDL_OK;
}

/* ---- one surface ---------------------------------------------------------------- */

static cdl_status read_geometry(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                cdl_surface_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    switch (out->kind) {
    case CDL_SURFACE_RECT:
        return cdl_scene_json_read_span(ctx, node, path, &out->origin, &out->u, &out->v);
    case CDL_SURFACE_POLYGON:
        return cdl_scene_json_read_polygon(ctx, node, path, &out->outer, &out->holes, &out->hole_count);
    case CDL_SURFACE_BOX: {
        if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_field(node, path, "min", p), p, 0, 1, &out->box_min) ||
            cdl_scene_json_read_vec3(ctx, cdl_scene_json_field(node, path, "max", p), p, 0, 1, &out->box_max) ||
            cdl_scene_json_read_bool(ctx, cdl_scene_json_field(node, path, "inward", p), p, 0, &out->inward))
            return CDL_ERR_INPUT;
        if (!(out->box_max.x > out->box_min.x && out->box_max.y > out->box_min.y && out->box_max.z > out->box_min.z))
            return cdl_scene_json_failf(ctx, (cdl_scene_json_path_key(p, path, "max"), p), "every coordinate greater than min's",
                                        "[%.10g, %.10g, %.10g] against min [%.10g, %.10g, %.10g]", out->box_max.x,
                                        out->box_max.y, out->box_max.z, out->box_min.x, out->box_min.y, out->box_min.z);
        return read_box_open(ctx, cdl_scene_json_field(node, path, "open", p), p, out);
    }
    case CDL_SURFACE_DISK:
        if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_field(node, path, "normal", p), p, 1, 1, &out->normal))
            return CDL_ERR_INPUT;
        out->normal = cdl_vec3_normalize(out->normal);
        /* fall through - center and radius are read as for spheres */
    case CDL_SURFACE_SPHERE:
        if (cdl_scene_json_read_vec3(ctx, cdl_scene_json_field(node, path, "center", p), p, 0, 1, &out->center) ||
            cdl_scene_json_read_number(ctx, cdl_scene_json_field(node, path, "radius", p), p, CDL_RANGE_POSITIVE, 1, &out->radius))
            return CDL_ERR_INPUT;
        if (out->kind == CDL_SURFACE_SPHERE &&
            cdl_scene_json_read_bool(ctx, cdl_scene_json_field(node, path, "inward", p), p, 0, &out->inward))
            return CDL_ERR_INPUT;
        return CDL_OK;
    case CDL_SURFACE_MESH:
        return read_mesh(ctx, node, path, out);
    }
    return CDL_OK;
}

cdl_status cdl_scene_json_read_surface(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                       cdl_scene_shape_use use, cdl_surface_spec *out)
{
    cdl_scene_json_copy_path(out->json_path, path);
    out->two_sided = 1;
    char p[CDL_SCENE_PATH_MAX];
    const char *what = use == CDL_SHAPE_USE_SURFACE ? "a surface" : "an area luminaire's shape";
    if (!cJSON_IsObject(node)) {
        char exp[64];
        snprintf(exp, sizeof exp, "%s (a JSON object)", what);
        return cdl_scene_json_fail(ctx, path, exp, node);
    }
    int kind = 0;
    cdl_scene_json_path_key(p, path, "type");
    const char *const shape_types[] = {"rect", "polygon", "disk", "mesh", NULL};
    const cdl_surface_kind shape_kinds[] = {CDL_SURFACE_RECT, CDL_SURFACE_POLYGON, CDL_SURFACE_DISK, CDL_SURFACE_MESH};
    if (use == CDL_SHAPE_USE_SURFACE) {
        if (cdl_scene_json_read_choice(ctx, cdl_scene_json_member(node, "type"), p, surface_types, 1, &kind) != CDL_OK)
            return CDL_ERR_INPUT;
        out->kind = (cdl_surface_kind)kind;
    } else {
        if (cdl_scene_json_read_choice(ctx, cdl_scene_json_member(node, "type"), p, shape_types, 1, &kind) != CDL_OK)
            return CDL_ERR_INPUT;
        out->kind = shape_kinds[kind];
        /* Material keys belong to the luminaire: say so rather than "unknown key". */
        for (size_t i = 0; material_keys[i]; ++i)
            if (cdl_scene_json_member(node, material_keys[i])) {
                cdl_scene_json_path_key(p, path, material_keys[i]);
                return cdl_scene_json_failf(ctx, p, "only geometric keys in a shape (put it on the luminaire)",
                                            "\"%s\"", material_keys[i]);
            }
    }

    const char *allowed[16];
    size_t n = 0;
    allowed[n++] = "type";
    for (size_t i = 0; geometry_keys[out->kind][i]; ++i) allowed[n++] = geometry_keys[out->kind][i];
    if (use == CDL_SHAPE_USE_SURFACE)
        for (size_t i = 0; material_keys[i]; ++i) allowed[n++] = material_keys[i];
    allowed[n] = NULL;
    char what_kind[64];
    if (use == CDL_SHAPE_USE_SURFACE) snprintf(what_kind, sizeof what_kind, "a %s surface", surface_types[out->kind]);
    else snprintf(what_kind, sizeof what_kind, "a %s shape", surface_types[out->kind]);
    if (cdl_scene_json_check_object(ctx, node, path, what_kind, allowed) != CDL_OK) return CDL_ERR_INPUT;

    if (read_geometry(ctx, node, path, out) != CDL_OK) return CDL_ERR_INPUT;
    if (use == CDL_SHAPE_USE_LUMINAIRE) return CDL_OK;

    cdl_scene_json_path_key(p, path, "name");
    if (cdl_scene_json_read_string(ctx, cdl_scene_json_member(node, "name"), p, 0, &out->name) != CDL_OK)
        return CDL_ERR_INPUT;
    if (read_glass(ctx, node, path, out) != CDL_OK) return CDL_ERR_INPUT;
    if (out->transmittance > 0.0) return CDL_OK;
    cdl_scene_json_path_key(p, path, "reflectance");
    const cJSON *rho = cdl_scene_json_member(node, "reflectance");
    if (out->kind == CDL_SURFACE_BOX) {
        if (read_box_reflectance(ctx, rho, p, out) != CDL_OK) return CDL_ERR_INPUT;
    } else if (cdl_scene_json_read_number(ctx, rho, p, CDL_RANGE_UNIT, 1, &out->reflectance) != CDL_OK) {
        return CDL_ERR_INPUT;
    }
    cdl_scene_json_path_key(p, path, "two_sided");
    if (cdl_scene_json_read_bool(ctx, cdl_scene_json_member(node, "two_sided"), p, 0, &out->two_sided) != CDL_OK)
        return CDL_ERR_INPUT;
    cdl_scene_json_path_key(p, path, "requirements");
    if (cdl_scene_json_read_requirements(ctx, cdl_scene_json_member(node, "requirements"), p, &out->required_Em_lx,
                                         &out->required_U0) != CDL_OK)
        return CDL_ERR_INPUT;
    cdl_scene_json_path_key(p, path, "luminance_cd_m2");
    return cdl_scene_json_read_quantity(ctx, cdl_scene_json_member(node, "luminance_cd_m2"), p, CDL_DIM_LUMINANCE,
                                        CDL_RANGE_NONNEGATIVE, 0, &out->luminance_cd_m2);
}

size_t cdl_scene_surface_key_sets(cdl_scene_keys *keys, size_t first)
{
    /* "type", the kind's geometric keys, and for surfaces the material
     * keys: what cdl_scene_json_read_surface allows. */
    static const int shape_ok[6] = {1, 1, 0, 1, 0, 1}; /* rect, polygon, disk, mesh */
    size_t n = first;
    for (int use = 0; use < 2; ++use)
        for (int kind = 0; surface_types[kind]; ++kind) {
            if (use == 1 && !shape_ok[kind]) continue;
            if (n >= CDL_SCENE_KEY_SETS_MAX) return n - first;
            const char **list = keys->lists[n];
            size_t k = 0;
            list[k++] = "type";
            for (size_t i = 0; geometry_keys[kind][i]; ++i) list[k++] = geometry_keys[kind][i];
            if (use == 0)
                for (size_t i = 0; material_keys[i]; ++i) list[k++] = material_keys[i];
            list[k] = NULL;
            snprintf(keys->names[n], sizeof keys->names[n], "%s %s", use ? "shape" : "surface", surface_types[kind]);
            keys->sets[n].object = keys->names[n];
            keys->sets[n].keys = list;
            ++n;
        }
    return n - first;
}
