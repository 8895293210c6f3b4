/* integrate_vertical.c - the sampled part of cylindrical and semicylindrical illuminance.
 *
 * The direct integrator gives the vertical outputs' exact part (point,
 * spot, goniometric and directional lights); extended emitters, skies and
 * interreflected light are sampled here to the target, with a stated error
 * (transport/vertical_sampled.h).
 */
#include "solver/integrate/integrator.h"
#include "solver/pool.h"

static int applies_vertical(const cdl_solve_state *state, const cdl_grid_job *job)
{
    (void)state;
    return job->gs->Ez_stderr || job->gs->Esz_stderr;
}

static cdl_status run_vertical(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_grid_solution *gs = job->gs;
    char stage[160];
    cdl_grid_job_stage(job, "cylindrical illuminance", stage, sizeof stage);
    cdl_path_stats before = state->vertical_stats;
    cdl_workers workers = cdl_solve_workers(state, job->everywhere);
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_vertical_sampled_grid(&state->vertical, &gs->grid, (size_t)job->plan->key,
                                              job->on_surface_count ? job->on_surface : NULL, gs->Ez, gs->Esz,
                                              gs->Ez_stderr, gs->Esz_stderr, &workers, stage,
                                              &state->vertical_stats, err);
    state->out->compute_seconds += cdl_pool_now_seconds() - t0;
    job->vertical_rays = state->vertical_stats.rays - before.rays + state->vertical_stats.direct.rays -
                         before.direct.rays;
    return st;
}

const cdl_integrator cdl_integrator_vertical = {"vertical", applies_vertical, run_vertical};
