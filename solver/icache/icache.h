/* icache.h - interreflected light by an irradiance cache (method "icache").
 *
 * Records (icache_record.h) are gathered at some grid points and
 * interpolated at all of them, with the weights of Tabellion and Lamorlette
 * ("An approximate global illumination system for computer generated
 * films", SIGGRAPH 2004) as Krivanek and Gautron write them ("Practical
 * Global Illumination with Irradiance Caching", Synthesis Lectures on
 * Computer Graphics and Animation, 2009):
 *     w_i(p) = 1 - kappa max( |p - p_i| / clamp(2 R_i, Rmin, Rmax),
 *                             sqrt(1 - n . n_i) / sqrt(1 - cos 10 deg) ),
 *     E(p)   = sum_{w_i > 0} w_i (E_i + (n_i x n) . g_r,i + (p - p_i) . g_t,i) / sum w_i,
 * plus, per record, the second-order term its gradient leaves out, 1/2
 * (g(p) - g_t,i) . (p - p_i) with g(p) the weighted mean of the records'
 * g_t (the trapezoid rule along p_i -> p; icache.c says what it buys),
 * a record serving only points in front of it (the behind test: (p - p_i) .
 * (n + n_i) / 2 may not be below -1 % of its reach) and only points it can
 * see (the leak test: a ray from p_i to p; a wall or a table top between
 * them rejects the record, so light does not bleed through).
 *
 * Placement depends only on the grid and the scene, never on the order of
 * queries or on other grids: a first pass seeds records on a lattice of the
 * grid's points; each further pass looks at every point, and where the
 * stated error of the interpolation is above its share of the target (or
 * no record serves the point), asks for a record there, taking the asking
 * points in index order and skipping any within a minimum distance of one
 * taken in the same pass. Every record's random numbers are keyed by the
 * grid point it sits on. The result: the same bytes for any thread count.
 *
 * The stated error of a point: the records' own noise, sum w_i^2 var_i /
 * (sum w_i)^2, plus the interpolation's, the spread of the records'
 * extrapolations to p beyond what their noise explains (where records
 * seen from p disagree, the interpolant is uncertain by about that much).
 * A point whose stated error, with its direct light's, is still above the
 * target after placement is given a record of its own, gathered to the
 * point's whole target and serving no other point (icache.c: OWN_RADIUS),
 * so that every point meets the target.
 */
#ifndef CANDELA_SOLVER_ICACHE_H
#define CANDELA_SOLVER_ICACHE_H

#include <stddef.h>

#include "base/error.h"
#include "solver/grid/grid.h"
#include "solver/icache/icache_record.h"
#include "solver/pool.h"
#include "solver/transport/path.h"

typedef struct cdl_icache_context {
    cdl_path_context path;
    double target;            /* relative standard error of a point's E = E_dir + E_ind */
    int gradients;            /* 1: interpolate with the records' gradients (the default); 0: without */
    int own_alone;            /* 1: a record of a point's own is not joined with the interpolation there */
} cdl_icache_context;

/* A grid's records. */
typedef struct cdl_icache_records {
    cdl_icache_record *items;
    size_t count, capacity;
} cdl_icache_records;

typedef struct cdl_icache_stats {
    cdl_path_stats paths;     /* of all gathers */
    size_t records, passes;
    size_t gather_rays;       /* rays per record, the largest gather */
    size_t alone;             /* points given a record of their own: their interpolation stated more than the target */
} cdl_icache_stats;

/* The interreflected illuminance at every point of a grid and its variance,
 * given the points' direct illuminance and its variance. (Ambient
 * occlusion is not interpolated from the records' open fractions: placed
 * for irradiance, not for occlusion's sharp edges, they erred by up to 0.09
 * against a plate's configuration factor where a point's own 256 rays give
 * 0.03; each point takes its own, solver/direct/.) When `records`
 * holds records (read from a cache file), they are used as they are and
 * none is gathered; otherwise the records made are left in it (the caller
 * releases them). grid_index keys the random numbers.
 *
 * On the workers (pool.h): with ranks, every rank must hold every point's
 * direct light; each gathers its block of each pass's records and every
 * rank gets them all, in the same order (so every rank's cache is the
 * same); each interpolates its block of the points, and the final values
 * are kept by their ranks or shared as `workers` says. */
cdl_status cdl_icache_solve_grid(const cdl_icache_context *ctx, const cdl_grid *grid, size_t grid_index,
                                 const double *E_direct, const double *var_direct, double *E_indirect,
                                 double *var_indirect, cdl_icache_records *records,
                                 const cdl_workers *workers, const char *stage, cdl_icache_stats *stats,
                                 cdl_error *err);

void cdl_icache_records_release(cdl_icache_records *records);

/* ---- one cache for a solve: records shared by every target ----------------
 *
 * With surface maps, a solve keeps one cache: records placed on
 * the surfaces' meshes serve the grids too, so a floor map and a grid on
 * the floor share their gathers. Each target (the maps' vertices and
 * midpoints, round by round; then each grid) is served in turn, as
 * cdl_icache_solve_grid serves a grid, with these differences: records
 * stay in the cache for the targets after it; seeds are laid only for the
 * first target (later ones ask for records where those already there do
 * not serve them well enough, as every pass does); the limits on reach
 * come from the target's spacing (given, or as a grid's). A record's
 * radius, clamped when it is made, carries its own target's limits.
 * Deterministic: the same targets in the same order give the same records. */
typedef struct cdl_icache_shared cdl_icache_shared;

/* An empty cache over `bounds` (every point any target will look up). */
cdl_status cdl_icache_shared_create(cdl_bounds3 bounds, cdl_icache_shared **out, cdl_error *err);
void cdl_icache_shared_release(cdl_icache_shared *cache);
size_t cdl_icache_shared_count(const cdl_icache_shared *cache);

typedef struct cdl_icache_target {
    const cdl_grid *points;           /* points and normals (count of each) */
    double spacing;                   /* m: the limits' spacing; 0: as a grid's (grid_spacing) */
    size_t key;                       /* keys the random numbers of records made at its points */
    const double *E_direct, *var_direct;
    double *E_indirect, *var_indirect;
    const double *floors;             /* NULL, or per point the least E its target is relative to (lux) */
    const cdl_grid *gather_at;        /* NULL, or where a record asked for by point i is gathered (point i
                                         of this grid; normals the same): a point where two surfaces meet
                                         lies on both, and a gather there loses the rays the other one
                                         should stop, so its record is gathered a little way in front */
    int only_unserved;                /* 1: no placement passes: records only at points no record serves
                                         (which would read 0 +- 0), the rest interpolated from those there */
    int no_own_records;               /* 1: points still above the target after placement keep the error
                                         the interpolation states, rather than get a record of their own
                                         (surface maps' probes: their count grows with refinement, and a
                                         record of one's own costs a whole point's paths) */
    const cdl_workers *workers;       /* threads and ranks (as cdl_icache_solve_grid) */
    const char *stage;
    cdl_icache_stats *stats;          /* records added to it, passes, paths, own records */
} cdl_icache_target;

/* Place what the target's points need in the cache and interpolate them. */
cdl_status cdl_icache_solve_shared(const cdl_icache_context *ctx, cdl_icache_shared *cache,
                                   const cdl_icache_target *target, cdl_error *err);

#endif
