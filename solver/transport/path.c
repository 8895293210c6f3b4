/* path.c - one path from a point, next-event estimation at every vertex. */
#include "solver/transport/path.h"

#include <math.h>
#include <string.h>

#include "radiometry/frame.h"
#include "radiometry/sampling.h"
#include "solver/transport/surface_hit.h"

/* Russian roulette starts when a path's throughput falls below this: paths
 * go on surely while they carry much, and the estimate stays less skewed
 * (a skewed estimate makes its own variance estimate unreliable). 0.1 was
 * faster and better calibrated than 1, and 0.03 no better (docs/tuning.md). */
#define RR_THRESHOLD 0.1

/* Counter indices of a path's random numbers: index 0 is the caller's;
 * each vertex then takes VERTEX_DRAWS consecutive indices (roulette,
 * continuation direction), and next-event estimation its own key per
 * vertex. */
#define VERTEX_DRAWS 2

void cdl_transport_path(const cdl_path_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                        cdl_path_result *out, cdl_path_stats *stats)
{
    memset(out, 0, sizeof *out);
    out->distance = INFINITY;
    double w = 1.0;
    cdl_vec3 origin = p, origin_n = n;
    int limit = ctx->bounces == CDL_BOUNCES_AUTO ? CDL_PATH_MAX_DEPTH : ctx->bounces;
    stats->paths++;
    for (int depth = 1; depth <= limit; ++depth) {
        cdl_surface_hit hit;
        stats->rays++;
        /* A ray that leaves the scene sees the sky or nothing: direct light,
         * counted where the path started. */
        if (!cdl_transport_trace(ctx->geometry, origin, origin_n, dir, &hit)) break;
        if (depth == 1) out->distance = hit.distance;
        /* what the panes of glass on the way let through, both ways (reciprocity) */
        w *= hit.transmission;
        stats->vertices++;
        if ((uint64_t)depth > stats->longest) stats->longest = (uint64_t)depth;
        double rho = hit.reflectance;
        if (!(rho > 0.0)) break;
        cdl_rng_key nee = {key.seed, cdl_rng_stream_id(key.stream, (uint64_t)depth, 0x6e6565 /* "nee" */)};
        double unoccluded;
        /* Next-event estimation, one light drawn (cdl_direct_estimate_one_light). */
        double Ed = cdl_direct_estimate_one_light(ctx->direct, nee, hit.p, hit.n, 0, &unoccluded, &stats->direct);
        double gained = w * rho * Ed;
        out->value += gained;
        if (depth == 1) out->potential = w * rho * unoccluded;
        if (depth == limit) out->last = gained;
        if (depth == limit - 1) out->before_last = gained;
        w *= rho;
        /* The rest of the path from what is known at its first vertex. */
        double known;
        if (depth == 1 && ctx->first_hit && ctx->bounces == CDL_BOUNCES_AUTO &&
            ctx->first_hit->lookup(ctx->first_hit->user, hit.p, hit.n, w, &known)) {
            out->value += w * known;
            break;
        }
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

void cdl_path_stats_add(cdl_path_stats *to, const cdl_path_stats *from)
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

cdl_status cdl_path_stats_share(cdl_rank_group *group, cdl_path_stats *s, cdl_error *err)
{
    if (cdl_rank_group_count(group) == 1) return CDL_OK;
    uint64_t sum[6] = {s->paths, s->vertices, s->rays, s->direct.rays, s->direct.exact_evaluations,
                       s->direct.sampled_evaluations};
    uint64_t longest = s->longest;
    cdl_status st = cdl_rank_sum_u64(group, sum, 6, err);
    if (st == CDL_OK) st = cdl_rank_max_u64(group, &longest, 1, err);
    if (st != CDL_OK) return st;
    s->paths = sum[0];
    s->vertices = sum[1];
    s->rays = sum[2];
    s->direct.rays = sum[3];
    s->direct.exact_evaluations = sum[4];
    s->direct.sampled_evaluations = sum[5];
    s->longest = longest;
    return CDL_OK;
}

void cdl_path_stats_add_tallies(cdl_path_stats *stats, const cdl_path_tally *tallies, size_t count)
{
    for (size_t i = 0; i < count; ++i) {
        stats->last += tallies[i].last;
        stats->before_last += tallies[i].before_last;
        stats->total += tallies[i].total;
    }
}

double cdl_path_left_out(const cdl_path_stats *stats)
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
