/* sphere_factor.h - the configuration factor of a sphere to a tilted
 * differential element, for tests of spherical sources (lights and solver). */
#ifndef CANDELA_TESTS_SPHERE_FACTOR_H
#define CANDELA_TESTS_SPHERE_FACTOR_H

#include <math.h>

#include "radiometry/constants.h"

/* Configuration factor from a differential element to a sphere of radius
 * r whose centre lies at distance d along a direction making angle theta
 * with the element's normal (Howell, A Catalog of Radiation Heat Transfer
 * Configuration Factors: a differential planar element tilted towards a
 * sphere; test_emitter_solid holds it to 1e-4 by sampling): H = d / r,
 * X = sqrt(H^2 - 1), Y = -X cot(theta);
 *   theta <= acos(1 / H)          F = cos(theta) / H^2
 *   up to pi/2 + asin(1 / H)      F = (cos(theta) acos(Y) - X sin(theta)
 *                                 sqrt(1 - Y^2)) / (pi H^2)
 *                                 + atan(sin(theta) sqrt(1 - Y^2) / X) / pi
 *   beyond                        F = 0. */
static inline double sphere_factor(double r, double d, double theta)
{
    double H = d / r, X = sqrt(H * H - 1.0);
    if (theta <= acos(1.0 / H)) return cos(theta) / (H * H);
    if (theta >= 0.5 * CDL_PI + asin(1.0 / H)) return 0.0;
    double Y = -X / tan(theta), s = sqrt(fmax(0.0, 1.0 - Y * Y));
    return (cos(theta) * acos(Y) - X * sin(theta) * s) / (CDL_PI * H * H) + atan(sin(theta) * s / X) / CDL_PI;
}

#endif
