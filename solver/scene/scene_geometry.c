/* scene_geometry.c - surfaces and area-luminaire shapes as ray-scene pieces.
 *
 * One piece per surface (per closed face for boxes), in the order of
 * scene->surfaces, then one per area luminaire in the order of
 * scene->luminaires, then one per luminaire body (scene_bodies.h) in the
 * same order; the piece index is its ray-scene geom id.
 *
 *   rect     2 triangles (o, o+u, o+u+v), (o, o+u+v, o+v): front = u x v
 *   box      one rect per closed face, corners shared bit for bit between
 *            faces (watertight); front outward, inward when "inward"
 *   polygon  CGAL constrained Delaunay triangulation of the rings' own
 *            vertices, counter-clockwise seen from the front
 *   disk     a fan of DISK_SEGMENTS triangles inscribed in the circle
 *   sphere   an exact Embree sphere
 *   mesh     the triangles as given
 *
 * Rays: the ray scene decides hits near a ray's ends in double
 * (ray_scene.c); this file only hands points through, with no epsilon of
 * the scene's size (scene_geometry.h, "Rays at every scale").
 */
#include "solver/scene/scene_geometry.h"

#include <float.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "solver/geometry/polygon.h"
#include "solver/scene/scene_bodies.h"

#define DISK_SEGMENTS CDL_DISK_SEGMENTS

/* The relative rounding bound of cdl_ray_offsets_epsilon. */
#define ROUNDING_RELATIVE 0x1p-40

typedef struct piece_data {
    cdl_geometry_piece piece;
    double *xyz;               /* vertex_count x 3 (NULL for spheres) */
    size_t vertex_count;
    uint32_t *triangles;       /* piece.triangle_count x 3 */
} piece_data;

struct cdl_scene_geometry {
    cdl_ray_scene *rays;
    piece_data *pieces;
    size_t piece_count, piece_capacity;
    size_t triangle_count;
    cdl_bounds3 bounds;
    double extent;
    int glass;                 /* 1: some piece is a pane of glass */
    uint32_t *luminaire_body;  /* per luminaire of the scene: its body piece, UINT32_MAX for none */
    cdl_luminaire_body *body_shape; /* per luminaire: its body as the file describes it */
    cdl_bounds3 surface_bounds; /* of every piece but the bodies */
};

/* ---- building ---------------------------------------------------------------- */

static double triangle_area(const double *xyz, const uint32_t *t)
{
    const double *a = &xyz[3 * t[0]], *b = &xyz[3 * t[1]], *c = &xyz[3 * t[2]];
    cdl_vec3 e1 = cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    cdl_vec3 e2 = cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    return 0.5 * cdl_vec3_length(cdl_vec3_cross(e1, e2));
}

/* Take ownership of xyz/triangles (freed here on failure), add them to the
 * ray scene and record the piece. tmpl carries the piece's material and
 * shape; area is computed from the triangles unless tmpl->area > 0. */
static cdl_status add_triangles(cdl_scene_geometry *g, const cdl_geometry_piece *tmpl, double *xyz, size_t nv,
                                uint32_t *tri, size_t nt, cdl_error *err)
{
    if (g->piece_count == g->piece_capacity) {
        size_t cap = g->piece_capacity ? 2 * g->piece_capacity : 16;
        piece_data *grown = realloc(g->pieces, cap * sizeof *grown);
        if (!grown) {
            free(xyz);
            free(tri);
            return cdl_error_out_of_memory(err);
        }
        g->pieces = grown;
        g->piece_capacity = cap;
    }
    uint32_t id = 0;
    cdl_status st = cdl_ray_scene_add_triangles(g->rays, xyz, nv, tri, nt, &id, err);
    if (st != CDL_OK) {
        free(xyz);
        free(tri);
        return st;
    }
    piece_data *pd = &g->pieces[g->piece_count++];
    pd->piece = *tmpl;
    pd->xyz = xyz;
    pd->vertex_count = nv;
    pd->triangles = tri;
    pd->piece.triangle_count = nt;
    double area = 0.0;
    for (size_t t = 0; t < nt; ++t) area += triangle_area(xyz, &tri[3 * t]);
    if (!(pd->piece.area > 0.0)) pd->piece.area = area;
    if (pd->piece.shape.kind == CDL_SHAPE_TRIANGLES) {
        pd->piece.shape.vertices = xyz;
        pd->piece.shape.vertex_count = nv;
        pd->piece.shape.triangles = tri;
        pd->piece.shape.triangle_count = nt;
    }
    g->triangle_count += nt;
    for (size_t v = 0; v < nv; ++v) cdl_bounds3_grow(&g->bounds, cdl_vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    return CDL_OK;
}

static cdl_status alloc_mesh(size_t nv, size_t nt, double **xyz, uint32_t **tri, cdl_error *err)
{
    *xyz = malloc(nv * 3 * sizeof **xyz);
    *tri = malloc(nt * 3 * sizeof **tri);
    if (!*xyz || !*tri) {
        free(*xyz);
        free(*tri);
        return cdl_error_out_of_memory(err);
    }
    return CDL_OK;
}

static void put_vertex(double *xyz, size_t i, cdl_vec3 p)
{
    xyz[3 * i] = p.x;
    xyz[3 * i + 1] = p.y;
    xyz[3 * i + 2] = p.z;
}

/* A quad of four corners, counter-clockwise seen from its front, as two
 * triangles and an analytic rect (origin c0, u = c1 - c0, v = c3 - c0). */
static cdl_status add_quad(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, const cdl_vec3 *c, cdl_error *err)
{
    double *xyz;
    uint32_t *tri;
    if (alloc_mesh(4, 2, &xyz, &tri, err) != CDL_OK) return CDL_ERR_INTERNAL;
    for (size_t i = 0; i < 4; ++i) put_vertex(xyz, i, c[i]);
    static const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    memcpy(tri, quad, sizeof quad);
    tmpl->shape.kind = CDL_SHAPE_RECT;
    tmpl->shape.origin = c[0];
    tmpl->shape.u = cdl_vec3_sub(c[1], c[0]);
    tmpl->shape.v = cdl_vec3_sub(c[3], c[0]);
    tmpl->area = cdl_vec3_length(cdl_vec3_cross(tmpl->shape.u, tmpl->shape.v));
    return add_triangles(g, tmpl, xyz, 4, tri, 2, err);
}

static cdl_status add_rect(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, cdl_vec3 o, cdl_vec3 u, cdl_vec3 v,
                           cdl_error *err)
{
    cdl_vec3 c[4] = {o, cdl_vec3_add(o, u), cdl_vec3_add(cdl_vec3_add(o, u), v), cdl_vec3_add(o, v)};
    cdl_status st = add_quad(g, tmpl, c, err);
    /* Keep the user's u and v exactly (c1 - c0 may round). */
    if (st == CDL_OK) {
        g->pieces[g->piece_count - 1].piece.shape.u = u;
        g->pieces[g->piece_count - 1].piece.shape.v = v;
    }
    return st;
}

/* Corner k of a box: bit 0 picks x, bit 1 y, bit 2 z (0 min, 1 max). */
static cdl_vec3 box_corner(const cdl_surface_spec *s, int k)
{
    return cdl_vec3_make(k & 1 ? s->box_max.x : s->box_min.x, k & 2 ? s->box_max.y : s->box_min.y,
                         k & 4 ? s->box_max.z : s->box_min.z);
}

void cdl_box_face_corners(const cdl_surface_spec *s, int face, cdl_vec3 corners[4])
{
    /* Corners of each face, counter-clockwise seen from outside. */
    static const int faces[CDL_BOX_FACES][4] = {
        {0, 4, 6, 2}, /* -x */
        {1, 3, 7, 5}, /* +x */
        {0, 1, 5, 4}, /* -y */
        {2, 6, 7, 3}, /* +y */
        {0, 2, 3, 1}, /* -z */
        {4, 5, 7, 6}, /* +z */
    };
    for (int k = 0; k < 4; ++k) {
        /* Inward: the same corners in the opposite order. */
        int corner = s->inward ? faces[face][(4 - k) % 4] : faces[face][k];
        corners[k] = box_corner(s, corner);
    }
}

static cdl_status add_box(cdl_scene_geometry *g, const cdl_surface_spec *s, cdl_geometry_piece *tmpl, cdl_error *err)
{
    for (int f = 0; f < CDL_BOX_FACES; ++f) {
        if (s->face_open[f]) continue;
        cdl_vec3 c[4];
        cdl_box_face_corners(s, f, c);
        tmpl->box_face = f;
        tmpl->reflectance = s->face_reflectance[f];
        cdl_status st = add_quad(g, tmpl, c, err);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

cdl_vec3 cdl_disk_rim_point(cdl_vec3 center, cdl_vec3 normal, double radius, uint32_t k)
{
    cdl_frame f = cdl_frame_from_normal(normal);
    /* Counter-clockwise about the normal, since s x t = n. */
    double phi = CDL_TWO_PI * k / CDL_DISK_SEGMENTS;
    return cdl_vec3_add(center, cdl_frame_to_world(&f, cdl_vec3_make(radius * cos(phi), radius * sin(phi), 0.0)));
}

static cdl_status add_disk(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, cdl_vec3 center, cdl_vec3 normal,
                           double radius, cdl_error *err)
{
    double *xyz;
    uint32_t *tri;
    if (alloc_mesh(DISK_SEGMENTS + 1, DISK_SEGMENTS, &xyz, &tri, err) != CDL_OK) return CDL_ERR_INTERNAL;
    normal = cdl_vec3_normalize(normal);
    put_vertex(xyz, 0, center);
    for (uint32_t k = 0; k < DISK_SEGMENTS; ++k) {
        put_vertex(xyz, k + 1u, cdl_disk_rim_point(center, normal, radius, k));
        tri[3 * k] = 0;
        tri[3 * k + 1] = k + 1u;
        tri[3 * k + 2] = (k + 1u) % DISK_SEGMENTS + 1u;
    }
    tmpl->shape.kind = CDL_SHAPE_DISK;
    tmpl->shape.center = center;
    tmpl->shape.normal = normal;
    tmpl->shape.radius = radius;
    /* The piece is the exact disk (cdl_shape); the fan only stands in for rays. */
    tmpl->area = CDL_PI * radius * radius;
    return add_triangles(g, tmpl, xyz, DISK_SEGMENTS + 1, tri, DISK_SEGMENTS, err);
}

static cdl_status add_sphere(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, cdl_vec3 center, double radius,
                             int inward, cdl_error *err)
{
    if (g->piece_count == g->piece_capacity) {
        size_t cap = g->piece_capacity ? 2 * g->piece_capacity : 16;
        piece_data *grown = realloc(g->pieces, cap * sizeof *grown);
        if (!grown) return cdl_error_out_of_memory(err);
        g->pieces = grown;
        g->piece_capacity = cap;
    }
    uint32_t id = 0;
    cdl_status st = cdl_ray_scene_add_sphere(g->rays, center, radius, &id, err);
    if (st != CDL_OK) return st;
    piece_data *pd = &g->pieces[g->piece_count++];
    memset(pd, 0, sizeof *pd);
    pd->piece = *tmpl;
    pd->piece.shape.kind = CDL_SHAPE_SPHERE;
    pd->piece.shape.center = center;
    pd->piece.shape.radius = radius;
    pd->piece.shape.inward = inward;
    pd->piece.triangle_count = 0;
    pd->piece.area = 4.0 * CDL_PI * radius * radius;
    cdl_vec3 r = cdl_vec3_make(radius, radius, radius);
    cdl_bounds3_grow(&g->bounds, cdl_vec3_sub(center, r));
    cdl_bounds3_grow(&g->bounds, cdl_vec3_add(center, r));
    return CDL_OK;
}

typedef struct keyed_point {
    double x, y;
    cdl_vec3 p;
} keyed_point;

static int compare_keyed(const void *pa, const void *pb)
{
    const keyed_point *a = pa, *b = pb;
    if (a->x != b->x) return (a->x > b->x) - (a->x < b->x);
    return (a->y > b->y) - (a->y < b->y);
}

static cdl_status add_polygon(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, const cdl_surface_spec *s,
                              cdl_error *err)
{
    cdl_polygon_plane plane;
    if (cdl_polygon_plane_of_checked(&s->outer, s->holes, s->hole_count, &plane, err) != CDL_OK) return CDL_ERR_INTERNAL;
    cdl_mesh2d mesh;
    cdl_status st = cdl_polygon_triangulate(&plane, &s->outer, s->holes, s->hole_count, 0.0, SIZE_MAX, &mesh, err);
    if (st != CDL_OK) return st;
    /* Map the mesh's vertices back to the rings' own 3D points (the
     * projection is exact for them, and triangulation adds none). */
    size_t total = s->outer.count;
    for (size_t h = 0; h < s->hole_count; ++h) total += s->holes[h].count;
    keyed_point *keys = malloc(total * sizeof *keys);
    double *xyz = NULL;
    uint32_t *tri = NULL;
    if (!keys || alloc_mesh(mesh.vertex_count, mesh.triangle_count, &xyz, &tri, err) != CDL_OK) {
        free(keys);
        cdl_mesh2d_release(&mesh);
        return cdl_error_out_of_memory(err);
    }
    size_t k = 0;
    for (long r = -1; r < (long)s->hole_count; ++r) {
        const cdl_ring3 *ring = r < 0 ? &s->outer : &s->holes[r];
        for (size_t i = 0; i < ring->count; ++i, ++k) {
            keys[k].p = ring->points[i];
            cdl_polygon_project(&plane, ring->points[i], &keys[k].x, &keys[k].y);
        }
    }
    qsort(keys, total, sizeof *keys, compare_keyed);
    for (size_t v = 0; v < mesh.vertex_count; ++v) {
        keyed_point key = {mesh.xy[2 * v], mesh.xy[2 * v + 1], {0, 0, 0}};
        const keyed_point *hit = bsearch(&key, keys, total, sizeof *keys, compare_keyed);
        put_vertex(xyz, v, hit ? hit->p : cdl_polygon_lift(&plane, key.x, key.y));
    }
    memcpy(tri, mesh.triangles, mesh.triangle_count * 3 * sizeof *tri);
    size_t nv = mesh.vertex_count, nt = mesh.triangle_count;
    free(keys);
    cdl_mesh2d_release(&mesh);
    tmpl->shape.kind = CDL_SHAPE_TRIANGLES;
    tmpl->area = 0.0;
    return add_triangles(g, tmpl, xyz, nv, tri, nt, err);
}

static cdl_status add_mesh(cdl_scene_geometry *g, cdl_geometry_piece *tmpl, const cdl_surface_spec *s, cdl_error *err)
{
    double *xyz;
    uint32_t *tri;
    if (alloc_mesh(s->mesh_vertex_count, s->mesh_triangle_count, &xyz, &tri, err) != CDL_OK) return CDL_ERR_INTERNAL;
    memcpy(xyz, s->mesh_vertices, s->mesh_vertex_count * 3 * sizeof *xyz);
    memcpy(tri, s->mesh_triangles, s->mesh_triangle_count * 3 * sizeof *tri);
    tmpl->shape.kind = CDL_SHAPE_TRIANGLES;
    tmpl->area = 0.0;
    return add_triangles(g, tmpl, xyz, s->mesh_vertex_count, tri, s->mesh_triangle_count, err);
}

static cdl_status add_surface(cdl_scene_geometry *g, const cdl_surface_spec *s, cdl_geometry_piece *tmpl,
                              cdl_error *err)
{
    switch (s->kind) {
    case CDL_SURFACE_RECT: return add_rect(g, tmpl, s->origin, s->u, s->v, err);
    case CDL_SURFACE_POLYGON: return add_polygon(g, tmpl, s, err);
    case CDL_SURFACE_BOX: return add_box(g, s, tmpl, err);
    case CDL_SURFACE_DISK: return add_disk(g, tmpl, s->center, s->normal, s->radius, err);
    case CDL_SURFACE_SPHERE: return add_sphere(g, tmpl, s->center, s->radius, s->inward, err);
    case CDL_SURFACE_MESH: return add_mesh(g, tmpl, s, err);
    }
    return cdl_error_set(err, CDL_ERR_INTERNAL, "unknown surface kind %d", (int)s->kind);
}

/* Pieces from `first` on must have an area a double can hold: a shape so
 * small that its area underflows would divide flux by zero. */
static cdl_status check_areas(const cdl_scene_geometry *g, size_t first, cdl_error *err)
{
    for (size_t i = first; i < g->piece_count; ++i) {
        double a = g->pieces[i].piece.area;
        if (!(a > 0.0) || !isfinite(a))
            return cdl_error_set(err, CDL_ERR_INPUT, "expected a surface of non-zero, finite area, found %g m^2", a);
    }
    return CDL_OK;
}

/* One piece per luminaire body (scene_bodies.h), after every other piece. */
static cdl_status add_bodies(cdl_scene_geometry *g, const cdl_scene *scene, cdl_error *err)
{
    size_t n = scene->luminaire_count;
    g->surface_bounds = g->bounds;
    g->luminaire_body = malloc((n + 1) * sizeof *g->luminaire_body);
    g->body_shape = calloc(n + 1, sizeof *g->body_shape);
    if (!g->luminaire_body || !g->body_shape) return cdl_error_out_of_memory(err);
    cdl_body_cache cache;
    memset(&cache, 0, sizeof cache);
    for (size_t k = 0; k < n; ++k) {
        g->luminaire_body[k] = UINT32_MAX;
        const cdl_luminaire_spec *l = &scene->luminaires[k];
        double reflectance = 0.0;
        cdl_status st = cdl_scene_body_of(scene, k, &cache, &g->body_shape[k], &reflectance, err);
        if (st != CDL_OK) return st;
        if (g->body_shape[k].kind == CDL_BODY_NONE) continue;
        cdl_body_mesh mesh;
        st = cdl_scene_body_mesh(&g->body_shape[k], l->position, l->rotation_deg, &mesh, err);
        if (st != CDL_OK) return st;
        cdl_geometry_piece tmpl;
        memset(&tmpl, 0, sizeof tmpl);
        tmpl.is_luminaire = 1;
        tmpl.is_body = 1;
        tmpl.source_index = k;
        tmpl.box_face = -1;
        tmpl.reflectance = reflectance;
        tmpl.curved = mesh.curved;
        tmpl.shape.kind = CDL_SHAPE_TRIANGLES;
        uint32_t id = (uint32_t)g->piece_count;
        if (mesh.is_sphere) {
            st = add_sphere(g, &tmpl, mesh.center, mesh.radius, 0, err);
        } else {
            /* a flat body reflects on its front alone; a solid's inside is never seen */
            st = add_triangles(g, &tmpl, mesh.xyz, mesh.vertex_count, mesh.triangles, mesh.triangle_count, err);
            mesh.xyz = NULL; /* the geometry owns them now (freed there on failure) */
            mesh.triangles = NULL;
        }
        cdl_body_mesh_release(&mesh);
        if (st != CDL_OK) return cdl_error_prefix(err, "%s: %s.body: ", scene->path ? scene->path : "scene", l->json_path);
        g->luminaire_body[k] = id;
    }
    return CDL_OK;
}

cdl_status cdl_scene_geometry_build(const cdl_scene *scene, cdl_scene_geometry **out, cdl_error *err)
{
    *out = NULL;
    cdl_scene_geometry *g = calloc(1, sizeof *g);
    if (!g) return cdl_error_out_of_memory(err);
    g->bounds = cdl_bounds3_empty();
    cdl_status st = cdl_ray_scene_create(&g->rays, err);
    const char *file = scene->path ? scene->path : "scene";
    for (size_t i = 0; i < scene->surface_count && st == CDL_OK; ++i) {
        const cdl_surface_spec *s = &scene->surfaces[i];
        cdl_geometry_piece tmpl;
        memset(&tmpl, 0, sizeof tmpl);
        tmpl.source_index = i;
        tmpl.box_face = -1;
        tmpl.reflectance = s->reflectance;
        tmpl.two_sided = s->two_sided;
        tmpl.luminance_cd_m2 = s->luminance_cd_m2;
        tmpl.transmittance = s->transmittance;
        if (s->transmittance > 0.0 && cdl_glass_from_transmittance(s->transmittance, &tmpl.glass, err) != CDL_OK) {
            st = cdl_error_prefix(err, "%s: %s.transmittance: ", file, s->json_path);
            break;
        }
        g->glass |= s->transmittance > 0.0;
        size_t first = g->piece_count;
        st = add_surface(g, s, &tmpl, err);
        if (st == CDL_OK) st = check_areas(g, first, err);
        if (st != CDL_OK) cdl_error_prefix(err, "%s: %s: ", file, s->json_path);
    }
    for (size_t i = 0; i < scene->luminaire_count && st == CDL_OK; ++i) {
        const cdl_luminaire_spec *l = &scene->luminaires[i];
        if (l->kind != CDL_LUMINAIRE_AREA) continue;
        cdl_geometry_piece tmpl;
        memset(&tmpl, 0, sizeof tmpl);
        tmpl.is_luminaire = 1;
        tmpl.source_index = i;
        tmpl.box_face = -1;
        tmpl.reflectance = l->reflectance;
        tmpl.two_sided = 1;
        size_t first = g->piece_count;
        st = add_surface(g, &l->shape, &tmpl, err);
        if (st == CDL_OK) st = check_areas(g, first, err);
        if (st != CDL_OK) {
            cdl_error_prefix(err, "%s: %s: ", file, l->shape.json_path);
            break;
        }
        /* Lambertian emitter: flux = pi L A (DESIGN.md, "area"); the
         * maintenance factor scales the output. */
        cdl_geometry_piece *p = &g->pieces[first].piece;
        p->luminance_cd_m2 =
            l->maintenance_factor * (l->has_luminance ? l->luminance_cd_m2 : l->flux_lm / (CDL_PI * p->area));
        if (!isfinite(p->luminance_cd_m2)) {
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: %s.flux_lm: expected a flux that spreads over the shape's %g m^2 with a finite "
                               "luminance (flux / (pi area)), found %g lm",
                               file, l->json_path, p->area, l->flux_lm);
            break;
        }
    }
    if (st == CDL_OK) st = add_bodies(g, scene, err);
    if (st == CDL_OK) st = cdl_ray_scene_commit(g->rays, err);
    if (st != CDL_OK) {
        cdl_scene_geometry_release(g);
        return st;
    }
    if (g->piece_count == 0) g->bounds.lo = g->bounds.hi = cdl_vec3_make(0, 0, 0);
    g->extent = cdl_bounds3_diagonal(g->bounds);
    *out = g;
    return CDL_OK;
}

void cdl_scene_geometry_release(cdl_scene_geometry *g)
{
    if (!g) return;
    for (size_t i = 0; i < g->piece_count; ++i) {
        free(g->pieces[i].xyz);
        free(g->pieces[i].triangles);
    }
    free(g->pieces);
    free(g->luminaire_body);
    free(g->body_shape);
    cdl_ray_scene_release(g->rays);
    free(g);
}

/* ---- queries ------------------------------------------------------------------- */

const cdl_ray_scene *cdl_scene_geometry_rays(const cdl_scene_geometry *g)
{
    return g->rays;
}

size_t cdl_scene_geometry_piece_count(const cdl_scene_geometry *g)
{
    return g->piece_count;
}

uint32_t cdl_scene_geometry_luminaire_body(const cdl_scene_geometry *g, size_t k)
{
    return g->luminaire_body ? g->luminaire_body[k] : UINT32_MAX;
}

const cdl_luminaire_body *cdl_scene_geometry_luminaire_body_shape(const cdl_scene_geometry *g, size_t k)
{
    static const cdl_luminaire_body none = {.kind = CDL_BODY_NONE, .flat_axis = -1};
    return g->body_shape ? &g->body_shape[k] : &none;
}

const cdl_geometry_piece *cdl_scene_geometry_piece(const cdl_scene_geometry *g, size_t geom_id)
{
    return geom_id < g->piece_count ? &g->pieces[geom_id].piece : NULL;
}

size_t cdl_scene_geometry_piece_triangles(const cdl_scene_geometry *g, size_t geom_id, const double **xyz,
                                          size_t *vertex_count, const uint32_t **triangles)
{
    if (geom_id >= g->piece_count) {
        *xyz = NULL;
        *vertex_count = 0;
        *triangles = NULL;
        return 0;
    }
    const piece_data *pd = &g->pieces[geom_id];
    *xyz = pd->xyz;
    *vertex_count = pd->vertex_count;
    *triangles = pd->triangles;
    return pd->piece.triangle_count;
}

size_t cdl_scene_geometry_triangle_count(const cdl_scene_geometry *g)
{
    return g->triangle_count;
}

void cdl_scene_geometry_surface_bounds(const cdl_scene_geometry *g, cdl_vec3 *lo, cdl_vec3 *hi)
{
    *lo = g->surface_bounds.lo;
    *hi = g->surface_bounds.hi;
}

void cdl_scene_geometry_bounds(const cdl_scene_geometry *g, cdl_vec3 *lo, cdl_vec3 *hi)
{
    *lo = g->bounds.lo;
    *hi = g->bounds.hi;
}

double cdl_scene_geometry_extent(const cdl_scene_geometry *g)
{
    return g->extent;
}

void cdl_scene_geometry_ray_offsets(const cdl_scene_geometry *g, cdl_ray_offsets *o)
{
    cdl_vec3 lo = g->bounds.lo, hi = g->bounds.hi;
    o->magnitude = fmax(fmax(fmax(fabs(lo.x), fabs(hi.x)), fmax(fabs(lo.y), fabs(hi.y))), fmax(fabs(lo.z), fabs(hi.z)));
    o->rounding = ROUNDING_RELATIVE;
}

double cdl_scene_geometry_ray_epsilon(const cdl_scene_geometry *g, cdl_vec3 p)
{
    cdl_ray_offsets o;
    cdl_scene_geometry_ray_offsets(g, &o);
    return cdl_ray_offsets_epsilon(&o, p);
}

double cdl_scene_geometry_resolution(const cdl_scene_geometry *g, cdl_vec3 p)
{
    return cdl_ray_scene_resolution(g->rays, p);
}

int cdl_scene_geometry_shadow_ray(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                                  cdl_vec3 *origin, double *t_near, double *t_far)
{
    cdl_ray_offsets o;
    cdl_scene_geometry_ray_offsets(g, &o);
    return cdl_ray_offsets_shadow_ray(&o, p, n, dir, distance, origin, t_near, t_far);
}

int cdl_scene_geometry_ray_occluded(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                    double distance)
{
    cdl_vec3 o;
    double t_near, t_far;
    if (!cdl_scene_geometry_shadow_ray(g, p, n, dir, distance, &o, &t_near, &t_far)) return 0;
    return cdl_ray_scene_occluded(g->rays, o, dir, t_near, t_far);
}

int cdl_scene_geometry_segment_occluded(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 p_normal, cdl_vec3 q,
                                        cdl_vec3 q_normal)
{
    (void)p_normal;
    (void)q_normal;
    /* t in (0, 1) along q - p: both ends are decided in double. */
    return cdl_ray_scene_occluded(g->rays, p, cdl_vec3_sub(q, p), 0.0, 1.0);
}

int cdl_scene_geometry_intersect(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double t_max,
                                 cdl_ray_hit *hit)
{
    (void)n;
    return cdl_ray_scene_intersect(g->rays, p, dir, 0.0, t_max, hit);
}

int cdl_scene_geometry_has_glass(const cdl_scene_geometry *g)
{
    return g->glass;
}

double cdl_scene_geometry_transmission(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 dir, double distance)
{
    return cdl_scene_geometry_transmission_except(g, p, dir, distance, UINT32_MAX);
}

double cdl_scene_geometry_transmission_except(const cdl_scene_geometry *g, cdl_vec3 p, cdl_vec3 dir, double distance,
                                              uint32_t exclude)
{
    if (!(distance > 0.0)) return 1.0;
    if (!g->glass) return cdl_ray_scene_occluded_except(g->rays, p, dir, 0.0, distance, exclude) ? 0.0 : 1.0;
    double T = 1.0, left = distance;
    cdl_vec3 origin = p;
    for (int panes = 0; panes <= CDL_GLASS_MAX_PANES; ++panes) {
        cdl_ray_hit hit;
        if (!cdl_ray_scene_intersect_except(g->rays, origin, dir, 0.0, left, exclude, &hit)) return T;
        const cdl_geometry_piece *piece = &g->pieces[hit.geom_id].piece;
        if (!(piece->transmittance > 0.0) || panes == CDL_GLASS_MAX_PANES) return 0.0;
        /* through the pane at its angle of incidence; on from its far side
         * (a ray from a point of a surface never hits that surface again) */
        T *= cdl_glass_transmittance(&piece->glass, cdl_vec3_dot(dir, hit.normal));
        origin = cdl_vec3_madd(origin, hit.t, dir);
        left -= hit.t;
        if (!(T > 0.0) || !(left > 0.0)) return left > 0.0 ? 0.0 : T;
    }
    return 0.0;
}
