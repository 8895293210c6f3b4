/* octahedral.h - the octahedral map between unit directions and the unit square.
 *
 * A direction d is projected onto the octahedron |x| + |y| + |z| = 1; the
 * upper half (z >= 0) unfolds onto the diamond |x| + |y| <= 1 and the lower
 * half folds outwards over the square's four corners (Praun and Hoppe,
 * "Spherical parametrization and remeshing", SIGGRAPH 2003; Cigolle et al.,
 * "A survey of efficient representations for independent unit vectors",
 * JCGT 3(2), 2014). The map is continuous over the sphere and needs no
 * trigonometry; the solid angle per unit of the square goes as 1 / |p|^3
 * for p on the octahedron, so its cells' solid angles differ by at most
 * 3^(3/2) = 5.2, and a table on a regular grid of the square tabulates the
 * sphere nearly evenly. Points of the square's edge mirrored
 * about an edge's midpoint name the same direction.
 */
#ifndef CANDELA_RADIOMETRY_OCTAHEDRAL_H
#define CANDELA_RADIOMETRY_OCTAHEDRAL_H

#include <math.h>

#include "radiometry/vec3.h"

/* -1 for negative x, else 1 (a comparison; copysign would give -1 for -0). */
static inline double cdl_octahedral_sign(double x)
{
    return x < 0.0 ? -1.0 : 1.0;
}

/* (u, v) in [0, 1]^2 of a direction d (any length > 0). */
static inline void cdl_octahedral_encode(cdl_vec3 d, double *u, double *v)
{
    double k = 1.0 / (fabs(d.x) + fabs(d.y) + fabs(d.z));
    double x = d.x * k, y = d.y * k;
    if (d.z < 0.0) {
        double fx = (1.0 - fabs(y)) * cdl_octahedral_sign(x), fy = (1.0 - fabs(x)) * cdl_octahedral_sign(y);
        x = fx;
        y = fy;
    }
    *u = 0.5 * (x + 1.0);
    *v = 0.5 * (y + 1.0);
}

/* The unit direction of (u, v) in [0, 1]^2. */
static inline cdl_vec3 cdl_octahedral_decode(double u, double v)
{
    double x = 2.0 * u - 1.0, y = 2.0 * v - 1.0;
    double z = 1.0 - fabs(x) - fabs(y);
    if (z < 0.0) {
        double fx = (1.0 - fabs(y)) * cdl_octahedral_sign(x), fy = (1.0 - fabs(x)) * cdl_octahedral_sign(y);
        x = fx;
        y = fy;
    }
    return cdl_vec3_normalize(cdl_vec3_make(x, y, z));
}

#endif
