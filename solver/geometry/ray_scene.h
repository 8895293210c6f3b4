/* ray_scene.h - ray queries against the scene's geometry (Embree behind a C API).
 *
 * Nothing outside solver/ knows Embree exists. A cdl_ray_scene holds triangle
 * meshes and exact spheres in one Embree scene built in robust mode (no rays
 * slip through shared edges, see ../shared/DEPENDENCIES.md section 4).
 *
 * Lifecycle: create, add geometry, commit, query (thread-safe), release.
 */
#ifndef CANDELA_SOLVER_RAY_SCENE_H
#define CANDELA_SOLVER_RAY_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_ray_scene cdl_ray_scene;

typedef struct cdl_ray_hit {
    double t;          /* distance along the (unit) direction */
    uint32_t geom_id;  /* id returned when the geometry was added */
    uint32_t prim_id;  /* triangle index within it (0 for a sphere) */
    double u, v;       /* barycentrics of the hit on the triangle */
    cdl_vec3 normal;   /* geometric normal, unit length, as stored (not flipped) */
} cdl_ray_hit;

cdl_status cdl_ray_scene_create(cdl_ray_scene **out, cdl_error *err);

/* Add a triangle mesh; vertices xyz in metres, triangles as index triples.
 * Copies the data. *geom_id receives the id reported in hits. */
cdl_status cdl_ray_scene_add_triangles(cdl_ray_scene *scene, const double *xyz, size_t vertex_count,
                                       const uint32_t *triangles, size_t triangle_count, uint32_t *geom_id,
                                       cdl_error *err);

/* Add an exact sphere. */
cdl_status cdl_ray_scene_add_sphere(cdl_ray_scene *scene, cdl_vec3 center, double radius, uint32_t *geom_id,
                                    cdl_error *err);

cdl_status cdl_ray_scene_commit(cdl_ray_scene *scene, cdl_error *err);

/* Is anything hit on the open segment origin + t dir, t in (t_near, t_far)?
 * dir need not be unit length; t is in units of |dir|. Decided in double
 * (ray_scene.c): a surface whose plane (sphere) the origin, or the end
 * origin + t_far dir, lies on to within the double rounding bound (about
 * 1e-12 of the coordinates' magnitude) does not count, so rays from a point
 * on a surface, or to a point on one, need no offset. */
int cdl_ray_scene_occluded(const cdl_ray_scene *scene, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far);

/* The same, with the geometry `exclude` (an id from the add calls) left
 * out: a luminaire's shadow rays pass its own body. CDL_RAY_EXCLUDE_NONE
 * leaves out nothing. */
#define CDL_RAY_EXCLUDE_NONE UINT32_MAX
int cdl_ray_scene_occluded_except(const cdl_ray_scene *scene, cdl_vec3 origin, cdl_vec3 dir, double t_near,
                                  double t_far, uint32_t exclude);

/* A segment to test: origin + t dir, t in (t_near, t_far), geometry
 * `exclude` left out, as cdl_ray_scene_occluded_except takes them. */
typedef struct cdl_ray_segment {
    cdl_vec3 origin, dir;
    double t_near, t_far;
    uint32_t exclude;
} cdl_ray_segment;

/* Many segments at once: occluded[k] = cdl_ray_scene_occluded_except's
 * answer for rays[k], to the bit (the same float rays and the same double
 * re-test), traced in blocks as Embree ray streams (rtcOccluded1M):
 * cheaper than one by one (about 1.5 times as fast on a direct chunk's
 * shadow rays, which start near one another and head towards one light
 * after another). */
void cdl_ray_scene_occluded_many(const cdl_ray_scene *scene, const cdl_ray_segment *rays, size_t count,
                                 unsigned char *occluded);

/* Closest hit with t in (t_near, t_far), by the same double test; returns 1
 * and fills *hit (t, normal and barycentrics in double), else 0. dir must be
 * unit length. */
int cdl_ray_scene_intersect(const cdl_ray_scene *scene, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far,
                            cdl_ray_hit *hit);
int cdl_ray_scene_intersect_except(const cdl_ray_scene *scene, cdl_vec3 origin, cdl_vec3 dir, double t_near,
                                   double t_far, uint32_t exclude, cdl_ray_hit *hit);

/* Embree's float resolution near p (after commit): one single-precision ulp
 * of the largest local coordinate a query near p involves. Closer than a
 * few of these, which side of a surface p is on is beyond Embree. */
double cdl_ray_scene_resolution(const cdl_ray_scene *scene, cdl_vec3 p);

/* Number of triangles added (spheres count as none). */
size_t cdl_ray_scene_triangle_count(const cdl_ray_scene *scene);

void cdl_ray_scene_release(cdl_ray_scene *scene);

#endif
