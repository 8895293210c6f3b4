/* occluder_index.h - "can anything be in the way?", answered exactly.
 *
 * The direct solver models only what a scene needs: no shadow rays between a
 * luminaire and a grid when no surface lies between them, and the exact
 * (closed-form) illuminance of an area emitter when nothing hides any part of
 * it. Both questions are "does any surface intersect this convex region?",
 * where the region is an intersection of half-spaces: the box around a light
 * and a grid, the pyramid from a receiver point to an emitter polygon, the
 * wedge of sky above a receiver.
 *
 * The index is a bounding-volume hierarchy, in double precision, over the
 * scene's triangles and spheres. A triangle intersects the region when
 * clipping it by every half-space (Sutherland-Hodgman) leaves something; a
 * sphere when it is not entirely outside any half-space (conservative: it may
 * report a sphere that only nears an edge, which costs sampling, never
 * accuracy). Every half-space is shrunk by a tolerance first, so surfaces
 * that merely touch the region - the floor a grid point lies on, the ceiling
 * an emitter is set into - do not count.
 */
#ifndef CANDELA_SOLVER_OCCLUDER_INDEX_H
#define CANDELA_SOLVER_OCCLUDER_INDEX_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_occluder_index cdl_occluder_index;

/* A closed half-space {x : normal . x <= offset}. */
typedef struct cdl_halfspace {
    cdl_vec3 normal;
    double offset;
} cdl_halfspace;

#define CDL_REGION_MAX_PLANES 40

/* A convex region: the intersection of its half-spaces. */
typedef struct cdl_convex_region {
    cdl_halfspace planes[CDL_REGION_MAX_PLANES];
    int plane_count;
} cdl_convex_region;

/* Build from triangles (xyz per vertex, index triples) and spheres, each
 * primitive tagged with an owner id (the geometry piece it belongs to). */
typedef struct cdl_occluder_input {
    const double *vertices;
    const uint32_t *triangles;
    const uint32_t *triangle_owner;
    size_t triangle_count;
    const double *sphere_centers;     /* xyz */
    const double *sphere_radii;
    const uint32_t *sphere_owner;
    size_t sphere_count;
} cdl_occluder_input;

cdl_status cdl_occluder_index_build(const cdl_occluder_input *input, cdl_occluder_index **out, cdl_error *err);
void cdl_occluder_index_release(cdl_occluder_index *index);

/* 1 if some primitive, other than those owned by `exclude_owner` (pass
 * UINT32_MAX to exclude nothing), intersects the region shrunk by `tolerance`. */
int cdl_occluder_index_intersects(const cdl_occluder_index *index, const cdl_convex_region *region, double tolerance,
                                  uint32_t exclude_owner);

/* 1 if the surface of some primitive meets the box [lo, hi] (a sphere by
 * its surface, not its ball, unlike the region test above). */
int cdl_occluder_index_surface_in_box(const cdl_occluder_index *index, cdl_vec3 lo, cdl_vec3 hi);

/* The triangles that intersect a region (as cdl_occluder_index_intersects
 * decides), for exact visibility: up to `max` of them into out[], their
 * number in *count. LISTED: that is every primitive in the region;
 * TOO_MANY: there are more than `max` triangles (the list is cut short);
 * SPHERE: a sphere may be in the region (no polygon describes it). */
typedef struct cdl_occluder_triangle {
    double v[9];                      /* xyz of its three corners */
    uint32_t owner;
} cdl_occluder_triangle;

typedef enum cdl_occluder_list_status {
    CDL_OCCLUDERS_LISTED,
    CDL_OCCLUDERS_TOO_MANY,
    CDL_OCCLUDERS_SPHERE
} cdl_occluder_list_status;

cdl_occluder_list_status cdl_occluder_index_list(const cdl_occluder_index *index, const cdl_convex_region *region,
                                                 double tolerance, uint32_t exclude_owner,
                                                 cdl_occluder_triangle *out, size_t max, size_t *count);

/* Each primitive whose surface meets the box [lo, hi], handed to `visit`:
 * a triangle as its 9 corner coordinates (counter-clockwise seen from its
 * front, as built), a sphere as cx cy cz r; owner as given at build. Returns
 * how many were visited. */
typedef void (*cdl_occluder_visit)(void *user, const double *primitive, int is_sphere, uint32_t owner);
int cdl_occluder_index_visit_box(const cdl_occluder_index *index, cdl_vec3 lo, cdl_vec3 hi, cdl_occluder_visit visit,
                                 void *user);

size_t cdl_occluder_index_primitive_count(const cdl_occluder_index *index);

/* ---- building regions ------------------------------------------------------ */

/* Axis-aligned box [lo, hi]. */
void cdl_region_box(cdl_convex_region *region, cdl_vec3 lo, cdl_vec3 hi);

/* The pyramid from apex p to a convex planar polygon (vertices in order,
 * either orientation): every segment from p to a point of the polygon lies
 * inside. Returns 0 (region unusable) if p lies in the polygon's plane or the
 * polygon has more than CDL_REGION_MAX_PLANES - 1 edges. Plane 0 is the
 * polygon's plane; planes 1 to count are the sides, through the apex. */
int cdl_region_pyramid(cdl_convex_region *region, cdl_vec3 apex, const cdl_vec3 *polygon, int count);

/* The region swept by segments from p to the part of a sphere visible from
 * p (a circumscribed pyramid of the tangent cone, capped at the sphere's
 * centre plane); if p is inside the sphere, the sphere's bounding box (6
 * planes). Otherwise planes 0 to CDL_REGION_SPHERE_SIDES - 1 are the sides,
 * through the apex, and the last plane is the cap. */
#define CDL_REGION_SPHERE_SIDES 16
void cdl_region_sphere_view(cdl_convex_region *region, cdl_vec3 apex, cdl_vec3 center, double radius);

/* Append a half-space {x : normal . x <= offset}; returns 0 if full. */
int cdl_region_add(cdl_convex_region *region, cdl_vec3 normal, double offset);

#endif
