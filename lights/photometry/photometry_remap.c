/* photometry_remap.c - type C tables as full circles of planes: expansion
 * of the stored symmetry sector, moving planes (C' = +-C + offset), finding
 * the most compact exact symmetry, and resampling any table to type C. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/photometry/photometry_internal.h"

/* Angles closer than this (degrees) are the same plane. */
#define ANGLE_EPS 1e-9

typedef struct plane_ref {
    double c;     /* angle in [0, 360) */
    size_t row;   /* row of the source table */
} plane_ref;

static double wrap360(double a)
{
    a = fmod(a, 360.0);
    if (a < 0.0) a += 360.0;
    if (a >= 360.0 - ANGLE_EPS) a = 0.0;
    if (fabs(a) < ANGLE_EPS) a = 0.0;
    return a;
}

static int by_angle(const void *a, const void *b)
{
    double x = ((const plane_ref *)a)->c, y = ((const plane_ref *)b)->c;
    return x < y ? -1 : x > y ? 1 : 0;
}

/* Sort and drop duplicate angles (keeping the first). */
static size_t sort_unique(plane_ref *r, size_t n)
{
    qsort(r, n, sizeof *r, by_angle);
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
        if (k == 0 || r[i].c - r[k - 1].c > ANGLE_EPS) r[k++] = r[i];
    return k;
}

/* The images of plane c under a symmetry (other than c itself). */
static size_t images(cdl_photometry_symmetry s, double c, double out[3])
{
    switch (s) {
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT:
        out[0] = wrap360(360.0 - c);
        out[1] = wrap360(180.0 - c);
        out[2] = wrap360(180.0 + c);
        return 3;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180:
        out[0] = wrap360(360.0 - c);
        return 1;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270:
        out[0] = wrap360(180.0 - c);
        return 1;
    default:
        return 0;
    }
}

/* Every plane of the full circle, each pointing at the source row holding its values. */
static plane_ref *expand(const cdl_photometry *p, size_t *count)
{
    plane_ref *r = malloc(4 * p->nh * sizeof *r);
    if (!r) return NULL;
    size_t n = 0;
    for (size_t i = 0; i < p->nh; ++i) {
        double c = p->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL ? 0.0 : wrap360(p->h[i]);
        r[n].c = c;
        r[n++].row = i;
        double im[3];
        size_t k = images(p->symmetry, c, im);
        for (size_t j = 0; j < k; ++j) {
            r[n].c = im[j];
            r[n++].row = i;
        }
    }
    *count = sort_unique(r, n);
    return r;
}

static long find(const plane_ref *r, size_t n, double c)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (r[mid].c < c - ANGLE_EPS) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && fabs(r[lo].c - c) <= ANGLE_EPS ? (long)lo : -1;
}

static int rows_equal(const double *a, const double *b, size_t nv, double tol)
{
    for (size_t j = 0; j < nv; ++j)
        if (fabs(a[j] - b[j]) > tol) return 0;
    return 1;
}

/* Does the full circle `r` (rows in `cd`) have symmetry s exactly: every
 * plane's images are planes with equal values, and the stored sector's
 * ends are planes? */
static int has_symmetry(cdl_photometry_symmetry s, const plane_ref *r, size_t n, const double *cd, size_t nv, double tol)
{
    static const double ends[5][2] = {{0, 0}, {0, 0}, {0, 180}, {90, 270}, {0, 90}};
    if (find(r, n, ends[s][0]) < 0 || find(r, n, ends[s][1]) < 0) return 0;
    for (size_t i = 0; i < n; ++i) {
        double im[3];
        size_t k = images(s, r[i].c, im);
        for (size_t j = 0; j < k; ++j) {
            long m = find(r, n, im[j]);
            if (m < 0 || !rows_equal(cd + r[i].row * nv, cd + r[m].row * nv, nv, tol)) return 0;
        }
    }
    return 1;
}

/* Build a compact type C photometry from a full circle of planes. */
static cdl_status build_compact(const cdl_photometry *src, const plane_ref *r, size_t n, const double *cd,
                                const double *g, size_t nv, double max_cd, cdl_photometry **out, cdl_error *err)
{
    double tol = 1e-9 * (max_cd > 0.0 ? max_cd : 1.0);
    cdl_photometry_symmetry sym = CDL_PHOTOMETRY_SYMMETRY_NONE;
    int rotational = 1;
    for (size_t i = 1; i < n && rotational; ++i)
        rotational = rows_equal(cd + r[0].row * nv, cd + r[i].row * nv, nv, tol);
    if (rotational) {
        sym = CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    } else {
        const cdl_photometry_symmetry order[3] = {CDL_PHOTOMETRY_SYMMETRY_QUADRANT,
                                                  CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180,
                                                  CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270};
        for (int k = 0; k < 3 && sym == CDL_PHOTOMETRY_SYMMETRY_NONE; ++k)
            if (has_symmetry(order[k], r, n, cd, nv, tol)) sym = order[k];
    }
    double lo = 0.0, hi = 360.0;
    if (sym == CDL_PHOTOMETRY_SYMMETRY_QUADRANT) hi = 90.0;
    else if (sym == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180) hi = 180.0;
    else if (sym == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270) { lo = 90.0; hi = 270.0; }
    double *c = malloc(n * sizeof *c), *table = malloc(n * nv * sizeof *table);
    cdl_photometry *p = cdl_photometry_alloc();
    cdl_status st = CDL_OK;
    if (!c || !table || !p) st = cdl_error_out_of_memory(err);
    size_t k = 0;
    for (size_t i = 0; i < n && st == CDL_OK; ++i) {
        if (sym == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL && k == 1) break;
        if (r[i].c < lo - ANGLE_EPS || r[i].c > hi + ANGLE_EPS) continue;
        c[k] = sym == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL ? 0.0 : r[i].c;
        memcpy(table + k * nv, cd + r[i].row * nv, nv * sizeof *table);
        ++k;
    }
    if (st == CDL_OK && src && cdl_photometry_copy_metadata(p, src) != CDL_OK) st = cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = cdl_photometry_set_table(p, CDL_PHOTOMETRIC_TYPE_C, sym, c, k, g, nv, table, err);
    free(c);
    free(table);
    if (st != CDL_OK) {
        cdl_photometry_release(p);
        return st;
    }
    *out = p;
    return CDL_OK;
}

cdl_status cdl_photometry_remap_c(const cdl_photometry *p, int sign, double offset, cdl_photometry **out, cdl_error *err)
{
    *out = NULL;
    if (p->type != CDL_PHOTOMETRIC_TYPE_C)
        return cdl_error_set(err, CDL_ERR_INPUT, "only type C tables have C-planes to remap (this one is type %c)",
                             p->type == CDL_PHOTOMETRIC_TYPE_B ? 'B' : 'A');
    size_t n;
    plane_ref *r = expand(p, &n);
    if (!r) return cdl_error_out_of_memory(err);
    if (p->symmetry != CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL) {
        for (size_t i = 0; i < n; ++i) r[i].c = wrap360((sign < 0 ? -r[i].c : r[i].c) + offset);
        n = sort_unique(r, n);
    }
    cdl_status st = build_compact(p, r, n, p->cd, p->v, p->nv, p->max_cd, out, err);
    free(r);
    return st;
}

cdl_status cdl_photometry_resample_type_c(const cdl_photometry *p, double dc, double dg, cdl_photometry **out,
                                          cdl_error *err)
{
    *out = NULL;
    if (!(dc > 0.0 && dg > 0.0) || fabs(360.0 / dc - floor(360.0 / dc + 0.5)) > 1e-9 ||
        fabs(180.0 / dg - floor(180.0 / dg + 0.5)) > 1e-9)
        return cdl_error_set(err, CDL_ERR_USAGE, "resampling steps must divide 360 and 180 degrees (got %g, %g)", dc, dg);
    size_t nc = (size_t)floor(360.0 / dc + 0.5), ng = (size_t)floor(180.0 / dg + 0.5) + 1;
    plane_ref *r = malloc(nc * sizeof *r);
    double *g = malloc(ng * sizeof *g), *cd = malloc(nc * ng * sizeof *cd);
    cdl_status st = CDL_OK;
    if (!r || !g || !cd) st = cdl_error_out_of_memory(err);
    double max_cd = 0.0;
    for (size_t j = 0; j < ng && st == CDL_OK; ++j) g[j] = j + 1 == ng ? 180.0 : dg * (double)j;
    for (size_t i = 0; i < nc && st == CDL_OK; ++i) {
        r[i].c = dc * (double)i;
        r[i].row = i;
        for (size_t j = 0; j < ng; ++j) {
            double v = cdl_photometry_intensity_c_gamma(p, r[i].c, g[j]).cd;
            cd[i * ng + j] = v;
            if (v > max_cd) max_cd = v;
        }
    }
    if (st == CDL_OK) st = build_compact(p, r, nc, cd, g, ng, max_cd, out, err);
    free(r);
    free(g);
    free(cd);
    return st;
}

cdl_status cdl_photometry_full_planes(const cdl_photometry *p, double **c, size_t *count)
{
    *c = NULL;
    *count = 0;
    size_t n;
    plane_ref *r = expand(p, &n);
    double *out = r ? malloc(n * sizeof *out) : NULL;
    if (!out) {
        free(r);
        return CDL_ERR_INTERNAL;
    }
    for (size_t i = 0; i < n; ++i) out[i] = r[i].c;
    free(r);
    *c = out;
    *count = n;
    return CDL_OK;
}
