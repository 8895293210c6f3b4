/* direct_grid.c - a grid's direct illuminance in chunks on the worker pool. */
#include "solver/direct/direct_grid.h"

#include <math.h>
#include <stdlib.h>

#include "radiometry/bounds.h"
#include "radiometry/rng.h"

#define CHUNK 16

uint64_t cdl_direct_point_stream(size_t grid_index, size_t index)
{
    return cdl_rng_stream_id((uint64_t)grid_index, (uint64_t)index, 0x6772696470ull /* "gridp" */);
}

typedef struct grid_job {
    const cdl_direct_context *ctx;
    const cdl_light_strategy *strategies;
    const cdl_grid *grid;
    size_t grid_index;
    double *E, *variance, *ao;
} grid_job;

typedef struct grid_worker {
    cdl_direct_sample_stats stats;
    uint32_t *active;             /* light indices for the current chunk */
    cdl_direct_scratch scratch;
} grid_worker;

static cdl_status solve_chunk(void *shared, void *local, size_t start, size_t end, cdl_error *err)
{
    const grid_job *job = shared;
    grid_worker *w = local;
    const cdl_grid *grid = job->grid;
    /* Skip, once for the whole chunk, the lights that cannot reach it. */
    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t i = start; i < end; ++i) cdl_bounds3_grow(&box, grid->points[i]);
    size_t active = cdl_direct_select_lights(job->ctx, cdl_bounds3_centre(box), 0.5 * cdl_bounds3_diagonal(box),
                                             w->active);
    uint64_t streams[CDL_DIRECT_CHUNK_MAX];
    for (size_t i = start; i < end; ++i) streams[i - start] = cdl_direct_point_stream(job->grid_index, i);
    cdl_status st = cdl_direct_illuminance_chunk(job->ctx, job->strategies, w->active, active, streams,
                                                 grid->points + start, grid->normals + start, end - start,
                                                 job->E + start, job->variance + start, &w->stats, &w->scratch, err);
    if (st != CDL_OK) return st;
    if (job->ao)
        for (size_t i = start; i < end; ++i)
            job->ao[i] = cdl_direct_ambient_occlusion(job->ctx, streams[i - start], grid->points[i], grid->normals[i],
                                                      &w->stats);
    return CDL_OK;
}

cdl_status cdl_direct_solve_grid(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                                 const cdl_grid *grid, size_t grid_index, double *E, double *variance, double *ao,
                                 int threads, const cdl_progress_sink *progress, const char *stage,
                                 cdl_direct_sample_stats *stats, cdl_error *err)
{
    if (threads < 1) threads = 1;
    grid_worker *workers = calloc((size_t)threads, sizeof *workers);
    uint32_t *active = malloc((size_t)threads * (ctx->light_count + 1) * sizeof(uint32_t));
    if (!workers || !active) {
        free(workers);
        free(active);
        return cdl_error_out_of_memory(err);
    }
    /* Each worker tallies its points' routes apart (when the caller asks). */
    cdl_direct_route_tally *routes =
        stats->routes ? calloc((size_t)threads * (ctx->light_count + 1), sizeof *routes) : NULL;
    if (stats->routes && !routes) {
        free(workers);
        free(active);
        return cdl_error_out_of_memory(err);
    }
    for (int i = 0; i < threads; ++i) {
        workers[i].active = active + (size_t)i * (ctx->light_count + 1);
        workers[i].stats.routes = routes ? routes + (size_t)i * (ctx->light_count + 1) : NULL;
    }
    grid_job job = {ctx, strategies, grid, grid_index, E, variance, ao};
    cdl_pool_task task = {.count = grid->count,
                          .chunk = CHUNK,
                          .run = solve_chunk,
                          .shared = &job,
                          .locals = workers,
                          .local_size = sizeof *workers,
                          .stage = stage};
    cdl_status st = cdl_pool_run(&task, threads, progress, err);
    for (int i = 0; i < threads; ++i) {
        cdl_direct_stats_add(stats, &workers[i].stats, ctx->light_count);
        cdl_direct_scratch_release(&workers[i].scratch);
    }
    free(routes);
    free(active);
    free(workers);
    return st;
}

/* A point's rays start one epsilon along its normal n (ray_offsets in
 * scene_geometry.h). That moves the start off every surface through the
 * point by epsilon x |cos| of the angle between n and the surface's normal:
 * the whole epsilon for the surface the point faces, nothing for one whose
 * plane contains n (a wall standing on the floor a point lies on). A surface
 * within an eighth of an epsilon of the start (an axis-aligned box: within
 * 0.125 to 0.22 epsilon) therefore passes through the point nearly along n,
 * and which side of it the point is on is unknown: an edge point. */
size_t cdl_direct_find_edge_points(const cdl_direct_context *ctx, const cdl_grid *grid, size_t *first)
{
    size_t count = 0;
    *first = 0;
    if (!ctx->occluders) return 0;
    for (size_t i = 0; i < grid->count; ++i) {
        cdl_vec3 p = grid->points[i];
        double eps = cdl_ray_offsets_epsilon(&ctx->offsets, p);
        cdl_vec3 o = cdl_vec3_madd(p, eps, grid->normals[i]);
        cdl_vec3 h = cdl_vec3_make(0.125 * eps, 0.125 * eps, 0.125 * eps);
        if (cdl_occluder_index_surface_in_box(ctx->occluders, cdl_vec3_sub(o, h), cdl_vec3_add(o, h))) {
            if (count++ == 0) *first = i;
        }
    }
    return count;
}
