/* photometry_flux.c - luminous flux as the exact integral of the bilinearly
 * interpolated intensity distribution, total and by zones.
 *
 * Phi = integral of I dOmega. The interpolant is linear in each table angle
 * inside a cell, so the azimuthal (longitude) integral is a trapezoid sum
 * that is exact, and the polar (latitude) integral of a linear function
 * times sin or cos has a closed form (FORMAT_NOTES section 4, "exact
 * bilinear"; the same method as the zonal-lumen summation of IES LM-63
 * practice, without the midpoint approximation):
 *   type C:  dOmega = sin(gamma) dgamma dC
 *   type B:  dOmega = cos(H) dH dV     (H latitude, V longitude)
 *   type A:  dOmega = cos(V) dV dH     (V latitude, H longitude)
 */
#include "lights/photometry/photometry_internal.h"

#include <math.h>
#include <stdlib.h>

#include "radiometry/constants.h"

/* Weights (wa, wb) with integral_a^b f(x) sin(x) dx = wa f(a) + wb f(b) for f
 * linear on [a, b] (radians): since integral (x - a) sin x dx =
 * [sin x - (x - a) cos x], the slope term gives wb = (sin b - sin a - d cos b) / d. */
static void sin_weights(double a, double b, double *wa, double *wb)
{
    double d = b - a;
    double whole = 2.0 * sin(0.5 * (a + b)) * sin(0.5 * d); /* cos a - cos b */
    double sb = (2.0 * cos(0.5 * (a + b)) * sin(0.5 * d) - d * cos(b)) / d;
    *wb = sb;
    *wa = whole - sb;
}

/* Same for integral_a^b f(x) cos(x) dx: integral (x - a) cos x dx = [(x - a) sin x + cos x]. */
static void cos_weights(double a, double b, double *wa, double *wb)
{
    double d = b - a;
    double whole = 2.0 * cos(0.5 * (a + b)) * sin(0.5 * d); /* sin b - sin a */
    double sb = (d * sin(b) - 2.0 * sin(0.5 * (a + b)) * sin(0.5 * d)) / d;
    *wb = sb;
    *wa = whole - sb;
}

typedef enum { WEIGHT_FLAT, WEIGHT_SIN, WEIGHT_COS } weight_kind;

/* Weights w[j] so that the integral over [lo, hi] (degrees) of the
 * piecewise-linear f(x) times 1, sin x or cos x equals sum w[j] f(x[j]).
 * Cells are clipped to the window; the value at a clip point is the linear
 * interpolant, so the result stays exact. The flat kernel is the trapezoid
 * rule (used for longitudes); sin and cos are the polar weights above. */
static void axis_weights(const double *x, size_t n, double lo, double hi, weight_kind kind, double *w)
{
    for (size_t j = 0; j < n; ++j) w[j] = 0.0;
    for (size_t j = 0; j + 1 < n; ++j) {
        double a = fmax(x[j], lo), b = fmin(x[j + 1], hi);
        if (!(a < b)) continue;
        double span = x[j + 1] - x[j];
        double ta = (a - x[j]) / span, tb = (b - x[j]) / span;
        double wa, wb;
        if (kind == WEIGHT_SIN) sin_weights(a * CDL_DEG_TO_RAD, b * CDL_DEG_TO_RAD, &wa, &wb);
        else if (kind == WEIGHT_COS) cos_weights(a * CDL_DEG_TO_RAD, b * CDL_DEG_TO_RAD, &wa, &wb);
        else wa = wb = 0.5 * (b - a) * CDL_DEG_TO_RAD;
        /* f(a) = (1 - ta) f_j + ta f_j+1, likewise f(b) */
        w[j] += wa * (1.0 - ta) + wb * (1.0 - tb);
        w[j + 1] += wa * ta + wb * tb;
    }
}

/* Azimuth weights of a type C table's planes over the whole circle. */
static void type_c_plane_weights(const cdl_photometry *p, double *w)
{
    size_t n = p->nh;
    if (n == 1) {
        w[0] = CDL_TWO_PI;
        return;
    }
    switch (p->symmetry) {
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT:
        axis_weights(p->h, n, 0.0, 90.0, WEIGHT_FLAT, w);
        for (size_t i = 0; i < n; ++i) w[i] *= 4.0;
        return;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180:
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270:
        axis_weights(p->h, n, p->h[0], p->h[n - 1], WEIGHT_FLAT, w);
        for (size_t i = 0; i < n; ++i) w[i] *= 2.0;
        return;
    default: {
        axis_weights(p->h, n, p->h[0], p->h[n - 1], WEIGHT_FLAT, w);
        /* the wrap interval from the last plane round to the first */
        double gap = (p->h[0] + 360.0 - p->h[n - 1]) * CDL_DEG_TO_RAD;
        w[n - 1] += 0.5 * gap;
        w[0] += 0.5 * gap;
        return;
    }
    }
}

/* sum_i sum_j wi[i] wj[j] cd[i][j] */
static double weighted_sum(const cdl_photometry *p, const double *wi, const double *wj)
{
    double total = 0.0;
    for (size_t i = 0; i < p->nh; ++i) {
        if (wi[i] == 0.0) continue;
        const double *r = p->cd + i * p->nv;
        double s = 0.0;
        for (size_t j = 0; j < p->nv; ++j) s += wj[j] * r[j];
        total += wi[i] * s;
    }
    return total;
}

/* Type C flux into gamma in [lo, hi] degrees: exact. */
static double type_c_flux(const cdl_photometry *p, double lo, double hi)
{
    double *wi = malloc(p->nh * sizeof *wi), *wj = malloc(p->nv * sizeof *wj);
    double total = NAN;
    if (wi && wj) {
        type_c_plane_weights(p, wi);
        axis_weights(p->v, p->nv, lo, hi, WEIGHT_SIN, wj);
        total = weighted_sum(p, wi, wj);
    }
    free(wi);
    free(wj);
    return total;
}

/* Weights along one A/B axis over the window [lo, hi] of the unmirrored
 * coordinate; a mirrored axis (stored 0..90) also collects the reflected window. */
static void ab_axis_weights(const double *x, size_t n, int mirrored, int latitude, double lo, double hi, double *w,
                            double *tmp)
{
    weight_kind kind = latitude ? WEIGHT_COS : WEIGHT_FLAT;
    axis_weights(x, n, lo, hi, kind, w);
    if (!mirrored) return;
    axis_weights(x, n, -hi, -lo, kind, tmp);
    for (size_t j = 0; j < n; ++j) w[j] += tmp[j];
}

/* Type A/B flux with the longitude restricted to [lon_lo, lon_hi] degrees:
 * exact. The downward hemisphere (frame z < 0) is |longitude| < 90. */
static double type_ab_flux(const cdl_photometry *p, double lon_lo, double lon_hi)
{
    size_t nmax = p->nh > p->nv ? p->nh : p->nv;
    double *wi = malloc(p->nh * sizeof *wi), *wj = malloc(p->nv * sizeof *wj), *tmp = malloc(nmax * sizeof *tmp);
    double total = NAN;
    if (wi && wj && tmp) {
        int h_is_lat = p->type == CDL_PHOTOMETRIC_TYPE_B;
        if (h_is_lat) {
            ab_axis_weights(p->h, p->nh, p->h_mirror, 1, -90.0, 90.0, wi, tmp);
            ab_axis_weights(p->v, p->nv, p->v_mirror, 0, lon_lo, lon_hi, wj, tmp);
        } else {
            ab_axis_weights(p->h, p->nh, p->h_mirror, 0, lon_lo, lon_hi, wi, tmp);
            ab_axis_weights(p->v, p->nv, p->v_mirror, 1, -90.0, 90.0, wj, tmp);
        }
        total = weighted_sum(p, wi, wj);
    }
    free(wi);
    free(wj);
    free(tmp);
    return total;
}

double cdl_photometry_compute_flux(const cdl_photometry *p)
{
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) return type_c_flux(p, 0.0, 180.0);
    return type_ab_flux(p, -180.0, 180.0);
}

/* Gauss-Legendre 2-point nodes on [-1, 1] (weights 1): exact for cubics. */
static const double gl_x[2] = {-0.57735026918962576, 0.57735026918962576};

/* Frame-space quadrature of I sin(gamma) for type A/B tables, whose cells do
 * not follow frame zones: 2-point Gauss-Legendre per degree of gamma and the
 * midpoint rule per degree of C. The flux into gamma in [lo, hi] (degrees,
 * whole degrees) is accumulated into zone[(int)(gamma / zone_width)]. The
 * interpolant is continuous and piecewise smooth, and its range edges
 * (|V| or |H| = 90) fall on the gamma = 90 zone boundary, so the error is
 * of second order: about 1e-5 of the flux for real tables. */
static void quadrature_zones(const cdl_photometry *p, int lo, int hi, double zone_width, int first_zone, double *zone)
{
    enum { NC = 360 };
    double sc[NC], cc[NC];
    const double dc = CDL_TWO_PI / NC, dg = CDL_DEG_TO_RAD;
    for (int m = 0; m < NC; ++m) {
        sc[m] = sin((m + 0.5) * dc);
        cc[m] = cos((m + 0.5) * dc);
    }
    for (int k = lo; k < hi; ++k) {
        double ring_total = 0.0;
        for (int q = 0; q < 2; ++q) {
            double g = (k + 0.5 + 0.5 * gl_x[q]) * dg, sg = sin(g), cg = cos(g);
            double ring = 0.0;
            for (int m = 0; m < NC; ++m) {
                double h, v;
                cdl_vec3 d = cdl_vec3_make(sg * cc[m], sg * sc[m], -cg);
                if (cdl_photometry_direction_to_hv(p->type, d, &h, &v)) ring += cdl_photometry_eval_hv(p, h, v);
            }
            ring_total += ring * sg;
        }
        zone[(int)((k + 0.5) / zone_width) - first_zone] += ring_total * dc * 0.5 * dg;
    }
}

/* The azimuth-integrated profile of a type C table: P[j] = sum_i W_i I_ij. */
static int type_c_profile(const cdl_photometry *p, double *profile)
{
    double *wi = malloc(p->nh * sizeof *wi);
    if (!wi) return 0;
    type_c_plane_weights(p, wi);
    for (size_t j = 0; j < p->nv; ++j) profile[j] = 0.0;
    for (size_t i = 0; i < p->nh; ++i)
        for (size_t j = 0; j < p->nv; ++j) profile[j] += wi[i] * p->cd[i * p->nv + j];
    free(wi);
    return 1;
}

static double profile_flux(const cdl_photometry *p, const double *profile, double lo, double hi, double *wj)
{
    axis_weights(p->v, p->nv, lo, hi, WEIGHT_SIN, wj);
    double total = 0.0;
    for (size_t j = 0; j < p->nv; ++j) total += wj[j] * profile[j];
    return total;
}

void cdl_photometry_zones(const cdl_photometry *p, double zone[CDL_PHOTOMETRY_ZONES])
{
    for (int k = 0; k < CDL_PHOTOMETRY_ZONES; ++k) zone[k] = 0.0;
    if (p->type != CDL_PHOTOMETRIC_TYPE_C) {
        quadrature_zones(p, 0, 180, 180.0 / CDL_PHOTOMETRY_ZONES, 0, zone);
        return;
    }
    double *profile = malloc(p->nv * sizeof *profile), *wj = malloc(p->nv * sizeof *wj);
    if (profile && wj && type_c_profile(p, profile))
        for (int k = 0; k < CDL_PHOTOMETRY_ZONES; ++k) {
            double w = 180.0 / CDL_PHOTOMETRY_ZONES;
            zone[k] = profile_flux(p, profile, w * k, w * (k + 1), wj);
        }
    free(profile);
    free(wj);
}

cdl_luminous_flux cdl_photometry_zone_flux(const cdl_photometry *p, double lo, double hi)
{
    if (!isfinite(lo) || !isfinite(hi)) return cdl_lumens(0.0);
    lo = fmax(lo, 0.0);
    hi = fmin(hi, 180.0);
    if (!(lo < hi)) return cdl_lumens(0.0);
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) return cdl_lumens(type_c_flux(p, lo, hi));
    if (lo == 0.0 && hi == 180.0) return cdl_lumens(p->flux_lm);
    if (lo == 0.0 && hi == 90.0) return cdl_lumens(type_ab_flux(p, -90.0, 90.0));
    if (lo == 90.0 && hi == 180.0) return cdl_lumens(p->flux_lm - type_ab_flux(p, -90.0, 90.0));
    /* whole degrees by quadrature, fractional ends by linear share of their degree */
    int a = (int)floor(lo), b = (int)ceil(hi);
    double acc = 0.0;
    double *deg = calloc((size_t)(b - a), sizeof *deg);
    if (!deg) return cdl_lumens(NAN);
    quadrature_zones(p, a, b, 1.0, a, deg);
    for (int k = a; k < b; ++k) {
        double from = fmax(lo, (double)k), to = fmin(hi, (double)(k + 1));
        acc += deg[k - a] * (to - from);
    }
    free(deg);
    return cdl_lumens(acc);
}
