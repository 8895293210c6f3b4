/* scene_placement.c - where a luminaire entry puts its luminaires, and which way they point.
 *
 * Keys (point, spot and goniometric luminaires; DESIGN.md, "Scene file"):
 *   aim        [x, y, z] m   spot, goniometric: the point the spot axis (or
 *                            the photometric nadir, gamma = 0) points at;
 *                            instead of "direction" (spot) or "rotation"
 *   spin       deg, 0        with aim: the luminaire turned about its own
 *                            nadir, right-handed about the axis pointing
 *                            away from the aim point (counter-clockwise
 *                            seen from behind the luminaire)
 *   array      {"counts": [nx, ny], "spacing": [dx, dy], "axes": A}: nx x ny
 *                            copies at position + R (i dx, j dy, 0), i < nx,
 *                            j < ny; counts >= 1, spacing in metres. With
 *                            "axes": "luminaire" (the default) R is the
 *                            entry's orientation (its rotation, or its aim
 *                            from `position`; for a spot the turn taking -z
 *                            to its axis; none for a point), so the rows run
 *                            along the luminaire's C0 (x) and C90 (y) axes
 *                            whichever way it is turned; with "axes":
 *                            "world" R is the identity: rows along world x
 *                            and y, as a plan shows them
 *   positions  [[x, y, z], ...]: one copy at each point, instead of
 *                            "position"
 * With aim, every copy points at the aim point from its own position; with
 * "positions", "aim" may also be a list of as many points, each copy aimed
 * at its own (floodlights on masts aimed over a pitch).
 *
 * Aim, as a rotation: first `spin` about the luminaire's z axis, then the
 * shortest turn taking the nadir -z to the unit vector d from the
 * luminaire to the aim point (Rodrigues' rotation formula about the axis
 * (-z) x d by the angle between them; d = +z, straight up, turns by 180
 * degrees about x). This agrees with "rotation": a nadir aimed 30 degrees
 * from -z towards +x is rotation [0, -30, 0]. The goniometric emitter
 * takes Euler angles, world_from_luminaire = Rz(c) Ry(b) Rx(a) (fixed
 * axes), recovered from the matrix: b = -asin(R20), a = atan2(R21, R22),
 * c = atan2(R10, R00) (with c = 0 where cos b = 0).
 */
#include "solver/scene/scene_parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

/* Aim points closer to the luminaire than this give no direction. */
#define AIM_MIN_DISTANCE 1e-9

typedef struct mat3 {
    double m[3][3];
} mat3;

static mat3 mat3_mul(mat3 a, mat3 b)
{
    mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}

static cdl_vec3 mat3_apply(mat3 a, cdl_vec3 v)
{
    return cdl_vec3_make(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                         a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                         a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}

/* Rotation by `angle` (radians) about the unit axis k (Rodrigues):
 * R = cos t I + sin t [k]x + (1 - cos t) k k^T. */
static mat3 mat3_axis_angle(cdl_vec3 k, double angle)
{
    double c = cos(angle), s = sin(angle), t = 1.0 - c;
    mat3 r = {{{c + t * k.x * k.x, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
               {t * k.y * k.x + s * k.z, c + t * k.y * k.y, t * k.y * k.z - s * k.x},
               {t * k.z * k.x - s * k.y, t * k.z * k.y + s * k.x, c + t * k.z * k.z}}};
    return r;
}

/* Rz(c) Ry(b) Rx(a), the goniometric emitter's world_from_luminaire. */
static mat3 mat3_from_euler_deg(const double deg[3])
{
    mat3 rx = mat3_axis_angle(cdl_vec3_make(1, 0, 0), deg[0] * CDL_DEG_TO_RAD);
    mat3 ry = mat3_axis_angle(cdl_vec3_make(0, 1, 0), deg[1] * CDL_DEG_TO_RAD);
    mat3 rz = mat3_axis_angle(cdl_vec3_make(0, 0, 1), deg[2] * CDL_DEG_TO_RAD);
    return mat3_mul(rz, mat3_mul(ry, rx));
}

static void mat3_to_euler_deg(mat3 r, double deg[3])
{
    double sb = -r.m[2][0];
    if (sb > 1.0) sb = 1.0;
    if (sb < -1.0) sb = -1.0;
    double b = asin(sb), cb = sqrt(r.m[0][0] * r.m[0][0] + r.m[1][0] * r.m[1][0]);
    double a, c;
    if (cb > 1e-12) {
        a = atan2(r.m[2][1], r.m[2][2]);
        c = atan2(r.m[1][0], r.m[0][0]);
    } else {
        /* Gimbal lock (nadir horizontal along x): c = 0, then R01 = sin a sin b, R11 = cos a. */
        a = atan2(sb * r.m[0][1], r.m[1][1]);
        c = 0.0;
    }
    deg[0] = a / CDL_DEG_TO_RAD;
    deg[1] = b / CDL_DEG_TO_RAD;
    deg[2] = c / CDL_DEG_TO_RAD;
}

/* The shortest turn taking -z to the unit vector d. */
static mat3 mat3_nadir_to(cdl_vec3 d)
{
    cdl_vec3 nadir = cdl_vec3_make(0, 0, -1);
    cdl_vec3 axis = cdl_vec3_cross(nadir, d);
    double s = cdl_vec3_length(axis), c = cdl_vec3_dot(nadir, d);
    if (s < 1e-15) return mat3_axis_angle(cdl_vec3_make(1, 0, 0), c > 0.0 ? 0.0 : CDL_PI);
    return mat3_axis_angle(cdl_vec3_scale(axis, 1.0 / s), atan2(s, c));
}

/* The orientation of a luminaire: world_from_luminaire. */
static mat3 orientation(const cdl_luminaire_spec *spec)
{
    mat3 identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    switch (spec->kind) {
    case CDL_LUMINAIRE_SPOT: {
        mat3 spin = mat3_axis_angle(cdl_vec3_make(0, 0, 1), spec->spin_deg * CDL_DEG_TO_RAD);
        return mat3_mul(mat3_nadir_to(spec->direction), spin);
    }
    case CDL_LUMINAIRE_GONIOMETRIC: return mat3_from_euler_deg(spec->rotation_deg);
    default: return identity;
    }
}

/* Point a spot or goniometric luminaire at spec->aim from spec->position. */
static int aim_copy(cdl_luminaire_spec *spec)
{
    cdl_vec3 to = cdl_vec3_sub(spec->aim, spec->position);
    double len = cdl_vec3_length(to);
    if (!(len > AIM_MIN_DISTANCE)) return 0;
    cdl_vec3 d = cdl_vec3_scale(to, 1.0 / len);
    if (spec->kind == CDL_LUMINAIRE_SPOT) {
        spec->direction = d;
        return 1;
    }
    mat3 spin = mat3_axis_angle(cdl_vec3_make(0, 0, 1), spec->spin_deg * CDL_DEG_TO_RAD);
    mat3_to_euler_deg(mat3_mul(mat3_nadir_to(d), spin), spec->rotation_deg);
    return 1;
}

cdl_status cdl_scene_json_read_aim(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                   cdl_luminaire_spec *out)
{
    char p[CDL_SCENE_PATH_MAX];
    const cJSON *aim = cdl_scene_json_field(node, path, "aim", p);
    const cJSON *spin = cdl_scene_json_member(node, "spin");
    if (!aim) {
        if (spin) {
            cdl_scene_json_path_key(p, path, "spin");
            return cdl_scene_json_failf(ctx, p, "\"spin\" only with \"aim\" (rotation already says how the luminaire "
                                        "turns)", "\"spin\" without \"aim\"");
        }
        return CDL_OK;
    }
    const char *other = out->kind == CDL_LUMINAIRE_SPOT ? "direction" : "rotation";
    if (cdl_scene_json_member(node, other)) {
        char exp[96];
        snprintf(exp, sizeof exp, "either \"aim\" or \"%s\"", other);
        return cdl_scene_json_failf(ctx, p, exp, "both");
    }
    out->has_aim = 1;
    if (cJSON_IsArray(aim) && cJSON_IsArray(aim->child)) {
        /* a list of aim points: each copy of "positions" its own (read with the copies) */
        if (!cdl_scene_json_member(node, "positions"))
            return cdl_scene_json_failf(ctx, p, "one aim point [x, y, z] (a list of them goes with \"positions\", one "
                                        "each)", "a list without \"positions\"");
    } else if (cdl_scene_json_read_vec3(ctx, aim, p, 0, 1, &out->aim) != CDL_OK) {
        return CDL_ERR_INPUT;
    }
    cdl_scene_json_path_key(p, path, "spin");
    return cdl_scene_json_read_number(ctx, spin, p, CDL_RANGE_ANY, 0, &out->spin_deg);
}

/* ---- copies ------------------------------------------------------------------------ */

const char *const cdl_scene_array_keys[] = {"counts", "spacing", "axes", NULL};

static cdl_status read_array(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int counts[2],
                             double spacing[2], int *world_axes)
{
    const char *const *keys = cdl_scene_array_keys;
    char p[CDL_SCENE_PATH_MAX], item[CDL_SCENE_PATH_MAX];
    if (!cJSON_IsObject(node))
        return cdl_scene_json_fail(ctx, path, "an array of luminaires {\"counts\": [nx, ny], \"spacing\": [dx, dy]}",
                                   node);
    if (cdl_scene_json_check_object(ctx, node, path, "a luminaire array", keys) != CDL_OK) return CDL_ERR_INPUT;
    const cJSON *c = cdl_scene_json_field(node, path, "counts", p);
    if (!cJSON_IsArray(c) || cJSON_GetArraySize(c) != 2)
        return cdl_scene_json_fail(ctx, p, "two whole numbers [nx, ny] >= 1", c);
    for (int k = 0; k < 2; ++k) {
        double v = 0;
        cdl_scene_json_path_index(item, p, (size_t)k);
        if (cdl_scene_json_read_integer(ctx, cJSON_GetArrayItem(c, k), item, 1, CDL_SCENE_MAX_LUMINAIRES, 1, &v) !=
            CDL_OK)
            return CDL_ERR_INPUT;
        counts[k] = (int)v;
    }
    const cJSON *s = cdl_scene_json_field(node, path, "spacing", p);
    if (!cJSON_IsArray(s) || cJSON_GetArraySize(s) != 2)
        return cdl_scene_json_fail(ctx, p, "two distances [dx, dy] in metres", s);
    for (int k = 0; k < 2; ++k) {
        cdl_scene_json_path_index(item, p, (size_t)k);
        if (cdl_scene_json_read_number(ctx, cJSON_GetArrayItem(s, k), item, CDL_RANGE_ANY, 1, &spacing[k]) != CDL_OK)
            return CDL_ERR_INPUT;
    }
    if ((double)counts[0] * counts[1] > CDL_SCENE_MAX_LUMINAIRES)
        return cdl_scene_json_failf(ctx, path, "at most 1000000 luminaires", "%d x %d", counts[0], counts[1]);
    const cJSON *axes = cdl_scene_json_field(node, path, "axes", p);
    *world_axes = 0;
    if (axes) {
        if (!cJSON_IsString(axes) || (strcmp(axes->valuestring, "world") && strcmp(axes->valuestring, "luminaire")))
            return cdl_scene_json_fail(ctx, p, "\"luminaire\" (rows along the luminaire's C0 and C90 axes, the "
                                       "default) or \"world\" (rows along world x and y)", axes);
        *world_axes = strcmp(axes->valuestring, "world") == 0;
    }
    return CDL_OK;
}

/* "aim" as a list, one point per entry of "positions": each copy its own. */
static cdl_status read_aims(const cdl_scene_parse *ctx, const cJSON *node, const char *path, size_t count,
                            cdl_luminaire_copies *out)
{
    const cJSON *aim = cdl_scene_json_member(node, "aim");
    if (!cJSON_IsArray(aim) || !cJSON_IsArray(aim->child)) return CDL_OK; /* one point, read with the luminaire */
    char p[CDL_SCENE_PATH_MAX], item[CDL_SCENE_PATH_MAX];
    cdl_scene_json_path_key(p, path, "aim");
    if ((size_t)cJSON_GetArraySize(aim) != count)
        return cdl_scene_json_failf(ctx, p, "one aim point per entry of \"positions\"", "%d aim points for %zu positions",
                                    cJSON_GetArraySize(aim), count);
    out->aims = malloc(count * sizeof *out->aims);
    if (!out->aims) return cdl_error_out_of_memory(ctx->err);
    size_t i = 0;
    for (const cJSON *e = aim->child; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, p, i);
        if (cdl_scene_json_read_vec3(ctx, e, item, 0, 1, &out->aims[i]) != CDL_OK) return CDL_ERR_INPUT;
    }
    return CDL_OK;
}

cdl_status cdl_scene_json_read_copies(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const cdl_luminaire_spec *proto, cdl_luminaire_copies *out)
{
    char p[CDL_SCENE_PATH_MAX];
    memset(out, 0, sizeof *out);
    const cJSON *array = cdl_scene_json_member(node, "array");
    const cJSON *positions = cdl_scene_json_member(node, "positions");
    const cJSON *position = cdl_scene_json_member(node, "position");
    if (array && positions) {
        cdl_scene_json_path_key(p, path, "positions");
        return cdl_scene_json_failf(ctx, p, "either \"array\" or \"positions\"", "both");
    }
    if (positions && position) {
        cdl_scene_json_path_key(p, path, "positions");
        return cdl_scene_json_failf(ctx, p, "either \"position\" or \"positions\"", "both");
    }
    if (positions) {
        cdl_scene_json_path_key(p, path, "positions");
        if (cdl_scene_json_check_array(ctx, positions, p, "a non-empty list of positions [x, y, z]", 1) != CDL_OK)
            return CDL_ERR_INPUT;
        size_t n = (size_t)cJSON_GetArraySize(positions);
        if (n > CDL_SCENE_MAX_LUMINAIRES) return cdl_scene_json_failf(ctx, p, "at most 1000000 positions", "%zu", n);
        out->positions = malloc(n * sizeof *out->positions);
        out->index = malloc(n * sizeof *out->index);
        if (!out->positions || !out->index) return cdl_error_out_of_memory(ctx->err);
        size_t i = 0;
        char item[CDL_SCENE_PATH_MAX];
        for (const cJSON *e = positions->child; e; e = e->next, ++i) {
            cdl_scene_json_path_index(item, p, i);
            if (cdl_scene_json_read_vec3(ctx, e, item, 0, 1, &out->positions[i]) != CDL_OK) return CDL_ERR_INPUT;
            out->index[i][0] = (int)i;
            out->index[i][1] = 0;
        }
        out->count = n;
        return read_aims(ctx, node, path, n, out);
    }
    /* "position" was read into proto by the luminaire's reader. */
    int counts[2] = {1, 1}, world_axes = 0;
    double spacing[2] = {0.0, 0.0};
    if (array) {
        cdl_scene_json_path_key(p, path, "array");
        if (read_array(ctx, array, p, counts, spacing, &world_axes) != CDL_OK) return CDL_ERR_INPUT;
    }
    size_t n = (size_t)counts[0] * (size_t)counts[1];
    out->positions = malloc(n * sizeof *out->positions);
    out->index = malloc(n * sizeof *out->index);
    if (!out->positions || !out->index) return cdl_error_out_of_memory(ctx->err);
    mat3 identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    mat3 r = world_axes ? identity : orientation(proto);
    cdl_vec3 ex = mat3_apply(r, cdl_vec3_make(1, 0, 0)), ey = mat3_apply(r, cdl_vec3_make(0, 1, 0));
    size_t k = 0;
    for (int j = 0; j < counts[1]; ++j)
        for (int i = 0; i < counts[0]; ++i, ++k) {
            cdl_vec3 q = cdl_vec3_madd(proto->position, i * spacing[0], ex);
            out->positions[k] = cdl_vec3_madd(q, j * spacing[1], ey);
            out->index[k][0] = i;
            out->index[k][1] = j;
        }
    out->count = n;
    return CDL_OK;
}

void cdl_scene_luminaire_copies_free(cdl_luminaire_copies *copies)
{
    free(copies->positions);
    free(copies->index);
    free(copies->aims);
    memset(copies, 0, sizeof *copies);
}

cdl_status cdl_scene_place_copy(const cdl_scene_parse *ctx, const char *path, cdl_luminaire_spec *spec)
{
    if (!spec->has_aim || aim_copy(spec)) return CDL_OK;
    char p[CDL_SCENE_PATH_MAX];
    cdl_scene_json_path_key(p, path, "aim");
    return cdl_scene_json_failf(ctx, p, "a point away from the luminaire (it says which way the luminaire points)",
                                "[%.10g, %.10g, %.10g], the luminaire's own position", spec->aim.x, spec->aim.y,
                                spec->aim.z);
}
