/* The scene's light hash sees every input of a daylight sky and of the sun's
 * disk: a stored irradiance cache (or a bench reference) made under one sky
 * must not be reused under another.
 *
 * Each case is a pair of scenes that differ in one daylight input only (the
 * sun's place, the CIE type, what scales the sky, the Perez inputs, the
 * disk's diameter): their light hashes differ, and their geometry and
 * materials hashes do not. The same scene loaded twice, its keys reordered,
 * hashes the same.
 */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene_lights_fixture.h"
#include "solver/scene/scene_hash.h"
#include "solver/scene/scene.h"
#include "solver/scene/scene_geometry.h"

#define GRID ", \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}"

static int hashes_of(const char *luminaire, cdl_scene_hashes *out)
{
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1,-1,2], \"u\": [2,0,0], "
             "\"v\": [0,2,0], \"reflectance\": 0.5}], \"luminaires\": [%s]" GRID,
             luminaire);
    cdl_error err;
    cdl_error_clear(&err);
    scene_lights_fixture f;
    cdl_status st = scene_lights_fixture_open(&f, json, CANDELA_TEST_TMPDIR "/hash.json", &err);
    if (st == CDL_OK) st = cdl_scene_hash(f.scene, &f.lights, out, &err);
    CHECK_MSG(st == CDL_OK, "%s: %s", luminaire, err.message);
    scene_lights_fixture_close(&f);
    return st == CDL_OK;
}

/* a and b differ in their lights only */
static void expect_lights_differ(const char *what, const char *a, const char *b)
{
    cdl_scene_hashes x, y;
    if (!hashes_of(a, &x) || !hashes_of(b, &y)) return;
    CHECK_MSG(x.lights != y.lights, "%s: the light hash did not change", what);
    CHECK_MSG(x.geometry == y.geometry && x.materials == y.materials, "%s: geometry or materials changed", what);
}

#define CIE "{\"type\": \"environment\", \"sky\": \"cie\", "
#define PEREZ "{\"type\": \"environment\", \"sky\": \"perez\", \"day_of_year\": 172, "
#define SUN40 "\"sun\": {\"azimuth_deg\": 180, \"altitude_deg\": 40}"
#define SITE "\"site\": {\"latitude_deg\": 52.5, \"longitude_deg\": 13.4}"

int main(void)
{
    expect_lights_differ("sun azimuth", CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SUN40 "}",
                         CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, "
                             "\"sun\": {\"azimuth_deg\": 181, \"altitude_deg\": 40}}");
    expect_lights_differ("time", CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SITE
                                     ", \"time\": \"2024-06-21T12:00:00Z\"}",
                         CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SITE
                             ", \"time\": \"2024-06-21T12:10:00Z\"}");
    expect_lights_differ("cie type", CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SUN40 "}",
                         CIE "\"cie_type\": 13, \"zenith_luminance_cd_m2\": 5000, " SUN40 "}");
    expect_lights_differ("scaled by zenith or horizontal",
                         CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SUN40 "}",
                         CIE "\"cie_type\": 12, \"diffuse_horizontal_illuminance_lx\": 5000, " SUN40 "}");
    expect_lights_differ("diffuse horizontal", CIE "\"cie_type\": 12, \"diffuse_horizontal_illuminance_lx\": 5000, " SUN40 "}",
                         CIE "\"cie_type\": 12, \"diffuse_horizontal_illuminance_lx\": 5001, " SUN40 "}");
    expect_lights_differ("cie sun's direct normal",
                         CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SUN40
                             ", \"direct_normal_illuminance_lx\": 60000}",
                         CIE "\"cie_type\": 12, \"zenith_luminance_cd_m2\": 5000, " SUN40
                             ", \"direct_normal_illuminance_lx\": 60001}");
    expect_lights_differ("overcast or cie type 1",
                         "{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 5000}",
                         CIE "\"cie_type\": 1, \"zenith_luminance_cd_m2\": 5000}");
    const char *perez = PEREZ "\"direct_normal_irradiance_w_m2\": 500, \"diffuse_horizontal_irradiance_w_m2\": 100, "
                              "\"dew_point_c\": 11, " SUN40 "}";
    expect_lights_differ("perez dew point", perez,
                         PEREZ "\"direct_normal_irradiance_w_m2\": 500, \"diffuse_horizontal_irradiance_w_m2\": 100, "
                               "\"dew_point_c\": 12, " SUN40 "}");
    expect_lights_differ("perez direct normal", perez,
                         PEREZ "\"direct_normal_irradiance_w_m2\": 501, \"diffuse_horizontal_irradiance_w_m2\": 100, "
                               "\"dew_point_c\": 11, " SUN40 "}");
    expect_lights_differ("perez in lx or W/m2", perez,
                         PEREZ "\"direct_normal_illuminance_lx\": 50000, \"diffuse_horizontal_illuminance_lx\": 12000, "
                               "\"dew_point_c\": 11, " SUN40 "}");
    expect_lights_differ("perez day of year", perez,
                         "{\"type\": \"environment\", \"sky\": \"perez\", \"day_of_year\": 173, "
                         "\"direct_normal_irradiance_w_m2\": 500, \"diffuse_horizontal_irradiance_w_m2\": 100, "
                         "\"dew_point_c\": 11, " SUN40 "}");
    expect_lights_differ("sun disk diameter",
                         "{\"type\": \"directional\", \"direction\": [0,0,-1], \"illuminance_lx\": 1000, "
                         "\"angular_diameter_deg\": 0.533}",
                         "{\"type\": \"directional\", \"direction\": [0,0,-1], \"illuminance_lx\": 1000, "
                         "\"angular_diameter_deg\": 0.5}");

    /* the same content, its keys in another order: the same hashes */
    cdl_scene_hashes x, y;
    if (hashes_of(perez, &x) &&
        hashes_of(PEREZ SUN40 ", \"dew_point_c\": 11, \"diffuse_horizontal_irradiance_w_m2\": 100, "
                              "\"direct_normal_irradiance_w_m2\": 500}",
                  &y))
        CHECK(x.lights == y.lights && x.geometry == y.geometry && x.materials == y.materials);
    return check_finish();
}
