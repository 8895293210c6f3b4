/* scene_hash.h - what a scene's light transport depends on, as three hashes.
 *
 * A cache of computed light (the irradiance cache's file, icache_file.h)
 * must know when the scene it was made for has changed, and say how. The
 * scene's loaded content is hashed (content_hash.h), never its JSON text,
 * so whitespace, key order and names do not count; what does:
 *   geometry   every surface's kind and shape (rect, polygon and holes,
 *              box and its open faces, disk, sphere, inward, mesh vertices
 *              and triangles, read from their files);
 *   materials  reflectances (surfaces, box faces, area luminaires) and
 *              two-sidedness;
 *   lights     every luminaire (kind, placement, intensity or flux, profile,
 *              multiplier, maintenance factor, area shape, environment, a daylight
 *              sky's model, sun and scaling inputs, the sun disk's
 *              diameter) with
 *              the bytes of its photometric file or environment image and
 *              any TILT table its photometric file brought, and every
 *              emitting surface's luminance.
 * Order counts (the n-th light keys its own random numbers). Grids and
 * solver settings are not part of these hashes: the cache keeps them apart
 * (a grid's records depend only on its own points, see icache_file.h).
 */
#ifndef CANDELA_SOLVER_SCENE_HASH_H
#define CANDELA_SOLVER_SCENE_HASH_H

#include <stdint.h>

#include "base/error.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_lights.h"

typedef struct cdl_scene_hashes {
    uint64_t geometry, materials, lights;
} cdl_scene_hashes;

/* The hashes of `scene`, whose lights are `lights` (built by
 * cdl_scene_lights_build: the TILT tables come from there). Reads the
 * luminaires' files again; a file that cannot be read is CDL_ERR_INPUT
 * naming it. */
cdl_status cdl_scene_hash(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_scene_hashes *out,
                          cdl_error *err);

#endif
