/* bounds.h - axis-aligned bounding boxes in double precision.
 *
 * The one box type of the project: grown point by point or box by box,
 * empty until the first point (lo = +DBL_MAX, hi = -DBL_MAX, so growing by
 * any finite point gives that point). Comparisons instead of fmin/fmax:
 * the points are finite, and fmin is a library call without -ffast-math. */
#ifndef CANDELA_RADIOMETRY_BOUNDS_H
#define CANDELA_RADIOMETRY_BOUNDS_H

#include <float.h>

#include "radiometry/vec3.h"

typedef struct cdl_bounds3 {
    cdl_vec3 lo, hi;
} cdl_bounds3;

static inline cdl_bounds3 cdl_bounds3_empty(void)
{
    cdl_bounds3 b = {{DBL_MAX, DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX, -DBL_MAX}};
    return b;
}

static inline int cdl_bounds3_is_empty(cdl_bounds3 b)
{
    return !(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y && b.lo.z <= b.hi.z);
}

static inline void cdl_bounds3_grow(cdl_bounds3 *b, cdl_vec3 p)
{
    b->lo.x = p.x < b->lo.x ? p.x : b->lo.x;
    b->lo.y = p.y < b->lo.y ? p.y : b->lo.y;
    b->lo.z = p.z < b->lo.z ? p.z : b->lo.z;
    b->hi.x = p.x > b->hi.x ? p.x : b->hi.x;
    b->hi.y = p.y > b->hi.y ? p.y : b->hi.y;
    b->hi.z = p.z > b->hi.z ? p.z : b->hi.z;
}

/* b grown to contain the box o (an empty o changes nothing). */
static inline void cdl_bounds3_merge(cdl_bounds3 *b, cdl_bounds3 o)
{
    if (cdl_bounds3_is_empty(o)) return;
    cdl_bounds3_grow(b, o.lo);
    cdl_bounds3_grow(b, o.hi);
}

static inline cdl_vec3 cdl_bounds3_centre(cdl_bounds3 b)
{
    return cdl_vec3_scale(cdl_vec3_add(b.lo, b.hi), 0.5);
}

/* Length of the diagonal; 0 for an empty box. */
static inline double cdl_bounds3_diagonal(cdl_bounds3 b)
{
    return cdl_bounds3_is_empty(b) ? 0.0 : cdl_vec3_distance(b.lo, b.hi);
}

#endif
