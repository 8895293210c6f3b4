/* contour.h - isolux lines of a grid's values by marching squares.
 *
 * The values sit at the centres of a raster's pixels (grid.h: rect grids
 * one point per pixel; polygon grids the point each pixel shows), pixel
 * (c, r) at x = c + 0.5, y = r + 0.5 in raster units (x right, y down).
 * Each square of four neighbouring centres, all inside the grid, is cut
 * where the level crosses its edges, the crossing placed by linear
 * interpolation along the edge (Lorensen and Cline 1987 in two dimensions,
 * "marching squares"); a saddle (opposite corners on the same side) is
 * resolved by the mean of the four corners. So a line lies where the
 * bilinear-on-edges interpolant of the grid equals the level: off the true
 * isoline by at most the interpolation error of the grid's spacing.
 *
 * Levels: a 1-2-5 step of lux giving 3 to 8 round values strictly between
 * the grid's minimum and maximum. Thread safety: no state.
 */
#ifndef CANDELA_REPORT_CONTOUR_H
#define CANDELA_REPORT_CONTOUR_H

#include <stddef.h>

#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_contour_segment {
    double x0, y0, x1, y1;   /* raster units */
} cdl_contour_segment;

/* The segments where values equal `level`. values: width x height, row
 * major, top row first, NaN outside the grid. *segments is the caller's
 * to free (NULL when *count = 0). CDL_ERR_INTERNAL for memory. */
cdl_status cdl_contour_trace(const double *values, int width, int height, double level,
                             cdl_contour_segment **segments, size_t *count, cdl_error *err);

struct cdl_grid;
/* The same over a grid's raster (grid.h) with one value per point (E,
 * grid->count values): each pixel takes its point's value (rect grids: one
 * pixel a point), or on a polygon grid's finer raster the inverse distance
 * weighted mean of the points within one spacing (contour.c); pixels
 * outside the grid none. */
cdl_status cdl_contour_trace_grid(const struct cdl_grid *grid, const double *E, double level,
                                  cdl_contour_segment **segments, size_t *count, cdl_error *err);

/* The world point at raster position (x, y) (x right, y down, in pixels)
 * on the grid's plane. */
cdl_vec3 cdl_contour_world_position(const struct cdl_grid *grid, double x, double y);

/* Round levels between lo and hi (exclusive) into levels[0 .. return). */
size_t cdl_contour_levels(double lo, double hi, double *levels, size_t max_levels);

#endif
