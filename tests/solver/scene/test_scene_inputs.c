/* What a solve's results depend on, hashed part by part (scene_inputs.h):
 * the same scene written another way (whitespace, key order, 0.8 as 8e-1)
 * hashes the same; each change a report must refuse is named by its JSON
 * path and key (a maintenance factor, a box face's reflectance, a key or an
 * entry added or removed, a photometric file's content); what no result
 * depends on (threads, a grid's requirements, the name and project) does
 * not count; summary.json's form reads back to the same parts. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "solver/scene/scene_internal.h"

static char folder[512], ies[640];

/* The base scene, with `luminaire` and `extra` spliced in. */
static cdl_scene *load(const char *surface, const char *luminaire, const char *grid, const char *top)
{
    char json[4096], path[700];
    snprintf(json, sizeof json,
             "{\"version\": 1, %s\n"
             " \"surfaces\": [%s],\n"
             " \"luminaires\": [%s],\n"
             " \"grids\": [%s]}",
             top, surface, luminaire, grid);
    snprintf(path, sizeof path, "%s/scene.json", folder);
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_status st = cdl_scene_load_string(json, path, &scene, &err);
    CHECK_MSG(st == CDL_OK, "%s", err.message);
    return scene;
}

static const char *const room =
    "{\"name\": \"room\", \"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 4, 2.8], \"inward\": true,"
    " \"reflectance\": {\"floor\": 0.2, \"walls\": 0.5, \"ceiling\": 0.7}}";
static const char *const downlight =
    "{\"type\": \"goniometric\", \"file\": \"downlight.ies\", \"position\": [3, 2, 2.7], \"maintenance_factor\": 0.8}";
static const char *const desk =
    "{\"name\": \"desk\", \"type\": \"rect\", \"origin\": [1, 1, 0.8], \"u\": [4, 0, 0], \"v\": [0, 2, 0], \"nu\": 8,"
    " \"nv\": 4}";
static const char *const solver = "\"solver\": {\"seed\": 1, \"threads\": 0},";

/* The differences between two scenes' inputs (files read now), as text. */
static size_t changes(const cdl_scene *a, const cdl_scene *b, char *text, size_t size)
{
    cdl_scene_inputs ia, ib;
    cdl_error err;
    CHECK(cdl_scene_inputs_collect(a, &ia, &err) == CDL_OK);
    CHECK(cdl_scene_inputs_collect(b, &ib, &err) == CDL_OK);
    size_t n = cdl_scene_inputs_describe_changes(&ia, &ib, text, size);
    /* the one hash agrees with the list */
    CHECK_MSG((n == 0) == (cdl_scene_inputs_hash(&ia) == cdl_scene_inputs_hash(&ib)), "%zu changes: %s", n, text);
    cdl_scene_inputs_release(&ia);
    cdl_scene_inputs_release(&ib);
    return n;
}

static void expect(const cdl_scene *a, const cdl_scene *b, size_t count, const char *says)
{
    char text[1024];
    size_t n = changes(a, b, text, sizeof text);
    CHECK_MSG(n == count, "%zu changes, expected %zu: \"%s\"", n, count, text);
    CHECK_MSG(!says || strstr(text, says), "\"%s\" does not say \"%s\"", text, says);
}

int main(void)
{
    CHECK(fixture_folder("scene_inputs", folder, sizeof folder));
    size_t size = 0;
    char *bytes = fixture_read_file(CANDELA_SOURCE_DIR "/data/office/downlight.ies", &size);
    CHECK(bytes != NULL);
    if (!bytes) return check_finish();
    snprintf(ies, sizeof ies, "%s/downlight.ies", folder);
    CHECK(fixture_write_file(ies, bytes));

    cdl_scene *base = load(room, downlight, desk, solver);
    if (!base) return check_finish();
    CHECK(base->inputs.count > 10);

    /* The same scene written otherwise: keys reordered, numbers spelt
     * otherwise, other whitespace. */
    cdl_scene *same = load("{\"reflectance\": {\"walls\": 5e-1, \"ceiling\": 0.70, \"floor\": 0.2},"
                           "\"type\":\"box\",\"max\":[6.0,4,2.80],\"min\":[0,0,-0],\"inward\":true,\"name\":\"room\"}",
                           "{\"maintenance_factor\": 8e-1, \"position\": [3.0, 2, 2.7], \"file\": \"downlight.ies\","
                           " \"type\": \"goniometric\"}",
                           desk, "\"solver\": {\"threads\": 0, \"seed\": 1.0},");
    expect(base, same, 0, NULL);

    /* What no result depends on: threads, a grid's requirements, the name and the project. */
    cdl_scene *report_only =
        load(room, downlight,
             "{\"name\": \"desk\", \"type\": \"rect\", \"origin\": [1, 1, 0.8], \"u\": [4, 0, 0], \"v\": [0, 2, 0],"
             " \"nu\": 8, \"nv\": 4, \"requirements\": {\"Em_lx\": 500}}",
             "\"name\": \"Office\", \"project\": {\"client\": \"ACME\"}, \"solver\": {\"seed\": 1, \"threads\": 2},");
    expect(base, report_only, 0, NULL);

    /* The case: a maintenance factor and a reflectance changed after the solve. */
    cdl_scene *mf = load(room,
                         "{\"type\": \"goniometric\", \"file\": \"downlight.ies\", \"position\": [3, 2, 2.7],"
                         " \"maintenance_factor\": 0.5}",
                         desk, solver);
    expect(base, mf, 1, "luminaires[0].maintenance_factor changed");
    cdl_scene *rho = load("{\"name\": \"room\", \"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 4, 2.8], "
                          "\"inward\": true, \"reflectance\": {\"floor\": 0.2, \"walls\": 0.6, \"ceiling\": 0.7}}",
                          downlight, desk, solver);
    expect(base, rho, 1, "surfaces[0].reflectance changed");
    cdl_scene *seed = load(room, downlight, desk, "\"solver\": {\"seed\": 2, \"threads\": 0},");
    expect(base, seed, 1, "solver.seed changed");

    /* A key added, an entry added (named once, not key by key), and removed. */
    cdl_scene *turned = load(room,
                             "{\"type\": \"goniometric\", \"file\": \"downlight.ies\", \"position\": [3, 2, 2.7],"
                             " \"maintenance_factor\": 0.8, \"rotation\": [0, 0, 90]}",
                             desk, solver);
    expect(base, turned, 1, "luminaires[0].rotation added");
    expect(turned, base, 1, "luminaires[0].rotation removed");
    char two[1024];
    snprintf(two, sizeof two, "%s, {\"type\": \"point\", \"position\": [1, 1, 2], \"intensity_cd\": 100}", downlight);
    cdl_scene *more = load(room, two, desk, solver);
    expect(base, more, 1, "luminaires[1] added");
    expect(more, base, 1, "luminaires[1] removed");

    /* The photometric file's content: one byte changed (a candela value)
     * between the solve's hashes and the report's. */
    cdl_scene_inputs before, after;
    cdl_error err;
    CHECK(cdl_scene_inputs_collect(base, &before, &err) == CDL_OK);
    char *digit = strstr(bytes, "TILT=NONE");
    CHECK(digit != NULL);
    while (digit && *digit && (*digit < '1' || *digit > '8')) ++digit;
    if (digit && *digit) {
        ++*digit;
        CHECK(fixture_write_file(ies, bytes));
        CHECK(cdl_scene_inputs_collect(base, &after, &err) == CDL_OK);
        char says[800], text[1024];
        snprintf(says, sizeof says, "luminaires[0].file content changed (%s)", ies);
        CHECK(cdl_scene_inputs_describe_changes(&before, &after, text, sizeof text) == 1);
        CHECK_MSG(strstr(text, says), "\"%s\" does not say \"%s\"", text, says);
        CHECK(cdl_scene_inputs_hash(&before) != cdl_scene_inputs_hash(&after));
        cdl_scene_inputs_release(&after);
        --*digit;
        CHECK(fixture_write_file(ies, bytes));
    }
    cdl_scene_inputs_release(&before);

    /* summary.json's form reads back to the same parts; a damaged one is refused. */
    cdl_scene_inputs now, back;
    CHECK(cdl_scene_inputs_collect(base, &now, &err) == CDL_OK);
    cJSON *json = cdl_scene_inputs_to_json(&now);
    CHECK(json != NULL);
    CHECK(cdl_scene_inputs_from_json(json, "summary.json: inputs", &back, &err) == CDL_OK);
    char text[256];
    CHECK(cdl_scene_inputs_describe_changes(&back, &now, text, sizeof text) == 0);
    CHECK(back.count == now.count && cdl_scene_inputs_hash(&back) == cdl_scene_inputs_hash(&now));
    cdl_scene_inputs_release(&back);
    cJSON_ReplaceItemInObject(cJSON_GetObjectItem(cJSON_GetObjectItem(json, "parts"), "luminaires[0]"), "position",
                              cJSON_CreateString("not hex"));
    CHECK(cdl_scene_inputs_from_json(json, "summary.json: inputs", &back, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "summary.json: inputs: parts.luminaires[0].position: expected 16 hex digits"),
              "%s", err.message);
    CHECK(cdl_scene_inputs_from_json(NULL, "summary.json: inputs", &back, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "solve again"), "%s", err.message);
    cJSON_Delete(json);

    /* Many changes: the first 8 named, then how many more. */
    cdl_scene_inputs other;
    CHECK(cdl_scene_inputs_collect(base, &other, &err) == CDL_OK);
    for (size_t k = 0; k < other.count; ++k) other.parts[k].hash ^= 1u;
    char list[1024];
    size_t n = cdl_scene_inputs_describe_changes(&now, &other, list, sizeof list);
    CHECK(n == now.count);
    char tail[64];
    snprintf(tail, sizeof tail, "; and %zu more", now.count - 8);
    CHECK_MSG(strstr(list, tail) != NULL, "%s", list);
    cdl_scene_inputs_release(&other);
    cdl_scene_inputs_release(&now);

    cdl_scene_release(base);
    cdl_scene_release(same);
    cdl_scene_release(report_only);
    cdl_scene_release(mf);
    cdl_scene_release(rho);
    cdl_scene_release(seed);
    cdl_scene_release(turned);
    cdl_scene_release(more);
    free(bytes);
    return check_finish();
}
