/* scene_lights.h - the scene's luminaires and emitting surfaces as emitters.
 *
 * Every luminaire of the scene becomes one emitter; every emitting surface
 * piece (a surface with luminance_cd_m2, each box face separately) becomes an
 * area emitter on its geometry. Photometric files and environment images
 * are read here; their errors are prefixed with the scene file and JSON path.
 * Conversions done once, at creation:
 *   point   flux_lm -> I = Phi / (4 pi)
 *   spot    flux_lm -> I0 = Phi / (flux of the same spot at 1 cd)
 *   area    flux_lm -> L = Phi / (pi A)
 *   all     x maintenance_factor (goniometric: also multiplier, file factors)
 */
#ifndef CANDELA_SOLVER_SCENE_LIGHTS_H
#define CANDELA_SOLVER_SCENE_LIGHTS_H

#include <stddef.h>

#include "lights/emitter.h"
#include "lights/photometry.h"
#include "solver/direct/direct.h"
#include "solver/scene/scene.h"
#include "solver/scene/scene_geometry.h"

typedef struct cdl_scene_lights {
    cdl_direct_light *lights;       /* one per emitter, in scene order: luminaires, then emitting surfaces */
    const char **kinds;             /* "point", "area", ... per light */
    cdl_emitter **emitters;
    size_t count;
    cdl_photometry **photometries;  /* owned, one per goniometric luminaire (NULL otherwise) */
    size_t photometry_count;
    int has_environment;
} cdl_scene_lights;

cdl_status cdl_scene_lights_build(const cdl_scene *scene, const cdl_scene_geometry *geometry, cdl_scene_lights *out,
                                  cdl_error *err);
void cdl_scene_lights_release(cdl_scene_lights *lights);

#endif
