/* scene_geometry.h - a loaded scene turned into triangles, spheres and rays.
 *
 * Every surface (and every area luminaire's shape and every goniometric
 * luminaire's body, which also block light: scene_bodies.h) becomes
 * triangles (polygons with holes by CGAL's constrained Delaunay
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

#include "lights/emitters/emitter.h"
#include "base/error.h"
#include "radiometry/glass.h"
#include "lights/photometry/luminaire_body.h"
#include "solver/geometry/ray_scene.h"
#include "solver/scene/scene_internal.h"

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
    double transmittance;                /* > 0: a pane of glass (its normal transmittance); 0: opaque */
    cdl_glass glass;                     /* the pane, when transmittance > 0 */
    int is_body;                         /* the body of luminaire source_index (scene_bodies.h); is_luminaire 1 */
    int curved;                          /* triangles standing in for a curved surface (a body's cylinder, disk
                                          * or ellipsoid): no exact route past it */
} cdl_geometry_piece;

/* Does a piece stand for a curved surface, which the exact routes leave to
 * sampling (a disk, or a curved body)? Spheres the occluder index reports
 * apart. */
static inline int cdl_geometry_piece_is_curved(const cdl_geometry_piece *piece)
{
    return piece->shape.kind == CDL_SHAPE_DISK || piece->curved;
}

/* Fan segments of a disk: the sagitta of each chord, r (1 - cos(pi / N)),
 * must stay below 1e-4 r; N = 224 gives 9.8e-5 r (N >= 223 is needed), a
 * multiple of 8 so the fan is symmetric about the frame's axes. */
#define CDL_DISK_SEGMENTS 224

/* The corners of a box's face (CDL_BOX_*), counter-clockwise seen from its
 * front (outside, or inside for an inward box), as the ray scene has them:
 * the faces share their corners bit for bit. */
void cdl_box_face_corners(const cdl_surface_spec *box, int face, cdl_vec3 corners[4]);

/* The rim vertex k (0 <= k < CDL_DISK_SEGMENTS) of a disk's fan, counter-
 * clockwise about its (unit) normal, as the ray scene has it. */
cdl_vec3 cdl_disk_rim_point(cdl_vec3 center, cdl_vec3 normal, double radius, uint32_t k);

cdl_status cdl_scene_geometry_build(const cdl_scene *scene, cdl_scene_geometry **out, cdl_error *err);
void cdl_scene_geometry_release(cdl_scene_geometry *geometry);

const cdl_ray_scene *cdl_scene_geometry_rays(const cdl_scene_geometry *geometry);
size_t cdl_scene_geometry_piece_count(const cdl_scene_geometry *geometry);
/* The body piece of luminaire k of the scene (scene_bodies.h), UINT32_MAX
 * when it has none. */
uint32_t cdl_scene_geometry_luminaire_body(const cdl_scene_geometry *geometry, size_t k);

/* The body of luminaire k as its file describes it (kind CDL_BODY_NONE when
 * it has none), for the plan. */
const cdl_luminaire_body *cdl_scene_geometry_luminaire_body_shape(const cdl_scene_geometry *geometry, size_t k);

/* Piece for a ray-scene geom id (as reported in cdl_ray_hit). */
const cdl_geometry_piece *cdl_scene_geometry_piece(const cdl_scene_geometry *geometry, size_t geom_id);
size_t cdl_scene_geometry_triangle_count(const cdl_scene_geometry *geometry);

/* Axis-aligned bounds of all geometry and its diagonal (0 for an empty scene). */
void cdl_scene_geometry_bounds(const cdl_scene_geometry *geometry, cdl_vec3 *lo, cdl_vec3 *hi);
double cdl_scene_geometry_extent(const cdl_scene_geometry *geometry);

/* The same of the surfaces and area luminaires alone, the luminaires'
 * bodies left out (they go where their luminaires go, which may be wrong:
 * empty bounds, lo > hi, when there are none). */
void cdl_scene_geometry_surface_bounds(const cdl_scene_geometry *geometry, cdl_vec3 *lo, cdl_vec3 *hi);

/* The triangles of a piece as placed in the ray scene (counter-clockwise
 * seen from the front; for disks the inscribed fan). Returns the triangle
 * count (0 for spheres, with NULL arrays). Valid while the geometry lives. */
size_t cdl_scene_geometry_piece_triangles(const cdl_scene_geometry *geometry, size_t geom_id, const double **xyz,
                                          size_t *vertex_count, const uint32_t **triangles);

/* Rays at every scale. Rays start at the point itself and end at their
 * target: the ray scene re-tests Embree's hits in double (ray_scene.c), so
 * the surface a point lies on, and the one a shadow ray's end lies on, never
 * count, whatever the scene's size, while any surface off the point by more
 * than the double rounding bound does. What is left for callers is that
 * bound (for exact region tests near a point), given here for the hot loops
 * that build rays themselves. */
typedef struct cdl_ray_offsets {
    double magnitude;         /* largest coordinate magnitude of the geometry, m */
    double rounding;          /* 2^-40: the relative rounding bound */
} cdl_ray_offsets;

void cdl_scene_geometry_ray_offsets(const cdl_scene_geometry *geometry, cdl_ray_offsets *offsets);

/* epsilon(p) = 2^-40 x max(magnitude, |p|_inf): a bound, with a margin of
 * about a hundred, on the rounding of any double computed from the scene's
 * coordinates and p (a few ulps, 2^-52 each): 1e-9 m in a 1 km scene,
 * 1e-7 m at 1e5 m from the origin. */
static inline double cdl_ray_offsets_epsilon(const cdl_ray_offsets *o, cdl_vec3 p)
{
    double m = fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z)));
    return o->rounding * fmax(o->magnitude, m);
}

/* The shadow segment of cdl_scene_geometry_shadow_ray (documented there). */
static inline int cdl_ray_offsets_shadow_ray(const cdl_ray_offsets *o, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                             double distance, cdl_vec3 *origin, double *t_near, double *t_far)
{
    (void)o;
    (void)n;
    (void)dir;
    if (!(distance > 0.0)) return 0;
    *origin = p;
    *t_near = 0.0;
    *t_far = distance;
    return 1;
}

double cdl_scene_geometry_ray_epsilon(const cdl_scene_geometry *geometry, cdl_vec3 p);

/* Embree's float resolution near p (cdl_ray_scene_resolution): closer than
 * a few of these to a surface, which side of it p is on is beyond Embree. */
double cdl_scene_geometry_resolution(const cdl_scene_geometry *geometry, cdl_vec3 p);

/* Ray queries (all thread-safe). p may lie on a surface (a floor grid at
 * z = 0, a hit point): that surface never blocks p's rays, in any
 * direction, grazing ones included. n is the normal of p's surface (or of
 * the receiving plane), kept for callers; the queries no longer need it.
 *
 * ray_occluded: anything on p + t dir (dir unit), t in (0, distance)?
 * distance may be INFINITY (directional light, environment, AO).
 * segment_occluded: anything strictly between p and q? A surface either
 * lies on does not count (an area-light sample on its emitter).
 * intersect: the first hit along dir (unit) up to t_max; hit->t is the
 * distance from p. */

/* The segment ray_occluded tests, for callers that query or record it
 * themselves: origin, and t in (t_near, t_far) along dir. Returns 0 when
 * the segment is empty (distance not positive). */
int cdl_scene_geometry_shadow_ray(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                  double distance, cdl_vec3 *origin, double *t_near, double *t_far);
int cdl_scene_geometry_ray_occluded(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                    double distance);
int cdl_scene_geometry_segment_occluded(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 p_normal, cdl_vec3 q,
                                        cdl_vec3 q_normal);
int cdl_scene_geometry_intersect(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                                 double t_max, cdl_ray_hit *hit);

/* Glass ("transmittance" surfaces): 1 when the scene has a pane. */
int cdl_scene_geometry_has_glass(const cdl_scene_geometry *geometry);

/* What reaches p along -dir from `distance` away (INFINITY: from the sky):
 * the product of the transmittances of the panes crossed, each at its
 * angle of incidence (radiometry/glass.h), 0 when an opaque surface is in
 * the way. Without glass, 0 or 1 as ray_occluded says. Panes are found one
 * after another (the ray restarted at each, where it cannot hit that pane
 * again); at most CDL_GLASS_MAX_PANES, beyond which the ray counts as
 * blocked. */
#define CDL_GLASS_MAX_PANES 64
double cdl_scene_geometry_transmission(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 dir, double distance);

/* The same towards a light, past the light's own piece `exclude` (its
 * emitting surface or its body: cdl_scene_light_own_piece; UINT32_MAX:
 * none), which never blocks its own light. */
double cdl_scene_geometry_transmission_except(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 dir,
                                              double distance, uint32_t exclude);

#endif
