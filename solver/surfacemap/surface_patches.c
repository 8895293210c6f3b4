/* surface_patches.c - mapped surfaces as patches (surface_patches.h). */
#include "solver/surfacemap/surface_patches.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "radiometry/bounds.h"
#include "radiometry/constants.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene_geometry.h"
#include "base/error_report.h"

/* The disk polygons' side counts: divisors of the fan's 224 segments. */
static const uint32_t disk_sides[] = {32, 56, 112, CDL_DISK_SEGMENTS};

uint32_t cdl_surface_patches_disk_sides(double radius, double max_edge)
{
    for (size_t i = 0; i < sizeof disk_sides / sizeof *disk_sides; ++i)
        if (2.0 * radius * sin(CDL_PI / disk_sides[i]) <= max_edge) return disk_sides[i];
    return CDL_DISK_SEGMENTS;
}

static double coarsest_edge(const cdl_vec3 *points, size_t n)
{
    cdl_bounds3 b = cdl_bounds3_empty();
    for (size_t i = 0; i < n; ++i) cdl_bounds3_grow(&b, points[i]);
    cdl_vec3 d = cdl_vec3_sub(b.hi, b.lo);
    return cdl_grid_auto_spacing(fmax(d.x, fmax(d.y, d.z)));
}

/* How many ring points and patches a surface needs. */
static void count(const cdl_surface_spec *s, size_t *points, size_t *patches)
{
    switch (s->kind) {
    case CDL_SURFACE_RECT: *points += 4, *patches += 1; break;
    case CDL_SURFACE_BOX:
        for (int f = 0; f < CDL_BOX_FACES; ++f)
            if (!s->face_open[f]) *points += 4, *patches += 1;
        break;
    case CDL_SURFACE_DISK: *points += CDL_DISK_SEGMENTS, *patches += 1; break;
    default: *patches += 1; break;
    }
}

static cdl_patch polygon(size_t map, cdl_vec3 *ring, size_t n)
{
    cdl_patch p = {0};
    p.kind = CDL_PATCH_POLYGON;
    p.surface = map;
    p.outer = (cdl_ring3){ring, n};
    p.max_edge = coarsest_edge(ring, n);
    return p;
}

/* The patches of surface s (map number `map`), their rings from *next on,
 * and each patch's reflectance. */
static size_t add_surface(const cdl_surface_spec *s, size_t map, cdl_vec3 **next, cdl_patch *out, double *rho)
{
    cdl_vec3 *r = *next;
    size_t n = 0;
    switch (s->kind) {
    case CDL_SURFACE_RECT:
        r[0] = s->origin;
        r[1] = cdl_vec3_add(s->origin, s->u);
        r[2] = cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v);
        r[3] = cdl_vec3_add(s->origin, s->v);
        out[n++] = polygon(map, r, 4);
        *next += 4;
        break;
    case CDL_SURFACE_BOX:
        for (int f = 0; f < CDL_BOX_FACES; ++f) {
            if (s->face_open[f]) continue;
            cdl_box_face_corners(s, f, *next);
            rho[n] = s->face_reflectance[f];
            out[n++] = polygon(map, *next, 4);
            *next += 4;
        }
        break;
    case CDL_SURFACE_DISK: {
        double edge = cdl_grid_auto_spacing(2.0 * s->radius);
        uint32_t sides = cdl_surface_patches_disk_sides(s->radius, edge), step = CDL_DISK_SEGMENTS / sides;
        for (uint32_t k = 0; k < sides; ++k) r[k] = cdl_disk_rim_point(s->center, s->normal, s->radius, k * step);
        out[n] = polygon(map, r, sides);
        out[n++].max_edge = edge;
        *next += sides;
        break;
    }
    case CDL_SURFACE_POLYGON:
        out[n] = polygon(map, s->outer.points, s->outer.count);
        out[n].holes = s->holes;
        out[n++].hole_count = s->hole_count;
        break;
    case CDL_SURFACE_SPHERE:
        out[n].kind = CDL_PATCH_SPHERE;
        out[n].surface = map;
        out[n].center = s->center;
        out[n].radius = s->radius;
        out[n].inward = s->inward;
        out[n++].max_edge = cdl_grid_auto_spacing(2.0 * s->radius);
        break;
    case CDL_SURFACE_MESH: {
        cdl_bounds3 b = cdl_bounds3_empty();
        for (size_t v = 0; v < s->mesh_vertex_count; ++v)
            cdl_bounds3_grow(&b, cdl_vec3_make(s->mesh_vertices[3 * v], s->mesh_vertices[3 * v + 1],
                                               s->mesh_vertices[3 * v + 2]));
        cdl_vec3 d = cdl_vec3_sub(b.hi, b.lo);
        out[n].kind = CDL_PATCH_TRIANGLES;
        out[n].surface = map;
        out[n].xyz = s->mesh_vertices;
        out[n].vertex_count = s->mesh_vertex_count;
        out[n].triangles = s->mesh_triangles;
        out[n].triangle_count = s->mesh_triangle_count;
        out[n++].max_edge = cdl_grid_auto_spacing(fmax(d.x, fmax(d.y, d.z)));
        break;
    }
    }
    if (s->kind != CDL_SURFACE_BOX) rho[0] = s->reflectance;
    return n;
}

cdl_status cdl_surface_patches_build(const cdl_scene *scene, cdl_surface_patches *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t points = 0, patches = 0, maps = 0;
    for (size_t k = 0; k < scene->surface_count; ++k)
        if (scene->surfaces[k].mapped) {
            count(&scene->surfaces[k], &points, &patches);
            ++maps;
        }
    out->points = malloc((points + 1) * sizeof *out->points);
    out->patches = calloc(patches + 1, sizeof *out->patches);
    out->scene_surface = malloc((maps + 1) * sizeof *out->scene_surface);
    out->reflectance = calloc(patches + 1, sizeof *out->reflectance);
    if (!out->points || !out->patches || !out->scene_surface || !out->reflectance) {
        cdl_surface_patches_release(out);
        return cdl_error_out_of_memory(err);
    }
    cdl_vec3 *next = out->points;
    for (size_t k = 0; k < scene->surface_count; ++k) {
        if (!scene->surfaces[k].mapped) continue;
        out->scene_surface[out->map_count] = k;
        out->count += add_surface(&scene->surfaces[k], out->map_count, &next, out->patches + out->count,
                                  out->reflectance + out->count);
        ++out->map_count;
    }
    out->point_count = (size_t)(next - out->points);
    return CDL_OK;
}

void cdl_surface_patches_release(cdl_surface_patches *p)
{
    free(p->patches);
    free(p->reflectance);
    free(p->scene_surface);
    free(p->points);
    memset(p, 0, sizeof *p);
}
