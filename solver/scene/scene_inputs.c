/* scene_inputs.c - the parts of a scene that results depend on, hashed (scene_inputs.h). */
#include "solver/scene/scene_inputs.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/error_report.h"
#include "base/grow.h"
#include "base/strings.h"
#include "lights/photometry/photometry_metadata.h"
#include "solver/scene/scene_internal.h"

/* The top-level keys no result depends on: what the report prints about
 * the scene, and the address of its schema. */
static const char *const report_only_keys[] = {"$schema", "name", "project", NULL};
/* The top-level lists whose entries are hashed key by key. */
static const char *const entry_lists[] = {"surfaces", "luminaires", "grids", "observers", NULL};

static int listed(const char *const *list, const char *s)
{
    for (size_t k = 0; list[k]; ++k)
        if (strcmp(list[k], s) == 0) return 1;
    return 0;
}

/* ---- a JSON value's hash ------------------------------------------------------- */

enum { TAG_NULL = 1, TAG_FALSE, TAG_TRUE, TAG_NUMBER, TAG_STRING, TAG_ARRAY, TAG_OBJECT };

static void hash_text(cdl_content_hash *h, const char *s)
{
    size_t n = s ? strlen(s) : 0;
    cdl_content_hash_u64(h, (uint64_t)n);
    cdl_content_hash_raw(h, s ? s : "", n);
}

/* By content: a number by its value (0.8 and 8e-1 alike), an array in order,
 * an object by the sum of its members' hashes (so their order does not
 * count), each member's hash covering its key. */
static uint64_t value_hash(const cJSON *v)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    if (cJSON_IsNumber(v)) {
        cdl_content_hash_u64(&h, TAG_NUMBER);
        cdl_content_hash_f64(&h, v->valuedouble + 0.0); /* -0 as 0 */
    } else if (cJSON_IsString(v)) {
        cdl_content_hash_u64(&h, TAG_STRING);
        hash_text(&h, v->valuestring);
    } else if (cJSON_IsArray(v) || cJSON_IsObject(v)) {
        int object = cJSON_IsObject(v);
        uint64_t sum = 0, count = 0;
        cdl_content_hash_u64(&h, object ? TAG_OBJECT : TAG_ARRAY);
        for (const cJSON *c = v->child; c; c = c->next, ++count) {
            if (!object) {
                cdl_content_hash_u64(&h, value_hash(c));
                continue;
            }
            cdl_content_hash member = CDL_CONTENT_HASH_INIT;
            hash_text(&member, c->string);
            cdl_content_hash_u64(&member, value_hash(c));
            sum += member.value;
        }
        cdl_content_hash_u64(&h, count);
        if (object) cdl_content_hash_u64(&h, sum);
    } else {
        cdl_content_hash_u64(&h, cJSON_IsTrue(v) ? TAG_TRUE : cJSON_IsFalse(v) ? TAG_FALSE : TAG_NULL);
    }
    return h.value;
}

/* ---- the list of parts -------------------------------------------------------- */

static cdl_status add_part(cdl_scene_inputs *in, const char *entry, const char *key, uint64_t hash, const char *file,
                           cdl_error *err)
{
    if (cdl_grow(&in->parts, &in->capacity, in->count + 1, sizeof *in->parts, 64, err) != CDL_OK)
        return CDL_ERR_INTERNAL;
    cdl_scene_input_part *p = &in->parts[in->count];
    p->entry = cdl_string_copy(entry);
    p->key = cdl_string_copy(key);
    p->hash = hash;
    p->file = file;
    if (!p->entry || !p->key) {
        free(p->entry);
        free(p->key);
        return cdl_error_out_of_memory(err);
    }
    ++in->count;
    return CDL_OK;
}

/* Each key of an object (an entry of a list, or "solver"), but those no
 * result depends on. */
static cdl_status add_members(cdl_scene_inputs *in, const char *list, const char *entry, const cJSON *object,
                              cdl_error *err)
{
    for (const cJSON *c = object->child; c; c = c->next) {
        int requirements = strcmp(c->string, "requirements") == 0 &&
                           (strcmp(list, "grids") == 0 || strcmp(list, "observers") == 0);
        int threads = strcmp(list, "solver") == 0 && strcmp(c->string, "threads") == 0;
        if (requirements || threads) continue;
        if (add_part(in, entry, c->string, value_hash(c), NULL, err) != CDL_OK) return CDL_ERR_INTERNAL;
    }
    return CDL_OK;
}

cdl_status cdl_scene_inputs_from_document(const cJSON *root, cdl_scene_inputs *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_status st = CDL_OK;
    for (const cJSON *top = root ? root->child : NULL; top && st == CDL_OK; top = top->next) {
        if (listed(report_only_keys, top->string)) continue;
        if (listed(entry_lists, top->string) && cJSON_IsArray(top)) {
            size_t i = 0;
            for (const cJSON *e = top->child; e && st == CDL_OK; e = e->next, ++i) {
                char entry[64];
                snprintf(entry, sizeof entry, "%s[%zu]", top->string, i);
                st = cJSON_IsObject(e) ? add_members(out, top->string, entry, e, err)
                                       : add_part(out, entry, "", value_hash(e), NULL, err);
            }
        } else if (cJSON_IsObject(top)) {
            st = add_members(out, top->string, top->string, top, err);
        } else {
            st = add_part(out, top->string, "", value_hash(top), NULL, err);
        }
    }
    if (st != CDL_OK) cdl_scene_inputs_release(out);
    return st;
}

/* ---- the files ---------------------------------------------------------------- */

/* A file's bytes; a photometric file's TILT table too (TILT=<file> brings
 * it from another file, which its own bytes do not show). */
static cdl_status file_hash(const char *path, const char *scene_path, const char *json_path, int photometric,
                            uint64_t *out, cdl_error *err)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    int code = cdl_content_hash_file(&h, path);
    if (code != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %s: %s: cannot read it to hash its content: %s", scene_path,
                             json_path, path, strerror(code));
    if (photometric) {
        cdl_photometry *p = NULL;
        cdl_status st = cdl_photometry_read_file(path, NULL, &p, err);
        if (st != CDL_OK) return cdl_error_prefix(err, "%s: %s: ", scene_path, json_path);
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        cdl_content_hash_u64(&h, (uint64_t)m->tilt_count);
        for (size_t k = 0; k < m->tilt_count; ++k) {
            cdl_content_hash_f64(&h, m->tilt_angles_deg[k]);
            cdl_content_hash_f64(&h, m->tilt_factors[k]);
        }
        cdl_photometry_release(p);
    }
    *out = h.value;
    return CDL_OK;
}

/* The file of entry `entry` (its key `key` names it), once per entry. */
static cdl_status add_file(cdl_scene_inputs *in, const cdl_scene *scene, const char *entry, const char *key,
                           const char *path, int photometric, cdl_error *err)
{
    char part_key[64], json_path[160];
    snprintf(part_key, sizeof part_key, "%s content", key);
    for (size_t k = 0; k < in->count; ++k)
        if (in->parts[k].file && strcmp(in->parts[k].entry, entry) == 0 && strcmp(in->parts[k].key, part_key) == 0)
            return CDL_OK; /* another copy of the same entry */
    snprintf(json_path, sizeof json_path, "%s.%s", entry, key);
    uint64_t hash = 0;
    cdl_status st = file_hash(path, scene->path, json_path, photometric, &hash, err);
    return st == CDL_OK ? add_part(in, entry, part_key, hash, path, err) : st;
}

cdl_status cdl_scene_inputs_collect(const cdl_scene *scene, cdl_scene_inputs *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_status st = CDL_OK;
    for (size_t k = 0; k < scene->inputs.count && st == CDL_OK; ++k) {
        const cdl_scene_input_part *p = &scene->inputs.parts[k];
        st = add_part(out, p->entry, p->key, p->hash, NULL, err);
    }
    for (size_t k = 0; k < scene->surface_count && st == CDL_OK; ++k) {
        const cdl_surface_spec *s = &scene->surfaces[k];
        if (s->file) st = add_file(out, scene, s->json_path, "file", s->file, 0, err);
    }
    for (size_t k = 0; k < scene->luminaire_count && st == CDL_OK; ++k) {
        const cdl_luminaire_spec *l = &scene->luminaires[k];
        if (l->file)
            st = add_file(out, scene, l->json_path, "file", l->file, l->kind == CDL_LUMINAIRE_GONIOMETRIC, err);
        if (st == CDL_OK && l->kind == CDL_LUMINAIRE_AREA && l->shape.file)
            st = add_file(out, scene, l->json_path, "shape.file", l->shape.file, 0, err);
    }
    if (st != CDL_OK) cdl_scene_inputs_release(out);
    return st;
}

uint64_t cdl_scene_inputs_hash(const cdl_scene_inputs *in)
{
    uint64_t sum = 0;
    for (size_t k = 0; k < in->count; ++k) {
        cdl_content_hash h = CDL_CONTENT_HASH_INIT;
        hash_text(&h, in->parts[k].entry);
        hash_text(&h, in->parts[k].key);
        cdl_content_hash_u64(&h, in->parts[k].hash);
        sum += h.value;
    }
    cdl_content_hash all = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&all, (uint64_t)in->count);
    cdl_content_hash_u64(&all, sum);
    return all.value;
}

/* ---- summary.json ------------------------------------------------------------- */

static void hex(char out[17], uint64_t v)
{
    snprintf(out, 17, "%016" PRIx64, v);
}

cJSON *cdl_scene_inputs_to_json(const cdl_scene_inputs *in)
{
    cJSON *root = cJSON_CreateObject();
    char text[17];
    hex(text, cdl_scene_inputs_hash(in));
    cJSON *parts = root && cJSON_AddStringToObject(root, "hash", text) ? cJSON_AddObjectToObject(root, "parts") : NULL;
    if (!parts) {
        cJSON_Delete(root);
        return NULL;
    }
    for (size_t k = 0; k < in->count; ++k) {
        const cdl_scene_input_part *p = &in->parts[k];
        cJSON *entry = cJSON_GetObjectItemCaseSensitive(parts, p->entry);
        if (!entry) entry = cJSON_AddObjectToObject(parts, p->entry);
        hex(text, p->hash);
        if (!entry || !cJSON_AddStringToObject(entry, p->key, text)) {
            cJSON_Delete(root);
            return NULL;
        }
    }
    return root;
}

static int parse_hex(const cJSON *v, uint64_t *out)
{
    if (!cJSON_IsString(v) || strlen(v->valuestring) != 16) return 0;
    char *end = NULL;
    *out = strtoull(v->valuestring, &end, 16);
    return *end == '\0';
}

cdl_status cdl_scene_inputs_from_json(const cJSON *json, const char *where, cdl_scene_inputs *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    const cJSON *parts = cJSON_GetObjectItemCaseSensitive(json, "parts");
    if (!cJSON_IsObject(json) || !cJSON_IsObject(parts))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: expected the hashes of the scene's parts ({\"hash\", \"parts\"}), found %s", where,
                             json ? "another value" : "nothing (written before the solve recorded them: solve again)");
    cdl_status st = CDL_OK;
    for (const cJSON *e = parts->child; e && st == CDL_OK; e = e->next)
        for (const cJSON *k = cJSON_IsObject(e) ? e->child : NULL; k && st == CDL_OK; k = k->next) {
            uint64_t hash = 0;
            st = parse_hex(k, &hash) ? add_part(out, e->string, k->string, hash, NULL, err)
                                     : cdl_error_set(err, CDL_ERR_INPUT, "%s: parts.%s.%s: expected 16 hex digits",
                                                     where, e->string, k->string);
        }
    if (st != CDL_OK) cdl_scene_inputs_release(out);
    return st;
}

/* ---- what changed ------------------------------------------------------------- */

/* The part of `in` with this entry and key, or NULL (the same index first:
 * both lists usually come in the document's order). */
static const cdl_scene_input_part *find(const cdl_scene_inputs *in, size_t hint, const char *entry, const char *key)
{
    if (hint < in->count && strcmp(in->parts[hint].entry, entry) == 0 && strcmp(in->parts[hint].key, key) == 0)
        return &in->parts[hint];
    for (size_t k = 0; k < in->count; ++k)
        if (strcmp(in->parts[k].entry, entry) == 0 && strcmp(in->parts[k].key, key) == 0) return &in->parts[k];
    return NULL;
}

static int has_entry(const cdl_scene_inputs *in, const char *entry)
{
    for (size_t k = 0; k < in->count; ++k)
        if (strcmp(in->parts[k].entry, entry) == 0) return 1;
    return 0;
}

typedef struct change_list {
    char *out;
    size_t size, used, count, shown;
} change_list;

#define CHANGES_SHOWN 8

static void say(change_list *c, const char *text)
{
    ++c->count;
    if (c->shown == CHANGES_SHOWN || c->used + 1 >= c->size) return;
    int n = snprintf(c->out + c->used, c->size - c->used, "%s%s", c->shown ? "; " : "", text);
    if (n > 0) c->used = c->used + (size_t)n < c->size ? c->used + (size_t)n : c->size - 1;
    ++c->shown;
}

/* A part's path for the message: "luminaires[0].maintenance_factor", "version". */
static void part_name(char *out, size_t size, const cdl_scene_input_part *p)
{
    snprintf(out, size, "%s%s%s", p->entry, p->key[0] ? "." : "", p->key);
}

/* The parts of `from` that `to` lacks: "ENTRY WHAT" once for an entry
 * `to` lacks whole, else "ENTRY.KEY WHAT". */
static void missing(change_list *c, const cdl_scene_inputs *from, const cdl_scene_inputs *to, const char *what)
{
    char name[160], text[224];
    for (size_t k = 0; k < from->count; ++k) {
        const cdl_scene_input_part *p = &from->parts[k];
        if (find(to, k, p->entry, p->key)) continue;
        int whole = !has_entry(to, p->entry);
        if (whole && k > 0 && strcmp(from->parts[k - 1].entry, p->entry) == 0) continue; /* named already */
        if (whole) snprintf(name, sizeof name, "%s", p->entry);
        else part_name(name, sizeof name, p);
        snprintf(text, sizeof text, "%s %s", name, what);
        say(c, text);
    }
}

size_t cdl_scene_inputs_describe_changes(const cdl_scene_inputs *then, const cdl_scene_inputs *now, char *out,
                                         size_t size)
{
    change_list c = {out, size, 0, 0, 0};
    if (size) out[0] = '\0';
    char name[160], text[512];
    for (size_t k = 0; k < now->count; ++k) {
        const cdl_scene_input_part *p = &now->parts[k];
        const cdl_scene_input_part *q = find(then, k, p->entry, p->key);
        if (!q || q->hash == p->hash) continue;
        part_name(name, sizeof name, p);
        if (p->file) snprintf(text, sizeof text, "%s changed (%s)", name, p->file);
        else snprintf(text, sizeof text, "%s changed", name);
        say(&c, text);
    }
    missing(&c, now, then, "added");
    missing(&c, then, now, "removed");
    if (c.count > c.shown && c.used + 1 < c.size)
        snprintf(c.out + c.used, c.size - c.used, "; and %zu more", c.count - c.shown);
    return c.count;
}

void cdl_scene_inputs_release(cdl_scene_inputs *in)
{
    if (!in) return;
    for (size_t k = 0; k < in->count; ++k) {
        free(in->parts[k].entry);
        free(in->parts[k].key);
    }
    free(in->parts);
    memset(in, 0, sizeof *in);
}
