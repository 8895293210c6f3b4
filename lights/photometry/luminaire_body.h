/* luminaire_body.h - the solid a luminaire occupies, as its file describes it.
 *
 * A luminaire with a luminous opening is an obstacle to every other light
 * in a room, and its housing reflects. Its body, in the luminaire's frame
 * (x along the length, C0; y along the width, C90; z up; the origin at the
 * photometric centre; metres):
 *
 *   EULUMDAT (lines 13-15 give the luminaire's length or diameter, width
 *   (0: round) and height): a box L x W x H, or a vertical cylinder of
 *   diameter L and height H when round, its bottom at the bottom of the
 *   luminous area (z = 0 for a flat one, the box's bottom for sides
 *   luminous to a height), each size at least the luminous area's; a
 *   housing (`housing` 1). A height of 0 leaves it flat: the rectangle or
 *   disk L x W at z = 0.
 *   IES LM-63 (width, length and height are the luminous opening's alone),
 *   and EULUMDAT files that give no luminaire size: the opening's own shape
 *   (`housing` 0): a flat rectangle, circle or ellipse in the opening's
 *   plane (LM-63-2019's vertical ones in the y-z plane), or the luminous
 *   solid itself (box, vertical or horizontal (elliptic) cylinder, sphere,
 *   ellipsoid) about the centre.
 *
 * A flat body reflects on the side away from its opening (up for a
 * horizontal opening, which gives its light downward and any upward light
 * through the same plane; towards C180 (-x) for a vertical one facing C0):
 * the opening's own side is the diffuser the file measured, whose
 * reflectance no file gives. A point (no opening) has no body.
 */
#ifndef CANDELA_LIGHTS_LUMINAIRE_BODY_H
#define CANDELA_LIGHTS_LUMINAIRE_BODY_H

#include "lights/photometry/photometry.h"
#include "radiometry/vec3.h"

typedef enum cdl_body_kind {
    CDL_BODY_NONE = 0,        /* a point: no body */
    CDL_BODY_BOX,             /* the box [lo, hi] (a rectangle when flat) */
    CDL_BODY_CYLINDER,        /* the elliptic cylinder inscribed in [lo, hi] along `axis` (a disk or
                               * ellipse when flat) */
    CDL_BODY_ELLIPSOID        /* the ellipsoid inscribed in [lo, hi] (a sphere when its sides agree) */
} cdl_body_kind;

typedef struct cdl_luminaire_body {
    cdl_body_kind kind;
    cdl_vec3 lo, hi;          /* its bounding box in the luminaire's frame, m */
    int axis;                 /* cylinder: its axis, 0 x, 1 y, 2 z */
    int flat_axis;            /* -1: a solid; 0..2: flat, no extent along this axis */
    int front_sign;           /* flat: the reflecting side faces +1 or -1 along flat_axis */
    int housing;              /* 1: the luminaire's own sizes (EULUMDAT lines 13-15); 0: the opening's */
} cdl_luminaire_body;

/* The body a photometry describes (above); kind CDL_BODY_NONE for a point
 * or an unknown shape. Never fails. */
void cdl_luminaire_body_of(const cdl_photometry *photometry, cdl_luminaire_body *out);

/* Its shape in words with its sizes, for the plan and messages:
 * "box 1.2 x 0.06 x 0.05 m (the luminaire's, EULUMDAT)", "rectangle 1.2 x
 * 0.06 m (the luminous opening)". */
void cdl_luminaire_body_describe(const cdl_luminaire_body *body, char *out, size_t size);

/* 1 when every face is flat (a box or rectangle): the exact routes treat
 * it as planar occluders; 0 for curved bodies (cylinders, disks,
 * ellipsoids), which the direct light samples. */
int cdl_luminaire_body_is_planar(const cdl_luminaire_body *body);

#endif
