/* bisect_mesh.c - longest-edge bisection with conforming splits (bisect_mesh.h).
 *
 * Each edge keeps the list of triangle corners ("half-edges", 3 t + k for
 * the edge from corner k to corner k + 1 of triangle t) that run along it,
 * linked through next[]; the key table maps the edge's vertex pair to the
 * head of its list. Splitting unlinks a triangle's three half-edges,
 * rewrites it as one half and appends the other, and links both.
 */
#include "solver/geometry/bisect_mesh.h"

#include <stdlib.h>
#include <string.h>

#include "solver/geometry/key_table.h"
#include "base/error_report.h"

/* An edge whose list is empty (it was split): kept in the table, since
 * keys are never removed. */
#define EMPTY_LIST (SIZE_MAX - 1)

struct cdl_bisect_mesh {
    cdl_vec3 *xyz;
    uint32_t *parent;          /* 2 per vertex */
    size_t vertex_count, vertex_capacity;
    uint32_t *tri;             /* 3 per triangle */
    uint32_t *region;
    size_t *next;              /* 3 per triangle: the next half-edge on the same edge */
    size_t triangle_count, triangle_capacity;
    cdl_key_table edges;       /* edge -> first half-edge, or EMPTY_LIST */
    cdl_vec3 center;
    double radius;             /* > 0: a sphere */
};

static uint32_t corner(const cdl_bisect_mesh *m, size_t h)
{
    return m->tri[h];
}

static uint32_t corner_after(const cdl_bisect_mesh *m, size_t h)
{
    return m->tri[3 * (h / 3) + (h % 3 + 1) % 3];
}

static uint64_t halfedge_key(const cdl_bisect_mesh *m, size_t h)
{
    return cdl_key_pair(corner(m, h), corner_after(m, h));
}

static size_t list_head(const cdl_bisect_mesh *m, uint64_t key)
{
    size_t head = cdl_key_table_find(&m->edges, key);
    return head == EMPTY_LIST ? CDL_KEY_TABLE_NONE : head;
}

static cdl_status link_halfedge(cdl_bisect_mesh *m, size_t h, cdl_error *err)
{
    uint64_t key = halfedge_key(m, h);
    m->next[h] = list_head(m, key);
    return cdl_key_table_put(&m->edges, key, h, err);
}

/* Unlinking never allocates: the key is present (its half-edge is on it). */
static void unlink_halfedge(cdl_bisect_mesh *m, size_t h)
{
    uint64_t key = halfedge_key(m, h);
    size_t head = list_head(m, key);
    if (head == h) {
        cdl_key_table_put(&m->edges, key, m->next[h] == CDL_KEY_TABLE_NONE ? EMPTY_LIST : m->next[h], NULL);
        return;
    }
    for (size_t p = head; p != CDL_KEY_TABLE_NONE; p = m->next[p])
        if (m->next[p] == h) {
            m->next[p] = m->next[h];
            return;
        }
}

static cdl_status link_triangle(cdl_bisect_mesh *m, size_t t, cdl_error *err)
{
    for (size_t k = 0; k < 3; ++k)
        if (link_halfedge(m, 3 * t + k, err) != CDL_OK) return CDL_ERR_INTERNAL;
    return CDL_OK;
}

static cdl_status reserve_vertices(cdl_bisect_mesh *m, size_t n, cdl_error *err)
{
    if (n <= m->vertex_capacity) return CDL_OK;
    size_t cap = m->vertex_capacity ? m->vertex_capacity : 64;
    while (cap < n) cap *= 2;
    cdl_vec3 *xyz = realloc(m->xyz, cap * sizeof *xyz);
    if (xyz) m->xyz = xyz;
    uint32_t *parent = realloc(m->parent, cap * 2 * sizeof *parent);
    if (parent) m->parent = parent;
    if (!xyz || !parent) return cdl_error_out_of_memory(err);
    m->vertex_capacity = cap;
    return CDL_OK;
}

static cdl_status reserve_triangles(cdl_bisect_mesh *m, size_t n, cdl_error *err)
{
    if (n <= m->triangle_capacity) return CDL_OK;
    size_t cap = m->triangle_capacity ? m->triangle_capacity : 64;
    while (cap < n) cap *= 2;
    uint32_t *tri = realloc(m->tri, cap * 3 * sizeof *tri);
    if (tri) m->tri = tri;
    uint32_t *region = realloc(m->region, cap * sizeof *region);
    if (region) m->region = region;
    size_t *next = realloc(m->next, cap * 3 * sizeof *next);
    if (next) m->next = next;
    if (!tri || !region || !next) return cdl_error_out_of_memory(err);
    m->triangle_capacity = cap;
    return CDL_OK;
}

cdl_status cdl_bisect_mesh_create(const double *xyz, size_t vertex_count, const uint32_t *triangles,
                                  const uint32_t *region, size_t triangle_count, cdl_vec3 sphere_center,
                                  double sphere_radius, cdl_bisect_mesh **out, cdl_error *err)
{
    *out = NULL;
    if (vertex_count >= CDL_BISECT_NONE)
        return cdl_error_set(err, CDL_ERR_INPUT, "a mesh to refine has too many vertices (%zu)", vertex_count);
    for (size_t t = 0; t < triangle_count; ++t) {
        const uint32_t *v = &triangles[3 * t];
        if (v[0] >= vertex_count || v[1] >= vertex_count || v[2] >= vertex_count)
            return cdl_error_set(err, CDL_ERR_INPUT, "triangle %zu names a vertex that does not exist", t);
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
            return cdl_error_set(err, CDL_ERR_INPUT, "triangle %zu uses a vertex twice", t);
    }
    cdl_bisect_mesh *m = calloc(1, sizeof *m);
    if (!m) return cdl_error_out_of_memory(err);
    m->center = sphere_center;
    m->radius = sphere_radius > 0.0 ? sphere_radius : 0.0;
    cdl_status st = reserve_vertices(m, vertex_count, err);
    if (st == CDL_OK) st = reserve_triangles(m, triangle_count, err);
    for (size_t v = 0; st == CDL_OK && v < vertex_count; ++v) {
        m->xyz[v] = cdl_vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
        m->parent[2 * v] = m->parent[2 * v + 1] = CDL_BISECT_NONE;
    }
    m->vertex_count = vertex_count;
    if (st == CDL_OK) {
        memcpy(m->tri, triangles, triangle_count * 3 * sizeof *m->tri);
        for (size_t t = 0; t < triangle_count; ++t) m->region[t] = region ? region[t] : 0;
        m->triangle_count = triangle_count;
    }
    for (size_t t = 0; st == CDL_OK && t < triangle_count; ++t) st = link_triangle(m, t, err);
    if (st != CDL_OK) {
        cdl_bisect_mesh_release(m);
        return st;
    }
    *out = m;
    return CDL_OK;
}

void cdl_bisect_mesh_release(cdl_bisect_mesh *mesh)
{
    if (!mesh) return;
    free(mesh->xyz);
    free(mesh->parent);
    free(mesh->tri);
    free(mesh->region);
    free(mesh->next);
    cdl_key_table_release(&mesh->edges);
    free(mesh);
}

size_t cdl_bisect_mesh_vertex_count(const cdl_bisect_mesh *mesh)
{
    return mesh->vertex_count;
}

cdl_vec3 cdl_bisect_mesh_vertex(const cdl_bisect_mesh *mesh, uint32_t id)
{
    return mesh->xyz[id];
}

void cdl_bisect_mesh_parent(const cdl_bisect_mesh *mesh, uint32_t id, uint32_t *a, uint32_t *b)
{
    *a = mesh->parent[2 * id];
    *b = mesh->parent[2 * id + 1];
}

size_t cdl_bisect_mesh_triangle_count(const cdl_bisect_mesh *mesh)
{
    return mesh->triangle_count;
}

const uint32_t *cdl_bisect_mesh_triangles(const cdl_bisect_mesh *mesh)
{
    return mesh->tri;
}

const uint32_t *cdl_bisect_mesh_regions(const cdl_bisect_mesh *mesh)
{
    return mesh->region;
}

cdl_vec3 cdl_bisect_mesh_midpoint(const cdl_bisect_mesh *mesh, uint32_t a, uint32_t b)
{
    cdl_vec3 mid = cdl_vec3_scale(cdl_vec3_add(mesh->xyz[a], mesh->xyz[b]), 0.5);
    if (!(mesh->radius > 0.0)) return mid;
    cdl_vec3 d = cdl_vec3_sub(mid, mesh->center);
    double len = cdl_vec3_length(d);
    return len > 0.0 ? cdl_vec3_madd(mesh->center, mesh->radius / len, d) : mid;
}

/* The strict order of edges longest-edge bisection goes by: length, then
 * the vertex pair's key (so equal lengths never tie). */
static int edge_longer(const cdl_bisect_mesh *m, size_t h, size_t g)
{
    double lh = cdl_vec3_length_squared(cdl_vec3_sub(m->xyz[corner_after(m, h)], m->xyz[corner(m, h)]));
    double lg = cdl_vec3_length_squared(cdl_vec3_sub(m->xyz[corner_after(m, g)], m->xyz[corner(m, g)]));
    if (lh != lg) return lh > lg;
    return halfedge_key(m, h) > halfedge_key(m, g);
}

static size_t longest_halfedge(const cdl_bisect_mesh *m, size_t t)
{
    size_t best = 3 * t;
    for (size_t k = 1; k < 3; ++k)
        if (edge_longer(m, 3 * t + k, best)) best = 3 * t + k;
    return best;
}

/* Bisect the edge of half-edge list `head` (every triangle on it has it as
 * its longest edge): a new vertex at its midpoint, each triangle (p, q, r)
 * with pq on the edge becomes (p, m, r) and (m, q, r). */
static cdl_status bisect(cdl_bisect_mesh *m, size_t head, uint32_t *new_vertex, cdl_error *err)
{
    uint32_t a = corner(m, head), b = corner_after(m, head);
    size_t count = 0;
    for (size_t h = head; h != CDL_KEY_TABLE_NONE; h = m->next[h]) ++count;
    if (reserve_vertices(m, m->vertex_count + 1, err) != CDL_OK ||
        reserve_triangles(m, m->triangle_count + count, err) != CDL_OK)
        return CDL_ERR_INTERNAL;
    size_t *halves = malloc(count * sizeof *halves);
    if (!halves) return cdl_error_out_of_memory(err);
    count = 0;
    for (size_t h = head; h != CDL_KEY_TABLE_NONE; h = m->next[h]) halves[count++] = h;
    uint32_t mid = (uint32_t)m->vertex_count++;
    m->xyz[mid] = cdl_bisect_mesh_midpoint(m, a, b);
    m->parent[2 * mid] = a;
    m->parent[2 * mid + 1] = b;
    cdl_status st = CDL_OK;
    for (size_t i = 0; st == CDL_OK && i < count; ++i) {
        size_t t = halves[i] / 3, k = halves[i] % 3;
        uint32_t p = m->tri[3 * t + k], q = m->tri[3 * t + (k + 1) % 3], r = m->tri[3 * t + (k + 2) % 3];
        for (size_t j = 0; j < 3; ++j) unlink_halfedge(m, 3 * t + j);
        size_t u = m->triangle_count++;
        uint32_t first[3] = {p, mid, r}, second[3] = {mid, q, r};
        memcpy(&m->tri[3 * t], first, sizeof first);
        memcpy(&m->tri[3 * u], second, sizeof second);
        m->region[u] = m->region[t];
        st = link_triangle(m, t, err);
        if (st == CDL_OK) st = link_triangle(m, u, err);
    }
    free(halves);
    *new_vertex = mid;
    return st;
}

cdl_status cdl_bisect_mesh_split(cdl_bisect_mesh *mesh, uint32_t a, uint32_t b, uint32_t *new_vertex,
                                 cdl_error *err)
{
    *new_vertex = CDL_BISECT_NONE;
    /* A stack of edges waiting to be split, each longer than the one below
     * it (in the strict order above), so it is never deeper than the mesh
     * has edges; its bottom is ab. */
    size_t depth = 0, capacity = 16;
    uint64_t *stack = malloc(capacity * sizeof *stack);
    if (!stack) return cdl_error_out_of_memory(err);
    stack[depth++] = cdl_key_pair(a, b);
    cdl_status st = CDL_OK;
    while (st == CDL_OK && depth > 0) {
        size_t head = list_head(mesh, stack[depth - 1]);
        if (head == CDL_KEY_TABLE_NONE) { /* gone (or never an edge) */
            --depth;
            continue;
        }
        size_t longer = CDL_KEY_TABLE_NONE;
        for (size_t h = head; h != CDL_KEY_TABLE_NONE && longer == CDL_KEY_TABLE_NONE; h = mesh->next[h]) {
            size_t l = longest_halfedge(mesh, h / 3);
            if (halfedge_key(mesh, l) != stack[depth - 1]) longer = l;
        }
        if (longer == CDL_KEY_TABLE_NONE) {
            uint32_t mid = CDL_BISECT_NONE;
            st = bisect(mesh, head, &mid, err);
            if (depth == 1) *new_vertex = mid;
            --depth;
            continue;
        }
        if (depth == capacity) {
            uint64_t *grown = realloc(stack, 2 * capacity * sizeof *stack);
            if (!grown) {
                st = cdl_error_out_of_memory(err);
                break;
            }
            stack = grown;
            capacity *= 2;
        }
        stack[depth++] = halfedge_key(mesh, longer);
    }
    free(stack);
    return st;
}
