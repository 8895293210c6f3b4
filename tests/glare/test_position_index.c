/* Guth's position index (glare/position_index.h): CIE 117:1995 Table 4.1
 * at its cells and between them by hand, the zones outside it, and the
 * whole table against the Luckiesh-Guth formula it tabulates. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "glare/position_index.h"
#include "radiometry/constants.h"

/* The position index by the Luckiesh-Guth formula as fitted by R. E.
 * Levin ("Position index in VCP calculations", J. IES 4(2), 1975):
 * ln p = (35.2 - 0.31889 tau - 1.22 e^(-2 tau / 9)) 1e-3 sigma + (21 +
 * 0.26667 tau - 0.002963 tau^2) 1e-5 sigma^2, sigma the angle (degrees)
 * between the line of sight and the source, tau the angle of the plane
 * through both from the vertical. */
static double levin(double R, double T, double H)
{
    double sigma = acos(R / sqrt(R * R + T * T + H * H)) * CDL_RAD_TO_DEG;
    double tau = (T == 0.0 && H == 0.0) ? 0.0 : atan2(fabs(T), H) * CDL_RAD_TO_DEG;
    return exp((35.2 - 0.31889 * tau - 1.22 * exp(-2.0 * tau / 9.0)) * 1e-3 * sigma +
               (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
}

static void test_cells_and_interpolation(void)
{
    double p;
    /* straight ahead: p = 1 by definition */
    CHECK(cdl_glare_position_index(5.0, 0.0, 0.0, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 1.0, 1e-15);
    /* on a node: T/R 1.0, H/R 0.5 is 3.91 in the table; T/R 2.0, H/R 1.0 is 8.90 */
    CHECK(cdl_glare_position_index(4.0, 4.0, 2.0, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 3.91, 1e-12);
    CHECK(cdl_glare_position_index(2.0, -4.0, 2.0, &p) == CDL_GLARE_IN_VIEW); /* either side */
    CHECK_ABS(p, 8.90, 1e-12);
    /* between nodes, by hand: T/R 0.25, H/R 0.35 is the mean of the cells
     * (0.2, 0.3) 1.80, (0.3, 0.3) 1.97, (0.2, 0.4) 2.20, (0.3, 0.4) 2.25 = 2.055 */
    CHECK(cdl_glare_position_index(2.0, 0.5, 0.7, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 2.055, 1e-12);
    /* a quarter of the way in T/R and three quarters in H/R from (1.0,
     * 0.5) 3.91: (1.1, 0.5) 4.20, (1.0, 0.6) 4.40, (1.1, 0.6) 4.70:
     * 0.75 0.25 3.91 + 0.25 0.25 4.20 + 0.75 0.75 4.40 + 0.25 0.75 4.70 */
    double expected = 0.1875 * 3.91 + 0.0625 * 4.20 + 0.5625 * 4.40 + 0.1875 * 4.70;
    CHECK(cdl_glare_position_index(1.0, 1.025, 0.575, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, expected, 1e-12);
    /* the far edges are inside: T/R 3 exactly, H/R 1.9 exactly */
    CHECK(cdl_glare_position_index(1.0, 3.0, 0.0, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 4.22, 1e-12);
    CHECK(cdl_glare_position_index(1.0, 3.0, 1.9, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 16.00, 1e-12);
    /* on the line of a blank cell's neighbour: H/R 1.7 at T/R 0.1 (the
     * blank 1.8 column has no weight there) */
    CHECK(cdl_glare_position_index(10.0, 1.0, 17.0, &p) == CDL_GLARE_IN_VIEW);
    CHECK_ABS(p, 16.10, 1e-12);
}

static void test_zones(void)
{
    double p = -1.0;
    CHECK(cdl_glare_position_index(0.0, 1.0, 1.0, &p) == CDL_GLARE_BEHIND);
    CHECK(p == 0.0);
    CHECK(cdl_glare_position_index(-2.0, 0.0, 1.0, &p) == CDL_GLARE_BEHIND);
    CHECK(cdl_glare_position_index(NAN, 0.0, 1.0, &p) == CDL_GLARE_BEHIND);
    CHECK(cdl_glare_position_index(2.0, 0.0, -0.01, &p) == CDL_GLARE_BELOW);
    CHECK(cdl_glare_position_index(1.0, 3.01, 0.5, &p) == CDL_GLARE_BEYOND_T);
    CHECK(cdl_glare_position_index(1.0, -3.01, 0.5, &p) == CDL_GLARE_BEYOND_T);
    CHECK(cdl_glare_position_index(1.0, 1.0, 1.95, &p) == CDL_GLARE_ABOVE);
    /* inside the table's span but in its blank corner: T/R 0.1, H/R 1.85 */
    CHECK(cdl_glare_position_index(1.0, 0.1, 1.85, &p) == CDL_GLARE_ABOVE);
    CHECK(p == 0.0);
    CHECK(cdl_glare_position_index(1.0, 0.1, 1.85, NULL) == CDL_GLARE_ABOVE);
    CHECK(strcmp(cdl_glare_zone_name(CDL_GLARE_BEHIND), "behind the eye") == 0);
    CHECK(strcmp(cdl_glare_zone_name(CDL_GLARE_ABOVE), "above the position index table") == 0);
}

/* Every cell against Levin's fit of the formula the table tabulates: the
 * fit agrees with the table within 11 % (its own accuracy, the worst at
 * T/R 2.7, H/R 0.6, the cell that looks misprinted); a transcription
 * slip of a digit would stand out. The blank cells are where the table
 * says they are. */
static void test_table_against_formula(void)
{
    int blanks = 0;
    double worst = 0.0;
    for (int i = 0; i <= 30; ++i)
        for (int j = 0; j <= 19; ++j) {
            double cell = cdl_glare_position_index_cell(i, j);
            if (cell == 0.0) {
                ++blanks;
                continue;
            }
            double ratio = cell / levin(1.0, i / 10.0, j / 10.0);
            worst = fmax(worst, fabs(log(ratio)));
            CHECK_MSG(fabs(log(ratio)) < log(1.115), "cell T/R %.1f H/R %.1f: %.2f, formula %.3f", i / 10.0,
                      j / 10.0, cell, cell / ratio);
        }
    CHECK(blanks == 13); /* 1.8 and 1.9 for T/R 0 to 0.3, 1.9 for T/R 0.4 to 0.8 */
    CHECK(cdl_glare_position_index_cell(0, 18) == 0.0 && cdl_glare_position_index_cell(4, 18) == 16.00);
    CHECK(cdl_glare_position_index_cell(8, 19) == 0.0 && cdl_glare_position_index_cell(9, 19) == 16.00);
    CHECK(cdl_glare_position_index_cell(31, 0) == 0.0 && cdl_glare_position_index_cell(0, 20) == 0.0);
    /* and most cells far closer than the worst */
    CHECK(worst > 0.09 && worst < 0.11);
}

int main(void)
{
    test_cells_and_interpolation();
    test_zones();
    test_table_against_formula();
    return check_finish();
}
