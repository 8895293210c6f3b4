/* direct_grid.c - a grid's direct illuminance in chunks on the worker pool. */
#include "solver/direct/direct_grid.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "base/rng.h"
#include "solver/scene/scene_geometry.h"

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
    double *E, *variance;
    const cdl_direct_outputs *outputs;
} grid_job;

typedef struct grid_worker {
    cdl_direct_sample_stats stats;
    uint32_t *active;             /* light indices for the current chunk */
    cdl_direct_scratch scratch;
} grid_worker;

static int chunk_near_surface(const cdl_direct_context *ctx, cdl_bounds3 box);

static cdl_status solve_chunk(void *shared, void *local, size_t start, size_t end, cdl_error *err)
{
    const grid_job *job = shared;
    grid_worker *w = local;
    const cdl_grid *grid = job->grid;
    /* Where each point is evaluated: itself, or for an edge point the
     * point just off it on the side the grid is meant for. */
    cdl_vec3 at[CHUNK];
    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t i = start; i < end; ++i) {
        at[i - start] = grid->points[i];
        cdl_bounds3_grow(&box, grid->points[i]);
    }
    /* One probe for the whole chunk: a chunk no surface comes near (a
     * work plane in the open) has no point to move. */
    if (chunk_near_surface(job->ctx, box))
        for (size_t i = start; i < end; ++i)
            cdl_direct_edge_point(job->ctx, grid->points[i], grid->normals[i], &at[i - start]);
    /* Skip, once for the whole chunk, the lights that cannot reach it. */
    box = cdl_bounds3_empty();
    for (size_t i = start; i < end; ++i) cdl_bounds3_grow(&box, at[i - start]);
    size_t active = cdl_direct_select_lights(job->ctx, cdl_bounds3_centre(box), 0.5 * cdl_bounds3_diagonal(box),
                                             w->active);
    uint64_t streams[CDL_DIRECT_CHUNK_MAX];
    for (size_t i = start; i < end; ++i) streams[i - start] = cdl_direct_point_stream(job->grid_index, i);
    cdl_status st = cdl_direct_illuminance_chunk(job->ctx, job->strategies, w->active, active, streams,
                                                 at, grid->normals + start, end - start,
                                                 job->E + start, job->variance + start, &w->stats, &w->scratch, err);
    if (st != CDL_OK) return st;
    const cdl_direct_outputs *v = job->outputs;
    if (v && v->ao)
        for (size_t i = start; i < end; ++i)
            v->ao[i] = cdl_direct_ambient_occlusion(job->ctx, streams[i - start], at[i - start], grid->normals[i],
                                                    v->ao_stderr ? &v->ao_stderr[i] : NULL, &w->stats);
    if (v && (v->Ez || v->Esz))
        for (size_t i = start; i < end; ++i) {
            cdl_vec3 facing = cdl_vec3_make(1, 0, 0);
            cdl_direct_facing_direction(grid->normals[i], &facing);
            cdl_direct_vertical_point(job->ctx, job->strategies, w->active, active, at[i - start], grid->normals[i],
                                      facing, v->on_surface && v->on_surface[i], v->Ez ? &v->Ez[i] : NULL,
                                      v->Esz ? &v->Esz[i] : NULL, &w->stats);
        }
    return CDL_OK;
}

cdl_status cdl_direct_solve_grid(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                                 const cdl_grid *grid, size_t grid_index, double *E, double *variance,
                                 int threads, const cdl_progress_sink *progress, const cdl_direct_outputs *outputs,
                                 const char *stage, cdl_direct_sample_stats *stats, cdl_error *err)
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
    grid_job job = {ctx, strategies, grid, grid_index, E, variance, outputs};
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

/* Edge points. A point's rays ignore the surfaces through it (their plane
 * within the double rounding bound, ray_scene.c). That is right for a
 * surface whose plane is the receiving plane (a floor point facing up: no
 * ray of its hemisphere crosses the floor), but a surface through the point
 * at an angle to that plane (a wall at the foot of which a floor point
 * lies, a sphere under a tilted receiver) would be seen through by the
 * rays that cross it. The same holds for surfaces nearer than Embree's
 * float resolution, whose side Embree cannot tell. Such a point is valued
 * as the limit from the side the grid is meant for: it is evaluated at the
 * point moved 8 float resolutions (far below any distance that changes
 * illuminance, yet resolved by Embree) towards n + the sum of the sides of
 * the surfaces through it, each side being
 *   - the one the point is on, when it is off the surface's plane by more
 *     than the double rounding bound;
 *   - else the one n faces, when n is at least 1/8 (in cosine) off the
 *     surface's plane: a grid lying on a surface belongs to the side its
 *     normal faces;
 *   - else (the surface's plane holds n, as a wall at the foot of which a
 *     floor point lies) the side the surface's front faces: the inside of
 *     an inward box, the room side of a wall drawn facing the room.
 * The last case is the one where two surfaces meet and n cannot say which
 * side is meant: those points are counted as edge points (the CLI warns).
 * A surface whose normal is within 4.5e-5 rad of n is the one the point
 * lies on and moves nothing. */
#define EDGE_PARALLEL_COS (1.0 - 1e-9)
#define EDGE_AMBIGUOUS_COS 0.125
#define EDGE_BOX_RESOLUTIONS 1.0
#define EDGE_MOVE_RESOLUTIONS 8.0

typedef struct edge_probe {
    const cdl_scene_geometry *geometry;
    cdl_vec3 p, n;
    double on_plane;             /* the rounding bound at p */
    cdl_vec3 side;               /* sum of the sides of the surfaces through p */
    int tilted;                  /* surfaces through p at an angle to the receiving plane */
    int ambiguous;               /* ... of which n cannot tell the side */
} edge_probe;

static void visit_edge_surface(void *user, const double *prim, int is_sphere, uint32_t owner)
{
    edge_probe *e = user;
    cdl_vec3 front;
    double dist; /* signed distance of p from the surface, positive in front */
    if (is_sphere) {
        cdl_vec3 d = cdl_vec3_sub(e->p, cdl_vec3_make(prim[0], prim[1], prim[2]));
        double len = cdl_vec3_length(d);
        front = len > 0.0 ? cdl_vec3_scale(d, 1.0 / len) : e->n;
        dist = len - prim[3];
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(e->geometry, owner);
        if (piece && piece->shape.inward) {
            front = cdl_vec3_neg(front);
            dist = -dist;
        }
    } else {
        cdl_vec3 a = cdl_vec3_make(prim[0], prim[1], prim[2]);
        cdl_vec3 b = cdl_vec3_make(prim[3], prim[4], prim[5]), c = cdl_vec3_make(prim[6], prim[7], prim[8]);
        front = cdl_vec3_normalize(cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
        dist = cdl_vec3_dot(front, cdl_vec3_sub(e->p, a));
    }
    double along = cdl_vec3_dot(front, e->n);
    if (!(fabs(along) < EDGE_PARALLEL_COS)) return;
    e->tilted++;
    int ambiguous = !(fabs(along) >= EDGE_AMBIGUOUS_COS);
    e->ambiguous += ambiguous;
    double sign = fabs(dist) > e->on_plane ? dist : ambiguous ? 1.0 : along;
    e->side = cdl_vec3_add(e->side, sign < 0.0 ? cdl_vec3_neg(front) : front);
}

int cdl_direct_edge_point(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 *at)
{
    *at = p;
    if (!ctx->occluders || !ctx->rays) return 0;
    double resolution = cdl_ray_scene_resolution(ctx->rays, p);
    edge_probe e = {ctx->geometry, p, n, cdl_ray_offsets_epsilon(&ctx->offsets, p), {0, 0, 0}, 0, 0};
    double half = EDGE_BOX_RESOLUTIONS * resolution;
    cdl_vec3 h = cdl_vec3_make(half, half, half);
    cdl_occluder_index_visit_box(ctx->occluders, cdl_vec3_sub(p, h), cdl_vec3_add(p, h), visit_edge_surface, &e);
    if (!e.tilted) return 0;
    cdl_vec3 dir = cdl_vec3_add(n, e.side);
    double len = cdl_vec3_length(dir);
    dir = len > 1e-6 ? cdl_vec3_scale(dir, 1.0 / len) : n;
    *at = cdl_vec3_madd(p, EDGE_MOVE_RESOLUTIONS * resolution, dir);
    return e.ambiguous > 0;
}

/* Does any surface come within the edge probe's reach of the box? */
static int chunk_near_surface(const cdl_direct_context *ctx, cdl_bounds3 box)
{
    if (!ctx->occluders || !ctx->rays) return 0;
    double half = EDGE_BOX_RESOLUTIONS * fmax(cdl_ray_scene_resolution(ctx->rays, box.lo),
                                              cdl_ray_scene_resolution(ctx->rays, box.hi));
    cdl_vec3 h = cdl_vec3_make(half, half, half);
    return cdl_occluder_index_surface_in_box(ctx->occluders, cdl_vec3_sub(box.lo, h), cdl_vec3_add(box.hi, h));
}

size_t cdl_direct_find_edge_points(const cdl_direct_context *ctx, const cdl_grid *grid, size_t *first)
{
    size_t count = 0;
    *first = 0;
    for (size_t i = 0; i < grid->count; ++i) {
        cdl_vec3 at;
        if (cdl_direct_edge_point(ctx, grid->points[i], grid->normals[i], &at) && count++ == 0) *first = i;
    }
    return count;
}
