/* sphere_quadrature.c - the distribution sampled for weighted integrals (sphere_quadrature.h). */
#include "lights/photometry/sphere_quadrature.h"

#include <math.h>
#include <stdlib.h>

#include "base/sort_doubles.h"
#include "radiometry/constants.h"

/* Gauss-Legendre, 2 nodes on [-1, 1], weights 1 (Abramowitz and Stegun 25.4.29). */
static const double gl2 = 0.57735026918962576451; /* 1 / sqrt(3) */

/* A type A/B table's finest spacing refines the steps by halving, down to this. */
#define FINEST_STEP_DEG (1.0 / 64.0)
/* Nodes at most: beyond this a type C table's own cuts are left out (C
 * first), and an A/B table's steps are refined less, so that a table of
 * thousands of angles stays in memory and its integrals take well under a
 * second. */
#define MAX_NODES ((size_t)1 << 23)
/* Cuts closer than this (degrees) are one cut. */
#define CUT_MERGE_DEG 1e-9

/* Angles as they fall on the full circle of C: a stored plane and its
 * images under each symmetry (C -> -C, C -> 180 - C, C -> 180 + C). */
static double wrap_c(double c)
{
    c = fmod(c, 360.0);
    return c < 0.0 ? c + 360.0 : c;
}

/* The sorted cuts of [lo, hi]: every step, and the extra angles inside
 * (with their C images when c_images). NULL when out of memory. */
static double *make_cuts(double lo, double hi, double step, const double *extra, size_t nextra, int c_images,
                         size_t *count)
{
    size_t steps = (size_t)llround((hi - lo) / step);
    if (steps < 1) steps = 1;
    size_t images = c_images ? 4 : 1, cap = steps + 1 + nextra * images, n = 0;
    double *x = malloc(cap * sizeof *x);
    if (!x) return NULL;
    for (size_t s = 0; s <= steps; ++s) x[n++] = s == steps ? hi : lo + (hi - lo) * (double)s / (double)steps;
    for (size_t k = 0; k < nextra; ++k) {
        double a = extra[k];
        double image[4] = {a, wrap_c(-a), wrap_c(180.0 - a), wrap_c(180.0 + a)};
        for (size_t m = 0; m < images; ++m)
            if (image[m] > lo && image[m] < hi) x[n++] = image[m];
    }
    cdl_sort_doubles(x, n);
    size_t u = 1;
    for (size_t k = 1; k < n; ++k)
        if (x[k] - x[u - 1] > CUT_MERGE_DEG) x[u++] = x[k];
    x[u - 1] = hi; /* the last cut is the range's end */
    *count = u;
    return x;
}

/* The finest spacing of a sorted angle list (infinity for one angle). */
static double finest_spacing(const double *a, size_t n)
{
    double s = INFINITY;
    for (size_t k = 1; k < n; ++k)
        if (a[k] - a[k - 1] > 0.0) s = fmin(s, a[k] - a[k - 1]);
    return s;
}

/* A step halved until it is no coarser than `finest` (or FINEST_STEP_DEG). */
static double refined_step(double step, double finest)
{
    while (step > finest && step * 0.5 >= FINEST_STEP_DEG) step *= 0.5;
    return step;
}

int cdl_sphere_quadrature_sample(const cdl_photometry *p, double g0, double g1, double dg, size_t nc,
                                 cdl_sphere_quadrature *q)
{
    return cdl_sphere_quadrature_sample_cut(p, g0, g1, dg, nc, NULL, 0, q);
}

int cdl_sphere_quadrature_sample_cut(const cdl_photometry *p, double g0, double g1, double dg, size_t nc,
                                     const double *gamma_cuts, size_t ncuts, cdl_sphere_quadrature *q)
{
    *q = (cdl_sphere_quadrature){0};
    double dc = 360.0 / (double)nc;
    int type_c = p->type == CDL_PHOTOMETRIC_TYPE_C;
    if (!type_c) {
        double finest = fmin(finest_spacing(p->h, p->nh), finest_spacing(p->v, p->nv));
        dg = refined_step(dg, finest);
        dc = refined_step(dc, finest);
        /* within MAX_NODES: the finer step coarsened again, a halving undone at a time */
        while (2.0 * ceil((g1 - g0) / dg) * (360.0 / dc) > (double)MAX_NODES) {
            if (dg < dc) dg *= 2.0;
            else dc *= 2.0;
        }
    }
    /* the cuts asked for, then a type C table's own angles (C first to go
     * when the nodes would be too many; the cuts asked for never go) */
    size_t table_g = type_c ? p->nv : 0;
    double *asked = malloc((ncuts + table_g + 1) * sizeof *asked);
    if (!asked) return 0;
    for (size_t k = 0; k < ncuts; ++k) asked[k] = gamma_cuts[k];
    for (size_t k = 0; k < table_g; ++k) asked[ncuts + k] = p->v[k];
    size_t extra_c = type_c && p->nh > 1 ? p->nh : 0, extra_g = ncuts + table_g;
    double *gc = NULL, *cc = NULL;
    size_t ngc = 0, ncc = 0;
    for (int attempt = 0; attempt < 3; ++attempt) {
        free(gc);
        free(cc);
        gc = make_cuts(g0, g1, dg, asked, extra_g, 0, &ngc);
        cc = make_cuts(0.0, 360.0, dc, p->h, extra_c, 1, &ncc);
        if (!gc || !cc) break;
        if (2 * (ngc - 1) * (ncc - 1) <= MAX_NODES) break;
        if (extra_c) extra_c = 0;
        else extra_g = ncuts;
    }
    free(asked);
    if (!gc || !cc) {
        free(gc);
        free(cc);
        return 0;
    }
    q->ng = 2 * (ngc - 1);
    q->nc = ncc - 1;
    q->gamma_deg = malloc(q->ng * sizeof *q->gamma_deg);
    q->weight = malloc(q->ng * sizeof *q->weight);
    q->c_deg = malloc(q->nc * sizeof *q->c_deg);
    q->c_weight = malloc(q->nc * sizeof *q->c_weight);
    q->cd = malloc(q->ng * q->nc * sizeof *q->cd);
    if (!q->gamma_deg || !q->weight || !q->c_deg || !q->c_weight || !q->cd) {
        free(gc);
        free(cc);
        cdl_sphere_quadrature_free(q);
        return 0;
    }
    /* C: the midpoint of each interval, weighted by its width */
    for (size_t j = 0; j < q->nc; ++j) {
        q->c_deg[j] = 0.5 * (cc[j] + cc[j + 1]);
        q->c_weight[j] = (cc[j + 1] - cc[j]) * CDL_DEG_TO_RAD;
    }
    /* gamma: two Gauss-Legendre nodes per interval, each weighing half of it times sin(gamma) */
    for (size_t s = 0; s + 1 < ngc; ++s)
        for (int k = 0; k < 2; ++k) {
            size_t i = 2 * s + (size_t)k;
            double mid = 0.5 * (gc[s] + gc[s + 1]), half = 0.5 * (gc[s + 1] - gc[s]);
            double g = mid + half * (k ? gl2 : -gl2);
            q->gamma_deg[i] = g;
            q->weight[i] = sin(g * CDL_DEG_TO_RAD) * half * CDL_DEG_TO_RAD;
            for (size_t j = 0; j < q->nc; ++j)
                q->cd[i * q->nc + j] = cdl_photometry_intensity_c_gamma(p, q->c_deg[j], g).cd;
        }
    free(gc);
    free(cc);
    return 1;
}

double cdl_sphere_quadrature_flux(const cdl_sphere_quadrature *q)
{
    double sum = 0.0;
    for (size_t i = 0; i < q->ng; ++i) {
        double ring = 0.0;
        for (size_t j = 0; j < q->nc; ++j) ring += q->cd[i * q->nc + j] * q->c_weight[j];
        sum += ring * q->weight[i];
    }
    return sum;
}

void cdl_sphere_quadrature_free(cdl_sphere_quadrature *q)
{
    free(q->gamma_deg);
    free(q->weight);
    free(q->c_deg);
    free(q->c_weight);
    free(q->cd);
    *q = (cdl_sphere_quadrature){0};
}
