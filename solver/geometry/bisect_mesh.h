/* bisect_mesh.h - a triangle mesh in space refined by longest-edge
 * bisection: the curved and imported surfaces of surface maps, refined
 * where a field needs it (surface_mesh.h).
 *
 * Splitting an edge splits every triangle that has it, at the edge's
 * midpoint (on a sphere, the midpoint pushed out onto the sphere), so the
 * mesh stays conforming: no vertex ever lies inside another triangle's
 * edge. Before a triangle is split along an edge that is not its longest,
 * its longest edge is split first (Rivara's longest-edge bisection, "New
 * longest-edge algorithms for the refinement and/or improvement of
 * unstructured triangulations", IJNME 40, 1997), which keeps every angle at
 * least half the smallest angle of the mesh it started from, however
 * often it refines. Ties between edges of equal length are broken by their
 * vertex numbers, so the same calls give the same mesh.
 *
 * Vertices are numbered in the order they appear and never move or go;
 * each triangle keeps the region number of the triangle it came from (the
 * caller's labels: the smooth parts of an imported mesh between its sharp
 * edges) and its orientation. Edges shared by more than two triangles
 * (non-manifold input) are allowed: every triangle on them is split.
 * Thread safety: none per mesh.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_BISECT_MESH_H
#define CANDELA_SOLVER_GEOMETRY_BISECT_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_bisect_mesh cdl_bisect_mesh;

/* No vertex: returned for an edge that is not (or no longer) in the mesh,
 * and as the parent of a vertex the mesh started with. */
#define CDL_BISECT_NONE UINT32_MAX

/* Make a mesh of the triangles (vertex numbers into xyz, vertex_count x 3;
 * region per triangle, NULL for all 0). sphere_radius > 0: the vertices lie
 * on the sphere about sphere_center and new ones are put on it too.
 * Errors: CDL_ERR_INPUT for a triangle naming a missing vertex or using a
 * vertex twice; memory. */
cdl_status cdl_bisect_mesh_create(const double *xyz, size_t vertex_count, const uint32_t *triangles,
                                  const uint32_t *region, size_t triangle_count, cdl_vec3 sphere_center,
                                  double sphere_radius, cdl_bisect_mesh **out, cdl_error *err);
void cdl_bisect_mesh_release(cdl_bisect_mesh *mesh);

size_t cdl_bisect_mesh_vertex_count(const cdl_bisect_mesh *mesh);
cdl_vec3 cdl_bisect_mesh_vertex(const cdl_bisect_mesh *mesh, uint32_t id);
/* The edge whose split made vertex id (CDL_BISECT_NONE for the first vertices). */
void cdl_bisect_mesh_parent(const cdl_bisect_mesh *mesh, uint32_t id, uint32_t *a, uint32_t *b);

size_t cdl_bisect_mesh_triangle_count(const cdl_bisect_mesh *mesh);
/* triangle_count x 3 vertex numbers and triangle_count regions; valid until
 * the next split. */
const uint32_t *cdl_bisect_mesh_triangles(const cdl_bisect_mesh *mesh);
const uint32_t *cdl_bisect_mesh_regions(const cdl_bisect_mesh *mesh);

/* Where splitting the edge ab puts its new vertex. */
cdl_vec3 cdl_bisect_mesh_midpoint(const cdl_bisect_mesh *mesh, uint32_t a, uint32_t b);

/* Split the edge ab (and, first, the longer edges longest-edge bisection
 * asks for). *new_vertex: the vertex at ab's midpoint, or CDL_BISECT_NONE
 * when ab is not an edge. Errors: memory (the mesh is then still valid,
 * possibly partly refined). */
cdl_status cdl_bisect_mesh_split(cdl_bisect_mesh *mesh, uint32_t a, uint32_t b, uint32_t *new_vertex,
                                 cdl_error *err);

#endif
