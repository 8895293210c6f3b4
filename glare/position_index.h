/* position_index.h - where a glare source lies in the field of view, and
 * Guth's position index p there (CIE 117:1995, Table 4.1).
 *
 * The observer looks horizontally along the line of sight. A source at the
 * point q is placed by three distances from the eye (CIE 117:1995, Figure
 * 4.2): R along the line of sight, T across it (horizontal, either side),
 * H above it (vertical). p weighs the source's glare by where it is: 1 on
 * the line of sight, growing away from it (a source at p = 2 counts as one
 * a quarter as bright, L^2 / p^2, straight ahead).
 *
 * Table 4.1 tabulates p at T/R = 0, 0.1, ..., 3.0 and H/R = 0, 0.1, ...,
 * 1.9, and leaves the cells for steep sources near the line of sight's
 * vertical plane blank; p between the cells is interpolated bilinearly
 * (as CIE 117 4.3 asks). A source outside the table is out of the field of
 * view the rating covers, and contributes nothing:
 *   behind the eye            R <= 0
 *   below the line of sight   H < 0 (the table is for sources above it)
 *   beyond T/R = 3            more than 71.6 degrees to the side
 *   above the table           H/R > 1.9 (more than 62 degrees above the
 *                             line of sight), or in a blank cell
 *
 * Units: metres (any length unit: only the ratios matter). Pure functions
 * of their arguments: thread-safe. Errors: none.
 */
#ifndef CANDELA_GLARE_POSITION_INDEX_H
#define CANDELA_GLARE_POSITION_INDEX_H

typedef enum cdl_glare_zone {
    CDL_GLARE_IN_VIEW = 0, /* inside Table 4.1: p defined */
    CDL_GLARE_BEHIND,      /* R <= 0 */
    CDL_GLARE_BELOW,       /* H < 0 */
    CDL_GLARE_BEYOND_T,    /* T/R > 3 */
    CDL_GLARE_ABOVE        /* H/R > 1.9, or a blank cell of the table */
} cdl_glare_zone;

/* A short stable phrase for the zone ("in view", "behind the eye", "below
 * the line of sight", "beyond T/R = 3", "above the position index table");
 * static storage. */
const char *cdl_glare_zone_name(cdl_glare_zone zone);

/* The zone of a source at distances R (along the line of sight), T (across
 * it, either sign) and H (above it) from the eye, and in *p (may be NULL)
 * its position index when in view, 0 otherwise. Non-finite distances are
 * "behind the eye". */
cdl_glare_zone cdl_glare_position_index(double R, double T, double H, double *p);

/* Table 4.1 itself: the value at row i (T/R = i/10, 0..30) and column j
 * (H/R = j/10, 0..19); 0 for a blank cell or an index out of range. */
double cdl_glare_position_index_cell(int i, int j);

#endif
