/* icache.c - records placed by passes over a grid, then interpolated. */
#include "solver/icache/icache.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sort_doubles.h"
#include "radiometry/bounds.h"
#include "radiometry/estimate.h"
#include "solver/icache/record_octree.h"
#include "solver/scene/scene_geometry.h"

/* A record's pilot gather: 8 x 16 strata, 128 paths (64 pairs for the
 * variance); its reported gather is planned from it, 2 k^2 strata (k x 2k)
 * with k in [8, MAX_SIDE]. */
#define PILOT_M 8
#define PILOT_N 16
#define MAX_SIDE 128

/* The largest gather of a record serving only its own point (below):
 * 512 x 1024 strata, 524 288 paths. */
#define OWN_MAX_SIDE 512

/* Further gathers a record of its own may take when its gather states more
 * than its budget (gather_records). */
#define OWN_REGATHERS 3

/* Placement passes after the seeds; each adds records only where points
 * ask for them, so few passes do anything. */
#define MAX_PASSES 16

/* A record's gather is held to RECORD_SHARE times a point's variance
 * target (t R)^2. Larger shares cost fewer rays at equal RMS error, but
 * where all light is interreflected (a furnace) a point served by one or
 * two records then states up to twice the target; share 2 keeps every
 * stated error within 1.5 times the target there (the measurements on the
 * closed cube: docs/tuning.md). */
#define RECORD_SHARE 2.0

/* No point asks for a record while one serves it from nearer than this
 * fraction of the least reach (visit_points). */
#define NEAREST_FRACTION 0.5

/* sqrt(1 - cos 10 deg): normals further apart than 10 degrees share no record. */
#define NORMAL_SPREAD 0.12326828329112158

/* How far records reach, from the grid's spacing h and the target t.
 *  - a, the accuracy of the weights (kappa = 1 / a; a record serves points
 *    closer than a clamp(2 R_i, Rmin, Rmax)): the error of extrapolating
 *    with gradients grows as (d / R)^2, so a grows as sqrt(t): a = 1.4
 *    sqrt t in [0.03, 0.4] (draft 0.2, normal 0.1, high 0.044, reference
 *    0.03).
 *  - the least reach 1.5 h (a record serves at least the grid points next
 *    to it: denser records than points would buy nothing), the largest
 *    16 h (a record never speaks for points 16 spacings away, however far
 *    the surfaces it saw). Rmin and Rmax are these divided by a. */
typedef struct reach_limits {
    double a, kappa, reach_min, reach_max, Rmin, Rmax;
} reach_limits;

static reach_limits limits_for(double spacing, double target)
{
    reach_limits l;
    l.a = fmin(0.4, fmax(0.03, 1.4 * sqrt(target)));
    l.kappa = 1.0 / l.a;
    l.reach_min = 1.5 * spacing;
    l.reach_max = 16.0 * spacing;
    l.Rmin = l.reach_min / l.a;
    l.Rmax = l.reach_max / l.a;
    return l;
}

/* The distance over which record r serves: a clamp(2 R, Rmin, Rmax). */
static double record_reach(const reach_limits *l, const cdl_icache_record *r)
{
    return l->a * fmin(l->Rmax, fmax(l->Rmin, 2.0 * r->radius));
}

/* The radius of a record that serves only the point it sits on (the same
 * position and normal): a point whose interpolation stated more than the
 * target after placement gets one, gathered to its whole target
 * (cdl_icache_solve_grid). */
#define OWN_RADIUS 0.0

/* The sphere a record is entered in the tree with: its reach, or for a
 * record serving its own point alone a sliver around it. */
static double tree_reach(const reach_limits *l, const cdl_icache_record *r)
{
    return r->radius == OWN_RADIUS ? 1e-6 * l->reach_min : record_reach(l, r);
}

/* A grid's spacing: the median distance from a point to the nearest other
 * point (the first 2048 points), no larger than the rect or polygon
 * spacing asked for. A polygon's points are the centroids of its mesh's
 * triangles, closer together than the spacing the mesh was made with (the
 * office's floor: spacing 0.70 m, points 0.23 m apart); with the mesh's
 * spacing every record reached at least 1.05 m there, records across the
 * 0.2 m gap between its cabinet and wall extrapolated a steep gradient
 * over most of it, and points stated 60-80 % errors. */
static double grid_spacing(const cdl_grid *g)
{
    double asked = g->spacing_m > 0.0 ? g->spacing_m : INFINITY;
    size_t n = g->count < 2048 ? g->count : 2048;
    if (n < 2) return isfinite(asked) ? asked : 1.0;
    double *near = malloc(n * sizeof *near);
    if (!near) return isfinite(asked) ? asked : 1.0;
    for (size_t i = 0; i < n; ++i) {
        near[i] = INFINITY;
        for (size_t j = 0; j < n; ++j) {
            double d = cdl_vec3_length(cdl_vec3_sub(g->points[i], g->points[j]));
            if (j != i && d > 0.0 && d < near[i]) near[i] = d;
        }
    }
    cdl_sort_doubles(near, n);
    double h = fmin(near[n / 2], asked);
    free(near);
    return isfinite(h) && h > 0.0 ? h : 1.0;
}

/* ---- interpolation -------------------------------------------------------------- */

typedef struct lookup {
    uint32_t *ids;
    size_t capacity;
    double *w;                /* the weights of the records that serve a point (0: rejected) */
    size_t w_capacity;
    size_t m;                 /* candidates of the last interpolation: ids[0 .. m - 1], w[0 .. m - 1] */
} lookup;

static void lookup_release(lookup *lk)
{
    free(lk->ids);
    free(lk->w);
}

typedef struct interpolation {
    double E, var;            /* the interpolated E_ind and its stated variance */
    double interp_var;        /* the interpolation's share of var */
    size_t used;              /* records with w > 0 */
    double reach;             /* smallest reach among them (reach_max when none) */
    double nearest;           /* m: the distance to the nearest of them (INFINITY when none) */
} interpolation;

/* E_ind at (p, n) from the records; 0 when memory ran out. */
static int interpolate(const cdl_icache_context *ctx, const reach_limits *l, const cdl_icache_records *recs,
                       const cdl_record_octree *tree, cdl_vec3 p, cdl_vec3 n, lookup *lk, interpolation *out)
{
    memset(out, 0, sizeof *out);
    out->reach = l->reach_max;
    out->nearest = INFINITY;
    lk->m = 0;
    size_t m = cdl_record_octree_lookup(tree, p, &lk->ids, &lk->capacity);
    if (m == (size_t)-1) return 0;
    if (m > lk->w_capacity) {
        double *grown = realloc(lk->w, m * sizeof *grown);
        if (!grown) return 0;
        lk->w = grown;
        lk->w_capacity = m;
    }
    lk->m = m;
    double W = 0.0, sum = 0.0, noise = 0.0, noise_mean = 0.0, sum2 = 0.0, change2 = 0.0;
    cdl_vec3 gbar = cdl_vec3_make(0, 0, 0);
    const cdl_icache_record *own = NULL;
    const cdl_scene_geometry *geometry = ctx->path.geometry;
    for (size_t c = 0; c < m; ++c) {
        const cdl_icache_record *r = &recs->items[lk->ids[c]];
        double reach = record_reach(l, r);
        cdl_vec3 d = cdl_vec3_sub(p, r->p);
        double dist = cdl_vec3_length(d);
        double e = fmax(dist / (reach / l->a), sqrt(fmax(0.0, 1.0 - cdl_vec3_dot(n, r->n))) / NORMAL_SPREAD);
        double w = 1.0 - l->kappa * e;
        lk->w[c] = 0.0;
        if (r->radius == OWN_RADIUS) {
            if (dist == 0.0 && cdl_vec3_dot(n, r->n) >= 1.0 - 1e-12) own = r;
            continue;
        }
        if (!(w > 0.0)) continue;
        /* Behind test: p may not lie behind the record's tangent plane
         * (averaged with its own), beyond 1 % of the record's reach. */
        if (cdl_vec3_dot(d, cdl_vec3_add(n, r->n)) * 0.5 < -0.01 * reach) continue;
        /* Leak test: the record must see p. */
        if (dist > 0.0 && geometry && cdl_scene_geometry_segment_occluded(geometry, r->p, r->n, p, n)) continue;
        double change = 0.0;
        if (ctx->gradients)
            change = cdl_vec3_dot(cdl_vec3_cross(r->n, n), r->grad_r) + cdl_vec3_dot(d, r->grad_t);
        double x = r->E + change;
        lk->w[c] = w;
        gbar = cdl_vec3_add(gbar, cdl_vec3_scale(r->grad_t, w));
        W += w;
        sum += w * x;
        sum2 += w * x * x;
        noise += w * w * r->var;
        noise_mean += w * r->var;
        /* What a lone record's extrapolation is unsure of: the first-order
         * change itself (its gradient, with or without using it). */
        double first = cdl_vec3_length(r->grad_r) * cdl_vec3_length(cdl_vec3_cross(r->n, n)) +
                       cdl_vec3_length(r->grad_t) * dist;
        change2 += w * first * first;
        if (reach < out->reach) out->reach = reach;
        if (dist < out->nearest) out->nearest = dist;
        out->used++;
    }
    if (own) {
        /* A point with a record of its own: that record alone. */
        out->E = own->E;
        out->var = own->var;
        out->interp_var = 0.0;
        out->used = 1;
        return 1;
    }
    if (out->used == 0) return 1;
    out->E = sum / W;
    double spread = fmax(0.0, sum2 / W - out->E * out->E);
    if (out->used >= 2)
        out->interp_var = fmax(0.0, spread - noise_mean / W);
    else
        out->interp_var = change2 / W;
    /* Extrapolating along each record's own gradient leaves out the
     * second-order term 1/2 (p - p_i)^T H (p - p_i), H the Hessian of E.
     * Along the segment the gradient changes from g_i to about g(p), so the
     * change is better (p - p_i) . (g_i + g(p)) / 2 (the trapezoid rule,
     * exact for a quadratic E), g(p) taken as the records' weighted mean
     * gradient: each record adds 1/2 (g(p) - g_i) . (p - p_i) to the
     * extrapolation of Ward and Heckbert. Records all round a minimum of E
     * (the middle of a room under a downlight) otherwise err the same way,
     * agree with each other, and their spread cannot show it (on the
     * downlight room the term takes the RMS error from 0.13 % to 0.05 % and
     * the bias from -1.1 stated sigma to -0.3: docs/tuning.md). */
    if (ctx->gradients) {
        gbar = cdl_vec3_scale(gbar, 1.0 / W);
        double second = 0.0;
        for (size_t c = 0; c < m; ++c) {
            if (!(lk->w[c] > 0.0)) continue;
            const cdl_icache_record *r = &recs->items[lk->ids[c]];
            second += lk->w[c] * 0.5 * cdl_vec3_dot(cdl_vec3_sub(gbar, r->grad_t), cdl_vec3_sub(p, r->p));
        }
        out->E = fmax(0.0, out->E + second / W); /* never below no light */
    }
    out->var = noise / (W * W) + out->interp_var;
    return 1;
}

/* ---- the records' gathers ---------------------------------------------------------
 *
 * A gather's path that first reaches a surface the cache already serves
 * takes the interreflected light arriving there from the records (as
 * Radiance's ambient values serve its rays' hits; Ward, Rubinstein and
 * Clear 1988) instead of tracing on: its value is rho_1 (E_dir(x_1) +
 * E_ind(x_1)), E_ind interpolated. Only records gathered before the pass
 * serve (the same for any thread count or rank), only where the
 * interpolation states no more than HIT_MAX_REL of its value (elsewhere
 * the path goes on, unbiased), and never for a record serving its own point
 * alone, whose gather is that point's whole estimate. The paths' spread
 * does not show the error of what they looked up, for one record serves
 * many of them: each lookup's stated standard deviation s is shared out to
 * the records it used by their weights, record c collecting A_c = sum over
 * paths of (w_1 rho_1) (w_c / W) s, and the gather states on top of its
 * strata's variance sum_c (A_c / paths)^2 (errors of one record taken as
 * the same on every path that used it, of different records as
 * independent). */
#define HIT_MAX_REL 0.05

typedef struct hit_lookup {
    const cdl_icache_context *ctx;
    const reach_limits *limits;
    const cdl_icache_records *recs;   /* its first `count` records serve */
    size_t count;
    const cdl_record_octree *tree;
    lookup lk;
    double *share;                    /* count: A_c */
    uint32_t *touched;                /* the records whose A_c is not 0 */
    size_t touched_count;
    int failed;                       /* out of memory: the lookups stop */
} hit_lookup;

static int hit_lookup_serve(void *user, cdl_vec3 p, cdl_vec3 n, double scale, double *E)
{
    hit_lookup *h = user;
    if (h->failed || h->count == 0) return 0;
    if (!h->share) {
        h->share = calloc(h->count, sizeof *h->share);
        h->touched = malloc(h->count * sizeof *h->touched);
        if (!h->share || !h->touched) {
            h->failed = 1;
            return 0;
        }
    }
    interpolation it;
    if (!interpolate(h->ctx, h->limits, h->recs, h->tree, p, n, &h->lk, &it)) {
        h->failed = 1;
        return 0;
    }
    double W = 0.0;
    for (size_t c = 0; c < h->lk.m; ++c)
        if (h->lk.ids[c] < h->count) W += h->lk.w[c];
    double sigma = sqrt(it.var);
    if (it.used == 0 || !(W > 0.0) || !(it.E > 0.0) || !(sigma <= HIT_MAX_REL * it.E)) return 0;
    for (size_t c = 0; c < h->lk.m; ++c) {
        uint32_t id = h->lk.ids[c];
        double add = scale * h->lk.w[c] / W * sigma;
        /* a record is listed once: when its A_c first becomes positive */
        if (!(h->lk.w[c] > 0.0) || id >= h->count || !(add > 0.0)) continue;
        if (h->share[id] == 0.0) h->touched[h->touched_count++] = id;
        h->share[id] += add;
    }
    *E = it.E;
    return 1;
}

/* sum_c (A_c / paths)^2, the A_c then cleared for the next gather. */
static double hit_lookup_take_variance(hit_lookup *h, double paths)
{
    double var = 0.0;
    for (size_t k = 0; k < h->touched_count; ++k) {
        double a = h->share[h->touched[k]] / paths;
        var += a * a;
        h->share[h->touched[k]] = 0.0;
    }
    h->touched_count = 0;
    return var;
}

static void hit_lookup_release(hit_lookup *h)
{
    lookup_release(&h->lk);
    free(h->share);
    free(h->touched);
}

/* A worker's own: its paths' counts, its first-hit lookups, and the
 * lookups of the points given records of their own. */
typedef struct gather_local {
    cdl_path_stats stats;
    hit_lookup hits;
    lookup own;
} gather_local;

typedef struct gather_job {
    const cdl_icache_context *ctx;
    const reach_limits *limits;       /* with recs and tree: the cache its gathers' first hits may use */
    const cdl_icache_records *recs;
    size_t served;                    /* the records before these: recs->items[0 .. served - 1] */
    const cdl_record_octree *tree;
    const cdl_grid *grid;
    size_t grid_index;
    const double *E_direct;
    const double *var_direct; /* with own: the points' direct variance */
    int own;                  /* 1: records serving only their own point (OWN_RADIUS), each joined with
                                 the interpolation from the records in recs / tree (own_gather) */
    const size_t *at;         /* grid point of each new record */
    double floor;             /* with own: least R of any point */
    const double *floors;     /* NULL, or per point a larger least R (its target relative to no less) */
    cdl_icache_record *out;   /* one per new record */
    cdl_path_tally *tallies;  /* per new record, of its reported gather (summed in record order after) */
} gather_job;

/* The record of a point whose interpolation still states more than its
 * target (serve: find_alone). Its gather is an estimate of the point's
 * E_ind independent of the interpolation there (other random streams, no
 * first-hit lookups), so the two are joined by inverse-variance weights,
 * as two independent measurements of one quantity are:
 *     E = w E_g + (1 - w) E_i,   w = v_i / (v_i + v_g),
 *     Var = w^2 Var_g + (1 - w)^2 v_i,
 * and the gather need only bring the joined variance down to the point's
 * budget B (what the target leaves after the direct part's, at least half
 * of it, as pathtrace.c): 1 / (1 / v_i + 1 / v_g) <= B, so
 * v_g = B v_i / (v_i - B), where a gather standing alone needed v_g = B.
 * Most such points state 1.0 to 1.2 times their target (on the dense cube
 * 270 of 10 000 floor points, median 1.10): their gathers need a fraction
 * of the paths. The weights come from the variance the gather was planned
 * to (from its pilot, independent of it), not from the variance it shows,
 * which would weight a gather that happened low more than one that
 * happened high. Where no record serves the point (v_i = 0 with nothing
 * interpolated) the gather stands alone, as it did before. A gather whose
 * joined variance still exceeds B is gathered anew, planned from the last
 * one as its pilot (a pilot of 128 paths can miss the rare bright paths of
 * a dark gap: 8 % stated at a 2 % target in the test's gap); the last
 * gather alone is joined and reported (estimate.h: its size depends only
 * on gathers before it). Returns 0 when memory ran out. */
static int own_gather(const gather_job *job, gather_local *mine, size_t i, uint64_t seed, uint64_t stream,
                      double R, const cdl_icache_record *pilot, cdl_icache_record *out, cdl_path_tally *tally)
{
    const cdl_icache_context *ctx = job->ctx;
    cdl_vec3 p = job->grid->points[i], n = job->grid->normals[i];
    double least = job->floors ? fmax(job->floor, job->floors[i]) : job->floor;
    double whole = ctx->target * ctx->target * fmax(R, least) * fmax(R, least);
    double B = fmax(whole - job->var_direct[i], 0.5 * whole);
    interpolation it;
    memset(&it, 0, sizeof it);
    if (job->tree && !ctx->own_alone && !interpolate(ctx, job->limits, job->recs, job->tree, p, n, &mine->own, &it))
        return 0;
    int joined = it.used > 0 && isfinite(it.var) && it.var > B;
    double want = joined ? B * it.var / (it.var - B) : B;
    /* what comes before each gather: its pilot, then the gather before it */
    double n_last = PILOT_M * PILOT_N, E_last = pilot->E, var_last = pilot->var;
    cdl_rng_key key = {seed, 0};
    int k = PILOT_M;
    for (int round = 0; round <= OWN_REGATHERS; ++round) {
        cdl_estimate last = {n_last, E_last * n_last, var_last * n_last * n_last, 1};
        k = cdl_estimate_side_for(cdl_estimate_plan(&last, want, n_last), round ? k : PILOT_M, OWN_MAX_SIDE);
        key.stream = cdl_rng_stream_id(stream, 3 + (uint64_t)round, 1);
        if (!cdl_icache_gather(&ctx->path, key, p, n, k, 2 * k, out, &mine->stats, tally)) return 0;
        double ng = 2.0 * k * k, vg = out->var, Eg = out->E;
        if (joined) {
            /* the variance this gather was planned to: what came before it, per path, over its paths */
            double planned = var_last * n_last / ng;
            double w = planned > 0.0 ? it.var / (it.var + planned) : 1.0;
            out->E = w * Eg + (1.0 - w) * it.E;
            out->var = w * w * vg + (1.0 - w) * (1.0 - w) * it.var;
        }
        if (!(out->var > B) || k >= OWN_MAX_SIDE) break;
        n_last = ng;
        E_last = Eg;
        var_last = vg;
    }
    return 1;
}

static cdl_status gather_records(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    const gather_job *job = shared;
    gather_local *mine = local;
    cdl_path_stats *stats = &mine->stats;
    const cdl_icache_context *ctx = job->ctx;
    hit_lookup *hits = &mine->hits;
    if (!hits->ctx) {
        hits->ctx = ctx;
        hits->limits = job->limits;
        hits->recs = job->recs;
        hits->count = job->recs ? job->served : 0;
        hits->tree = job->tree;
    }
    cdl_path_first_hit first = {hit_lookup_serve, hits};
    cdl_path_context served = ctx->path;
    if (!job->own && hits->count > 0) served.first_hit = &first;
    for (size_t r = begin; r < end; ++r) {
        size_t i = job->at[r];
        cdl_vec3 p = job->grid->points[i], n = job->grid->normals[i];
        uint64_t stream = cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x6963616368 /* "icach" */);
        /* Pilot: how variable are this record's paths. */
        uint64_t stage_base = job->own ? 2 : 0; /* own: streams 2, 3, ... */
        cdl_rng_key key = {ctx->path.seed, cdl_rng_stream_id(stream, stage_base, 1)};
        cdl_icache_record pilot;
        if (!cdl_icache_gather(&served, key, p, n, PILOT_M, PILOT_N, &pilot, stats, NULL))
            return cdl_error_out_of_memory(err);
        (void)hit_lookup_take_variance(hits, PILOT_M * PILOT_N);
        double R = job->E_direct[i] + pilot.E;
        /* Where the points' target is relative to a floor (surface maps:
         * half their surface's mean), a record there need be no better. */
        if (job->floors) R = fmax(R, job->floors[i]);
        if (job->own) {
            if (!own_gather(job, mine, i, ctx->path.seed, stream, R, &pilot, &job->out[r], &job->tallies[r]))
                return cdl_error_out_of_memory(err);
            continue;
        }
        /* The record's own variance: RECORD_SHARE (t R)^2, R = E_dir +
         * E_ind there. A point averages several records (their noise
         * shrinks by about the number it uses), so a record need not be as
         * accurate as a point. */
        double budget = RECORD_SHARE * ctx->target * ctx->target * R * R;
        double n_pilot = PILOT_M * PILOT_N;
        cdl_estimate est = {n_pilot, pilot.E * n_pilot, pilot.var * n_pilot * n_pilot, 1};
        double want = cdl_estimate_plan(&est, budget, PILOT_M * PILOT_N);
        int k = cdl_estimate_side_for(want, PILOT_M, MAX_SIDE);
        key.stream = cdl_rng_stream_id(stream, stage_base + 1, 1);
        if (!cdl_icache_gather(&served, key, p, n, k, 2 * k, &job->out[r], stats, &job->tallies[r]))
            return cdl_error_out_of_memory(err);
        job->out[r].var += hit_lookup_take_variance(hits, 2.0 * k * k);
        if (hits->failed) return cdl_error_out_of_memory(err);
    }
    return CDL_OK;
}

/* Gather records at grid points base->at[0 .. count - 1] onto the end of
 * recs (base: the job but for out and tallies). With ranks, each gathers
 * its block of them and every rank gets every record, in order. */
static cdl_status gather(const gather_job *base, size_t count, cdl_icache_records *recs, const cdl_workers *workers,
                         const char *stage, cdl_icache_stats *stats, cdl_error *err)
{
    if (recs->count + count > recs->capacity) {
        size_t cap = 2 * (recs->count + count);
        cdl_icache_record *grown = realloc(recs->items, cap * sizeof *grown);
        if (!grown) return cdl_error_out_of_memory(err);
        recs->items = grown;
        recs->capacity = cap;
    }
    int threads = workers->threads < 1 ? 1 : workers->threads;
    gather_local *locals = calloc((size_t)threads, sizeof *locals);
    cdl_path_tally *tallies = calloc(count ? count : 1, sizeof *tallies);
    if (!locals || !tallies) {
        free(locals);
        free(tallies);
        return cdl_error_out_of_memory(err);
    }
    gather_job job = *base;
    job.recs = base->tree ? recs : NULL;
    job.served = recs->count;
    job.out = recs->items + recs->count;
    job.tallies = tallies;
    cdl_workers everywhere = *workers;
    everywhere.everywhere = 1;
    cdl_pool_task task = {.count = count,
                          .chunk = 1,
                          .run = gather_records,
                          .shared = &job,
                          .locals = locals,
                          .local_size = sizeof *locals,
                          .stage = stage,
                          .records = recs->count,
                          .outputs = {{job.out, sizeof *job.out}, {tallies, sizeof *tallies}}};
    cdl_status st = cdl_pool_run_shared(&task, &everywhere, err);
    cdl_path_stats sum = {0};
    for (int t = 0; t < threads; ++t) {
        cdl_path_stats_add(&sum, &locals[t].stats);
        hit_lookup_release(&locals[t].hits);
        lookup_release(&locals[t].own);
    }
    if (st == CDL_OK) st = cdl_path_stats_share(workers->ranks, &sum, err);
    if (st == CDL_OK) {
        cdl_path_stats_add(&stats->paths, &sum);
        cdl_path_stats_add_tallies(&stats->paths, tallies, count);
        recs->count += count;
    }
    free(locals);
    free(tallies);
    return st;
}

/* A new record's radius: the harmonic mean distance, no larger than
 * E / |g_t| (where the irradiance changes by its own size: Tabellion and
 * Lamorlette 2004) nor than its distance to an earlier record plus that
 * record's radius (neighbour clamping: Krivanek et al., "Radiance caching
 * for efficient global illumination computation", IEEE TVCG 2005), and
 * within [Rmin, Rmax] / 2. */
static void set_radius(const reach_limits *l, cdl_icache_records *recs, size_t id, const cdl_record_octree *tree,
                       lookup *lk)
{
    cdl_icache_record *r = &recs->items[id];
    double R = r->harmonic;
    double g = cdl_vec3_length(r->grad_t);
    if (g > 0.0 && r->E > 0.0 && r->E / g < R) R = r->E / g;
    size_t m = cdl_record_octree_lookup(tree, r->p, &lk->ids, &lk->capacity);
    for (size_t c = 0; m != (size_t)-1 && c < m; ++c) {
        const cdl_icache_record *o = &recs->items[lk->ids[c]];
        if (o->radius == OWN_RADIUS) continue;
        double bound = cdl_vec3_length(cdl_vec3_sub(r->p, o->p)) + o->radius;
        if (bound < R) R = bound;
    }
    r->radius = fmin(0.5 * l->Rmax, fmax(0.5 * l->Rmin, R));
}

/* Gather records at grid points at[0 .. count - 1], give them radii in
 * order and enter them in the tree. */
static cdl_status add_records(const cdl_icache_context *ctx, const reach_limits *l, const cdl_grid *grid,
                              size_t grid_index, const double *E_direct, const double *floors, const size_t *at,
                              size_t count,
                              cdl_icache_records *recs, cdl_record_octree *tree, unsigned char *has, lookup *lk,
                              const cdl_workers *workers, const char *stage, cdl_icache_stats *stats, cdl_error *err)
{
    size_t first = recs->count;
    gather_job base = {ctx, l, NULL, 0, tree, grid, grid_index, E_direct, NULL, 0, at, 0.0, floors, NULL, NULL};
    cdl_status st = gather(&base, count, recs, workers, stage, stats, err);
    for (size_t c = 0; st == CDL_OK && c < count; ++c) has[at[c]] = 1;
    for (size_t id = first; st == CDL_OK && id < recs->count; ++id) {
        set_radius(l, recs, id, tree, lk);
        st = cdl_record_octree_insert(tree, (uint32_t)id, recs->items[id].p, tree_reach(l, &recs->items[id]), err);
    }
    return st;
}

/* Gather, at grid points at[0 .. count - 1], records that serve only their
 * own point (radius OWN_RADIUS), each to that point's whole target, and
 * enter them in the tree. */
static cdl_status add_own_records(const cdl_icache_context *ctx, const reach_limits *l, const cdl_grid *grid,
                                  size_t grid_index, const double *E_direct, const double *var_direct, double floor,
                                  const double *floors, const size_t *at, size_t count, cdl_icache_records *recs,
                                  cdl_record_octree *tree, const cdl_workers *workers, const char *stage,
                                  cdl_icache_stats *stats, cdl_error *err)
{
    size_t first = recs->count;
    gather_job base = {ctx, l, NULL, 0, tree, grid, grid_index, E_direct, var_direct, 1, at, floor, floors, NULL, NULL};
    cdl_status st = gather(&base, count, recs, workers, stage, stats, err);
    for (size_t id = first; st == CDL_OK && id < recs->count; ++id) {
        recs->items[id].radius = OWN_RADIUS;
        st = cdl_record_octree_insert(tree, (uint32_t)id, recs->items[id].p, tree_reach(l, &recs->items[id]), err);
    }
    return st;
}

/* ---- a grid --------------------------------------------------------------------- */

typedef struct point_job {
    const cdl_icache_context *ctx;
    const reach_limits *limits;
    const cdl_icache_records *recs;
    const cdl_record_octree *tree;
    const cdl_grid *grid;
    const double *E_direct, *var_direct;
    double floor;             /* least R of any point: 1e-3 of the grid's brightest direct light */
    const double *floors;     /* NULL, or per point a larger least R (surface maps: their tolerance's floor) */
    int final;                /* 1: write E and var; 0: flag points that need a record */
    int sweep;                /* with final 0: flag only the points no record serves */
    double *E, *var;
    double *ask;              /* per point: the separation a new record there keeps, or 0 */
} point_job;

static cdl_status visit_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    const point_job *job = shared;
    lookup *lk = local;
    for (size_t i = begin; i < end; ++i) {
        interpolation it;
        if (!interpolate(job->ctx, job->limits, job->recs, job->tree, job->grid->points[i], job->grid->normals[i], lk,
                         &it))
            return cdl_error_out_of_memory(err);
        if (job->final) {
            job->E[i] = it.E;
            job->var[i] = it.var;
            continue;
        }
        if (job->sweep) {
            /* every such point gets its own record: no separation */
            job->ask[i] = it.used == 0 ? 1e-300 : 0.0;
            continue;
        }
        double R = fmax(job->E_direct[i] + it.E, job->floors ? fmax(job->floor, job->floors[i]) : job->floor);
        /* A point asks for a record when the interpolation's own variance
         * exceeds (t R)^2 (the records' noise, averaged, comes on top;
         * asking at a quarter of it took 35 % more records for an error
         * 20 % smaller in the cube above). */
        double share = job->ctx->target * job->ctx->target * R * R;
        /* Records are no denser than half the least reach apart: where a
         * record already serves the point from nearer than that, another
         * would not serve it much better (its reach cannot shrink below
         * reach_min, so the records' spread there stays), and the point
         * keeps the error it states. Without this bound a wall's gap
         * behind a cabinet, or the ceiling an inch above a panel, asked
         * anew in every pass: on the example office's surface maps 2550
         * records, against 1180 with it at no loss of accuracy against a
         * converged reference (320 points, median error 0.41 %). */
        int crowded = it.nearest < NEAREST_FRACTION * job->limits->reach_min;
        job->ask[i] = (it.used == 0 || (it.interp_var > share && !crowded)) ? fmax(job->limits->reach_min, 0.5 * it.reach)
                                                                             : 0.0;
    }
    return CDL_OK;
}

/* With ranks, each rank's asks (its block of the points'), exchanged as
 * the list of the points that ask: every rank then holds every point's
 * ask, as one process would, for what is usually a small share of them. */
typedef struct ask_entry {
    uint64_t index;
    double ask;
} ask_entry;

static cdl_status share_asks(cdl_rank_group *group, double *ask, size_t count, cdl_error *err)
{
    if (cdl_rank_group_count(group) == 1) return CDL_OK;
    size_t begin, end, mine = 0;
    cdl_rank_block(count, CDL_RANK_KEEP_ALIGN, group->rank, group->count, &begin, &end);
    for (size_t i = begin; i < end; ++i) mine += ask[i] > 0.0;
    ask_entry *own = malloc((mine + 1) * sizeof *own);
    if (!own) return cdl_error_out_of_memory(err);
    mine = 0;
    for (size_t i = begin; i < end; ++i)
        if (ask[i] > 0.0) own[mine++] = (ask_entry){i, ask[i]};
    void *all = NULL;
    size_t total = 0;
    cdl_status st = cdl_rank_allgather_list(group, own, mine, sizeof *own, &all, &total, err);
    if (st == CDL_OK) {
        memset(ask, 0, count * sizeof *ask);
        const ask_entry *e = all;
        for (size_t k = 0; k < total; ++k) ask[e[k].index] = e[k].ask;
    }
    free(own);
    free(all);
    return st;
}

/* Every point through visit_points on the workers: the final values kept
 * or everywhere as the workers say, the asks always everywhere. */
static cdl_status visit(point_job *job, const cdl_workers *workers, const char *stage, size_t records,
                        cdl_error *err)
{
    int threads = workers->threads < 1 ? 1 : workers->threads;
    lookup *locals = calloc((size_t)threads, sizeof *locals);
    if (!locals) return cdl_error_out_of_memory(err);
    cdl_workers w = *workers;
    if (!job->final) w.everywhere = 0;
    cdl_pool_task task = {.count = job->grid->count, .chunk = 16, .run = visit_points, .shared = job,
                          .locals = locals, .local_size = sizeof *locals, .stage = stage, .records = records};
    if (job->final) {
        task.outputs[0] = (cdl_pool_output){job->E, sizeof *job->E};
        task.outputs[1] = (cdl_pool_output){job->var, sizeof *job->var};
    }
    cdl_status st = cdl_pool_run_shared(&task, &w, err);
    for (int t = 0; t < threads; ++t) lookup_release(&locals[t]);
    free(locals);
    if (st == CDL_OK && !job->final) st = share_asks(workers->ranks, job->ask, job->grid->count, err);
    return st;
}

/* Of list[0 .. count - 1] (in order), those farther than `factor` times
 * their ask (at least `least`) from every one kept before them, into
 * kept[0 .. *kept_count - 1];
 * the others, in order, into rest (unless NULL). */
static cdl_status thin(const cdl_grid *grid, const size_t *list, size_t count, const double *ask, double least,
                       double factor, cdl_bounds3 box, size_t *kept, size_t *kept_count, size_t *rest, cdl_error *err)
{
    cdl_record_octree *tree;
    cdl_status st = cdl_record_octree_create(box, &tree, err);
    if (st != CDL_OK) return st;
    lookup lk = {NULL, 0, NULL, 0, 0};
    size_t nk = 0, nr = 0;
    for (size_t k = 0; k < count && st == CDL_OK; ++k) {
        size_t i = list[k];
        size_t m = cdl_record_octree_lookup(tree, grid->points[i], &lk.ids, &lk.capacity);
        if (m == (size_t)-1) {
            st = cdl_error_out_of_memory(err);
            break;
        }
        int near = 0;
        for (size_t c = 0; c < m && !near; ++c) {
            size_t j = kept[lk.ids[c]];
            near = cdl_vec3_length(cdl_vec3_sub(grid->points[i], grid->points[j])) < factor * fmax(least, ask[j]);
        }
        if (near) {
            if (rest) rest[nr++] = i;
            continue;
        }
        kept[nk] = i;
        st = cdl_record_octree_insert(tree, (uint32_t)nk, grid->points[i], factor * fmax(least, ask[i]), err);
        ++nk;
    }
    *kept_count = nk;
    lookup_release(&lk);
    cdl_record_octree_release(tree);
    return st;
}

/* Pick, in index order, the asking points that keep their separation from
 * every point picked before them in this pass (and hold no record yet). */
static cdl_status pick(const cdl_grid *grid, const double *ask, const unsigned char *has, cdl_bounds3 box,
                       size_t **at, size_t *count, cdl_error *err)
{
    *count = 0;
    size_t *asking = malloc((grid->count + 1) * sizeof *asking), n = 0;
    if (!asking) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < grid->count; ++i)
        if (ask[i] > 0.0 && !has[i]) asking[n++] = i;
    cdl_status st = thin(grid, asking, n, ask, 0.0, 1.0, box, *at, count, NULL, err);
    free(asking);
    return st;
}

/* The records a pass asked for (at[0 .. count - 1], each keeping ask[i]
 * from the others), gathered coarse to fine: where they are many more than
 * the records already there, first a sparser lattice of them (twice the
 * separation, at least the least reach, recursively), then the rest, whose gathers' first hits the
 * sparser records then serve (gather_records). The records placed are the
 * same; only the order they are gathered in, and so what serves their
 * first hits, follows from this. */
#define STAGE_LEAST 32

typedef struct stage_args {
    const cdl_icache_context *ctx;
    const reach_limits *l;
    const cdl_grid *gather_grid;
    size_t grid_index;
    const double *E_direct, *floors, *ask;
    cdl_icache_records *recs;
    cdl_record_octree *tree;
    unsigned char *has;
    lookup *lk;
    const cdl_workers *workers;
    const char *stage;
    cdl_icache_stats *stats;
    const cdl_grid *grid;
    cdl_bounds3 box;
} stage_args;

static cdl_status add_records_staged(const stage_args *a, const size_t *at, size_t count, double factor,
                                     cdl_error *err)
{
    if (count <= STAGE_LEAST || count <= a->recs->count)
        return add_records(a->ctx, a->l, a->gather_grid, a->grid_index, a->E_direct, a->floors, at, count, a->recs,
                           a->tree, a->has, a->lk, a->workers, a->stage, a->stats, err);
    size_t *kept = malloc(2 * count * sizeof *kept), nk = 0;
    if (!kept) return cdl_error_out_of_memory(err);
    size_t *rest = kept + count;
    cdl_status st = thin(a->grid, at, count, a->ask, a->l->reach_min, 2.0 * factor, a->box, kept, &nk, rest, err);
    if (st == CDL_OK && nk < count) st = add_records_staged(a, kept, nk, 2.0 * factor, err);
    if (st == CDL_OK)
        st = nk < count ? add_records(a->ctx, a->l, a->gather_grid, a->grid_index, a->E_direct, a->floors, rest,
                                      count - nk, a->recs, a->tree, a->has, a->lk, a->workers, a->stage, a->stats, err)
                        : add_records(a->ctx, a->l, a->gather_grid, a->grid_index, a->E_direct, a->floors, at, count,
                                      a->recs, a->tree, a->has, a->lk, a->workers, a->stage, a->stats, err);
    free(kept);
    return st;
}

/* One target (a grid, or the probes of surface maps) served by records in
 * `recs` entered in `tree`: with `place`, records are seeded (when `seed`)
 * and placed where its points need them; then every point is interpolated. */
typedef struct serve_request {
    const cdl_icache_context *ctx;
    const reach_limits *limits;
    cdl_icache_records *recs;
    cdl_record_octree *tree;
    const cdl_grid *grid;
    size_t grid_index;
    const double *E_direct, *var_direct;
    double *E_indirect, *var_indirect;
    const double *floors;
    const cdl_grid *gather_at; /* where records for the points are gathered (the same indices), or NULL: at them */
    int place, seed, passes, own;
    const cdl_workers *workers;
    const char *stage;
    cdl_icache_stats *stats;
} serve_request;

/* The points whose stated error, direct and interpolated, is above the
 * target, in index order, into at[0 .. *count - 1]. With kept results each
 * rank looks at its block and the ranks exchange what they found. */
static cdl_status find_alone(const serve_request *q, double floor, size_t *at, size_t *count, cdl_error *err)
{
    size_t n = q->grid->count, begin = 0, end = n;
    cdl_rank_group *group = q->workers->ranks;
    int kept = !q->workers->everywhere && cdl_rank_group_count(group) > 1;
    if (kept) cdl_rank_block(n, CDL_RANK_KEEP_ALIGN, group->rank, group->count, &begin, &end);
    *count = 0;
    for (size_t i = begin; i < end; ++i) {
        double least = q->floors ? fmax(floor, q->floors[i]) : floor;
        double R = fmax(q->E_direct[i] + q->E_indirect[i], least);
        if (q->var_direct[i] + q->var_indirect[i] > q->ctx->target * q->ctx->target * R * R) at[(*count)++] = i;
    }
    if (!kept) return CDL_OK;
    void *all = NULL;
    size_t total = 0;
    cdl_status st = cdl_rank_allgather_list(group, at, *count, sizeof *at, &all, &total, err);
    if (st == CDL_OK && total) memcpy(at, all, total * sizeof *at);
    if (st == CDL_OK) *count = total;
    free(all);
    return st;
}

static cdl_status serve(const serve_request *q, cdl_bounds3 box, cdl_error *err)
{
    const cdl_grid *grid = q->grid;
    const cdl_grid *gather_grid = q->gather_at ? q->gather_at : grid;
    const reach_limits *l = q->limits;
    double brightest = 0.0;
    for (size_t i = 0; i < grid->count; ++i)
        if (q->E_direct[i] > brightest) brightest = q->E_direct[i];
    size_t *at = malloc(grid->count * sizeof *at);
    double *ask = calloc(grid->count, sizeof *ask);
    unsigned char *has = calloc(grid->count, 1);
    lookup lk = {NULL, 0, NULL, 0, 0};
    cdl_status st = (!at || !ask || !has) ? cdl_error_out_of_memory(err) : CDL_OK;
    if (st == CDL_OK && q->place && q->seed) {
        /* Seeds: every point farther than the largest reach from the seeds
         * before it (in index order). */
        for (size_t i = 0; i < grid->count; ++i) ask[i] = l->reach_max;
        size_t count = 0;
        st = pick(grid, ask, has, box, &at, &count, err);
        if (st == CDL_OK)
            st = add_records(q->ctx, l, gather_grid, q->grid_index, q->E_direct, q->floors, at, count, q->recs, q->tree,
                             has, &lk, q->workers, q->stage, q->stats, err);
    }
    point_job job = {q->ctx, l, q->recs, q->tree, grid, q->E_direct, q->var_direct, 1e-3 * brightest, q->floors,
                     0, 0, q->E_indirect, q->var_indirect, ask};
    for (int pass = 1; st == CDL_OK && q->place && q->passes && pass <= MAX_PASSES; ++pass) {
        st = visit(&job, q->workers, q->stage, q->recs->count, err);
        size_t count = 0;
        if (st == CDL_OK) st = pick(grid, ask, has, box, &at, &count, err);
        if (st != CDL_OK || count == 0) break;
        q->stats->passes = (size_t)pass;
        stage_args sa = {q->ctx,  l,        gather_grid, q->grid_index, q->E_direct, q->floors, ask, q->recs,
                         q->tree, has,      &lk,         q->workers,    q->stage,    q->stats,  grid, box};
        st = add_records_staged(&sa, at, count, 1.0, err);
    }
    /* No point may go unserved (it would read 0 +- 0): the passes take
     * asking points apart from each other and may stop before every point
     * is served; the sweep gives each point still unserved its own record. */
    if (st == CDL_OK && q->place) {
        job.sweep = 1;
        st = visit(&job, q->workers, q->stage, q->recs->count, err);
        job.sweep = 0;
        size_t count = 0;
        if (st == CDL_OK) st = pick(grid, ask, has, box, &at, &count, err);
        stage_args sa = {q->ctx,  l,        gather_grid, q->grid_index, q->E_direct, q->floors, ask, q->recs,
                         q->tree, has,      &lk,         q->workers,    q->stage,    q->stats,  grid, box};
        if (st == CDL_OK && count > 0) st = add_records_staged(&sa, at, count, 1.0, err);
    }
    if (st == CDL_OK) {
        job.final = 1;
        st = visit(&job, q->workers, q->stage, q->recs->count, err);
    }
    /* Points still above the target: each gets a record of its own. */
    size_t alone = 0;
    if (st == CDL_OK && q->place && q->own) st = find_alone(q, job.floor, at, &alone, err);
    if (st == CDL_OK && alone > 0) {
        st = add_own_records(q->ctx, l, gather_grid, q->grid_index, q->E_direct, q->var_direct, job.floor, q->floors, at,
                             alone, q->recs, q->tree, q->workers, q->stage, q->stats, err);
        q->stats->alone += alone;
        if (st == CDL_OK) st = visit(&job, q->workers, q->stage, q->recs->count, err);
    }
    lookup_release(&lk);
    free(at);
    free(ask);
    free(has);
    return st;
}

cdl_status cdl_icache_solve_grid(const cdl_icache_context *ctx, const cdl_grid *grid, size_t grid_index,
                                 const double *E_direct, const double *var_direct, double *E_indirect,
                                 double *var_indirect, cdl_icache_records *recs,
                                 const cdl_workers *workers, const char *stage, cdl_icache_stats *stats,
                                 cdl_error *err)
{
    if (grid->count == 0) return CDL_OK;
    reach_limits l = limits_for(grid_spacing(grid), ctx->target);
    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t i = 0; i < grid->count; ++i) cdl_bounds3_grow(&box, grid->points[i]);
    cdl_record_octree *tree = NULL;
    cdl_status st = cdl_record_octree_create(box, &tree, err);
    int reuse = recs->count > 0;
    /* Records read from a cache file keep the radii they were made with. */
    for (size_t id = 0; st == CDL_OK && reuse && id < recs->count; ++id)
        st = cdl_record_octree_insert(tree, (uint32_t)id, recs->items[id].p, tree_reach(&l, &recs->items[id]), err);
    serve_request q = {ctx,     &l,      recs,    tree,    grid, grid_index, E_direct, var_direct, E_indirect,
                       var_indirect, NULL, NULL, !reuse, !reuse, 1, 1, workers, stage, stats};
    if (st == CDL_OK) st = serve(&q, box, err);
    stats->records += recs->count;
    cdl_record_octree_release(tree);
    return st;
}

void cdl_icache_records_release(cdl_icache_records *records)
{
    free(records->items);
    memset(records, 0, sizeof *records);
}

/* ---- one cache for a solve -------------------------------------------------------- */

struct cdl_icache_shared {
    cdl_icache_records records;
    cdl_record_octree *tree;
    cdl_bounds3 bounds;
};

cdl_status cdl_icache_shared_create(cdl_bounds3 bounds, cdl_icache_shared **out, cdl_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return cdl_error_out_of_memory(err);
    (*out)->bounds = bounds;
    cdl_status st = cdl_record_octree_create(bounds, &(*out)->tree, err);
    if (st != CDL_OK) {
        free(*out);
        *out = NULL;
    }
    return st;
}

void cdl_icache_shared_release(cdl_icache_shared *cache)
{
    if (!cache) return;
    cdl_icache_records_release(&cache->records);
    cdl_record_octree_release(cache->tree);
    free(cache);
}

size_t cdl_icache_shared_count(const cdl_icache_shared *cache)
{
    return cache->records.count;
}

cdl_status cdl_icache_solve_shared(const cdl_icache_context *ctx, cdl_icache_shared *cache,
                                   const cdl_icache_target *target, cdl_error *err)
{
    const cdl_grid *grid = target->points;
    if (grid->count == 0) return CDL_OK;
    double h = target->spacing > 0.0 ? target->spacing : grid_spacing(grid);
    reach_limits l = limits_for(h, ctx->target);
    size_t before = cache->records.count;
    serve_request q = {ctx,
                       &l,
                       &cache->records,
                       cache->tree,
                       grid,
                       target->key,
                       target->E_direct,
                       target->var_direct,
                       target->E_indirect,
                       target->var_indirect,
                       target->floors,
                       target->gather_at,
                       1,
                       before == 0,
                       !target->only_unserved,
                       !target->no_own_records,
                       target->workers,
                       target->stage,
                       target->stats};
    cdl_status st = serve(&q, cache->bounds, err);
    target->stats->records += cache->records.count - before;
    return st;
}
