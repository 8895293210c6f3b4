/* solve.c - a solve: plan the scene, run each grid through the integrators, finish.
 *
 * The three steps are integrate/integrator.h's: cdl_solve_plan
 * (solve_plan.c) builds and checks everything first; the solve-wide
 * integrators run once (the surface maps); each grid then goes through the
 * table below, each integrator adding its part where it
 * applies; cdl_solve_finish_grid and cdl_solve_finish (solve_finish.c)
 * combine the parts and say what the solve found besides its numbers. The
 * plan's JSON is narrated by plan_json.c from the counts the steps leave.
 *
 * Shared by ranks (solve_ranks.h), every rank plans the whole scene and
 * goes through the same steps; the integrators' worker tasks split the
 * points among the ranks (pool.h: cdl_pool_run_shared). A grid's results
 * are kept by the rank that computed them until the grid's integrators are
 * done, then gathered to rank 0 (solve_ranks.c), which alone finishes the
 * grids and the solve; after each step that can fail the ranks agree on
 * how it went, so that a failure anywhere ends every rank.
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
#include "solver/solve_ranks_internal.h"

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

/* The integrators that run once, before the grids: the surface maps first,
 * so that the grids share the cache records placed on them. */
static const cdl_solve_integrator *const solve_integrators[] = {
    &cdl_integrator_surfaces,
};

cdl_workers cdl_solve_workers(const cdl_solve_state *state, int everywhere)
{
    cdl_workers w = {.threads = state->threads, .progress = &state->options.progress, .ranks = state->ranks,
                     .everywhere = everywhere};
    return w;
}

int cdl_grid_job_direct_everywhere(const cdl_solve_state *state, const cdl_grid_job *job)
{
    return job->everywhere || (state->indirect && job->plan->method == CDL_METHOD_ICACHE);
}

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
    /* The parts the ranks kept go to rank 0, which finishes the grid. */
    if (st == CDL_OK && !job->everywhere) st = cdl_solve_ranks_collect_job(state, job, err);
    if (st == CDL_OK) {
        cdl_status finished = CDL_OK;
        if (!job->observers && cdl_rank_group_rank(state->ranks) == 0) {
            cdl_plan_json_grid(state->plan, state, job);
            finished = cdl_solve_finish_grid(state, job, err);
        }
        st = cdl_rank_agree(state->ranks, finished, err);
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

/* The integrators, the grids and the observers, after planning. */
static cdl_status integrate(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    cdl_solution *out = state->out;
    cdl_status st = CDL_OK;
    for (size_t k = 0; st == CDL_OK && k < sizeof solve_integrators / sizeof *solve_integrators; ++k)
        if (solve_integrators[k]->applies(state)) st = solve_integrators[k]->run(state, err);
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) {
        cdl_grid_job job = {.index = g, .spec = &scene->grids[g], .gs = &out->grids[g], .plan = &state->grids[g]};
        st = solve_job(state, &job, err);
    }
    if (st == CDL_OK && scene->observer_count) {
        /* Glare rates every observer on every rank: their light goes everywhere. */
        cdl_grid_job job = {.index = scene->grid_count, .observers = 1, .everywhere = 1, .direct = &state->background,
                            .spec = &state->observer_spec, .gs = &state->observer_points,
                            .plan = &state->observer_plan};
        st = solve_job(state, &job, err);
    }
    return st;
}

cdl_status cdl_solve_scene_shared(const cdl_scene *scene, const cdl_solve_options *options,
                                  const cdl_solve_debug *debug, cdl_rank_group *ranks, cdl_solution *out,
                                  cdl_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = cdl_pool_now_seconds(), cpu0 = cdl_pool_cpu_seconds();
    cdl_solve_state state = {.options = CDL_SOLVE_OPTIONS_INIT, .debug = CDL_SOLVE_DEBUG_NONE, .out = out,
                             .ranks = ranks};
    cdl_sized_struct_read(&state.options, sizeof state.options, options);
    if (debug) state.debug = *debug;
    int root = cdl_rank_group_rank(ranks) == 0;
    /* Progress is rank 0's to report (and its cancel every rank's). */
    if (!root) state.options.progress.fn = NULL;
    cdl_scene settled;
    cdl_status st = cdl_rank_agree(ranks, override_settings(scene, &state.options, &settled, err), err);
    if (st != CDL_OK) return st;
    state.scene = &settled;

    /* A file one rank cannot read fails the plan there: every rank stops. */
    st = cdl_rank_agree(ranks, cdl_solve_plan(&state, err), err);
    if (st == CDL_OK) st = cdl_solve_ranks_check_scene(&state, err);
    if (st == CDL_OK) st = integrate(&state, err);
    if (st == CDL_OK) st = cdl_rank_agree(ranks, root ? cdl_solve_finish(&state, err) : CDL_OK, err);
    if (st == CDL_OK) st = cdl_solve_ranks_report(&state, t0, cpu0, err);
    cdl_solve_state_release(&state);
    if (st != CDL_OK || !root) {
        cdl_solution_clear(out);
        return st;
    }
    out->seconds = cdl_pool_now_seconds() - t0;
    return CDL_OK;
}

cdl_status cdl_solve_scene_into(const cdl_scene *scene, const cdl_solve_options *options,
                                const cdl_solve_debug *debug, cdl_solution *out, cdl_error *err)
{
    cdl_rank_group alone;
    cdl_status st = cdl_rank_group_init(&alone, NULL, err);
    if (st != CDL_OK) return st;
    return cdl_solve_scene_shared(scene, options, debug, &alone, out, err);
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
