/* Daylight skies through the scene file and the solver, against closed forms:
 *  - CIE type 5 (a = c = e = 0: the sky of uniform luminance L_z): pi L_z on
 *    a horizontal plane, pi L_z (1 + cos beta) / 2 on a plane tilted by beta
 *    (the isotropic sky's view factor), 0 facing straight down;
 *  - the sun of direct_normal_illuminance_lx where "sun" or "site" + "time"
 *    put it, with "north": a plane facing the sun (its normal computed here
 *    from the azimuth and altitude: the SPA report's example, zenith
 *    50.11162 and azimuth 194.34024 degrees) receives E_n in full, one a
 *    degree off E_n cos(1 deg); north along +x turns the sun with it;
 *  - a CIE sky scaled by its diffuse horizontal illuminance gives exactly
 *    that on an unobstructed horizontal plane;
 *  - a Perez sky from illuminances gives E_dh + E_dn sin(altitude) on a
 *    horizontal plane (the sky normalised to E_dh, as gendaylit does, and
 *    the sun's disk wholly above the plane).
 * Every one of these is exact in the solver (closed forms and the sky's
 * quadrature, 3e-8), checked to 1e-7.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/frame.h"
#include "solver/solve_fixture.h"

/* a unit direction from azimuth (eastward from north) and altitude, degrees,
 * given north and up = +z: east = north x up */
static cdl_vec3 direction(double az_deg, double alt_deg, cdl_vec3 north)
{
    cdl_vec3 up = cdl_vec3_make(0, 0, 1), east = cdl_vec3_cross(north, up);
    double az = az_deg * CDL_DEG_TO_RAD, h = alt_deg * CDL_DEG_TO_RAD;
    return cdl_vec3_add(cdl_vec3_scale(cdl_vec3_add(cdl_vec3_scale(north, cos(az)), cdl_vec3_scale(east, sin(az))),
                                       cos(h)),
                        cdl_vec3_scale(up, sin(h)));
}

static int solve(const char *luminaire, const cdl_vec3 *normals, int count, cdl_scene **scene, cdl_solution *sol)
{
    char points[2048] = "", json[4096];
    for (int i = 0; i < count; ++i) {
        char one[160];
        snprintf(one, sizeof one, "%s{\"p\": [0, 0, 0], \"n\": [%.17g, %.17g, %.17g]}", i ? ", " : "", normals[i].x,
                 normals[i].y, normals[i].z);
        strcat(points, one);
    }
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [%s], \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": "
             "[%s]}], \"solver\": {\"method\": \"direct\"}}",
             luminaire, points);
    return fixture_solve(json, scene, sol, 1);
}

/* the uniform upper-hemisphere sky on a plane of normal n */
static double uniform_sky(double L, cdl_vec3 n)
{
    return CDL_PI * L * 0.5 * (1.0 + n.z);
}

static void test_uniform_type_and_sun(void)
{
    cdl_vec3 north = cdl_vec3_make(1, 0, 0);
    cdl_vec3 sun = direction(90.0, 30.0, north); /* east of north = +x: -y */
    CHECK(fabs(sun.y + cos(30.0 * CDL_DEG_TO_RAD)) < 1e-15 && fabs(sun.x) < 1e-15);
    cdl_frame f = cdl_frame_from_normal(sun);
    double off = 1.0 * CDL_DEG_TO_RAD;
    cdl_vec3 normals[5] = {
        {0, 0, 1}, {0, 0, -1}, sun, cdl_frame_to_world(&f, cdl_vec3_make(sin(off), 0, cos(off))), cdl_vec3_neg(sun)};
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve("{\"type\": \"environment\", \"sky\": \"cie\", \"cie_type\": 5, \"zenith_luminance_cd_m2\": 4000, "
               "\"north\": [1, 0, 0], \"sun\": {\"azimuth_deg\": 90, \"altitude_deg\": 30}, "
               "\"direct_normal_illuminance_lx\": 70000}",
               normals, 5, &scene, &sol))
        return;
    const double *E = sol.grids[0].E;
    CHECK_REL(E[0], CDL_PI * 4000.0 + 70000.0 * 0.5, 1e-7);
    CHECK_ABS(E[1], 0.0, 1e-9);
    CHECK_REL(E[2], uniform_sky(4000.0, normals[2]) + 70000.0, 1e-7);
    CHECK_REL(E[3], uniform_sky(4000.0, normals[3]) + 70000.0 * cos(off), 1e-7);
    CHECK_REL(E[4], uniform_sky(4000.0, normals[4]), 1e-7);
    fixture_release(scene, &sol);
}

static void test_site_and_time(void)
{
    /* the SPA report's example: zenith 50.11162, azimuth 194.34024 */
    cdl_vec3 sun = direction(194.34024, 90.0 - 50.11162, cdl_vec3_make(0, 1, 0));
    cdl_vec3 normals[2] = {sun, {0, 0, 1}};
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve("{\"type\": \"environment\", \"sky\": \"cie\", \"cie_type\": 5, \"zenith_luminance_cd_m2\": 1000, "
               "\"site\": {\"latitude_deg\": 39.742476, \"longitude_deg\": -105.1786, \"elevation_m\": 1830.14, "
               "\"pressure_mbar\": 820, \"temperature_c\": 11, \"delta_t_s\": 67}, "
               "\"time\": \"2003-10-17T12:30:30-07:00\", \"direct_normal_illuminance_lx\": 90000}",
               normals, 2, &scene, &sol))
        return;
    /* within 1e-4 degrees of the report's sun: cos 1e-4 deg = 1 - 1.5e-12 */
    CHECK_REL(sol.grids[0].E[0], uniform_sky(1000.0, sun) + 90000.0, 1e-7);
    CHECK_REL(sol.grids[0].E[1], CDL_PI * 1000.0 + 90000.0 * cos(50.11162 * CDL_DEG_TO_RAD), 1e-7);
    CHECK(strstr(sol.plan_json, "NREL SPA") && strstr(sol.plan_json, "azimuth 194.340"));
    fixture_release(scene, &sol);
}

static void test_scaled_to_horizontal(void)
{
    cdl_vec3 normals[1] = {{0, 0, 1}};
    for (int type = 1; type <= 15; type += 7) {
        char lum[400];
        snprintf(lum, sizeof lum,
                 "{\"type\": \"environment\", \"sky\": \"cie\", \"cie_type\": %d, \"diffuse_horizontal_illuminance_lx\": "
                 "\"2 klx\", \"sun\": {\"azimuth_deg\": 200, \"altitude_deg\": 40}, \"maintenance_factor\": 0.9}",
                 type);
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve(lum, normals, 1, &scene, &sol)) continue;
        CHECK_REL(sol.grids[0].E[0], 0.9 * 2000.0, 1e-10);
        fixture_release(scene, &sol);
    }
}

static void test_perez_horizontal(void)
{
    cdl_vec3 normals[1] = {{0, 0, 1}};
    cdl_scene *scene;
    cdl_solution sol;
    if (!solve("{\"type\": \"environment\", \"sky\": \"perez\", \"direct_normal_illuminance_lx\": 65000, "
               "\"diffuse_horizontal_illuminance_lx\": 18000, \"dew_point_c\": 9, "
               "\"sun\": {\"azimuth_deg\": 160, \"altitude_deg\": 52}, \"day_of_year\": 140}",
               normals, 1, &scene, &sol))
        return;
    CHECK_REL(sol.grids[0].E[0], 18000.0 + 65000.0 * sin(52.0 * CDL_DEG_TO_RAD), 1e-7);
    CHECK(strstr(sol.plan_json, "Perez all-weather sky") && strstr(sol.plan_json, "(sun)"));
    fixture_release(scene, &sol);
}

int main(void)
{
    test_uniform_type_and_sun();
    test_site_and_time();
    test_scaled_to_horizontal();
    test_perez_horizontal();
    return check_finish();
}
