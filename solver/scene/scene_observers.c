/* scene_observers.c - "observers" and grids of "type": "observers": the
 * eyes and lines of sight glare is rated for (CIE 117:1995 UGR).
 *
 *   key            meaning                                         unit
 *   name           required, a name usable as a file name
 *   eye            the eye (or "positions": one observer at each)  m
 *   array          {"counts": [n1, n2], "spacing": [d1, d2]}: rows m
 *                  along the line of sight and to its left
 *   view           the line of sight, within 1 degree of the       any length > 0
 *                  horizontal (CIE 117's position index assumes a
 *                  horizontal one)
 *   requirements   {"UGR_L": limit}, EN 12464-1's UGR limit
 * An observer grid: name, "type": "observers", origin, u, v, nu, nv as a
 * rect grid (an observer at each cell centre, u fastest), view,
 * requirements.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiometry/constants.h"
#include "solver/scene/scene_parse.h"

const char *const cdl_scene_observer_keys[] = {"name", "eye", "positions", "array", "view", "requirements", NULL};
const char *const cdl_scene_observer_grid_keys[] = {"name", "type", "origin", "u", "v", "nu", "nv", "view",
                                                    "requirements", NULL};
const char *const cdl_scene_observer_requirements_keys[] = {"UGR_L", NULL};

/* The line of sight: a direction within CDL_OBSERVER_TILT_MAX_DEG of the
 * horizontal, kept as its unit horizontal part. */
static cdl_status read_view(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_vec3 *out)
{
    cdl_vec3 v;
    if (cdl_scene_json_read_vec3(ctx, node, path, 1, 1, &v) != CDL_OK) return CDL_ERR_INPUT;
    double horizontal = hypot(v.x, v.y), tilt = atan2(fabs(v.z), horizontal) * CDL_RAD_TO_DEG;
    if (!(tilt <= CDL_OBSERVER_TILT_MAX_DEG))
        return cdl_scene_json_failf(ctx, path,
                                    "a horizontal line of sight (within 1 degree: CIE 117's position index is for "
                                    "a horizontal view)",
                                    "[%.6g, %.6g, %.6g], %.3g degrees %s the horizontal", v.x, v.y, v.z, tilt,
                                    v.z > 0.0 ? "above" : "below");
    *out = cdl_vec3_make(v.x / horizontal, v.y / horizontal, 0.0);
    return CDL_OK;
}

/* "requirements": {"UGR_L": limit}. */
static cdl_status read_requirements(const cdl_scene_parse *ctx, const cJSON *node, const char *path, double *ugr_l)
{
    *ugr_l = 0.0;
    if (!node) return CDL_OK;
    char p[CDL_SCENE_PATH_MAX];
    if (cdl_scene_json_check_object(ctx, node, path, "requirements {\"UGR_L\": limit}",
                                    cdl_scene_observer_requirements_keys) != CDL_OK)
        return CDL_ERR_INPUT;
    return cdl_scene_json_read_number(ctx, cdl_scene_json_field(node, path, "UGR_L", p), p, CDL_RANGE_POSITIVE, 1,
                                      ugr_l);
}

static cdl_status read_name(const cdl_scene_parse *ctx, const cJSON *node, const char *path, char **out)
{
    char p[CDL_SCENE_PATH_MAX];
    const cJSON *name = cdl_scene_json_field(node, path, "name", p);
    if (!cJSON_IsString(name) || !cdl_scene_name_ok(name->valuestring))
        return cdl_scene_json_fail(ctx, p,
                                   "an observer name usable as a file name (1 to 64 letters, digits, '.', '_', '-', "
                                   "not starting with '.' or '-')",
                                   name);
    return cdl_scene_json_read_string(ctx, name, p, 1, out);
}

/* Room for n more observers. */
static cdl_status grow(const cdl_scene_parse *ctx, const char *path, cdl_scene *scene, size_t n)
{
    if (scene->observer_count + n > CDL_SCENE_MAX_OBSERVERS)
        return cdl_scene_json_failf(ctx, path, "at most 100000 observers in a scene", "%zu with this entry's",
                                    scene->observer_count + n);
    cdl_observer_spec *grown = realloc(scene->observers, (scene->observer_count + n) * sizeof *grown);
    if (!grown) return cdl_error_out_of_memory(ctx->err);
    scene->observers = grown;
    return CDL_OK;
}

/* Append the observer `proto` as copy k of n: its own name ("NAME[k]"
 * when n > 1). */
static cdl_status append(const cdl_scene_parse *ctx, cdl_scene *scene, const cdl_observer_spec *proto, size_t k,
                         size_t n)
{
    cdl_observer_spec *o = &scene->observers[scene->observer_count];
    *o = *proto;
    o->copy = k;
    o->copy_count = n;
    size_t len = strlen(proto->name) + 24;
    o->name = malloc(len);
    if (!o->name) return cdl_error_out_of_memory(ctx->err);
    if (n > 1) snprintf(o->name, len, "%s[%zu]", proto->name, k);
    else snprintf(o->name, len, "%s", proto->name);
    scene->observer_count++;
    return CDL_OK;
}

/* What every observer of an entry shares: its place in the document, its
 * keys checked, its line of sight and requirements. */
static cdl_status read_common(const cdl_scene_parse *ctx, const cJSON *node, const char *path, size_t entry,
                              const char *what, const char *const *keys, cdl_observer_spec *proto)
{
    char p[CDL_SCENE_PATH_MAX];
    memset(proto, 0, sizeof *proto);
    cdl_scene_json_copy_path(proto->json_path, path);
    proto->entry = entry;
    if (cdl_scene_json_check_object(ctx, node, path, what, keys) != CDL_OK ||
        read_view(ctx, cdl_scene_json_field(node, path, "view", p), p, &proto->view) != CDL_OK ||
        read_requirements(ctx, cdl_scene_json_field(node, path, "requirements", p), p, &proto->required_ugr) != CDL_OK)
        return CDL_ERR_INPUT;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_observer_entry(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                              size_t entry, cdl_scene *scene)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_observer_spec proto;
    if (read_common(ctx, node, path, entry, "an observer", cdl_scene_observer_keys, &proto) != CDL_OK)
        return CDL_ERR_INPUT;
    const cJSON *eye = cdl_scene_json_field(node, path, "eye", p);
    if (eye && cdl_scene_json_member(node, "positions"))
        return cdl_scene_json_failf(ctx, p, "either \"eye\" or \"positions\"", "both");
    if (!cdl_scene_json_member(node, "positions") &&
        cdl_scene_json_read_vec3(ctx, eye, p, 0, 1, &proto.eye) != CDL_OK)
        return CDL_ERR_INPUT;
    /* Copies as a luminaire's: a frame turned about z to the line of sight
     * lays an "array" out along it (x) and to its left (y). */
    cdl_luminaire_spec frame;
    memset(&frame, 0, sizeof frame);
    frame.kind = CDL_LUMINAIRE_GONIOMETRIC;
    frame.position = proto.eye;
    frame.rotation_deg[2] = atan2(proto.view.y, proto.view.x) * CDL_RAD_TO_DEG;
    cdl_luminaire_copies copies;
    cdl_status st = cdl_scene_json_read_copies(ctx, node, path, &frame, &copies);
    if (st == CDL_OK) st = grow(ctx, path, scene, copies.count);
    if (st == CDL_OK) st = read_name(ctx, node, path, &proto.name);
    for (size_t k = 0; st == CDL_OK && k < copies.count; ++k) {
        proto.eye = copies.positions[k];
        proto.array_index[0] = copies.index[k][0];
        proto.array_index[1] = copies.index[k][1];
        st = append(ctx, scene, &proto, k, copies.count);
    }
    free(proto.name);
    cdl_scene_luminaire_copies_free(&copies);
    return st;
}

cdl_status cdl_scene_json_read_observer_grid(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                             size_t entry, cdl_scene *scene)
{
    char p[CDL_SCENE_PATH_MAX];
    cdl_observer_spec proto;
    cdl_vec3 origin, u, v;
    double nu = 0, nv = 0;
    if (read_common(ctx, node, path, entry, "an observer grid", cdl_scene_observer_grid_keys, &proto) != CDL_OK ||
        cdl_scene_json_read_span(ctx, node, path, &origin, &u, &v) != CDL_OK ||
        cdl_scene_json_read_integer(ctx, cdl_scene_json_field(node, path, "nu", p), p, 1, CDL_SCENE_MAX_OBSERVERS, 1,
                                    &nu) != CDL_OK ||
        cdl_scene_json_read_integer(ctx, cdl_scene_json_field(node, path, "nv", p), p, 1, CDL_SCENE_MAX_OBSERVERS, 1,
                                    &nv) != CDL_OK)
        return CDL_ERR_INPUT;
    proto.from_grid = 1;
    size_t n = (size_t)nu * (size_t)nv;
    cdl_status st = grow(ctx, path, scene, n);
    if (st == CDL_OK) st = read_name(ctx, node, path, &proto.name);
    /* an observer at each cell centre, as a rect grid's points: u fastest */
    for (size_t k = 0; st == CDL_OK && k < n; ++k) {
        int i = (int)(k % (size_t)nu), j = (int)(k / (size_t)nu);
        proto.eye = cdl_vec3_madd(cdl_vec3_madd(origin, (i + 0.5) / nu, u), (j + 0.5) / nv, v);
        proto.array_index[0] = i;
        proto.array_index[1] = j;
        st = append(ctx, scene, &proto, k, n);
    }
    free(proto.name);
    return st;
}
