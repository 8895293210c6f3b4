/* solve_checks.h - what a solve says besides its numbers (solve_checks.c). */
#ifndef CANDELA_SOLVER_SOLVE_CHECKS_H
#define CANDELA_SOLVER_SOLVE_CHECKS_H

#include "base/error.h"
#include "solver/direct/direct.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_lights.h"
#include "solver/solution_internal.h"

/* Warnings (cdl_solution_add_warning) for every light that reaches no
 * grid point, saying why, every grid at 0 lx, and a scene without light.
 * ctx is the solve's direct context; out holds the solved grids. */
cdl_status cdl_solve_check_lights(const cdl_scene *scene, const cdl_direct_context *ctx, cdl_solution *out,
                                  cdl_error *err);

/* A warning for each luminaire entry with near_field "always" whose file
 * gives no opening that is spread (cdl_luminous_opening_is_spread): it is
 * lit as a point, which the scene did not ask for. */
cdl_status cdl_solve_check_near_field(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_solution *out,
                                      cdl_error *err);

/* Installed power: the input watts of every placed luminaire whose file
 * gives them, the others counted apart; for the whole scene (out->power)
 * and per rect or polygon grid facing up (within 30 degrees of the
 * vertical), of the luminaires over it (out->grids[g].power: their
 * position projected along the grid's normal falls within its outline, on
 * the side its points face). */
void cdl_solve_sum_power(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_solution *out);

#endif
