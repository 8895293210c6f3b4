/* glare_parts.h - the luminous parts of a glare source as flat pieces:
 * their solid angle at an eye, and points on them for visibility.
 *
 * A source's luminous parts are up to CDL_GLARE_PARTS_MAX flat pieces, each
 * a parallelogram c +- u +- v, an ellipse c + cos(t) u + sin(t) v, or a
 * triangle (a, b, c), emitting on one side or both. Seen from an eye:
 *  - the solid angle of each piece facing it: a parallelogram as two
 *    spherical triangles and a triangle as one (Van Oosterom and Strackee,
 *    IEEE Trans. Biomed. Eng. 30(2), 1983), an ellipse as an equal-area
 *    256-gon (within 1e-6 of the curve's); the pieces of a convex part
 *    (a box's faces) do not overlap as seen, so their solid angles add;
 *  - points on the pieces, a piece chosen in proportion to its solid angle
 *    and a point uniform over its area, each with the weight (cos theta /
 *    r^2) / pdf that makes sum w V / sum w, V the point's visibility, the
 *    fraction of the pieces' solid angle an eye sees (a ratio estimator).
 * Pure functions: thread-safe. Units: metres, steradians.
 */
#ifndef CANDELA_GLARE_GLARE_PARTS_H
#define CANDELA_GLARE_GLARE_PARTS_H

#include "radiometry/vec3.h"

#define CDL_GLARE_PARTS_MAX 6

typedef enum cdl_glare_piece_kind {
    CDL_GLARE_PIECE_PARALLELOGRAM,
    CDL_GLARE_PIECE_ELLIPSE,
    CDL_GLARE_PIECE_TRIANGLE
} cdl_glare_piece_kind;

typedef struct cdl_glare_piece {
    cdl_glare_piece_kind kind;
    cdl_vec3 c, u, v;  /* parallelogram and ellipse: centre and half axes; triangle: its corners c, u, v */
    int one_sided;     /* 1: only the side u x v faces emits (an area luminaire) */
} cdl_glare_piece;

typedef struct cdl_glare_parts {
    cdl_glare_piece piece[CDL_GLARE_PARTS_MAX];
    int count;
} cdl_glare_parts;

/* The solid angle at `eye` of one piece (0 when the eye sees its back and
 * it is one-sided, or lies in its plane). */
double cdl_glare_piece_solid_angle(const cdl_glare_piece *piece, cdl_vec3 eye);

/* The solid angle of all the pieces, and each in omega[] (may be NULL). */
double cdl_glare_parts_solid_angle(const cdl_glare_parts *parts, cdl_vec3 eye, double omega[CDL_GLARE_PARTS_MAX]);

/* A point on the pieces seen from `eye` for (u1, u2, u3) in [0, 1)^3, and
 * its weight (above); omega[] and total from cdl_glare_parts_solid_angle
 * (total > 0). Returns 0 when no point could be drawn. */
int cdl_glare_parts_sample(const cdl_glare_parts *parts, const double omega[CDL_GLARE_PARTS_MAX], double total,
                           cdl_vec3 eye, const double u[3], cdl_vec3 *point, double *weight);

#endif
