/* surface_patch.h - one patch of a surface map while it is refined
 * (surface_mesh.h; internal to surface_mesh.c and surface_join.c).
 *
 * A patch state holds the patch's mesh (a cdl_cdt2d for planar patches, a
 * cdl_bisect_mesh for spheres and triangle meshes), its current triangles,
 * and the field's values:
 *   - slots: one per (vertex, region), the value at a vertex with the normal
 *     of a region (region 0 but for imported meshes split at sharp edges);
 *   - tests: one per (edge, region), the value at the edge's midpoint, where
 *     the vertex splitting the edge would go, with the normal it would get.
 * Slot and test numbers only grow; a test whose edge has gone stays,
 * unused. Thread safety: none per state.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_SURFACE_PATCH_H
#define CANDELA_SOLVER_GEOMETRY_SURFACE_PATCH_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/bounds.h"
#include "solver/geometry/bisect_mesh.h"
#include "solver/geometry/key_table.h"
#include "solver/geometry/mesh2d.h"
#include "solver/geometry/polygon.h"
#include "solver/geometry/surface_mesh.h"

typedef struct cdl_patch_slot {
    uint32_t vertex, region;
    cdl_vec3 normal;
    double value, sigma, noise;
    double aux[CDL_FIELD_AUX_MAX];
    int known;                /* value, sigma, noise and aux hold the field */
} cdl_patch_slot;

typedef struct cdl_patch_test {
    uint64_t edge;            /* cdl_key_pair of its vertices */
    uint32_t region;
    size_t next;              /* the edge's test for another region, or CDL_KEY_TABLE_NONE */
    cdl_vec3 position, normal;
    double value, sigma, noise;
    double aux[CDL_FIELD_AUX_MAX];
    int known;
} cdl_patch_test;

typedef struct cdl_patch_state {
    const cdl_patch *spec;
    cdl_polygon_plane plane;  /* polygon */
    cdl_cdt2d *cdt;           /* polygon */
    cdl_bisect_mesh *bisect;  /* sphere, triangles */
    uint32_t *tri, *tri_region;
    size_t tri_count;
    cdl_patch_slot *slots;
    size_t slot_count, slot_capacity;
    cdl_key_table slot_of;    /* cdl_key_ordered(vertex, region) -> slot */
    cdl_patch_test *tests;
    size_t test_count, test_capacity;
    cdl_key_table test_of;    /* edge -> its first test */
    cdl_bounds3 bounds;       /* of the patch's outline or surface */
    int as_given;             /* triangles CGAL could not remesh, used as given */
} cdl_patch_state;

/* The patch's first mesh (max_edge, the settings' feature angle), seeds
 * inserted; slots and tests are made by the first refresh. */
cdl_status cdl_patch_state_init(cdl_patch_state *ps, const cdl_patch *spec, const cdl_surface_mesh_settings *settings,
                                cdl_error *err);
void cdl_patch_state_release(cdl_patch_state *ps);

size_t cdl_patch_state_vertex_count(const cdl_patch_state *ps);
cdl_vec3 cdl_patch_state_position(const cdl_patch_state *ps, uint32_t vertex);
int cdl_patch_state_on_outline(const cdl_patch_state *ps, uint32_t vertex);

/* Take the mesh's current triangles and make the slots and tests they need
 * (values unknown until the caller fills them). */
cdl_status cdl_patch_state_refresh(cdl_patch_state *ps, cdl_error *err);

/* The slot of (vertex, region) and the first test of an edge, or
 * CDL_KEY_TABLE_NONE. */
size_t cdl_patch_state_slot(const cdl_patch_state *ps, uint32_t vertex, uint32_t region);
size_t cdl_patch_state_test(const cdl_patch_state *ps, uint32_t a, uint32_t b, uint32_t region);

/* Split the edges (cdl_key_pair keys) at their tested midpoints, which
 * become vertices with the tests' values; planar patches then restore
 * their angle bound (max_vertices as cdl_cdt2d_improve). The caller
 * refreshes afterwards. */
cdl_status cdl_patch_state_split(cdl_patch_state *ps, const uint64_t *edges, size_t count, size_t max_vertices,
                                 cdl_error *err);

/* ---- joining patches (surface_join.c) ---- */

/* Make planar patches that meet along their outlines share their vertices
 * there (surface_mesh.h, "Watertight"): each patch's outline vertices that
 * lie on another's outline (within tolerance) are inserted there, and the
 * patches that took some restore their angle bound, until none takes any
 * (at most a few passes). *joined counts the vertices inserted. */
cdl_status cdl_patch_join(cdl_patch_state *states, size_t count, double tolerance, size_t max_vertices,
                          size_t *joined, cdl_error *err);

/* Outline vertices of the meshes within tolerance of one another get the
 * coordinates of one of them (the one with the least x; ties by mesh and
 * vertex number), the same in every run. */
cdl_status cdl_surface_mesh_snap(cdl_surface_mesh *meshes, size_t count, double tolerance, cdl_error *err);

#endif
