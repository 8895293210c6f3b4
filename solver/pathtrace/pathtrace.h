/* pathtrace.h - interreflected light by path tracing: the unbiased reference.
 *
 * The indirect illuminance at a point p with normal n is the light that
 * reaches it from the surfaces it sees, each reflecting diffusely:
 *     E_ind(p) = int_H L_r(x(w)) cos(theta) dw,
 *     L_r(x)   = rho(x) / pi (E_dir(x) + E_ind(x))
 * (the rendering equation for Lambertian surfaces written for irradiance;
 * Kajiya, "The rendering equation", SIGGRAPH 1986). With directions drawn
 * cosine-weighted (pdf cos / pi), one sample of the integral is
 *     pi L_r(x) = rho(x) (E_dir(x) + E_ind(x)),
 * and unrolling the recursion gives a path p -> x_1 -> x_2 -> ... whose value
 * is sum_k (prod_{j <= k} rho_j) E_dir(x_k): next-event estimation, with
 * E_dir at each vertex from the direct module (cdl_direct_estimate_point),
 * so light sources are reached only through it and never counted twice.
 * Paths end by Russian roulette: after each vertex the path goes on with
 * probability q = min(0.99, w) (w the path's throughput so far), its
 * throughput divided by q, which keeps the estimate unbiased (Arvo and Kirk,
 * "Particle transport and image synthesis", SIGGRAPH 1990). With
 * "bounces": N the path stops after N reflections instead, and what is left
 * out is estimated (cdl_pathtrace_stats).
 *
 * Each point is sampled in rounds (radiometry/estimate.h): its first
 * direction stratified over k x k cells of the cosine-weighted hemisphere,
 * two paths a cell, so every round's variance has an unbiased estimate; the
 * rounds grow until the variance of E = E_dir + E_ind meets the target.
 * Random numbers are keyed by (seed, grid, point, path): the result of a
 * point depends on nothing else.
 */
#ifndef CANDELA_SOLVER_PATHTRACE_H
#define CANDELA_SOLVER_PATHTRACE_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/error.h"
#include "solver/direct/direct.h"
#include "solver/grid/grid.h"
#include "solver/pool.h"
#include "solver/scene/scene_geometry.h"

/* Most reflections a path follows under "auto": the Russian roulette ends
 * paths long before (a path survives 1000 reflections with probability
 * 0.99^1000 = 4e-5 even in a perfectly white, closed room). */
#define CDL_PATHTRACE_MAX_DEPTH 1000

typedef struct cdl_pathtrace_context {
    const cdl_direct_context *direct;     /* lights, rays and next-event estimation */
    const cdl_scene_geometry *geometry;   /* not NULL */
    uint64_t seed;
    int bounces;                          /* CDL_BOUNCES_AUTO or the most reflections followed */
    double target;                        /* relative standard error of a point's E = E_dir + E_ind */
    double max_paths;                     /* most paths a point (the cost's bound) */
} cdl_pathtrace_context;

typedef struct cdl_pathtrace_stats {
    uint64_t paths, vertices, rays;
    uint64_t longest;                     /* most reflections of any path */
    /* Under a bounce limit N: the sums over all paths of what their N-th and
     * (N-1)-th reflections contributed (per point, divided by the point's
     * paths), from which the tail beyond N is estimated as a geometric
     * series. */
    double last, before_last, total;
    cdl_direct_sample_stats direct;       /* next-event estimation */
} cdl_pathtrace_stats;

/* The interreflected illuminance at every point of a grid, and its
 * variance, given the points' direct illuminance and its variance (their
 * sum is held to the target). grid_index keys the random numbers. */
cdl_status cdl_pathtrace_solve_grid(const cdl_pathtrace_context *ctx, const cdl_grid *grid, size_t grid_index,
                                    const double *E_direct, const double *var_direct, double *E_indirect,
                                    double *var_indirect, int threads, const cdl_progress_sink *progress,
                                    const char *stage, cdl_pathtrace_stats *stats, cdl_error *err);

/* The same for one point (p, unit n) with stream `stream`; adds to *stats. */
void cdl_pathtrace_point(const cdl_pathtrace_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n, double E_direct,
                         double var_direct, double *E_indirect, double *var_indirect, cdl_pathtrace_stats *stats);

/* The fraction of the interreflected light a bounce limit left out,
 * estimated from the stats' last two reflections (0 under "auto"). */
double cdl_pathtrace_left_out(const cdl_pathtrace_stats *stats);

#endif
