/* environment_bounds.h - where a convex spherical polygon of directions lies
 * on an environment, and the least and greatest pixel over it (private to
 * lights/; callers use cdl_emitter_luminance_bounds in emitter.h).
 *
 * A solver that knows exactly which part of the sky a point sees (the
 * visible polygon past planar occluders) integrates the sky's luminance
 * over that part; where the luminance there is one value the answer is
 * exact, and elsewhere the spread between its least and greatest value is
 * the most any missed feature can change a sample. Both need bounds over a
 * region, which this module gives:
 *  - the region's extent in the environment's frame: the range of cos(theta)
 *    (at the vertices, at the points of the great-circle edges nearest and
 *    farthest from the zenith, 1 or -1 where the polygon holds a pole) and
 *    of azimuth (the vertices' azimuths joined edge by edge: an arc that
 *    passes no pole turns monotonically in azimuth, by less than pi);
 *  - the least and greatest pixel over the rows and columns that extent
 *    touches, widened by one pixel each way against rounding, from a
 *    pyramid of 4 x 4, 8 x 8, ... blocks' minima and maxima: blocks wholly
 *    inside the rectangle count whole, those on its edge are split into
 *    the level below, so a query reads the blocks along the rectangle's
 *    edge, not its area.
 * The bounds are conservative (they may include pixels just outside the
 * region), never too tight.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_BOUNDS_H
#define CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_BOUNDS_H

#include "lights/environment/environment_pixels.h"
#include "base/error.h"

/* The extent of a polygon in a frame (z up): cos(theta) in [cos_lo, cos_hi];
 * azimuth (atan2(y, x)) in [phi_lo, phi_lo + phi_span], or every azimuth
 * when full_azimuth. */
typedef struct cdl_env_extent {
    double cos_lo, cos_hi;
    double phi_lo, phi_span;
    int full_azimuth;
} cdl_env_extent;

/* The extent, in `frame`, of the convex spherical polygon whose unit world
 * vertex directions are dirs[0 .. count) (count >= 3, edges the shorter
 * great-circle arcs, either orientation). */
void cdl_env_extent_of_polygon(const cdl_frame *frame, const cdl_vec3 *dirs, int count, cdl_env_extent *out);

/* Block minima and maxima of an image's rows that carry light. */
typedef struct cdl_env_range {
    int levels;
    int block[16];           /* block side of each level, in pixels: 4, 8, 16, ... */
    int nx[16], ny[16];      /* blocks across and down */
    float *lo[16], *hi[16];  /* ny x nx each */
} cdl_env_range;

cdl_status cdl_env_range_build(cdl_env_range *range, const cdl_env_pixels *px, cdl_error *err);
void cdl_env_range_free(cdl_env_range *range);

/* Least and greatest luminance (cd/m^2, scale applied) over the pixels an
 * extent touches; 0 is included when the extent reaches rows that carry no
 * light (below an upper-only sky's horizon). */
void cdl_env_range_query(const cdl_env_range *range, const cdl_env_pixels *px, const cdl_env_extent *extent,
                         double *L_lo, double *L_hi);

/* The pixels an extent touches, with one of margin each way: rows j0 ..
 * j1 (of those that carry light), columns i0 .. i0 + ni - 1 modulo the
 * width; *dark when the extent reaches where the sky carries no light.
 * Returns 0 when it touches no row that carries light. */
int cdl_env_extent_pixels(const cdl_env_pixels *px, const cdl_env_extent *e, int *j0, int *j1, int *i0, int *ni,
                          int *dark);

/* The block pyramid of an image environment; NULL for any other emitter
 * (emitter_environment.c). */
const cdl_env_range *cdl_emitter_environment_range(const cdl_emitter *emitter);

#endif
