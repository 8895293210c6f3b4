/* integrate_icache.c - the irradiance-cache integrator: a grid's interreflected light from records.
 *
 * Records are gathered at some of the grid's points and interpolated at
 * all of them (icache/icache.h), or, when the solve's cache file was made
 * for this scene, read from it and only interpolated. With surface maps
 * the grid is served by the solve's one cache, whose records the maps'
 * points placed first (integrate_surfaces.c). (Ambient occlusion is each
 * point's own: integrate_direct.c.)
 */
#include "solver/integrate/integrator.h"
#include "solver/pool.h"

static int applies_icache(const cdl_solve_state *state, const cdl_grid_job *job)
{
    return state->indirect && job->plan->method == CDL_METHOD_ICACHE;
}

static cdl_status run_icache(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_grid_solution *gs = job->gs;
    cdl_icache_records *records = &state->records[job->index];
    char stage[160];
    cdl_grid_job_stage(job, "interreflection (records)", stage, sizeof stage);
    cdl_icache_stats before = state->icache_stats;
    size_t preloaded = records->count;
    double t0 = cdl_pool_now_seconds();
    cdl_status st;
    if (state->shared_cache) {
        /* With surface maps: the solve's one cache, records on the maps included. */
        cdl_icache_target target = {.points = &gs->grid,
                                    .key = (size_t)job->plan->key,
                                    .E_direct = gs->E_direct,
                                    .var_direct = job->var_direct,
                                    .E_indirect = gs->E_indirect,
                                    .var_indirect = job->var_indirect,
                                    .threads = state->threads,
                                    .progress = &state->options.progress,
                                    .stage = stage,
                                    .stats = &state->icache_stats};
        st = cdl_icache_solve_shared(&state->icache, state->shared_cache, &target, err);
    } else {
        st = cdl_icache_solve_grid(&state->icache, &gs->grid, (size_t)job->plan->key, gs->E_direct, job->var_direct,
                                   gs->E_indirect, job->var_indirect, records, state->threads,
                                   &state->options.progress, stage, &state->icache_stats, err);
    }
    state->out->compute_seconds += cdl_pool_now_seconds() - t0;
    state->out->records_gathered += records->count - preloaded;
    job->records = state->icache_stats.records - before.records;
    job->passes = state->icache_stats.passes;
    job->alone = state->icache_stats.alone - before.alone;
    return st;
}

const cdl_integrator cdl_integrator_icache = {"icache", applies_icache, run_icache};
