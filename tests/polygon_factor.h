/* polygon_factor.h - illuminance from a Lambertian polygon, for tests of
 * extended sources (lights and solver). */
#ifndef CANDELA_TESTS_POLYGON_FACTOR_H
#define CANDELA_TESTS_POLYGON_FACTOR_H

#include <math.h>

#include "radiometry/vec3.h"

/* Illuminance at p (normal n) from a Lambertian convex polygon of
 * luminance L lying wholly in front of p's plane, by Lambert's contour
 * integral (Siegel and Howell, Thermal Radiation Heat Transfer, the
 * polygon-to-element factor): E = (L / 2) |sum_i beta_i n.u_i|. */
static inline double lambert_polygon(const cdl_vec3 *v, int count, double L, cdl_vec3 p, cdl_vec3 n)
{
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        cdl_vec3 a = cdl_vec3_sub(v[i], p), b = cdl_vec3_sub(v[(i + 1) % count], p), x = cdl_vec3_cross(a, b);
        double lx = cdl_vec3_length(x);
        if (lx > 0.0) sum += atan2(lx, cdl_vec3_dot(a, b)) * cdl_vec3_dot(n, x) / lx;
    }
    return 0.5 * L * fabs(sum);
}

/* E at p (normal n, facing the box so that every face it sees is in front
 * of it) from a box of half sides h about c, axis-aligned, every luminous
 * part of luminance L: Lambert's factor of each face p lies beyond, a side
 * face (C0 +x, C90 +y, C180 -x, C270 -y) luminous from the bottom up to
 * its tops[] (z relative to c; h[2] for all of it). */
static inline double lambert_box(cdl_vec3 c, const double h[3], const double tops[4], double L, cdl_vec3 p,
                                 cdl_vec3 n)
{
    cdl_vec3 at = cdl_vec3_sub(p, c);
    double q[3] = {at.x, at.y, at.z}, E = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2) {
            if (q[axis] * side <= h[axis]) continue; /* p behind this face's plane */
            int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            double top = axis == 2 ? h[2] : tops[axis == 0 ? (side > 0 ? 0 : 2) : (side > 0 ? 1 : 3)];
            cdl_vec3 v[4];
            for (int m = 0; m < 4; ++m) {
                double w[3];
                w[axis] = side * h[axis];
                w[a1] = (m == 1 || m == 2) ? (a1 == 2 ? top : h[a1]) : -h[a1];
                w[a2] = m >= 2 ? (a2 == 2 ? top : h[a2]) : -h[a2];
                v[m] = cdl_vec3_add(c, cdl_vec3_make(w[0], w[1], w[2]));
            }
            E += lambert_polygon(v, 4, L, p, n);
        }
    return E;
}

#endif
