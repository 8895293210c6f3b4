/* pathtrace.h - interreflected light by path tracing: the unbiased reference.
 *
 * Paths (transport/path.h) start from each grid point, their first
 * direction cosine-weighted; their mean is the point's interreflected
 * illuminance.
 *
 * Each point is sampled in two stages (radiometry/estimate.h), its first
 * direction stratified over k x k cells of the cosine-weighted hemisphere,
 * two paths a cell, so that each stage's variance has an unbiased
 * estimate: a pilot of 8 x 8 cells plans how many paths the point needs for
 * the variance of E = E_dir + E_ind to meet the target (its variance
 * modelled as falling as N^-alpha, alpha measured on the grid, with a
 * margin for the pilot's own error), and the stage of that size, alone, is
 * reported.
 * Random numbers are keyed by (seed, grid, point, path): the result of a
 * point depends on nothing else.
 */
#ifndef CANDELA_SOLVER_PATHTRACE_H
#define CANDELA_SOLVER_PATHTRACE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/direct/direct.h"
#include "solver/grid/grid.h"
#include "solver/pool.h"
#include "solver/transport/path.h"

typedef struct cdl_pathtrace_context {
    cdl_path_context path;
    double target;                        /* relative standard error of a point's E = E_dir + E_ind */
    double max_paths;                     /* most paths a point (the cost's bound) */
    double alpha;                         /* the exponent a point's plan takes, Var ~ N^-alpha (below 1: 1);
                                           * cdl_pathtrace_solve_grid measures it for its grid */
    double alpha_paths;                   /* the paths up to which alpha was measured; beyond, the plan
                                           * takes Var ~ N^-alpha_beyond (cdl_pathtrace_solve_grid sets both) */
    double alpha_beyond;
    int measure_alpha;                    /* 1: cdl_pathtrace_solve_grid measures alpha; 0: takes 1 */
} cdl_pathtrace_context;

/* What a grid's plan took: the exponent alpha measured on it and the
 * points that measured it (fewer than 3, or too far apart: alpha = 1). */
typedef struct cdl_pathtrace_convergence {
    double alpha;
    size_t measured;
    double spread;        /* the measured exponents' quartile spread */
    double reach_paths;   /* the paths of the calibration rounds of 8 pilots: alpha holds up to them */
    double alpha_beyond;  /* the exponent beyond: between rounds of 8 and 64 pilots (<= alpha; alpha unmeasured) */
    size_t measured_beyond; /* the points that measured alpha_beyond (fewer than 3: it is alpha) */
    int agreed;           /* 1: measured at 3 points or more, the spread small enough to plan by */
} cdl_pathtrace_convergence;

/* The interreflected illuminance at every point of a grid, and its
 * variance, given the points' direct illuminance and its variance (their
 * sum is held to the target), on the workers (pool.h; with ranks kept, a
 * rank needs only its block's direct light, and rank 0's stats get every
 * point's tallies). grid_index keys the random numbers. The points' plans
 * take the exponent measured on the grid (pathtrace.c; 1 unmeasured when
 * ctx->measure_alpha is 0), reported in *convergence (may be NULL);
 * ctx->alpha is not read. */
cdl_status cdl_pathtrace_solve_grid(const cdl_pathtrace_context *ctx, const cdl_grid *grid, size_t grid_index,
                                    const double *E_direct, const double *var_direct, double *E_indirect,
                                    double *var_indirect, const cdl_workers *workers, const char *stage,
                                    cdl_pathtrace_convergence *convergence, cdl_path_stats *stats, cdl_error *err);

/* The same for one point (p, unit n) with stream `stream`; adds to *stats
 * and its paths' sums to *tally. */
void cdl_pathtrace_point(const cdl_pathtrace_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n, double E_direct,
                         double var_direct, double *E_indirect, double *var_indirect, cdl_path_stats *stats,
                         cdl_path_tally *tally);

#endif
