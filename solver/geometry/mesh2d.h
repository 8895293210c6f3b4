/* mesh2d.h - triangulation of planar polygons with holes (CGAL behind a C API).
 *
 * Used to turn `polygon` surfaces into triangles (constrained Delaunay
 * triangulation, no new vertices) and to mesh `polygon` calculation grids
 * into well-shaped triangles no longer than a target edge (Delaunay
 * refinement, Ruppert/Shewchuk style, CGAL 2D Conforming Meshes).
 *
 * Coordinates are 2D (the caller projects the polygon into its plane). The
 * outer ring and the holes may be given in either orientation; a hole must
 * lie inside the outer ring. Which triangles are inside is decided by the
 * parity of constrained edges crossed from the unbounded face, so nested
 * rings alternate between solid and hole.
 */
#ifndef CANDELA_SOLVER_MESH2D_H
#define CANDELA_SOLVER_MESH2D_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cdl_ring2d {
    const double *xy;  /* x0 y0 x1 y1 ... */
    size_t count;      /* number of points, >= 3; the ring closes itself */
} cdl_ring2d;

typedef struct cdl_mesh2d {
    double *xy;           /* vertex_count x 2 */
    size_t vertex_count;
    uint32_t *triangles;  /* triangle_count x 3, counter-clockwise */
    size_t triangle_count;
    double area;          /* sum of triangle areas */
} cdl_mesh2d;

/* Triangulate `outer` minus `holes`. max_edge <= 0: constrained Delaunay
 * triangulation of the ring vertices only. max_edge > 0: refine until no
 * triangle edge is longer than max_edge and no angle is below ~20.6 degrees.
 * On success the caller owns *out (release with cdl_mesh2d_release). */
cdl_status cdl_mesh2d_triangulate(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count, double max_edge,
                                  cdl_mesh2d *out, cdl_error *err);

/* As cdl_mesh2d_triangulate, but refinement gives up with CDL_ERR_INPUT once
 * the mesh has more than max_vertices vertices. Tiny features (a vertex a
 * hair's breadth from an edge, an edge far shorter than max_edge) make
 * Delaunay refinement grade down to their size, which can take millions of
 * points or, below double precision, never end. */
cdl_status cdl_mesh2d_triangulate_bounded(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count,
                                          double max_edge, size_t max_vertices, cdl_mesh2d *out, cdl_error *err);

void cdl_mesh2d_release(cdl_mesh2d *mesh);

#ifdef __cplusplus
}
#endif

#endif
