/* spherical_rectangle.h - sampling a rectangle uniformly in solid angle.
 *
 * The area-preserving map of Urena, Fajardo and King, "An Area-Preserving
 * Parametrization for Spherical Rectangles", Computer Graphics Forum 32(4),
 * 2013: (u, v) in [0,1)^2 -> a point on the rectangle whose direction from
 * the receiver is uniformly distributed over the rectangle's solid angle S,
 * so the pdf in solid angle is exactly 1 / S. Near a large emitter this
 * keeps the variance of L cos / pdf bounded by the cosine alone, where
 * uniform area sampling grows like (size / distance)^2.
 *
 * The rectangle's interior angles are taken with atan2 (not acos), so S
 * keeps ~15 digits absolutely; callers use the map only when S is not tiny
 * (there area sampling is just as good and S's relative precision drops).
 * Pure functions: thread-safe.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_SPHERICAL_RECTANGLE_H
#define CANDELA_LIGHTS_EMITTERS_SPHERICAL_RECTANGLE_H

#include "radiometry/vec3.h"

typedef struct cdl_spherical_rectangle {
    cdl_vec3 o;                 /* receiver */
    cdl_vec3 x, y, z;           /* local frame: x along ex, y along ey, z = x cross y or its opposite */
    double x0, x1, y0, y1, z0;  /* the rectangle [x0,x1] x [y0,y1] at height z0 < 0 in that frame */
    double b0, b1, k;           /* constants of the map */
    double S;                   /* solid angle (sr) */
} cdl_spherical_rectangle;

/* Prepares the map for receiver p and the rectangle s0 + s ex + t ey
 * (s, t in [0,1]; ex and ey orthogonal, non-zero). Returns the solid angle
 * S, 0 when p lies in the rectangle's plane. */
double cdl_spherical_rectangle_init(cdl_spherical_rectangle *r, cdl_vec3 p, cdl_vec3 s0, cdl_vec3 ex, cdl_vec3 ey);

/* The sampled point for (u, v) in [0, 1]^2, RELATIVE to the receiver
 * (x - p: no cancellation however far p is from the origin); requires S > 0. */
cdl_vec3 cdl_spherical_rectangle_sample(const cdl_spherical_rectangle *r, double u, double v);

#endif
