/* scene_geometry.h - a loaded scene turned into triangles, spheres and rays.
 *
 * Every surface (and every area luminaire's shape, which also blocks light)
 * becomes triangles (polygons with holes by CGAL's constrained Delaunay
 * triangulation; boxes as up to six rects; disks as fans fine enough for
 * ray casting) or an exact sphere, all in one Embree scene built in robust
 * mode. Each piece keeps a link to the surface or luminaire it came from,
 * its material and, for emitting surfaces, an emitter shape the lights
 * layer can use for exact formulas (rects and disks stay analytic).
 */
#ifndef CANDELA_SOLVER_SCENE_GEOMETRY_H
#define CANDELA_SOLVER_SCENE_GEOMETRY_H

#include <stddef.h>
#include <math.h>
#include <stdint.h>

#include "lights/emitter.h"
#include "radiometry/error.h"
#include "solver/geometry/ray_scene.h"
#include "solver/scene/scene.h"

typedef struct cdl_scene_geometry cdl_scene_geometry;

/* One piece of geometry as placed in the ray scene (one per ray-scene geom id). */
typedef struct cdl_geometry_piece {
    int is_luminaire;                    /* 0: from surfaces[], 1: from luminaires[] (area;
                                          * reflectance from the luminaire, default 0; two_sided 1) */
    size_t source_index;                 /* index into scene->surfaces or scene->luminaires */
    int box_face;                        /* CDL_BOX_* for boxes, -1 otherwise */
    double reflectance;
    int two_sided;
    double luminance_cd_m2;              /* > 0: the front emits (Lambertian). Area luminaires: the
                                          * luminance they emit, maintenance factor included and
                                          * flux_lm converted by flux = pi L area, so an emitter made
                                          * from `shape` and this value is the luminaire. */
    cdl_shape shape;                     /* world-space shape; TRIANGLES arrays owned by the geometry */
    size_t triangle_count;               /* 0 for spheres */
    double area;                         /* m^2 */
} cdl_geometry_piece;

cdl_status cdl_scene_geometry_build(const cdl_scene *scene, cdl_scene_geometry **out, cdl_error *err);
void cdl_scene_geometry_release(cdl_scene_geometry *geometry);

const cdl_ray_scene *cdl_scene_geometry_rays(const cdl_scene_geometry *geometry);
size_t cdl_scene_geometry_piece_count(const cdl_scene_geometry *geometry);
/* Piece for a ray-scene geom id (as reported in cdl_ray_hit). */
const cdl_geometry_piece *cdl_scene_geometry_piece(const cdl_scene_geometry *geometry, size_t geom_id);
size_t cdl_scene_geometry_triangle_count(const cdl_scene_geometry *geometry);

/* Axis-aligned bounds of all geometry and its diagonal (0 for an empty scene). */
void cdl_scene_geometry_bounds(const cdl_scene_geometry *geometry, cdl_vec3 *lo, cdl_vec3 *hi);
double cdl_scene_geometry_extent(const cdl_scene_geometry *geometry);

/* The triangles of a piece as placed in the ray scene (counter-clockwise
 * seen from the front; for disks the inscribed fan). Returns the triangle
 * count (0 for spheres, with NULL arrays). Valid while the geometry lives. */
size_t cdl_scene_geometry_piece_triangles(const cdl_scene_geometry *geometry, size_t geom_id, const double **xyz,
                                          size_t *vertex_count, const uint32_t **triangles);

/* The ray offsets of a scene, for callers that build many rays themselves
 * (the direct solver's hot loop): the functions below are these, inlined. */
typedef struct cdl_ray_offsets {
    cdl_vec3 centre;          /* bounding-box centre (where the ray scene works) */
    double extent_term;       /* 1e-5 x extent */
    double float_fraction;    /* 2^-16 */
} cdl_ray_offsets;

void cdl_scene_geometry_ray_offsets(const cdl_scene_geometry *geometry, cdl_ray_offsets *offsets);

/* epsilon(p) = extent_term + float_fraction x |p - centre|_inf */
static inline double cdl_ray_offsets_epsilon(const cdl_ray_offsets *o, cdl_vec3 p)
{
    double ax = fabs(p.x - o->centre.x), ay = fabs(p.y - o->centre.y), az = fabs(p.z - o->centre.z);
    double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az); /* p finite: no NaN to guard */
    return o->extent_term + o->float_fraction * m;
}

/* The shadow segment of cdl_scene_geometry_shadow_ray (documented there). */
static inline int cdl_ray_offsets_shadow_ray(const cdl_ray_offsets *o, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                             double distance, cdl_vec3 *origin, double *t_near, double *t_far)
{
    double eps = cdl_ray_offsets_epsilon(o, p);
    double far = INFINITY;
    if (isfinite(distance)) {
        /* The origin moves up to eps; the far point q is known to the float
         * precision of its own coordinates, which 4 epsilons there cover;
         * |q - c| <= |p - c| + distance bounds epsilon(q) by eps + 2^-16 distance. */
        double eps_far = eps + o->float_fraction * distance;
        far = distance - eps - 4.0 * eps_far;
    }
    if (!(far > eps)) return 0;
    /* off the surface p may lie on, to the side the ray goes */
    double side = cdl_vec3_dot(n, dir);
    *origin = side == 0.0 ? p : cdl_vec3_madd(p, side > 0.0 ? eps : -eps, n);
    *t_near = eps;
    *t_far = far;
    return 1;
}

/* Ray epsilon that works at every scale: a small fraction of the scene
 * extent plus the float resolution at the magnitude of p (measured from the
 * centre of the bounds, where the ray scene works): 1e-5 x extent +
 * 2^-16 x |p - centre|_inf. Shadow and secondary rays start at t = epsilon
 * and stop epsilon short of their end. Alone, that leaves grazing rays from
 * points on tilted or curved surfaces hitting their own surface; the
 * queries below also move the origin off the surface and handle that. */
double cdl_scene_geometry_ray_epsilon(const cdl_scene_geometry *geometry, cdl_vec3 p);

/* Ray queries that apply the epsilon for the caller (all thread-safe).
 *
 * A point p lying on a surface (a floor grid at z = 0, a hit point) with
 * that surface's normal n starts its rays from p moved epsilon along n, to
 * the side the ray goes (ray_origin; n may be the zero vector: no move).
 * Then every direction of the hemisphere n faces, grazing ones included,
 * leaves the surface without hitting it. Rays also ignore hits closer than
 * epsilon and stop epsilon short of their end.
 *
 * ray_occluded: anything on p + t dir (dir unit), t in (0, distance)?
 * distance may be INFINITY (directional light, environment, AO).
 * segment_occluded: anything between p and q? Each end may carry the normal
 * of the surface it lies on (an area-light sample), or the zero vector.
 * intersect: the first hit along dir (unit) up to t_max; hit->t is the
 * distance from p. */
cdl_vec3 cdl_scene_geometry_ray_origin(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 toward);

/* The segment ray_occluded tests, for callers that query or record it
 * themselves: origin, and t in (t_near, t_far) along dir. The far end stops
 * short of `distance` by the origin's move plus 4 epsilons at the far point,
 * so a ray aimed at a point on a surface (a sample on an area emitter, a
 * luminaire set into a ceiling) never reports that surface. Returns 0 when
 * the segment is too short to hold anything. */
int cdl_scene_geometry_shadow_ray(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                  double distance, cdl_vec3 *origin, double *t_near, double *t_far);
int cdl_scene_geometry_ray_occluded(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                    double distance);
int cdl_scene_geometry_segment_occluded(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 p_normal, cdl_vec3 q,
                                        cdl_vec3 q_normal);
int cdl_scene_geometry_intersect(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                 double t_max, cdl_ray_hit *hit);

#endif
