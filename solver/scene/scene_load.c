/* scene_load.c - the JSON scene file of DESIGN.md into a cdl_scene.
 *
 * Top level: version (required, 1), name and project (scene_project.c),
 * surfaces, luminaires, observers
 * (scene_observers.c), grids (at least one unless there are observers; a
 * grid of "type": "observers" places observers), solver. Luminaire keys by type (all take
 * maintenance_factor in (0, 1], default 1):
 *   point        position; exactly one of intensity_cd, flux_lm (>= 0)
 *   spot         position, direction; exactly one of intensity_cd, flux_lm;
 *                either half_angle in (0, 180] with falloff_start in
 *                [0, half_angle] (default half_angle), or exponent >= 0
 *   goniometric  file, position; rotation (default [0, 0, 0]), near_field
 *                ("auto", "always" or "never"; default "auto"), multiplier
 *                (>= 0, default 1), flux_lm (> 0, optional rescale), body
 *                (true, the default; false; or {"reflectance": R in [0, 1]})
 *   area         shape (rect, disk, polygon, mesh); exactly one of
 *                luminance_cd_m2, flux_lm (>= 0); reflectance (default 0)
 *   directional  direction, illuminance_lx (>= 0), angular_diameter_deg
 *                ([0, 10], default 0: parallel; the sun is 0.533)
 *   environment  exactly one of luminance_cd_m2 (>= 0) or file (with
 *                scale >= 0, default 1); up (default [0, 0, 1]);
 *                hemisphere "full" (default) or "upper"; or "sky":
 *                "cie_overcast" with zenith_luminance_cd_m2 (>= 0), up
 *                and no other (the CIE standard overcast sky, L_z (1 + 2
 *                cos theta) / 3 above the horizon, nothing below);
 *                "sky": "uniform" is the default; "sky": "cie" or "perez" with
 *                their keys (scene_daylight.c)
 * Grids: name (letters, digits, '.', '_', '-'; unique ignoring case, so the
 * output files differ on every file system), type, outputs (["ao"]), and
 *   rect     origin, u, v, nu, nv, normal (default u x v)
 *   polygon  vertices, holes, spacing (metres > 0 or "auto", default "auto"), normal
 *   points   points: [{"p": [x, y, z], "n": [nx, ny, nz]}, ...]
 * Solver: method, quality, target_error, bounces, seed, threads, direct_samples, ao_samples,
 *   surface_maps ("none", the default, "all", or a list of surface names; a
 *   surface with "requirements" is mapped in any case).
 * The photometric values (intensity_cd, flux_lm, luminance_cd_m2,
 * illuminance_lx) are a number in the unit the key names or text with any
 * unit of the same dimension, as people type it: "46.45 fc", "2 kcd",
 * "3 klm", "1200 cd/m2" (radiometry/quantity.h).
 */
#include "solver/scene/scene_internal.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/file_bytes.h"
#include "base/strings.h"
#include "solver/scene/scene_file.h"
#include "solver/scene/scene_parse.h"

/* Room in the key tables of luminaires and grids, NULL included. */
#define LUMINAIRE_KEYS_MAX 24

static const char *const document_keys[] = {"$schema", "version", "name",   "project", "surfaces",
                                            "luminaires", "grids", "observers", "solver", NULL};
static const char *const settings_keys[] = {"method", "quality", "target_error", "bounces", "seed", "threads",
                                            "direct_samples", "ao_samples", "surface_maps", NULL};
static const char *const point_keys[] = {"p", "n", NULL};


static const char *const method_names[] = {"auto", "direct", "icache", "pathtrace", NULL};
static const char *const quality_names[] = {"draft", "normal", "high", "reference", NULL};

const char *cdl_method_name(cdl_method method)
{
    return (unsigned)method < 4 ? method_names[method] : "unknown";
}

double cdl_quality_target_error(cdl_quality quality)
{
    static const double targets[] = {0.02, 0.005, 0.001, 0.0002};
    return (unsigned)quality < 4 ? targets[quality] : 0.005;
}

double cdl_solver_settings_target(const cdl_solver_settings *settings)
{
    return settings->target_error > 0.0 ? settings->target_error : cdl_quality_target_error(settings->quality);
}

const char *cdl_quality_name(cdl_quality quality)
{
    return (unsigned)quality < 4 ? quality_names[quality] : "unknown";
}

/* ---- helpers ------------------------------------------------------------------ */

/* At most one of keys a and b; with `required`, exactly one. *which = 0 (a), 1 (b) or -1. */
static cdl_status one_of(const cdl_scene_parse *ctx, const cJSON *node, const char *path, const char *a,
                         const char *b, int required, int *which)
{
    const cJSON *na = cdl_scene_json_member(node, a), *nb = cdl_scene_json_member(node, b);
    char p[CDL_SCENE_PATH_MAX], exp[128];
    if (na && nb) {
        cdl_scene_json_path_key(p, path, b);
        snprintf(exp, sizeof exp, "either \"%s\" or \"%s\"", a, b);
        return cdl_scene_json_failf(ctx, p, exp, "both");
    }
    if (!na && !nb && required) {
        snprintf(exp, sizeof exp, "exactly one of \"%s\" and \"%s\"", a, b);
        return cdl_scene_json_failf(ctx, path, exp, "neither");
    }
    *which = na ? 0 : nb ? 1 : -1;
    return CDL_OK;
}

static const cJSON *field(const cJSON *node, const char *path, const char *key, char *p)
{
    return cdl_scene_json_field(node, path, key, p);
}

/* An object with a "type" among `types` whose keys are all in keys[type]. */
static cdl_status read_kind(const cdl_scene_parse *ctx, const cJSON *node, const char *path, const char *noun,
                            const char *const *types, const char *const (*keys)[LUMINAIRE_KEYS_MAX], int *kind)
{
    char p[CDL_SCENE_PATH_MAX], what[64];
    if (!cJSON_IsObject(node)) {
        snprintf(what, sizeof what, "a %s (a JSON object)", noun);
        return cdl_scene_json_fail(ctx, path, what, node);
    }
    if (cdl_scene_json_read_choice(ctx, field(node, path, "type", p), p, types, 1, kind) != CDL_OK)
        return CDL_ERR_INPUT;
    snprintf(what, sizeof what, "a %s %s", types[*kind], noun);
    return cdl_scene_json_check_object(ctx, node, path, what, keys[*kind]);
}

/* ---- luminaires ----------------------------------------------------------------- */

static const char *const luminaire_types[] = {"point", "spot", "goniometric", "area", "directional", "environment", NULL};
static const char *const luminaire_keys[][LUMINAIRE_KEYS_MAX] = {
    {"type", "name", "position", "positions", "array", "intensity_cd", "flux_lm", "maintenance_factor", NULL},
    {"type", "name", "position", "positions", "array", "direction", "aim", "spin", "intensity_cd", "flux_lm",
     "half_angle", "falloff_start", "exponent", "maintenance_factor", NULL},
    {"type", "name", "file", "position", "positions", "array", "rotation", "aim", "spin", "multiplier", "flux_lm",
     "maintenance_factor", "near_field", "body", NULL},
    {"type", "name", "shape", "luminance_cd_m2", "flux_lm", "reflectance", "maintenance_factor", NULL},
    {"type", "name", "direction", "illuminance_lx", "angular_diameter_deg", "maintenance_factor", NULL},
    {"type", "name", "luminance_cd_m2", "file", "scale", "up", "hemisphere", "maintenance_factor", "sky",
     "zenith_luminance_cd_m2", "cie_type", "diffuse_horizontal_illuminance_lx", "direct_normal_illuminance_lx",
     "diffuse_horizontal_irradiance_w_m2", "direct_normal_irradiance_w_m2", "dew_point_c", "sun", "site", "time",
     "day_of_year", "north", NULL},
};

static cdl_status read_intensity(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                 cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    int which = -1;
    if (one_of(ctx, node, path, "intensity_cd", "flux_lm", 1, &which) != CDL_OK) return CDL_ERR_INPUT;
    out->has_intensity = which == 0;
    out->has_flux = which == 1;
    if (which == 0)
        return cdl_scene_json_read_quantity(ctx, field(node, path, "intensity_cd", p), p, CDL_DIM_LUMINOUS_INTENSITY,
                                            CDL_RANGE_NONNEGATIVE, 1, &out->intensity_cd);
    return cdl_scene_json_read_quantity(ctx, field(node, path, "flux_lm", p), p, CDL_DIM_LUMINOUS_FLUX,
                                        CDL_RANGE_NONNEGATIVE, 1, &out->flux_lm);
}

static cdl_status read_spot(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    out->direction = cdl_vec3_make(0, 0, -1);
    if (cdl_scene_json_read_vec3(ctx, field(node, path, "direction", p), p, 1, !out->has_aim, &out->direction) !=
            CDL_OK ||
        read_intensity(ctx, node, path, out) != CDL_OK)
        return CDL_ERR_INPUT;
    out->direction = cdl_vec3_normalize(out->direction);
    const cJSON *exponent = field(node, path, "exponent", p);
    if (exponent) {
        out->has_exponent = 1;
        if (cdl_scene_json_read_number(ctx, exponent, p, CDL_RANGE_NONNEGATIVE, 1, &out->exponent) != CDL_OK)
            return CDL_ERR_INPUT;
        for (int i = 0; i < 2; ++i) {
            const char *key = i ? "falloff_start" : "half_angle";
            if (field(node, path, key, p))
                return cdl_scene_json_failf(ctx, p, "no beam edge on a cos^n spot (\"exponent\" is given)",
                                            "\"%s\"", key);
        }
        return CDL_OK;
    }
    const cJSON *half = field(node, path, "half_angle", p);
    if (!cJSON_IsNumber(half) || !isfinite(half->valuedouble) || !(half->valuedouble > 0.0) ||
        half->valuedouble > 180.0)
        return cdl_scene_json_fail(ctx, p, "a half angle in (0, 180] degrees (or \"exponent\" instead)", half);
    out->half_angle_deg = half->valuedouble;
    out->falloff_start_deg = out->half_angle_deg;
    const cJSON *falloff = field(node, path, "falloff_start", p);
    if (falloff) {
        if (!cJSON_IsNumber(falloff) || !isfinite(falloff->valuedouble) || falloff->valuedouble < 0.0 ||
            falloff->valuedouble > out->half_angle_deg) {
            char exp[96];
            snprintf(exp, sizeof exp, "an angle in [0, half_angle = %.10g] degrees", out->half_angle_deg);
            return cdl_scene_json_fail(ctx, p, exp, falloff);
        }
        out->falloff_start_deg = falloff->valuedouble;
    }
    return CDL_OK;
}

static cdl_status read_environment(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                   cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    int which = -1, sky = 0;
    /* the order of cdl_scene_sky */
    static const char *const skies[] = {"uniform", "cie_overcast", "cie", "perez", NULL};
    if (cdl_scene_json_read_choice(ctx, field(node, path, "sky", p), p, skies, 0, &sky) != CDL_OK)
        return CDL_ERR_INPUT;
    out->sky = (cdl_scene_sky)sky;
    out->sky_overcast = out->sky == CDL_SCENE_SKY_CIE_OVERCAST;
    if (out->sky == CDL_SCENE_SKY_CIE || out->sky == CDL_SCENE_SKY_PEREZ)
        return cdl_scene_json_read_daylight(ctx, node, path, out);
    static const char *const daylight_only[] = {"cie_type", "diffuse_horizontal_illuminance_lx",
                                                "direct_normal_illuminance_lx", "diffuse_horizontal_irradiance_w_m2",
                                                "direct_normal_irradiance_w_m2", "dew_point_c", "sun", "site", "time",
                                                "day_of_year", "north", NULL};
    for (int k = 0; daylight_only[k]; ++k)
        if (field(node, path, daylight_only[k], p))
            return cdl_scene_json_failf(ctx, p, "this key only with \"sky\": \"cie\" or \"perez\"",
                                        "\"%s\" with a %s sky",
                                        daylight_only[k], skies[sky]);
    if (out->sky_overcast) {
        /* A sky model: its zenith luminance and `up` only. */
        static const char *const others[] = {"luminance_cd_m2", "file", "scale", "hemisphere", NULL};
        for (int k = 0; others[k]; ++k)
            if (field(node, path, others[k], p))
                return cdl_scene_json_failf(ctx, p, "no \"luminance_cd_m2\", \"file\", \"scale\" or \"hemisphere\" "
                                            "with \"sky\": \"cie_overcast\" (zenith_luminance_cd_m2 and up only)",
                                            "\"%s\"", others[k]);
        out->has_luminance = 1;
        out->upper_hemisphere_only = 1;
        if (cdl_scene_json_read_quantity(ctx, field(node, path, "zenith_luminance_cd_m2", p), p, CDL_DIM_LUMINANCE,
                                         CDL_RANGE_NONNEGATIVE, 1, &out->luminance_cd_m2) != CDL_OK ||
            cdl_scene_json_read_vec3(ctx, field(node, path, "up", p), p, 1, 0, &out->up) != CDL_OK)
            return CDL_ERR_INPUT;
        out->up = cdl_vec3_normalize(out->up);
        return CDL_OK;
    }
    if (field(node, path, "zenith_luminance_cd_m2", p))
        return cdl_scene_json_failf(ctx, p, "\"zenith_luminance_cd_m2\" only with \"sky\": \"cie_overcast\" or \"cie\"",
                                    "it with a uniform or image sky");
    if (one_of(ctx, node, path, "luminance_cd_m2", "file", 1, &which) != CDL_OK) return CDL_ERR_INPUT;
    if (which == 0) {
        out->has_luminance = 1;
        if (cdl_scene_json_read_quantity(ctx, field(node, path, "luminance_cd_m2", p), p, CDL_DIM_LUMINANCE,
                                         CDL_RANGE_NONNEGATIVE, 1, &out->luminance_cd_m2) != CDL_OK)
            return CDL_ERR_INPUT;
        if (field(node, path, "scale", p))
            return cdl_scene_json_failf(ctx, p, "\"scale\" only with an image \"file\"", "it with luminance_cd_m2");
    } else {
        if (cdl_scene_json_read_path(ctx, field(node, path, "file", p), p, 1, &out->file) != CDL_OK ||
            cdl_scene_json_read_number(ctx, field(node, path, "scale", p), p, CDL_RANGE_NONNEGATIVE, 0, &out->scale) !=
                CDL_OK)
            return CDL_ERR_INPUT;
    }
    static const char *const hemispheres[] = {"full", "upper", NULL};
    if (cdl_scene_json_read_vec3(ctx, field(node, path, "up", p), p, 1, 0, &out->up) != CDL_OK ||
        cdl_scene_json_read_choice(ctx, field(node, path, "hemisphere", p), p, hemispheres, 0,
                                   &out->upper_hemisphere_only) != CDL_OK)
        return CDL_ERR_INPUT;
    out->up = cdl_vec3_normalize(out->up);
    return CDL_OK;
}

/* "body": true or false, or {"reflectance": R} (a body with that reflectance). */
static cdl_status read_body(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    const cJSON *body = field(node, path, "body", p);
    out->body = 1;
    if (!body) return CDL_OK;
    if (cJSON_IsBool(body)) return cdl_scene_json_read_bool(ctx, body, p, 1, &out->body);
    if (!cJSON_IsObject(body))
        return cdl_scene_json_fail(ctx, p, "true, false or an object {\"reflectance\": R}", body);
    static const char *const body_keys[] = {"reflectance", NULL};
    if (cdl_scene_json_check_object(ctx, body, p, "a luminaire body", body_keys) != CDL_OK) return CDL_ERR_INPUT;
    char rp[CDL_SCENE_PATH_MAX];
    const cJSON *r = field(body, p, "reflectance", rp);
    out->has_body_reflectance = r != NULL;
    return cdl_scene_json_read_number(ctx, r, rp, CDL_RANGE_UNIT, 0, &out->body_reflectance);
}

static cdl_status read_luminaire(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                 cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_scene_json_copy_path(out->json_path, path);
    out->multiplier = 1.0;
    out->maintenance_factor = 1.0;
    out->scale = 1.0;
    out->up = cdl_vec3_make(0, 0, 1);
    int kind = 0;
    if (read_kind(ctx, node, path, "luminaire", luminaire_types, luminaire_keys, &kind) != CDL_OK) return CDL_ERR_INPUT;
    out->kind = (cdl_luminaire_kind)kind;
    if (cdl_scene_json_read_string(ctx, field(node, path, "name", p), p, 0, &out->name) != CDL_OK ||
        cdl_scene_json_read_number(ctx, field(node, path, "maintenance_factor", p), p, CDL_RANGE_UNIT_OPEN0, 0,
                                   &out->maintenance_factor) != CDL_OK)
        return CDL_ERR_INPUT;
    /* A list of "positions" replaces "position". */
    int need_position = !cdl_scene_json_member(node, "positions");
    if ((out->kind == CDL_LUMINAIRE_SPOT || out->kind == CDL_LUMINAIRE_GONIOMETRIC) &&
        cdl_scene_json_read_aim(ctx, node, path, out) != CDL_OK)
        return CDL_ERR_INPUT;
    switch (out->kind) {
    case CDL_LUMINAIRE_POINT:
        if (cdl_scene_json_read_vec3(ctx, field(node, path, "position", p), p, 0, need_position, &out->position) !=
            CDL_OK)
            return CDL_ERR_INPUT;
        return read_intensity(ctx, node, path, out);
    case CDL_LUMINAIRE_SPOT:
        if (cdl_scene_json_read_vec3(ctx, field(node, path, "position", p), p, 0, need_position, &out->position) !=
            CDL_OK)
            return CDL_ERR_INPUT;
        return read_spot(ctx, node, path, out);
    case CDL_LUMINAIRE_GONIOMETRIC: {
        cdl_vec3 rotation = cdl_vec3_make(0, 0, 0);
        if (cdl_scene_json_read_path(ctx, field(node, path, "file", p), p, 1, &out->file) != CDL_OK ||
            cdl_scene_json_read_vec3(ctx, field(node, path, "position", p), p, 0, need_position, &out->position) !=
                CDL_OK ||
            cdl_scene_json_read_vec3(ctx, field(node, path, "rotation", p), p, 0, 0, &rotation) != CDL_OK ||
            cdl_scene_json_read_number(ctx, field(node, path, "multiplier", p), p, CDL_RANGE_NONNEGATIVE, 0,
                                       &out->multiplier) != CDL_OK)
            return CDL_ERR_INPUT;
        /* the order of cdl_near_field_mode */
        static const char *const near_modes[] = {"auto", "always", "never", NULL};
        int near = CDL_NEAR_FIELD_AUTO;
        if (cdl_scene_json_read_choice(ctx, field(node, path, "near_field", p), p, near_modes, 0, &near) != CDL_OK)
            return CDL_ERR_INPUT;
        out->near_field = (cdl_near_field_mode)near;
        if (read_body(ctx, node, path, out) != CDL_OK) return CDL_ERR_INPUT;
        out->rotation_deg[0] = rotation.x;
        out->rotation_deg[1] = rotation.y;
        out->rotation_deg[2] = rotation.z;
        const cJSON *flux = field(node, path, "flux_lm", p);
        out->has_flux = flux != NULL;
        return cdl_scene_json_read_quantity(ctx, flux, p, CDL_DIM_LUMINOUS_FLUX, CDL_RANGE_POSITIVE, 0, &out->flux_lm);
    }
    case CDL_LUMINAIRE_AREA: {
        int which = -1;
        if (cdl_scene_json_read_surface(ctx, field(node, path, "shape", p), p, CDL_SHAPE_USE_LUMINAIRE, &out->shape) !=
                CDL_OK ||
            one_of(ctx, node, path, "luminance_cd_m2", "flux_lm", 1, &which) != CDL_OK ||
            cdl_scene_json_read_number(ctx, field(node, path, "reflectance", p), p, CDL_RANGE_UNIT, 0,
                                       &out->reflectance) != CDL_OK)
            return CDL_ERR_INPUT;
        out->has_luminance = which == 0;
        out->has_flux = which == 1;
        if (which == 0)
            return cdl_scene_json_read_quantity(ctx, field(node, path, "luminance_cd_m2", p), p, CDL_DIM_LUMINANCE,
                                                CDL_RANGE_NONNEGATIVE, 1, &out->luminance_cd_m2);
        return cdl_scene_json_read_quantity(ctx, field(node, path, "flux_lm", p), p, CDL_DIM_LUMINOUS_FLUX,
                                            CDL_RANGE_NONNEGATIVE, 1, &out->flux_lm);
    }
    case CDL_LUMINAIRE_DIRECTIONAL:
        if (cdl_scene_json_read_vec3(ctx, field(node, path, "direction", p), p, 1, 1, &out->direction) != CDL_OK)
            return CDL_ERR_INPUT;
        out->direction = cdl_vec3_normalize(out->direction);
        if (cdl_scene_json_read_number(ctx, field(node, path, "angular_diameter_deg", p), p, CDL_RANGE_NONNEGATIVE, 0,
                                       &out->angular_diameter_deg) != CDL_OK)
            return CDL_ERR_INPUT;
        if (out->angular_diameter_deg > 10.0)
            return cdl_scene_json_failf(ctx, p, "an angular diameter in [0, 10] degrees (the sun's is 0.533)", "%g",
                                        out->angular_diameter_deg);
        return cdl_scene_json_read_quantity(ctx, field(node, path, "illuminance_lx", p), p, CDL_DIM_ILLUMINANCE,
                                            CDL_RANGE_NONNEGATIVE, 1, &out->illuminance_lx);
    case CDL_LUMINAIRE_ENVIRONMENT:
        return read_environment(ctx, node, path, out);
    }
    return CDL_OK;
}

/* One entry of "luminaires": its luminaire, placed once or at every
 * position of its "array" or "positions" (each copy its own spec). */
static cdl_status read_luminaire_entry(const cdl_scene_parse *ctx, const cJSON *node, const char *path, size_t entry,
                                       cdl_scene *scene)
{
    cdl_luminaire_spec proto;
    memset(&proto, 0, sizeof proto);
    cdl_luminaire_copies copies;
    memset(&copies, 0, sizeof copies);
    cdl_status st = read_luminaire(ctx, node, path, &proto);
    int placed = proto.kind == CDL_LUMINAIRE_POINT || proto.kind == CDL_LUMINAIRE_SPOT ||
                 proto.kind == CDL_LUMINAIRE_GONIOMETRIC;
    /* The entry's own orientation (aimed from "position") lays out an array. */
    if (st == CDL_OK && placed && !cdl_scene_json_member(node, "positions"))
        st = cdl_scene_place_copy(ctx, path, &proto);
    if (st == CDL_OK && placed) {
        st = cdl_scene_json_read_copies(ctx, node, path, &proto, &copies);
    } else if (st == CDL_OK) {
        copies.count = 1;
    }
    if (st == CDL_OK && scene->luminaire_count + copies.count > CDL_SCENE_MAX_LUMINAIRES)
        st = cdl_scene_json_failf(ctx, path, "at most 1000000 luminaires in a scene", "%zu with this entry's",
                                  scene->luminaire_count + copies.count);
    cdl_luminaire_spec *grown = NULL;
    if (st == CDL_OK) {
        grown = realloc(scene->luminaires, (scene->luminaire_count + copies.count) * sizeof *grown);
        if (!grown) st = cdl_error_out_of_memory(ctx->err);
        else scene->luminaires = grown;
    }
    for (size_t k = 0; st == CDL_OK && k < copies.count; ++k) {
        cdl_luminaire_spec *c = &scene->luminaires[scene->luminaire_count];
        *c = proto;
        c->entry = entry;
        c->copy = k;
        c->copy_count = copies.count;
        c->array_index[0] = copies.index ? copies.index[k][0] : 0;
        c->array_index[1] = copies.index ? copies.index[k][1] : 0;
        if (copies.positions) c->position = copies.positions[k];
        if (copies.aims) c->aim = copies.aims[k];
        if (k == copies.count - 1) {
            /* The last copy takes the entry's strings and shape. */
            memset(&proto, 0, sizeof proto);
        } else {
            c->name = proto.name ? cdl_string_copy(proto.name) : NULL;
            c->file = proto.file ? cdl_string_copy(proto.file) : NULL;
            if ((proto.name && !c->name) || (proto.file && !c->file)) {
                free(c->name);
                free(c->file);
                st = cdl_error_out_of_memory(ctx->err);
                break;
            }
            memset(&c->shape, 0, sizeof c->shape);
        }
        scene->luminaire_count++;
        st = cdl_scene_place_copy(ctx, path, c);
    }
    free(proto.name);
    free(proto.file);
    cdl_scene_surface_spec_free(&proto.shape);
    cdl_scene_luminaire_copies_free(&copies);
    return st;
}

/* ---- grids ------------------------------------------------------------------------ */

static const char *const grid_types[] = {"rect", "polygon", "points", NULL};
static const char *const grid_keys[][LUMINAIRE_KEYS_MAX] = {
    {"name", "type", "origin", "u", "v", "nu", "nv", "normal", "outputs", "requirements", NULL},
    {"name", "type", "vertices", "holes", "spacing", "normal", "outputs", "requirements", NULL},
    {"name", "type", "points", "outputs", "requirements", NULL},
};

static int names_equal_ignoring_case(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
    return *a == *b;
}

static cdl_status read_grid_points(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                   cdl_grid_spec *out)
{
    if (cdl_scene_json_check_array(ctx, node, path, "a non-empty list of points {\"p\": [x, y, z], \"n\": [nx, ny, nz]}",
                                   1) != CDL_OK)
        return CDL_ERR_INPUT;
    size_t n = (size_t)cJSON_GetArraySize(node);
    if (n > CDL_GRID_MAX_POINTS)
        return cdl_scene_json_failf(ctx, path, "at most 10000000 points", "%zu", n);
    out->points = malloc(n * sizeof *out->points);
    out->normals = malloc(n * sizeof *out->normals);
    if (!out->points || !out->normals) return cdl_error_out_of_memory(ctx->err);
    const char *const *keys = point_keys;
    size_t i = 0;
    char item[CDL_SCENE_PATH_MAX], p[CDL_SCENE_PATH_MAX];
    for (const cJSON *e = node->child; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, path, i);
        if (cdl_scene_json_check_object(ctx, e, item, "a calculation point", keys) != CDL_OK ||
            cdl_scene_json_read_vec3(ctx, field(e, item, "p", p), p, 0, 1, &out->points[i]) != CDL_OK ||
            cdl_scene_json_read_vec3(ctx, field(e, item, "n", p), p, 1, 1, &out->normals[i]) != CDL_OK)
            return CDL_ERR_INPUT;
        out->normals[i] = cdl_vec3_normalize(out->normals[i]);
    }
    out->point_count = n;
    return CDL_OK;
}

static cdl_status read_grid_outputs(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                    cdl_grid_spec *out)
{
    if (!node) return CDL_OK;
    if (cdl_scene_json_check_array(ctx, node, path,
                                   "a list of extra outputs (\"ao\", \"cylindrical\", \"semicylindrical\", "
                                   "\"luminance\", \"daylight_factor\")",
                                   0) != CDL_OK)
        return CDL_ERR_INPUT;
    static const char *const outputs[] = {"ao", "cylindrical", "semicylindrical", "luminance", "daylight_factor", NULL};
    int *wants[] = {&out->want_ao, &out->want_cylindrical, &out->want_semicylindrical, &out->want_luminance,
                    &out->want_daylight_factor};
    size_t i = 0;
    char item[CDL_SCENE_PATH_MAX];
    for (const cJSON *e = node->child; e; e = e->next, ++i) {
        int which = 0;
        cdl_scene_json_path_index(item, path, i);
        if (cdl_scene_json_read_choice(ctx, e, item, outputs, 1, &which) != CDL_OK) return CDL_ERR_INPUT;
        if (*wants[which]) return cdl_scene_json_fail(ctx, item, "each output named once", e);
        *wants[which] = 1;
    }
    return CDL_OK;
}

static cdl_status read_grid(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_grid_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_scene_json_copy_path(out->json_path, path);
    int kind = 0;
    if (read_kind(ctx, node, path, "grid", grid_types, grid_keys, &kind) != CDL_OK) return CDL_ERR_INPUT;
    out->kind = (cdl_grid_kind)kind;
    const cJSON *name = field(node, path, "name", p);
    if (!cJSON_IsString(name) || !cdl_scene_name_ok(name->valuestring))
        return cdl_scene_json_fail(ctx, p,
                                   "a grid name usable as a file name (1 to 64 letters, digits, '.', '_', '-', not "
                                   "starting with '.' or '-')",
                                   name);
    if (cdl_scene_json_read_string(ctx, name, p, 1, &out->name) != CDL_OK ||
        read_grid_outputs(ctx, field(node, path, "outputs", p), p, out) != CDL_OK ||
        cdl_scene_json_read_requirements(ctx, field(node, path, "requirements", p), p, &out->required_Em_lx,
                                         &out->required_U0) != CDL_OK)
        return CDL_ERR_INPUT;
    switch (out->kind) {
    case CDL_GRID_RECT: {
        double nu = 0, nv = 0;
        if (cdl_scene_json_read_span(ctx, node, path, &out->origin, &out->u, &out->v) != CDL_OK ||
            cdl_scene_json_read_integer(ctx, field(node, path, "nu", p), p, 1, CDL_GRID_MAX_POINTS, 1, &nu) != CDL_OK ||
            cdl_scene_json_read_integer(ctx, field(node, path, "nv", p), p, 1, CDL_GRID_MAX_POINTS, 1, &nv) != CDL_OK)
            return CDL_ERR_INPUT;
        if (nu * nv > CDL_GRID_MAX_POINTS)
            return cdl_scene_json_failf(ctx, p, "nu x nv at most 10000000 points", "%.0f x %.0f", nu, nv);
        out->nu = (int)nu;
        out->nv = (int)nv;
        break;
    }
    case CDL_GRID_POLYGON: {
        if (cdl_scene_json_read_polygon(ctx, node, path, &out->outer, &out->holes, &out->hole_count) != CDL_OK)
            return CDL_ERR_INPUT;
        const cJSON *spacing = field(node, path, "spacing", p);
        out->spacing = 0.0;
        if (spacing && !(cJSON_IsString(spacing) && strcmp(spacing->valuestring, "auto") == 0) &&
            (!cJSON_IsNumber(spacing) || !isfinite(spacing->valuedouble) || !(spacing->valuedouble > 0.0) ||
             spacing->valuedouble > CDL_SCENE_MAX_MAGNITUDE))
            return cdl_scene_json_fail(ctx, p, "a spacing in metres > 0 or \"auto\"", spacing);
        if (cJSON_IsNumber(spacing)) out->spacing = spacing->valuedouble;
        break;
    }
    case CDL_GRID_POINTS:
        return read_grid_points(ctx, field(node, path, "points", p), p, out);
    }
    const cJSON *normal = field(node, path, "normal", p);
    out->has_normal = normal != NULL;
    if (cdl_scene_json_read_vec3(ctx, normal, p, 1, 0, &out->normal) != CDL_OK) return CDL_ERR_INPUT;
    out->normal = cdl_vec3_normalize(out->normal);
    return CDL_OK;
}

static void grid_spec_free(cdl_grid_spec *g)
{
    free(g->name);
    cdl_scene_rings_free(&g->outer, g->holes, g->hole_count);
    free(g->points);
    free(g->normals);
    memset(g, 0, sizeof *g);
}

/* ---- solver settings --------------------------------------------------------------- */

static cdl_status read_settings(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                cdl_solver_settings *out)
{
    char p[CDL_SCENE_PATH_MAX];
    out->method = CDL_METHOD_AUTO;
    out->quality = CDL_QUALITY_NORMAL;
    out->target_error = 0.0;
    out->bounces = CDL_BOUNCES_AUTO;
    out->seed = 1;
    out->threads = 0;
    if (!node) return CDL_OK;
    int method = 0, quality = 1;
    double target = 0.0, bounces = CDL_BOUNCES_AUTO, seed = 1, threads = 0, direct = 0, ao = 0;
    if (cdl_scene_json_check_object(ctx, node, path, "the solver settings", settings_keys) != CDL_OK ||
        cdl_scene_json_read_choice(ctx, field(node, path, "method", p), p, method_names, 0, &method) != CDL_OK ||
        cdl_scene_json_read_choice(ctx, field(node, path, "quality", p), p, quality_names, 0, &quality) != CDL_OK ||
        /* 2^53: every integer up to it is exact in a JSON (double) number. */
        cdl_scene_json_read_integer(ctx, field(node, path, "seed", p), p, 0, 9007199254740992.0, 0, &seed) != CDL_OK ||
        cdl_scene_json_read_integer(ctx, field(node, path, "threads", p), p, 0, 4096, 0, &threads) != CDL_OK ||
        cdl_scene_json_read_integer(ctx, field(node, path, "direct_samples", p), p, 1, CDL_SCENE_MAX_SAMPLES, 0,
                                    &direct) != CDL_OK ||
        cdl_scene_json_read_integer(ctx, field(node, path, "ao_samples", p), p, 1, CDL_SCENE_MAX_SAMPLES, 0, &ao) !=
            CDL_OK)
        return CDL_ERR_INPUT;
    const cJSON *t = field(node, path, "target_error", p);
    if (t && (!cJSON_IsNumber(t) || !(t->valuedouble >= CDL_TARGET_ERROR_MIN && t->valuedouble <= CDL_TARGET_ERROR_MAX))) {
        char expected[128];
        snprintf(expected, sizeof expected,
                 "a relative standard error per point as a fraction in [%g, %g] (0.005 is 0.5 %%)",
                 CDL_TARGET_ERROR_MIN, CDL_TARGET_ERROR_MAX);
        return cdl_scene_json_fail(ctx, p, expected, t);
    }
    if (t) target = t->valuedouble;
    /* "bounces": "auto" or a count. */
    const cJSON *b = field(node, path, "bounces", p);
    if (b && !(cJSON_IsString(b) && b->valuestring && strcmp(b->valuestring, "auto") == 0) &&
        cdl_scene_json_read_integer(ctx, b, p, 0, 10000, 0, &bounces) != CDL_OK) {
        cdl_error_clear(ctx->err);
        return cdl_scene_json_fail(ctx, p, "\"auto\" or a whole number of reflections in [0, 10000]", b);
    }
    out->method = (cdl_method)method;
    out->quality = (cdl_quality)quality;
    out->target_error = target;
    out->bounces = (int)bounces;
    out->seed = (uint64_t)seed;
    out->threads = (int)threads;
    out->direct_samples = (int)direct;
    out->ao_samples = (int)ao;
    return CDL_OK;
}

/* ---- surface maps -------------------------------------------------------------------- */

/* The name of surface k's map files: its name, or "surface_K". */
static cdl_status name_map(const cdl_scene_parse *ctx, cdl_scene *scene, size_t k)
{
    cdl_surface_spec *s = &scene->surfaces[k];
    char fallback[32], p[CDL_SCENE_PATH_MAX];
    snprintf(fallback, sizeof fallback, "surface_%zu", k);
    const char *name = s->name ? s->name : fallback;
    if (!cdl_scene_name_ok(name)) {
        cdl_scene_json_path_key(p, s->json_path, "name");
        return cdl_scene_json_failf(ctx, p,
                                    "the name of a mapped surface usable as a file name (1 to 64 letters, digits, "
                                    "'.', '_', '-', not starting with '.' or '-')",
                                    "\"%s\"", name);
    }
    for (size_t j = 0; j < k; ++j)
        if (scene->surfaces[j].map_name && names_equal_ignoring_case(scene->surfaces[j].map_name, name)) {
            cdl_scene_json_path_key(p, s->json_path, s->name ? "name" : "type");
            return cdl_scene_json_failf(ctx, p, "a mapped surface's name not used by another (ignoring case)",
                                        "\"%s\", already %s's", name, scene->surfaces[j].json_path);
        }
    s->map_name = cdl_string_copy(name);
    return s->map_name ? CDL_OK : cdl_error_out_of_memory(ctx->err);
}

/* "surface_maps": "none" (the default), "all", or a list of surface names;
 * a surface with requirements is mapped in any case. */
static cdl_status read_surface_maps(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_scene *scene)
{
    static const char *const modes[] = {"none", "all", NULL};
    const char *expected = "\"all\", \"none\" or a list of surface names";
    int mode = 0;
    scene->settings.surface_maps = CDL_SURFACE_MAPS_NONE;
    if (cJSON_IsArray(node)) {
        scene->settings.surface_maps = CDL_SURFACE_MAPS_LISTED;
        size_t i = 0;
        char item[CDL_SCENE_PATH_MAX];
        for (const cJSON *e = node->child; e; e = e->next, ++i) {
            cdl_scene_json_path_index(item, path, i);
            if (!cJSON_IsString(e)) return cdl_scene_json_fail(ctx, item, "a surface name", e);
            size_t found = 0;
            for (size_t k = 0; k < scene->surface_count; ++k)
                if (scene->surfaces[k].name && strcmp(scene->surfaces[k].name, e->valuestring) == 0) {
                    if (scene->surfaces[k].mapped) return cdl_scene_json_fail(ctx, item, "each surface named once", e);
                    scene->surfaces[k].mapped = 1;
                    ++found;
                }
            if (!found)
                return cdl_scene_json_failf(ctx, item, "the name of a surface in \"surfaces\"",
                                            "\"%s\", which no surface has", e->valuestring);
        }
    } else if (node) {
        if (!cJSON_IsString(node) || cdl_scene_json_read_choice(ctx, node, path, modes, 1, &mode) != CDL_OK) {
            cdl_error_clear(ctx->err);
            return cdl_scene_json_fail(ctx, path, expected, node);
        }
        scene->settings.surface_maps = mode == 1 ? CDL_SURFACE_MAPS_ALL : CDL_SURFACE_MAPS_NONE;
    }
    for (size_t k = 0; k < scene->surface_count; ++k) {
        cdl_surface_spec *s = &scene->surfaces[k];
        s->mapped |= scene->settings.surface_maps == CDL_SURFACE_MAPS_ALL || s->required_Em_lx > 0.0 ||
                     s->required_U0 > 0.0;
        if (s->mapped && name_map(ctx, scene, k) != CDL_OK) return CDL_ERR_INPUT;
    }
    return CDL_OK;
}

/* ---- the document ------------------------------------------------------------------ */

/* Allocate *items for the array `node` (optional unless min_count > 0). */
static cdl_status array_items(const cdl_scene_parse *ctx, const cJSON *node, const char *path, const char *expected,
                              size_t min_count, size_t item_size, void **items, size_t *count)
{
    *count = 0;
    if (!node && min_count == 0) return CDL_OK;
    if (cdl_scene_json_check_array(ctx, node, path, expected, min_count) != CDL_OK) return CDL_ERR_INPUT;
    size_t n = (size_t)cJSON_GetArraySize(node);
    *items = calloc(n ? n : 1, item_size);
    if (!*items) return cdl_error_out_of_memory(ctx->err);
    *count = n;
    return CDL_OK;
}

static cdl_status read_document(const cdl_scene_parse *ctx, const cJSON *root, cdl_scene *scene)
{
    char p[CDL_SCENE_PATH_MAX], item[CDL_SCENE_PATH_MAX], named[CDL_SCENE_PATH_MAX];
    if (cdl_scene_json_check_object(ctx, root, "", "a scene", document_keys) != CDL_OK) return CDL_ERR_INPUT;
    /* "$schema" names the JSON Schema editors check the file against
     * (data/scene.schema.json); the loader needs nothing from it. */
    const cJSON *schema = field(root, "", "$schema", p);
    if (schema && !cJSON_IsString(schema))
        return cdl_scene_json_fail(ctx, p, "the address of the scene's JSON Schema (a string)", schema);
    const cJSON *version = field(root, "", "version", p);
    if (!cJSON_IsNumber(version) || version->valuedouble != 1.0)
        return cdl_scene_json_fail(ctx, p, "the scene format version 1", version);
    if (cdl_scene_json_read_about(ctx, root, scene) != CDL_OK) return CDL_ERR_INPUT;

    const cJSON *list = field(root, "", "surfaces", p);
    if (array_items(ctx, list, p, "a list of surfaces", 0, sizeof *scene->surfaces, (void **)&scene->surfaces,
                    &scene->surface_count) != CDL_OK)
        return CDL_ERR_INPUT;
    size_t i = 0;
    for (const cJSON *e = list ? list->child : NULL; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        if (cdl_scene_json_read_surface(ctx, e, item, CDL_SHAPE_USE_SURFACE, &scene->surfaces[i]) != CDL_OK)
            return CDL_ERR_INPUT;
    }

    list = field(root, "", "luminaires", p);
    if (list && cdl_scene_json_check_array(ctx, list, p, "a list of luminaires", 0) != CDL_OK) return CDL_ERR_INPUT;
    i = 0;
    for (const cJSON *e = list ? list->child : NULL; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        if (read_luminaire_entry(ctx, e, item, i, scene) != CDL_OK) return CDL_ERR_INPUT;
    }

    list = field(root, "", "observers", p);
    if (list && cdl_scene_json_check_array(ctx, list, p, "a list of observers", 0) != CDL_OK) return CDL_ERR_INPUT;
    i = 0;
    for (const cJSON *e = list ? list->child : NULL; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        if (cdl_scene_json_read_observer_entry(ctx, e, item, i, scene) != CDL_OK) return CDL_ERR_INPUT;
        const char *name = cJSON_GetStringValue(cdl_scene_json_member(e, "name"));
        size_t k = 0;
        for (const cJSON *f = list->child; f != e; f = f->next, ++k)
            if (names_equal_ignoring_case(cJSON_GetStringValue(cdl_scene_json_member(f, "name")), name)) {
                cdl_scene_json_path_key(named, item, "name");
                return cdl_scene_json_failf(ctx, named, "an observer name not used before (ignoring case)",
                                            "\"%s\", already the name of observers[%zu]", name, k);
            }
    }
    size_t observer_entries = i;
    const cJSON *observer_list = list;

    /* Grids: at least one, unless there are observers to rate. A grid of
     * "type": "observers" places observers, not calculation points. */
    list = field(root, "", "grids", p);
    size_t entries = 0;
    if (array_items(ctx, list, p,
                    observer_entries ? "a list of calculation grids" : "a list of at least one calculation grid",
                    observer_entries ? 0 : 1, sizeof *scene->grids, (void **)&scene->grids, &entries) != CDL_OK)
        return CDL_ERR_INPUT;
    const char **names = calloc(entries ? entries : 1, sizeof *names);
    if (!names) return cdl_error_out_of_memory(ctx->err);
    cdl_status st = CDL_OK;
    i = 0;
    for (const cJSON *e = list ? list->child : NULL; st == CDL_OK && e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        const cJSON *type = cJSON_IsObject(e) ? cdl_scene_json_member(e, "type") : NULL;
        if (cJSON_IsString(type) && strcmp(type->valuestring, "observers") == 0) {
            st = cdl_scene_json_read_observer_grid(ctx, e, item, i, scene);
            /* its name, in the document (which outlives this loop) */
            if (st == CDL_OK) names[i] = cJSON_GetStringValue(cdl_scene_json_member(e, "name"));
            size_t k = 0;
            for (const cJSON *f = observer_list ? observer_list->child : NULL; st == CDL_OK && f; f = f->next, ++k)
                if (names_equal_ignoring_case(cJSON_GetStringValue(cdl_scene_json_member(f, "name")), names[i])) {
                    cdl_scene_json_path_key(named, item, "name");
                    st = cdl_scene_json_failf(ctx, named, "a name not used by an observer (ignoring case)",
                                              "\"%s\", already the name of observers[%zu]", names[i], k);
                }
        } else {
            st = read_grid(ctx, e, item, &scene->grids[scene->grid_count]);
            if (st == CDL_OK) names[i] = scene->grids[scene->grid_count++].name;
            else grid_spec_free(&scene->grids[scene->grid_count]); /* what it read before it failed */
        }
        for (size_t k = 0; st == CDL_OK && k < i; ++k)
            if (names[k] && names_equal_ignoring_case(names[k], names[i])) {
                cdl_scene_json_path_key(named, item, "name");
                st = cdl_scene_json_failf(ctx, named, "a grid name not used before (ignoring case)",
                                          "\"%s\", already the name of grids[%zu]", names[i], k);
            }
    }
    free(names);
    if (st != CDL_OK) return st;
    if (scene->grid_count + scene->observer_count == 0)
        return cdl_scene_json_fail(ctx, p, "at least one calculation grid or observer", list);
    const cJSON *solver = field(root, "", "solver", p);
    if (read_settings(ctx, solver, p, &scene->settings) != CDL_OK) return CDL_ERR_INPUT;
    return read_surface_maps(ctx, solver ? field(solver, p, "surface_maps", item) : NULL, item, scene);
}

/* Line and column (1-based) of byte `offset` in text. */
static void line_column(const char *text, size_t offset, size_t *line, size_t *column)
{
    *line = 1;
    *column = 1;
    for (size_t i = 0; i < offset && text[i]; ++i) {
        if (text[i] == '\n') {
            ++*line;
            *column = 1;
        } else {
            ++*column;
        }
    }
}

/* cJSON reports where it gave up, which is at or shortly after the error. */
static cdl_status json_syntax_error(cdl_error *err, const char *file, const char *text, size_t size, size_t offset)
{
    size_t line, column;
    line_column(text, offset, &line, &column);
    char near[48];
    size_t k = 0;
    for (size_t i = offset; i < size && k + 4 < sizeof near && text[i] != '\n'; ++i)
        near[k++] = isprint((unsigned char)text[i]) ? text[i] : '?';
    near[k] = '\0';
    if (offset >= size)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:%zu:%zu: invalid JSON: expected a well-formed JSON document, found a syntax error at "
                             "or before the end of the file",
                             file, line, column);
    return cdl_error_set(err, CDL_ERR_INPUT,
                         "%s:%zu:%zu: invalid JSON: expected a well-formed JSON document, found a syntax error at or "
                         "before \"%s\"",
                         file, line, column, near);
}


cdl_status cdl_scene_load_string(const char *json, const char *path, cdl_scene **out, cdl_error *err)
{
    *out = NULL;
    if (!path) path = "scene.json";
    cdl_scene *scene = calloc(1, sizeof *scene);
    if (!scene) return cdl_error_out_of_memory(err);
    const char *slash = strrchr(path, '/');
    scene->path = cdl_string_copy_n(path, strlen(path));
    scene->base_dir = !slash ? cdl_string_copy_n(".", 1) : slash == path ? cdl_string_copy_n("/", 1)
                                                                   : cdl_string_copy_n(path, (size_t)(slash - path));
    if (!scene->path || !scene->base_dir) {
        cdl_scene_release(scene);
        return cdl_error_out_of_memory(err);
    }

    size_t size = strlen(json);
    size_t skip = size >= 3 && memcmp(json, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0; /* UTF-8 byte-order mark */
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(json + skip, &end, 1);
    if (!root) {
        size_t offset = end && end >= json + skip ? (size_t)(end - json) : skip;
        cdl_status st = json_syntax_error(err, path, json, size, offset);
        cdl_scene_release(scene);
        return st;
    }
    cdl_scene_parse ctx = {path, scene->base_dir, err};
    cdl_status st = read_document(&ctx, root, scene);
    if (st == CDL_OK) st = cdl_scene_inputs_from_document(root, &scene->inputs, err);
    cJSON_Delete(root);
    if (st != CDL_OK) {
        cdl_scene_release(scene);
        return st;
    }
    *out = scene;
    return CDL_OK;
}

cdl_status cdl_scene_load(const char *path, cdl_scene **out, cdl_error *err)
{
    *out = NULL;
    char *text = NULL;
    size_t size = 0;
    cdl_status read = cdl_file_read_bytes(path, "scene file", CDL_SCENE_MAX_JSON_BYTES, &text, &size, err);
    if (read != CDL_OK) return read;
    const char *nul = memchr(text, '\0', size);
    if (nul) {
        size_t line, column;
        line_column(text, (size_t)(nul - text), &line, &column);
        free(text);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%zu:%zu: invalid JSON: expected text, found a NUL byte", path,
                             line, column);
    }
    cdl_status st = cdl_scene_load_string(text, path, out, err);
    free(text);
    return st;
}

void cdl_scene_release(cdl_scene *scene)
{
    if (!scene) return;
    for (size_t i = 0; i < scene->surface_count; ++i) cdl_scene_surface_spec_free(&scene->surfaces[i]);
    free(scene->surfaces);
    for (size_t i = 0; i < scene->luminaire_count; ++i) {
        free(scene->luminaires[i].name);
        free(scene->luminaires[i].file);
        cdl_scene_surface_spec_free(&scene->luminaires[i].shape);
    }
    free(scene->luminaires);
    for (size_t i = 0; i < scene->grid_count; ++i) grid_spec_free(&scene->grids[i]);
    free(scene->grids);
    for (size_t i = 0; i < scene->observer_count; ++i) free(scene->observers[i].name);
    free(scene->observers);
    free(scene->name);
    cdl_scene_project_free(&scene->project);
    cdl_scene_inputs_release(&scene->inputs);
    free(scene->path);
    free(scene->base_dir);
    free(scene);
}

/* ---- what the loader knows ---------------------------------------------------------- */

void cdl_scene_keys_collect(cdl_scene_keys *out)
{
    memset(out, 0, sizeof *out);
    size_t n = 0;
    out->sets[n++] = (cdl_scene_key_set){"scene", document_keys};
    out->sets[n++] = (cdl_scene_key_set){"solver", settings_keys};
    out->sets[n++] = (cdl_scene_key_set){"project", cdl_scene_project_keys};
    out->sets[n++] = (cdl_scene_key_set){"grid point", point_keys};
    out->sets[n++] = (cdl_scene_key_set){"array", cdl_scene_array_keys};
    out->sets[n++] = (cdl_scene_key_set){"requirements", cdl_scene_requirements_keys};
    out->sets[n++] = (cdl_scene_key_set){"sun", cdl_scene_sun_keys};
    out->sets[n++] = (cdl_scene_key_set){"site", cdl_scene_site_keys};
    out->sets[n++] = (cdl_scene_key_set){"observer", cdl_scene_observer_keys};
    out->sets[n++] = (cdl_scene_key_set){"grid observers", cdl_scene_observer_grid_keys};
    out->sets[n++] = (cdl_scene_key_set){"observer requirements", cdl_scene_observer_requirements_keys};
    for (int t = 0; luminaire_types[t]; ++t, ++n) {
        snprintf(out->names[n], sizeof out->names[n], "luminaire %s", luminaire_types[t]);
        out->sets[n] = (cdl_scene_key_set){out->names[n], luminaire_keys[t]};
    }
    for (int t = 0; grid_types[t]; ++t, ++n) {
        snprintf(out->names[n], sizeof out->names[n], "grid %s", grid_types[t]);
        out->sets[n] = (cdl_scene_key_set){out->names[n], grid_keys[t]};
    }
    out->count = n + cdl_scene_surface_key_sets(out, n);
}

void cdl_luminaire_spec_label(const cdl_luminaire_spec *spec, char *out, size_t size)
{
    char copy[64] = "";
    if (spec->copy_count > 1) snprintf(copy, sizeof copy, "%zu of %zu", spec->copy + 1, spec->copy_count);
    if (spec->name && copy[0]) snprintf(out, size, "%s (%s, %s)", spec->json_path, spec->name, copy);
    else if (spec->name) snprintf(out, size, "%s (%s)", spec->json_path, spec->name);
    else if (copy[0]) snprintf(out, size, "%s (%s)", spec->json_path, copy);
    else snprintf(out, size, "%s", spec->json_path);
}
