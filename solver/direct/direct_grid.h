/* direct_grid.h - the direct illuminance of a whole grid, on worker threads.
 *
 * Points are taken in chunks of 16; for each chunk the lights whose
 * emission cone misses the chunk's bounding ball are skipped once, and the
 * rest go through cdl_direct_illuminance_chunk. Random numbers are keyed by
 * (seed, grid index, point index): results do not depend on the threads.
 */
#ifndef CANDELA_SOLVER_DIRECT_GRID_H
#define CANDELA_SOLVER_DIRECT_GRID_H

#include <stddef.h>

#include "base/error.h"
#include "solver/direct/direct.h"
#include "solver/grid/grid.h"
#include "solver/pool.h"

/* The stream of grid point `index` of grid `grid_index` (the key every
 * per-point random number derives from). */
uint64_t cdl_direct_point_stream(size_t grid_index, size_t index);

/* Where the outputs beyond E go (each NULL when not asked for): ambient
 * occlusion and its standard error; cylindrical and semicylindrical
 * illuminance (their exact part). Semicylinders face each point's normal's
 * horizontal part (cdl_direct_facing_direction; the caller checks there is
 * one). */
typedef struct cdl_direct_outputs {
    double *ao, *ao_stderr;
    double *Ez, *Esz;
    const unsigned char *on_surface;  /* per point, 1 where it lies on a surface (NULL: none does) */
} cdl_direct_outputs;

/* Direct illuminance (lux) at every point of `grid`, the variance of each
 * value (0 where exact), and the outputs `outputs` asks for (NULL: none).
 * Sample counts are added to *stats. */
cdl_status cdl_direct_solve_grid(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                                 const cdl_grid *grid, size_t grid_index, double *E, double *variance,
                                 int threads, const cdl_progress_sink *progress, const cdl_direct_outputs *outputs,
                                 const char *stage, cdl_direct_sample_stats *stats, cdl_error *err);

/* Where p (receiving normal n) is evaluated: itself, or, where a surface
 * passes through it at an angle to its receiving plane, the point just off
 * it whose value is the limit from the side the grid is meant for
 * (direct_grid.c). Returns 1 for an edge point: one where a surface whose
 * plane holds n passes through p (two surfaces meet there). */
int cdl_direct_edge_point(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 *at);

/* Edge points of a grid: their number, and the index of the first in *first. */
size_t cdl_direct_find_edge_points(const cdl_direct_context *ctx, const cdl_grid *grid, size_t *first);

#endif
