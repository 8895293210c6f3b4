/* visible_polygon.c - convex pieces of a face minus central projections (see the header). */
#include "solver/geometry/visible_polygon.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/frame.h"

/* Vertices of a triangle clipped by the 6 half-spaces of a projection
 * (near, far, four sides): at most 3 + 6. */
#define CLIP3_MAX 12

/* Pieces smaller than this fraction of the square of the face's size are
 * dropped (slivers left by rounding where two occluders share an edge). */
#define SLIVER_FRACTION 1e-14

void cdl_visible_face_init(cdl_visible_face *f, cdl_vec3 apex, cdl_vec3 toward, cdl_vec3 point_in_plane, int bounded,
                           double near)
{
    memset(f, 0, sizeof *f);
    cdl_frame frame = cdl_frame_from_normal(toward);
    f->apex = apex;
    f->toward = toward;
    f->e1 = frame.s;
    f->e2 = frame.t;
    f->height = cdl_vec3_dot(cdl_vec3_sub(apex, point_in_plane), toward);
    f->bounded = bounded;
    f->near = near;
    f->lo[0] = f->lo[1] = INFINITY;
    f->hi[0] = f->hi[1] = -INFINITY;
    if (!(f->height > 0.0)) f->overflow = 1;
}

void cdl_visible_face_release(cdl_visible_face *f)
{
    free(f->pieces);
    f->pieces = NULL;
    f->count = f->capacity = 0;
}

static double signed_area(const double (*v)[2], int count)
{
    /* Shoelace formula about the first vertex. */
    double a = 0.0;
    for (int i = 1; i + 1 < count; ++i)
        a += (v[i][0] - v[0][0]) * (v[i + 1][1] - v[0][1]) - (v[i + 1][0] - v[0][0]) * (v[i][1] - v[0][1]);
    return 0.5 * a;
}

static double sliver_area(const cdl_visible_face *f)
{
    double dx = f->hi[0] - f->lo[0], dy = f->hi[1] - f->lo[1];
    return SLIVER_FRACTION * (dx * dx + dy * dy);
}

static void push_piece(cdl_visible_face *f, const cdl_visible_piece *p)
{
    if (f->overflow) return;
    if (f->count == f->capacity) {
        size_t cap = f->capacity ? 2 * f->capacity : 16;
        cdl_visible_piece *np = cap <= CDL_VISIBLE_MAX_PIECES ? realloc(f->pieces, cap * sizeof *np) : NULL;
        if (!np) {
            f->overflow = 1;
            return;
        }
        f->pieces = np;
        f->capacity = cap;
    }
    f->pieces[f->count++] = *p;
}

void cdl_visible_face_add_polygon_2d(cdl_visible_face *f, const double (*xy)[2], int count)
{
    if (count < 3 || count > CDL_VISIBLE_MAX_VERTICES) {
        if (count > CDL_VISIBLE_MAX_VERTICES) f->overflow = 1;
        return;
    }
    cdl_visible_piece p;
    p.count = count;
    int ccw = signed_area(xy, count) >= 0.0;
    for (int i = 0; i < count; ++i) {
        const double *v = xy[ccw ? i : count - 1 - i];
        p.v[i][0] = v[0];
        p.v[i][1] = v[1];
        for (int k = 0; k < 2; ++k) {
            f->lo[k] = fmin(f->lo[k], v[k]);
            f->hi[k] = fmax(f->hi[k], v[k]);
        }
    }
    push_piece(f, &p);
}

void cdl_visible_face_add_polygon(cdl_visible_face *f, const cdl_vec3 *points, int count)
{
    double xy[CDL_VISIBLE_MAX_VERTICES][2];
    if (count > CDL_VISIBLE_MAX_VERTICES) {
        f->overflow = 1;
        return;
    }
    cdl_vec3 foot = cdl_vec3_madd(f->apex, -f->height, f->toward);
    for (int i = 0; i < count; ++i) {
        cdl_vec3 d = cdl_vec3_sub(points[i], foot);
        xy[i][0] = cdl_vec3_dot(d, f->e1);
        xy[i][1] = cdl_vec3_dot(d, f->e2);
    }
    cdl_visible_face_add_polygon_2d(f, (const double(*)[2])xy, count);
}

/* ---- 2-D: a convex piece cut by a directed line ----------------------------- */

/* The line through (ax, ay) along (dx, dy); its left side has side() > 0. */
typedef struct line2 {
    double ax, ay, dx, dy;
} line2;

static double side(const line2 *l, const double *v)
{
    return l->dx * (v[1] - l->ay) - l->dy * (v[0] - l->ax);
}

/* 1 if a comes before b lexicographically: intersections along an edge are
 * computed from its first endpoint in this order, so that two pieces (or
 * two occluders) sharing the edge get the same bits. */
static int before2(const double *a, const double *b)
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

/* Keep the part of `in` on the side `keep` (+1 left, -1 right) of the line,
 * boundary included. Returns 0 when nothing of positive extent is left. */
static int cut_piece(const cdl_visible_piece *in, const line2 *l, double keep, cdl_visible_piece *out, int *overflow)
{
    double d[CDL_VISIBLE_MAX_VERTICES];
    int any_in = 0, any_out = 0;
    for (int i = 0; i < in->count; ++i) {
        d[i] = keep * side(l, in->v[i]);
        any_in |= d[i] > 0.0;
        any_out |= d[i] < 0.0;
    }
    if (!any_in) return 0;
    if (!any_out) {
        *out = *in;
        return 1;
    }
    int m = 0;
    for (int i = 0; i < in->count; ++i) {
        int j = (i + 1) % in->count;
        int crosses = (d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0);
        if (m + (d[i] >= 0.0) + crosses > CDL_VISIBLE_MAX_VERTICES) {
            *overflow = 1; /* refuse rather than approximate */
            return 0;
        }
        if (d[i] >= 0.0) {
            out->v[m][0] = in->v[i][0];
            out->v[m][1] = in->v[i][1];
            m++;
        }
        if (crosses) {
            int a = before2(in->v[i], in->v[j]) ? i : j, b = a == i ? j : i;
            double t = d[a] / (d[a] - d[b]);
            out->v[m][0] = in->v[a][0] + t * (in->v[b][0] - in->v[a][0]);
            out->v[m][1] = in->v[a][1] + t * (in->v[b][1] - in->v[a][1]);
            m++;
        }
    }
    out->count = m;
    return m >= 3;
}

void cdl_visible_face_clip(cdl_visible_face *f, double a, double b, double c)
{
    double r2 = a * a + b * b;
    if (!(r2 > 0.0)) {
        if (c < 0.0) f->count = 0;
        return;
    }
    /* a x + b y + c >= 0 is the left side of the line through -c (a, b) / r2 along (b, -a). */
    line2 l = {-c * a / r2, -c * b / r2, b, -a};
    size_t kept = 0;
    double sliver = sliver_area(f);
    for (size_t i = 0; i < f->count; ++i) {
        cdl_visible_piece out;
        if (cut_piece(&f->pieces[i], &l, 1.0, &out, &f->overflow) &&
            signed_area((const double(*)[2])out.v, out.count) > sliver)
            f->pieces[kept++] = out;
    }
    f->count = kept;
}

/* Subtract the convex polygon q (counter-clockwise, n vertices, no two
 * consecutive ones alike: an edge of no length has no direction, and its
 * line would cut the rest anywhere). */
static void subtract_convex(cdl_visible_face *f, const double (*q)[2], int n)
{
    double qlo[2] = {INFINITY, INFINITY}, qhi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 2; ++k) {
            qlo[k] = fmin(qlo[k], q[i][k]);
            qhi[k] = fmax(qhi[k], q[i][k]);
        }
    double sliver = sliver_area(f);
    size_t old = f->count;
    /* New pieces are appended after the old ones; the old ones are then
     * compacted away (or kept, when q misses them). */
    size_t kept = 0;
    for (size_t c = 0; c < old && !f->overflow; ++c) {
        cdl_visible_piece rest = f->pieces[c];
        double plo[2] = {INFINITY, INFINITY}, phi[2] = {-INFINITY, -INFINITY};
        for (int i = 0; i < rest.count; ++i)
            for (int k = 0; k < 2; ++k) {
                plo[k] = fmin(plo[k], rest.v[i][k]);
                phi[k] = fmax(phi[k], rest.v[i][k]);
            }
        if (plo[0] >= qhi[0] || phi[0] <= qlo[0] || plo[1] >= qhi[1] || phi[1] <= qlo[1]) {
            f->pieces[kept++] = rest; /* kept < c + 1: never overwrites an unread piece */
            continue;
        }
        int left = 1;
        for (int i = 0; i < n && left; ++i) {
            const double *a = q[i], *b = q[(i + 1) % n];
            line2 l = {a[0], a[1], b[0] - a[0], b[1] - a[1]};
            cdl_visible_piece outside, inside;
            if (cut_piece(&rest, &l, -1.0, &outside, &f->overflow) &&
                signed_area((const double(*)[2])outside.v, outside.count) > sliver)
                push_piece(f, &outside);
            left = cut_piece(&rest, &l, 1.0, &inside, &f->overflow);
            rest = inside;
        }
        /* what is left inside every edge of q is hidden */
    }
    /* Move the new pieces down after the kept old ones. */
    size_t fresh = f->count - old;
    memmove(&f->pieces[kept], &f->pieces[old], fresh * sizeof *f->pieces);
    f->count = kept + fresh;
}

/* ---- 3-D: an occluder triangle clipped and projected ----------------------- */

static int before3(cdl_vec3 a, cdl_vec3 b)
{
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

/* Keep {w : m . w <= offset} of the polygon w[0 .. count). */
static int clip3(const cdl_vec3 *in, int count, cdl_vec3 m, double offset, cdl_vec3 *out)
{
    double d[CLIP3_MAX];
    for (int i = 0; i < count; ++i) d[i] = cdl_vec3_dot(m, in[i]) - offset;
    int k = 0;
    for (int i = 0; i < count && k < CLIP3_MAX; ++i) {
        int j = (i + 1) % count;
        if (d[i] <= 0.0) out[k++] = in[i];
        if (((d[i] < 0.0 && d[j] > 0.0) || (d[i] > 0.0 && d[j] < 0.0)) && k < CLIP3_MAX) {
            int a = before3(in[i], in[j]) ? i : j, b = a == i ? j : i;
            double t = d[a] / (d[a] - d[b]);
            out[k++] = cdl_vec3_madd(in[a], t, cdl_vec3_sub(in[b], in[a]));
        }
    }
    return k;
}

void cdl_visible_face_subtract_triangle(cdl_visible_face *f, const double *tri)
{
    if (f->overflow || f->count == 0) return;
    cdl_vec3 buf[2][CLIP3_MAX];
    int n = 3, cur = 0;
    /* Relative to the apex, where the precision of near occluders is kept. */
    for (int i = 0; i < 3; ++i)
        buf[0][i] = cdl_vec3_sub(cdl_vec3_make(tri[3 * i], tri[3 * i + 1], tri[3 * i + 2]), f->apex);
    /* With s = -toward . w the depth towards the plane, a point projects to
     * (x, y) = height (w . e1, w . e2) / s; x <= hi[0] is
     * w . (height e1 + hi[0] toward) <= 0, and so on for each side. */
    cdl_vec3 t = f->toward, e1 = f->e1, e2 = f->e2;
    double h = f->height;
    cdl_vec3 planes[6];
    double offsets[6];
    int count = 0;
    planes[count] = t, offsets[count++] = -f->near; /* s >= near */
    if (f->bounded) planes[count] = cdl_vec3_neg(t), offsets[count++] = h; /* s <= height */
    planes[count] = cdl_vec3_add(cdl_vec3_scale(e1, h), cdl_vec3_scale(t, f->hi[0])), offsets[count++] = 0.0;
    planes[count] = cdl_vec3_neg(cdl_vec3_add(cdl_vec3_scale(e1, h), cdl_vec3_scale(t, f->lo[0]))), offsets[count++] = 0.0;
    planes[count] = cdl_vec3_add(cdl_vec3_scale(e2, h), cdl_vec3_scale(t, f->hi[1])), offsets[count++] = 0.0;
    planes[count] = cdl_vec3_neg(cdl_vec3_add(cdl_vec3_scale(e2, h), cdl_vec3_scale(t, f->lo[1]))), offsets[count++] = 0.0;
    for (int p = 0; p < count && n >= 3; ++p) {
        n = clip3(buf[cur], n, planes[p], offsets[p], buf[1 - cur]);
        cur = 1 - cur;
    }
    if (n < 3) return;
    double q[CLIP3_MAX][2];
    for (int i = 0; i < n; ++i) {
        cdl_vec3 w = buf[cur][i];
        double s = -cdl_vec3_dot(t, w);
        q[i][0] = h * cdl_vec3_dot(w, e1) / s;
        q[i][1] = h * cdl_vec3_dot(w, e2) / s;
    }
    /* Drop vertices that repeat the one before within 1e-12 of the face's
     * size (a corner on a side of the pyramid comes out of two clips). */
    double dx = f->hi[0] - f->lo[0], dy = f->hi[1] - f->lo[1], same = 1e-12 * sqrt(dx * dx + dy * dy);
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (m > 0 && fabs(q[i][0] - q[m - 1][0]) <= same && fabs(q[i][1] - q[m - 1][1]) <= same) continue;
        q[m][0] = q[i][0];
        q[m][1] = q[i][1];
        m++;
    }
    while (m > 1 && fabs(q[m - 1][0] - q[0][0]) <= same && fabs(q[m - 1][1] - q[0][1]) <= same) m--;
    n = m;
    if (n < 3) return;
    double area = signed_area((const double(*)[2])q, n);
    if (fabs(area) <= sliver_area(f)) return; /* seen edge-on: hides nothing */
    if (area < 0.0)
        for (int i = 0; i < n / 2; ++i)
            for (int k = 0; k < 2; ++k) {
                double tmp = q[i][k];
                q[i][k] = q[n - 1 - i][k];
                q[n - 1 - i][k] = tmp;
            }
    subtract_convex(f, (const double(*)[2])q, n);
}

double cdl_visible_face_projected_solid_angle(const cdl_visible_face *f, cdl_vec3 n)
{
    /* A point (x, y) of the plane is foot + x e1 + y e2, relative to the
     * apex -height toward + x e1 + y e2; pieces are counter-clockwise in
     * (e1, e2), e1 x e2 = toward, so counter-clockwise seen from the apex. */
    double sum = 0.0;
    cdl_vec3 down = cdl_vec3_scale(f->toward, -f->height);
    for (size_t i = 0; i < f->count; ++i) {
        const cdl_visible_piece *p = &f->pieces[i];
        cdl_vec3 rel[CDL_VISIBLE_MAX_VERTICES];
        for (int k = 0; k < p->count; ++k)
            rel[k] = cdl_vec3_add(down, cdl_vec3_add(cdl_vec3_scale(f->e1, p->v[k][0]), cdl_vec3_scale(f->e2, p->v[k][1])));
        sum += cdl_projected_solid_angle_polygon(rel, (size_t)p->count, n);
    }
    return sum;
}
