/* path.h - one light path from a point: the interreflected illuminance
 * estimator shared by the path tracer and the irradiance cache's gathers.
 *
 * The indirect illuminance at a point p with normal n is the light that
 * reaches it from the surfaces it sees, each reflecting diffusely:
 *     E_ind(p) = int_H L_r(x(w)) cos(theta) dw,
 *     L_r(x)   = rho(x) / pi (E_dir(x) + E_ind(x))
 * (the rendering equation for Lambertian surfaces written for irradiance;
 * Kajiya, "The rendering equation", SIGGRAPH 1986). With the first
 * direction w drawn cosine-weighted (pdf cos / pi), one sample of the
 * integral is pi L_r(x_1) = rho_1 (E_dir(x_1) + E_ind(x_1)); unrolling the
 * recursion gives a path p -> x_1 -> x_2 -> ... whose value is
 *     sum_k (prod_{j <= k} rho_j) E_dir(x_k):
 * next-event estimation, E_dir at each vertex from the direct module
 * (cdl_direct_estimate_point), so light sources are reached only through it
 * and never counted twice. Paths end by Russian roulette once their
 * throughput is small (Arvo and Kirk, "Particle transport and image
 * synthesis", SIGGRAPH 1990), which keeps the estimate unbiased; with
 * "bounces": N they stop after N reflections instead, and the tally of the
 * last two reflections estimates what was left out.
 */
#ifndef CANDELA_SOLVER_TRANSPORT_PATH_H
#define CANDELA_SOLVER_TRANSPORT_PATH_H

#include <stddef.h>
#include <stdint.h>

#include "base/rng.h"
#include "radiometry/vec3.h"
#include "solver/direct/direct.h"
#include "solver/rank_group.h"
#include "solver/scene/scene_geometry.h"

/* Most reflections a path follows under "auto": the Russian roulette ends
 * paths long before (a path survives 1000 reflections with probability
 * 0.99^1000 = 4e-5 even in a perfectly white, closed room). */
#define CDL_PATH_MAX_DEPTH 1000

/* What is already known of the light arriving at a path's first vertex
 * (the irradiance cache's records, at its gathers' first hits): `lookup`
 * returns 1 when it knows the interreflected irradiance arriving at (p, n),
 * into *E (lx); the path then ends there, its value w rho (E_dir + E) with
 * w rho = `scale` (the lookup keeps the account of its own error, which
 * the paths' spread does not show: one cached value serves many paths). */
typedef struct cdl_path_first_hit {
    int (*lookup)(void *user, cdl_vec3 p, cdl_vec3 n, double scale, double *E);
    void *user;
} cdl_path_first_hit;

typedef struct cdl_path_context {
    const cdl_direct_context *direct;     /* lights, rays and next-event estimation */
    const cdl_scene_geometry *geometry;   /* not NULL */
    uint64_t seed;
    int bounces;                          /* CDL_BOUNCES_AUTO or the most reflections followed */
    const cdl_path_first_hit *first_hit;  /* NULL, or asked at the first vertex (bounces "auto" only) */
} cdl_path_context;

typedef struct cdl_path_stats {
    uint64_t paths, vertices, rays;
    uint64_t longest;                     /* most reflections of any path */
    /* Under a bounce limit N: the sums over all paths of what their N-th and
     * (N-1)-th reflections contributed, and of all they carried, from which
     * the tail beyond N is estimated as a geometric series. */
    double last, before_last, total;
    cdl_direct_sample_stats direct;       /* next-event estimation */
} cdl_path_stats;

typedef struct cdl_path_result {
    double value;             /* sum_k (prod rho) E_dir(x_k): one sample of E_ind, lx */
    double potential;         /* rho_1 x the first vertex's unoccluded direct light, lx */
    double distance;          /* to the first vertex, m (INFINITY when the ray left the scene) */
    double last, before_last; /* what reflections N and N - 1 gave (bounce limit N) */
} cdl_path_result;

/* What the bounce-limit estimate needs of one item's paths (a grid point's,
 * a record's): the sums of their N-th and (N-1)-th reflections and of all
 * they carried. Kept per item and added to the stats in item order, so
 * that the sums do not depend on which thread took which item. */
typedef struct cdl_path_tally {
    double last, before_last, total;
} cdl_path_tally;

static inline void cdl_path_tally_add(cdl_path_tally *t, const cdl_path_result *r)
{
    t->last += r->last;
    t->before_last += r->before_last;
    t->total += r->value;
}

/* stats' last, before_last and total += those of tallies[0 .. count - 1], in order. */
void cdl_path_stats_add_tallies(cdl_path_stats *stats, const cdl_path_tally *tallies, size_t count);

/* One path from p (on a surface of unit normal n) leaving along unit
 * `dir`; random numbers from `key` (counter 0 is left to the caller, e.g.
 * for jittering `dir`). Adds to *stats' counts; its floating-point sums
 * come from the callers' tallies. */
void cdl_transport_path(const cdl_path_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                        cdl_path_result *out, cdl_path_stats *stats);

/* to += from */
void cdl_path_stats_add(cdl_path_stats *to, const cdl_path_stats *from);

/* s's counts added up (its longest path the longest) over the ranks of
 * `group` (a collective; nothing without one). Its floating-point sums are
 * left alone: they come from per-item tallies, added in item order once
 * the ranks have exchanged them. */
cdl_status cdl_path_stats_share(cdl_rank_group *group, cdl_path_stats *s, cdl_error *err);

/* The fraction of the interreflected light a bounce limit left out,
 * estimated from the stats' last two reflections (0 when nothing was cut). */
double cdl_path_left_out(const cdl_path_stats *stats);

#endif
