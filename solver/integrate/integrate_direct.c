/* integrate_direct.c - the direct integrator: every light's direct illuminance at a grid's points.
 *
 * Each light is planned for the grid (a strategy: exact, one shadow ray,
 * exact past planar occluders or sampled; direct/direct.h), then the grid
 * is solved on worker threads (direct/direct_grid.h): E_direct and its
 * variance, ambient occlusion where asked (unless the cache's gathers give
 * it), and the exact part of the vertical outputs. The routes each light's
 * points took are left in the state for the plan.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "solver/direct/direct_grid.h"
#include "solver/integrate/integrator.h"
#include "solver/pool.h"

void cdl_grid_job_stage(const cdl_grid_job *job, const char *what, char *out, size_t size)
{
    if (what) snprintf(out, size, "grid %s: %s", job->spec->name, what);
    else snprintf(out, size, "grid %s", job->spec->name);
}

static int applies_always(const cdl_solve_state *state, const cdl_grid_job *job)
{
    (void)state;
    (void)job;
    return 1;
}

/* A point lying on a surface sees nothing behind it: the vertical outputs,
 * which look all round, are the limit from the side the point's normal
 * faces (a floor grid's cylinders stand on the floor). */
static cdl_status find_points_on_surfaces(const cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    const cdl_grid_solution *gs = job->gs;
    if (!gs->Ez && !gs->Esz) return CDL_OK;
    job->on_surface = calloc(gs->grid.count ? gs->grid.count : 1, 1);
    if (!job->on_surface) return cdl_error_out_of_memory(err);
    if (state->pieces > 0)
        job->on_surface_count = cdl_grid_surface_mask(&gs->grid, state->geometry, state->occluders, job->on_surface);
    return CDL_OK;
}

static cdl_status run_direct(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_grid_solution *gs = job->gs;
    const cdl_direct_context *direct = job->direct ? job->direct : &state->direct;
    gs->edge_point_count = cdl_direct_find_edge_points(direct, &gs->grid, &gs->first_edge_point);
    cdl_direct_plan_grid(direct, gs->grid.points, gs->grid.count, state->strategies);
    memset(state->routes, 0, (state->lights.count + 1) * sizeof *state->routes);
    cdl_status st = find_points_on_surfaces(state, job, err);
    if (st != CDL_OK) return st;

    char stage[160];
    cdl_grid_job_stage(job, NULL, stage, sizeof stage);
    /* Ambient occlusion from each point's own rays, with its stated error:
     * interpolated from the cache's gathers it missed the sharp edges of
     * occlusion (0.09 off at a plate's edge where a point's own 256 rays
     * are within 0.03; tests/solver/direct/test_ambient_occlusion.c). */
    cdl_direct_outputs outputs = {gs->ao, gs->ao_stderr, gs->Ez, gs->Esz,
                                  job->on_surface_count ? job->on_surface : NULL};
    state->direct_stats.routes = state->routes;
    double t0 = cdl_pool_now_seconds();
    st = cdl_direct_solve_grid(direct, state->strategies, &gs->grid, (size_t)job->plan->key, gs->E_direct,
                               job->var_direct, state->threads, &state->options.progress, &outputs, stage,
                               &state->direct_stats, err);
    state->direct_stats.routes = NULL;
    state->out->compute_seconds += cdl_pool_now_seconds() - t0;
    return st;
}

const cdl_integrator cdl_integrator_direct = {"direct", applies_always, run_direct};
