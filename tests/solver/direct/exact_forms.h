/* exact_forms.h - closed forms of the direct-light test scenes, computed
 * independently of the solver's exact route: the parallel-rectangle
 * configuration factor (Hottel; Howell's catalogue, case B-3) for openings
 * above a point, and Lambert's contour integral of one rectangle. */
#ifndef CANDELA_TESTS_EXACT_FORMS_H
#define CANDELA_TESTS_EXACT_FORMS_H

#include <math.h>

#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "radiometry/vec3.h"

/* Configuration factor from a point to the rectangle [0, a] x [0, b] in a
 * parallel plane at height h, the point below the corner (0, 0). Odd in a
 * and in b, so the factor of [x1, x2] x [y1, y2] (offsets from the foot of
 * the point) is the signed sum over the four corners. */
static inline double cf_corner(double a, double b, double h)
{
    double A = a / h, B = b / h;
    return (A / sqrt(1 + A * A) * atan(B / sqrt(1 + A * A)) + B / sqrt(1 + B * B) * atan(A / sqrt(1 + B * B))) /
           (2.0 * CDL_PI);
}

static inline double cf_parallel_rect(double x1, double x2, double y1, double y2, double h)
{
    return cf_corner(x2, y2, h) - cf_corner(x1, y2, h) - cf_corner(x2, y1, h) + cf_corner(x1, y1, h);
}

/* Lambert's projected solid angle of the rectangle origin + s u + t v from p. */
static inline double psa_rect(cdl_vec3 p, cdl_vec3 n, cdl_vec3 origin, cdl_vec3 u, cdl_vec3 v)
{
    cdl_vec3 c[4] = {cdl_vec3_sub(origin, p), cdl_vec3_sub(cdl_vec3_add(origin, u), p),
                     cdl_vec3_sub(cdl_vec3_add(cdl_vec3_add(origin, u), v), p), cdl_vec3_sub(cdl_vec3_add(origin, v), p)};
    return fabs(cdl_projected_solid_angle_polygon(c, 4, n));
}

/* The window room of data/daylight/window_room.json: a uniform 5000 cd/m2
 * sky seen through a 2 x 1.2 m window at x = 5 (sill 0.9 m), L Omega_p. */
static inline double window_room_exact(cdl_vec3 p, cdl_vec3 n)
{
    return 5000.0 * psa_rect(p, n, cdl_vec3_make(5, 1, 0.9), cdl_vec3_make(0, 2, 0), cdl_vec3_make(0, 0, 1.2));
}

#endif
