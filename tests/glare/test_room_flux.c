/* The standard room's flux transfer (glare/room_flux.h): configuration
 * factors, transfer factors and the array's geometric factors, against
 * closed forms, independent quadratures and CIE 190:2010's printed rows. */
#include <math.h>

#include "check.h"
#include "gauss_legendre.h"
#include "glare/room_flux.h"
#include "polygon_factor.h"
#include "radiometry/constants.h"

/* The floor-to-ceiling factor as the mean over the floor of Lambert's
 * point-to-rectangle factor (its contour integral), by a product
 * Gauss-Legendre rule on 8 x 8 panels: an independent route to Hamilton
 * and Morgan's closed form. */
static double floor_to_ceiling_by_quadrature(double X, double Y, double H)
{
    cdl_vec3 ceiling[4] = {{0, 0, H}, {X, 0, H}, {X, Y, H}, {0, Y, H}};
    double sum = 0.0;
    for (int pi = 0; pi < 8; ++pi)
        for (int pj = 0; pj < 8; ++pj)
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    cdl_vec3 p = {X * (pi + gl8_x[a]) / 8.0, Y * (pj + gl8_x[b]) / 8.0, 0.0};
                    sum += gl8_w[a] * gl8_w[b] / 64.0 * lambert_polygon(ceiling, 4, 1.0, p, cdl_vec3_make(0, 0, 1)) / CDL_PI;
                }
    return sum;
}

static void test_parallel_factor(void)
{
    /* the quadrature's error on these smooth integrands is below 1e-9 */
    CHECK_ABS(cdl_room_parallel_factor(8.0, 16.0, 2.0), floor_to_ceiling_by_quadrature(8.0, 16.0, 2.0), 1e-8);
    CHECK_ABS(cdl_room_parallel_factor(1.0, 1.0, 1.0), floor_to_ceiling_by_quadrature(1.0, 1.0, 1.0), 1e-8);
    CHECK_ABS(cdl_room_parallel_factor(24.0, 4.0, 2.0), floor_to_ceiling_by_quadrature(24.0, 4.0, 2.0), 1e-8);
    /* a unit square one side apart: 0.19982 (Howell's catalogue C-11, tabulated) */
    CHECK_ABS(cdl_room_parallel_factor(1.0, 1.0, 1.0), 0.19982, 5e-6);
}

/* CIE 190:2010 Table 5, room 4H x 8H (k = 2.67): F_T,FW, F_T,WW-1, F_T,CW
 * for the five reflectance sets, as printed (three decimals). */
static void test_transfer_factors_against_cie190(void)
{
    static const double rho[5][3] = {{0.7, 0.5, 0.2}, {0.7, 0.3, 0.2}, {0.5, 0.5, 0.2}, {0.5, 0.3, 0.2}, {0.3, 0.3, 0.2}};
    static const double table5[5][3] = {{0.115, 0.211, 0.307}, {0.106, 0.117, 0.283}, {0.100, 0.187, 0.211},
                                        {0.093, 0.104, 0.196}, {0.081, 0.092, 0.114}};
    cdl_room room = {8.0, 16.0, 2.0, 4, 8};
    for (int s = 0; s < 5; ++s) {
        cdl_room_reflectances r = {rho[s][0], rho[s][1], rho[s][2]};
        cdl_room_transfer t;
        cdl_room_transfer_factors(&room, &r, &t);
        /* the table's rounding to three decimals: 5e-4, and a hair for ties */
        CHECK_ABS(t.floor_to_walls, table5[s][0], 5.01e-4);
        CHECK_ABS(t.walls_to_walls, table5[s][1], 5.01e-4);
        CHECK_ABS(t.ceiling_to_walls, table5[s][2], 5.01e-4);
    }
}

/* Limits with closed forms: black floor and ceiling leave the walls alone,
 * each lumen on them coming back rho f_WW / (1 - rho f_WW) times; black
 * walls stop everything reaching them (their reflections, but not the
 * first arrival: floor-to-walls is then the floor's reflected share
 * f_FW rho_F plus its bounce via the ceiling). */
static void test_transfer_limits(void)
{
    cdl_room room = {6.0, 10.0, 2.5, 3, 5};
    double X = room.x_m, Y = room.y_m, H = room.h_m;
    double f_fc = cdl_room_parallel_factor(X, Y, H), f_wf = (1.0 - f_fc) * X * Y / (2.0 * H * (X + Y));
    double f_ww = 1.0 - 2.0 * f_wf;
    cdl_room_reflectances walls_only = {0.0, 0.6, 0.0};
    cdl_room_transfer t;
    cdl_room_transfer_factors(&room, &walls_only, &t);
    /* rounding only: a few ulps of quantities of order 1 */
    CHECK_ABS(t.walls_to_walls, 0.6 * f_ww / (1.0 - 0.6 * f_ww), 1e-12);
    CHECK_ABS(t.floor_to_walls, 0.0, 1e-15);
    CHECK_ABS(t.ceiling_to_walls, 0.0, 1e-15);
    /* black walls: floor -> walls directly (rho_F f_FW), and via the
     * ceiling, the floor and ceiling ping-ponging: geometric series in
     * rho_F rho_C f_FC^2 */
    cdl_room_reflectances black_walls = {0.8, 0.0, 0.3};
    cdl_room_transfer_factors(&room, &black_walls, &t);
    double f_fw = 1.0 - f_fc, q = 0.3 * 0.8 * f_fc * f_fc;
    double expected = (0.3 * f_fw + 0.3 * f_fc * 0.8 * f_fw) / (1.0 - q);
    CHECK_ABS(t.floor_to_walls, expected, 1e-12);
    CHECK_ABS(t.walls_to_walls, 0.0, 1e-15);
}

/* One luminaire in the middle of a square 2a x 2a: a ray of reach rho
 * lands on the floor at every azimuth while rho < a, and between a and
 * a sqrt(2) for azimuths between acos(a / rho) and asin(a / rho) in each
 * quadrant. */
static void test_direct_ratio_single(void)
{
    double a = 1.5, H = 2.0;
    cdl_room room = {2.0 * a, 2.0 * a, H, 1, 1};
    CHECK_ABS(cdl_room_direct_ratio(&room, 1.0), 1.0, 0.0);
    CHECK_ABS(cdl_room_direct_ratio(&room, 0.0), 0.0, 0.0);
    double rho_in = 1.2, u_in = H / hypot(H, rho_in);
    CHECK_ABS(cdl_room_direct_ratio(&room, u_in), 1.0, 1e-15);
    double rho = 1.9, u = H / hypot(H, rho);
    double expected = (asin(a / rho) - acos(a / rho)) / (0.5 * CDL_PI);
    /* rounding of the reach and the angles only */
    CHECK_ABS(cdl_room_direct_ratio(&room, u), expected, 1e-12);
    double rho_out = 2.2, u_out = H / hypot(H, rho_out); /* beyond the corners: a sqrt(2) = 2.12 */
    CHECK_ABS(cdl_room_direct_ratio(&room, u_out), 0.0, 0.0);
}

/* CIE 190:2010 Table 4, room index k = 2.67 (4H x 8H): F_GL1..4 = 0.280,
 * 0.165, 0.499, 0.006 as printed. The table is for CIE 190's array at
 * spacing H (4 x 8 luminaires). */
static void test_geometric_factors_against_cie190(void)
{
    cdl_room room = {8.0, 16.0, 2.0, 4, 8};
    double fgl[4];
    cdl_error err;
    CHECK_OK(cdl_room_geometric_factors(&room, fgl, &err), &err);
    static const double table4[4] = {0.280, 0.165, 0.499, 0.006};
    /* the printed rounding (5e-4) and a hair */
    for (int i = 0; i < 4; ++i) CHECK_ABS(fgl[i], table4[i], 6e-4);
    /* square rooms and long ones alike are symmetric in x and y */
    cdl_room turned = {16.0, 8.0, 2.0, 8, 4};
    double fgl_turned[4];
    CHECK_OK(cdl_room_geometric_factors(&turned, fgl_turned, &err), &err);
    for (int i = 0; i < 4; ++i) CHECK_ABS(fgl_turned[i], fgl[i], 1e-12);
}

/* A Lambertian luminaire's cumulative flux, 1 - u^2 of its total, is a
 * quartic in u: the factors then give its direct ratio exactly, which is
 * also the mean over the array of Lambert's factor from each luminaire
 * (a point facing down) to the floor rectangle. */
static void test_lambertian_direct_ratio(void)
{
    static const double rooms[3][4] = {{8.0, 16.0, 2.0, 0.5}, {4.0, 4.0, 2.0, 2.0}, {24.0, 16.0, 2.0, 0.5}};
    for (int r = 0; r < 3; ++r) {
        double X = rooms[r][0], Y = rooms[r][1], H = rooms[r][2], s = rooms[r][3];
        cdl_room room = {X, Y, H, (size_t)lround(X / s), (size_t)lround(Y / s)};
        double fgl[4];
        cdl_error err;
        CHECK_OK(cdl_room_geometric_factors(&room, fgl, &err), &err);
        double by_factors = 0.0;
        for (int i = 0; i < 4; ++i)
            by_factors += fgl[i] * (1.0 - cdl_room_zone_cosines[i] * cdl_room_zone_cosines[i]);
        cdl_vec3 floor[4] = {{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}};
        double by_lambert = 0.0;
        for (size_t i = 0; i < room.nx; ++i)
            for (size_t j = 0; j < room.ny; ++j) {
                cdl_vec3 p = {(i + 0.5) * s, (j + 0.5) * s, H};
                by_lambert += lambert_polygon(floor, 4, 1.0, p, cdl_vec3_make(0, 0, -1)) / CDL_PI;
            }
        by_lambert /= (double)(room.nx * room.ny);
        /* the factors' quadrature (8-point Gauss-Legendre between D's
         * kinks, smoothed at their square-root ends): 2e-8 on these rooms */
        CHECK_ABS(by_factors, by_lambert, 5e-8);
    }
}

int main(void)
{
    test_parallel_factor();
    test_transfer_factors_against_cie190();
    test_transfer_limits();
    test_direct_ratio_single();
    test_geometric_factors_against_cie190();
    test_lambertian_direct_ratio();
    return check_finish();
}
