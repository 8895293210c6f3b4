/* bench_ladder.h - a ladder of solves measured against a converged reference.
 *
 * Shared by `candela bench` (tools/cmd_bench.c) and tools/bench/bench_icache:
 * a rung is one whole solve of the scene with its method and target_error
 * overridden (same seed); its error is measured against a reference solve
 * (path tracing to a small target) at the reference's points: every point
 * of every grid, or a simple random sample of them (cdl_bench_sample) when
 * path tracing all of them to the reference's target would cost too much.
 * The reference is solved with a seed of its own (cdl_bench_reference_seed)
 * so that its noise is independent of every rung's.
 *
 * Errors are relative to the reference's E and given as fractions (points
 * where the reference's E is 0 have no relative error and are left out):
 *   rms       RMS of (E - E_ref)/E_ref with the reference's own noise taken
 *             out in quadrature (never below zero); over a sample, an
 *             estimate of the RMS over all points;
 *   rms_sd    the standard error of rms as that estimate (0 when the
 *             reference has every point);
 *   worst     the largest |E - E_ref|/E_ref (noise of both included);
 *   within2   share of points with |E - E_ref| <= 2 sqrt(s^2 + s_ref^2);
 *   stated    RMS of E_stderr/E over all the rung's points: the error the
 *             rung says it has.
 * No printing; pure functions of their arguments except where a file or
 * a solve is named.
 */
#ifndef CANDELA_SOLVER_BENCH_LADDER_H
#define CANDELA_SOLVER_BENCH_LADDER_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/scene/scene_internal.h"
#include "solver/solution_internal.h"

typedef struct cdl_bench_rung {
    cdl_method method;
    double target;                /* relative standard error asked for */
    double seconds;               /* wall time of the whole solve */
    uint64_t rays, records;
    double rms, rms_sd;           /* against the reference, see above */
    double worst, within2;
    double stated_rms;            /* RMS of E_stderr / E */
} cdl_bench_rung;

/* A rung as `candela bench` lists it. */
typedef struct cdl_bench_row {
    char label[48];               /* "icache_normal", "pathtrace_t0.0025": also the folder under runs/ */
    const char *quality;          /* "draft", "normal", "high", or "custom" for a target between them */
    int skipped;                  /* 1: not run (it would not fit the budget); measured fields unset */
    int below_reference;          /* 1: rms not above CDL_BENCH_RESOLVABLE x the reference's stated RMS */
    cdl_bench_rung rung;
} cdl_bench_row;

/* A measured RMS error is resolved only when it is above this multiple of
 * the reference's own stated RMS: below it, the difference is mostly the
 * reference's noise and the figure says little. */
#define CDL_BENCH_RESOLVABLE 2.0

/* Solve `scene` with its settings' method and target_error replaced by
 * `method` and `target` (the scene itself is not changed). threads < 0: as
 * the scene says. */
cdl_status cdl_bench_solve_rung(const cdl_scene *scene, cdl_method method, double target, int threads,
                                cdl_solution *out, cdl_error *err);

/* RMS over all points of E_stderr/E (points with E <= 0 are skipped). */
double cdl_bench_stated_rms(const cdl_solution *solution);

/* The points a reference is computed at, as a scene of its own: `scene`
 * (the original, borrowed: keep it alive and unchanged) is the same but for
 * its grids, which are points grids of a simple random sample of `count`
 * of the `total` points of the original's grids (grids with no point
 * sampled left out), each point and normal as the original grid has it;
 * or, when the sample would have every point, the original's grids
 * themselves. The sample's seed is cdl_bench_reference_seed of the
 * original's. */
typedef struct cdl_bench_sample {
    cdl_scene scene;
    size_t total, count;
    size_t *grid_of;              /* per grid of `scene`: the original grid it samples */
    size_t **index;               /* per grid of `scene`: its points' indices in that grid, rising */
    int owns_grids;               /* 1: scene.grids and their points are this sample's */
} cdl_bench_sample;

/* The seed a reference of a scene of seed `seed` is solved with: another
 * stream, so that the reference and the rungs (solved with `seed`) share
 * no random numbers and their errors are independent. */
uint64_t cdl_bench_reference_seed(uint64_t seed);

/* Sample at most `max_points` points of `scene`'s grids (0: every point)
 * into `out` (release with cdl_bench_sample_release). The sample depends
 * on the grids' point count only (a fixed hash of each point's place in
 * the scene's order decides), never on the seed or the machine: the same
 * scene gives the same sample. CDL_ERR_INTERNAL for memory; a grid that
 * cannot be built is its error. */
cdl_status cdl_bench_sample_build(const cdl_scene *scene, size_t max_points, cdl_bench_sample *out, cdl_error *err);

/* Free what cdl_bench_sample_build allocated (the original scene is not
 * touched); harmless on a zeroed sample. */
void cdl_bench_sample_release(cdl_bench_sample *sample);

/* Fill rung's measured fields (seconds, rays, records, rms, rms_sd, worst,
 * within2, stated_rms) from `solution` (of the original scene) against
 * `reference` (a solve of sample->scene). sample NULL: the reference has
 * the solution's grids and points. */
void cdl_bench_rung_measure(const cdl_solution *solution, const cdl_solution *reference,
                            const cdl_bench_sample *sample, cdl_bench_rung *rung);

/* The time a method needs for a given RMS error, from its rungs sorted by
 * falling RMS: log t linear in log RMS between the two rungs that bracket
 * it; past the ends, Monte Carlo's t ~ RMS^-2 from the nearest rung. */
double cdl_bench_time_at_rms(const cdl_bench_rung *rungs, int count, double rms);

/* Read a reference written by cdl_solution_write into `dir` (NAME.csv per
 * grid: E_lx and E_stderr_lx) for the grids of `scene`, into `out` (grids
 * built from the scene; release with cdl_solution_release). A missing
 * file, a point that is not the scene's (to 1e-9 m) or a wrong count is
 * CDL_ERR_INPUT naming the file. */
cdl_status cdl_bench_reference_read(const char *dir, const cdl_scene *scene, cdl_solution *out, cdl_error *err);

/* What a reference of `scene` to `target` depends on, as one FNV-1a hash:
 * the scene's geometry, materials and lights (scene_hash.h), every grid's
 * name, points and normals, and the settings of the solve (target, seed,
 * bounces, direct_samples). */
cdl_status cdl_bench_reference_key(const cdl_scene *scene, double target, uint64_t *key, cdl_error *err);

#endif
