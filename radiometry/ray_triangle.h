/* ray_triangle.h - where a ray meets a triangle, in double precision.
 *
 * The triangle v0, v0 + e1, v0 + e2; the ray p + t w, t > 0 (w need not be
 * unit length: t is in units of |w|). Moller and Trumbore, "Fast, minimum
 * storage ray-triangle intersection", JGT 2(1), 1997: the barycentrics
 * (b1, b2) and t solve p + t w = v0 + b1 e1 + b2 e2 by Cramer's rule with
 * the scalar triple products of the edges. Used where a few triangles are
 * tested exactly, away from the ray scene (an area emitter's mesh, the
 * panes of a sky's portals). Thread safety: pure. */
#ifndef CANDELA_RADIOMETRY_RAY_TRIANGLE_H
#define CANDELA_RADIOMETRY_RAY_TRIANGLE_H

#include "radiometry/vec3.h"

/* t of the hit, or -1 when the ray misses the triangle (or lies in its plane). */
static inline double cdl_ray_triangle_distance(cdl_vec3 v0, cdl_vec3 e1, cdl_vec3 e2, cdl_vec3 p, cdl_vec3 w)
{
    cdl_vec3 pv = cdl_vec3_cross(w, e2);
    double det = cdl_vec3_dot(e1, pv);
    if (det == 0.0) return -1.0;
    cdl_vec3 s = cdl_vec3_sub(p, v0);
    double b1 = cdl_vec3_dot(s, pv) / det;
    if (b1 < 0.0 || b1 > 1.0) return -1.0;
    cdl_vec3 qv = cdl_vec3_cross(s, e1);
    double b2 = cdl_vec3_dot(w, qv) / det;
    if (b2 < 0.0 || b1 + b2 > 1.0) return -1.0;
    double dist = cdl_vec3_dot(e2, qv) / det;
    return dist > 0.0 ? dist : -1.0;
}

#endif
