/* ring3.h - a ring of points in space: a polygon's outline or one of its
 * holes, as the scene file gives them (metres, world frame, in order;
 * counter-clockwise seen from the front for an outline). Checking and
 * triangulating rings is polygon.h's; this header holds only the type, so
 * that the public scene.h does not carry the geometry machinery.
 *
 * Ownership: a ring owns nothing by itself; whoever fills it says who frees
 * `points` (a loaded cdl_scene owns its rings' points and frees them with
 * cdl_scene_release). Thread safety: a plain type; no functions.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_RING3_H
#define CANDELA_SOLVER_GEOMETRY_RING3_H

#include <stddef.h>

#include "radiometry/vec3.h"

/* A ring of points (a polygon's outline or one of its holes), in order. */
typedef struct cdl_ring3 {
    cdl_vec3 *points;
    size_t count;
} cdl_ring3;

#endif
