/* ellipse_segment.h - illuminance from part of a Lambertian ellipse, for
 * tests of partly hidden flat openings (lights and solver). */
#ifndef CANDELA_TESTS_ELLIPSE_SEGMENT_H
#define CANDELA_TESTS_ELLIPSE_SEGMENT_H

#include <math.h>

#include "radiometry/constants.h"

/* The integral of 1 / (a^2 + u^2)^2 du from u0 to u1 (a > 0): with
 * F(u) = u / (2 a^2 (a^2 + u^2)) + atan(u / a) / (2 a^3), F(u1) - F(u0). */
static inline double inverse_square_squared(double a, double u0, double u1)
{
    double a2 = a * a;
    double F1 = u1 / (2.0 * a2 * (a2 + u1 * u1)) + atan(u1 / a) / (2.0 * a2 * a);
    double F0 = u0 / (2.0 * a2 * (a2 + u0 * u0)) + atan(u0 / a) / (2.0 * a2 * a);
    return F1 - F0;
}

/* E at (px, py, 0), normal +z, from the part x <= cut of a horizontal
 * Lambertian ellipse of semi-axes (ra along x, rb along y) and luminance L
 * at height h: E = L int h^2 / r^4 dA (cos theta_o = cos theta_r = h / r).
 * x = ra cos(t), t from acos(cut / ra) to pi, the y integral in closed form
 * (above) between -rb sin(t) and rb sin(t); the midpoint rule in t on
 * 20000 steps (the integrand is smooth in t: 80000 steps moved it by at
 * most 5.4e-10 relative at the tests' probes). */
static inline double ellipse_segment_E(double L, double ra, double rb, double h, double px, double py, double cut)
{
    double t0 = cut >= ra ? 0.0 : acos(fmax(-1.0, cut / ra)), sum = 0.0;
    int steps = 20000;
    double dt = (CDL_PI - t0) / steps;
    for (int i = 0; i < steps; ++i) {
        double t = t0 + (i + 0.5) * dt, x = ra * cos(t), half = rb * sin(t);
        double a = sqrt((x - px) * (x - px) + h * h);
        sum += inverse_square_squared(a, -half - py, half - py) * ra * sin(t);
    }
    return L * h * h * sum * dt;
}

#endif
