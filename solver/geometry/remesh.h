/* remesh.h - well-shaped triangle meshes of curved and imported surfaces
 * (CGAL's isotropic remeshing behind a C API; remesh_cgal.cpp).
 *
 * Surface maps (surface_mesh.h) start every surface from a mesh of
 * well-shaped triangles of about one size: planar faces come from
 * Delaunay refinement (mesh2d.h), spheres and imported meshes from here:
 *
 *   sphere: an icosahedron split until its edges are near the target, then
 *     isotropic remeshing (Botsch and Kobbelt, "A remeshing approach to
 *     multiresolution modeling", SGP 2004: split long edges, collapse short
 *     ones, flip towards valence 6, tangential relaxation) with every vertex
 *     projected back onto the sphere, and projected exactly once more at
 *     the end;
 *   triangles: the same remeshing of the given mesh, vertices projected
 *     onto the input surface, with its sharp edges (dihedral angle above
 *     feature_angle_deg) and its borders kept: split to the target first,
 *     then held fixed, so corners and outlines stay where they were.
 *
 * Triangles are counter-clockwise seen from the front: outward for a
 * sphere unless inward; as the input's for a mesh. A mesh CGAL cannot
 * remesh (not a manifold surface: an edge shared by three triangles, a
 * vertex joining two sheets, inconsistent orientation) is refused with
 * CDL_ERR_INPUT saying so; callers may then use the triangles as given.
 * Thread safety: no shared state; each call is independent.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_REMESH_H
#define CANDELA_SOLVER_GEOMETRY_REMESH_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cdl_trimesh {
    double *xyz;              /* vertex_count x 3 */
    size_t vertex_count;
    uint32_t *triangles;      /* triangle_count x 3 */
    size_t triangle_count;
} cdl_trimesh;

/* The sphere (center xyz, radius > 0) with edges of about target_edge (> 0;
 * at least 20 triangles). */
cdl_status cdl_remesh_sphere(const double center[3], double radius, int inward, double target_edge,
                             cdl_trimesh *out, cdl_error *err);

/* The triangles (vertex_count x 3 coordinates) remeshed to edges of about
 * target_edge (> 0), keeping sharp edges and borders (above). */
cdl_status cdl_remesh_triangles(const double *xyz, size_t vertex_count, const uint32_t *triangles,
                                size_t triangle_count, double target_edge, double feature_angle_deg,
                                cdl_trimesh *out, cdl_error *err);

void cdl_trimesh_release(cdl_trimesh *mesh);

#ifdef __cplusplus
}
#endif

#endif
