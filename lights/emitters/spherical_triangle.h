/* spherical_triangle.h - solid angle of a triangle and sampling it uniformly in solid angle.
 *
 *  - Solid angle by Van Oosterom and Strackee ("The solid angle of a plane
 *    triangle", IEEE Trans. Biomed. Eng. 30(2), 1983):
 *        tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|),
 *    positive for every non-degenerate triangle and accurate for tiny ones.
 *  - Sampling by Arvo's area-preserving map ("Stratified sampling of
 *    spherical triangles", SIGGRAPH 1995): (u1, u2) -> a direction inside
 *    the spherical triangle, uniform in solid angle (pdf 1 / Omega). The
 *    map's intermediate tangents lose relative precision for triangles of
 *    tiny solid angle; callers use it above ~1e-3 sr.
 * Positions are relative to the receiver. Pure functions: thread-safe.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_SPHERICAL_TRIANGLE_H
#define CANDELA_LIGHTS_EMITTERS_SPHERICAL_TRIANGLE_H

#include "radiometry/vec3.h"

/* Solid angle (sr) of the triangle a, b, c (relative to the receiver). */
double cdl_triangle_solid_angle(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c);

typedef struct cdl_spherical_triangle {
    cdl_vec3 A, B, C;          /* unit directions to the vertices */
    double alpha, cos_alpha, sin_alpha; /* interior angle at A */
    double cos_c;              /* A . B */
    double S;                  /* solid angle (Van Oosterom-Strackee) */
    cdl_vec3 tC;               /* unit tangent at A towards C */
} cdl_spherical_triangle;

/* Prepares the map; returns the solid angle (0 for a degenerate triangle). */
double cdl_spherical_triangle_init(cdl_spherical_triangle *t, cdl_vec3 a, cdl_vec3 b, cdl_vec3 c);

/* Unit direction for (u1, u2) in [0, 1]^2; requires S > 0. */
cdl_vec3 cdl_spherical_triangle_sample(const cdl_spherical_triangle *t, double u1, double u2);

#endif
