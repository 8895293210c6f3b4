/* photometry_intensity.c - I(direction): mapping frame directions to table
 * angles for photometric types A, B and C, symmetry reduction, wrap-around,
 * and bilinear interpolation. The conventions are documented in photometry.h. */
#include "lights/photometry/photometry_internal.h"

#include <math.h>

#include "radiometry/constants.h"

/* Angles this close to a range end (degrees) count as on it: acos/atan2
 * round-off must not switch a tabulated edge value off. */
#define EDGE_TOL_DEG 1e-9

double cdl_photometry_reduce_c(cdl_photometry_symmetry s, double c)
{
    c = fmod(c, 360.0);
    if (c < 0.0) c += 360.0;
    if (c >= 360.0) c -= 360.0;
    switch (s) {
    case CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL:
        return 0.0;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180: /* I(C) = I(360 - C) */
        return c > 180.0 ? 360.0 - c : c;
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT: /* mirrored about both the C0-C180 and C90-C270 planes */
        if (c > 180.0) c = 360.0 - c;
        return c > 90.0 ? 180.0 - c : c;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270: /* I(C) = I(180 - C), mod 360 */
        if (c < 90.0) return 180.0 - c;
        if (c > 270.0) return 540.0 - c;
        return c;
    default:
        return c;
    }
}

/* Cell index i and fraction t with x in [a[i], a[i+1]]; n >= 2 and x is
 * clamped into [a[0], a[n-1]]. */
static inline size_t locate(const double *a, size_t n, int uniform, double inv_step, double x, double *t)
{
    if (x <= a[0]) {
        *t = 0.0;
        return 0;
    }
    if (x >= a[n - 1]) {
        *t = 1.0;
        return n - 2;
    }
    size_t i;
    if (uniform) {
        double f = (x - a[0]) * inv_step;
        i = f <= 0.0 ? 0 : (size_t)f;
        if (i > n - 2) i = n - 2;
        /* round-off in the division can land one cell off */
        if (x < a[i] && i > 0) --i;
        else if (x > a[i + 1] && i < n - 2) ++i;
    } else {
        size_t lo = 0, hi = n - 1; /* a[lo] <= x < a[hi] */
        while (hi - lo > 1) {
            size_t mid = lo + (hi - lo) / 2;
            if (a[mid] <= x) lo = mid;
            else hi = mid;
        }
        i = lo;
    }
    /* evenly spaced: multiply by 1 / step (within an ulp of dividing) */
    double u = uniform ? (x - a[i]) * inv_step : (x - a[i]) / (a[i + 1] - a[i]);
    *t = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    return i;
}

/* Clamp x into [lo, hi] when it is within the edge tolerance; returns 0 when outside. */
static inline int in_range(double *x, double lo, double hi)
{
    if (*x < lo) {
        if (*x < lo - EDGE_TOL_DEG) return 0;
        *x = lo;
    }
    if (*x > hi) {
        if (*x > hi + EDGE_TOL_DEG) return 0;
        *x = hi;
    }
    return 1;
}

/* Linear interpolation of row i at inner fraction (j, u). */
static inline double row_value(const cdl_photometry *p, size_t i, size_t j, double u)
{
    const double *r = p->cd + i * p->nv;
    return r[j] + u * (r[j + 1] - r[j]);
}

double cdl_photometry_eval_hv(const cdl_photometry *p, double h, double v)
{
    if (!isfinite(h) || !isfinite(v)) return 0.0;
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) {
        if (p->nh > 1) h = cdl_photometry_reduce_c(p->symmetry, h); /* one plane: C does not matter */
    } else {
        if (p->h_mirror) h = fabs(h);
        if (p->v_mirror) v = fabs(v);
    }
    if (!in_range(&v, p->v[0], p->v[p->nv - 1])) return 0.0;
    double u;
    size_t j = locate(p->v, p->nv, p->v_uniform, p->v_inv_step, v, &u);
    if (p->nh == 1) return row_value(p, 0, j, u);

    size_t i0, i1;
    double t;
    if (p->type == CDL_PHOTOMETRIC_TYPE_C && p->symmetry == CDL_PHOTOMETRY_SYMMETRY_NONE &&
        (h < p->h[0] || h > p->h[p->nh - 1])) {
        /* Wrap-around: the gap from the last plane to the first plane + 360. */
        double last = p->h[p->nh - 1], span = p->h[0] + 360.0 - last;
        double hh = h < p->h[0] ? h + 360.0 : h;
        t = (hh - last) / span;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        i0 = p->nh - 1;
        i1 = 0;
    } else {
        if (p->type != CDL_PHOTOMETRIC_TYPE_C && !in_range(&h, p->h[0], p->h[p->nh - 1])) return 0.0;
        i0 = locate(p->h, p->nh, p->h_uniform, p->h_inv_step, h, &t);
        i1 = i0 + 1;
    }
    double a = row_value(p, i0, j, u), b = row_value(p, i1, j, u);
    return a + t * (b - a);
}

double cdl_photometry_gamma_deg(cdl_vec3 unit)
{
    double c = -unit.z;
    if (fabs(c) < 0.7) return acos(c) * CDL_RAD_TO_DEG;
    double r = sqrt(unit.x * unit.x + unit.y * unit.y);
    double s = asin(r < 1.0 ? r : 1.0) * CDL_RAD_TO_DEG; /* a comparison: fmin is a library call */
    return c > 0.0 ? s : 180.0 - s;
}

int cdl_photometry_direction_to_hv(cdl_photometric_type type, cdl_vec3 d, double *h, double *v)
{
    double len = cdl_vec3_length(d);
    if (!(len > 0.0) || !isfinite(len)) return 0;
    d = cdl_vec3_scale(d, 1.0 / len);
    switch (type) {
    case CDL_PHOTOMETRIC_TYPE_B: {
        /* d = (sin V cos H, -sin H, -cos V cos H) */
        double s = -d.y;
        s = s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s);
        *h = asin(s) * CDL_RAD_TO_DEG;
        /* 0.0 - x turns -0 into +0, so the poles (x = z = 0) read V = 0, not 180 */
        *v = atan2(d.x, 0.0 - d.z) * CDL_RAD_TO_DEG;
        return 1;
    }
    case CDL_PHOTOMETRIC_TYPE_A: {
        /* d = (sin V, -cos V sin H, -cos V cos H) */
        double s = d.x > 1.0 ? 1.0 : (d.x < -1.0 ? -1.0 : d.x);
        *v = asin(s) * CDL_RAD_TO_DEG;
        *h = atan2(0.0 - d.y, 0.0 - d.z) * CDL_RAD_TO_DEG;
        return 1;
    }
    default: {
        /* d = (sin g cos C, sin g sin C, -cos g) */
        double c = atan2(d.y, d.x) * CDL_RAD_TO_DEG;
        if (c < 0.0) c += 360.0;
        *h = c;
        *v = cdl_photometry_gamma_deg(d);
        return 1;
    }
    }
}

cdl_vec3 cdl_photometry_direction(cdl_photometric_type type, double h_deg, double v_deg)
{
    double h = h_deg * CDL_DEG_TO_RAD, v = v_deg * CDL_DEG_TO_RAD;
    switch (type) {
    case CDL_PHOTOMETRIC_TYPE_B:
        return cdl_vec3_make(sin(v) * cos(h), -sin(h), -cos(v) * cos(h));
    case CDL_PHOTOMETRIC_TYPE_A:
        return cdl_vec3_make(sin(v), -cos(v) * sin(h), -cos(v) * cos(h));
    default:
        return cdl_vec3_make(sin(v) * cos(h), sin(v) * sin(h), -cos(v));
    }
}

cdl_luminous_intensity cdl_photometry_intensity(const cdl_photometry *p, cdl_vec3 direction)
{
    double h, v;
    if (!cdl_photometry_direction_to_hv(p->type, direction, &h, &v)) return cdl_candelas(0.0);
    return cdl_candelas(cdl_photometry_eval_hv(p, h, v));
}

double cdl_photometry_intensity_one_plane(const cdl_photometry *p, double gamma_deg)
{
    /* eval_hv for a table with one plane, without the azimuth handling */
    double v = gamma_deg;
    if (!in_range(&v, p->v[0], p->v[p->nv - 1])) return 0.0;
    double u;
    size_t j = locate(p->v, p->nv, p->v_uniform, p->v_inv_step, v, &u);
    return row_value(p, 0, j, u);
}

cdl_luminous_intensity cdl_photometry_intensity_c_gamma(const cdl_photometry *p, double c_deg, double gamma_deg)
{
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) {
        if (!isfinite(c_deg) || !isfinite(gamma_deg)) return cdl_candelas(0.0);
        /* gamma outside [0, 180] names the same direction as its reflection through the pole */
        double g = gamma_deg;
        if (!(g >= 0.0 && g <= 180.0)) {
            g = fmod(g, 360.0);
            if (g < 0.0) g += 360.0;
            if (g > 180.0) {
                g = 360.0 - g;
                c_deg += 180.0;
            }
        }
        return cdl_candelas(cdl_photometry_eval_hv(p, c_deg, g));
    }
    return cdl_photometry_intensity(p, cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, c_deg, gamma_deg));
}
