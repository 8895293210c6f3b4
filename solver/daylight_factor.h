/* daylight_factor.h - the daylight factor of a grid's points: the
 * illuminance under the CIE overcast sky over that sky's illuminance on an
 * unobstructed horizontal plane, in percent (CIE 17.4-1987, 845-09-97;
 * EN 17037:2018, 3.1.9):
 *     DF = 100 E / E_h,
 * E the point's illuminance, direct and interreflected, E_h = 7 pi L_z / 9
 * for the CIE standard overcast sky of Moon and Spencer ("sky":
 * "cie_overcast") and the sky's exact horizontal illuminance for ISO
 * 15469's type 1 ("sky": "cie", "cie_type": 1, its overcast sky of steep
 * gradation), the sky's maintenance factor in both. DF is a ratio of the
 * sky's own light: a grid may ask for it only where that sky is the scene's
 * one light (no luminaire, no sun, no emitting surface). Its stated error
 * is E_stderr_lx scaled the same way (100 E_stderr / E_h).
 */
#ifndef CANDELA_SOLVER_DAYLIGHT_FACTOR_H
#define CANDELA_SOLVER_DAYLIGHT_FACTOR_H

#include <stddef.h>

#include "base/error.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_lights.h"

/* For grid `spec` asking for "daylight_factor": E_h (lx) and the sky in
 * words ("luminaires[0], the CIE standard overcast sky (Moon and Spencer),
 * E_h = 7 pi L_z / 9 = 15393.8 lx"). CDL_ERR_INPUT naming the file, the
 * grid's outputs and the light that is not that sky, otherwise. */
cdl_status cdl_daylight_factor_reference(const cdl_scene *scene, const cdl_scene_lights *lights,
                                         const cdl_grid_spec *spec, double *E_h, char *words, size_t size,
                                         cdl_error *err);

#endif
