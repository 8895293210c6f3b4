/* The scene's JSON Schema (data/scene.schema.json) and the loader cannot
 * drift apart: every kind of object the loader knows has a schema entry
 * with exactly the loader's keys (each way: no key the loader accepts is
 * missing from the schema, none the schema offers is refused), every
 * schema entry describing an object is one the loader knows, and the
 * schema compiled into the library (for `candela help scene`) is the file. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_schema.h"

static int in_keys(const char *const *keys, const char *key)
{
    for (size_t i = 0; keys[i]; ++i)
        if (strcmp(keys[i], key) == 0) return 1;
    return 0;
}

int main(void)
{
    size_t size = 0;
    char *text = fixture_read_file(CANDELA_SOURCE_DIR "/data/scene.schema.json", &size);
    CHECK(text != NULL);
    if (!text) return check_finish();
    CHECK_MSG(strcmp(text, cdl_scene_schema_text) == 0, "the compiled-in schema differs from data/scene.schema.json");
    cJSON *schema = cJSON_Parse(text);
    CHECK(schema != NULL);
    const cJSON *defs = cJSON_GetObjectItemCaseSensitive(schema, "$defs");
    CHECK(cJSON_IsObject(defs));

    static cdl_scene_keys known;
    cdl_scene_keys_collect(&known);
    const cdl_scene_key_set *sets = known.sets;
    size_t count = known.count;
    CHECK(count >= 20);
    size_t matched = 0;
    for (size_t s = 0; s < count; ++s) {
        /* "surface rect" is $defs.surface_rect; "scene" the top level. */
        char name[64];
        snprintf(name, sizeof name, "%s", sets[s].object);
        for (char *c = name; *c; ++c)
            if (*c == ' ') *c = '_';
        const cJSON *entry = strcmp(name, "scene") == 0 ? schema : cJSON_GetObjectItemCaseSensitive(defs, name);
        const cJSON *props = entry ? cJSON_GetObjectItemCaseSensitive(entry, "properties") : NULL;
        CHECK_MSG(cJSON_IsObject(props), "the schema has no entry \"%s\" for the loader's %s", name, sets[s].object);
        if (!props) continue;
        ++matched;
        for (size_t k = 0; sets[s].keys[k]; ++k)
            CHECK_MSG(cJSON_GetObjectItemCaseSensitive(props, sets[s].keys[k]) != NULL,
                      "the loader accepts %s.%s, the schema does not know it", sets[s].object, sets[s].keys[k]);
        for (const cJSON *p = props->child; p; p = p->next)
            CHECK_MSG(in_keys(sets[s].keys, p->string), "the schema offers %s.%s, the loader refuses it",
                      sets[s].object, p->string);
        /* Objects the loader checks refuse unknown keys: so must the schema. */
        const cJSON *extra = cJSON_GetObjectItemCaseSensitive(entry, "additionalProperties");
        CHECK_MSG(cJSON_IsFalse(extra), "%s: additionalProperties is not false", name);
    }
    CHECK(matched == count);
    /* The other way: every schema entry of an object with keys is a kind the loader knows. */
    for (const cJSON *d = defs ? defs->child : NULL; d; d = d->next) {
        if (!cJSON_GetObjectItemCaseSensitive(d, "properties")) continue;
        int known = 0;
        for (size_t s = 0; s < count && !known; ++s) {
            char name[64];
            snprintf(name, sizeof name, "%s", sets[s].object);
            for (char *c = name; *c; ++c)
                if (*c == ' ') *c = '_';
            known = strcmp(name, d->string) == 0;
        }
        CHECK_MSG(known, "the schema describes $defs.%s, which the loader does not read", d->string);
    }
    cJSON_Delete(schema);
    free(text);
    return check_finish();
}
