/* plan_json.h - the plan of a solve as JSON: what was modelled and why, in words.
 *
 * The thin layer over the solve's state (integrate/integrator.h): the
 * planning step, the integrators and the finish step decide and count; this
 * narrates their decisions and counts as summary.json's "plan" object
 * (DESIGN.md). It computes nothing a result depends on.
 *
 * Not public. Errors: CDL_ERR_INTERNAL when out of memory.
 */
#ifndef CANDELA_SOLVER_PLAN_JSON_H
#define CANDELA_SOLVER_PLAN_JSON_H

#include "base/error.h"
#include "solver/integrate/integrator.h"

typedef struct cdl_plan_json cdl_plan_json;

/* A plan with the method and whether (and why) interreflection is modelled. */
cdl_status cdl_plan_json_create(const cdl_solve_state *state, cdl_plan_json **out, cdl_error *err);

/* Each light's entry, and what the scene has (environment, geometry). */
cdl_status cdl_plan_json_lights(cdl_plan_json *plan, const cdl_solve_state *state, cdl_error *err);

/* One grid: each light's strategy and routes, its interreflection method
 * and counts, its vertical outputs. */
void cdl_plan_json_grid(cdl_plan_json *plan, const cdl_solve_state *state, const cdl_grid_job *job);

/* The surface maps: their meshes' counts and how their light was found. */
void cdl_plan_json_surfaces(cdl_plan_json *plan, const cdl_solve_state *state);
/* A grid's daylight factor, in words (daylight_factor.h), under
 * "daylight_factor": {GRID: WORDS}. */
void cdl_plan_json_daylight_factor(cdl_plan_json *plan, const char *grid, const char *words);

/* The totals after every grid: evaluations, interreflection, the cache file. */
void cdl_plan_json_totals(cdl_plan_json *plan, const cdl_solve_state *state);

/* The plan as JSON text (unformatted), the caller's to free(). */
cdl_status cdl_plan_json_print(const cdl_plan_json *plan, char **out, cdl_error *err);

void cdl_plan_json_release(cdl_plan_json *plan);

#endif
