/* solve.c - a solve: plan the scene, run each grid through the integrators, finish.
 *
 * The three steps are integrate/integrator.h's: cdl_solve_plan
 * (solve_plan.c) builds and checks everything first; each grid then goes
 * through the table below, each integrator adding its part where it
 * applies; cdl_solve_finish_grid and cdl_solve_finish (solve_finish.c)
 * combine the parts and say what the solve found besides its numbers. The
 * plan's JSON is narrated by plan_json.c from the counts the steps leave.
 */
#include "solver/solve.h"

#include <stdlib.h>
#include <string.h>

#include "solver/integrate/integrator.h"
#include "solver/plan_json.h"
#include "solver/pool.h"
#include "solver/solve_plan.h"

/* The integrators, in the order each grid goes through them: direct light
 * first (the others take its values and variances), then interreflection
 * by the cache or by paths, then the sampled part of the vertical outputs. */
static const cdl_integrator *const integrators[] = {
    &cdl_integrator_direct,
    &cdl_integrator_icache,
    &cdl_integrator_pathtrace,
    &cdl_integrator_vertical,
    &cdl_integrator_glare,
};

/* One job through the table: a grid (then its parts combined) or the
 * observers (their glare, from the background's light at the eyes). */
static cdl_status solve_job(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    size_t n = job->gs->grid.count ? job->gs->grid.count : 1;
    job->var_direct = calloc(n, sizeof *job->var_direct);
    job->var_indirect = calloc(n, sizeof *job->var_indirect);
    cdl_status st = job->var_direct && job->var_indirect ? CDL_OK : cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < sizeof integrators / sizeof *integrators; ++k)
        if (integrators[k]->applies(state, job)) st = integrators[k]->run(state, job, err);
    if (st == CDL_OK && !job->observers) {
        cdl_plan_json_grid(state->plan, state, job);
        st = cdl_solve_finish_grid(state, job, err);
    }
    free(job->var_direct);
    free(job->var_indirect);
    free(job->on_surface);
    return st;
}

cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution *out,
                           cdl_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = cdl_pool_now_seconds();
    cdl_solve_state state = {.scene = scene, .options = CDL_SOLVE_OPTIONS_DEFAULT, .out = out};
    if (options) state.options = *options;

    cdl_status st = cdl_solve_plan(&state, err);
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) {
        cdl_grid_job job = {.index = g, .spec = &scene->grids[g], .gs = &state.out->grids[g], .plan = &state.grids[g]};
        st = solve_job(&state, &job, err);
    }
    if (st == CDL_OK && scene->observer_count) {
        cdl_grid_job job = {.index = scene->grid_count, .observers = 1, .direct = &state.background,
                            .spec = &state.observer_spec, .gs = &state.observer_points, .plan = &state.observer_plan};
        st = solve_job(&state, &job, err);
    }
    if (st == CDL_OK) st = cdl_solve_finish(&state, err);
    cdl_solve_state_release(&state);
    if (st != CDL_OK) {
        cdl_solution_release(out);
        return st;
    }
    out->seconds = cdl_pool_now_seconds() - t0;
    return CDL_OK;
}
