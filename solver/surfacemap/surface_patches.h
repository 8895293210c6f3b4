/* surface_patches.h - the scene's mapped surfaces as the patches their
 * meshes start from (solver/geometry/surface_mesh.h).
 *
 *   rect     the parallelogram o, o + u, o + u + v, o + v (front u x v)
 *   polygon  its outline and holes
 *   box      a patch per closed face, its corners the ray scene's
 *            (cdl_box_face_corners: shared bit for bit, front inside for an
 *            inward box); one surface, so its faces share one map
 *   disk     the polygon of every (224 / N)-th rim vertex of the ray
 *            scene's fan (the same points bit for bit, so every vertex lies
 *            on the disk the rays see), N the fewest of 32, 56, 112 and 224
 *            whose chords are no longer than the patch's coarsest edge
 *            (with N >= 32 the polygon holds 99.4 % of the disk's area)
 *   sphere   the sphere (front outside, or inside when inward)
 *   mesh     its triangles
 * Each patch's coarsest edge (max_edge) is EN 12464-1:2021's grid spacing
 * p = 0.2 x 5^log10(d) for d the longest side of the patch's bounding box
 * (cdl_grid_auto_spacing: a 6 m wall 0.70 m, a 1.2 m desk 0.21 m, at most
 * 10 m): where the light is even, the map is as fine as the standard's
 * grid; refinement makes it finer where the light asks.
 *
 * Ownership: the patches point into storage of their own (released with
 * them) and into the scene (mesh triangles, polygon rings), which must
 * outlive them. Errors: memory. Thread safety: none needed (no state).
 */
#ifndef CANDELA_SOLVER_SURFACEMAP_SURFACE_PATCHES_H
#define CANDELA_SOLVER_SURFACEMAP_SURFACE_PATCHES_H

#include <stddef.h>

#include "base/error.h"
#include "solver/geometry/surface_mesh.h"
#include "solver/scene/scene_internal.h"

typedef struct cdl_surface_patches {
    cdl_patch *patches;          /* their .surface numbers the maps 0 .. map_count */
    size_t count;
    double *reflectance;         /* per patch: its surface's (a box face: that face's) */
    size_t *scene_surface;       /* map k is scene->surfaces[scene_surface[k]] */
    size_t map_count;
    cdl_vec3 *points;            /* the rings made here (rects, box faces, disks) */
    size_t point_count;
} cdl_surface_patches;

/* The patches of every mapped surface (cdl_surface_spec.mapped), in the
 * scene's order. */
cdl_status cdl_surface_patches_build(const cdl_scene *scene, cdl_surface_patches *out, cdl_error *err);
void cdl_surface_patches_release(cdl_surface_patches *patches);

/* The disk's polygon: how many rim vertices for a coarsest edge. */
uint32_t cdl_surface_patches_disk_sides(double radius, double max_edge);

#endif
