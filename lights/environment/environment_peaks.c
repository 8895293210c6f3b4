/* environment_peaks.c - bright pixels over a spherical polygon, exactly (see
 * the header). */
#include "lights/environment/environment_peaks.h"

#include <math.h>

#include "lights/environment/environment_bounds.h"
#include "lights/environment/environment_pixels.h"
#include "radiometry/constants.h"

/* Sub-arcs a polygon's boundary falls into at one parallel: each edge at
 * most three (two crossings). */
#define MAX_ARCS (3 * CDL_ENV_PEAK_MAX_VERTICES)

/* Sutherland-Hodgman: the part of the polygon (vectors from the centre of
 * the sphere) on the side m.w >= 0 of a plane through the centre; the cut
 * point on an edge is on the chord, its direction on the great-circle arc. */
static int clip_plane(const cdl_vec3 *in, int count, cdl_vec3 m, cdl_vec3 *out)
{
    int k = 0;
    for (int a = 0; a < count; ++a) {
        cdl_vec3 p = in[a], q = in[(a + 1) % count];
        double dp = cdl_vec3_dot(m, p), dq = cdl_vec3_dot(m, q);
        if (dp >= 0.0) out[k++] = p;
        if ((dp >= 0.0) != (dq >= 0.0)) out[k++] = cdl_vec3_madd(p, dp / (dp - dq), cdl_vec3_sub(q, p));
    }
    return k;
}

/* F(c) = int over poly and {z >= c} of n.w dw, poly counter-clockwise seen
 * from outside and within one pixel's columns (narrower than pi), by the
 * boundary integral (header). The crossing points of the parallel are
 * computed once and shared by the arc they end and the parallel's piece
 * they start. */
static double cap_flux(const cdl_vec3 *poly, int count, double c, double s, cdl_vec3 n)
{
    if (c >= 1.0) return 0.0;
    /* The cap of the whole sphere: every arc counts. (The parallel there is
     * a point: an arc through the pole would touch it at a root found a
     * square root of rounding away, and the piece beyond be lost.) */
    int whole = c <= -1.0;
    int lit[MAX_ARCS], arcs = 0;
    double end_phi[MAX_ARCS], flux = 0.0;
    for (int k = 0; k < count; ++k) {
        cdl_vec3 p = poly[k], q = poly[(k + 1) % count];
        cdl_vec3 cr = cdl_vec3_cross(p, q);
        double sn = cdl_vec3_length(cr), cs = cdl_vec3_dot(p, q);
        if (!(sn > 1e-15)) continue; /* a repeated vertex: no edge */
        /* w(t) = p cos t + u sin t, t in [0, angle]; z(t) = p.z cos t + u.z sin t */
        cdl_vec3 u = cdl_vec3_scale(cdl_vec3_madd(q, -cs, p), 1.0 / sn), m = cdl_vec3_scale(cr, 1.0 / sn);
        double angle = atan2(sn, cs), cut[4], roots[2];
        int r = whole ? 0 : cdl_env_sinusoid_roots(p.z, u.z, -c, 0.0, angle, roots), nc = 0;
        cut[nc++] = 0.0;
        for (int i = 0; i < r; ++i) cut[nc++] = roots[i];
        cut[nc++] = angle;
        double arc_flux = cdl_vec3_dot(n, m);
        for (int i = 0; i + 1 < nc; ++i) {
            double mid = 0.5 * (cut[i] + cut[i + 1]);
            lit[arcs] = whole || p.z * cos(mid) + u.z * sin(mid) > c;
            cdl_vec3 e = i + 2 == nc ? q : cdl_vec3_add(cdl_vec3_scale(p, cos(cut[i + 1])), cdl_vec3_scale(u, sin(cut[i + 1])));
            end_phi[arcs] = atan2(e.y, e.x);
            if (lit[arcs]) flux += arc_flux * (cut[i + 1] - cut[i]);
            arcs++;
        }
    }
    /* Where the boundary leaves the cap the parallel takes over, eastwards
     * to the nearest point where it comes back. */
    double exits[MAX_ARCS], entries[MAX_ARCS];
    int ne = 0, nr = 0;
    for (int k = 0; k < arcs; ++k) {
        int next = (k + 1) % arcs;
        if (lit[k] == lit[next]) continue;
        if (lit[k]) exits[ne++] = end_phi[k];
        else entries[nr++] = end_phi[k];
    }
    for (int a = 0; a < ne; ++a) {
        double best = cdl_env_next_entry(entries, nr, exits[a]);
        if (isfinite(best)) flux += cdl_env_parallel_flux(c, s, exits[a], exits[a] + best, n);
    }
    return 0.5 * flux;
}

/* Q of the cell (its parallels by cosine and sine, its meridians phi_a <
 * phi_b within pi) inside the polygon: R clipped by the two meridian planes
 * (a convex spherical polygon again), then the cap below theta_b less the
 * cap below theta_a. */
static double cell_polygon(double cos_a, double sin_a, double cos_b, double sin_b, double phi_a, double phi_b,
                           const cdl_vec3 *poly, int count, cdl_vec3 n_local)
{
    if (count < 3 || count > CDL_ENV_PEAK_MAX_VERTICES - 2) return 0.0;
    cdl_vec3 a[CDL_ENV_PEAK_MAX_VERTICES], b[CDL_ENV_PEAK_MAX_VERTICES];
    int m = clip_plane(poly, count, cdl_vec3_make(-sin(phi_a), cos(phi_a), 0.0), a);
    if (m < 3) return 0.0;
    m = clip_plane(a, m, cdl_vec3_make(sin(phi_b), -cos(phi_b), 0.0), b);
    if (m < 3) return 0.0;
    for (int k = 0; k < m; ++k) b[k] = cdl_vec3_normalize(b[k]);
    double Q = cap_flux(b, m, cos_b, sin_b, n_local) - cap_flux(b, m, cos_a, sin_a, n_local);
    return Q > 0.0 ? Q : 0.0;
}

double cdl_env_cell_polygon(double theta_a, double theta_b, double phi_a, double phi_b, const cdl_vec3 *poly,
                            int count, cdl_vec3 n_local)
{
    return cell_polygon(cos(theta_a), sin(theta_a), cos(theta_b), sin(theta_b), phi_a, phi_b, poly, count, n_local);
}

double cdl_env_peaks_cell_polygon(const cdl_emitter *emitter, int i, int j, const cdl_vec3 *poly, int count,
                                  cdl_vec3 n_local)
{
    const cdl_env_pixels *px = cdl_emitter_environment_pixels(emitter);
    if (!px || j >= px->rows) return 0.0;
    return cell_polygon(px->cos_a[j], px->sin_a[j], px->cos_b[j], px->sin_b[j], px->phi_a[i], px->phi_a[i + 1], poly,
                        count, n_local);
}

/* The walk over the pyramid: one polygon, the cut, and the running sums. */
typedef struct peak_walk {
    const cdl_emitter *emitter;
    const cdl_env_pixels *px;
    const cdl_env_range *range;
    const cdl_vec3 *poly;
    int count;
    cdl_vec3 n;
    double cut;
    int max_pixels;
    int j0, j1, c0, c1; /* the rectangle of pixels, no wrap */
    cdl_env_peaks *sum;
    double rest_hi;     /* the greatest pixel at most the cut met */
} peak_walk;

/* Block (x, y) of `level` (-1: the pixel (x, y)): at most the cut, it
 * bounds the rest of the sky (wholly inside the rectangle: its maximum;
 * else its children inside, so that the bound is of the rectangle's
 * pixels, as cdl_env_range_query's); above it, its children inside the
 * rectangle are opened, and a bright pixel is summed. 0 once too many
 * bright pixels were met. */
static int walk_block(peak_walk *w, int level, int x, int y)
{
    const cdl_env_pixels *px = w->px;
    const cdl_env_range *r = w->range;
    if (level < 0) {
        double L = px->scale * (double)px->image[(size_t)y * (size_t)px->width + (size_t)x];
        if (!(L > w->cut)) {
            w->rest_hi = fmax(w->rest_hi, L);
            return 1;
        }
        if (++w->sum->pixels > w->max_pixels) return 0;
        double Q = cdl_env_peaks_cell_polygon(w->emitter, x, y, w->poly, w->count, w->n);
        w->sum->LQ += L * Q;
        w->sum->Q += Q;
        return 1;
    }
    double hi = px->scale * (double)r->hi[level][y * r->nx[level] + x];
    int b = r->block[level], by0 = y * b, bx0 = x * b;
    if (!(hi > w->cut) && by0 >= w->j0 && by0 + b - 1 <= w->j1 && bx0 >= w->c0 && bx0 + b - 1 <= w->c1) {
        w->rest_hi = fmax(w->rest_hi, hi);
        return 1;
    }
    /* children: the level below's blocks (or pixels) within this one and the rectangle */
    int cb = level > 0 ? r->block[level - 1] : 1, step = level > 0 ? 2 : 4;
    for (int cy = step * y; cy < step * y + step; ++cy) {
        if (cy * cb > w->j1 || (cy + 1) * cb - 1 < w->j0) continue;
        if (level > 0 ? cy >= r->ny[level - 1] : cy >= px->rows) break;
        for (int cx = step * x; cx < step * x + step; ++cx) {
            if (cx * cb > w->c1 || (cx + 1) * cb - 1 < w->c0) continue;
            if (level > 0 ? cx >= r->nx[level - 1] : cx >= px->width) break;
            if (!walk_block(w, level - 1, cx, cy)) return 0;
        }
    }
    return 1;
}

/* Every top block that meets the rectangle. */
static int walk_rect(peak_walk *w)
{
    const cdl_env_range *r = w->range;
    int top = r->levels - 1, b = r->block[top];
    for (int y = w->j0 / b; y <= w->j1 / b && y < r->ny[top]; ++y)
        for (int x = w->c0 / b; x <= w->c1 / b && x < r->nx[top]; ++x)
            if (!walk_block(w, top, x, y)) return 0;
    return 1;
}

int cdl_env_peaks_add(const cdl_emitter *emitter, const cdl_vec3 *dirs, int count, cdl_vec3 n, double L_cut,
                      int max_pixels, cdl_env_peaks *sum, double *rest_hi)
{
    *rest_hi = 0.0;
    const cdl_env_pixels *px = cdl_emitter_environment_pixels(emitter);
    const cdl_env_range *range = cdl_emitter_environment_range(emitter);
    if (!px || !range || px->width < 4 || count < 3 || count > CDL_ENV_PEAK_MAX_VERTICES - 2) return 0;
    if (range->levels == 0) return 1; /* no row carries light */
    peak_walk w = {emitter, px, range, NULL, count, cdl_frame_to_local(&px->frame, n), L_cut, max_pixels,
                   0, 0, 0, 0, sum, 0.0};
    /* The polygon in the emitter's frame, counter-clockwise seen from
     * outside: (v_k x v_k+1) . centre > 0. */
    cdl_vec3 poly[CDL_ENV_PEAK_MAX_VERTICES], centre = cdl_vec3_make(0, 0, 0);
    double orient = 0.0;
    for (int k = 0; k < count; ++k) {
        poly[k] = cdl_vec3_normalize(cdl_frame_to_local(&px->frame, dirs[k]));
        centre = cdl_vec3_add(centre, poly[k]);
    }
    for (int k = 0; k < count; ++k) orient += cdl_vec3_dot(cdl_vec3_cross(poly[k], poly[(k + 1) % count]), centre);
    if (orient < 0.0)
        for (int k = 0; k < count / 2; ++k) {
            cdl_vec3 t = poly[k];
            poly[k] = poly[count - 1 - k];
            poly[count - 1 - k] = t;
        }
    w.poly = poly;
    cdl_env_extent e;
    cdl_env_extent_of_polygon(&px->frame, dirs, count, &e);
    int i0, ni, dark;
    if (!cdl_env_extent_pixels(px, &e, &w.j0, &w.j1, &i0, &ni, &dark)) return 1;
    int c1 = i0 + ni - 1;
    w.c0 = i0;
    w.c1 = c1 < px->width ? c1 : px->width - 1;
    if (!walk_rect(&w)) return 0;
    if (c1 >= px->width) {
        w.c0 = 0;
        w.c1 = c1 - px->width;
        if (!walk_rect(&w)) return 0;
    }
    *rest_hi = w.rest_hi;
    return 1;
}
