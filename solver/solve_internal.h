/* solve_internal.h - what the library's own tools and tests may ask of a solve beyond solve.h (not public). */
#ifndef CANDELA_SOLVER_SOLVE_INTERNAL_H
#define CANDELA_SOLVER_SOLVE_INTERNAL_H

#include "base/error.h"
#include "solver/scene/scene_internal.h"
#include "solver/solution_internal.h"
#include "solver/solve.h"
#include "solver/solve_debug.h"
#include "solver/solve_plan.h"

/* cdl_solve_scene into a solution the caller holds (on its stack; freed
 * with cdl_solution_clear), with the debug knobs (NULL: none). On failure
 * *out is left empty. */
cdl_status cdl_solve_scene_into(const cdl_scene *scene, const cdl_solve_options *options,
                                const cdl_solve_debug *debug, cdl_solution *out, cdl_error *err);

#endif
