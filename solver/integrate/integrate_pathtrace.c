/* integrate_pathtrace.c - the path-tracing integrator: a grid's interreflected light, point by point.
 *
 * Paths from every point of the grid, each point sampled until E = E_direct
 * + E_indirect meets the target (pathtrace/pathtrace.h): the unbiased
 * reference.
 */
#include "solver/integrate/integrator.h"
#include "solver/pool.h"

static int applies_pathtrace(const cdl_solve_state *state, const cdl_grid_job *job)
{
    return state->indirect && job->plan->method == CDL_METHOD_PATHTRACE;
}

static cdl_status run_pathtrace(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_grid_solution *gs = job->gs;
    char stage[160];
    cdl_grid_job_stage(job, "interreflection (paths)", stage, sizeof stage);
    uint64_t before = state->pathtrace_stats.paths;
    cdl_workers workers = cdl_solve_workers(state, job->everywhere);
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_pathtrace_solve_grid(&state->pathtrace, &gs->grid, (size_t)job->plan->key, gs->E_direct,
                                             job->var_direct, gs->E_indirect, job->var_indirect, &workers, stage,
                                             &job->convergence, &state->pathtrace_stats, err);
    state->out->compute_seconds += cdl_pool_now_seconds() - t0;
    job->paths = state->pathtrace_stats.paths - before;
    return st;
}

const cdl_integrator cdl_integrator_pathtrace = {"pathtrace", applies_pathtrace, run_pathtrace};
