/* reinhart_patches.h - the sky cut into Tregenza and Reinhart patches, the
 * basis of daylight coefficients (private to lights/ and its callers).
 *
 * Tregenza's 145 patches (Tregenza, "Subdivision of the sky hemisphere for
 * luminance measurements", Lighting Research and Technology 19(1), 1987):
 * seven rows of 12 degrees of altitude from the horizon, holding 30, 30,
 * 24, 24, 18, 12 and 6 patches, and a cap over the zenith. Reinhart's
 * subdivision (as Radiance's reinhartb.cal defines it) splits each row into
 * MF rows and each patch of them into MF across, the cap staying one patch:
 * 144 MF^2 + 1 sky patches (MF 1: 145, MF 2: 577, MF 4: 2305). The rows
 * are alpha = 90 / (7 MF + 0.5) degrees high (12 for MF 1, 6.207 for MF 2,
 * 3.103 for MF 4), the cap half a row. Row r (0 from the horizon) holds MF
 * times Tregenza's count of row floor((r + 0.5) / MF).
 *
 * Numbering (our convention, stated because tools differ): index 0 is the
 * ground, every direction below the horizon (as Radiance's rfluxmtx counts
 * it: 146, 578 and 2306 columns in all); then the sky patches row by row
 * from the horizon up, the cap last; within a row patch 0 is centred on
 * north and the others follow eastwards (azimuth eastward from north, as
 * the sun's). A patch is the region
 *     altitude in [r alpha, (r + 1) alpha), azimuth in [(k - 1/2) w, (k + 1/2) w),
 * w = 360 / n degrees, n the row's count.
 *
 * Frame: up, and north perpendicular to it; locally x = north, y = west
 * (up x north), z = up, so that a patch is a cell of polar angle theta =
 * 90 - altitude and of local azimuth phi = -(azimuth), counter-clockwise
 * seen from above, as lights/environment's lat-long cells are
 * (environment_pixels.h: cdl_env_cell_projected_solid_angle).
 *
 * Thread safety: immutable after init; every query is pure.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_REINHART_PATCHES_H
#define CANDELA_LIGHTS_ENVIRONMENT_REINHART_PATCHES_H

#include "base/error.h"
#include "radiometry/frame.h"
#include "radiometry/vec3.h"

/* The largest subdivision accepted (MF 8: 9217 sky patches). */
#define CDL_REINHART_MAX_MF 8
#define CDL_REINHART_MAX_ROWS (7 * CDL_REINHART_MAX_MF + 1)

/* Index of the ground in every numbering. */
#define CDL_REINHART_GROUND 0

typedef struct cdl_reinhart_patches {
    int mf;                                   /* subdivision factor, 1..CDL_REINHART_MAX_MF */
    int rows;                                 /* 7 MF + 1, the cap last */
    int count;                                /* ground + sky patches: 144 MF^2 + 2 */
    double alpha;                             /* row height, radians */
    int row_count[CDL_REINHART_MAX_ROWS];     /* patches in each row */
    int row_first[CDL_REINHART_MAX_ROWS + 1]; /* index of each row's first patch; [rows] = count */
    cdl_frame frame;                          /* s north, t west, n up */
} cdl_reinhart_patches;

/* The patches of subdivision `mf` about unit `up` and `north` (north made
 * perpendicular to up; it must not lie along up). CDL_ERR_INPUT for an mf
 * out of 1..CDL_REINHART_MAX_MF or a north along up. */
cdl_status cdl_reinhart_init(cdl_reinhart_patches *p, int mf, cdl_vec3 up, cdl_vec3 north, cdl_error *err);

/* The patch holding unit world direction w (CDL_REINHART_GROUND below the
 * horizon, up.w < 0). */
int cdl_reinhart_patch_of(const cdl_reinhart_patches *p, cdl_vec3 w);

/* The patch of a place in the sky: altitude and azimuth (eastward from
 * north) in radians; the ground for a negative altitude. */
int cdl_reinhart_patch_at(const cdl_reinhart_patches *p, double altitude, double azimuth);

/* Patch k's extent (k >= 1): altitude [*alt_lo, *alt_hi], azimuth [*az_lo,
 * *az_hi] (radians; patch 0 of a row starts at a negative azimuth). */
void cdl_reinhart_patch_bounds(const cdl_reinhart_patches *p, int k, double *alt_lo, double *alt_hi, double *az_lo,
                               double *az_hi);

/* Its solid angle, sr: (sin alt_hi - sin alt_lo)(az_hi - az_lo); the
 * ground's is 2 pi. */
double cdl_reinhart_solid_angle(const cdl_reinhart_patches *p, int k);

/* The world direction at altitude and azimuth (radians). */
cdl_vec3 cdl_reinhart_direction(const cdl_reinhart_patches *p, double altitude, double azimuth);

/* Q_k(n): the projected solid angle of patch k about unit world normal n,
 * the part of the patch in front of n (int over the patch of max(0, n.w) dw),
 * in closed form (environment_pixels.h); the ground's likewise over the
 * lower hemisphere. */
double cdl_reinhart_projected_solid_angle(const cdl_reinhart_patches *p, int k, cdl_vec3 n);

/* Most vertices of a polygon cdl_reinhart_add_polygon takes. */
#define CDL_REINHART_POLYGON_MAX 36

/* For every patch (ground included) the projected solid angle about unit
 * world normal n of its part inside the convex spherical polygon poly[0 ..
 * count) (unit world directions, edges the shorter great-circle arcs,
 * either orientation, within the hemisphere of n), times `weight`, added
 * to out[k] (p->count entries): exact (environment_peaks.h's cell and
 * polygon contour, the cap and the ground in quarters); only the patches
 * the polygon's extent in altitude and azimuth reaches are visited.
 * Returns 0, adding nothing, for fewer than 3 or more than
 * CDL_REINHART_POLYGON_MAX vertices. */
int cdl_reinhart_add_polygon(const cdl_reinhart_patches *p, const cdl_vec3 *poly, int count, cdl_vec3 n,
                             double weight, double *out);

#endif
