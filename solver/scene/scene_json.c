/* scene_json.c - typed, path-aware readers of cJSON nodes for the scene loader.
 *
 * Every message has the form "SCENE.json: PATH: expected WHAT, found WHAT",
 * so a user can find the value in the file and knows what to write instead.
 */
#include "solver/scene/scene_parse.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/strings.h"

/* out = parent + separator + text, truncated to CDL_SCENE_PATH_MAX - 1 characters. */
static void path_join(char *out, const char *parent, const char *separator, const char *text, const char *closing)
{
    const char *parts[4] = {parent, separator, text, closing};
    size_t len = 0;
    if (out != parent) out[0] = '\0';
    else len = strlen(out);
    for (int i = out == parent ? 1 : 0; i < 4; ++i)
        for (const char *c = parts[i]; *c && len + 1 < CDL_SCENE_PATH_MAX; ++c) out[len++] = *c;
    out[len] = '\0';
}

void cdl_scene_json_copy_path(char *json_path, const char *path)
{
    size_t n = strlen(path);
    if (n > CDL_JSON_PATH_SIZE - 1) n = CDL_JSON_PATH_SIZE - 1;
    memcpy(json_path, path, n);
    json_path[n] = '\0';
}

void cdl_scene_json_path_key(char *out, const char *parent, const char *key)
{
    path_join(out, parent, parent[0] ? "." : "", key, "");
}

void cdl_scene_json_path_index(char *out, const char *parent, size_t index)
{
    char digits[24];
    snprintf(digits, sizeof digits, "%zu", index);
    path_join(out, parent, "[", digits, "]");
}

void cdl_scene_json_describe(const cJSON *node, char *out, size_t size)
{
    if (!node) {
        snprintf(out, size, "nothing (the key is missing)");
    } else if (cJSON_IsString(node)) {
        const char *s = node->valuestring ? node->valuestring : "";
        if (strlen(s) <= 40)
            snprintf(out, size, "the string \"%s\"", s);
        else
            snprintf(out, size, "a string of %zu characters", strlen(s));
    } else if (cJSON_IsNumber(node)) {
        if (isfinite(node->valuedouble))
            snprintf(out, size, "the number %.10g", node->valuedouble);
        else
            snprintf(out, size, "a number too large for a double (%s)", node->valuedouble > 0 ? "+inf" : "-inf");
    } else if (cJSON_IsArray(node)) {
        int n = cJSON_GetArraySize(node);
        snprintf(out, size, n == 0 ? "an empty array" : n == 1 ? "an array of 1 item" : "an array of %d items", n);
    } else if (cJSON_IsObject(node)) {
        snprintf(out, size, "an object");
    } else if (cJSON_IsBool(node)) {
        snprintf(out, size, "%s", cJSON_IsTrue(node) ? "true" : "false");
    } else if (cJSON_IsNull(node)) {
        snprintf(out, size, "null");
    } else {
        snprintf(out, size, "an unreadable value");
    }
}

cdl_status cdl_scene_json_failf(const cdl_scene_parse *ctx, const char *path, const char *expected, const char *fmt, ...)
{
    char found[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(found, sizeof found, fmt, ap);
    va_end(ap);
    if (path && path[0])
        return cdl_error_set(ctx->err, CDL_ERR_INPUT, "%s: %s: expected %s, found %s", ctx->file, path, expected, found);
    return cdl_error_set(ctx->err, CDL_ERR_INPUT, "%s: expected %s, found %s", ctx->file, expected, found);
}

cdl_status cdl_scene_json_fail(const cdl_scene_parse *ctx, const char *path, const char *expected, const cJSON *found)
{
    char what[128];
    cdl_scene_json_describe(found, what, sizeof what);
    return cdl_scene_json_failf(ctx, path, expected, "%s", what);
}

const cJSON *cdl_scene_json_member(const cJSON *object, const char *key)
{
    return cJSON_GetObjectItemCaseSensitive(object, key);
}

const cJSON *cdl_scene_json_field(const cJSON *object, const char *path, const char *key, char *key_path)
{
    cdl_scene_json_path_key(key_path, path, key);
    return cJSON_GetObjectItemCaseSensitive(object, key);
}

cdl_status cdl_scene_json_check_object(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                       const char *what, const char *const *allowed)
{
    char expected[512];
    if (!cJSON_IsObject(node)) {
        snprintf(expected, sizeof expected, "%s (a JSON object)", what);
        return cdl_scene_json_fail(ctx, path, expected, node);
    }
    char key_path[CDL_SCENE_PATH_MAX];
    for (const cJSON *child = node->child; child; child = child->next) {
        const char *key = child->string ? child->string : "";
        cdl_scene_json_path_key(key_path, path, key);
        for (const cJSON *earlier = node->child; earlier != child; earlier = earlier->next)
            if (earlier->string && strcmp(earlier->string, key) == 0)
                return cdl_scene_json_failf(ctx, key_path, "each key once", "\"%s\" a second time", key);
        int known = 0;
        for (size_t i = 0; allowed[i]; ++i)
            if (strcmp(allowed[i], key) == 0) known = 1;
        if (!known) {
            size_t len = (size_t)snprintf(expected, sizeof expected, "a key of %s (", what);
            for (size_t i = 0; allowed[i] && len < sizeof expected; ++i)
                len += (size_t)snprintf(expected + len, sizeof expected - len, "%s%s", i ? ", " : "", allowed[i]);
            if (len < sizeof expected) snprintf(expected + len, sizeof expected - len, ")");
            return cdl_scene_json_failf(ctx, key_path, expected, "an unknown key");
        }
    }
    return CDL_OK;
}

cdl_status cdl_scene_json_check_array(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const char *expected, size_t min_count)
{
    if (!cJSON_IsArray(node) || (size_t)cJSON_GetArraySize(node) < min_count)
        return cdl_scene_json_fail(ctx, path, expected, node);
    return CDL_OK;
}

static const char *range_text(cdl_scene_range range)
{
    switch (range) {
    case CDL_RANGE_ANY: return "a number";
    case CDL_RANGE_NONNEGATIVE: return "a number >= 0";
    case CDL_RANGE_POSITIVE: return "a number > 0";
    case CDL_RANGE_UNIT: return "a number in [0, 1]";
    case CDL_RANGE_UNIT_OPEN0: return "a number in (0, 1]";
    }
    return "a number";
}

static int in_range(double v, cdl_scene_range range)
{
    switch (range) {
    case CDL_RANGE_ANY: return 1;
    case CDL_RANGE_NONNEGATIVE: return v >= 0.0;
    case CDL_RANGE_POSITIVE: return v > 0.0;
    case CDL_RANGE_UNIT: return v >= 0.0 && v <= 1.0;
    case CDL_RANGE_UNIT_OPEN0: return v > 0.0 && v <= 1.0;
    }
    return 0;
}

/* The checks every number of a scene passes, whether written as a JSON
 * number or as a quantity with its unit; `node` is what the file holds. */
static cdl_status accept_number(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_scene_range range,
                                double value, double *out)
{
    if (!isfinite(value) || !in_range(value, range)) return cdl_scene_json_fail(ctx, path, range_text(range), node);
    if (fabs(value) > CDL_SCENE_MAX_MAGNITUDE) {
        char expected[96];
        snprintf(expected, sizeof expected, "%s of magnitude at most %g", range_text(range), CDL_SCENE_MAX_MAGNITUDE);
        return cdl_scene_json_fail(ctx, path, expected, node);
    }
    *out = value;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_number(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      cdl_scene_range range, int required, double *out)
{
    if (!node && !required) return CDL_OK;
    if (!cJSON_IsNumber(node)) return cdl_scene_json_fail(ctx, path, range_text(range), node);
    return accept_number(ctx, node, path, range, node->valuedouble, out);
}

cdl_status cdl_scene_json_read_quantity(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                        cdl_dimension dimension, cdl_scene_range range, int required, double *out)
{
    if (!cJSON_IsString(node) || !node->valuestring)
        return cdl_scene_json_read_number(ctx, node, path, range, required, out);
    cdl_error parse_err;
    double value = 0.0;
    if (cdl_quantity_parse(node->valuestring, dimension, &value, &parse_err) != CDL_OK)
        return cdl_error_set(ctx->err, CDL_ERR_INPUT, "%s: %s: %s", ctx->file, path, parse_err.message);
    return accept_number(ctx, node, path, range, value, out);
}

cdl_status cdl_scene_json_read_integer(const cdl_scene_parse *ctx, const cJSON *node, const char *path, double lo,
                                       double hi, int required, double *out)
{
    if (!node && !required) return CDL_OK;
    if (!cJSON_IsNumber(node) || !isfinite(node->valuedouble) || node->valuedouble != floor(node->valuedouble) ||
        node->valuedouble < lo || node->valuedouble > hi) {
        char expected[96];
        snprintf(expected, sizeof expected, "an integer in [%.17g, %.17g]", lo, hi);
        return cdl_scene_json_fail(ctx, path, expected, node);
    }
    *out = node->valuedouble;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_bool(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                    int *out)
{
    if (!node && !required) return CDL_OK;
    if (!cJSON_IsBool(node)) return cdl_scene_json_fail(ctx, path, "true or false", node);
    *out = cJSON_IsTrue(node) ? 1 : 0;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_choice(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const char *const *choices, int required, int *out)
{
    if (!node && !required) return CDL_OK;
    if (cJSON_IsString(node) && node->valuestring)
        for (int i = 0; choices[i]; ++i)
            if (strcmp(choices[i], node->valuestring) == 0) {
                *out = i;
                return CDL_OK;
            }
    char expected[256];
    size_t len = (size_t)snprintf(expected, sizeof expected, "one of the strings");
    for (int i = 0; choices[i] && len < sizeof expected; ++i)
        len += (size_t)snprintf(expected + len, sizeof expected - len, "%s \"%s\"", i ? "," : "", choices[i]);
    return cdl_scene_json_fail(ctx, path, expected, node);
}

cdl_status cdl_scene_json_read_string(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                      char **out)
{
    if (!node && !required) return CDL_OK;
    if (!cJSON_IsString(node) || !node->valuestring || !node->valuestring[0])
        return cdl_scene_json_fail(ctx, path, "a non-empty string", node);
    char *copy = cdl_string_copy(node->valuestring);
    if (!copy) return cdl_error_out_of_memory(ctx->err);
    free(*out);
    *out = copy;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_vec3(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int nonzero,
                                    int required, cdl_vec3 *out)
{
    if (!node && !required) return CDL_OK;
    const char *expected = nonzero ? "a non-zero vector of 3 numbers" : "an array of 3 numbers";
    if (!cJSON_IsArray(node) || cJSON_GetArraySize(node) != 3) return cdl_scene_json_fail(ctx, path, expected, node);
    double c[3];
    int i = 0;
    for (const cJSON *e = node->child; e; e = e->next, ++i) {
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble) || fabs(e->valuedouble) > CDL_SCENE_MAX_MAGNITUDE) {
            char item[CDL_SCENE_PATH_MAX], expected[64];
            cdl_scene_json_path_index(item, path, (size_t)i);
            snprintf(expected, sizeof expected, "a finite number of magnitude at most %g", CDL_SCENE_MAX_MAGNITUDE);
            return cdl_scene_json_fail(ctx, item, expected, e);
        }
        c[i] = e->valuedouble;
    }
    cdl_vec3 v = cdl_vec3_make(c[0], c[1], c[2]);
    if (nonzero && !(cdl_vec3_length(v) > 0.0))
        return cdl_scene_json_failf(ctx, path, expected, "the zero vector");
    *out = v;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_ring(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_ring3 *out)
{
    const char *expected = "a list of at least 3 points [x, y, z]";
    if (!cJSON_IsArray(node)) return cdl_scene_json_fail(ctx, path, expected, node);
    size_t n = (size_t)cJSON_GetArraySize(node);
    cdl_vec3 *pts = malloc((n ? n : 1) * sizeof *pts);
    if (!pts) return cdl_error_out_of_memory(ctx->err);
    size_t i = 0;
    char item[CDL_SCENE_PATH_MAX];
    for (const cJSON *e = node->child; e; e = e->next, ++i) {
        cdl_scene_json_path_index(item, path, i);
        if (cdl_scene_json_read_vec3(ctx, e, item, 0, 1, &pts[i]) != CDL_OK) {
            free(pts);
            return CDL_ERR_INPUT;
        }
    }
    /* A ring written closed (last point = first) means the same polygon. */
    if (n >= 2 && pts[n - 1].x == pts[0].x && pts[n - 1].y == pts[0].y && pts[n - 1].z == pts[0].z) --n;
    if (n < 3) {
        free(pts);
        return cdl_scene_json_fail(ctx, path, expected, node);
    }
    out->points = pts;
    out->count = n;
    return CDL_OK;
}

cdl_status cdl_scene_json_read_path(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                    char **out)
{
    char *name = NULL;
    if (!node && !required) return CDL_OK;
    if (cdl_scene_json_read_string(ctx, node, path, 1, &name) != CDL_OK) return CDL_ERR_INPUT;
    if (name[0] == '/' || !ctx->base_dir[0] || strcmp(ctx->base_dir, ".") == 0) {
        free(*out);
        *out = name;
        return CDL_OK;
    }
    size_t len = strlen(ctx->base_dir) + 1 + strlen(name) + 1;
    char *full = malloc(len);
    if (!full) {
        free(name);
        return cdl_error_out_of_memory(ctx->err);
    }
    snprintf(full, len, "%s/%s", ctx->base_dir, name);
    free(name);
    free(*out);
    *out = full;
    return CDL_OK;
}

int cdl_scene_name_ok(const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n > 64 || name[0] == '.' || name[0] == '-') return 0;
    for (size_t i = 0; i < n; ++i)
        if (!isalnum((unsigned char)name[i]) && name[i] != '.' && name[i] != '_' && name[i] != '-') return 0;
    return 1;
}
