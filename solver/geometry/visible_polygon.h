/* visible_polygon.h - the part of a planar face a point sees past planar
 * occluders, exactly.
 *
 * Seen from an apex p, an occluder hides from a face (an emitter polygon in
 * its own plane, or a face of a cube around p standing for the sky) exactly
 * its central projection from p onto the face's plane: the points q of the
 * plane whose segment from p (emitter) or ray from p (sky) meets it. Only
 * the occluder's part on the far side of p (and, for an emitter, before the
 * emitter's plane) projects; it is clipped to that first, in 3-D, and to the
 * pyramid from p through the face's bounding rectangle, so the projection
 * is bounded. A triangle cut by half-spaces stays convex, and the central
 * projection of a convex set in front of p is convex.
 *
 * The visible face is kept as a list of convex pieces in the plane's 2-D
 * coordinates. Subtracting a convex polygon Q of k edges from a convex piece
 * C leaves at most k convex pieces, C cut by one edge of Q at a time:
 *     C \ Q = union over i of (C inside edges 1 .. i-1, outside edge i),
 * exact up to the rounding of the intersection points (the same edge of
 * two pieces is cut at the same points: intersections are computed from
 * the edge's endpoints in a fixed order). Pieces thinner than a relative
 * 1e-14 of the face's size are dropped (their projected solid angle is
 * below 1e-13 of the face's).
 *
 * The visible part's projected solid angle is Lambert's closed form of each
 * piece (lights/emitters/projected_solid_angle.h), so a Lambertian face of luminance
 * L gives E = L x the sum (the configuration factor of the visible polygon
 * times pi L: the method of exact daylight references and CIE 171:2006).
 *
 * Pure computation, no scene: thread-safe for distinct faces.
 */
#ifndef CANDELA_SOLVER_VISIBLE_POLYGON_H
#define CANDELA_SOLVER_VISIBLE_POLYGON_H

#include <stddef.h>

#include "radiometry/vec3.h"

/* Most vertices of one convex piece, and most pieces of a face; beyond
 * either the face is refused (the caller samples instead). */
#define CDL_VISIBLE_MAX_VERTICES 32
#define CDL_VISIBLE_MAX_PIECES 4096

typedef struct cdl_visible_piece {
    int count;
    double v[CDL_VISIBLE_MAX_VERTICES][2];
} cdl_visible_piece;

/* A face seen from an apex. The plane's 2-D coordinates (x, y) stand for
 * the point foot + x e1 + y e2, foot = apex - height x toward. */
typedef struct cdl_visible_face {
    cdl_vec3 apex;
    cdl_vec3 toward;                 /* unit normal of the plane, pointing to the apex */
    cdl_vec3 e1, e2;                 /* unit axes in the plane, e1 x e2 = toward */
    double height;                   /* the apex's distance to the plane, > 0 */
    int bounded;                     /* 1: only what lies between apex and plane hides it (an emitter);
                                      * 0: anything in front of the apex does (a face of the sky's cube) */
    double near;                     /* occluder parts closer than this along -toward are ignored
                                      * (they pass through the apex: the point lies on them) */
    double lo[2], hi[2];             /* bounding rectangle of the pieces as first added */
    cdl_visible_piece *pieces;
    size_t count, capacity;
    int overflow;                    /* 1: a limit was reached or memory ran out; the result is void */
} cdl_visible_face;

/* Start a face: the plane through `point_in_plane` with normal `toward`
 * (unit, towards the apex; the apex must be strictly on that side). */
void cdl_visible_face_init(cdl_visible_face *face, cdl_vec3 apex, cdl_vec3 toward, cdl_vec3 point_in_plane,
                           int bounded, double near);
void cdl_visible_face_release(cdl_visible_face *face);

/* Add a convex polygon lying in the plane (3-D points, either orientation). */
void cdl_visible_face_add_polygon(cdl_visible_face *face, const cdl_vec3 *points, int count);

/* Add a convex polygon given in the plane's 2-D coordinates. */
void cdl_visible_face_add_polygon_2d(cdl_visible_face *face, const double (*xy)[2], int count);

/* Keep only the part of the face where a x + b y + c >= 0 (a horizon). */
void cdl_visible_face_clip(cdl_visible_face *face, double a, double b, double c);

/* Subtract what the triangle (xyz of its three corners) hides. */
void cdl_visible_face_subtract_triangle(cdl_visible_face *face, const double *triangle);

/* Projected solid angle, about the receiver normal n, of what is left:
 * Omega_p of each piece, clipped to n's hemisphere. */
double cdl_visible_face_projected_solid_angle(const cdl_visible_face *face, cdl_vec3 n);

#endif
