/* surface_join.c - planar patches that meet share their outline vertices
 * (surface_patch.h, surface_mesh.h "Watertight"). */
#include "solver/geometry/surface_patch.h"

#include <math.h>
#include <stdlib.h>

#include "base/grow.h"
#include "base/error_report.h"

/* Passes of joining: a vertex inserted into one outline may make Delaunay
 * refinement split an edge of it, whose new vertex the other patch then
 * takes; the outlines settle within a few passes. */
#define MAX_JOIN_PASSES 12

static int within(const cdl_bounds3 *b, cdl_vec3 p, double tolerance)
{
    return p.x >= b->lo.x - tolerance && p.x <= b->hi.x + tolerance && p.y >= b->lo.y - tolerance &&
           p.y <= b->hi.y + tolerance && p.z >= b->lo.z - tolerance && p.z <= b->hi.z + tolerance;
}

static double segment_distance(cdl_vec3 p, cdl_vec3 a, cdl_vec3 b)
{
    cdl_vec3 d = cdl_vec3_sub(b, a);
    double len2 = cdl_vec3_length_squared(d);
    double t = len2 > 0.0 ? cdl_vec3_dot(cdl_vec3_sub(p, a), d) / len2 : 0.0;
    t = fmax(0.0, fmin(1.0, t));
    return cdl_vec3_distance(p, cdl_vec3_madd(a, t, d));
}

/* Does p lie on the outline (outer ring or a hole) of a polygon patch? */
static int on_outline(const cdl_patch *patch, cdl_vec3 p, double tolerance)
{
    for (size_t r = 0; r <= patch->hole_count; ++r) {
        const cdl_ring3 *ring = r == 0 ? &patch->outer : &patch->holes[r - 1];
        for (size_t i = 0; i < ring->count; ++i)
            if (segment_distance(p, ring->points[i], ring->points[(i + 1) % ring->count]) <= tolerance) return 1;
    }
    return 0;
}

/* The outline vertices of B that lie on A's outline, in A's plane coordinates. */
static cdl_status gather(const cdl_patch_state *a, const cdl_patch_state *b, double tolerance, double **xy,
                         size_t *count, size_t *capacity, cdl_error *err)
{
    size_t n = cdl_patch_state_vertex_count(b);
    for (uint32_t v = 0; v < n; ++v) {
        if (!cdl_patch_state_on_outline(b, v)) continue;
        cdl_vec3 p = cdl_patch_state_position(b, v);
        if (!within(&a->bounds, p, tolerance) || !on_outline(a->spec, p, tolerance)) continue;
        if (cdl_grow(xy, capacity, 2 * (*count + 1), sizeof **xy, 128, err) != CDL_OK) return CDL_ERR_INTERNAL;
        cdl_polygon_project(&a->plane, p, &(*xy)[2 * *count], &(*xy)[2 * *count + 1]);
        ++*count;
    }
    return CDL_OK;
}

static int bounds_meet(const cdl_bounds3 *a, const cdl_bounds3 *b, double tolerance)
{
    return a->lo.x <= b->hi.x + tolerance && b->lo.x <= a->hi.x + tolerance && a->lo.y <= b->hi.y + tolerance &&
           b->lo.y <= a->hi.y + tolerance && a->lo.z <= b->hi.z + tolerance && b->lo.z <= a->hi.z + tolerance;
}

cdl_status cdl_patch_join(cdl_patch_state *states, size_t count, double tolerance, size_t max_vertices,
                          size_t *joined, cdl_error *err)
{
    double *xy = NULL;
    size_t capacity = 0;
    cdl_status st = CDL_OK;
    for (int pass = 0; st == CDL_OK && pass < MAX_JOIN_PASSES; ++pass) {
        size_t inserted_in_pass = 0;
        for (size_t i = 0; st == CDL_OK && i < count; ++i) {
            cdl_patch_state *a = &states[i];
            if (!a->cdt) continue;
            size_t n = 0;
            for (size_t j = 0; st == CDL_OK && j < count; ++j)
                if (j != i && states[j].cdt && bounds_meet(&a->bounds, &states[j].bounds, tolerance))
                    st = gather(a, &states[j], tolerance, &xy, &n, &capacity, err);
            size_t inserted = 0;
            if (st == CDL_OK && n) st = cdl_cdt2d_insert_on_boundary(a->cdt, xy, n, tolerance, &inserted, err);
            if (st == CDL_OK && inserted) st = cdl_cdt2d_improve(a->cdt, a->spec->max_edge, max_vertices, err);
            inserted_in_pass += inserted;
        }
        *joined += inserted_in_pass;
        if (!inserted_in_pass) break;
    }
    free(xy);
    return st;
}

/* ---- snapping ------------------------------------------------------------------ */

typedef struct outline_vertex {
    double *xyz;
    size_t mesh, vertex;
} outline_vertex;

static int compare_outline(const void *pa, const void *pb)
{
    const outline_vertex *a = pa, *b = pb;
    if (a->xyz[0] != b->xyz[0]) return a->xyz[0] < b->xyz[0] ? -1 : 1;
    if (a->mesh != b->mesh) return a->mesh < b->mesh ? -1 : 1;
    return (a->vertex > b->vertex) - (a->vertex < b->vertex);
}

cdl_status cdl_surface_mesh_snap(cdl_surface_mesh *meshes, size_t count, double tolerance, cdl_error *err)
{
    size_t n = 0;
    for (size_t m = 0; m < count; ++m)
        for (size_t v = 0; v < meshes[m].vertex_count; ++v) n += meshes[m].on_outline[v] != 0;
    outline_vertex *all = malloc((n + 1) * sizeof *all);
    unsigned char *done = calloc(n + 1, 1);
    if (!all || !done) {
        free(all);
        free(done);
        return cdl_error_out_of_memory(err);
    }
    n = 0;
    for (size_t m = 0; m < count; ++m)
        for (size_t v = 0; v < meshes[m].vertex_count; ++v)
            if (meshes[m].on_outline[v]) all[n++] = (outline_vertex){&meshes[m].xyz[3 * v], m, v};
    qsort(all, n, sizeof *all, compare_outline);
    for (size_t i = 0; i < n; ++i) {
        if (done[i]) continue;
        const double *rep = all[i].xyz;
        for (size_t j = i + 1; j < n && all[j].xyz[0] - rep[0] <= tolerance; ++j) {
            if (done[j]) continue;
            double *p = all[j].xyz;
            if (hypot(hypot(p[0] - rep[0], p[1] - rep[1]), p[2] - rep[2]) > tolerance) continue;
            p[0] = rep[0];
            p[1] = rep[1];
            p[2] = rep[2];
            done[j] = 1;
        }
    }
    free(all);
    free(done);
    return CDL_OK;
}
