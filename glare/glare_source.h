/* glare_source.h - one luminaire seen from an observer's eye, as CIE
 * 117:1995 rates it: where it lies in the field of view (R, T, H and the
 * position index p), the luminance of its luminous parts towards the eye,
 * and their solid angle.
 *
 *   L      = I(w) / A_p(w)      the luminance of a source seen as a whole
 *                               (CIE S 017 17-21-050; CIE 117 4.5): the
 *                               intensity towards the eye w over the
 *                               luminous opening's area projected across w
 *   omega  the solid angle the luminous parts subtend at the eye: exact for
 *          the flat openings (a rectangle as two spherical triangles, Van
 *          Oosterom and Strackee 1983; a circle or ellipse as a 256-gon of
 *          the same area, within 1e-6 of the curve's), for a box (the faces
 *          the eye sees, each at its luminous height) and for a sphere (its
 *          cap, 2 pi (1 - cos a)); CIE 117's A_p / r^2 for the other solids
 *          (cylinders, ellipsoids), flagged.
 * Nothing here hides a source: surfaces between the eye and the luminaire
 * are the solver's business.
 *
 * The luminaire is placed by its photometric centre (the middle of its
 * opening) and its axes in the world: x along C0, y along C90, z up (the
 * nadir is -z). Units: metres, candela, cd/m^2, sr. Pure functions of
 * their arguments (the photometry is only read): thread-safe. Errors:
 * none.
 */
#ifndef CANDELA_GLARE_GLARE_SOURCE_H
#define CANDELA_GLARE_GLARE_SOURCE_H

#include "glare/glare_parts.h"
#include "glare/position_index.h"
#include "glare/ugr.h"
#include "lights/photometry/photometry.h"
#include "radiometry/vec3.h"

/* An observer: the eye, and the line of sight (unit, horizontal: z = 0). */
typedef struct cdl_glare_observer {
    cdl_vec3 eye;
    cdl_vec3 forward;
} cdl_glare_observer;

typedef struct cdl_glare_luminaire {
    const cdl_photometry *photometry;
    cdl_vec3 position; /* the photometric centre, world */
    cdl_vec3 axis[3];  /* the luminaire's x (C0), y (C90), z (up) in world: orthonormal, right-handed */
    double scale;      /* factor on the table's intensity (multiplier, maintenance, output factor) */
} cdl_glare_luminaire;

typedef struct cdl_glare_source {
    cdl_glare_zone zone;       /* where the centre lies (position_index.h) */
    double R_m, T_m, H_m;      /* the centre along the line of sight, across it (+ to the right), above it */
    double c_deg, gamma_deg;   /* the eye's direction in the luminaire's photometric frame */
    cdl_luminous_intensity intensity; /* I(w), scale applied */
    double projected_area_m2;  /* A_p(w) */
    cdl_luminance luminance;   /* I / A_p; 0 where A_p is 0 */
    double omega_sr;           /* solid angle of the luminous parts */
    int omega_exact;           /* 1: exact (above); 0: A_p / r^2 */
    double p;                  /* position index; 0 out of view */
    cdl_ugr_term term;         /* L^2 omega / p^2; 0 out of view or dark */
} cdl_glare_source;

/* The luminous parts of a goniometric luminaire's opening in the world as
 * an eye sees them (glare_parts.h): a flat opening (rectangle, circle,
 * ellipse, LM-63-2019's vertical circle or ellipse) as itself; a box as
 * its six faces, each side at its luminous height; a sphere as the disk
 * across its tangent cone through its centre (the same solid angle,
 * exactly); the other solids (cylinders, ellipsoids) as the disk facing
 * the eye of their projected area, *exact = 0 (then omega = A_p / r^2 as
 * CIE 117 4.5 takes it); *exact = 1 otherwise. No parts for a point. */
void cdl_glare_opening_parts(const cdl_glare_luminaire *luminaire, cdl_vec3 eye, cdl_glare_parts *parts, int *exact);

/* The source as the observer sees it. */
void cdl_glare_source_evaluate(const cdl_glare_luminaire *luminaire, const cdl_glare_observer *observer,
                               cdl_glare_source *source);

/* The observer's coordinates of a point q: *R along the line of sight,
 * *T across it (to the right of it looking along it), *H above it. */
void cdl_glare_observer_coordinates(const cdl_glare_observer *observer, cdl_vec3 q, double *R, double *T, double *H);

#endif
