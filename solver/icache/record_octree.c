/* record_octree.c - records in the cells their spheres overlap, larger higher up. */
#include "base/error_report.h"
#include "solver/icache/record_octree.h"

#include <stdlib.h>
#include <string.h>

/* Deepest level: cells 2^-24 of the root, far below any record's radius. */
#define MAX_DEPTH 24

typedef struct node {
    int32_t child[8];         /* node index, or 0 for none (0 is the root, never a child) */
    uint32_t *ids;
    uint32_t count, capacity;
} node;

struct cdl_record_octree {
    cdl_vec3 centre;
    double half;              /* the root cube's half-size */
    node *nodes;
    size_t count, capacity;
    /* every id stored so far greater than the one before: each cell's ids
     * then ascend (the cache stores its records in id order) */
    int in_order;
    uint32_t last_id;
    size_t stored;            /* inserts so far */
};

cdl_status cdl_record_octree_create(cdl_bounds3 bounds, cdl_record_octree **out, cdl_error *err)
{
    *out = NULL;
    cdl_record_octree *t = calloc(1, sizeof *t);
    if (!t) return cdl_error_out_of_memory(err);
    t->centre = cdl_bounds3_centre(bounds);
    cdl_vec3 d = cdl_vec3_sub(bounds.hi, bounds.lo);
    double h = 0.5 * (d.x > d.y ? (d.x > d.z ? d.x : d.z) : (d.y > d.z ? d.y : d.z));
    t->half = h > 0.0 ? 1.0001 * h : 1.0;
    t->capacity = 64;
    t->nodes = calloc(t->capacity, sizeof *t->nodes);
    if (!t->nodes) {
        free(t);
        return cdl_error_out_of_memory(err);
    }
    t->count = 1;
    t->in_order = 1;
    *out = t;
    return CDL_OK;
}

void cdl_record_octree_release(cdl_record_octree *tree)
{
    if (!tree) return;
    for (size_t i = 0; i < tree->count; ++i) free(tree->nodes[i].ids);
    free(tree->nodes);
    free(tree);
}

static int32_t new_node(cdl_record_octree *t)
{
    if (t->count == t->capacity) {
        node *grown = realloc(t->nodes, 2 * t->capacity * sizeof *grown);
        if (!grown) return -1;
        memset(grown + t->capacity, 0, t->capacity * sizeof *grown);
        t->nodes = grown;
        t->capacity *= 2;
    }
    return (int32_t)t->count++;
}

static int node_add(node *nd, uint32_t id)
{
    if (nd->count == nd->capacity) {
        uint32_t cap = nd->capacity ? 2 * nd->capacity : 4;
        uint32_t *grown = realloc(nd->ids, cap * sizeof *grown);
        if (!grown) return 0;
        nd->ids = grown;
        nd->capacity = cap;
    }
    nd->ids[nd->count++] = id;
    return 1;
}

/* The centre of child `c` of a cell (centre, half). */
static cdl_vec3 child_centre(cdl_vec3 centre, double half, int c)
{
    double q = 0.5 * half;
    return cdl_vec3_make(centre.x + (c & 1 ? q : -q), centre.y + (c & 2 ? q : -q), centre.z + (c & 4 ? q : -q));
}

/* Store id in every cell at depth `level` below `at` (a cell at `depth`)
 * that the box [lo, hi] overlaps. */
static int insert_at(cdl_record_octree *t, int32_t at, int depth, cdl_vec3 centre, double half, int level,
                     uint32_t id, cdl_vec3 lo, cdl_vec3 hi)
{
    if (depth == level) return node_add(&t->nodes[at], id);
    for (int c = 0; c < 8; ++c) {
        cdl_vec3 cc = child_centre(centre, half, c);
        double q = 0.5 * half;
        if (hi.x < cc.x - q || lo.x > cc.x + q || hi.y < cc.y - q || lo.y > cc.y + q || hi.z < cc.z - q ||
            lo.z > cc.z + q)
            continue;
        if (t->nodes[at].child[c] == 0) {
            int32_t k = new_node(t);
            if (k < 0) return 0;
            t->nodes[at].child[c] = k;
        }
        if (!insert_at(t, t->nodes[at].child[c], depth + 1, cc, q, level, id, lo, hi)) return 0;
    }
    return 1;
}

cdl_status cdl_record_octree_insert(cdl_record_octree *tree, uint32_t id, cdl_vec3 centre, double radius,
                                    cdl_error *err)
{
    /* The deepest level whose cells (half-size h / 2^level) still hold the
     * sphere whole: then it overlaps at most 2 cells along each axis. */
    int level = 0;
    double half = tree->half;
    while (level < MAX_DEPTH && 0.5 * half >= radius) {
        half *= 0.5;
        ++level;
    }
    if (tree->stored++ > 0) tree->in_order &= id > tree->last_id;
    tree->last_id = id;
    cdl_vec3 r = cdl_vec3_make(radius, radius, radius);
    if (!insert_at(tree, 0, 0, tree->centre, tree->half, level, id, cdl_vec3_sub(centre, r), cdl_vec3_add(centre, r)))
        return cdl_error_out_of_memory(err);
    return CDL_OK;
}

static int compare_ids(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Merge the ascending run b[0 .. nb - 1] into the ascending a[0 .. na - 1],
 * from the top down into a[0 .. na + nb - 1] (b lies beyond that range:
 * every write lands at or above the element of a it leaves). */
static void merge_run(uint32_t *a, size_t na, const uint32_t *b, size_t nb)
{
    size_t i = na, j = nb, k = na + nb;
    while (j > 0) {
        if (i > 0 && a[i - 1] > b[j - 1]) a[--k] = a[--i];
        else a[--k] = b[--j];
    }
}

size_t cdl_record_octree_lookup(const cdl_record_octree *tree, cdl_vec3 p, uint32_t **ids, size_t *capacity)
{
    size_t n = 0;
    int32_t at = 0;
    cdl_vec3 centre = tree->centre;
    double half = tree->half;
    for (;;) {
        const node *nd = &tree->nodes[at];
        /* room for the run twice: merged in below, and copied above it */
        if (n + 2 * (size_t)nd->count > *capacity) {
            size_t cap = 2 * (n + 2 * (size_t)nd->count) + 16;
            uint32_t *grown = realloc(*ids, cap * sizeof *grown);
            if (!grown) return (size_t)-1;
            *ids = grown;
            *capacity = cap;
        }
        if (nd->count > 0) { /* an empty cell has no array (memcpy from NULL is undefined) */
            /* A cell's ids are in the order they were stored: ascending when
             * they were stored in id order, and then merged run by run;
             * otherwise sorted once at the end. */
            if (tree->in_order) {
                memcpy(*ids + n + nd->count, nd->ids, nd->count * sizeof **ids);
                merge_run(*ids, n, *ids + n + nd->count, nd->count);
            } else {
                memcpy(*ids + n, nd->ids, nd->count * sizeof **ids);
            }
            n += nd->count;
        }
        int c = (p.x >= centre.x) | ((p.y >= centre.y) << 1) | ((p.z >= centre.z) << 2);
        if (nd->child[c] == 0) break;
        centre = child_centre(centre, half, c);
        half *= 0.5;
        at = nd->child[c];
    }
    if (!tree->in_order && n > 1) qsort(*ids, n, sizeof **ids, compare_ids);
    return n;
}
