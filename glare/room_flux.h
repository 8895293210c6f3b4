/* room_flux.h - light in a rectangular room lit by a regular array of
 * luminaires on its ceiling, by the flux-transfer method of CIE 52:1982
 * that CIE 190:2010 (4.2) uses for the background luminance of its
 * standard rooms.
 *
 * The room is a box X x Y (floor) x H: its "floor" is the reference plane
 * (at the observer's eye, for glare), its "ceiling" the plane of the
 * luminaires, its walls the band of height H between them. Each of the
 * three surfaces is taken as uniformly lit and a Lambertian reflector, so
 * the flux they exchange follows from the configuration factors between
 * them: parallel opposed rectangles for floor and ceiling (Hamilton and
 * Morgan, NACA TN 2836, 1952; Howell's catalogue C-11), and the rest by
 * the summation and reciprocity rules. These are exactly the transfer
 * factors CIE 190's Table 5 tabulates (its k = 2.67 row, room 4H x 8H, is
 * reproduced to the printed three decimals: tests/glare/test_room_flux.c).
 *
 * The direct flux on the reference plane comes from the luminaire's
 * cumulative flux at gamma = 41.4, 60, 75.5 and 90 degrees (cos gamma =
 * 0.75, 0.5, 0.25, 0: four zones of equal solid angle) weighted by
 * geometric factors F_GL1..4 (CIE 190 eq. 9, CIE 52's "zonal multiplier"
 * method). CIE 190 prints the factors (its Table 4); here they are
 * computed, as what they are: the weights that integrate the array's
 * direct ratio D(u) against the cumulative flux interpolated by the
 * quartic through (u, Phi) = (1, 0), (0.75, Phi1), (0.5, Phi2), (0.25,
 * Phi3), (0, Phi4) in u = cos(gamma):
 *     F_GLi = int_0^1 D(u) (-l_i'(u)) du,   l_i the Lagrange basis,
 * so that the direct flux on the plane is exact for any luminaire whose
 * cumulative flux is such a quartic (a Lambertian one, Phi = 1 - u^2,
 * among them). D(u) is the fraction of the array's luminaires from which a
 * ray at cos(gamma) = u, averaged over azimuth, lands on the reference
 * plane, found exactly (the landing count is piecewise constant in
 * azimuth). With the array at spacing H (CIE 190's own SHR 1) this
 * reproduces Table 4's k = 2.67 row to its printed three decimals.
 *
 * Units: metres, lumens; factors dimensionless. Pure functions:
 * thread-safe. Errors: only memory (the caller passes a valid room).
 */
#ifndef CANDELA_GLARE_ROOM_FLUX_H
#define CANDELA_GLARE_ROOM_FLUX_H

#include <stddef.h>

#include "base/error.h"

/* A room: floor x_m by y_m, height h_m between the reference plane and
 * the luminaires' plane, all above 0; the luminaires at the centres of an
 * nx by ny grid of equal cells over the ceiling (nx, ny >= 1). */
typedef struct cdl_room {
    double x_m, y_m, h_m;
    size_t nx, ny;
} cdl_room;

/* Reflectances of the ceiling (the luminaires' plane), the walls and the
 * floor (the reference plane), each in [0, 1). */
typedef struct cdl_room_reflectances {
    double ceiling, walls, floor;
} cdl_room_reflectances;

/* Configuration factor from a rectangle a x b to the parallel rectangle
 * a x b directly opposite it at distance c (Hamilton and Morgan 1952). */
double cdl_room_parallel_factor(double a, double b, double c);

/* Transfer factors to the walls (CIE 190 eq. 8b): per lumen the floor, the
 * walls or the ceiling receive directly, the lumens the walls receive after
 * every interreflection, the walls' direct lumen itself excluded
 * (F_T,FW, F_T,WW-1, F_T,CW). */
typedef struct cdl_room_transfer {
    double floor_to_walls, walls_to_walls, ceiling_to_walls;
} cdl_room_transfer;

void cdl_room_transfer_factors(const cdl_room *room, const cdl_room_reflectances *rho, cdl_room_transfer *out);

/* D(u): the fraction of the array's luminaires from which a ray leaving
 * downwards at cos(gamma) = u in (0, 1], averaged over its azimuth, lands on
 * the reference plane; 0 for u <= 0. */
double cdl_room_direct_ratio(const cdl_room *room, double u);

/* The geometric factors F_GL1..4 of the array (above). CDL_ERR_INTERNAL
 * when out of memory. */
cdl_status cdl_room_geometric_factors(const cdl_room *room, double fgl[4], cdl_error *err);

/* The cosines of the four cumulative-flux angles the factors weigh:
 * 0.75, 0.5, 0.25, 0. */
extern const double cdl_room_zone_cosines[4];

#endif
