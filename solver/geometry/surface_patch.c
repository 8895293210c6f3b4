/* surface_patch.c - a patch's mesh, slots and tests (surface_patch.h). */
#include "solver/geometry/surface_patch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "radiometry/constants.h"
#include "solver/geometry/remesh.h"
#include "base/error_report.h"

/* ---- the first mesh ------------------------------------------------------------ */

static cdl_vec3 triangle_normal(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    return cdl_vec3_normalize(cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
}

static cdl_vec3 xyz_at(const double *xyz, uint32_t v)
{
    return cdl_vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
}

/* Two triangles across the edge they share are in one region when the
 * edge has just the two of them, they run along it in opposite directions
 * (consistent orientation) and their normals are within the feature angle. */
typedef struct edge_use {
    size_t triangle, count;
    int forward;              /* the first triangle runs a -> b with a < b */
    size_t other;
    int other_forward;
} edge_use;

static cdl_status edge_uses(const uint32_t *tri, size_t nt, cdl_key_table *table, edge_use **uses, size_t *n_uses,
                            cdl_error *err)
{
    *uses = malloc((3 * nt + 1) * sizeof **uses);
    if (!*uses) return cdl_error_out_of_memory(err);
    *n_uses = 0;
    for (size_t t = 0; t < nt; ++t)
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3];
            uint64_t key = cdl_key_pair(a, b);
            size_t u = cdl_key_table_find(table, key);
            if (u == CDL_KEY_TABLE_NONE) {
                u = (*n_uses)++;
                (*uses)[u] = (edge_use){t, 0, a < b, 0, 0};
                if (cdl_key_table_put(table, key, u, err) != CDL_OK) return CDL_ERR_INTERNAL;
            } else if ((*uses)[u].count == 1) {
                (*uses)[u].other = t;
                (*uses)[u].other_forward = a < b;
            }
            ++(*uses)[u].count;
        }
    return CDL_OK;
}

/* Regions of a triangle mesh between its sharp edges, numbered in the
 * order of their first triangle (a flood fill from each unlabelled one). */
static cdl_status mesh_regions(const double *xyz, const uint32_t *tri, size_t nt, double feature_angle_deg,
                               uint32_t **region_out, cdl_error *err)
{
    cdl_key_table table = {0};
    edge_use *uses = NULL;
    size_t n_uses = 0;
    uint32_t *region = malloc((nt + 1) * sizeof *region);
    size_t *queue = malloc((nt + 1) * sizeof *queue);
    cdl_vec3 *normal = malloc((nt + 1) * sizeof *normal);
    cdl_status st = region && queue && normal ? edge_uses(tri, nt, &table, &uses, &n_uses, err)
                                              : cdl_error_out_of_memory(err);
    double cos_feature = cos(feature_angle_deg * CDL_PI / 180.0);
    for (size_t t = 0; st == CDL_OK && t < nt; ++t) {
        region[t] = UINT32_MAX;
        normal[t] = triangle_normal(xyz_at(xyz, tri[3 * t]), xyz_at(xyz, tri[3 * t + 1]), xyz_at(xyz, tri[3 * t + 2]));
    }
    uint32_t next_region = 0;
    for (size_t seed = 0; st == CDL_OK && seed < nt; ++seed) {
        if (region[seed] != UINT32_MAX) continue;
        size_t head = 0, tail = 0;
        region[seed] = next_region;
        queue[tail++] = seed;
        while (head < tail) {
            size_t t = queue[head++];
            for (size_t k = 0; k < 3; ++k) {
                const edge_use *u = &uses[cdl_key_table_find(&table, cdl_key_pair(tri[3 * t + k], tri[3 * t + (k + 1) % 3]))];
                if (u->count != 2 || u->forward == u->other_forward) continue;
                size_t n = u->triangle == t ? u->other : u->triangle;
                if (region[n] != UINT32_MAX || cdl_vec3_dot(normal[t], normal[n]) < cos_feature) continue;
                region[n] = next_region;
                queue[tail++] = n;
            }
        }
        ++next_region;
    }
    cdl_key_table_release(&table);
    free(uses);
    free(queue);
    free(normal);
    if (st != CDL_OK) {
        free(region);
        return st;
    }
    *region_out = region;
    return CDL_OK;
}

/* Triangles of no area (an imported mesh's slivers) carry no normal and
 * no light; they are left out of the map. */
static size_t drop_degenerate(const double *xyz, uint32_t *tri, size_t nt)
{
    size_t kept = 0;
    for (size_t t = 0; t < nt; ++t) {
        cdl_vec3 a = xyz_at(xyz, tri[3 * t]), b = xyz_at(xyz, tri[3 * t + 1]), c = xyz_at(xyz, tri[3 * t + 2]);
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a));
        double scale = cdl_vec3_length_squared(cdl_vec3_sub(b, a)) + cdl_vec3_length_squared(cdl_vec3_sub(c, a));
        if (!(cdl_vec3_length(n) > 1e-12 * scale)) continue;
        memmove(&tri[3 * kept], &tri[3 * t], 3 * sizeof *tri);
        ++kept;
    }
    return kept;
}

static cdl_status init_triangles(cdl_patch_state *ps, const cdl_patch *p, const cdl_surface_mesh_settings *s,
                                 cdl_error *err)
{
    cdl_trimesh mesh = {0};
    cdl_error remesh_err;
    cdl_status st = p->kind == CDL_PATCH_SPHERE
                        ? cdl_remesh_sphere((const double[3]){p->center.x, p->center.y, p->center.z}, p->radius,
                                            p->inward, p->max_edge, &mesh, err)
                        : cdl_remesh_triangles(p->xyz, p->vertex_count, p->triangles, p->triangle_count, p->max_edge,
                                               s->feature_angle_deg, &mesh, &remesh_err);
    if (st == CDL_ERR_INPUT && p->kind == CDL_PATCH_TRIANGLES) {
        /* Not a manifold: refined as given. */
        ps->as_given = 1;
        mesh.xyz = malloc((p->vertex_count + 1) * 3 * sizeof *mesh.xyz);
        mesh.triangles = malloc((p->triangle_count + 1) * 3 * sizeof *mesh.triangles);
        if (!mesh.xyz || !mesh.triangles) {
            cdl_trimesh_release(&mesh);
            return cdl_error_out_of_memory(err);
        }
        memcpy(mesh.xyz, p->xyz, p->vertex_count * 3 * sizeof *mesh.xyz);
        memcpy(mesh.triangles, p->triangles, p->triangle_count * 3 * sizeof *mesh.triangles);
        mesh.vertex_count = p->vertex_count;
        mesh.triangle_count = p->triangle_count;
        st = CDL_OK;
    } else if (st != CDL_OK && p->kind == CDL_PATCH_TRIANGLES) {
        if (err) *err = remesh_err;
    }
    if (st != CDL_OK) return st;
    uint32_t *region = NULL;
    if (p->kind == CDL_PATCH_TRIANGLES) {
        mesh.triangle_count = drop_degenerate(mesh.xyz, mesh.triangles, mesh.triangle_count);
        st = mesh_regions(mesh.xyz, mesh.triangles, mesh.triangle_count, s->feature_angle_deg, &region, err);
    }
    if (st == CDL_OK && mesh.triangle_count == 0)
        st = cdl_error_set(err, CDL_ERR_INPUT, "the mesh has no triangle of any area");
    if (st == CDL_OK)
        st = cdl_bisect_mesh_create(mesh.xyz, mesh.vertex_count, mesh.triangles, region, mesh.triangle_count,
                                    p->center, p->kind == CDL_PATCH_SPHERE ? p->radius : 0.0, &ps->bisect, err);
    for (size_t v = 0; st == CDL_OK && v < mesh.vertex_count; ++v) cdl_bounds3_grow(&ps->bounds, xyz_at(mesh.xyz, (uint32_t)v));
    free(region);
    cdl_trimesh_release(&mesh);
    return st;
}

static cdl_status init_polygon(cdl_patch_state *ps, const cdl_patch *p, size_t max_vertices, cdl_error *err)
{
    cdl_polygon_problem problem;
    if (!cdl_polygon_check(&p->outer, p->holes, p->hole_count, &ps->plane, &problem))
        return cdl_error_set(err, CDL_ERR_INPUT, "the polygon is not valid (defect %d at ring %ld, vertex %zu)",
                             (int)problem.defect, problem.ring, problem.vertex);
    size_t total = p->outer.count;
    for (size_t h = 0; h < p->hole_count; ++h) total += p->holes[h].count;
    double *xy = malloc((2 * total + 2 * p->seed_count + 2) * sizeof *xy);
    cdl_ring2d *rings = malloc((p->hole_count + 1) * sizeof *rings);
    if (!xy || !rings) {
        free(xy);
        free(rings);
        return cdl_error_out_of_memory(err);
    }
    size_t k = 0;
    for (size_t r = 0; r <= p->hole_count; ++r) {
        const cdl_ring3 *ring = r == 0 ? &p->outer : &p->holes[r - 1];
        rings[r] = (cdl_ring2d){&xy[2 * k], ring->count};
        for (size_t i = 0; i < ring->count; ++i, ++k) {
            cdl_polygon_project(&ps->plane, ring->points[i], &xy[2 * k], &xy[2 * k + 1]);
            cdl_bounds3_grow(&ps->bounds, ring->points[i]);
        }
    }
    cdl_status st = cdl_cdt2d_create(rings[0], rings + 1, p->hole_count, p->max_edge, max_vertices, &ps->cdt, err);
    size_t inserted = 0;
    double *seeds = &xy[2 * total];
    for (size_t i = 0; i < p->seed_count; ++i) cdl_polygon_project(&ps->plane, p->seeds[i], &seeds[2 * i], &seeds[2 * i + 1]);
    if (st == CDL_OK && p->seed_count) st = cdl_cdt2d_insert_inside(ps->cdt, seeds, p->seed_count, &inserted, err);
    if (st == CDL_OK && inserted) st = cdl_cdt2d_improve(ps->cdt, p->max_edge, max_vertices, err);
    free(xy);
    free(rings);
    return st;
}

cdl_status cdl_patch_state_init(cdl_patch_state *ps, const cdl_patch *spec, const cdl_surface_mesh_settings *settings,
                                cdl_error *err)
{
    memset(ps, 0, sizeof *ps);
    ps->spec = spec;
    ps->bounds = cdl_bounds3_empty();
    if (!(spec->max_edge > 0.0) || !isfinite(spec->max_edge))
        return cdl_error_set(err, CDL_ERR_INPUT, "a patch's largest edge must be positive");
    switch (spec->kind) {
    case CDL_PATCH_POLYGON:
        return init_polygon(ps, spec, settings->max_vertices, err);
    case CDL_PATCH_SPHERE:
        if (!(spec->radius > 0.0) || !isfinite(spec->radius))
            return cdl_error_set(err, CDL_ERR_INPUT, "a sphere's radius must be positive");
        return init_triangles(ps, spec, settings, err);
    case CDL_PATCH_TRIANGLES:
        return init_triangles(ps, spec, settings, err);
    }
    return cdl_error_set(err, CDL_ERR_INPUT, "unknown patch kind %d", (int)spec->kind);
}

void cdl_patch_state_release(cdl_patch_state *ps)
{
    cdl_cdt2d_release(ps->cdt);
    cdl_bisect_mesh_release(ps->bisect);
    free(ps->tri);
    free(ps->tri_region);
    free(ps->slots);
    free(ps->tests);
    cdl_key_table_release(&ps->slot_of);
    cdl_key_table_release(&ps->test_of);
    memset(ps, 0, sizeof *ps);
}

/* ---- vertices, slots, tests ------------------------------------------------------ */

size_t cdl_patch_state_vertex_count(const cdl_patch_state *ps)
{
    return ps->cdt ? cdl_cdt2d_vertex_count(ps->cdt) : cdl_bisect_mesh_vertex_count(ps->bisect);
}

cdl_vec3 cdl_patch_state_position(const cdl_patch_state *ps, uint32_t vertex)
{
    if (!ps->cdt) return cdl_bisect_mesh_vertex(ps->bisect, vertex);
    double xy[2];
    cdl_cdt2d_vertex(ps->cdt, vertex, xy, NULL);
    return cdl_polygon_lift(&ps->plane, xy[0], xy[1]);
}

int cdl_patch_state_on_outline(const cdl_patch_state *ps, uint32_t vertex)
{
    if (!ps->cdt) return 0;
    double xy[2];
    int on = 0;
    cdl_cdt2d_vertex(ps->cdt, vertex, xy, &on);
    return on;
}

/* The 2D midpoint of a planar patch's edge: where cdl_cdt2d_split_edges puts it. */
static void midpoint_2d(const cdl_patch_state *ps, uint32_t a, uint32_t b, double mid[2])
{
    double pa[2], pb[2];
    cdl_cdt2d_vertex(ps->cdt, a, pa, NULL);
    cdl_cdt2d_vertex(ps->cdt, b, pb, NULL);
    mid[0] = (pa[0] + pb[0]) * 0.5;
    mid[1] = (pa[1] + pb[1]) * 0.5;
}

static cdl_vec3 midpoint(const cdl_patch_state *ps, uint32_t a, uint32_t b)
{
    if (!ps->cdt) return cdl_bisect_mesh_midpoint(ps->bisect, a, b);
    double mid[2];
    midpoint_2d(ps, a, b, mid);
    return cdl_polygon_lift(&ps->plane, mid[0], mid[1]);
}

/* The normal a polygon or sphere gives a point (meshes: from their triangles). */
static cdl_vec3 fixed_normal(const cdl_patch_state *ps, cdl_vec3 p)
{
    if (ps->spec->kind == CDL_PATCH_POLYGON) return ps->plane.normal;
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_sub(p, ps->spec->center));
    return ps->spec->inward ? cdl_vec3_neg(n) : n;
}

size_t cdl_patch_state_slot(const cdl_patch_state *ps, uint32_t vertex, uint32_t region)
{
    return cdl_key_table_find(&ps->slot_of, cdl_key_ordered(vertex, region));
}

size_t cdl_patch_state_test(const cdl_patch_state *ps, uint32_t a, uint32_t b, uint32_t region)
{
    for (size_t t = cdl_key_table_find(&ps->test_of, cdl_key_pair(a, b)); t != CDL_KEY_TABLE_NONE; t = ps->tests[t].next)
        if (ps->tests[t].region == region) return t;
    return CDL_KEY_TABLE_NONE;
}

static cdl_status add_slot(cdl_patch_state *ps, uint32_t vertex, uint32_t region, size_t *slot, cdl_error *err)
{
    *slot = cdl_patch_state_slot(ps, vertex, region);
    if (*slot != CDL_KEY_TABLE_NONE) return CDL_OK;
    if (cdl_grow(&ps->slots, &ps->slot_capacity, ps->slot_count + 1, sizeof *ps->slots, 256, err) != CDL_OK)
        return CDL_ERR_INTERNAL;
    *slot = ps->slot_count;
    cdl_vec3 p = cdl_patch_state_position(ps, vertex);
    ps->slots[ps->slot_count++] = (cdl_patch_slot){vertex, region,
                                                   ps->spec->kind == CDL_PATCH_TRIANGLES ? cdl_vec3_make(0, 0, 0)
                                                                                         : fixed_normal(ps, p),
                                                   0.0, 0.0, 0.0, {0.0}, 0};
    return cdl_key_table_put(&ps->slot_of, cdl_key_ordered(vertex, region), *slot, err);
}

/* A new test for edge ab in region (its normal, for meshes, summed by the caller). */
static cdl_status add_test(cdl_patch_state *ps, uint32_t a, uint32_t b, uint32_t region, size_t *test, cdl_error *err)
{
    if (cdl_grow(&ps->tests, &ps->test_capacity, ps->test_count + 1, sizeof *ps->tests, 256, err) != CDL_OK)
        return CDL_ERR_INTERNAL;
    uint64_t key = cdl_key_pair(a, b);
    *test = ps->test_count;
    cdl_vec3 p = midpoint(ps, a, b);
    ps->tests[ps->test_count++] = (cdl_patch_test){key, region, cdl_key_table_find(&ps->test_of, key), p,
                                                   ps->spec->kind == CDL_PATCH_TRIANGLES ? cdl_vec3_make(0, 0, 0)
                                                                                         : fixed_normal(ps, p),
                                                   0.0, 0.0, 0.0, {0.0}, 0};
    return cdl_key_table_put(&ps->test_of, key, *test, err);
}

/* The angle of triangle abc at a. */
static double corner_angle(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    cdl_vec3 u = cdl_vec3_sub(b, a), v = cdl_vec3_sub(c, a);
    return atan2(cdl_vec3_length(cdl_vec3_cross(u, v)), cdl_vec3_dot(u, v));
}

static cdl_status take_triangles(cdl_patch_state *ps, cdl_error *err)
{
    free(ps->tri);
    free(ps->tri_region);
    ps->tri = ps->tri_region = NULL;
    ps->tri_count = 0;
    size_t n;
    uint32_t *tri;
    if (ps->cdt) {
        if (cdl_cdt2d_triangles(ps->cdt, &tri, &n, err) != CDL_OK) return CDL_ERR_INTERNAL;
    } else {
        n = cdl_bisect_mesh_triangle_count(ps->bisect);
        tri = malloc((n + 1) * 3 * sizeof *tri);
        if (tri) memcpy(tri, cdl_bisect_mesh_triangles(ps->bisect), n * 3 * sizeof *tri);
    }
    uint32_t *region = calloc(n + 1, sizeof *region);
    if (!tri || !region) {
        free(tri);
        free(region);
        return cdl_error_out_of_memory(err);
    }
    if (ps->bisect) memcpy(region, cdl_bisect_mesh_regions(ps->bisect), n * sizeof *region);
    ps->tri = tri;
    ps->tri_region = region;
    ps->tri_count = n;
    return CDL_OK;
}

cdl_status cdl_patch_state_refresh(cdl_patch_state *ps, cdl_error *err)
{
    if (take_triangles(ps, err) != CDL_OK) return CDL_ERR_INTERNAL;
    int mesh = ps->spec->kind == CDL_PATCH_TRIANGLES;
    size_t first_new_test = ps->test_count;
    if (mesh)
        for (size_t s = 0; s < ps->slot_count; ++s) ps->slots[s].normal = cdl_vec3_make(0, 0, 0);
    for (size_t t = 0; t < ps->tri_count; ++t) {
        const uint32_t *v = &ps->tri[3 * t];
        uint32_t region = ps->tri_region[t];
        cdl_vec3 p[3] = {cdl_patch_state_position(ps, v[0]), cdl_patch_state_position(ps, v[1]),
                         cdl_patch_state_position(ps, v[2])};
        cdl_vec3 face = triangle_normal(p[0], p[1], p[2]);
        for (size_t k = 0; k < 3; ++k) {
            size_t slot, test;
            if (add_slot(ps, v[k], region, &slot, err) != CDL_OK) return CDL_ERR_INTERNAL;
            /* Angle-weighted normals (Thurmer and Wuthrich, "Computing vertex
             * normals from polygonal facets", JGT 3(1), 1998): unchanged when a
             * triangle is bisected, so a vertex keeps its normal as the mesh refines. */
            if (mesh)
                ps->slots[slot].normal = cdl_vec3_madd(ps->slots[slot].normal,
                                                       corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]), face);
            uint32_t a = v[k], b = v[(k + 1) % 3];
            test = cdl_patch_state_test(ps, a, b, region);
            if (test == CDL_KEY_TABLE_NONE && add_test(ps, a, b, region, &test, err) != CDL_OK) return CDL_ERR_INTERNAL;
            /* The vertex splitting an edge gets an angle of pi in each of its
             * triangles: its normal is the sum of their normals. */
            if (mesh && test >= first_new_test) ps->tests[test].normal = cdl_vec3_add(ps->tests[test].normal, face);
        }
    }
    if (mesh) {
        for (size_t s = 0; s < ps->slot_count; ++s) ps->slots[s].normal = cdl_vec3_normalize(ps->slots[s].normal);
        for (size_t t = first_new_test; t < ps->test_count; ++t)
            ps->tests[t].normal = cdl_vec3_normalize(ps->tests[t].normal);
    }
    return CDL_OK;
}

/* ---- splitting -------------------------------------------------------------------- */

/* A new vertex made at the midpoint of edge ab takes the values of the
 * edge's tests, region by region. */
static cdl_status inherit(cdl_patch_state *ps, uint32_t vertex, uint32_t a, uint32_t b, cdl_error *err)
{
    for (size_t t = cdl_key_table_find(&ps->test_of, cdl_key_pair(a, b)); t != CDL_KEY_TABLE_NONE; t = ps->tests[t].next) {
        if (!ps->tests[t].known) continue;
        size_t slot;
        if (add_slot(ps, vertex, ps->tests[t].region, &slot, err) != CDL_OK) return CDL_ERR_INTERNAL;
        if (ps->slots[slot].known) continue;
        ps->slots[slot].value = ps->tests[t].value;
        ps->slots[slot].sigma = ps->tests[t].sigma;
        ps->slots[slot].noise = ps->tests[t].noise;
        memcpy(ps->slots[slot].aux, ps->tests[t].aux, sizeof ps->slots[slot].aux);
        ps->slots[slot].known = 1;
    }
    return CDL_OK;
}

static cdl_status split_planar(cdl_patch_state *ps, const uint64_t *edges, size_t count, size_t max_vertices,
                               cdl_error *err)
{
    uint32_t *ab = calloc(2 * count + 1, sizeof *ab);
    double *xy = calloc(2 * count + 1, sizeof *xy);
    size_t *new_id = malloc((count + 1) * sizeof *new_id);
    cdl_status st = ab && xy && new_id ? CDL_OK : cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < count; ++k) {
        ab[2 * k] = (uint32_t)(edges[k] >> 32);
        ab[2 * k + 1] = (uint32_t)edges[k];
        midpoint_2d(ps, ab[2 * k], ab[2 * k + 1], &xy[2 * k]);
    }
    if (st == CDL_OK) st = cdl_cdt2d_split_edges(ps->cdt, ab, xy, count, new_id, err);
    for (size_t k = 0; st == CDL_OK && k < count; ++k)
        if (new_id[k] != SIZE_MAX) st = inherit(ps, (uint32_t)new_id[k], ab[2 * k], ab[2 * k + 1], err);
    if (st == CDL_OK) st = cdl_cdt2d_improve(ps->cdt, ps->spec->max_edge, max_vertices, err);
    free(ab);
    free(xy);
    free(new_id);
    return st;
}

cdl_status cdl_patch_state_split(cdl_patch_state *ps, const uint64_t *edges, size_t count, size_t max_vertices,
                                 cdl_error *err)
{
    if (ps->cdt) return split_planar(ps, edges, count, max_vertices, err);
    size_t first = cdl_bisect_mesh_vertex_count(ps->bisect);
    for (size_t k = 0; k < count; ++k) {
        uint32_t mid;
        if (cdl_bisect_mesh_split(ps->bisect, (uint32_t)(edges[k] >> 32), (uint32_t)edges[k], &mid, err) != CDL_OK)
            return CDL_ERR_INTERNAL;
    }
    /* Every new vertex, those longest-edge bisection made on the way included. */
    size_t last = cdl_bisect_mesh_vertex_count(ps->bisect);
    for (size_t v = first; v < last; ++v) {
        uint32_t a, b;
        cdl_bisect_mesh_parent(ps->bisect, (uint32_t)v, &a, &b);
        if (inherit(ps, (uint32_t)v, a, b, err) != CDL_OK) return CDL_ERR_INTERNAL;
    }
    return CDL_OK;
}
