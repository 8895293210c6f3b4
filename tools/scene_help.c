/* scene_help.c - `candela help scene`: the scene format's reference, printed from its JSON Schema.
 *
 * Sections in the order a scene is written: the top level, surfaces, area
 * luminaires' shapes, luminaires, the sun and the site of a daylight sky,
 * luminaire arrays, grids and their points, grids' requirements, observers
 * and theirs, solver settings. Each key on one line with what it takes (its
 * type, unit and range) and its default or "required", then what it
 * means. Everything comes from data/scene.schema.json (compiled in), so
 * the reference cannot say other than the schema editors check against.
 */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene_help.h"
#include "solver/scene/scene_schema.h"

/* What a $ref names, in words. */
static const char *ref_words(const char *ref)
{
    static const struct {
        const char *ref, *words;
    } names[] = {
        {"#/$defs/vec3", "[x, y, z]"},
        {"#/$defs/ring", "list of points [x, y, z]"},
        {"#/$defs/quantity", "number, or text with a unit"},
        {"#/$defs/unit_interval", "number in [0, 1]"},
        {"#/$defs/array", "object (see \"luminaire array\")"},
        {"#/$defs/shape", "object (see the shapes)"},
        {"#/$defs/solver", "object (see \"solver settings\")"},
        {"#/$defs/surface", "surface"},
        {"#/$defs/luminaire", "luminaire"},
        {"#/$defs/grid", "grid"},
        {"#/$defs/grid_point", "{\"p\": [x, y, z], \"n\": [nx, ny, nz]}"},
        {"#/$defs/requirements", "object (see \"grid requirements\")"},
        {"#/$defs/sun", "object (see \"sun\")"},
        {"#/$defs/site", "object (see \"site\")"},
        {"#/$defs/observer", "observer"},
        {"#/$defs/observer_requirements", "object (see \"observer requirements\")"},
        {"#/$defs/project", "object (see \"project\")"},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strcmp(ref, names[i].ref) == 0) return names[i].words;
    return ref;
}

static void append(char *out, size_t size, const char *fmt, const char *text)
{
    size_t n = strlen(out);
    if (n < size) snprintf(out + n, size - n, fmt, text);
}

static void append_number(char *out, size_t size, const char *fmt, double v)
{
    char num[32];
    snprintf(num, sizeof num, "%.10g", v);
    append(out, size, fmt, num);
}

/* "number > 0, <= 180", "one of auto, direct", ... */
static void describe_value(const cJSON *p, char *out, size_t size)
{
    const cJSON *ref = cJSON_GetObjectItemCaseSensitive(p, "$ref");
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(p, "type");
    const cJSON *en = cJSON_GetObjectItemCaseSensitive(p, "enum");
    const cJSON *cn = cJSON_GetObjectItemCaseSensitive(p, "const");
    const cJSON *one = cJSON_GetObjectItemCaseSensitive(p, "oneOf");
    const cJSON *items = cJSON_GetObjectItemCaseSensitive(p, "items");
    if (cJSON_IsString(ref)) {
        append(out, size, "%s", ref_words(ref->valuestring));
    } else if (cJSON_IsArray(en)) {
        append(out, size, "%s", "one of ");
        for (const cJSON *e = en->child; e; e = e->next) append(out, size, e->next ? "%s, " : "%s", e->valuestring);
    } else if (cn) {
        if (cJSON_IsString(cn)) append(out, size, "\"%s\"", cn->valuestring);
        else append_number(out, size, "%s", cn->valuedouble);
    } else if (cJSON_IsArray(one)) {
        for (const cJSON *e = one->child; e; e = e->next) {
            if (e != one->child) append(out, size, "%s", " or ");
            describe_value(e, out, size);
        }
    } else if (cJSON_IsString(type) && strcmp(type->valuestring, "array") == 0) {
        append(out, size, "%s", "list of ");
        if (items) describe_value(items, out, size);
    } else if (cJSON_IsString(type)) {
        const char *t = type->valuestring;
        append(out, size, "%s", strcmp(t, "integer") == 0 ? "whole number" : strcmp(t, "string") == 0 ? "text" : t);
    }
    const char *bounds[][2] = {{"minimum", ">= %s"}, {"exclusiveMinimum", "> %s"}, {"maximum", "<= %s"},
                               {"exclusiveMaximum", "< %s"}};
    int first = 1;
    for (int b = 0; b < 4; ++b) {
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(p, bounds[b][0]);
        if (!cJSON_IsNumber(v)) continue;
        append(out, size, "%s", first ? " (" : ", ");
        first = 0;
        append_number(out, size, bounds[b][1], v->valuedouble);
    }
    if (!first) append(out, size, "%s", ")");
    const cJSON *unit = cJSON_GetObjectItemCaseSensitive(p, "x-unit");
    if (cJSON_IsString(unit) && unit->valuestring[0]) append(out, size, ", in %s", unit->valuestring);
    const cJSON *range = cJSON_GetObjectItemCaseSensitive(p, "x-range");
    if (cJSON_IsString(range)) append(out, size, ", %s", range->valuestring);
}

static int is_required(const cJSON *object, const char *key)
{
    const cJSON *req = cJSON_GetObjectItemCaseSensitive(object, "required");
    for (const cJSON *r = req ? req->child : NULL; r; r = r->next)
        if (cJSON_IsString(r) && strcmp(r->valuestring, key) == 0) return 1;
    return 0;
}

static void print_object(FILE *out, const char *heading, const cJSON *object)
{
    const cJSON *desc = cJSON_GetObjectItemCaseSensitive(object, "description");
    fprintf(out, "\n%s%s%s\n", heading, cJSON_IsString(desc) ? ": " : "", cJSON_IsString(desc) ? desc->valuestring : "");
    const cJSON *props = cJSON_GetObjectItemCaseSensitive(object, "properties");
    for (const cJSON *p = props ? props->child : NULL; p; p = p->next) {
        if (strcmp(p->string, "type") == 0) continue; /* in the heading */
        char what[512] = "";
        describe_value(p, what, sizeof what);
        const cJSON *def = cJSON_GetObjectItemCaseSensitive(p, "default");
        char dflt[128] = "";
        if (is_required(object, p->string)) {
            snprintf(dflt, sizeof dflt, "; required");
        } else if (def) {
            char *text = cJSON_PrintUnformatted(def);
            snprintf(dflt, sizeof dflt, "; default %s", text ? text : "");
            cJSON_free(text);
        }
        fprintf(out, "  %-22s %s%s\n", p->string, what, dflt);
        const cJSON *d = cJSON_GetObjectItemCaseSensitive(p, "description");
        if (cJSON_IsString(d)) fprintf(out, "  %-22s   %s\n", "", d->valuestring);
    }
}

int cdl_scene_help_print(FILE *out)
{
    cJSON *schema = cJSON_Parse(cdl_scene_schema_text);
    if (!schema) return 3;
    fprintf(out,
            "candela help scene - the scene file of `candela solve`, every key with what it takes\n"
            "(type, unit, range), its default or \"required\", and what it means. From the JSON\n"
            "Schema data/scene.schema.json (draft 2020-12): `candela help scene --schema` prints it\n"
            "for editors, and a scene may name it in \"$schema\".\n");
    const cJSON *root_title = cJSON_GetObjectItemCaseSensitive(schema, "title");
    char top[96];
    snprintf(top, sizeof top, "%s (the top level)", cJSON_IsString(root_title) ? root_title->valuestring : "scene");
    print_object(out, top, schema);
    const cJSON *defs = cJSON_GetObjectItemCaseSensitive(schema, "$defs");
    static const char *const order[] = {"surface_", "shape_",       "luminaire_", "sun",     "site",   "array",
                                        "grid_",    "requirements", "observer",   "project", "solver", NULL};
    for (int k = 0; order[k]; ++k)
        for (const cJSON *d = defs ? defs->child : NULL; d; d = d->next) {
            const cJSON *t = cJSON_GetObjectItemCaseSensitive(d, "title");
            if (!cJSON_IsString(t) || strncmp(d->string, order[k], strlen(order[k])) != 0) continue;
            const cJSON *props = cJSON_GetObjectItemCaseSensitive(d, "properties");
            const cJSON *kind = cJSON_GetObjectItemCaseSensitive(props, "type");
            const cJSON *c = kind ? cJSON_GetObjectItemCaseSensitive(kind, "const") : NULL;
            char heading[128];
            if (cJSON_IsString(c)) snprintf(heading, sizeof heading, "%s (\"type\": \"%s\")", t->valuestring, c->valuestring);
            else snprintf(heading, sizeof heading, "%s", t->valuestring);
            print_object(out, heading, d);
        }
    cJSON_Delete(schema);
    return 0;
}

int cdl_scene_help_print_schema(FILE *out)
{
    fputs(cdl_scene_schema_text, out);
    return 0;
}
