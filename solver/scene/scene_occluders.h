/* scene_occluders.h - the scene's geometry as an exact occluder index.
 *
 * Every piece of the scene geometry enters the index (geometry/
 * occluder_index.h) tagged with its piece id: triangles as placed in the
 * ray scene, rects as two triangles, spheres exactly, and disks as their
 * circumscribed 32-gon, a superset, so an occluder is never missed. */
#ifndef CANDELA_SOLVER_SCENE_OCCLUDERS_H
#define CANDELA_SOLVER_SCENE_OCCLUDERS_H

#include "base/error.h"
#include "solver/geometry/occluder_index.h"
#include "solver/scene/scene_geometry.h"

cdl_status cdl_scene_occluders_build(const cdl_scene_geometry *geometry, cdl_occluder_index **out, cdl_error *err);

#endif
