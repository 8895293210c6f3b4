/* projected_solid_angle.h - exact cosine-weighted solid angles of shapes.
 *
 * The projected solid angle of a shape seen from a receiver point p with
 * unit normal n is
 *     Omega_p = int over the directions w towards the shape of max(0, n.w) dw,
 * so a Lambertian emitter of luminance L, unoccluded, gives the illuminance
 * E = L Omega_p (and Omega_p / pi is the point-to-shape configuration
 * factor). The whole hemisphere gives pi.
 *
 * Every function takes positions RELATIVE to the receiver (x - p), which is
 * where the precision of near and far receivers is kept, clips the shape to
 * the receiver's hemisphere n.w >= 0, and integrates in closed form:
 *  - polygons by Lambert's contour integral (Lambert, Photometria, 1760;
 *    the form used in graphics: Arvo, "Applications of irradiance tensors to
 *    the simulation of non-Lambertian phenomena", SIGGRAPH 1995, eq. 5), the
 *    polygon first clipped to the half-space by Sutherland-Hodgman;
 *  - disks by the same contour integral along the circle, whose integrand is
 *    a ratio of trigonometric polynomials with an elementary antiderivative,
 *    plus the straight chord where the receiver's plane cuts the disk;
 *  - spheres through their silhouette: the cone of directions a sphere
 *    subtends equals that of its tangent circle's disk, so Omega_p of the
 *    sphere is Omega_p of that disk.
 * All are pure functions (thread-safe).
 */
#ifndef CANDELA_LIGHTS_EMITTERS_PROJECTED_SOLID_ANGLE_H
#define CANDELA_LIGHTS_EMITTERS_PROJECTED_SOLID_ANGLE_H

#include <stddef.h>

#include "radiometry/vec3.h"

/* A planar polygon of `count` >= 3 vertices (relative to p), counter-clockwise
 * as seen from p; clockwise gives the negated value. Non-convex polygons are
 * fine (the clipped contour may run back and forth along the receiver's
 * plane; those parts cancel). Degenerate edges through p contribute 0. */
double cdl_projected_solid_angle_polygon(const cdl_vec3 *rel, size_t count, cdl_vec3 n);

/* A disk of centre c (relative to p), unit normal m and radius R > 0 that
 * emits on the side m faces: 0 unless p is strictly on that side. */
double cdl_projected_solid_angle_disk(cdl_vec3 c, cdl_vec3 m, double R, cdl_vec3 n);

/* A sphere of centre c (relative to p) and radius R > 0 seen from outside;
 * 0 when p is on or inside the sphere. */
double cdl_projected_solid_angle_sphere(cdl_vec3 c, double R, cdl_vec3 n);

#endif
