/* icache_record.h - an irradiance-cache record and the gather that makes it.
 *
 * A record holds the interreflected irradiance E_i at a point p_i with
 * normal n_i, before any reflectance (it serves a surface of any colour,
 * and a work plane, which has none), with what is needed to use it nearby:
 *  - its rotational and translational gradients (Ward and Heckbert,
 *    "Irradiance gradients", Eurographics Rendering Workshop 1992), so that
 *    a point p, n near it is given E_i + (n_i x n) . g_r + (p - p_i) . g_t;
 *  - its validity radius R_i, from the harmonic mean of the distances its
 *    gather rays travelled (Ward, Rubinstein and Clear, SIGGRAPH 1988);
 *  - the variance of its own E_i (the gather is a Monte Carlo estimate).
 *
 * The gather: M x N strata of the cosine-weighted hemisphere,
 *     (theta, phi) = (arccos sqrt(1 - (j + u1) / M), 2 pi (k + u2) / N),
 * one path each (transport/path.h): a path's value is pi L of the surface
 * its first ray reaches, excluding emission (light sources enter through
 * next-event estimation at every vertex, the direct module's work), with
 * further reflections path-traced from there. So E_i = (1 / MN) sum v_jk
 * holds only interreflected light. Path tracing from the gather hits,
 * rather than caches of every bounce: a per-bounce cache needs records on
 * every surface the gathers reach, not only on the grids asked for, and
 * its error compounds bounce over bounce; the paths beyond the first hit
 * are unbiased and, with next-event estimation, cheap (in the closed-box
 * test 2.3 vertices a path on average). Where the cache's records do lie
 * on the surface a first hit reaches (surface maps), the path may end
 * there on the records' interpolation, its error accounted for
 * (icache.c, gather_records, through the path context's first_hit).
 */
#ifndef CANDELA_SOLVER_ICACHE_RECORD_H
#define CANDELA_SOLVER_ICACHE_RECORD_H

#include <stdint.h>

#include "base/rng.h"
#include "radiometry/vec3.h"
#include "solver/transport/path.h"

typedef struct cdl_icache_record {
    cdl_vec3 p, n;            /* where, unit normal */
    double E;                 /* interreflected irradiance before reflectance, lx */
    double var;               /* variance of E, lx^2 */
    double radius;            /* validity radius R_i (harmonic mean distance, clamped), m */
    cdl_vec3 grad_r;          /* rotational gradient, lx per radian (axis n_i x n) */
    cdl_vec3 grad_t;          /* translational gradient, lx / m */
    double open;              /* fraction of gather rays that left the scene (cosine-weighted) */
    double harmonic;          /* unclamped harmonic mean distance, m (INFINITY when all rays left) */
} cdl_icache_record;

/* Gather M x N strata (N even) at p (unit normal n) into *rec (all fields
 * but `radius`, which the cache sets from harmonic and its limits).
 * Random numbers from `key`; counts added to *stats, the paths' sums to
 * *tally (when not NULL). Returns 0 when memory ran out. */
int cdl_icache_gather(const cdl_path_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, int M, int N,
                      cdl_icache_record *rec, cdl_path_stats *stats, cdl_path_tally *tally);

#endif
