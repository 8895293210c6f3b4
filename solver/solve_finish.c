/* solve_finish.c - the last step of a solve: each grid's parts combined, then what the solve says besides. */
#include "solver/solve_observers.h"
#include "solver/solve_plan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"
#include "solver/plan_json.h"
#include "solver/pool.h"
#include "solver/solve_cache.h"
#include "solver/solve_checks.h"

/* A light closer to a grid point than a double's range allows (1e-200 m)
 * makes I cos / d^2 infinite; a result file cannot hold that. Say which
 * point and which light, as bad input, instead of failing at writing. */
static cdl_status check_finite(const cdl_solve_state *state, const cdl_grid_job *job, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    const cdl_scene_lights *lights = &state->lights;
    const cdl_grid_spec *spec = job->spec;
    const cdl_grid_solution *gs = job->gs;
    for (size_t i = 0; i < gs->grid.count; ++i) {
        if (isfinite(gs->E[i]) && isfinite(gs->E_stderr[i])) continue;
        cdl_vec3 p = gs->grid.points[i], n = gs->grid.normals[i];
        const char *culprit = NULL;
        for (size_t l = 0; l < lights->count && !culprit; ++l) {
            cdl_illuminance E;
            if (cdl_emitter_exact_illuminance(lights->emitters[l], p, n, &E, NULL) == CDL_OK && !isfinite(E.lx))
                culprit = lights->lights[l].label;
        }
        const char *what = isfinite(gs->E[i]) ? "its standard error" : "the illuminance";
        if (culprit)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s (%s) point %zu at [%.10g, %.10g, %.10g]: expected a finite illuminance, found "
                                 "%s beyond the range of a double: %s is too close to the point (or too bright)",
                                 scene->path, spec->json_path, spec->name, i, p.x, p.y, p.z, what, culprit);
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: %s (%s) point %zu at [%.10g, %.10g, %.10g]: expected a finite illuminance, found %s "
                             "beyond the range of a double: a light is too close to the point (or too bright)",
                             scene->path, spec->json_path, spec->name, i, p.x, p.y, p.z, what);
    }
    return CDL_OK;
}

cdl_status cdl_solve_finish_grid(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_grid_solution *gs = job->gs;
    for (size_t i = 0; i < gs->grid.count; ++i) {
        /* The direct and interreflected parts are independent estimates:
         * their variances add. */
        double var = job->var_direct[i] + job->var_indirect[i];
        gs->E[i] = gs->E_direct[i] + gs->E_indirect[i];
        gs->E_stderr[i] = sqrt(var);
        /* Luminance of a Lambertian surface under illuminance E: L = rho E / pi
         * (its exitance rho E spread as pi L over the hemisphere). */
        if (gs->L) gs->L[i] = gs->rho[i] * gs->E[i] / CDL_PI;
        /* Daylight factor (daylight_factor.h): DF = 100 E / E_h. */
        if (gs->DF) gs->DF[i] = 100.0 * gs->E[i] / job->plan->daylight_E_h;
    }
    return check_finite(state, job, err);
}

/* Points where two surfaces meet, per grid. */
static cdl_status warn_edge_points(cdl_solve_state *state, cdl_error *err)
{
    cdl_solution *out = state->out;
    for (size_t g = 0; g < state->scene->grid_count; ++g) {
        const cdl_grid_solution *gs = &out->grids[g];
        if (gs->edge_point_count == 0) continue;
        cdl_vec3 q = gs->grid.points[gs->first_edge_point];
        cdl_status st = cdl_solution_add_warning(
            out, err,
            "grid '%s': %zu point%s lie%s where two surfaces meet (the first is point %zu at (%.9g, %.9g, %.9g)); a "
            "surface through a point does not say which side the point is on: each reports the limit from the side "
            "its grid is meant for (the inside of a box, the side a surface's front faces); move such points off the "
            "edge if another side is meant (summary.json: edge_points)",
            state->scene->grids[g].name, gs->edge_point_count, gs->edge_point_count == 1 ? "" : "s",
            gs->edge_point_count == 1 ? "s" : "", gs->first_edge_point, q.x, q.y, q.z);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

/* Rays and records over the whole solve. */
static void count_totals(cdl_solve_state *state)
{
    uint64_t rays = state->direct_stats.rays + state->vertical_stats.rays + state->vertical_stats.direct.rays +
                    state->glare_stats.rays;
    if (state->indirect) {
        cdl_path_stats all = state->pathtrace_stats;
        cdl_path_stats_add(&all, &state->icache_stats.paths);
        rays += all.rays + all.direct.rays;
        state->out->records = state->icache_stats.records;
    }
    state->out->rays = rays;
}

cdl_status cdl_solve_finish(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    cdl_solution *out = state->out;
    count_totals(state);
    cdl_plan_json_totals(state->plan, state);
    cdl_status st = warn_edge_points(state, err);
    if (st == CDL_OK) st = cdl_solve_check_lights(scene, &state->direct, out, err);
    if (st == CDL_OK) st = cdl_solve_check_near_field(scene, &state->lights, out, err);
    if (st != CDL_OK) return st;
    cdl_solve_sum_power(scene, &state->lights, out);
    if (state->cache.path) {
        if (!state->cache.reused) {
            st = cdl_solve_cache_save(state, err);
            if (st != CDL_OK) return st;
        }
        out->cache_reused = state->cache.reused;
    }
    return cdl_plan_json_print(state->plan, &out->plan_json, err);
}

void cdl_solve_state_release(cdl_solve_state *state)
{
    cdl_plan_json_release(state->plan);
    cdl_solve_observers_release(state);
    if (state->records)
        for (size_t g = 0; g < state->scene->grid_count; ++g) cdl_icache_records_release(&state->records[g]);
    free(state->records);
    cdl_icache_shared_release(state->shared_cache);
    free(state->grids);
    free(state->strategies);
    free(state->routes);
    cdl_solve_cache_release(&state->cache);
    cdl_scene_lights_release(&state->lights);
    cdl_occluder_index_release(state->occluders);
    cdl_sky_portals_release(&state->portals);
    cdl_scene_geometry_release(state->geometry);
    memset(state, 0, sizeof *state);
}
