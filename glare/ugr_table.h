/* ugr_table.h - the standard UGR table of a luminaire (CIE 190:2010), as
 * makers print it in their catalogues.
 *
 * Standard conditions (CIE 190:2010 4.2, CIE 117:1995 4.5): rectangular
 * rooms X by Y, X across the observer's line of sight and Y along it, in
 * multiples of H = 2 m, the height of the luminaires above the eye; the 19
 * rooms 2H x 2H ... 12H x 8H; the luminaires in a regular array over the
 * whole ceiling, at spacing S = SHR x H in both directions (SHR 0.25 as
 * catalogues print, 1 in CIE 190's own example), half a spacing from the
 * walls; the observer at the middle of one wall (X side), eye 2 m below the
 * luminaires, looking horizontally along Y; the luminaires viewed
 * crosswise (their C0-C180 plane along the line of sight: a linear
 * luminaire's C90-C270 length across it) and endwise (turned 90 degrees);
 * reflectances ceiling / walls / floor 0.70/0.50/0.20, 0.70/0.30/0.20,
 * 0.50/0.50/0.20, 0.50/0.30/0.20, 0.30/0.30/0.20.
 *
 * In each room and view, by CIE 117:1995 eq. 4.1 (glare/ugr.h), every
 * luminaire of the array inside the position index table (glare/
 * position_index.h) contributes
 *     L^2 omega / p^2,  L = I(C, gamma) / A_p(C, gamma),  omega = A_p / r^2
 * (CIE 117 4.5: the luminance of the luminous parts, their projected area
 * A_p seen from the eye, r the distance), I the file's interpolated
 * intensity towards the eye and A_p that of the file's luminous opening
 * (cdl_luminous_opening_projected_area, sides and solids included); crosswise
 * the eye lies in the luminaire's C = atan(T/R) direction, endwise in C =
 * 90 - atan(T/R) (CIE 190 eq. 4.5, 4.6), gamma = atan(sqrt(R^2 + T^2)/H).
 *
 * The background luminance is CIE 190's (4.2, eq. 7 to 12): Lb = E_WID /
 * pi, E_WID the walls' mean indirect illuminance,
 *     E_WID = N (Phi_F F_T,FW + Phi_W F_T,WW-1 + Phi_C F_T,CW) / A_W,
 * N the luminaires, A_W = 2 H (X + Y) the walls between the eye's plane and
 * the luminaires', Phi_F the lumens of one luminaire falling directly on
 * the eye's plane (the geometric factors of glare/room_flux.h against the
 * file's cumulative flux to 41.4, 60, 75.5 and 90 degrees), Phi_W the rest
 * of its downward lumens (on the walls), Phi_C its upward lumens (on the
 * ceiling), and the transfer factors F_T of the room's three surfaces
 * (glare/room_flux.h). Two choices, said here: the cumulative fluxes are
 * the exact integrals of the interpolated table (CIE 190 sums 10-degree
 * zones at their mid-angles; the two differ by about 0.1 % of the flux);
 * and the geometric factors are those of the array being rated (at SHR
 * 0.25 too, where CIE 190's Table 4 holds the SHR 1 array's; the direct
 * flux on the plane then differs by about 2 %, 0.04 UGR).
 *
 * Flux and luminance are the luminaire's as the file gives them (absolute
 * candela, lamp flux applied for relative photometry) times the file's
 * output factor (ballast factor), as the solver lights a scene: a catalogue
 * table is "corrected" to the luminaire's real flux, not to 1000 lm.
 *
 * Units: metres, lumens, cd/m^2. The computation reads the photometry
 * only: thread-safe. Errors: CDL_ERR_INPUT when the file cannot be rated
 * (no luminous opening, radiometric data, no light), the message saying
 * why; CDL_ERR_USAGE for options out of range; CDL_ERR_INTERNAL for memory.
 */
#ifndef CANDELA_GLARE_UGR_TABLE_H
#define CANDELA_GLARE_UGR_TABLE_H

#include <stddef.h>

#include "base/error.h"
#include "lights/photometry/photometry.h"

#define CDL_UGR_TABLE_ROOMS 19
#define CDL_UGR_TABLE_REFLECTANCE_SETS 5
#define CDL_UGR_TABLE_HEIGHT_M 2.0 /* H: luminaires above the eye (CIE 190 4.2) */


/* Set `size` to sizeof(cdl_ugr_table_options) (CDL_UGR_TABLE_OPTIONS_INIT):
 * fields past an older program's size keep their defaults. */
typedef struct cdl_ugr_table_options {
    size_t size;
    double spacing_to_height; /* SHR, luminaire spacing / H: 0.25 (catalogues), 1 (CIE 190's
                               * worked example); 1 / SHR times every room's side in H must be
                               * whole (1/SHR in {1, 2, 4, 8, ...} or any divisor of all of them) */
} cdl_ugr_table_options;

#define CDL_UGR_TABLE_OPTIONS_INIT {.size = sizeof(cdl_ugr_table_options), .spacing_to_height = 0.25}

typedef struct cdl_ugr_table_room {
    double x_h, y_h;          /* X across the line of sight, Y along it, in multiples of H */
    size_t luminaires;        /* N of the array */
    double room_index;        /* k = X Y / (H (X + Y)) */
    double direct_floor_lm;   /* Phi_F, Phi_W, Phi_C of one luminaire */
    double direct_walls_lm;
    double direct_ceiling_lm;
    double background_cd_m2[CDL_UGR_TABLE_REFLECTANCE_SETS];
    int defined[2];           /* [0] crosswise, [1] endwise: 0 when no luminaire in view sends light to the eye */
    double ugr[2][CDL_UGR_TABLE_REFLECTANCE_SETS];
} cdl_ugr_table_room;

/* The table. Set `size` to sizeof(cdl_ugr_table) before the call
 * (CDL_UGR_TABLE_INIT): the library fills only the fields that size covers. */
typedef struct cdl_ugr_table {
    size_t size;
    double spacing_to_height;
    double output_factor;     /* applied to flux and luminance */
    double flux_lm;           /* the luminaire's flux, output factor applied */
    double reflectances[CDL_UGR_TABLE_REFLECTANCE_SETS][3]; /* each set's ceiling, walls, floor */
    cdl_ugr_table_room rooms[CDL_UGR_TABLE_ROOMS];
} cdl_ugr_table;

#define CDL_UGR_TABLE_INIT {.size = sizeof(cdl_ugr_table)}

/* Fill *table (caller's, its size set) for the photometry; options NULL for
 * the defaults (SHR 0.25). */
cdl_status cdl_ugr_table_compute(const cdl_photometry *photometry, const cdl_ugr_table_options *options,
                                 cdl_ugr_table *table, cdl_error *err);

#endif
