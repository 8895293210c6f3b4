/* environment_bounds.c - extents of direction polygons and block minima and
 * maxima of environment images (see the header). */
#include "lights/environment/environment_bounds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

/* Vertices a polygon may have; a larger one gets the whole sphere. */
#define EXTENT_MAX_VERTICES 64

/* Tolerances that only ever widen an extent: the cosine range by 1e-9, a
 * pole counted as inside when within 1e-12 (in the triple product) of an
 * edge, a vertex within 1e-9 of a pole gives every azimuth. */
#define COS_MARGIN 1e-9
#define POLE_TOLERANCE 1e-12
#define AXIS_TOLERANCE 1e-9

/* Pixels a query reads one by one before it turns to blocks. */
#define SCAN_PIXELS 256

static void extent_everything(cdl_env_extent *out)
{
    out->cos_lo = -1.0;
    out->cos_hi = 1.0;
    out->phi_lo = -CDL_PI;
    out->phi_span = CDL_TWO_PI;
    out->full_azimuth = 1;
}

/* Is q on the shorter arc from a to b (m the unit normal a x b / |a x b|)? */
static int on_arc(cdl_vec3 a, cdl_vec3 b, cdl_vec3 m, cdl_vec3 q)
{
    return cdl_vec3_dot(cdl_vec3_cross(a, q), m) >= 0.0 && cdl_vec3_dot(cdl_vec3_cross(q, b), m) >= 0.0;
}

/* The azimuth difference b - a wrapped to (-pi, pi]. */
static double azimuth_step(double a, double b)
{
    double d = b - a;
    while (d > CDL_PI) d -= CDL_TWO_PI;
    while (d <= -CDL_PI) d += CDL_TWO_PI;
    return d;
}

void cdl_env_extent_of_polygon(const cdl_frame *frame, const cdl_vec3 *dirs, int count, cdl_env_extent *out)
{
    if (count < 3 || count > EXTENT_MAX_VERTICES) {
        extent_everything(out);
        return;
    }
    cdl_vec3 l[EXTENT_MAX_VERTICES], centre = cdl_vec3_make(0, 0, 0);
    out->cos_lo = 1.0;
    out->cos_hi = -1.0;
    int near_axis = 0;
    for (int k = 0; k < count; ++k) {
        l[k] = cdl_vec3_normalize(cdl_frame_to_local(frame, dirs[k]));
        centre = cdl_vec3_add(centre, l[k]);
        out->cos_lo = fmin(out->cos_lo, l[k].z);
        out->cos_hi = fmax(out->cos_hi, l[k].z);
        near_axis |= !(hypot(l[k].x, l[k].y) > AXIS_TOLERANCE);
    }
    /* Edges: the great circle through a and b comes nearest the zenith at
     * q = z - (z.m) m normalised (m its unit normal), farthest at -q; they
     * bound cos(theta) where they lie on the arc. The polygon holds the
     * zenith when it is on the inner side of every edge: sign((a x b).z)
     * the polygon's orientation for all edges. */
    double orient = 0.0, zmin = INFINITY, zmax = -INFINITY;
    for (int k = 0; k < count; ++k) {
        cdl_vec3 a = l[k], b = l[(k + 1) % count], m = cdl_vec3_cross(a, b);
        orient += cdl_vec3_dot(m, centre);
        zmin = fmin(zmin, m.z);
        zmax = fmax(zmax, m.z);
        double len = cdl_vec3_length(m);
        if (!(len > 0.0)) continue;
        m = cdl_vec3_scale(m, 1.0 / len);
        cdl_vec3 q = cdl_vec3_make(-m.z * m.x, -m.z * m.y, 1.0 - m.z * m.z);
        double ql = cdl_vec3_length(q);
        if (!(ql > 1e-12)) continue; /* the edge's circle is the equator */
        q = cdl_vec3_scale(q, 1.0 / ql);
        if (on_arc(a, b, m, q)) out->cos_hi = fmax(out->cos_hi, q.z);
        if (on_arc(a, b, m, cdl_vec3_neg(q))) out->cos_lo = fmin(out->cos_lo, -q.z);
    }
    int zenith = orient >= 0.0 ? zmin >= -POLE_TOLERANCE : zmax <= POLE_TOLERANCE;
    int nadir = orient >= 0.0 ? zmax <= POLE_TOLERANCE : zmin >= -POLE_TOLERANCE;
    if (zenith) out->cos_hi = 1.0;
    if (nadir) out->cos_lo = -1.0;
    out->cos_lo = fmax(-1.0, out->cos_lo - COS_MARGIN);
    out->cos_hi = fmin(1.0, out->cos_hi + COS_MARGIN);
    out->full_azimuth = zenith || nadir || near_axis;
    out->phi_lo = -CDL_PI;
    out->phi_span = CDL_TWO_PI;
    if (out->full_azimuth) return;
    /* An arc that passes no pole turns monotonically in azimuth, by less
     * than pi: the vertices' azimuths joined edge by edge span the polygon. */
    double phi0 = atan2(l[0].y, l[0].x), at = 0.0, lo = 0.0, hi = 0.0;
    for (int k = 0; k < count; ++k) {
        at += azimuth_step(atan2(l[k].y, l[k].x), atan2(l[(k + 1) % count].y, l[(k + 1) % count].x));
        lo = fmin(lo, at);
        hi = fmax(hi, at);
    }
    if (hi - lo >= CDL_TWO_PI - 1e-9) {
        out->full_azimuth = 1;
        return;
    }
    out->phi_lo = phi0 + lo;
    out->phi_span = hi - lo;
}

/* ---- the pyramid ------------------------------------------------------------------ */

void cdl_env_range_free(cdl_env_range *r)
{
    for (int l = 0; l < r->levels; ++l) {
        free(r->lo[l]);
        free(r->hi[l]);
    }
    memset(r, 0, sizeof *r);
}

cdl_status cdl_env_range_build(cdl_env_range *r, const cdl_env_pixels *px, cdl_error *err)
{
    memset(r, 0, sizeof *r);
    int W = px->width, H = px->rows;
    for (int l = 0; H > 0 && l < 16; ++l) {
        int b = 4 << l, nx = (W + b - 1) / b, ny = (H + b - 1) / b;
        r->block[l] = b;
        r->nx[l] = nx;
        r->ny[l] = ny;
        r->lo[l] = malloc((size_t)nx * (size_t)ny * sizeof(float));
        r->hi[l] = malloc((size_t)nx * (size_t)ny * sizeof(float));
        r->levels = l + 1;
        if (!r->lo[l] || !r->hi[l]) {
            cdl_env_range_free(r);
            return cdl_error_out_of_memory(err);
        }
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                float lo = INFINITY, hi = -INFINITY;
                if (l == 0) {
                    for (int j = 4 * y; j < 4 * y + 4 && j < H; ++j)
                        for (int i = 4 * x; i < 4 * x + 4 && i < W; ++i) {
                            float v = px->image[(size_t)j * (size_t)W + (size_t)i];
                            lo = fminf(lo, v);
                            hi = fmaxf(hi, v);
                        }
                } else {
                    int cnx = r->nx[l - 1], cny = r->ny[l - 1];
                    for (int cy = 2 * y; cy < 2 * y + 2 && cy < cny; ++cy)
                        for (int cx = 2 * x; cx < 2 * x + 2 && cx < cnx; ++cx) {
                            lo = fminf(lo, r->lo[l - 1][cy * cnx + cx]);
                            hi = fmaxf(hi, r->hi[l - 1][cy * cnx + cx]);
                        }
                }
                r->lo[l][y * nx + x] = lo;
                r->hi[l][y * nx + x] = hi;
            }
        if (nx == 1 && ny == 1) break;
    }
    return CDL_OK;
}

/* Fold the pixels of rows j0..j1 and columns c0..c1 (no wrap) into lo,
 * hi, exactly: blocks of `level` that lie wholly inside the rectangle by
 * their minima and maxima, those it cuts through by the level below (at
 * the bottom, pixel by pixel). Cost: the blocks along the rectangle's
 * edge at each level. */
static void fold_rect(const cdl_env_range *r, const cdl_env_pixels *px, int level, int j0, int j1, int c0, int c1,
                      float *lo, float *hi)
{
    if (level < 0) {
        for (int j = j0; j <= j1; ++j)
            for (int i = c0; i <= c1; ++i) {
                float v = px->image[(size_t)j * (size_t)px->width + (size_t)i];
                *lo = fminf(*lo, v);
                *hi = fmaxf(*hi, v);
            }
        return;
    }
    int b = r->block[level], nx = r->nx[level];
    for (int y = j0 / b; y <= j1 / b; ++y)
        for (int x = c0 / b; x <= c1 / b; ++x) {
            /* the block's pixels, clipped to the image */
            int by0 = y * b, by1 = by0 + b - 1 < px->rows - 1 ? by0 + b - 1 : px->rows - 1;
            int bx0 = x * b, bx1 = bx0 + b - 1 < px->width - 1 ? bx0 + b - 1 : px->width - 1;
            if (by0 >= j0 && by1 <= j1 && bx0 >= c0 && bx1 <= c1) {
                *lo = fminf(*lo, r->lo[level][y * nx + x]);
                *hi = fmaxf(*hi, r->hi[level][y * nx + x]);
            } else {
                fold_rect(r, px, level - 1, by0 > j0 ? by0 : j0, by1 < j1 ? by1 : j1, bx0 > c0 ? bx0 : c0,
                          bx1 < c1 ? bx1 : c1, lo, hi);
            }
        }
}

int cdl_env_extent_pixels(const cdl_env_pixels *px, const cdl_env_extent *e, int *j0, int *j1, int *i0, int *ni,
                          int *dark)
{
    int W = px->width, H = px->height;
    /* Rows: theta_j = pi j / H; one row of margin each way. */
    double t_lo = acos(fmin(1.0, fmax(-1.0, e->cos_hi))), t_hi = acos(fmin(1.0, fmax(-1.0, e->cos_lo)));
    *j0 = (int)floor(t_lo * H / CDL_PI) - 1;
    *j1 = (int)floor(t_hi * H / CDL_PI) + 1;
    if (*j0 < 0) *j0 = 0;
    if (*j1 > H - 1) *j1 = H - 1;
    *dark = *j1 >= px->rows || (px->upper_only && e->cos_lo <= 0.0);
    if (*j1 > px->rows - 1) *j1 = px->rows - 1;
    /* Columns: phi = pi + 2 pi u, one column of margin each way. */
    *i0 = 0;
    *ni = W;
    if (!e->full_azimuth) {
        double u = (e->phi_lo - CDL_PI) / CDL_TWO_PI;
        u -= floor(u);
        *i0 = (int)floor(u * W) - 1;
        *ni = (int)ceil(e->phi_span / CDL_TWO_PI * W) + 3;
        if (*ni >= W) {
            *i0 = 0;
            *ni = W;
        }
        *i0 = ((*i0 % W) + W) % W;
    }
    return *j0 <= *j1;
}

void cdl_env_range_query(const cdl_env_range *r, const cdl_env_pixels *px, const cdl_env_extent *e, double *L_lo,
                         double *L_hi)
{
    int W = px->width, j0, j1, i0, ni, dark;
    if (!cdl_env_extent_pixels(px, e, &j0, &j1, &i0, &ni, &dark) || r->levels == 0) {
        *L_lo = *L_hi = 0.0;
        return;
    }
    int rows = j1 - j0 + 1, reach = rows > ni ? rows : ni, level = -1;
    if ((double)rows * ni > SCAN_PIXELS) {
        level = 0;
        while (level + 1 < r->levels && 4 * r->block[level] < reach) level++;
    }
    float lo = INFINITY, hi = -INFINITY;
    int c1 = i0 + ni - 1;
    fold_rect(r, px, level, j0, j1, i0, c1 < W ? c1 : W - 1, &lo, &hi);
    if (c1 >= W) fold_rect(r, px, level, j0, j1, 0, c1 - W, &lo, &hi);
    *L_lo = dark ? 0.0 : px->scale * lo;
    *L_hi = px->scale * fmaxf(hi, 0.0f);
}
