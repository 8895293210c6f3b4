/* pathtrace.c - paths from grid points, next-event estimation at every vertex. */
#include "solver/pathtrace/pathtrace.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "radiometry/estimate.h"
#include "radiometry/frame.h"
#include "radiometry/rng.h"
#include "radiometry/sampling.h"
#include "solver/transport/surface_hit.h"

/* Strata per side of a point's pilot round, and the least of a reported
 * stage: 8 x 8 cells, 128 paths, a variance estimate of 64 degrees of
 * freedom. */
#define PILOT_SIDE 8

/* Russian roulette starts when a path's throughput falls below this: paths
 * go on surely while they carry much, and the estimate stays less skewed
 * (a skewed estimate makes its own variance estimate unreliable). Measured
 * on the closed-form test set (tests/solver/pathtrace): a threshold of 1
 * (roulette from the first bounce) took 24 s with 59 % of points within
 * one stated sigma; 0.1 took 6.3 s with 74 %; 0.03 no better than 0.1. */
#define RR_THRESHOLD 0.1

/* Counter indices of a path's random numbers: index 0 is the jitter of its
 * first direction; each vertex then takes VERTEX_DRAWS consecutive indices
 * (continuation direction, roulette), and next-event estimation its own
 * key per vertex. */
#define VERTEX_DRAWS 2

typedef struct path_result {
    double value;             /* sum_k (prod rho) E_dir(x_k) */
    double potential;         /* rho_1 x the first vertex's unoccluded direct light */
    double last, before_last; /* what reflections N and N - 1 gave (bounce limit N) */
} path_result;

/* One path from p (unit n) leaving along `dir`. */
static void trace_path(const cdl_pathtrace_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                       path_result *out, cdl_pathtrace_stats *stats)
{
    memset(out, 0, sizeof *out);
    double w = 1.0;
    cdl_vec3 origin = p, origin_n = n;
    int limit = ctx->bounces == CDL_BOUNCES_AUTO ? CDL_PATHTRACE_MAX_DEPTH : ctx->bounces;
    stats->paths++;
    for (int depth = 1; depth <= limit; ++depth) {
        cdl_surface_hit hit;
        stats->rays++;
        /* A ray that leaves the scene sees the sky or nothing: direct light,
         * counted where the path started. */
        if (!cdl_transport_trace(ctx->geometry, origin, origin_n, dir, &hit)) break;
        stats->vertices++;
        if ((uint64_t)depth > stats->longest) stats->longest = (uint64_t)depth;
        double rho = hit.reflectance;
        if (!(rho > 0.0)) break;
        cdl_rng_key nee = {key.seed, cdl_rng_stream_id(key.stream, (uint64_t)depth, 0x6e6565 /* "nee" */)};
        double unoccluded;
        double Ed = cdl_direct_estimate_point(ctx->direct, nee, hit.p, hit.n, &unoccluded, &stats->direct);
        double gained = w * rho * Ed;
        out->value += gained;
        if (depth == 1) out->potential = rho * unoccluded;
        if (depth == limit) out->last = gained;
        if (depth == limit - 1) out->before_last = gained;
        w *= rho;
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)(1 + VERTEX_DRAWS * (depth - 1)), u);
        /* Russian roulette on the throughput: below RR_THRESHOLD the path
         * goes on with probability q = w / RR_THRESHOLD and then carries
         * RR_THRESHOLD (w / q); never above 0.99, so that paths end. */
        double q = w < RR_THRESHOLD ? w / RR_THRESHOLD : 1.0;
        if (q > 0.99) q = 0.99;
        if (u[0] >= q) break;
        w /= q;
        cdl_rng_uniform2(key, (uint64_t)(2 + VERTEX_DRAWS * (depth - 1)), u);
        cdl_frame f = cdl_frame_from_normal(hit.n);
        dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u[0], u[1]));
        origin = hit.p;
        origin_n = hit.n;
    }
}

/* One round: k x k cells of the first direction, two paths a cell. */
static void path_round(const cdl_pathtrace_context *ctx, uint64_t stream, uint64_t base, cdl_vec3 p, cdl_vec3 n,
                       int k, cdl_estimate *est, double *potential_sum, cdl_pathtrace_stats *stats)
{
    cdl_frame f = cdl_frame_from_normal(n);
    cdl_round round = {0.0, 0.0, 0.0, 0};
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double v[2];
            for (int s = 0; s < 2; ++s) {
                uint64_t path = base + (uint64_t)(2 * (j * k + i) + s);
                cdl_rng_key key = {ctx->seed, cdl_rng_stream_id(stream, path, 0x70617468 /* "path" */)};
                double u[2];
                cdl_rng_uniform2(key, 0, u);
                cdl_vec3 dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere((i + u[0]) / k, (j + u[1]) / k));
                path_result r;
                trace_path(ctx, key, p, n, dir, &r, stats);
                v[s] = r.value;
                *potential_sum += r.potential;
                stats->last += r.last;
                stats->before_last += r.before_last;
                stats->total += r.value;
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
                         double var_direct, double *E_indirect, double *var_indirect, cdl_pathtrace_stats *stats)
{
    /* The pilot: how variable are this point's paths, how much light. */
    cdl_estimate pilot = {0.0, 0.0, 0.0, 0};
    double potential_sum = 0.0;
    path_round(ctx, stream, 0, p, n, PILOT_SIDE, &pilot, &potential_sum, stats);
    uint64_t taken = (uint64_t)pilot.samples;
    double potential = potential_sum / pilot.samples;
    /* The point's E = E_dir + E_ind is held to t; the direct part was held
     * to t / sqrt 2 (half the variance), the rest is the paths'. A point in
     * the dark is held to a thousandth of what its paths could carry. */
    double R = fmax(E_direct + cdl_estimate_mean(&pilot), 1e-3 * potential);
    double whole = ctx->target * ctx->target * R * R;
    double budget = fmax(whole - var_direct, 0.5 * whole);
    cdl_estimate planning = pilot;
    planning.var_num = paths_variance(&pilot, potential) * pilot.samples * pilot.samples;
    double want = cdl_estimate_plan(&planning, budget, 2.0 * PILOT_SIDE * PILOT_SIDE);
    /* The reported stage: its size depends on the pilot only, so its mean
     * and its variance estimate are those of a fixed number of paths
     * (estimate.h). Should the pilot have seen too little, the stated error
     * is above the target, and says so. */
    if (want > ctx->max_paths - (double)taken) want = ctx->max_paths - (double)taken;
    cdl_estimate est = {0.0, 0.0, 0.0, 0};
    path_round(ctx, stream, taken, p, n, cdl_estimate_side_for(want, PILOT_SIDE, 1 << 12), &est, &potential_sum,
               stats);
    *E_indirect = cdl_estimate_mean(&est);
    *var_indirect = paths_variance(&est, potential);
}

double cdl_pathtrace_left_out(const cdl_pathtrace_stats *stats)
{
    if (!(stats->total > 0.0) || !(stats->last > 0.0)) return 0.0;
    /* The last reflections decay by r = last / before_last each; the tail
     * beyond the limit is last (r + r^2 + ...) = last r / (1 - r). A ratio
     * of 1 or more means the limit cut off a tail it cannot bound: report
     * it as everything from the last reflection on, repeated 100 times. */
    double r = stats->before_last > 0.0 ? stats->last / stats->before_last : 0.0;
    double tail = r < 1.0 ? stats->last * r / (1.0 - r) : 100.0 * stats->last;
    return tail / (stats->total + tail);
}

/* ---- a grid on the worker pool ---------------------------------------------- */

typedef struct grid_job {
    const cdl_pathtrace_context *ctx;
    const cdl_grid *grid;
    size_t grid_index;
    const double *E_direct, *var_direct;
    double *E_indirect, *var_indirect;
    double *tails;            /* per point: last, before_last, total (summed in point order after) */
} grid_job;

static cdl_status trace_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)err;
    const grid_job *job = shared;
    cdl_pathtrace_stats *stats = local;
    for (size_t i = begin; i < end; ++i) {
        uint64_t stream = cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x707472616365 /* "ptrace" */);
        /* The floating-point tallies are kept per point, so that their sums
         * do not depend on which thread took which point. */
        double last = stats->last, before = stats->before_last, total = stats->total;
        cdl_pathtrace_point(job->ctx, stream, job->grid->points[i], job->grid->normals[i], job->E_direct[i],
                            job->var_direct[i], &job->E_indirect[i], &job->var_indirect[i], stats);
        job->tails[3 * i] = stats->last - last;
        job->tails[3 * i + 1] = stats->before_last - before;
        job->tails[3 * i + 2] = stats->total - total;
        stats->last = last;
        stats->before_last = before;
        stats->total = total;
    }
    return CDL_OK;
}

static void stats_add(cdl_pathtrace_stats *to, const cdl_pathtrace_stats *from)
{
    to->paths += from->paths;
    to->vertices += from->vertices;
    to->rays += from->rays;
    if (from->longest > to->longest) to->longest = from->longest;
    to->last += from->last;
    to->before_last += from->before_last;
    to->total += from->total;
    to->direct.rays += from->direct.rays;
    to->direct.exact_evaluations += from->direct.exact_evaluations;
    to->direct.sampled_evaluations += from->direct.sampled_evaluations;
}

cdl_status cdl_pathtrace_solve_grid(const cdl_pathtrace_context *ctx, const cdl_grid *grid, size_t grid_index,
                                    const double *E_direct, const double *var_direct, double *E_indirect,
                                    double *var_indirect, int threads, const cdl_progress_sink *progress,
                                    const char *stage, cdl_pathtrace_stats *stats, cdl_error *err)
{
    if (threads < 1) threads = 1;
    cdl_pathtrace_stats *locals = calloc((size_t)threads, sizeof *locals);
    double *tails = calloc(3 * (grid->count ? grid->count : 1), sizeof *tails);
    if (!locals || !tails) {
        free(locals);
        free(tails);
        return cdl_error_out_of_memory(err);
    }
    grid_job job = {ctx, grid, grid_index, E_direct, var_direct, E_indirect, var_indirect, tails};
    /* Points differ a hundredfold in cost: small chunks keep threads busy. */
    cdl_pool_task task = {.count = grid->count, .chunk = 2, .run = trace_points, .shared = &job,
                          .locals = locals, .local_size = sizeof *locals, .stage = stage};
    cdl_status st = cdl_pool_run(&task, threads, progress, err);
    for (int t = 0; t < threads; ++t) stats_add(stats, &locals[t]);
    for (size_t i = 0; i < grid->count; ++i) {
        stats->last += tails[3 * i];
        stats->before_last += tails[3 * i + 1];
        stats->total += tails[3 * i + 2];
    }
    free(locals);
    free(tails);
    return st;
}
