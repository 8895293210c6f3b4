/* surface_hit.h - the surface a ray meets, as light transport sees it.
 *
 * Both interreflection methods (the irradiance cache and the path tracer)
 * follow rays from a point into the scene and need, where a ray lands: the
 * point, the normal on the side the ray came from, and how much that side
 * reflects. Surfaces reflect diffusely (Lambertian) with their reflectance
 * rho on the front (the side their normal faces: u x v for rects, counter-
 * clockwise triangles seen from the front, inside of inward boxes and
 * spheres) and, when two-sided (the default), on the back too; the back of
 * a one-sided surface absorbs everything (it still blocks light). Emission
 * is not reported: light sources enter the transport only through the
 * direct module, at every point where light is gathered (next-event
 * estimation), so no light is counted twice.
 */
#ifndef CANDELA_SOLVER_SURFACE_HIT_H
#define CANDELA_SOLVER_SURFACE_HIT_H

#include <stdint.h>

#include "radiometry/vec3.h"
#include "solver/scene/scene_geometry.h"

typedef struct cdl_surface_hit {
    cdl_vec3 p;               /* where the ray landed, m */
    cdl_vec3 n;               /* unit normal on the side the ray came from (n . dir < 0) */
    double distance;          /* from the ray's start, m */
    uint32_t piece;           /* the geometry piece (scene_geometry.h) */
    int front;                /* 1: the front side was hit */
    double reflectance;       /* of the side hit, [0, 1] */
    double transmission;      /* the product of the transmittances of the panes of glass the ray passed
                               * through on its way (1 without glass) */
} cdl_surface_hit;

/* Follow the ray from p (lying on a surface of unit normal p_normal, or the
 * zero vector when p is in free space) along unit `dir`; returns 0 when it
 * leaves the scene. Panes of glass ("transmittance") are passed through,
 * their transmittance at the ray's angle multiplied into hit->transmission
 * (the ray goes on undeviated: a thin pane's two faces refract it back);
 * the hit is the first surface that is not glass, or none after
 * CDL_GLASS_MAX_PANES panes. On 0, hit->transmission alone is set: what
 * the panes on the way out let through to the sky (0 after too many). */
int cdl_transport_trace(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 p_normal, cdl_vec3 dir,
                        cdl_surface_hit *hit);

/* The front normal of a piece at one of its points: for triangle pieces the
 * normal of triangle `prim` (from its double-precision corners), for
 * spheres the outward radius, inward for inward spheres. */
cdl_vec3 cdl_transport_front_normal(const cdl_scene_geometry *geometry, uint32_t piece, uint32_t prim, cdl_vec3 p);

#endif
