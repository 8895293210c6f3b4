/* grid.h - calculation points of a grid, and the raster used to draw them.
 *
 *   rect     nu x nv points at cell centres, origin + (i+0.5)/nu u + (j+0.5)/nv v,
 *            row-major with i fastest; normal u x v (or the given normal).
 *   polygon  the polygon (minus holes) meshed by CGAL into well-shaped
 *            triangles, one point at the centroid of each, weighted by the
 *            triangle's area; the spacing p is EN 12464-1's: about one
 *            point per p^2 of area, as a square grid of spacing p has (the
 *            mesh's edges are at most sqrt(5) p: CDL_GRID_MESH_EDGE).
 *            spacing "auto": p = 0.2 x 5^log10(d), d the longer side of the
 *            polygon's bounding rectangle in its plane (EN 12464-1:2021,
 *            4.3.3), p <= 10 m.
 *   points   the listed points and normals, in order.
 *
 * Rect and polygon grids also carry a raster (for EXR and PNG maps): each
 * pixel holds the index of the point whose value it shows, or -1 outside.
 * A rect grid's raster is nu x nv, row 0 at the v = 1 edge (top of the
 * image), column 0 at the u = 0 edge. A polygon grid's raster covers its
 * bounding rectangle in the plane (first axis along the first edge of the
 * outer ring) at p/4 per pixel (coarser when that would exceed 4096 pixels
 * on a side), each pixel taking the point of the triangle containing its
 * centre.
 *
 * Units: metres (points, pixel size, spacing), square metres (weights).
 * Ownership: cdl_grid_build fills the caller's cdl_grid with arrays it
 * allocates; cdl_grid_release frees them (a grid inside a cdl_solution is
 * freed by cdl_solution_release). Thread safety: no state; a built grid is
 * only read. Errors: cdl_grid_build fails with CDL_ERR_INPUT for a polygon
 * that cannot be meshed or too many points (message with the JSON path),
 * CDL_ERR_INTERNAL for memory; the grid is then empty.
 */
#ifndef CANDELA_SOLVER_GRID_H
#define CANDELA_SOLVER_GRID_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/scene/scene_internal.h"

typedef struct cdl_grid {
    size_t count;
    cdl_vec3 *points;
    cdl_vec3 *normals;        /* unit */
    double *weights;          /* area weights (m^2) for averages; all 1 for points grids */
    /* raster (rect and polygon grids); width = height = 0 for points grids */
    int raster_width, raster_height;
    int32_t *raster_index;    /* width x height, row-major, top row first; -1 outside */
    double pixel_size_m;      /* size of a raster pixel along the grid's first axis */
    /* Where the raster lies in the world (for axes in metres on maps):
     * raster_corner is the lower-left corner of the image (left edge of
     * column 0, bottom edge of the last row); raster_right and raster_up
     * the unit directions of increasing column and of decreasing row;
     * each pixel pixel_width_m x pixel_height_m. */
    cdl_vec3 raster_corner, raster_right, raster_up;
    double pixel_width_m, pixel_height_m;
    double spacing_m;         /* polygon: spacing used; rect: |u|/nu */
} cdl_grid;

/* The longest edge of a polygon grid's mesh, in grid spacings p. CGAL's
 * refinement with edges at most e makes about 5 triangles per e^2
 * (measured: 4.9 to 5.0 on squares from 4 m to 20 m), one point each; at
 * e = sqrt(5) p that is one point per p^2, the density of a square grid
 * of spacing p that EN 12464-1 means. */
#define CDL_GRID_MESH_EDGE 2.2360679774997897

/* EN 12464-1 grid spacing for a longest dimension d (m): 0.2 x 5^log10(d), capped at 10 m. */
double cdl_grid_auto_spacing(double longest_dimension_m);

/* Place the points of a grid as its spec says (above) into *out; free them
 * with cdl_grid_release (NULL and an empty grid are fine). */
cdl_status cdl_grid_build(const cdl_grid_spec *spec, cdl_grid *out, cdl_error *err);

struct cdl_scene_geometry;
struct cdl_occluder_index;
/* The reflectance of the surface each point of the grid lies on
 * (grid_surface.c), into rho[0 .. count) (owned by the caller).
 * CDL_ERR_INPUT, with *missing the first point on no reflecting side of any
 * surface, when there is none (the caller names the grid and the point);
 * no message is set. Thread-safe for distinct outputs. */
cdl_status cdl_grid_surface_reflectance(const cdl_grid *grid, const struct cdl_scene_geometry *geometry,
                                        const struct cdl_occluder_index *occluders, double *rho, size_t *missing);
/* Which points of the grid lie on a surface (either side; within a few of
 * Embree's float resolutions, its plane across the point's normal), as
 * on_surface[i] = 1 (else 0), into an array of grid->count owned by the
 * caller; returns how many do. There the surface hides every direction
 * behind the normal. Thread-safe for distinct outputs; no errors. */
size_t cdl_grid_surface_mask(const cdl_grid *grid, const struct cdl_scene_geometry *geometry,
                             const struct cdl_occluder_index *occluders, unsigned char *on_surface);
void cdl_grid_release(cdl_grid *grid);

#endif
