/* bench_ladder.h - a ladder of solves measured against a converged reference.
 *
 * Shared by `candela bench` (tools/cmd_bench.c) and tools/bench/bench_icache:
 * a rung is one whole solve of the scene with its method and target_error
 * overridden (same seed); its error is measured against a reference solve
 * (path tracing to a small target) over every point of every grid.
 *
 * Errors are relative to the reference's E and given as fractions (points
 * where the reference's E is 0 have no relative error and are left out):
 *   rms       RMS of (E - E_ref)/E_ref with the reference's own noise taken
 *             out in quadrature (never below zero);
 *   worst     the largest |E - E_ref|/E_ref (noise of both included);
 *   within2   share of points with |E - E_ref| <= 2 sqrt(s^2 + s_ref^2);
 *   stated    RMS of E_stderr/E: the error the rung says it has.
 * No printing; pure functions of their arguments except where a file or
 * a solve is named.
 */
#ifndef CANDELA_SOLVER_BENCH_LADDER_H
#define CANDELA_SOLVER_BENCH_LADDER_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"

typedef struct cdl_bench_rung {
    cdl_method method;
    double target;                /* relative standard error asked for */
    double seconds;               /* wall time of the whole solve */
    uint64_t rays, records;
    double rms, worst, within2;   /* against the reference, see above */
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

/* Fill rung's measured fields (seconds, rays, records, rms, worst, within2,
 * stated_rms) from `solution` against `reference` (the same grids). */
void cdl_bench_rung_measure(const cdl_solution *solution, const cdl_solution *reference, cdl_bench_rung *rung);

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
