/* scene_sky.h - the emitters of a "cie" or "perez" sky and of its sun
 * (private to solver/scene; scene_lights.c adds them as lights).
 *
 * A "cie" sky: the CIE standard general sky of its type (emitter.h,
 * CDL_SKY_CIE_GENERAL) scaled by its zenith luminance or its horizontal
 * illuminance; with direct_normal_illuminance_lx > 0, a sun besides. A
 * "perez" sky: the Perez all-weather sky from the weather inputs
 * (lights/environment/perez_sky.h), scaled so that it gives the diffuse
 * horizontal illuminance, and the sun of the direct normal illuminance
 * (from the irradiance by the Perez 1990 efficacy when given in W/m^2).
 * The sun is a directional emitter with a disk of CDL_SUN_ANGULAR_DIAMETER_DEG
 * (emitter.h), where the sky's sun is; none when its illuminance is 0.
 * Both carry the maintenance factor.
 */
#ifndef CANDELA_SOLVER_SCENE_SKY_H
#define CANDELA_SOLVER_SCENE_SKY_H

#include <stddef.h>

#include "lights/emitters/emitter.h"
#include "solver/scene/scene_internal.h"

/* The sun's mean angular diameter seen from the Earth, degrees: 2 x
 * 959.63" (the IAU 2015 nominal solar radius at 1 AU), 0.5331 degrees; as
 * Radiance's gendaylit, 0.533. */
#define CDL_SUN_ANGULAR_DIAMETER_DEG 0.533

typedef struct cdl_scene_sky_emitters {
    cdl_emitter *sky;                     /* owned by the caller once built */
    cdl_emitter *sun;                     /* NULL without a sun */
    char description[768];                /* the model and what it was made from, for the plan */
} cdl_scene_sky_emitters;

/* Build the emitters of environment luminaire `sp` (sky CIE or PEREZ).
 * Errors carry no prefix (the caller adds the scene file and JSON path). */
cdl_status cdl_scene_sky_build(const cdl_luminaire_spec *sp, cdl_scene_sky_emitters *out, cdl_error *err);

#endif
