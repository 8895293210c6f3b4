/* scene.glb (gltf_output.h): the GLB container read back byte by byte, its
 * JSON against the meshes given (counts, POSITION bounds, the y-up frame,
 * the false colours as linear light, the illuminance attribute, materials,
 * markers), refusals of non-numbers, and the Khronos glTF validator
 * (tools/gltf_validator, installed by scripts/setup.sh) run on the files:
 * no error, no warning. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "check.h"
#include "file_fixture.h"
#include "solver/output/gltf_output.h"

static uint32_t u32(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, 4);
    return v;
}

/* The GLB's two chunks: JSON parsed, BIN borrowed. */
typedef struct glb {
    cJSON *json;
    const uint8_t *bin;
    size_t bin_size;
} glb;

static int parse_glb(const uint8_t *bytes, size_t size, glb *out)
{
    memset(out, 0, sizeof *out);
    if (size < 20 || u32(bytes) != 0x46546C67u || u32(bytes + 4) != 2 || u32(bytes + 8) != size) return 0;
    size_t json_size = u32(bytes + 12);
    if (u32(bytes + 16) != 0x4E4F534Au || json_size % 4 || 20 + json_size > size) return 0;
    char *text = malloc(json_size + 1);
    memcpy(text, bytes + 20, json_size);
    text[json_size] = 0;
    out->json = cJSON_Parse(text);
    free(text);
    size_t at = 20 + json_size;
    if (at < size) {
        if (at + 8 > size || u32(bytes + at + 4) != 0x004E4942u || u32(bytes + at) % 4) return 0;
        out->bin_size = u32(bytes + at);
        out->bin = bytes + at + 8;
        if (at + 8 + out->bin_size != size) return 0;
    }
    return out->json != NULL;
}

static int number(const cJSON *o, const char *key)
{
    return (int)cJSON_GetNumberValue(cJSON_GetObjectItem(o, key));
}

/* The floats an accessor holds (tightly packed in its own view). */
static const float *accessor_floats(const glb *g, int accessor, int *count)
{
    const cJSON *a = cJSON_GetArrayItem(cJSON_GetObjectItem(g->json, "accessors"), accessor);
    const cJSON *v = cJSON_GetArrayItem(cJSON_GetObjectItem(g->json, "bufferViews"), number(a, "bufferView"));
    *count = number(a, "count");
    return (const float *)(g->bin + number(v, "byteOffset"));
}

static int attribute(const glb *g, int mesh, const char *name)
{
    const cJSON *m = cJSON_GetArrayItem(cJSON_GetObjectItem(g->json, "meshes"), mesh);
    const cJSON *p = cJSON_GetArrayItem(cJSON_GetObjectItem(m, "primitives"), 0);
    const cJSON *a = cJSON_GetObjectItem(cJSON_GetObjectItem(p, "attributes"), name);
    return a ? (int)cJSON_GetNumberValue(a) : -1;
}

/* The validator on files: its exit status (0 clean), its report in buf. */
static int validate(const char *files, char *buf, size_t size)
{
    char command[4096];
    snprintf(command, sizeof command, "node %s/tools/gltf_validator/validate.js %s 2>&1", CANDELA_SOURCE_DIR, files);
    FILE *p = popen(command, "r");
    if (!p) return -1;
    size_t n = fread(buf, 1, size - 1, p);
    buf[n] = 0;
    int status = pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* A 2 x 1 m floor at z = 0.8 in two triangles, mapped; a 1 m cube at
 * (3, 0, 0), unmapped; two luminaires. */
static const double floor_xyz[] = {0, 0, 0.8, 2, 0, 0.8, 2, 1, 0.8, 0, 1, 0.8};
static const double floor_normal[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
static const uint32_t floor_tri[] = {0, 1, 2, 0, 2, 3};
static const uint8_t floor_rgb[] = {0, 0, 0, 255, 255, 255, 128, 64, 10, 12, 200, 90};
static const double floor_E[] = {0.0, 512.25, 100.5, 3.0e4};
static const double cube_xyz[] = {3, 0, 0, 4, 0, 0, 4, 1, 0, 3, 1, 0, 3, 0, 1, 4, 0, 1, 4, 1, 1, 3, 1, 1};
static const uint32_t cube_tri[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

int main(void)
{
    cdl_error err;
    double cube_normal[24];
    for (int v = 0; v < 8; ++v) {
        /* Corner normals of the cube, unit. */
        double d[3] = {cube_xyz[3 * v] - 3.5, cube_xyz[3 * v + 1] - 0.5, cube_xyz[3 * v + 2] - 0.5};
        for (int k = 0; k < 3; ++k) cube_normal[3 * v + k] = d[k] / sqrt(0.75);
    }
    cdl_gltf_mesh meshes[2] = {{"floor", floor_xyz, floor_normal, 4, floor_tri, 2, floor_rgb, floor_E},
                               {"cabinet", cube_xyz, cube_normal, 8, cube_tri, 12, NULL, NULL}};
    cdl_gltf_marker markers[2] = {{"luminaires[0]", {1, 0.5, 2.7}}, {"luminaires[1]", {3.5, 0.5, 2.7}}};
    cdl_gltf_scene scene = {meshes, 2, markers, 2, 0.1, "Candela test"};
    uint8_t *bytes;
    size_t size;
    CHECK_OK(cdl_gltf_encode(&scene, &bytes, &size, &err), &err);
    glb g;
    CHECK(parse_glb(bytes, size, &g));
    if (!g.json) return check_finish();

    /* Three meshes (floor, cabinet, the marker), four nodes. */
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(g.json, "meshes")) == 3);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(g.json, "nodes")) == 4);
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(cJSON_GetObjectItem(g.json, "asset"), "version")), "2.0"));

    /* Positions in glTF's frame: (x, y, z) -> (x, z, -y); bounds exact. */
    int count;
    const float *pos = accessor_floats(&g, attribute(&g, 0, "POSITION"), &count);
    CHECK(count == 4);
    CHECK(pos[3] == 2.0f && pos[4] == 0.8f && pos[5] == -0.0f && pos[8] == -1.0f);
    const cJSON *pa = cJSON_GetArrayItem(cJSON_GetObjectItem(g.json, "accessors"), attribute(&g, 0, "POSITION"));
    CHECK(cJSON_GetArrayItem(cJSON_GetObjectItem(pa, "max"), 0)->valuedouble == 2.0);
    CHECK(cJSON_GetArrayItem(cJSON_GetObjectItem(pa, "min"), 2)->valuedouble == -1.0);
    CHECK(cJSON_GetArrayItem(cJSON_GetObjectItem(pa, "max"), 1)->valuedouble == (double)0.8f);
    const float *nrm = accessor_floats(&g, attribute(&g, 0, "NORMAL"), &count);
    CHECK(nrm[0] == 0.0f && nrm[1] == 1.0f && nrm[2] == -0.0f);
    /* Colours as linear light (IEC 61966-2-1): 0 -> 0, 255 -> 1, 128 ->
     * ((128/255 + 0.055) / 1.055)^2.4 = 0.2158605, 10 -> 10/255/12.92. */
    const float *col = accessor_floats(&g, attribute(&g, 0, "COLOR_0"), &count);
    CHECK(col[0] == 0.0f && col[3] == 1.0f);
    CHECK_ABS(col[6], 0.21586050011389926, 1e-7);   /* float rounding */
    CHECK_ABS(col[8], 10.0 / 255.0 / 12.92, 1e-9);
    const float *lux = accessor_floats(&g, attribute(&g, 0, "_ILLUMINANCE_LX"), &count);
    CHECK(count == 4 && lux[1] == 512.25f && lux[3] == 3.0e4f);
    /* The unmapped cabinet: no colours, no illuminance, the grey material. */
    CHECK(attribute(&g, 1, "COLOR_0") < 0 && attribute(&g, 1, "_ILLUMINANCE_LX") < 0);
    const cJSON *mats = cJSON_GetObjectItem(g.json, "materials");
    const cJSON *prim1 = cJSON_GetArrayItem(cJSON_GetObjectItem(cJSON_GetArrayItem(cJSON_GetObjectItem(g.json, "meshes"), 1), "primitives"), 0);
    const cJSON *grey = cJSON_GetArrayItem(mats, number(prim1, "material"));
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(grey, "name")), "unmapped surface"));
    /* A marker at the second luminaire, (3.5, 0.5, 2.7) -> (3.5, 2.7, -0.5). */
    const cJSON *node = cJSON_GetArrayItem(cJSON_GetObjectItem(g.json, "nodes"), 3);
    const cJSON *t = cJSON_GetObjectItem(node, "translation");
    CHECK(cJSON_GetArrayItem(t, 0)->valuedouble == 3.5 && cJSON_GetArrayItem(t, 1)->valuedouble == 2.7 &&
          cJSON_GetArrayItem(t, 2)->valuedouble == -0.5);
    cJSON_Delete(g.json);

    /* Written to files: this scene, and one with nothing in it. */
    char dir[512], one[1024], empty[1024], files[2100];
    CHECK(fixture_folder("gltf_output", dir, sizeof dir));
    snprintf(one, sizeof one, "%s/scene.glb", dir);
    snprintf(empty, sizeof empty, "%s/empty.glb", dir);
    CHECK_OK(cdl_gltf_write(one, &scene, &err), &err);
    cdl_gltf_scene nothing = {NULL, 0, NULL, 0, 0.1, "Candela test"};
    CHECK_OK(cdl_gltf_write(empty, &nothing, &err), &err);
    size_t written;
    uint8_t *back = (uint8_t *)fixture_read_file(one, &written);
    CHECK(back && written == size && !memcmp(back, bytes, size));
    free(back);
    free(bytes);

    /* The Khronos validator: no error and no warning in either. */
    snprintf(files, sizeof files, "%s %s", one, empty);
    char report[8192];
    int status = validate(files, report, sizeof report);
    CHECK_MSG(status == 0, "the glTF validator (status %d; run scripts/setup.sh if it is missing):\n%s", status, report);
    CHECK(strstr(report, "scene.glb: 0 errors, 0 warnings") != NULL);

    /* The validator catches what is wrong: a triangle naming a vertex the
     * mesh does not have, written past the writer's own check. */
    uint32_t bad_tri[] = {0, 1, 2, 0, 2, 3};
    cdl_gltf_mesh bad = meshes[0];
    bad.triangles = bad_tri;
    cdl_gltf_scene bad_scene = {&bad, 1, NULL, 0, 0.1, "Candela test"};
    CHECK_OK(cdl_gltf_encode(&bad_scene, &bytes, &size, &err), &err);
    glb b;
    CHECK(parse_glb(bytes, size, &b));
    /* The index view is the last; its last index goes to 7. */
    const cJSON *views = cJSON_GetObjectItem(b.json, "bufferViews");
    const cJSON *last = cJSON_GetArrayItem(views, cJSON_GetArraySize(views) - 1);
    uint32_t seven = 7;
    memcpy((uint8_t *)b.bin + number(last, "byteOffset") + 5 * 4, &seven, 4);
    cJSON_Delete(b.json);
    char broken[1024];
    snprintf(broken, sizeof broken, "%s/broken.glb", dir);
    FILE *fp = fopen(broken, "wb");
    fwrite(bytes, 1, size, fp);
    fclose(fp);
    free(bytes);
    status = validate(broken, report, sizeof report);
    CHECK_MSG(status == 1 && strstr(report, "ACCESSOR_INDEX_OOB"), "validator on a broken file: %d\n%s", status, report);

    /* Not a number: refused, nothing written. */
    double nan_E[] = {0.0, NAN, 1.0, 2.0};
    bad = meshes[0];
    bad.E_lx = nan_E;
    bad_scene.meshes = &bad;
    CHECK(cdl_gltf_write(broken, &bad_scene, &err) == CDL_ERR_INTERNAL && strstr(err.message, "not a number"));
    bad.E_lx = floor_E;
    bad.triangles = bad_tri;
    bad_tri[5] = 9;
    cdl_status st = cdl_gltf_encode(&bad_scene, &bytes, &size, &err);
    CHECK_MSG(st == CDL_ERR_INTERNAL && bytes == NULL, "status %d: %s", (int)st, err.message);
    return check_finish();
}
