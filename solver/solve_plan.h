/* solve_plan.h - the first and last steps of a solve: plan, then finish (solve.c runs the integrators between).
 *
 * Not public.
 */
#ifndef CANDELA_SOLVER_SOLVE_PLAN_H
#define CANDELA_SOLVER_SOLVE_PLAN_H

#include "base/error.h"
#include "solver/integrate/integrator.h"
#include "solver/scene/scene_internal.h"

/* Does light reflect anywhere? The JSON path of the first surface (or area
 * luminaire) with a reflectance above 0, its reflectance in *rho; NULL
 * when nothing reflects (then only direct light is computed). */
const char *cdl_solve_first_reflector(const cdl_scene *scene, double *rho);

/* Plan a solve whose state holds the scene, the options and the (zeroed)
 * solution (solve_plan.c): the method, the settings, the scene's geometry
 * and lights, the methods' contexts, every grid built and checked with its
 * plan, the cache file matched. On failure the state holds what was built
 * (cdl_solve_state_release frees it). */
cdl_status cdl_solve_plan(cdl_solve_state *state, cdl_error *err);

/* One grid after its integrators (solve_finish.c): E = E_direct +
 * E_indirect, E_stderr from the two variances, the luminance where asked;
 * a value a double cannot hold is refused, naming the point and the light. */
cdl_status cdl_solve_finish_grid(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err);

/* After every grid (solve_finish.c): the totals, the warnings, installed
 * power, the cache file written, the plan's JSON into the solution. */
cdl_status cdl_solve_finish(cdl_solve_state *state, cdl_error *err);

/* Free what the state owns (not the scene, the options or the solution). */
void cdl_solve_state_release(cdl_solve_state *state);

#endif
