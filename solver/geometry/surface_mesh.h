/* surface_mesh.h - meshes of surfaces whose vertices follow a field: the
 * meshes of surface maps, refined where the illuminance changes.
 *
 * A surface is one or more patches: planar polygons with holes (a rect, a
 * disk's polygon, each face of a box, a polygon), spheres and triangle
 * meshes. Each patch starts as well-shaped triangles no longer than its
 * max_edge (planar ones by constrained Delaunay refinement, mesh2d.h;
 * spheres and meshes by isotropic remeshing, remesh.h) and is then refined
 * in rounds:
 *
 *   1. the field is evaluated at every vertex that has no value yet and at
 *      the midpoint of every edge not tested yet (one call of the caller's
 *      function per round, for all patches: it can spread the work over
 *      threads);
 *   2. linear interpolation along an edge is off at its midpoint by
 *      d = E(mid) - (E(a) + E(b)) / 2; an edge whose |d| is above the
 *      tolerance max(rel_tol |E_ab|, rel_tol floor_fraction Em) (Em the
 *      surface's mean, E_ab the interpolated value) and above twice the
 *      noise of d (the three values' independent noise), and that is longer than
 *      min_edge, is split at that midpoint, whose value is then known;
 *   3. planar patches restore Delaunay refinement's angle bound (new
 *      vertices), spheres and meshes split by longest-edge bisection
 *      (bisect_mesh.h), which keeps every angle above half the smallest
 *      they started with.
 * It stops when no edge asks to be split, or at max_vertices over all
 * surfaces (stats->budget_reached). Where a field is even, a patch keeps
 * its first size; where it bends, triangles shrink until they follow it.
 *
 * Why midpoints: on a triangle where the field is locally quadratic, the
 * error of the linear interpolant is e = 4 (d_ab l_a l_b + d_bc l_b l_c +
 * d_ca l_c l_a) in barycentric coordinates l, fixed by the three midpoint
 * deviations d alone, so they bound it (|e| <= 4/3 max |d|) and give its
 * root mean square over the triangle, from the integrals of products of
 * barycentric coordinates (integral of l_a^i l_b^j l_c^k over a triangle
 * of area A is 2A i! j! k! / (i + j + k + 2)!):
 *     rms(e)^2 = 16/90 [ d_ab^2 + d_bc^2 + d_ca^2 + d_ab d_bc + d_bc d_ca + d_ca d_ab ]
 * (the mean of (l_a l_b)^2 is 1/90, of (l_a l_b)(l_b l_c) 1/180, and each
 * cross term appears twice in the square).
 * Every edge of the final mesh has had its midpoint evaluated, so every
 * triangle has this estimate; a vertex's `interpolation` is the largest
 * over its triangles: how far the map may be off near it.
 *
 * Watertight: where planar patches meet along their outlines (the faces of
 * a box, a wall's edge on the floor's, a partition's edge along a wall's),
 * each patch's outline vertices are inserted into the other's outline, until
 * both have the same vertices along the shared part; the vertices there
 * are then given the very same coordinates (the first patch's), so no crack
 * or T-junction is left between them. Spheres and imported meshes are
 * watertight within themselves, not joined to other patches.
 *
 * Values: each patch vertex has its own value with its patch's normal, so
 * a box edge's vertex appears once per face; an imported mesh is split into
 * regions at its sharp edges (dihedral angle above feature_angle_deg), and
 * a vertex on a sharp edge has a value per region, with the region's
 * angle-weighted normal.
 *
 * Deterministic: the same patches, settings and field give the same meshes
 * and the same calls of the field, in the same order. Thread safety: no
 * shared state; the field function is called from the calling thread.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_SURFACE_MESH_H
#define CANDELA_SOLVER_GEOMETRY_SURFACE_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/geometry/ring3.h"

typedef enum cdl_patch_kind { CDL_PATCH_POLYGON, CDL_PATCH_SPHERE, CDL_PATCH_TRIANGLES } cdl_patch_kind;

typedef struct cdl_patch {
    cdl_patch_kind kind;
    size_t surface;                      /* the output surface it belongs to, < surface_count */
    double max_edge;                     /* m, > 0: the coarsest triangles' edge */
    /* polygon: outline and holes, valid for cdl_polygon_check; its front is
     * the side it runs counter-clockwise on */
    cdl_ring3 outer;
    const cdl_ring3 *holes;
    size_t hole_count;
    /* sphere: front outside, or inside when inward */
    cdl_vec3 center;
    double radius;
    int inward;
    /* triangles: vertex_count x 3 coordinates, counter-clockwise from the front */
    const double *xyz;
    size_t vertex_count;
    const uint32_t *triangles;
    size_t triangle_count;
    /* polygon: points that are to be vertices from the start (say, where a
     * luminaire aims); points off the patch are left out */
    const cdl_vec3 *seeds;
    size_t seed_count;
} cdl_patch;

/* Where the field is asked for: a point on a surface and the normal of the
 * side mapped. */
typedef struct cdl_field_probe {
    cdl_vec3 position;
    cdl_vec3 normal;                     /* unit */
    size_t surface;
    int is_vertex;                       /* 1: a vertex; 0: an edge's midpoint, tested */
    double floor;                        /* the least value the tolerance is relative to on its surface
                                          * (floor_fraction Em); 0 before the first round's values */
} cdl_field_probe;

/* Values a field may carry beside the one it is refined by (the direct
 * and interreflected parts of an illuminance): at most this many. */
#define CDL_FIELD_AUX_MAX 2

/* The field at count probes: value[i] and its one-sigma error sigma[i] (0
 * when exact); noise[i] <= sigma[i], the part of that error independent
 * from probe to probe (sampling noise; not an error neighbouring probes
 * share, such as interpolation from the same cache records), which is all
 * that can make an edge look bent when it is not; and with aux_channels > 0
 * the probe's other values in aux[aux_channels i ...] (aux is NULL
 * otherwise). noise arrives filled with -1: a field that leaves it so has
 * it taken as sigma. A failure stops the meshing with its status. */
typedef cdl_status (*cdl_field_fn)(void *user, const cdl_field_probe *probes, size_t count, double *value,
                                   double *sigma, double *noise, double *aux, cdl_error *err);

typedef struct cdl_surface_mesh_settings {
    double rel_tol;                      /* > 0: interpolation tolerance relative to the value */
    double floor_fraction;               /* >= 0: absolute tolerance rel_tol floor_fraction Em */
    double min_edge;                     /* m, > 0: edges this short are not split */
    double join_tolerance;               /* m, > 0: outline points closer than this are one */
    double feature_angle_deg;            /* sharp edges of imported meshes: dihedral angle above this */
    size_t max_vertices;                 /* over all surfaces */
    int aux_channels;                    /* 0 .. CDL_FIELD_AUX_MAX values per probe beside the field */
} cdl_surface_mesh_settings;

typedef struct cdl_surface_mesh_request {
    const cdl_patch *patches;
    size_t patch_count;
    size_t surface_count;
    cdl_surface_mesh_settings settings;
    cdl_field_fn field;
    void *user;
} cdl_surface_mesh_request;

/* One surface's mesh; every array is vertex_count (x 3) or triangle_count x 3. */
typedef struct cdl_surface_mesh {
    double *xyz;
    double *normal;                      /* unit, the side mapped */
    size_t vertex_count;
    uint32_t *triangles;                 /* counter-clockwise seen from the normal's side */
    size_t triangle_count;
    double *value, *sigma;               /* the field at the vertex and its one-sigma error */
    double *interpolation;               /* rms interpolation error over the vertex's triangles (above) */
    double *aux;                         /* aux_channels per vertex (NULL without) */
    uint32_t *patch;                     /* the request's patch each vertex belongs to */
    unsigned char *on_outline;           /* 1: the vertex lies on a planar patch's outline */
    double area;                         /* m^2, of the triangles */
} cdl_surface_mesh;

typedef struct cdl_surface_mesh_stats {
    size_t rounds;                       /* refinement rounds that split edges */
    size_t evaluations;                  /* probes the field was asked for */
    size_t vertices, triangles;          /* over all surfaces */
    size_t unresolved;                   /* final edges at min_edge still above the tolerance */
    size_t joined;                       /* outline vertices inserted to join patches */
    size_t mesh_as_given;                /* imported meshes CGAL could not remesh, used as given */
    int budget_reached;                  /* refinement stopped at max_vertices */
} cdl_surface_mesh_stats;

/* Mesh and refine every patch; out[0 .. surface_count) are the caller's to
 * release (each with cdl_surface_mesh_release; zeroed on failure).
 * Errors: CDL_ERR_INPUT for a patch that cannot be meshed (a polygon
 * cdl_polygon_check refuses, a sphere of no radius, settings out of range),
 * the field's failures, memory. */
cdl_status cdl_surface_mesh_build(const cdl_surface_mesh_request *request, cdl_surface_mesh *out,
                                  cdl_surface_mesh_stats *stats, cdl_error *err);
void cdl_surface_mesh_release(cdl_surface_mesh *mesh);

#endif
