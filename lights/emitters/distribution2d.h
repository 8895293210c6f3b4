/* distribution2d.h - sampling a grid of cells in proportion to their weights.
 *
 * A piecewise-constant 2D distribution over nx x ny cells (row-major, row j
 * of nx cells), weight(i, j) = values[j nx + i] x row_scale[j]: the marginal
 * over rows, then the conditional within the chosen row, each by inverting
 * its cumulative sum (pbrt-v4 PiecewiseConstant2D; Pharr, Jakob and
 * Humphreys, "Physically Based Rendering" 4th ed., 2023, A.5). Used for
 * environment images, where values are luminance and the row scale is a
 * pixel's solid angle.
 *
 * A created distribution is immutable: sampling is thread-safe.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_DISTRIBUTION2D_H
#define CANDELA_LIGHTS_EMITTERS_DISTRIBUTION2D_H

#include <stddef.h>

#include "base/error.h"

typedef struct cdl_distribution2d cdl_distribution2d;

/* values: nx * ny finite numbers >= 0 (copied into sums, not kept);
 * row_scale: ny finite numbers >= 0, or NULL for all 1. An all-zero grid is
 * allowed (total 0: sampling then returns 0). Errors: CDL_ERR_INPUT for a
 * negative or non-finite weight, naming the cell. */
cdl_status cdl_distribution2d_create(const float *values, const double *row_scale, size_t nx, size_t ny,
                                     cdl_distribution2d **out, cdl_error *err);
void cdl_distribution2d_release(cdl_distribution2d *d);

/* Sum of all weights. */
double cdl_distribution2d_total(const cdl_distribution2d *d);

/* Picks a cell with probability weight / total from u1 (row) and u2 (column)
 * in [0, 1), and returns in fx, fy in [0, 1] where u1, u2 fell within the
 * cell's share, so that stratified (u1, u2) give stratified points inside
 * cells. Returns 0 when the total is 0. */
int cdl_distribution2d_sample(const cdl_distribution2d *d, double u1, double u2, size_t *i, size_t *j, double *fx,
                              double *fy);

/* Inverts a normalised cumulative sum cdf[0..n) (non-decreasing, last = 1):
 * the first k with cdf[k] > u, so cells of zero weight are never chosen,
 * and in *frac where u fell within [cdf[k-1], cdf[k]). u in [0, 1). */
size_t cdl_distribution_invert_cdf(const double *cdf, size_t n, double u, double *frac);

#endif
