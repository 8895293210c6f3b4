/* mesh2d.h - triangulation of planar polygons with holes (CGAL behind a C API).
 *
 * Used to turn `polygon` surfaces into triangles (constrained Delaunay
 * triangulation, no new vertices) and to mesh `polygon` calculation grids
 * into well-shaped triangles no longer than a target edge (Delaunay
 * refinement, Ruppert/Shewchuk style, CGAL 2D Conforming Meshes); and, kept
 * live (cdl_cdt2d), to carry the surface maps' planar faces, whose meshes
 * keep refining where the light changes and whose vertices hold the solve's
 * irradiance cache records (solver/geometry/surface_mesh.h).
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

/* ---- a mesh that keeps refining: cdl_cdt2d ----------------------------------
 *
 * The constrained Delaunay mesh of a polygon with holes, kept alive so that
 * points can be added where a field needs them (surface maps, refined where
 * the illuminance changes): its rings are constraints, the faces between
 * them (odd nesting depth, as above) its domain, and after every change
 * cdl_cdt2d_improve restores Delaunay refinement's guarantees (no angle
 * below CDL_MESH2D_MIN_ANGLE_DEG except at input corners that are sharper,
 * no edge longer than max_edge).
 *
 * Vertices are numbered 0, 1, ... in the order they appear and keep their
 * number for the mesh's life (Delaunay refinement inserts, never removes);
 * numbers go to vertices outside the domain too (in holes), which no domain
 * triangle uses. Every operation is deterministic: the same calls give the
 * same numbers and triangles. Not thread-safe on one mesh; distinct meshes
 * are independent. */

/* The smallest angle Delaunay refinement keeps (CGAL's default shape bound
 * B = sin^2(angle) = 0.125): asin(sqrt(0.125)) = 20.705 degrees. */
#define CDL_MESH2D_MIN_ANGLE_DEG 20.704811054635442

typedef struct cdl_cdt2d cdl_cdt2d;

/* The constrained Delaunay triangulation of `outer` minus `holes`, refined
 * to max_edge (> 0) and the angle bound; CDL_ERR_INPUT as
 * cdl_mesh2d_triangulate_bounded (a degenerate polygon, more than
 * max_vertices vertices). */
cdl_status cdl_cdt2d_create(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count, double max_edge,
                            size_t max_vertices, cdl_cdt2d **out, cdl_error *err);
void cdl_cdt2d_release(cdl_cdt2d *mesh);

size_t cdl_cdt2d_vertex_count(const cdl_cdt2d *mesh);
/* Vertex `id`'s coordinates; *on_boundary (may be NULL) 1 when it lies on
 * a ring (an endpoint of a constrained edge). */
void cdl_cdt2d_vertex(const cdl_cdt2d *mesh, size_t id, double xy[2], int *on_boundary);

/* The domain's triangles as vertex numbers, counter-clockwise, in a
 * deterministic order, into a malloc'ed array the caller frees. */
cdl_status cdl_cdt2d_triangles(const cdl_cdt2d *mesh, uint32_t **triangles, size_t *triangle_count, cdl_error *err);

/* Split edges: for each k, the point xy[2k..2k+1] (the caller's midpoint of
 * the edge between vertices ab[2k] and ab[2k+1]) is inserted on that edge if
 * it is still an edge of the mesh (a constrained edge is split in two
 * constrained halves); new_id[k] is the new vertex's number, or SIZE_MAX
 * when the edge had gone (an earlier insertion of the batch flipped it). */
cdl_status cdl_cdt2d_split_edges(cdl_cdt2d *mesh, const uint32_t *ab, const double *xy, size_t count,
                                 size_t *new_id, cdl_error *err);

/* Insert points that lie on the rings (within `tolerance`, in the plane's
 * units) as vertices splitting the constrained edge they lie on: how the
 * meshes of surfaces that meet along an edge are made to share their
 * vertices there. A point already a vertex (within tolerance of one), or
 * on no constrained edge, is left out. *inserted counts those added. */
cdl_status cdl_cdt2d_insert_on_boundary(cdl_cdt2d *mesh, const double *xy, size_t count, double tolerance,
                                        size_t *inserted, cdl_error *err);

/* Insert points strictly inside the domain (seeds a caller wants as
 * vertices); points outside it or on a ring are left out. */
cdl_status cdl_cdt2d_insert_inside(cdl_cdt2d *mesh, const double *xy, size_t count, size_t *inserted,
                                   cdl_error *err);

/* Restore the refinement's guarantees after insertions (the mesher adds
 * points; CDL_ERR_INPUT beyond max_vertices vertices in all). */
cdl_status cdl_cdt2d_improve(cdl_cdt2d *mesh, double max_edge, size_t max_vertices, cdl_error *err);

#ifdef __cplusplus
}
#endif

#endif
