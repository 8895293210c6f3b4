/* polygon.c - plane, validity and triangulation of polygons with holes.
 *
 * Validity is checked in the polygon's own plane coordinates: a sweep over
 * the edges sorted by their smallest x finds crossings in O(E log E + pairs
 * whose x-ranges overlap), so CAD outlines with thousands of vertices cost
 * little. Orientation tests are plain double arithmetic: a polygon whose
 * edges miss each other by less than about 1e-16 of its size may be judged
 * either way, which no meaningful input does.
 */
#include "solver/geometry/polygon.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "radiometry/frame.h"

/* A polygon whose area is below this fraction of its squared size has no
 * usable normal (its points are collinear up to rounding). */
#define NO_AREA_TOLERANCE 1e-10

void cdl_polygon_project(const cdl_polygon_plane *plane, cdl_vec3 p, double *x, double *y)
{
    cdl_vec3 d = cdl_vec3_sub(p, plane->origin);
    *x = cdl_vec3_dot(d, plane->e1);
    *y = cdl_vec3_dot(d, plane->e2);
}

cdl_vec3 cdl_polygon_lift(const cdl_polygon_plane *plane, double x, double y)
{
    return cdl_vec3_add(plane->origin, cdl_vec3_add(cdl_vec3_scale(plane->e1, x), cdl_vec3_scale(plane->e2, y)));
}

/* Twice the signed area of the triangle abc (positive when counter-clockwise). */
static double orient2d(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* c, known to be on the line ab, lies within the closed segment ab. */
static int within_box(const double *a, const double *b, const double *c)
{
    return c[0] >= fmin(a[0], b[0]) && c[0] <= fmax(a[0], b[0]) && c[1] >= fmin(a[1], b[1]) &&
           c[1] <= fmax(a[1], b[1]);
}

/* Distance from point c to the closed segment ab. */
static double point_segment_distance(const double *a, const double *b, const double *c)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / len2 : 0.0;
    t = fmax(0.0, fmin(1.0, t));
    return hypot(c[0] - (a[0] + t * dx), c[1] - (a[1] + t * dy));
}

/* Do the closed segments pq and rs share a point? */
static int segments_meet(const double *p, const double *q, const double *r, const double *s)
{
    double d1 = orient2d(p, q, r), d2 = orient2d(p, q, s), d3 = orient2d(r, s, p), d4 = orient2d(r, s, q);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 1;
    return (d1 == 0 && within_box(p, q, r)) || (d2 == 0 && within_box(p, q, s)) ||
           (d3 == 0 && within_box(r, s, p)) || (d4 == 0 && within_box(r, s, q));
}

/* Do the segments pq and rs meet, or pass closer than tol? */
static int segments_near(const double *p, const double *q, const double *r, const double *s, double tol)
{
    if (segments_meet(p, q, r, s)) return 1;
    return point_segment_distance(p, q, r) <= tol || point_segment_distance(p, q, s) <= tol ||
           point_segment_distance(r, s, p) <= tol || point_segment_distance(r, s, q) <= tol;
}

/* Crossing-number test of point pt against a ring of n 2D points. */
static int point_in_ring(const double *pt, const double *ring, size_t n)
{
    int inside = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double *a = &ring[2 * i], *b = &ring[2 * j];
        if ((a[1] > pt[1]) != (b[1] > pt[1])) {
            double x = a[0] + (pt[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if (pt[0] < x) inside = !inside;
        }
    }
    return inside;
}

typedef struct edge2d {
    const double *a, *b;
    double min_x, max_x, min_y, max_y;
    long ring;
    size_t index, ring_count;
} edge2d;

static int compare_edges(const void *pa, const void *pb)
{
    const edge2d *a = pa, *b = pb;
    /* Ties broken by position in the file, so reports do not depend on qsort. */
    if (a->min_x != b->min_x) return (a->min_x > b->min_x) - (a->min_x < b->min_x);
    if (a->ring != b->ring) return (a->ring > b->ring) - (a->ring < b->ring);
    return (a->index > b->index) - (a->index < b->index);
}

static int edges_adjacent(const edge2d *e, const edge2d *f)
{
    if (e->ring != f->ring) return 0;
    size_t n = e->ring_count;
    return (e->index + 1) % n == f->index || (f->index + 1) % n == e->index;
}

static const cdl_ring3 *ring_at(const cdl_ring3 *outer, const cdl_ring3 *holes, long r)
{
    return r < 0 ? outer : &holes[r];
}

/* Newell's method relative to the first vertex: the sum of (v_i - v_0) x
 * (v_i+1 - v_0) is twice the vector area, normal to a planar polygon and
 * counter-clockwise positive (Newell 1972; Sutherland et al., "A
 * characterization of ten hidden-surface algorithms", 1974). */
static cdl_vec3 vector_area_twice(const cdl_ring3 *ring)
{
    cdl_vec3 sum = cdl_vec3_make(0, 0, 0), o = ring->points[0];
    for (size_t i = 1; i + 1 < ring->count; ++i)
        sum = cdl_vec3_add(sum, cdl_vec3_cross(cdl_vec3_sub(ring->points[i], o), cdl_vec3_sub(ring->points[i + 1], o)));
    return sum;
}

/* Twice the vector area of the largest triangle found greedily among the
 * ring's points: the first point, the point farthest from it, and the point
 * farthest from the line through those two. Zero when all points lie on
 * one line; otherwise normal to the plane of a planar ring even when the
 * ring's own vector area cancels (a bow tie). */
static cdl_vec3 spanning_area_twice(const cdl_ring3 *ring)
{
    cdl_vec3 a = ring->points[0], b = a, best = cdl_vec3_make(0, 0, 0);
    double far = 0.0, widest = 0.0;
    for (size_t i = 1; i < ring->count; ++i) {
        double d = cdl_vec3_distance(a, ring->points[i]);
        if (d > far) {
            far = d;
            b = ring->points[i];
        }
    }
    for (size_t i = 1; i < ring->count; ++i) {
        cdl_vec3 c = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(ring->points[i], a));
        double w = cdl_vec3_length(c);
        if (w > widest) {
            widest = w;
            best = c;
        }
    }
    return best;
}

static int set_problem(cdl_polygon_problem *pr, cdl_polygon_defect defect, long ring, size_t vertex)
{
    pr->defect = defect;
    pr->ring = ring;
    pr->vertex = vertex;
    return 0;
}

/* Two edges that are not neighbours in a ring must not meet, nor come
 * closer than tol (a feature that small is an artefact, and Delaunay
 * refinement would grade the mesh down to it). */
static int find_crossing(edge2d *edges, size_t n, double tol, cdl_polygon_problem *problem)
{
    qsort(edges, n, sizeof *edges, compare_edges);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n && edges[j].min_x <= edges[i].max_x + tol; ++j) {
            const edge2d *e = &edges[i], *f = &edges[j];
            if (f->min_y > e->max_y + tol || f->max_y < e->min_y - tol || edges_adjacent(e, f)) continue;
            if (!segments_near(e->a, e->b, f->a, f->b, tol)) continue;
            /* Report the edge that comes first in the file first. */
            int swap = f->ring < e->ring || (f->ring == e->ring && f->index < e->index);
            if (swap) {
                const edge2d *t = e;
                e = f;
                f = t;
            }
            set_problem(problem, CDL_POLYGON_CROSSING, e->ring, e->index);
            problem->other_ring = f->ring;
            problem->other_vertex = f->index;
            return 1;
        }
    return 0;
}

/* Checks done in plane coordinates: spikes, crossings, hole placement. */
static int check_in_plane(const cdl_polygon_plane *plane, const cdl_ring3 *outer, const cdl_ring3 *holes,
                          size_t hole_count, cdl_polygon_problem *problem, int *ok)
{
    size_t total = outer->count;
    for (size_t h = 0; h < hole_count; ++h) total += holes[h].count;
    double *xy = malloc(2 * total * sizeof *xy);
    edge2d *edges = malloc(total * sizeof *edges);
    size_t *start = malloc((hole_count + 1) * sizeof *start);
    if (!xy || !edges || !start) {
        free(xy);
        free(edges);
        free(start);
        return 0;
    }
    *ok = 0;
    double tol = CDL_POLYGON_MIN_EDGE * plane->size;
    size_t k = 0;
    for (long r = -1; r < (long)hole_count; ++r) {
        const cdl_ring3 *ring = ring_at(outer, holes, r);
        start[r + 1] = k;
        for (size_t i = 0; i < ring->count; ++i)
            cdl_polygon_project(plane, ring->points[i], &xy[2 * (k + i)], &xy[2 * (k + i) + 1]);
        for (size_t i = 0; i < ring->count; ++i) {
            const double *a = &xy[2 * (k + (i + ring->count - 1) % ring->count)];
            const double *b = &xy[2 * (k + i)], *c = &xy[2 * (k + (i + 1) % ring->count)];
            /* b folds the ring back (or makes a needle too thin to mesh) when c
             * lies on edge ab or a on edge bc, to within tol. */
            if (point_segment_distance(a, b, c) <= tol || point_segment_distance(b, c, a) <= tol) {
                set_problem(problem, CDL_POLYGON_SPIKE, r, i);
                goto done;
            }
            edge2d *e = &edges[k + i];
            e->a = b;
            e->b = c;
            e->min_x = fmin(b[0], c[0]);
            e->max_x = fmax(b[0], c[0]);
            e->min_y = fmin(b[1], c[1]);
            e->max_y = fmax(b[1], c[1]);
            e->ring = r;
            e->index = i;
            e->ring_count = ring->count;
        }
        k += ring->count;
    }
    if (find_crossing(edges, total, tol, problem)) goto done;
    /* No edges meet, so one vertex decides where a whole ring lies. */
    for (size_t h = 0; h < hole_count; ++h) {
        const double *p = &xy[2 * start[h + 1]];
        if (!point_in_ring(p, xy, outer->count)) {
            set_problem(problem, CDL_POLYGON_HOLE_OUTSIDE, (long)h, 0);
            goto done;
        }
        for (size_t g = 0; g < hole_count; ++g)
            if (g != h && point_in_ring(p, &xy[2 * start[g + 1]], holes[g].count)) {
                set_problem(problem, CDL_POLYGON_HOLE_IN_HOLE, (long)h, 0);
                problem->other_ring = (long)g;
                goto done;
            }
    }
    *ok = 1;
done:
    free(xy);
    free(edges);
    free(start);
    return 1;
}

/* The plane of the polygon and its frame, checking what its computation
 * needs (no repeated vertex, an area, every vertex in the plane); the
 * in-plane checks are cdl_polygon_check's. *cancelled: the outline's lobes
 * cancel (no net area), so its normal came from its spanning area. */
static int find_plane(const cdl_ring3 *outer, const cdl_ring3 *holes, size_t hole_count, cdl_polygon_plane *plane,
                      cdl_polygon_problem *problem, int *cancelled_out)
{
    problem->defect = CDL_POLYGON_VALID;
    problem->ring = problem->other_ring = -1;
    problem->vertex = problem->other_vertex = 0;
    problem->distance = 0.0;

    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t i = 0; i < outer->count; ++i) cdl_bounds3_grow(&box, outer->points[i]);
    plane->size = cdl_bounds3_diagonal(box);

    for (long r = -1; r < (long)hole_count; ++r) {
        const cdl_ring3 *ring = ring_at(outer, holes, r);
        for (size_t i = 0; i < ring->count; ++i) {
            cdl_vec3 prev = ring->points[(i + ring->count - 1) % ring->count];
            double d = cdl_vec3_distance(prev, ring->points[i]);
            if (!(d > CDL_POLYGON_MIN_EDGE * plane->size)) {
                set_problem(problem, CDL_POLYGON_REPEATED_VERTEX, r, i);
                problem->distance = d;
                return 0;
            }
        }
    }
    plane->origin = outer->points[0];
    cdl_vec3 area2 = vector_area_twice(outer);
    double area2_len = cdl_vec3_length(area2), min_area2 = NO_AREA_TOLERANCE * plane->size * plane->size;
    int cancelled = !(area2_len > min_area2);
    if (cancelled) {
        /* No net area. Points on one line have no plane either; an outline
         * whose lobes cancel (a bow tie) has one, and the checks in that
         * plane below then name the edges that cross. */
        area2 = spanning_area_twice(outer);
        area2_len = cdl_vec3_length(area2);
        if (!(area2_len > min_area2)) return set_problem(problem, CDL_POLYGON_NO_AREA, -1, 0);
    }
    plane->normal = cdl_vec3_scale(area2, 1.0 / area2_len);

    /* Distances from the plane with that normal through the outer ring's
     * mean point; the vertex farthest from it is reported, the one to fix. */
    cdl_vec3 mean = cdl_vec3_make(0, 0, 0);
    for (size_t i = 0; i < outer->count; ++i) mean = cdl_vec3_add(mean, outer->points[i]);
    mean = cdl_vec3_scale(mean, 1.0 / (double)outer->count);
    double tolerance = CDL_POLYGON_PLANARITY_TOLERANCE * plane->size, worst = 0.0;
    for (long r = -1; r < (long)hole_count; ++r) {
        const cdl_ring3 *ring = ring_at(outer, holes, r);
        for (size_t i = 0; i < ring->count; ++i) {
            double d = fabs(cdl_vec3_dot(cdl_vec3_sub(ring->points[i], mean), plane->normal));
            if (d > tolerance && d > worst) {
                worst = d;
                set_problem(problem, CDL_POLYGON_NOT_PLANAR, r, i);
                problem->distance = d;
            }
        }
    }
    if (worst > 0.0) return 0;

    /* e1 along the first edge, made exactly orthogonal to the normal. */
    cdl_vec3 edge = cdl_vec3_sub(outer->points[1], outer->points[0]);
    edge = cdl_vec3_madd(edge, -cdl_vec3_dot(edge, plane->normal), plane->normal);
    double edge_len = cdl_vec3_length(edge);
    plane->e1 = edge_len > 0.0 ? cdl_vec3_scale(edge, 1.0 / edge_len) : cdl_frame_from_normal(plane->normal).s;
    plane->e2 = cdl_vec3_normalize(cdl_vec3_cross(plane->normal, plane->e1));
    *cancelled_out = cancelled;
    return 1;
}

int cdl_polygon_check(const cdl_ring3 *outer, const cdl_ring3 *holes, size_t hole_count,
                            cdl_polygon_plane *plane, cdl_polygon_problem *problem)
{
    int cancelled = 0;
    if (!find_plane(outer, holes, hole_count, plane, problem, &cancelled)) return 0;
    int ok = 0;
    if (!check_in_plane(plane, outer, holes, hole_count, problem, &ok)) {
        /* Out of memory: the polygon cannot be judged; let triangulation report it. */
        return 1;
    }
    /* A ring without net area that passed the in-plane checks (within their
     * tolerances) still has no usable normal. */
    if (ok && cancelled) return set_problem(problem, CDL_POLYGON_NO_AREA, -1, 0);
    return ok;
}

cdl_status cdl_polygon_plane_of_checked(const cdl_ring3 *outer, const cdl_ring3 *holes, size_t hole_count,
                                        cdl_polygon_plane *plane, cdl_error *err)
{
    cdl_polygon_problem problem;
    int cancelled = 0;
    if (find_plane(outer, holes, hole_count, plane, &problem, &cancelled) && !cancelled) return CDL_OK;
    return cdl_error_set(err, CDL_ERR_INTERNAL,
                         "a polygon the scene loader did not check (defect %d at ring %ld vertex %zu)",
                         (int)problem.defect, problem.ring, problem.vertex);
}

double cdl_polygon_outer_area(const cdl_polygon_plane *plane, const cdl_ring3 *outer)
{
    /* The shoelace formula in the plane's coordinates (Gauss's area formula). */
    double twice = 0.0, x0, y0;
    cdl_polygon_project(plane, outer->points[outer->count - 1], &x0, &y0);
    for (size_t i = 0; i < outer->count; ++i) {
        double x1, y1;
        cdl_polygon_project(plane, outer->points[i], &x1, &y1);
        twice += x0 * y1 - x1 * y0;
        x0 = x1;
        y0 = y1;
    }
    return 0.5 * fabs(twice);
}

cdl_status cdl_polygon_triangulate(const cdl_polygon_plane *plane, const cdl_ring3 *outer,
                                         const cdl_ring3 *holes, size_t hole_count, double max_edge,
                                         size_t max_vertices, cdl_mesh2d *out, cdl_error *err)
{
    size_t total = outer->count;
    for (size_t h = 0; h < hole_count; ++h) total += holes[h].count;
    double *xy = malloc(2 * total * sizeof *xy);
    cdl_ring2d *rings = malloc((hole_count + 1) * sizeof *rings);
    if (!xy || !rings) {
        free(xy);
        free(rings);
        return cdl_error_out_of_memory(err);
    }
    size_t k = 0;
    for (long r = -1; r < (long)hole_count; ++r) {
        const cdl_ring3 *ring = ring_at(outer, holes, r);
        rings[r + 1].xy = &xy[2 * k];
        rings[r + 1].count = ring->count;
        for (size_t i = 0; i < ring->count; ++i, ++k)
            cdl_polygon_project(plane, ring->points[i], &xy[2 * k], &xy[2 * k + 1]);
    }
    cdl_status st = cdl_mesh2d_triangulate_bounded(rings[0], rings + 1, hole_count, max_edge, max_vertices, out, err);
    free(xy);
    free(rings);
    return st;
}
