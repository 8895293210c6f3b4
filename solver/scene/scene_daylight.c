/* scene_daylight.c - the daylight skies of an environment luminaire: "sky":
 * "cie" and "sky": "perez", and where their sun is.
 *
 *   key                                  meaning                                      unit    default
 *   cie_type                             "cie": the CIE standard general sky, 1..15   -       -
 *   zenith_luminance_cd_m2               "cie": scale by the zenith's luminance       cd/m2   -
 *   diffuse_horizontal_illuminance_lx    "cie": scale by the unobstructed horizontal  lx      -
 *                                        illuminance instead; "perez": input
 *   direct_normal_illuminance_lx         the sun's, normal to its rays: a disk of     lx      0 ("cie"),
 *                                        0.533 degrees ("perez": input)                       none
 *   direct_normal_irradiance_w_m2,       "perez": the inputs as irradiances instead    W/m2    -
 *   diffuse_horizontal_irradiance_w_m2
 *   dew_point_c                          "perez": for the precipitable water          degC    11
 *   sun {azimuth_deg, altitude_deg}      the sun's place: azimuth eastward from       degree  -
 *                                        north, apparent altitude above the horizon
 *   site {latitude_deg, longitude_deg,   or the place and "time", the sun by the      -       -
 *     elevation_m, pressure_mbar,        NREL SPA (lights/environment/
 *     temperature_c, delta_t_s}          solar_position.h)
 *   time                                 ISO 8601 with its UTC offset                 -       -
 *   day_of_year                          "perez" with "sun": the Earth's distance      -       -
 *   north                                the direction of north (made perpendicular   -       [0,1,0]
 *                                        to up); east = north x up
 *   up                                   the zenith                                   -       [0,0,1]
 *
 * A world direction from azimuth az and altitude h: cos h (cos az north +
 * sin az east) + sin h up. Every error names the JSON path.
 */
#include "solver/scene/scene_parse.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/emitter.h"
#include "lights/environment/solar_position.h"
#include "radiometry/constants.h"

const char *const cdl_scene_sun_keys[] = {"azimuth_deg", "altitude_deg", NULL};
const char *const cdl_scene_site_keys[] = {"latitude_deg", "longitude_deg", "elevation_m", "pressure_mbar",
                                           "temperature_c", "delta_t_s", NULL};

static const cJSON *field(const cJSON *node, const char *path, const char *key, char *p)
{
    return cdl_scene_json_field(node, path, key, p);
}

/* A number in [lo, hi] (required or kept). */
static cdl_status read_in(const cdl_scene_parse *ctx, const cJSON *node, const char *path, double lo, double hi,
                          const char *unit, int required, double *out)
{
    double v = *out;
    if (cdl_scene_json_read_number(ctx, node, path, CDL_RANGE_ANY, required, &v) != CDL_OK) return CDL_ERR_INPUT;
    if (node && !(v >= lo && v <= hi)) {
        char expected[96];
        snprintf(expected, sizeof expected, "a number in [%g, %g] %s", lo, hi, unit);
        return cdl_scene_json_fail(ctx, path, expected, node);
    }
    *out = v;
    return CDL_OK;
}

/* Keys that must not be there, with why. */
static cdl_status refuse(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                         const char *const *keys, const char *why)
{
    char p[CDL_SCENE_PATH_MAX];
    for (int k = 0; keys[k]; ++k)
        if (field(node, path, keys[k], p)) return cdl_scene_json_failf(ctx, p, why, "\"%s\"", keys[k]);
    return CDL_OK;
}

static int day_of_year(int year, int month, int day)
{
    static const int before[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    int leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return before[month - 1] + day + (leap && month > 2);
}

/* "north" made perpendicular to up; east = north x up. */
static cdl_status read_north(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_vec3 up,
                             cdl_daylight_spec *d)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_vec3 north = cdl_vec3_make(0, 1, 0);
    const cJSON *n = field(node, path, "north", p);
    if (cdl_scene_json_read_vec3(ctx, n, p, 1, 0, &north) != CDL_OK) return CDL_ERR_INPUT;
    north = cdl_vec3_normalize(north);
    cdl_vec3 flat = cdl_vec3_madd(north, -cdl_vec3_dot(north, up), up);
    if (!(cdl_vec3_length(flat) > 1e-6))
        return cdl_scene_json_failf(ctx, p, "a direction of north not along \"up\"", "[%g, %g, %g]", north.x, north.y,
                                    north.z);
    d->north = cdl_vec3_normalize(flat);
    return CDL_OK;
}

/* The sun from "site" and "time" by the SPA. */
static cdl_status read_site(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_daylight_spec *d)
{
    char p[CDL_SCENE_PATH_MAX], site_path[CDL_SCENE_PATH_MAX], q[CDL_SCENE_PATH_MAX];
    const cJSON *site = field(node, path, "site", site_path);
    const cJSON *time = field(node, path, "time", p);
    if (!time) return cdl_scene_json_fail(ctx, p, "a \"time\" (ISO 8601 with its UTC offset) with \"site\"", time);
    cdl_solar_site s = CDL_SOLAR_SITE_DEFAULT;
    if (cdl_scene_json_check_object(ctx, site, site_path, "a site {\"latitude_deg\", \"longitude_deg\", ...}",
                                    cdl_scene_site_keys) != CDL_OK ||
        read_in(ctx, field(site, site_path, "latitude_deg", q), q, -90, 90, "degrees", 1, &s.latitude_deg) != CDL_OK ||
        read_in(ctx, field(site, site_path, "longitude_deg", q), q, -180, 180, "degrees", 1, &s.longitude_deg) !=
            CDL_OK ||
        read_in(ctx, field(site, site_path, "elevation_m", q), q, -6500000, 1e7, "m", 0, &s.elevation_m) != CDL_OK ||
        read_in(ctx, field(site, site_path, "pressure_mbar", q), q, 0, 5000, "mbar", 0, &s.pressure_mbar) != CDL_OK ||
        read_in(ctx, field(site, site_path, "temperature_c", q), q, -273, 6000, "degrees C", 0, &s.temperature_c) !=
            CDL_OK ||
        read_in(ctx, field(site, site_path, "delta_t_s", q), q, -8000, 8000, "s", 0, &s.delta_t_s) != CDL_OK)
        return CDL_ERR_INPUT;
    if (!cJSON_IsString(time) || !time->valuestring)
        return cdl_scene_json_fail(ctx, p, "an ISO 8601 time with its UTC offset, e.g. \"2024-06-21T12:00:00+02:00\"",
                                   time);
    cdl_civil_time t;
    cdl_solar_position sun;
    cdl_error e;
    if (cdl_civil_time_parse(time->valuestring, &t, &e) != CDL_OK ||
        cdl_solar_position_compute(&s, &t, &sun, &e) != CDL_OK)
        return cdl_error_set(ctx->err, CDL_ERR_INPUT, "%s: %s: %s", ctx->file, p, e.message);
    d->from_site = 1;
    d->latitude_deg = s.latitude_deg;
    d->longitude_deg = s.longitude_deg;
    d->elevation_m = s.elevation_m;
    d->pressure_mbar = s.pressure_mbar;
    d->temperature_c = s.temperature_c;
    d->delta_t_s = sun.delta_t_s;
    snprintf(d->time, sizeof d->time, "%s", time->valuestring);
    d->day_of_year = day_of_year(t.year, t.month, t.day);
    d->sun_altitude_deg = sun.elevation_deg;
    d->sun_azimuth_deg = sun.azimuth_deg;
    return CDL_OK;
}

/* "sun", or "site" and "time": the sun's altitude and azimuth, then its
 * world direction. `needed`: one of them is required. */
static cdl_status read_sun(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_vec3 up,
                           int needed, const char *why, cdl_daylight_spec *d)
{
    char p[CDL_SCENE_PATH_MAX], q[CDL_SCENE_PATH_MAX];
    const cJSON *sun = field(node, path, "sun", p), *site = cdl_scene_json_member(node, "site");
    if (sun && site) return cdl_scene_json_failf(ctx, p, "either \"sun\" or \"site\" and \"time\"", "both");
    if (!sun && !site) {
        if (cdl_scene_json_member(node, "time"))
            return cdl_scene_json_failf(ctx, path, "\"time\" only with \"site\"", "\"time\" without a \"site\"");
        if (needed) return cdl_scene_json_failf(ctx, path, why, "neither \"sun\" nor \"site\"");
        d->sun = up;
        return CDL_OK;
    }
    if (sun) {
        if (field(node, path, "time", q))
            return cdl_scene_json_failf(ctx, q, "\"time\" only with \"site\" (\"sun\" gives the place directly)",
                                        "it with \"sun\"");
        if (cdl_scene_json_check_object(ctx, sun, p, "a sun {\"azimuth_deg\", \"altitude_deg\"}",
                                        cdl_scene_sun_keys) != CDL_OK ||
            read_in(ctx, field(sun, p, "azimuth_deg", q), q, 0, 360, "degrees (eastward from north)", 1,
                    &d->sun_azimuth_deg) != CDL_OK ||
            read_in(ctx, field(sun, p, "altitude_deg", q), q, -90, 90, "degrees", 1, &d->sun_altitude_deg) != CDL_OK)
            return CDL_ERR_INPUT;
    } else if (read_site(ctx, node, path, d) != CDL_OK) {
        return CDL_ERR_INPUT;
    }
    d->has_sun = 1;
    cdl_vec3 east = cdl_vec3_cross(d->north, up);
    double h = d->sun_altitude_deg * CDL_DEG_TO_RAD, az = d->sun_azimuth_deg * CDL_DEG_TO_RAD;
    d->sun = cdl_vec3_normalize(cdl_vec3_add(
        cdl_vec3_scale(cdl_vec3_add(cdl_vec3_scale(d->north, cos(az)), cdl_vec3_scale(east, sin(az))), cos(h)),
        cdl_vec3_scale(up, sin(h))));
    return CDL_OK;
}

static cdl_status read_cie(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_luminaire_spec *out)
{
    static const char *const not_cie[] = {"luminance_cd_m2", "file", "scale", "hemisphere", "dew_point_c",
                                          "direct_normal_irradiance_w_m2", "diffuse_horizontal_irradiance_w_m2",
                                          "day_of_year", NULL};
    char p[CDL_SCENE_PATH_MAX];
    cdl_daylight_spec *d = &out->daylight;
    double type = 0;
    if (refuse(ctx, node, path, not_cie, "none of luminance_cd_m2, file, scale, hemisphere or the Perez sky's "
                                         "inputs with \"sky\": \"cie\"") != CDL_OK ||
        cdl_scene_json_read_integer(ctx, field(node, path, "cie_type", p), p, 1, 15, 1, &type) != CDL_OK)
        return CDL_ERR_INPUT;
    d->cie_type = (int)type;
    const cJSON *z = cdl_scene_json_member(node, "zenith_luminance_cd_m2"),
                *h = cdl_scene_json_member(node, "diffuse_horizontal_illuminance_lx");
    if ((z != NULL) == (h != NULL))
        return cdl_scene_json_failf(ctx, path,
                                    "exactly one of \"zenith_luminance_cd_m2\" and \"diffuse_horizontal_illuminance_lx\"",
                                    z ? "both" : "neither");
    d->scale_to_horizontal = h != NULL;
    if (cdl_scene_json_read_quantity(ctx, field(node, path, "zenith_luminance_cd_m2", p), p, CDL_DIM_LUMINANCE,
                                     CDL_RANGE_NONNEGATIVE, 0, &out->luminance_cd_m2) != CDL_OK ||
        cdl_scene_json_read_quantity(ctx, field(node, path, "diffuse_horizontal_illuminance_lx", p), p,
                                     CDL_DIM_ILLUMINANCE, CDL_RANGE_NONNEGATIVE, 0, &d->diffuse_horizontal) != CDL_OK ||
        cdl_scene_json_read_quantity(ctx, field(node, path, "direct_normal_illuminance_lx", p), p, CDL_DIM_ILLUMINANCE,
                                     CDL_RANGE_NONNEGATIVE, 0, &d->direct_normal) != CDL_OK)
        return CDL_ERR_INPUT;
    char why[160];
    snprintf(why, sizeof why, "the sun's place (\"sun\", or \"site\" and \"time\") for CIE sky type %d%s", d->cie_type,
             d->direct_normal > 0.0 ? " and its direct_normal_illuminance_lx" : "");
    return read_sun(ctx, node, path, out->up, cdl_sky_cie_type_uses_sun(d->cie_type) || d->direct_normal > 0.0, why,
                    d);
}

static cdl_status read_perez(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_luminaire_spec *out)
{
    static const char *const not_perez[] = {"luminance_cd_m2", "file", "scale", "hemisphere",
                                            "zenith_luminance_cd_m2", "cie_type", NULL};
    char p[CDL_SCENE_PATH_MAX];
    cdl_daylight_spec *d = &out->daylight;
    if (refuse(ctx, node, path, not_perez, "none of luminance_cd_m2, file, scale, hemisphere, zenith_luminance_cd_m2 "
                                           "or cie_type with \"sky\": \"perez\"") != CDL_OK)
        return CDL_ERR_INPUT;
    const char *lx[2] = {"direct_normal_illuminance_lx", "diffuse_horizontal_illuminance_lx"};
    const char *w[2] = {"direct_normal_irradiance_w_m2", "diffuse_horizontal_irradiance_w_m2"};
    int has_lx = cdl_scene_json_member(node, lx[0]) || cdl_scene_json_member(node, lx[1]);
    int has_w = cdl_scene_json_member(node, w[0]) || cdl_scene_json_member(node, w[1]);
    if (has_lx == has_w)
        return cdl_scene_json_failf(ctx, path,
                                    "the direct normal and diffuse horizontal illuminances (lx) or irradiances (W/m2)",
                                    has_lx ? "both" : "neither");
    d->radiometric = has_w;
    const char **keys = has_w ? w : lx;
    cdl_dimension dim = has_w ? CDL_DIM_IRRADIANCE : CDL_DIM_ILLUMINANCE;
    d->dew_point_c = 11.0;
    if (cdl_scene_json_read_quantity(ctx, field(node, path, keys[0], p), p, dim, CDL_RANGE_NONNEGATIVE, 1,
                                     &d->direct_normal) != CDL_OK ||
        cdl_scene_json_read_quantity(ctx, field(node, path, keys[1], p), p, dim, CDL_RANGE_POSITIVE, 1,
                                     &d->diffuse_horizontal) != CDL_OK ||
        read_in(ctx, field(node, path, "dew_point_c", p), p, -100, 60, "degrees C", 0, &d->dew_point_c) != CDL_OK ||
        read_sun(ctx, node, path, out->up, 1, "the sun's place (\"sun\" with \"day_of_year\", or \"site\" and \"time\")",
                 d) != CDL_OK)
        return CDL_ERR_INPUT;
    const cJSON *doy = field(node, path, "day_of_year", p);
    if (d->from_site && doy)
        return cdl_scene_json_failf(ctx, p, "no \"day_of_year\" with \"time\" (the date gives it)", "both");
    if (!d->from_site) {
        double v = 0;
        if (cdl_scene_json_read_integer(ctx, doy, p, 1, 366, 1, &v) != CDL_OK) return CDL_ERR_INPUT;
        d->day_of_year = (int)v;
    }
    if (!(d->sun_altitude_deg > 0.0))
        return cdl_scene_json_failf(ctx, path, "the sun above the horizon for a Perez sky",
                                    "an altitude of %.6g degrees", d->sun_altitude_deg);
    return CDL_OK;
}

cdl_status cdl_scene_json_read_daylight(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                        cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    out->upper_hemisphere_only = 1;
    if (cdl_scene_json_read_vec3(ctx, field(node, path, "up", p), p, 1, 0, &out->up) != CDL_OK) return CDL_ERR_INPUT;
    out->up = cdl_vec3_normalize(out->up);
    if (read_north(ctx, node, path, out->up, &out->daylight) != CDL_OK) return CDL_ERR_INPUT;
    return out->sky == CDL_SCENE_SKY_CIE ? read_cie(ctx, node, path, out) : read_perez(ctx, node, path, out);
}
