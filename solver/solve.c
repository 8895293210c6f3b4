/* solve.c - a solve: plan the scene, run each grid through the integrators, finish.
 *
 * The three steps are integrate/integrator.h's: cdl_solve_plan
 * (solve_plan.c) builds and checks everything first; each grid then goes
 * through the table below, each integrator adding its part where it
 * applies; cdl_solve_finish_grid and cdl_solve_finish (solve_finish.c)
 * combine the parts and say what the solve found besides its numbers. The
 * plan's JSON is narrated by plan_json.c from the counts the steps leave.
 */
#include "solver/solve_internal.h"

#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
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

/* The scene's settings with the options' overrides, checked. */
static cdl_status override_settings(const cdl_scene *scene, const cdl_solve_options *o, cdl_scene *copy,
                                    cdl_error *err)
{
    *copy = *scene;
    cdl_solver_settings *set = &copy->settings;
    if (o->method != -1) {
        if (o->method < CDL_METHOD_AUTO || o->method > CDL_METHOD_PATHTRACE)
            return cdl_error_set(err, CDL_ERR_USAGE, "solve options: expected a method (%d to %d) or -1, found %d",
                                 CDL_METHOD_AUTO, CDL_METHOD_PATHTRACE, o->method);
        set->method = (cdl_method)o->method;
    }
    if (o->quality != -1) {
        if (o->quality < CDL_QUALITY_DRAFT || o->quality > CDL_QUALITY_REFERENCE)
            return cdl_error_set(err, CDL_ERR_USAGE, "solve options: expected a quality (%d to %d) or -1, found %d",
                                 CDL_QUALITY_DRAFT, CDL_QUALITY_REFERENCE, o->quality);
        set->quality = (cdl_quality)o->quality;
        set->target_error = 0.0;
    }
    if (o->target_error != 0.0) {
        if (!(o->target_error >= CDL_TARGET_ERROR_MIN && o->target_error <= CDL_TARGET_ERROR_MAX))
            return cdl_error_set(err, CDL_ERR_USAGE,
                                 "solve options: expected a target error from %g to %g (a fraction) or 0, found %g",
                                 CDL_TARGET_ERROR_MIN, CDL_TARGET_ERROR_MAX, o->target_error);
        set->target_error = o->target_error;
    }
    return CDL_OK;
}

cdl_status cdl_solve_scene_into(const cdl_scene *scene, const cdl_solve_options *options,
                                const cdl_solve_debug *debug, cdl_solution *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = cdl_pool_now_seconds();
    cdl_solve_state state = {.options = CDL_SOLVE_OPTIONS_INIT, .debug = CDL_SOLVE_DEBUG_NONE, .out = out};
    cdl_sized_struct_read(&state.options, sizeof state.options, options);
    if (debug) state.debug = *debug;
    cdl_scene settled;
    cdl_status st = override_settings(scene, &state.options, &settled, err);
    if (st != CDL_OK) return st;
    state.scene = &settled;

    st = cdl_solve_plan(&state, err);
    for (size_t g = 0; st == CDL_OK && g < settled.grid_count; ++g) {
        cdl_grid_job job = {.index = g, .spec = &settled.grids[g], .gs = &out->grids[g], .plan = &state.grids[g]};
        st = solve_job(&state, &job, err);
    }
    if (st == CDL_OK && settled.observer_count) {
        cdl_grid_job job = {.index = settled.grid_count, .observers = 1, .direct = &state.background,
                            .spec = &state.observer_spec, .gs = &state.observer_points, .plan = &state.observer_plan};
        st = solve_job(&state, &job, err);
    }
    if (st == CDL_OK) st = cdl_solve_finish(&state, err);
    cdl_solve_state_release(&state);
    if (st != CDL_OK) {
        cdl_solution_clear(out);
        return st;
    }
    out->seconds = cdl_pool_now_seconds() - t0;
    return CDL_OK;
}

cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution **out,
                           cdl_error *err)
{
    *out = NULL;
    cdl_solution *solution = calloc(1, sizeof *solution);
    if (!solution) return cdl_error_out_of_memory(err);
    cdl_status st = cdl_solve_scene_into(scene, options, NULL, solution, err);
    if (st != CDL_OK) {
        free(solution);
        return st;
    }
    *out = solution;
    return CDL_OK;
}
