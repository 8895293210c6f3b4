/* polygon.h - planar polygons with holes in 3D: their plane, their
 * validity, and their triangulation (through mesh2d.h, CGAL).
 *
 * Used by the scene loader (to refuse bad polygons with the JSON path of the
 * offending vertex), by scene geometry (polygon surfaces and shapes) and by
 * polygon calculation grids.
 *
 * The plane's frame: origin at the outer ring's first vertex, e1 along the
 * outer ring's first edge (projected into the plane), normal from the outer
 * ring's orientation (counter-clockwise seen from the front, Newell's
 * method), e2 = normal x e1. Counter-clockwise in (e1, e2) coordinates is
 * counter-clockwise seen from the front.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_POLYGON_H
#define CANDELA_SOLVER_GEOMETRY_POLYGON_H

#include <stddef.h>

#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/geometry/mesh2d.h"
#include "solver/geometry/ring3.h"

typedef struct cdl_polygon_plane {
    cdl_vec3 origin;   /* the outer ring's first vertex */
    cdl_vec3 e1, e2;   /* unit, in the plane; e1 x e2 = normal */
    cdl_vec3 normal;   /* unit */
    double size;       /* diagonal of the outer ring's bounding box (m) */
} cdl_polygon_plane;

typedef enum cdl_polygon_defect {
    CDL_POLYGON_VALID,
    CDL_POLYGON_REPEATED_VERTEX,   /* vertex (almost) equals the one before it */
    CDL_POLYGON_SPIKE,             /* vertex folds the ring back onto an edge (or a needle thinner than the minimum) */
    CDL_POLYGON_NO_AREA,           /* outer ring collinear (or too thin to have a normal) */
    CDL_POLYGON_NOT_PLANAR,        /* vertex off the outer ring's plane */
    CDL_POLYGON_CROSSING,          /* two edges cross, touch, or come closer than the minimum */
    CDL_POLYGON_HOLE_OUTSIDE,      /* a hole not inside the outer ring */
    CDL_POLYGON_HOLE_IN_HOLE       /* a hole inside another hole */
} cdl_polygon_defect;

/* Where a defect is: ring -1 is the outer ring, k >= 0 hole k. */
typedef struct cdl_polygon_problem {
    cdl_polygon_defect defect;
    long ring;
    size_t vertex;          /* start vertex of the offending edge, or the vertex */
    long other_ring;        /* CROSSING: the other edge; HOLE_IN_HOLE: the enclosing hole */
    size_t other_vertex;
    double distance;        /* NOT_PLANAR: distance from the plane (m) */
} cdl_polygon_problem;

/* Relative planarity tolerance: vertices within this fraction of the outer
 * ring's size from its plane are accepted. */
#define CDL_POLYGON_PLANARITY_TOLERANCE 1e-6
/* Smallest feature, as a fraction of the outer ring's size: consecutive
 * vertices closer than this are a repeated vertex, edges closer than this
 * a crossing (CAD artefacts, which Delaunay refinement would grade down to). */
#define CDL_POLYGON_MIN_EDGE 1e-9

/* Check the polygon and compute its plane. Returns 1 when valid (then *plane
 * is set); 0 with *problem filled otherwise. Rings need >= 3 points. */
int cdl_polygon_check(const cdl_ring3 *outer, const cdl_ring3 *holes, size_t hole_count,
                            cdl_polygon_plane *plane, cdl_polygon_problem *problem);

/* The plane of a polygon the scene loader has checked (cdl_polygon_check),
 * without checking it again: its later users (scene geometry, polygon
 * grids) take it from here. CDL_ERR_INTERNAL for a polygon that is not
 * valid (the loader would have refused it). */
cdl_status cdl_polygon_plane_of_checked(const cdl_ring3 *outer, const cdl_ring3 *holes, size_t hole_count,
                                        cdl_polygon_plane *plane, cdl_error *err);

/* Area of the outer ring (m^2), holes not taken out. */
double cdl_polygon_outer_area(const cdl_polygon_plane *plane, const cdl_ring3 *outer);

/* Plane coordinates of p, and back (the point on the plane). */
void cdl_polygon_project(const cdl_polygon_plane *plane, cdl_vec3 p, double *x, double *y);
cdl_vec3 cdl_polygon_lift(const cdl_polygon_plane *plane, double x, double y);

/* Triangulate a checked polygon in its plane (mesh2d.h: max_edge <= 0 keeps
 * the ring vertices only; refinement stops with an error beyond
 * max_vertices). The 2D mesh is in plane coordinates; its triangles are
 * counter-clockwise seen from the front. */
cdl_status cdl_polygon_triangulate(const cdl_polygon_plane *plane, const cdl_ring3 *outer,
                                         const cdl_ring3 *holes, size_t hole_count, double max_edge,
                                         size_t max_vertices, cdl_mesh2d *out, cdl_error *err);

#endif
