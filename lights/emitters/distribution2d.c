/* distribution2d.c - piecewise-constant 2D sampling by inverse cumulative sums. */
#include "base/error_report.h"
#include "lights/emitters/distribution2d.h"

#include <math.h>
#include <stdlib.h>

struct cdl_distribution2d {
    size_t nx, ny;
    double total;
    double *row_cdf; /* ny: cumulative row sums / total (last = 1) */
    double *cdf;     /* nx * ny: within each row, cumulative / row sum (last = 1) */
};

void cdl_distribution2d_release(cdl_distribution2d *d)
{
    if (!d) return;
    free(d->row_cdf);
    free(d->cdf);
    free(d);
}

/* Cumulative sums of w[0..n) into cdf, normalised so the last is exactly 1;
 * returns the sum (cdf left all zero when it is 0). */
static double build_cdf(double *cdf, size_t n)
{
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k) {
        sum += cdf[k];
        cdf[k] = sum;
    }
    if (sum > 0.0) {
        for (size_t k = 0; k < n; ++k) cdf[k] /= sum;
        cdf[n - 1] = 1.0;
    }
    return sum;
}

cdl_status cdl_distribution2d_create(const float *values, const double *row_scale, size_t nx, size_t ny,
                                     cdl_distribution2d **out, cdl_error *err)
{
    *out = NULL;
    if (nx == 0 || ny == 0 || nx > ((size_t)-1) / sizeof(double) / ny)
        return cdl_error_set(err, CDL_ERR_INPUT, "distribution: expected at least 1 x 1 cells, found %zu x %zu", nx,
                             ny);
    cdl_distribution2d *d = calloc(1, sizeof *d);
    if (!d) return cdl_error_out_of_memory(err);
    d->nx = nx;
    d->ny = ny;
    d->row_cdf = malloc(ny * sizeof *d->row_cdf);
    d->cdf = malloc(nx * ny * sizeof *d->cdf);
    if (!d->row_cdf || !d->cdf) {
        cdl_distribution2d_release(d);
        return cdl_error_out_of_memory(err);
    }
    for (size_t j = 0; j < ny; ++j) {
        double scale = row_scale ? row_scale[j] : 1.0;
        if (!(isfinite(scale) && scale >= 0.0)) {
            cdl_distribution2d_release(d);
            return cdl_error_set(err, CDL_ERR_INPUT, "distribution: row %zu: expected a finite scale >= 0, found %g",
                                 j, scale);
        }
        double *row = d->cdf + j * nx;
        for (size_t i = 0; i < nx; ++i) {
            double v = values[j * nx + i];
            if (!(isfinite(v) && v >= 0.0)) {
                cdl_distribution2d_release(d);
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "distribution: cell (column %zu, row %zu): expected a finite value >= 0, found %g",
                                     i, j, v);
            }
            row[i] = v * scale;
        }
        d->row_cdf[j] = build_cdf(row, nx);
    }
    d->total = build_cdf(d->row_cdf, ny);
    if (!isfinite(d->total)) {
        double total = d->total;
        cdl_distribution2d_release(d);
        return cdl_error_set(err, CDL_ERR_INPUT, "distribution: expected a finite total weight, found %g", total);
    }
    *out = d;
    return CDL_OK;
}

double cdl_distribution2d_total(const cdl_distribution2d *d)
{
    return d->total;
}

size_t cdl_distribution_invert_cdf(const double *cdf, size_t n, double u, double *frac)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cdf[mid] > u) hi = mid;
        else lo = mid + 1;
    }
    double start = lo > 0 ? cdf[lo - 1] : 0.0, width = cdf[lo] - start;
    *frac = width > 0.0 ? fmin(fmax((u - start) / width, 0.0), 1.0) : 0.5;
    return lo;
}

int cdl_distribution2d_sample(const cdl_distribution2d *d, double u1, double u2, size_t *i, size_t *j, double *fx,
                              double *fy)
{
    if (!(d->total > 0.0)) return 0;
    *j = cdl_distribution_invert_cdf(d->row_cdf, d->ny, u1, fy);
    *i = cdl_distribution_invert_cdf(d->cdf + *j * d->nx, d->nx, u2, fx);
    return 1;
}
