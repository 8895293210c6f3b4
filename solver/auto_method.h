/* auto_method.h - which method computes a grid's interreflection under "auto".
 *
 * A grid takes the irradiance cache when its point count times the target
 * relative error is at least CDL_AUTO_CACHE_SCORE, else path tracing. Why
 * a product: path tracing costs points / t^2; the cache costs records / t^2
 * (each record gathered to about a point's variance), and its records,
 * spaced in proportion to sqrt t (icache.c), number about 1 / t over a
 * grid's area, so the ratio goes as points t. Measured at equal RMS error
 * on the downlight room, the office and the closed cube (docs/tuning.md),
 * the crossing lies near points t = 0.3 to 0.4.
 *
 * Not public.
 */
#ifndef CANDELA_SOLVER_AUTO_METHOD_H
#define CANDELA_SOLVER_AUTO_METHOD_H

#include <stddef.h>

#include "solver/scene/scene_internal.h"

#define CDL_AUTO_CACHE_SCORE 0.4

/* The method (ICACHE or PATHTRACE) that computes the interreflection of a
 * grid of `points` points for the scene's `method`, and in *score the
 * points times the target that chose it under "auto". */
static inline cdl_method cdl_auto_grid_method(cdl_method method, size_t points, double target, double *score)
{
    *score = (double)points * target;
    if (method == CDL_METHOD_ICACHE || method == CDL_METHOD_PATHTRACE) return method;
    return *score >= CDL_AUTO_CACHE_SCORE ? CDL_METHOD_ICACHE : CDL_METHOD_PATHTRACE;
}

#endif
