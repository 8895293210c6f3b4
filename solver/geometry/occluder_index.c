/* occluder_index.c - double-precision BVH answering convex-region queries. */
#include "solver/geometry/occluder_index.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "radiometry/constants.h"

#define LEAF_SIZE 4

typedef struct prim {
    cdl_bounds3 box;
    double centroid[3];
    uint32_t index;    /* triangle index, or triangle_count + sphere index */
    uint32_t owner;
} prim;

typedef struct node {
    cdl_bounds3 box;
    uint32_t first;    /* leaf: first prim; inner: right child index */
    uint16_t count;    /* leaf: number of prims; 0 for inner nodes */
} node;

struct cdl_occluder_index {
    double *vertices;        /* triangle corners, 9 per triangle */
    size_t triangle_count;
    double *spheres;         /* cx cy cz r */
    size_t sphere_count;
    prim *prims;
    size_t prim_count;
    node *nodes;
    size_t node_count;
};

/* Reorder p[0..n) so that p[k] has the k-th smallest centroid along `axis`,
 * smaller ones before it and larger ones after (quickselect, Hoare
 * partition, median-of-three pivot: deterministic, O(n) on average). */
static void select_kth(prim *p, size_t n, size_t k, int axis)
{
    size_t lo = 0, hi = n - 1;
    while (hi > lo) {
        size_t mid = lo + (hi - lo) / 2;
        double a = p[lo].centroid[axis], b = p[mid].centroid[axis], c = p[hi].centroid[axis];
        double pivot = (a < b) ? ((b < c) ? b : (a < c ? c : a)) : ((a < c) ? a : (b < c ? c : b));
        size_t i = lo, j = hi;
        while (i <= j) {
            while (p[i].centroid[axis] < pivot) ++i;
            while (p[j].centroid[axis] > pivot) --j;
            if (i <= j) {
                prim t = p[i];
                p[i] = p[j];
                p[j] = t;
                ++i;
                if (j == 0) break;
                --j;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return;
    }
}

/* Recursive median split; returns the node index. */
static uint32_t build_node(cdl_occluder_index *ix, size_t first, size_t count)
{
    uint32_t id = (uint32_t)ix->node_count++;
    node *nd = &ix->nodes[id];
    nd->box = cdl_bounds3_empty();
    cdl_bounds3 cbox = cdl_bounds3_empty();
    for (size_t i = first; i < first + count; ++i) {
        cdl_bounds3_merge(&nd->box, ix->prims[i].box);
        const double *c = ix->prims[i].centroid;
        cdl_bounds3_grow(&cbox, cdl_vec3_make(c[0], c[1], c[2]));
    }
    if (count <= LEAF_SIZE) {
        nd->first = (uint32_t)first;
        nd->count = (uint16_t)count;
        return id;
    }
    int axis = 0;
    double ext = -1.0;
    cdl_vec3 size = cdl_vec3_sub(cbox.hi, cbox.lo);
    for (int k = 0; k < 3; ++k)
        if (cdl_vec3_axis(size, k) > ext) {
            ext = cdl_vec3_axis(size, k);
            axis = k;
        }
    size_t half = count / 2;
    select_kth(ix->prims + first, count, half, axis);
    nd->count = 0;
    build_node(ix, first, half);                        /* left child is id + 1 */
    uint32_t right = build_node(ix, first + half, count - half);
    ix->nodes[id].first = right;
    return id;
}

cdl_status cdl_occluder_index_build(const cdl_occluder_input *in, cdl_occluder_index **out, cdl_error *err)
{
    *out = NULL;
    cdl_occluder_index *ix = calloc(1, sizeof *ix);
    if (!ix) return cdl_error_out_of_memory(err);
    ix->triangle_count = in->triangle_count;
    ix->sphere_count = in->sphere_count;
    ix->prim_count = in->triangle_count + in->sphere_count;
    ix->vertices = malloc((in->triangle_count ? in->triangle_count : 1) * 9 * sizeof(double));
    ix->spheres = malloc((in->sphere_count ? in->sphere_count : 1) * 4 * sizeof(double));
    ix->prims = malloc((ix->prim_count ? ix->prim_count : 1) * sizeof(prim));
    ix->nodes = malloc((2 * ix->prim_count + 1) * sizeof(node));
    if (!ix->vertices || !ix->spheres || !ix->prims || !ix->nodes) {
        cdl_occluder_index_release(ix);
        return cdl_error_out_of_memory(err);
    }
    for (size_t t = 0; t < in->triangle_count; ++t) {
        prim *p = &ix->prims[t];
        p->box = cdl_bounds3_empty();
        for (int c = 0; c < 3; ++c) {
            const double *v = &in->vertices[3 * in->triangles[3 * t + c]];
            for (int k = 0; k < 3; ++k) ix->vertices[9 * t + 3 * c + k] = v[k];
            cdl_bounds3_grow(&p->box, cdl_vec3_make(v[0], v[1], v[2]));
        }
        cdl_vec3 mid = cdl_bounds3_centre(p->box);
        p->centroid[0] = mid.x;
        p->centroid[1] = mid.y;
        p->centroid[2] = mid.z;
        p->index = (uint32_t)t;
        p->owner = in->triangle_owner ? in->triangle_owner[t] : 0;
    }
    for (size_t s = 0; s < in->sphere_count; ++s) {
        prim *p = &ix->prims[in->triangle_count + s];
        double r = in->sphere_radii[s];
        for (int k = 0; k < 3; ++k) {
            ix->spheres[4 * s + k] = in->sphere_centers[3 * s + k];
            p->centroid[k] = in->sphere_centers[3 * s + k];
        }
        cdl_vec3 c = cdl_vec3_make(p->centroid[0], p->centroid[1], p->centroid[2]);
        p->box.lo = cdl_vec3_sub(c, cdl_vec3_make(r, r, r));
        p->box.hi = cdl_vec3_add(c, cdl_vec3_make(r, r, r));
        ix->spheres[4 * s + 3] = r;
        p->index = (uint32_t)(in->triangle_count + s);
        p->owner = in->sphere_owner ? in->sphere_owner[s] : 0;
    }
    if (ix->prim_count) build_node(ix, 0, ix->prim_count);
    *out = ix;
    return CDL_OK;
}

void cdl_occluder_index_release(cdl_occluder_index *ix)
{
    if (!ix) return;
    free(ix->vertices);
    free(ix->spheres);
    free(ix->prims);
    free(ix->nodes);
    free(ix);
}

size_t cdl_occluder_index_primitive_count(const cdl_occluder_index *ix)
{
    return ix->prim_count;
}

/* The box lies entirely outside the half-space: its corner nearest to the
 * half-space (smallest normal . x) is already beyond the offset. */
static int box_outside(const cdl_bounds3 *b, const cdl_halfspace *h, double offset)
{
    cdl_vec3 n = h->normal;
    double m = n.x * (n.x >= 0.0 ? b->lo.x : b->hi.x) + n.y * (n.y >= 0.0 ? b->lo.y : b->hi.y) +
               n.z * (n.z >= 0.0 ? b->lo.z : b->hi.z);
    return m > offset;
}

/* Sutherland-Hodgman: clip a convex polygon by every half-space; something
 * left means the triangle reaches into the region. */
static int triangle_in_region(const double *v, const cdl_convex_region *r, double tol)
{
    double poly[2][CDL_REGION_MAX_PLANES + 3][3];
    int n = 3, cur = 0;
    memcpy(poly[0], v, 9 * sizeof(double));
    for (int p = 0; p < r->plane_count && n > 0; ++p) {
        const cdl_halfspace *h = &r->planes[p];
        double off = h->offset - tol;
        int m = 0, nxt = 1 - cur;
        for (int i = 0; i < n; ++i) {
            const double *a = poly[cur][i], *b = poly[cur][(i + 1) % n];
            double da = h->normal.x * a[0] + h->normal.y * a[1] + h->normal.z * a[2] - off;
            double db = h->normal.x * b[0] + h->normal.y * b[1] + h->normal.z * b[2] - off;
            if (da < 0.0) memcpy(poly[nxt][m++], a, 3 * sizeof(double));
            if ((da < 0.0) != (db < 0.0)) {
                double t = da / (da - db);
                for (int k = 0; k < 3; ++k) poly[nxt][m][k] = a[k] + t * (b[k] - a[k]);
                ++m;
            }
        }
        n = m;
        cur = nxt;
    }
    return n > 0;
}

static int sphere_in_region(const double *s, const cdl_convex_region *r, double tol)
{
    for (int p = 0; p < r->plane_count; ++p) {
        const cdl_halfspace *h = &r->planes[p];
        double d = h->normal.x * s[0] + h->normal.y * s[1] + h->normal.z * s[2] - s[3];
        if (d >= h->offset - tol) return 0;
    }
    return 1;
}

/* Does the surface of sphere s (cx cy cz r), not its ball, meet the box
 * [lo, hi]? Iff the box's nearest point is no further than r from the centre
 * and its farthest corner no nearer. */
static int sphere_surface_in_box(const double *s, cdl_vec3 lo, cdl_vec3 hi)
{
    const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    double near2 = 0.0, far2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        double c = s[k];
        double dn = c < l[k] ? l[k] - c : (c > h[k] ? c - h[k] : 0.0);
        double df = fmax(fabs(c - l[k]), fabs(c - h[k]));
        near2 += dn * dn;
        far2 += df * df;
    }
    double r2 = s[3] * s[3];
    return near2 <= r2 && r2 <= far2;
}

/* Called for each primitive found in a region; returns 1 to stop the
 * traversal (the query then returns 1). NULL: stop at the first. */
typedef int (*visit_fn)(void *user, const cdl_occluder_index *ix, const prim *pr);

/* The traversal behind the queries; with `surface_box` set, spheres count
 * by their surface meeting that box instead of by their ball. */
static int query(const cdl_occluder_index *ix, const cdl_convex_region *region, double tolerance,
                 uint32_t exclude_owner, const cdl_vec3 *surface_box, visit_fn visit, void *user)
{
    if (!ix->prim_count) return 0;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        uint32_t id = stack[--top];
        const node *nd = &ix->nodes[id];
        int culled = 0;
        for (int p = 0; p < region->plane_count && !culled; ++p)
            culled = box_outside(&nd->box, &region->planes[p], region->planes[p].offset - tolerance);
        if (culled) continue;
        if (nd->count == 0) {
            if (top + 2 > (int)(sizeof stack / sizeof stack[0])) return 1; /* too deep: be conservative */
            stack[top++] = nd->first;
            stack[top++] = id + 1;
            continue;
        }
        for (uint32_t i = nd->first; i < nd->first + nd->count; ++i) {
            const prim *pr = &ix->prims[i];
            if (pr->owner == exclude_owner) continue;
            int hit;
            if (pr->index < ix->triangle_count) {
                hit = triangle_in_region(&ix->vertices[9 * (size_t)pr->index], region, tolerance);
            } else {
                const double *sphere = &ix->spheres[4 * (size_t)(pr->index - ix->triangle_count)];
                hit = surface_box ? sphere_surface_in_box(sphere, surface_box[0], surface_box[1])
                                  : sphere_in_region(sphere, region, tolerance);
            }
            if (hit && (!visit || visit(user, ix, pr))) return 1;
        }
    }
    return 0;
}

int cdl_occluder_index_intersects(const cdl_occluder_index *ix, const cdl_convex_region *region, double tolerance,
                                  uint32_t exclude_owner)
{
    return query(ix, region, tolerance, exclude_owner, NULL, NULL, NULL);
}

int cdl_occluder_index_surface_in_box(const cdl_occluder_index *ix, cdl_vec3 lo, cdl_vec3 hi)
{
    cdl_convex_region box;
    cdl_region_box(&box, lo, hi);
    const cdl_vec3 corners[2] = {lo, hi};
    return query(ix, &box, 0.0, UINT32_MAX, corners, NULL, NULL);
}

typedef struct list_state {
    cdl_occluder_triangle *out;
    size_t max, count;
    cdl_occluder_list_status status;
} list_state;

static int list_visit(void *user, const cdl_occluder_index *ix, const prim *pr)
{
    list_state *ls = user;
    if (pr->index >= ix->triangle_count) {
        ls->status = CDL_OCCLUDERS_SPHERE;
        return 1;
    }
    if (ls->count == ls->max) {
        ls->status = CDL_OCCLUDERS_TOO_MANY;
        return 1;
    }
    cdl_occluder_triangle *t = &ls->out[ls->count++];
    memcpy(t->v, &ix->vertices[9 * (size_t)pr->index], sizeof t->v);
    t->owner = pr->owner;
    return 0;
}

cdl_occluder_list_status cdl_occluder_index_list(const cdl_occluder_index *ix, const cdl_convex_region *region,
                                                 double tolerance, uint32_t exclude_owner,
                                                 cdl_occluder_triangle *out, size_t max, size_t *count)
{
    list_state ls = {out, max, 0, CDL_OCCLUDERS_LISTED};
    if (query(ix, region, tolerance, exclude_owner, NULL, list_visit, &ls)) {
        /* stopped early: too deep a tree (conservative), or a refusal */
        if (ls.status == CDL_OCCLUDERS_LISTED) ls.status = CDL_OCCLUDERS_TOO_MANY;
    }
    *count = ls.count;
    return ls.status;
}

typedef struct box_state {
    cdl_occluder_visit visit;
    void *user;
    int count;
} box_state;

static int box_visit(void *user, const cdl_occluder_index *ix, const prim *pr)
{
    box_state *b = user;
    b->count++;
    if (pr->index < ix->triangle_count)
        b->visit(b->user, &ix->vertices[9 * (size_t)pr->index], 0, pr->owner);
    else
        b->visit(b->user, &ix->spheres[4 * (size_t)(pr->index - ix->triangle_count)], 1, pr->owner);
    return 0;
}

int cdl_occluder_index_visit_box(const cdl_occluder_index *ix, cdl_vec3 lo, cdl_vec3 hi, cdl_occluder_visit visit,
                                 void *user)
{
    cdl_convex_region box;
    cdl_region_box(&box, lo, hi);
    const cdl_vec3 corners[2] = {lo, hi};
    box_state b = {visit, user, 0};
    /* query answers 1 alone when its tree was too deep to finish: count
     * that as something found (conservative). */
    int stopped = query(ix, &box, 0.0, UINT32_MAX, corners, box_visit, &b);
    return stopped && b.count == 0 ? 1 : b.count;
}

int cdl_region_add(cdl_convex_region *r, cdl_vec3 normal, double offset)
{
    if (r->plane_count >= CDL_REGION_MAX_PLANES) return 0;
    r->planes[r->plane_count].normal = normal;
    r->planes[r->plane_count].offset = offset;
    r->plane_count++;
    return 1;
}

void cdl_region_box(cdl_convex_region *r, cdl_vec3 lo, cdl_vec3 hi)
{
    r->plane_count = 0;
    cdl_region_add(r, cdl_vec3_make(1, 0, 0), hi.x);
    cdl_region_add(r, cdl_vec3_make(-1, 0, 0), -lo.x);
    cdl_region_add(r, cdl_vec3_make(0, 1, 0), hi.y);
    cdl_region_add(r, cdl_vec3_make(0, -1, 0), -lo.y);
    cdl_region_add(r, cdl_vec3_make(0, 0, 1), hi.z);
    cdl_region_add(r, cdl_vec3_make(0, 0, -1), -lo.z);
}

int cdl_region_pyramid(cdl_convex_region *r, cdl_vec3 apex, const cdl_vec3 *poly, int count)
{
    r->plane_count = 0;
    if (count < 3 || count > CDL_REGION_MAX_PLANES - 1) return 0;
    cdl_vec3 centroid = cdl_vec3_make(0, 0, 0);
    for (int i = 0; i < count; ++i) centroid = cdl_vec3_add(centroid, poly[i]);
    centroid = cdl_vec3_scale(centroid, 1.0 / count);
    /* Polygon plane (Newell's method), oriented so the apex is inside. */
    cdl_vec3 nrm = cdl_vec3_make(0, 0, 0);
    for (int i = 0; i < count; ++i) {
        cdl_vec3 a = cdl_vec3_sub(poly[i], centroid), b = cdl_vec3_sub(poly[(i + 1) % count], centroid);
        nrm = cdl_vec3_add(nrm, cdl_vec3_cross(a, b));
    }
    nrm = cdl_vec3_normalize(nrm);
    double plane = cdl_vec3_dot(nrm, centroid);
    double apex_side = cdl_vec3_dot(nrm, apex) - plane;
    if (apex_side == 0.0 || !isfinite(apex_side)) return 0;
    if (apex_side > 0.0) {
        nrm = cdl_vec3_neg(nrm);
        plane = -plane;
    }
    cdl_region_add(r, nrm, plane);
    /* Side planes through the apex and each edge, the polygon inside. */
    for (int i = 0; i < count; ++i) {
        cdl_vec3 a = cdl_vec3_sub(poly[i], apex), b = cdl_vec3_sub(poly[(i + 1) % count], apex);
        cdl_vec3 m = cdl_vec3_normalize(cdl_vec3_cross(a, b));
        if (cdl_vec3_dot(m, cdl_vec3_sub(centroid, apex)) > 0.0) m = cdl_vec3_neg(m);
        cdl_region_add(r, m, cdl_vec3_dot(m, apex));
    }
    return 1;
}

void cdl_region_sphere_view(cdl_convex_region *r, cdl_vec3 apex, cdl_vec3 center, double radius)
{
    cdl_vec3 d = cdl_vec3_sub(center, apex);
    double dist = cdl_vec3_length(d);
    if (dist <= radius * (1.0 + 1e-12)) {
        cdl_region_box(r, cdl_vec3_sub(center, cdl_vec3_make(radius, radius, radius)),
                       cdl_vec3_add(center, cdl_vec3_make(radius, radius, radius)));
        return;
    }
    r->plane_count = 0;
    cdl_vec3 a = cdl_vec3_scale(d, 1.0 / dist);
    double sin_a = radius / dist, cos_a = sqrt(fmax(0.0, 1.0 - sin_a * sin_a));
    /* A regular 16-sided pyramid circumscribing the tangent cone (half-angle
     * a = asin(r / d)): plane k has normal m = cos(a) u_k - sin(a) axis
     * through the apex. A cone direction cos(a) axis + sin(a) u(psi) gives
     * m . w = sin(a) cos(a) (cos(psi - psi_k) - 1) <= 0, zero only along
     * u_k: every plane touches the cone along one line and contains it. */
    const int sides = CDL_REGION_SPHERE_SIDES;
    cdl_vec3 e1 = fabs(a.x) < 0.9 ? cdl_vec3_normalize(cdl_vec3_cross(a, cdl_vec3_make(1, 0, 0)))
                                  : cdl_vec3_normalize(cdl_vec3_cross(a, cdl_vec3_make(0, 1, 0)));
    cdl_vec3 e2 = cdl_vec3_cross(a, e1);
    for (int k = 0; k < sides; ++k) {
        double phi = CDL_TWO_PI * k / sides;
        cdl_vec3 u = cdl_vec3_add(cdl_vec3_scale(e1, cos(phi)), cdl_vec3_scale(e2, sin(phi)));
        cdl_vec3 m = cdl_vec3_sub(cdl_vec3_scale(u, cos_a), cdl_vec3_scale(a, sin_a));
        cdl_region_add(r, m, cdl_vec3_dot(m, apex));
    }
    /* Visible points of the sphere lie no further along the axis than the centre. */
    cdl_region_add(r, a, cdl_vec3_dot(a, center));
}
