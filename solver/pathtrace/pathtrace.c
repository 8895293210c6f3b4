/* pathtrace.c - paths from grid points, next-event estimation at every vertex. */
#include "solver/pathtrace/pathtrace.h"

#include "solver/direct/direct_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/estimate.h"
#include "radiometry/frame.h"
#include "base/rng.h"
#include "radiometry/sampling.h"

/* Strata per side of a point's pilot round, and the least of a reported
 * stage: 8 x 8 cells, 128 paths, a variance estimate of 64 degrees of
 * freedom. */
#define PILOT_SIDE 8

/* One round: k x k cells of the first direction, two paths a cell. */
static void path_round(const cdl_pathtrace_context *ctx, uint64_t stream, uint64_t base, cdl_vec3 p, cdl_vec3 n,
                       int k, cdl_estimate *est, double *potential_sum, cdl_path_stats *stats, cdl_path_tally *tally)
{
    cdl_frame f = cdl_frame_from_normal(n);
    cdl_round round = {0.0, 0.0, 0.0, 0};
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double v[2];
            for (int s = 0; s < 2; ++s) {
                uint64_t path = base + (uint64_t)(2 * (j * k + i) + s);
                cdl_rng_key key = {ctx->path.seed, cdl_rng_stream_id(stream, path, 0x70617468 /* "path" */)};
                double u[2];
                cdl_rng_uniform2(key, 0, u);
                cdl_vec3 dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere((i + u[0]) / k, (j + u[1]) / k));
                cdl_path_result r;
                cdl_transport_path(&ctx->path, key, p, n, dir, &r, stats);
                v[s] = r.value;
                *potential_sum += r.potential;
                cdl_path_tally_add(tally, &r);
            }
            cdl_round_add_pair(&round, v[0], v[1]);
        }
    cdl_estimate_add_round(est, &round);
}

/* The variance of an estimate of paths, at least what paths that all gave
 * nothing could have missed (estimate.h). */
static double paths_variance(const cdl_estimate *est, double potential)
{
    double v = cdl_estimate_variance(est);
    if (est->nonzero == 0) {
        double unseen = cdl_estimate_unseen_variance(est->samples, potential);
        if (unseen > v) v = unseen;
    }
    return v;
}

void cdl_pathtrace_point(const cdl_pathtrace_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n, double E_direct,
                         double var_direct, double *E_indirect, double *var_indirect, cdl_path_stats *stats,
                         cdl_path_tally *tally)
{
    /* The pilot: how variable are this point's paths, how much light. */
    cdl_estimate pilot = {0.0, 0.0, 0.0, 0};
    double potential_sum = 0.0;
    path_round(ctx, stream, 0, p, n, PILOT_SIDE, &pilot, &potential_sum, stats, tally);
    uint64_t taken = (uint64_t)pilot.samples;
    double potential = potential_sum / pilot.samples;
    /* The point's E = E_dir + E_ind is held to t; the direct part was held
     * to t / sqrt 2 (half the variance), the rest is the paths'. A point in
     * the dark is held to a thousandth of what its paths could carry. */
    double R = fmax(E_direct + cdl_estimate_mean(&pilot), 1e-3 * potential);
    double whole = ctx->target * ctx->target * R * R;
    double budget = fmax(whole - var_direct, 0.5 * whole);
    double least = 2.0 * PILOT_SIDE * PILOT_SIDE, want;
    if (pilot.nonzero == 0) {
        /* A pilot that saw nothing: as many paths as hold what all of them
         * could have missed to the budget (estimate.h). */
        want = cdl_estimate_plan_unseen(potential, budget, least);
    } else {
        cdl_estimate planning = pilot;
        planning.var_num = paths_variance(&pilot, potential) * pilot.samples * pilot.samples;
        want = cdl_estimate_plan(&planning, budget, least);
    }
    /* The reported stage: its size depends on the pilot only, so its mean
     * and its variance estimate are those of a fixed number of paths
     * (estimate.h). Should the pilot have seen too little, the stated error
     * is above the target, and says so. */
    if (want > ctx->max_paths - (double)taken) want = ctx->max_paths - (double)taken;
    cdl_estimate est = {0.0, 0.0, 0.0, 0};
    path_round(ctx, stream, taken, p, n, cdl_estimate_side_for(want, PILOT_SIDE, 1 << 12), &est, &potential_sum,
               stats, tally);
    *E_indirect = cdl_estimate_mean(&est);
    *var_indirect = paths_variance(&est, potential);
}

/* ---- a grid on the worker pool ---------------------------------------------- */

typedef struct grid_job {
    const cdl_pathtrace_context *ctx;
    const cdl_grid *grid;
    size_t grid_index;
    const double *E_direct, *var_direct;
    double *E_indirect, *var_indirect;
    cdl_path_tally *tallies;  /* per point (summed in point order after) */
} grid_job;

static cdl_status trace_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)err;
    const grid_job *job = shared;
    cdl_path_stats *stats = local;
    for (size_t i = begin; i < end; ++i) {
        uint64_t stream = cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x707472616365 /* "ptrace" */);
        /* A point on a line where two surfaces meet (a floor point at the
         * foot of a wall) sends its paths from just off it, on the side the
         * grid is meant for, as its direct light is found there: from the
         * line itself the rays towards the other surface start in its plane
         * and pass it unseen (measured on a floor at the foot of a wall:
         * 88 lx interreflected on the line, 125 lx a millimetre off it). */
        cdl_vec3 from = job->grid->points[i];
        if (job->ctx->path.direct) cdl_direct_edge_point(job->ctx->path.direct, from, job->grid->normals[i], &from);
        cdl_pathtrace_point(job->ctx, stream, from, job->grid->normals[i], job->E_direct[i],
                            job->var_direct[i], &job->E_indirect[i], &job->var_indirect[i], stats, &job->tallies[i]);
    }
    return CDL_OK;
}

cdl_status cdl_pathtrace_solve_grid(const cdl_pathtrace_context *ctx, const cdl_grid *grid, size_t grid_index,
                                    const double *E_direct, const double *var_direct, double *E_indirect,
                                    double *var_indirect, const cdl_workers *workers, const char *stage,
                                    cdl_path_stats *stats, cdl_error *err)
{
    int threads = workers->threads < 1 ? 1 : workers->threads;
    cdl_path_stats *locals = calloc((size_t)threads, sizeof *locals);
    cdl_path_tally *tallies = calloc(grid->count ? grid->count : 1, sizeof *tallies);
    if (!locals || !tallies) {
        free(locals);
        free(tallies);
        return cdl_error_out_of_memory(err);
    }
    grid_job job = {ctx, grid, grid_index, E_direct, var_direct, E_indirect, var_indirect, tallies};
    /* Points differ a hundredfold in cost: small chunks keep threads busy. */
    cdl_pool_task task = {.count = grid->count,
                          .chunk = 2,
                          .run = trace_points,
                          .shared = &job,
                          .locals = locals,
                          .local_size = sizeof *locals,
                          .stage = stage,
                          .outputs = {{E_indirect, sizeof *E_indirect},
                                      {var_indirect, sizeof *var_indirect},
                                      {tallies, sizeof *tallies}}};
    cdl_status st = cdl_pool_run_shared(&task, workers, err);
    cdl_path_stats sum = {0};
    for (int t = 0; t < threads; ++t) cdl_path_stats_add(&sum, &locals[t]);
    if (st == CDL_OK) st = cdl_path_stats_share(workers->ranks, &sum, err);
    /* Kept results: rank 0, which reports the stats, sums every point's tallies. */
    if (st == CDL_OK && !workers->everywhere)
        st = cdl_rank_gather_items(workers->ranks, tallies, sizeof *tallies, grid->count, CDL_RANK_KEEP_ALIGN, err);
    if (st == CDL_OK) {
        cdl_path_stats_add(stats, &sum);
        cdl_path_stats_add_tallies(stats, tallies, grid->count);
    }
    free(locals);
    free(tallies);
    return st;
}
