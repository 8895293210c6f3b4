/* Goniometric emitter: a type C table placed and turned as DESIGN.md says,
 * probed against hand-computed I(C, gamma) cos(theta) / d^2, its factors,
 * and its flux three ways. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "lights/photometry/photometry.h"
#include "radiometry/constants.h"

/* A full (asymmetric) table: C every 30 degrees over 0..360, gamma every 10
 * over 0..180, I = 1000 (1 + 0.5 cos C + 0.2 sin 2C) (1 + cos gamma) / 2 + 10,
 * so every (C, gamma) node has its own value and I(gamma = 0) does not
 * depend on C (a real nadir). */
static double table_value(double C, double g)
{
    double c = C * CDL_DEG_TO_RAD, r = g * CDL_DEG_TO_RAD;
    return 1000.0 * (1.0 + 0.5 * cos(c) * sin(r) + 0.2 * sin(2 * c) * sin(r)) * 0.5 * (1.0 + cos(r)) + 10.0;
}

static cdl_photometry *make_table(void)
{
    double C[13], G[19], cd[13 * 19];
    for (int i = 0; i < 13; ++i) C[i] = 30.0 * i;
    for (int j = 0; j < 19; ++j) G[j] = 10.0 * j;
    for (int i = 0; i < 13; ++i)
        for (int j = 0; j < 19; ++j) cd[i * 19 + j] = table_value(C[i], G[j]);
    cdl_photometry *ph = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(C, 13, G, 19, cd, &ph, &err), &err);
    return ph;
}

static cdl_emitter *place(const cdl_photometry *ph, cdl_vec3 pos, double rx, double ry, double rz)
{
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.position = pos;
    p.rotation_deg[0] = rx;
    p.rotation_deg[1] = ry;
    p.rotation_deg[2] = rz;
    p.photometry = ph;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    return e;
}

/* Rodrigues: v turned by angle (degrees, right-handed) about unit axis k. */
static cdl_vec3 turn(cdl_vec3 v, cdl_vec3 k, double deg)
{
    double t = deg * CDL_DEG_TO_RAD, c = cos(t), s = sin(t);
    return cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(v, c), cdl_vec3_scale(cdl_vec3_cross(k, v), s)),
                        cdl_vec3_scale(k, cdl_vec3_dot(k, v) * (1 - c)));
}

/* The photometric direction of (C, gamma): (sin g cos C, sin g sin C, -cos g). */
static cdl_vec3 photometric_dir(double C, double g)
{
    double c = C * CDL_DEG_TO_RAD, r = g * CDL_DEG_TO_RAD;
    return cdl_vec3_make(sin(r) * cos(c), sin(r) * sin(c), -cos(r));
}

static void test_documented_tilt_example(void)
{
    /* [0, -30, 0] tilts the nadir from -z towards +x. */
    cdl_photometry *ph = make_table();
    cdl_vec3 pos = {1.0, 2.0, 3.0};
    cdl_emitter *e = place(ph, pos, 0.0, -30.0, 0.0);
    CHECK_REL(cdl_emitter_goniometric_tilt_deg(e), 30.0, 1e-13);
    /* Along the turned nadir (sin 30, 0, -cos 30), 2 m away, facing the
     * luminaire: E = I(gamma = 0) / 2^2. */
    cdl_vec3 nadir = {0.5, 0.0, -sqrt(3.0) / 2.0};
    cdl_delta_light dl;
    cdl_emitter_eval_delta(e, cdl_vec3_madd(pos, 2.0, nadir), cdl_vec3_neg(nadir), &dl);
    CHECK_REL(dl.E.lx, table_value(0, 0) / 4.0, 1e-12);
    /* Straight below, 3 m down on the floor: world -z is gamma = 30 in the
     * C = 180 half-plane (the luminaire leans towards +x, so "down" lies on
     * its -x side): E = I(180, 30) cos(0) / 3^2. */
    cdl_emitter_eval_delta(e, cdl_vec3_make(1.0, 2.0, 0.0), cdl_vec3_make(0, 0, 1), &dl);
    CHECK_REL(dl.E.lx, table_value(180, 30) / 9.0, 1e-12);
    /* Towards world +x horizontally: gamma = 60 in the C = 0 half-plane;
     * on a vertical receiver facing -x at 4 m: E = I(0, 60) / 16. */
    cdl_emitter_eval_delta(e, cdl_vec3_add(pos, cdl_vec3_make(4, 0, 0)), cdl_vec3_make(-1, 0, 0), &dl);
    CHECK_REL(dl.E.lx, table_value(0, 60) / 16.0, 1e-12);
    cdl_emitter_release(e);

    /* About z by 90: the C = 0 plane now faces world +y, so world +x is C = 270. */
    e = place(ph, pos, 0, 0, 90);
    CHECK_ABS(cdl_emitter_goniometric_tilt_deg(e), 0.0, 1e-12);
    cdl_vec3 w = {sin(40 * CDL_DEG_TO_RAD), 0, -cos(40 * CDL_DEG_TO_RAD)};
    CHECK_REL(cdl_emitter_intensity(e, w).cd, table_value(270, 40), 1e-12);
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

static void test_rotated_probes(void)
{
    /* Arbitrary rotations: a table node (C, gamma) must land on world
     * direction Rz Ry Rx d(C, gamma), built here with Rodrigues' formula
     * about the fixed axes, x first. Receivers at 0.5 to 50 m, tilted by
     * theta from the direction to the light: E = I(C, gamma) cos(theta) / d^2. */
    cdl_photometry *ph = make_table();
    double rots[][3] = {{20, -30, 45}, {-90, 0, 0}, {180, 10, -120}, {5, 5, 5}};
    double nodes[][2] = {{60, 40}, {0, 0}, {150, 90}, {270, 170}, {330, 20}};
    cdl_vec3 X = {1, 0, 0}, Y = {0, 1, 0}, Z = {0, 0, 1};
    cdl_vec3 pos = {-2.0, 0.5, 4.0};
    for (size_t r = 0; r < sizeof rots / sizeof rots[0]; ++r) {
        cdl_emitter *e = place(ph, pos, rots[r][0], rots[r][1], rots[r][2]);
        /* Installed tilt from the turned nadir. */
        cdl_vec3 nadir = turn(turn(turn(cdl_vec3_make(0, 0, -1), X, rots[r][0]), Y, rots[r][1]), Z, rots[r][2]);
        CHECK_ABS(cdl_emitter_goniometric_tilt_deg(e), acos(-nadir.z) * CDL_RAD_TO_DEG, 1e-10);
        for (size_t k = 0; k < sizeof nodes / sizeof nodes[0]; ++k) {
            double C = nodes[k][0], g = nodes[k][1];
            cdl_vec3 w = turn(turn(turn(photometric_dir(C, g), X, rots[r][0]), Y, rots[r][1]), Z, rots[r][2]);
            double d = 0.5 * pow(10.0, (double)k / 2.0), theta = 10.0 * k;
            cdl_vec3 p = cdl_vec3_madd(pos, d, w);
            cdl_frame f = cdl_frame_from_normal(cdl_vec3_neg(w));
            cdl_vec3 n = cdl_frame_to_world(&f, cdl_vec3_make(sin(theta * CDL_DEG_TO_RAD), 0, cos(theta * CDL_DEG_TO_RAD)));
            cdl_delta_light dl;
            cdl_emitter_eval_delta(e, p, n, &dl);
            /* Rounding in the rotations moves the direction by ~1e-15 rad;
             * the table's slope is ~1e3 cd/rad: 1e-11 relative is ample. */
            CHECK_REL(dl.E.lx, table_value(C, g) * cos(theta * CDL_DEG_TO_RAD) / (d * d), 1e-11);
        }
        cdl_emitter_release(e);
    }
    /* Between nodes the table is bilinear in C and gamma: at (45, 15),
     * the mean of the four surrounding nodes. */
    cdl_emitter *e = place(ph, pos, 20, -30, 45);
    cdl_vec3 w = turn(turn(turn(photometric_dir(45, 15), X, 20), Y, -30), Z, 45);
    double want = 0.25 * (table_value(30, 10) + table_value(60, 10) + table_value(30, 20) + table_value(60, 20));
    CHECK_REL(cdl_emitter_intensity(e, w).cd, want, 1e-11);
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

static void test_factors_and_flux(void)
{
    cdl_photometry *ph = make_table();
    double table_flux = cdl_photometry_flux(ph).lm;
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.position = cdl_vec3_make(0, 0, 3);
    p.rotation_deg[0] = 15;
    p.rotation_deg[1] = -40;
    p.rotation_deg[2] = 70;
    p.photometry = ph;
    p.multiplier = 2.0;
    p.maintenance_factor = 0.8;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    double Phi = cdl_emitter_flux(e).lm;
    /* 1. Closed form: multiplier x MF x the table's exact flux (a table
     * from arrays has no ballast or tilt factor: both 1). */
    CHECK_REL(Phi, 2.0 * 0.8 * table_flux, 1e-14);
    /* 2. Quadrature of the turned intensity over the sphere: bilinear
     * interpolation has kinks along the grid lines, so the midpoint rule is
     * O(h^2) there: ~1e-6 with 1000 x 2000 cells; 2e-5 leaves margin. */
    CHECK_REL(sphere_quadrature(intensity_of, e, 1000), Phi, 2e-5);
    /* 3. Monte Carlo with eval_delta on a sphere of radius 1.5 m around the
     * luminaire, uniform points (pdf 1 / (4 pi r^2) in area), 65536 samples:
     * 5 standard errors. */
    double mean, se;
    delta_flux_on_sphere(e, p.position, 1.5, 65536, 8, &mean, &se);
    CHECK_MSG(fabs(mean - Phi) <= 5 * se, "MC %g vs %g (se %g)", mean, Phi, se);
    CHECK(se < 0.01 * Phi);

    /* flux_lm rescales the table first, then the factors act: 3000 lm x 2 x
     * 0.8, and in every direction I = (3000 / table flux) x the unscaled I. */
    p.flux_lm = 3000.0;
    cdl_emitter *scaled = NULL;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &scaled, &err), &err);
    CHECK_REL(cdl_emitter_flux(scaled).lm, 3000.0 * 1.6, 1e-14);
    cdl_vec3 dirs[3] = {{0.2, 0.3, -1}, {1, 0, 0}, {-0.3, 0.9, 0.1}};
    for (int k = 0; k < 3; ++k)
        CHECK_REL(cdl_emitter_intensity(scaled, dirs[k]).cd, 3000.0 / table_flux * cdl_emitter_intensity(e, dirs[k]).cd,
                  1e-14);
    cdl_emitter_release(scaled);
    cdl_emitter_release(e);

    /* Bad parameters. */
    p.flux_lm = 0.0;
    p.maintenance_factor = 0.0;
    CHECK(cdl_emitter_create_goniometric(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "maintenance_factor"), "%s", err.message);
    p.maintenance_factor = 1.0;
    p.multiplier = -1.0;
    CHECK(cdl_emitter_create_goniometric(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "multiplier"), "%s", err.message);
    p.multiplier = 1.0;
    p.rotation_deg[1] = NAN;
    CHECK(cdl_emitter_create_goniometric(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "rotation[1]"), "%s", err.message);
    p.rotation_deg[1] = 0;
    p.photometry = NULL;
    CHECK(cdl_emitter_create_goniometric(&p, &e, &err) == CDL_ERR_USAGE);
    cdl_photometry_release(ph);
}

/* A small LM-63-2002 file: TILT=INCLUDE with factors 1, 0.8, 0.5 at 0, 45,
 * 90 degrees; ballast factor 0.9; a rotationally symmetric distribution. */
static const char tilted_ies[] =
    "IESNA:LM-63-2002\r\n"
    "[TEST] emitter tilt and ballast factors\r\n"
    "TILT=INCLUDE\r\n"
    "1\r\n"
    "3\r\n"
    "0 45 90\r\n"
    "1.0 0.8 0.5\r\n"
    "1 1000 1 3 1 1 2 0 0 0\r\n"
    "0.9 1 100\r\n"
    "0 45 90\r\n"
    "0\r\n"
    "100 80 50\r\n";

static void test_file_factors(void)
{
    cdl_photometry *ph = NULL;
    cdl_error err;
    cdl_photometry_read_options opts = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    CHECK_OK(cdl_photometry_read_memory(tilted_ies, sizeof tilted_ies - 1, "tilted.ies", &opts, &ph, &err), &err);
    if (!ph) return;
    CHECK_REL(cdl_photometry_output_factor(ph), 0.9, 1e-15);
    double table_flux = cdl_photometry_flux(ph).lm;
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.position = cdl_vec3_make(0, 0, 3);
    p.photometry = ph;
    p.rotation_deg[1] = -30.0; /* installed 30 degrees from nadir-down */
    p.multiplier = 2.0;
    p.maintenance_factor = 0.75;
    cdl_emitter *e = NULL;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    /* Tilt factor at 30 degrees, by hand: linear between (0, 1) and (45, 0.8). */
    double tilt = 1.0 - 30.0 / 45.0 * 0.2;
    double k = 0.9 * tilt * 2.0 * 0.75;
    CHECK_REL(cdl_emitter_flux(e).lm, k * table_flux, 1e-13);
    /* Along the turned nadir, 2 m away: E = I(0) k / 4 = 100 k / 4. */
    cdl_vec3 nadir = {0.5, 0, -sqrt(3.0) / 2};
    cdl_delta_light dl;
    cdl_emitter_eval_delta(e, cdl_vec3_madd(p.position, 2.0, nadir), cdl_vec3_neg(nadir), &dl);
    CHECK_REL(dl.E.lx, 100.0 * k / 4.0, 1e-12);
    cdl_emitter_release(e);
    /* Without the output factor, and untilted (factor 1 at 0 degrees). */
    p.apply_output_factor = 0;
    p.rotation_deg[1] = 0.0;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    CHECK_REL(cdl_emitter_flux(e).lm, 2.0 * 0.75 * table_flux, 1e-13);
    cdl_emitter_release(e);
    /* Upside down (180 degrees about x): the TILT table is clamped at its
     * last entry, 0.5 at 90 degrees. flux_lm rescales before the factors. */
    p.rotation_deg[0] = 180.0;
    p.flux_lm = 500.0;
    p.apply_output_factor = 1;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    CHECK_REL(cdl_emitter_goniometric_tilt_deg(e), 180.0, 1e-13);
    CHECK_REL(cdl_emitter_flux(e).lm, 500.0 * 0.9 * 0.5 * 2.0 * 0.75, 1e-13);
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

int main(void)
{
    test_file_factors();
    test_documented_tilt_example();
    test_rotated_probes();
    test_factors_and_flux();
    return check_finish();
}
