/* pathtrace.c - paths from grid points, next-event estimation at every vertex. */
#include "solver/pathtrace/pathtrace.h"

#include "solver/direct/direct_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sort_doubles.h"
#include "radiometry/estimate.h"
#include "radiometry/frame.h"
#include "base/rng.h"
#include "radiometry/sampling.h"

/* Strata per side of a point's pilot round, and the least of a reported
 * stage: 8 x 8 cells, 128 paths, a variance estimate of 64 degrees of
 * freedom. */
#define PILOT_SIDE 8

/* One round: k x k cells of the first direction, two paths a cell. Returns
 * the round's differing pairs in effect, (sum d^2)^2 / sum d^4 (d a cell's
 * difference): the degrees of freedom its variance estimate has, about
 * (chi-square) a relative spread of sqrt(2 / pairs). */
static double path_round(const cdl_pathtrace_context *ctx, uint64_t stream, uint64_t base, cdl_vec3 p, cdl_vec3 n,
                         int k, cdl_estimate *est, double *potential_sum, cdl_path_stats *stats, cdl_path_tally *tally)
{
    cdl_frame f = cdl_frame_from_normal(n);
    cdl_round round = {0.0, 0.0, 0.0, 0};
    double d4 = 0.0;
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
            double d2 = (v[0] - v[1]) * (v[0] - v[1]);
            d4 += d2 * d2;
        }
    cdl_estimate_add_round(est, &round);
    return d4 > 0.0 ? round.sum_d2 * round.sum_d2 / d4 : 0.0;
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

/* The plan's margin for the pilot's own error: its variance estimate, of
 * D differing pairs in effect, is uncertain by about sqrt(2 / D)
 * relative, and the stage is planned for the variance of two such spreads
 * above it, 1 + 2 sqrt(2 / D) (1.35 at D = 64, the pilot's 8 x 8 cells all
 * alike), at most PLAN_MARGIN_MAX (a skewed pilot, a few bright paths:
 * D of 2 or 3). PLAN_MARGIN_MAX = 2 is the margin every plan took before
 * (radiometry/estimate.h): in the furnace a pilot of skewed paths misjudged
 * the variance by up to 2.6 times. */
#define PLAN_MARGIN_MAX 2.0

static double plan_margin(double pairs)
{
    if (!(pairs > 0.0)) return PLAN_MARGIN_MAX;
    return fmin(PLAN_MARGIN_MAX, 1.0 + 2.0 * sqrt(2.0 / pairs));
}

/* Paths for the stage from a pilot of n = `pilot->samples` paths whose
 * variance of the mean is v, the budget divided by the margin: with
 * X = margin v / budget, the variance modelled as v (n / N)^alpha up to
 * the Na = alpha_paths of the grid's calibration rounds of 8 pilots, over
 * which alpha was measured, and beyond them as falling from there as
 * N^-beta, beta measured between those rounds and rounds of 64 pilots
 * (cdl_pathtrace_solve_grid):
 *     N = n X^(1 / alpha)                         where that is at most Na,
 *     N = Na (X (n / Na)^alpha)^(1 / beta)        beyond (the two meet at Na).
 * The exponent of the first paths is not carried past the range it was
 * read on: the first bounce's strata may gain most at few paths. */
static double plan_paths(const cdl_estimate *pilot, double v, double budget, const cdl_pathtrace_context *ctx,
                         double margin, double least)
{
    if (!(v > 0.0) || !(budget > 0.0)) return least;
    double n0 = pilot->samples, X = margin * v / budget, alpha = ctx->alpha, Na = ctx->alpha_paths;
    double beta = ctx->alpha_beyond > 1.0 ? ctx->alpha_beyond : 1.0;
    if (!(alpha > 1.0)) alpha = 1.0;
    double n = n0 * pow(X, 1.0 / alpha);
    if (alpha > 1.0 && n > Na) n = Na > n0 ? Na * pow(X * pow(n0 / Na, alpha), 1.0 / beta) : n0 * pow(X, 1.0 / beta);
    return n > least ? n : least;
}

/* A pilot whose plan reaches beyond PLAN_REACH times its paths and whose
 * variance estimate rests on fewer than PLAN_PAIRS differing pairs in
 * effect (a few bright paths among many dim ones: the integrating
 * sphere's pilots had 5 to 18) is followed by a second pilot round of
 * 16 x 16 cells, 512 paths, and the point is planned from that round
 * alone. Measured on the sphere of tests/tools/test_bench_cli.sh at 0.02 %:
 * planned from pilots of 5 to 18 pairs with the margin alone, stated
 * errors spread from 0.59 to 1.13 of the target (docs/tuning.md). */
#define PLAN_REACH 16.0
#define PLAN_PAIRS 32.0
#define SECOND_PILOT_SIDE 16

/* Further stages a point may take when its stage states more than the
 * target (cdl_pathtrace_point). */
#define STAGE_RETRIES 2

/* The pilot of a point and what it asks for: the paths of its stage. */
typedef struct point_pilot {
    cdl_estimate est;         /* the round planned from */
    cdl_estimate first;       /* the first round (PILOT_SIDE) */
    double taken;             /* paths of the pilot rounds */
    double potential_sum, potential, pairs, budget, want;
} point_pilot;

/* The point's E = E_dir + E_ind is held to t; the direct part was held to
 * t / sqrt 2 (half the variance), the rest is the paths'. A point in the
 * dark is held to a thousandth of what its paths could carry. */
static double point_whole(const cdl_pathtrace_context *ctx, double E_direct, double mean, double potential)
{
    double R = fmax(E_direct + mean, 1e-3 * potential);
    return ctx->target * ctx->target * R * R;
}

/* The paths' share of a point's variance target `whole`. */
static double paths_budget(double whole, double var_direct)
{
    return fmax(whole - var_direct, 0.5 * whole);
}

static void plan_point(const cdl_pathtrace_context *ctx, double E_direct, double var_direct, double mean,
                       point_pilot *pp)
{
    pp->potential = pp->potential_sum / pp->taken;
    pp->budget = paths_budget(point_whole(ctx, E_direct, mean, pp->potential), var_direct);
    double least = 2.0 * PILOT_SIDE * PILOT_SIDE;
    if (pp->est.nonzero == 0)
        /* A pilot that saw nothing: as many paths as hold what all of them
         * could have missed to the budget (estimate.h). */
        pp->want = cdl_estimate_plan_unseen(pp->potential, pp->budget, least);
    else
        pp->want = plan_paths(&pp->est, paths_variance(&pp->est, pp->potential), pp->budget, ctx,
                              plan_margin(pp->pairs), least);
}

static void pilot_point(const cdl_pathtrace_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n, double E_direct,
                        double var_direct, point_pilot *pp, cdl_path_stats *stats, cdl_path_tally *tally)
{
    memset(pp, 0, sizeof *pp);
    pp->pairs = path_round(ctx, stream, 0, p, n, PILOT_SIDE, &pp->first, &pp->potential_sum, stats, tally);
    pp->est = pp->first;
    pp->taken = pp->first.samples;
    plan_point(ctx, E_direct, var_direct, cdl_estimate_mean(&pp->first), pp);
    if (pp->first.nonzero == 0 || pp->want <= PLAN_REACH * pp->taken || pp->pairs >= PLAN_PAIRS) return;
    cdl_estimate second = {0.0, 0.0, 0.0, 0};
    pp->pairs = path_round(ctx, stream, (uint64_t)pp->taken, p, n, SECOND_PILOT_SIDE, &second, &pp->potential_sum,
                           stats, tally);
    pp->taken += second.samples;
    pp->est = second;
    /* the scale from both rounds, the plan from the second */
    double mean = (pp->first.weighted + second.weighted) / (pp->first.samples + second.samples);
    plan_point(ctx, E_direct, var_direct, mean, pp);
}

void cdl_pathtrace_point(const cdl_pathtrace_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n, double E_direct,
                         double var_direct, double *E_indirect, double *var_indirect, cdl_path_stats *stats,
                         cdl_path_tally *tally)
{
    /* The pilot: how variable are this point's paths, how much light. */
    point_pilot pp;
    pilot_point(ctx, stream, p, n, E_direct, var_direct, &pp, stats, tally);
    uint64_t taken = (uint64_t)pp.taken;
    double want = pp.want, potential_sum = pp.potential_sum;
    /* The reported stage: its size depends on the pilot only, so its mean
     * and its variance estimate are those of a fixed number of paths
     * (estimate.h). Should the pilot have seen too little, the stated error
     * is above the target, and says so. */
    if (want > ctx->max_paths - (double)taken) want = ctx->max_paths - (double)taken;
    cdl_estimate est = {0.0, 0.0, 0.0, 0};
    double pairs = path_round(ctx, stream, taken, p, n, cdl_estimate_side_for(want, PILOT_SIDE, 1 << 12), &est,
                              &potential_sum, stats, tally);
    *E_indirect = cdl_estimate_mean(&est);
    *var_indirect = paths_variance(&est, pp.potential);
    /* A stage that still states more than the target (its pilot missed
     * some of the paths' spread) is traced anew, independently, planned
     * from it as from a pilot (as 1/N, its own margin), and the last stage
     * alone is reported: its size depends only on the stages before it, so
     * it stays an estimate of a fixed number of paths (estimate.h), and the
     * choice to trace it, made on the stage before, does not bias it. On
     * the office at "high" 2 to 8 of 469 points stated 1.05 to 1.24 times
     * the target after their stage. */
    for (int again = 0; again < STAGE_RETRIES; ++again) {
        double whole = point_whole(ctx, E_direct, *E_indirect, pp.potential);
        if (var_direct + *var_indirect <= whole || est.nonzero == 0) break;
        taken += (uint64_t)est.samples;
        double budget = paths_budget(whole, var_direct);
        double more = est.samples * plan_margin(pairs) * *var_indirect / budget;
        if (more > ctx->max_paths - (double)taken) more = ctx->max_paths - (double)taken;
        if (!(more > est.samples)) break;
        est = (cdl_estimate){0.0, 0.0, 0.0, 0};
        pairs = path_round(ctx, stream, taken, p, n, cdl_estimate_side_for(more, PILOT_SIDE, 1 << 12), &est,
                           &potential_sum, stats, tally);
        *E_indirect = cdl_estimate_mean(&est);
        *var_indirect = paths_variance(&est, pp.potential);
    }
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

/* ---- the grid's convergence exponent -------------------------------------- */

/* How fast a point's variance falls with its paths, Var(N) = v (n / N)^alpha,
 * is measured on the grid before it is planned: at CALIBRATION_POINTS of
 * its points (evenly spread over its index order) whose pilot asks for
 * CALIBRATION_REACH times its paths or more (where alpha matters), a round
 * of CALIBRATION_REACH pilots' paths is traced (random numbers of their
 * own, never the stage's) and alpha_i = ln(v_pilot / v_round) /
 * ln(N_round / n_pilot); the grid takes their median, within [1,
 * ALPHA_MAX] (1: independent paths; the first direction's strata can make
 * it more, never less), or 1 when fewer than 3 points measured it. Why
 * measured and not assumed: the stratified first bounce makes the
 * variance fall faster than 1 / N where it carries much of the variance
 * and hardly at all where later bounces do (docs/tuning.md: 1.11 in the
 * downlight room between 128 and 3000 paths). The points are the grid's,
 * not the thread's: the same alpha, the same bytes, for any threads and
 * ranks. */
#define CALIBRATION_POINTS 12
#define CALIBRATION_REACH 8.0
/* Where a point's plan asks for CALIBRATION_REACH_MAX pilots or more, a
 * third round that large reads the exponent beyond the first 8 pilots'
 * worth, and the plans take it there (never above alpha; alpha itself
 * where fewer than 3 points measured it): the first bounce's strata may
 * gain most at few paths, and a ratio of 8 between rounds of 8 and 64
 * pilots reads it sharply. With alpha carried on from the first 8 pilots
 * the example office at quality high measured it from 1.02 to 1.16 over
 * three seeds (floor grid), and at 1.16 38 of its 67 points stated errors
 * above the target, up to 1.59 times it (docs/tuning.md). */
#define CALIBRATION_REACH_MAX 64.0
#define ALPHA_MAX 1.5
/* ... unless the points disagree: where the spread between their quartiles
 * (3rd and 10th of 12) is above ALPHA_SPREAD_MAX the grid plans as 1/N.
 * Pilots of 64 alike pairs read alpha_i to about 0.07-0.09 (a quartile
 * spread of about 0.12); heavy-tailed paths (a point light 0.2 m under a
 * white ceiling: its bright spot found by few paths) scatter them from 0
 * to 2.3, and their median swung from 0.98 to 1.38 with the seed, the
 * solve's cost fivefold with it; spreads of 0.49 to 1.9 over four seeds
 * of a smaller such room (docs/tuning.md). The downlight room's spread:
 * 0.24; the one-bounce room of tests/solver/pathtrace/test_path_planning.c
 * (every exponent at the cap or above) 0.15 to 0.25. */
#define ALPHA_SPREAD_MAX 0.35

/* The side k of a calibration round of `pilots` first pilots' paths (k x 2k strata). */
static int calibration_side(double pilots)
{
    return cdl_estimate_side_for(pilots * 2.0 * PILOT_SIDE * PILOT_SIDE, PILOT_SIDE, 1 << 12);
}

typedef struct calibration_job {
    const cdl_pathtrace_context *ctx;
    const cdl_grid *grid;
    size_t grid_index, stride;
    const double *E_direct, *var_direct;
    double *alpha;            /* per point: alpha_i at the calibration points where measured, else NAN */
    double *alpha_late;       /* per point: the exponent between its rounds of 8 and 64 pilots, else NAN */
} calibration_job;

/* The calibration points are those i with i % stride == stride / 2. */
static cdl_status calibrate_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)err;
    const calibration_job *job = shared;
    cdl_path_stats *stats = local;
    for (size_t i = begin; i < end; ++i) {
        job->alpha[i] = job->alpha_late[i] = NAN;
        if (i % job->stride != job->stride / 2 || i / job->stride >= CALIBRATION_POINTS) continue;
        uint64_t stream = cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x63616c6962 /* "calib" */);
        cdl_vec3 from = job->grid->points[i];
        if (job->ctx->path.direct) cdl_direct_edge_point(job->ctx->path.direct, from, job->grid->normals[i], &from);
        cdl_path_tally tally;
        memset(&tally, 0, sizeof tally);
        point_pilot pp;
        pilot_point(job->ctx, stream, from, job->grid->normals[i], job->E_direct[i], job->var_direct[i], &pp, stats,
                    &tally);
        /* the first pilot round against one CALIBRATION_REACH times its
         * size and, where the plan asks for CALIBRATION_REACH_MAX pilots or
         * more, against one that large too, each with random numbers of
         * its own */
        double v_pilot = cdl_estimate_variance(&pp.first), n_pilot = pp.first.samples;
        if (pp.first.nonzero == 0 || !(v_pilot > 0.0) || pp.want < CALIBRATION_REACH * n_pilot) continue;
        double potential_sum = 0.0;
        uint64_t offset = (uint64_t)pp.taken;
        cdl_estimate near = {0.0, 0.0, 0.0, 0};
        path_round(job->ctx, stream, offset, from, job->grid->normals[i], calibration_side(CALIBRATION_REACH), &near,
                   &potential_sum, stats, &tally);
        double v_near = cdl_estimate_variance(&near);
        if (!(v_near > 0.0)) continue;
        job->alpha[i] = log(v_pilot / v_near) / log(near.samples / n_pilot);
        if (pp.want < CALIBRATION_REACH_MAX * n_pilot) continue;
        cdl_estimate far = {0.0, 0.0, 0.0, 0};
        path_round(job->ctx, stream, offset + (uint64_t)near.samples, from, job->grid->normals[i],
                   calibration_side(CALIBRATION_REACH_MAX), &far, &potential_sum, stats, &tally);
        double v_far = cdl_estimate_variance(&far);
        if (v_far > 0.0 && far.samples > near.samples)
            job->alpha_late[i] = log(v_near / v_far) / log(far.samples / near.samples);
    }
    return CDL_OK;
}

/* The median of x[0 .. m) (sorted in place), m >= 1. */
static double median_of(double *x, size_t m)
{
    cdl_sort_doubles(x, m);
    return m % 2 ? x[m / 2] : 0.5 * (x[m / 2 - 1] + x[m / 2]);
}

/* The spread between the quartiles of sorted x[0 .. m) (the 3rd and 10th of 12). */
static double quartile_spread(const double *x, size_t m)
{
    return x[m - 1 - (m - 1) / 4] - x[(m - 1) / 4];
}

static cdl_status measure_alpha(const cdl_pathtrace_context *ctx, const cdl_grid *grid, size_t grid_index,
                                const double *E_direct, const double *var_direct, const cdl_workers *workers,
                                const char *stage, cdl_path_stats *locals, cdl_pathtrace_convergence *conv,
                                cdl_error *err)
{
    conv->alpha = 1.0;
    conv->measured = 0;
    conv->spread = 0.0;
    conv->reach_paths = 0.0;
    conv->alpha_beyond = 1.0;
    conv->measured_beyond = 0;
    conv->agreed = 0;
    size_t count = grid->count < CALIBRATION_POINTS ? grid->count : CALIBRATION_POINTS;
    if (count == 0 || !ctx->measure_alpha) return CDL_OK;
    double *alpha = malloc(2 * grid->count * sizeof *alpha);
    if (!alpha) return cdl_error_out_of_memory(err);
    double *alpha_late = alpha + grid->count;
    calibration_job job = {ctx, grid, grid_index, grid->count / count, E_direct, var_direct, alpha, alpha_late};
    /* Over the grid's points, each calibrated by the rank that holds its
     * direct light (ranks keep theirs in blocks of CDL_RANK_KEEP_ALIGN
     * points), and every rank ends with every alpha_i. */
    cdl_workers everywhere = *workers;
    everywhere.everywhere = 1;
    cdl_pool_task task = {.count = grid->count,
                          .chunk = cdl_rank_group_count(workers->ranks) > 1 ? CDL_RANK_KEEP_ALIGN : 1,
                          .run = calibrate_points,
                          .shared = &job,
                          .locals = locals,
                          .local_size = sizeof *locals,
                          .stage = stage,
                          .outputs = {{alpha, sizeof *alpha}, {alpha_late, sizeof *alpha_late}}};
    cdl_status st = cdl_pool_run_shared(&task, &everywhere, err);
    if (st == CDL_OK) {
        size_t m = 0, late = 0;
        for (size_t i = 0; i < grid->count; ++i) {
            if (isfinite(alpha_late[i])) alpha_late[late++] = alpha_late[i];
            if (isfinite(alpha[i])) alpha[m++] = alpha[i];
        }
        conv->measured = m;
        conv->measured_beyond = late;
        if (m >= 3) {
            int side = calibration_side(CALIBRATION_REACH);
            conv->reach_paths = 2.0 * side * side;
            double median = median_of(alpha, m); /* sorts alpha for the spread */
            conv->spread = quartile_spread(alpha, m);
            conv->agreed = conv->spread <= ALPHA_SPREAD_MAX;
            if (conv->agreed) {
                conv->alpha = fmin(ALPHA_MAX, fmax(1.0, median));
                /* beyond the rounds of 8 pilots: the exponent between them
                 * and those of 64, never above alpha; alpha where fewer
                 * than 3 points asked for 64 pilots or more */
                conv->alpha_beyond =
                    late >= 3 ? fmin(conv->alpha, fmax(1.0, median_of(alpha_late, late))) : conv->alpha;
            }
        }
    }
    free(alpha);
    return st;
}

cdl_status cdl_pathtrace_solve_grid(const cdl_pathtrace_context *ctx_in, const cdl_grid *grid, size_t grid_index,
                                    const double *E_direct, const double *var_direct, double *E_indirect,
                                    double *var_indirect, const cdl_workers *workers, const char *stage,
                                    cdl_pathtrace_convergence *convergence, cdl_path_stats *stats, cdl_error *err)
{
    int threads = workers->threads < 1 ? 1 : workers->threads;
    cdl_path_stats *locals = calloc((size_t)threads, sizeof *locals);
    cdl_path_tally *tallies = calloc(grid->count ? grid->count : 1, sizeof *tallies);
    if (!locals || !tallies) {
        free(locals);
        free(tallies);
        return cdl_error_out_of_memory(err);
    }
    /* the grid's exponent first, then every point planned with it */
    cdl_pathtrace_convergence conv;
    cdl_status st = measure_alpha(ctx_in, grid, grid_index, E_direct, var_direct, workers, stage, locals, &conv, err);
    if (st != CDL_OK) {
        free(locals);
        free(tallies);
        return st;
    }
    if (convergence) *convergence = conv;
    cdl_pathtrace_context planned = *ctx_in;
    planned.alpha = conv.alpha;
    planned.alpha_paths = conv.reach_paths;
    planned.alpha_beyond = conv.alpha_beyond;
    const cdl_pathtrace_context *ctx = &planned;
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
    st = cdl_pool_run_shared(&task, workers, err);
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
