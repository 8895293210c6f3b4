/* solve_sealed.h - lights that cannot reach anything the solve evaluates.
 *
 * A closed box (all six faces present, none of them glass) is opaque from
 * either side: no ray crosses it. When every point the solve evaluates (the
 * grids' points, the observers' eyes, the mapped surfaces' vertices) lies
 * inside one such box, looking into it, a light wholly outside it (a sky, the
 * sun, parallel light, or a bounded emitter clear of the box) cannot reach any
 * of them, directly or by any number of reflections: every path from the
 * light to a point would cross the box. Such a light is left out of the solve
 * (cdl_scene_light.sealed_by names the box), so that a closed room under a
 * sky costs nothing for the sky and its answer, exactly 0, carries no error,
 * where sampling would spend the solver's whole budget on directions that are
 * all dark. */
#ifndef CANDELA_SOLVER_SOLVE_SEALED_H
#define CANDELA_SOLVER_SOLVE_SEALED_H

#include "solver/integrate/integrator.h"

/* Mark the lights the scene's closed boxes seal out (state->lights), once
 * the grids are built (state->out->grids) and before the observers' copies
 * of the lights are made. (The solve's checks name them in a warning.) */
void cdl_solve_seal_lights(cdl_solve_state *state);

#endif
