/* scene_bodies.c - luminaire bodies placed in the scene (scene_bodies.h). */
#include "solver/scene/scene_bodies.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"
#include "solver/scene/scene_geometry.h"

cdl_status cdl_scene_body_of(const cdl_scene *scene, size_t k, cdl_body_cache *cache, cdl_luminaire_body *body,
                             double *reflectance, cdl_error *err)
{
    memset(body, 0, sizeof *body);
    body->flat_axis = -1;
    *reflectance = 0.0;
    const cdl_luminaire_spec *sp = &scene->luminaires[k];
    if (sp->kind != CDL_LUMINAIRE_GONIOMETRIC || !sp->body) return CDL_OK;
    if (!cache->valid || cache->entry != sp->entry) {
        cdl_photometry *ph = NULL;
        cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
        cdl_status st = cdl_photometry_read_file(sp->file, &opt, &ph, err);
        if (st != CDL_OK) {
            cdl_error_prefix(err, "%s.file: ", sp->json_path);
            return cdl_error_prefix(err, "%s: ", scene->path ? scene->path : "scene");
        }
        cdl_luminaire_body_of(ph, &cache->body);
        cdl_photometry_release(ph);
        cache->entry = sp->entry;
        cache->valid = 1;
    }
    *body = cache->body;
    if (body->kind == CDL_BODY_NONE) return CDL_OK;
    *reflectance = sp->has_body_reflectance ? sp->body_reflectance
                   : body->housing          ? CDL_BODY_HOUSING_REFLECTANCE
                                            : 0.0;
    return CDL_OK;
}

/* ---- meshes in the luminaire's frame ---------------------------------------- */

typedef struct mesh_builder {
    double *xyz;
    uint32_t *tri;
    size_t nv, nt;
} mesh_builder;

static uint32_t put(mesh_builder *m, cdl_vec3 p)
{
    m->xyz[3 * m->nv] = p.x;
    m->xyz[3 * m->nv + 1] = p.y;
    m->xyz[3 * m->nv + 2] = p.z;
    return (uint32_t)m->nv++;
}

static void tri(mesh_builder *m, uint32_t a, uint32_t b, uint32_t c)
{
    m->tri[3 * m->nt] = a;
    m->tri[3 * m->nt + 1] = b;
    m->tri[3 * m->nt + 2] = c;
    m->nt++;
}

static cdl_vec3 vertex(const mesh_builder *m, uint32_t i)
{
    return cdl_vec3_make(m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
}

/* Component k of v (0 x, 1 y, 2 z), and v with component k set. */
static double get(cdl_vec3 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

static cdl_vec3 with(cdl_vec3 v, int k, double value)
{
    if (k == 0) v.x = value;
    else if (k == 1) v.y = value;
    else v.z = value;
    return v;
}

/* The point at angle phi on the ellipse inscribed in the box's section
 * across `axis`, at `along` on the axis. */
static cdl_vec3 ellipse_point(const cdl_luminaire_body *b, int axis, double along, double phi)
{
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    cdl_vec3 c = cdl_vec3_scale(cdl_vec3_add(b->lo, b->hi), 0.5);
    double ri = 0.5 * (get(b->hi, i) - get(b->lo, i)), rj = 0.5 * (get(b->hi, j) - get(b->lo, j));
    cdl_vec3 p = with(c, axis, along);
    p = with(p, i, get(c, i) + ri * cos(phi));
    return with(p, j, get(c, j) + rj * sin(phi));
}

/* An elliptic fan across `axis` at `along`, N segments. */
static void fan(mesh_builder *m, const cdl_luminaire_body *b, int axis, double along, int n)
{
    cdl_vec3 c = with(cdl_vec3_scale(cdl_vec3_add(b->lo, b->hi), 0.5), axis, along);
    uint32_t centre = put(m, c), first = (uint32_t)m->nv;
    for (int k = 0; k < n; ++k) put(m, ellipse_point(b, axis, along, CDL_TWO_PI * k / n));
    for (int k = 0; k < n; ++k) tri(m, centre, first + (uint32_t)k, first + (uint32_t)((k + 1) % n));
}

/* The rectangle of the box across `axis` at `along`. */
static void rectangle(mesh_builder *m, const cdl_luminaire_body *b, int axis, double along)
{
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    uint32_t first = (uint32_t)m->nv;
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 p = with(b->lo, axis, along);
        p = with(p, i, (k == 1 || k == 2) ? get(b->hi, i) : get(b->lo, i));
        p = with(p, j, k >= 2 ? get(b->hi, j) : get(b->lo, j));
        put(m, p);
    }
    tri(m, first, first + 1, first + 2);
    tri(m, first, first + 2, first + 3);
}

static void box_solid(mesh_builder *m, const cdl_luminaire_body *b)
{
    for (int axis = 0; axis < 3; ++axis) {
        rectangle(m, b, axis, get(b->lo, axis));
        rectangle(m, b, axis, get(b->hi, axis));
    }
}

static void cylinder_solid(mesh_builder *m, const cdl_luminaire_body *b, int n)
{
    int a = b->axis;
    fan(m, b, a, get(b->lo, a), n);
    fan(m, b, a, get(b->hi, a), n);
    uint32_t lo = (uint32_t)m->nv;
    for (int k = 0; k < n; ++k) put(m, ellipse_point(b, a, get(b->lo, a), CDL_TWO_PI * k / n));
    uint32_t hi = (uint32_t)m->nv;
    for (int k = 0; k < n; ++k) put(m, ellipse_point(b, a, get(b->hi, a), CDL_TWO_PI * k / n));
    for (uint32_t k = 0; k < (uint32_t)n; ++k) {
        uint32_t k1 = (k + 1) % (uint32_t)n;
        tri(m, lo + k, lo + k1, hi + k1);
        tri(m, lo + k, hi + k1, hi + k);
    }
}

/* The ellipsoid inscribed in the box: poles on z, n slices, n / 2 stacks. */
static void ellipsoid(mesh_builder *m, const cdl_luminaire_body *b, int n)
{
    cdl_vec3 c = cdl_vec3_scale(cdl_vec3_add(b->lo, b->hi), 0.5);
    cdl_vec3 r = cdl_vec3_scale(cdl_vec3_sub(b->hi, b->lo), 0.5);
    int stacks = n / 2;
    uint32_t south = put(m, cdl_vec3_make(c.x, c.y, c.z - r.z));
    uint32_t north = put(m, cdl_vec3_make(c.x, c.y, c.z + r.z));
    uint32_t ring0 = (uint32_t)m->nv;
    for (int s = 1; s < stacks; ++s) {
        double theta = CDL_PI * s / stacks, st = sin(theta), ct = cos(theta);
        for (int k = 0; k < n; ++k) {
            double phi = CDL_TWO_PI * k / n;
            put(m, cdl_vec3_make(c.x + r.x * st * cos(phi), c.y + r.y * st * sin(phi), c.z - r.z * ct));
        }
    }
    uint32_t un = (uint32_t)n;
    for (uint32_t k = 0; k < un; ++k) {
        uint32_t k1 = (k + 1) % un;
        tri(m, south, ring0 + k, ring0 + k1);
        uint32_t top = ring0 + (uint32_t)(stacks - 2) * un;
        tri(m, north, top + k1, top + k);
        for (uint32_t s = 0; s + 2 < (uint32_t)stacks; ++s) {
            uint32_t a = ring0 + s * un, b2 = a + un;
            tri(m, a + k, b2 + k, b2 + k1);
            tri(m, a + k, b2 + k1, a + k1);
        }
    }
}

/* Every triangle turned to face outward (away from the centre of a convex
 * solid) or, flat, to face `front`. */
static void orient(mesh_builder *m, const cdl_luminaire_body *b)
{
    cdl_vec3 c = cdl_vec3_scale(cdl_vec3_add(b->lo, b->hi), 0.5);
    cdl_vec3 front = cdl_vec3_make(0, 0, 0);
    if (b->flat_axis >= 0) front = with(front, b->flat_axis, (double)b->front_sign);
    for (size_t t = 0; t < m->nt; ++t) {
        uint32_t *f = &m->tri[3 * t];
        cdl_vec3 p0 = vertex(m, f[0]), p1 = vertex(m, f[1]), p2 = vertex(m, f[2]);
        cdl_vec3 nrm = cdl_vec3_cross(cdl_vec3_sub(p1, p0), cdl_vec3_sub(p2, p0));
        cdl_vec3 out = b->flat_axis >= 0 ? front : cdl_vec3_sub(cdl_vec3_scale(cdl_vec3_add(cdl_vec3_add(p0, p1), p2), 1.0 / 3.0), c);
        if (cdl_vec3_dot(nrm, out) < 0.0) {
            uint32_t swap = f[1];
            f[1] = f[2];
            f[2] = swap;
        }
    }
}

cdl_status cdl_scene_body_mesh(const cdl_luminaire_body *b, cdl_vec3 position, const double rotation_deg[3],
                               cdl_body_mesh *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_vec3 col[3];
    cdl_emitter_rotation_columns(rotation_deg, col);
    cdl_vec3 size = cdl_vec3_sub(b->hi, b->lo);
    if (b->kind == CDL_BODY_ELLIPSOID && size.x == size.y && size.y == size.z) {
        cdl_vec3 c = cdl_vec3_scale(cdl_vec3_add(b->lo, b->hi), 0.5);
        out->is_sphere = 1;
        out->curved = 1;
        out->center = cdl_vec3_add(position, cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(col[0], c.x),
                                                                       cdl_vec3_scale(col[1], c.y)),
                                                          cdl_vec3_scale(col[2], c.z)));
        out->radius = 0.5 * size.x;
        return CDL_OK;
    }
    const int n = CDL_DISK_SEGMENTS, slices = CDL_BODY_SLICES;
    size_t nv = 0, nt = 0;
    switch (b->kind) {
    case CDL_BODY_NONE: return CDL_OK;
    case CDL_BODY_BOX: nv = b->flat_axis >= 0 ? 4 : 24; nt = b->flat_axis >= 0 ? 2 : 12; break;
    case CDL_BODY_CYLINDER:
        nv = b->flat_axis >= 0 ? (size_t)n + 1 : 4 * (size_t)n + 2;
        nt = b->flat_axis >= 0 ? (size_t)n : 4 * (size_t)n;
        break;
    case CDL_BODY_ELLIPSOID:
        nv = 2 + (size_t)(slices / 2 - 1) * (size_t)slices;
        nt = 2 * (size_t)slices * (size_t)(slices / 2 - 1);
        break;
    }
    mesh_builder m = {malloc(nv * 3 * sizeof(double)), malloc(nt * 3 * sizeof(uint32_t)), 0, 0};
    if (!m.xyz || !m.tri) {
        free(m.xyz);
        free(m.tri);
        return cdl_error_out_of_memory(err);
    }
    if (b->kind == CDL_BODY_BOX && b->flat_axis >= 0) rectangle(&m, b, b->flat_axis, get(b->lo, b->flat_axis));
    else if (b->kind == CDL_BODY_BOX) box_solid(&m, b);
    else if (b->kind == CDL_BODY_CYLINDER && b->flat_axis >= 0) fan(&m, b, b->flat_axis, get(b->lo, b->flat_axis), n);
    else if (b->kind == CDL_BODY_CYLINDER) cylinder_solid(&m, b, n);
    else ellipsoid(&m, b, slices);
    orient(&m, b);
    /* world = position + world_from_luminaire local (a rotation keeps the orientation) */
    for (size_t v = 0; v < m.nv; ++v) {
        cdl_vec3 l = vertex(&m, (uint32_t)v);
        cdl_vec3 w = cdl_vec3_add(position, cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(col[0], l.x), cdl_vec3_scale(col[1], l.y)),
                                                         cdl_vec3_scale(col[2], l.z)));
        m.xyz[3 * v] = w.x;
        m.xyz[3 * v + 1] = w.y;
        m.xyz[3 * v + 2] = w.z;
    }
    out->xyz = m.xyz;
    out->vertex_count = m.nv;
    out->triangles = m.tri;
    out->triangle_count = m.nt;
    out->curved = b->kind != CDL_BODY_BOX;
    return CDL_OK;
}

void cdl_body_mesh_release(cdl_body_mesh *mesh)
{
    free(mesh->xyz);
    free(mesh->triangles);
    memset(mesh, 0, sizeof *mesh);
}
