/* gltf_output.c - scene.glb: meshes, false colours, illuminance, markers (gltf_output.h). */
#include "solver/output/gltf_output.h"

#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/grow.h"
#include "base/error_report.h"

/* glTF 2.0 constants (the specification's enumerations). */
#define GLB_MAGIC 0x46546C67u        /* "glTF" */
#define GLB_VERSION 2u
#define GLB_CHUNK_JSON 0x4E4F534Au   /* "JSON" */
#define GLB_CHUNK_BIN 0x004E4942u    /* "BIN\0" */
#define GL_FLOAT 5126
#define GL_UNSIGNED_INT 5125
#define GL_ARRAY_BUFFER 34962
#define GL_ELEMENT_ARRAY_BUFFER 34963
#define GL_TRIANGLES 4

enum { MATERIAL_FALSE_COLOUR, MATERIAL_UNMAPPED, MATERIAL_LUMINAIRE };

typedef struct glb_builder {
    uint8_t *bin;
    size_t size, capacity;
    cJSON *root, *views, *accessors;
    cdl_error *err;
    cdl_status status;
} glb_builder;

/* Append bytes at a 4-byte boundary (glTF 2.0, 3.6.2.4: accessor data
 * aligned to its component size; every component here is 4 bytes) as a
 * new buffer view; returns its index, or -1 on failure. */
static int add_view(glb_builder *b, const void *data, size_t bytes, int target)
{
    if (b->status != CDL_OK) return -1;
    size_t offset = (b->size + 3) & ~(size_t)3;
    if (cdl_grow(&b->bin, &b->capacity, offset + bytes, 1, 4096, b->err) != CDL_OK) {
        b->status = CDL_ERR_INTERNAL;
        return -1;
    }
    memset(b->bin + b->size, 0, offset - b->size);
    memcpy(b->bin + offset, data, bytes);
    b->size = offset + bytes;
    cJSON *v = cJSON_CreateObject();
    cJSON_AddNumberToObject(v, "buffer", 0);
    cJSON_AddNumberToObject(v, "byteOffset", (double)offset);
    cJSON_AddNumberToObject(v, "byteLength", (double)bytes);
    cJSON_AddNumberToObject(v, "target", target);
    cJSON_AddItemToArray(b->views, v);
    return cJSON_GetArraySize(b->views) - 1;
}

/* A float accessor of `count` items of `components` (1 or 3) over a new
 * view; min and max (per component) when asked, as POSITION needs them
 * (3.7.2.1). Returns its index or -1. */
static int add_float_accessor(glb_builder *b, const float *data, size_t count, int components, int bounds)
{
    int view = add_view(b, data, count * (size_t)components * sizeof *data, GL_ARRAY_BUFFER);
    if (view < 0) return -1;
    cJSON *a = cJSON_CreateObject();
    cJSON_AddNumberToObject(a, "bufferView", view);
    cJSON_AddNumberToObject(a, "componentType", GL_FLOAT);
    cJSON_AddNumberToObject(a, "count", (double)count);
    cJSON_AddStringToObject(a, "type", components == 3 ? "VEC3" : "SCALAR");
    if (bounds) {
        double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
        for (size_t i = 0; i < count; ++i)
            for (int k = 0; k < components; ++k) {
                lo[k] = fmin(lo[k], data[components * i + k]);
                hi[k] = fmax(hi[k], data[components * i + k]);
            }
        cJSON_AddItemToObject(a, "min", cJSON_CreateDoubleArray(lo, components));
        cJSON_AddItemToObject(a, "max", cJSON_CreateDoubleArray(hi, components));
    }
    cJSON_AddItemToArray(b->accessors, a);
    return cJSON_GetArraySize(b->accessors) - 1;
}

static int add_index_accessor(glb_builder *b, const uint32_t *indices, size_t count)
{
    int view = add_view(b, indices, count * sizeof *indices, GL_ELEMENT_ARRAY_BUFFER);
    if (view < 0) return -1;
    cJSON *a = cJSON_CreateObject();
    cJSON_AddNumberToObject(a, "bufferView", view);
    cJSON_AddNumberToObject(a, "componentType", GL_UNSIGNED_INT);
    cJSON_AddNumberToObject(a, "count", (double)count);
    cJSON_AddStringToObject(a, "type", "SCALAR");
    cJSON_AddItemToArray(b->accessors, a);
    return cJSON_GetArraySize(b->accessors) - 1;
}

/* Candela's z-up point or direction in glTF's y-up frame: (x, z, -y). */
static void to_gltf(const double *p, float *out)
{
    out[0] = (float)p[0];
    out[1] = (float)p[2];
    out[2] = (float)-p[1];
}

/* The sRGB transfer function inverted (IEC 61966-2-1:1999, 5.2): an 8-bit
 * code value to linear light, what COLOR_0 holds (glTF 2.0, 3.7.2.1). */
static float srgb_to_linear(uint8_t code)
{
    double c = code / 255.0;
    return (float)(c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4));
}

static cJSON *material(const char *name, const double rgb[3], int unlit, int emissive, int double_sided)
{
    cJSON *m = cJSON_CreateObject();
    cJSON_AddStringToObject(m, "name", name);
    cJSON *pbr = cJSON_AddObjectToObject(m, "pbrMetallicRoughness");
    double base[4] = {rgb[0], rgb[1], rgb[2], 1.0};
    cJSON_AddItemToObject(pbr, "baseColorFactor", cJSON_CreateDoubleArray(base, 4));
    cJSON_AddNumberToObject(pbr, "metallicFactor", 0.0);
    cJSON_AddNumberToObject(pbr, "roughnessFactor", 0.9);
    if (emissive) cJSON_AddItemToObject(m, "emissiveFactor", cJSON_CreateDoubleArray(rgb, 3));
    if (double_sided) cJSON_AddTrueToObject(m, "doubleSided");
    if (unlit) cJSON_AddObjectToObject(cJSON_AddObjectToObject(m, "extensions"), "KHR_materials_unlit");
    return m;
}

static cdl_status check_mesh(const cdl_gltf_mesh *m, cdl_error *err)
{
    for (size_t v = 0; v < m->vertex_count; ++v)
        for (int k = 0; k < 3; ++k)
            if (!isfinite(m->xyz[3 * v + k]) || !isfinite(m->normal[3 * v + k]) ||
                (m->E_lx && !isfinite(m->E_lx[v])))
                return cdl_error_set(err, CDL_ERR_INTERNAL, "surface %s: vertex %zu has a value that is not a number",
                                     m->name ? m->name : "(unnamed)", v);
    for (size_t t = 0; t < 3 * m->triangle_count; ++t)
        if (m->triangles[t] >= m->vertex_count)
            return cdl_error_set(err, CDL_ERR_INTERNAL, "surface %s: a triangle names vertex %u of %zu",
                                 m->name ? m->name : "(unnamed)", m->triangles[t], m->vertex_count);
    return CDL_OK;
}

/* One surface's mesh: its accessors and the glTF mesh; returns its index or -1. */
static int add_surface(glb_builder *b, cJSON *meshes, const cdl_gltf_mesh *m)
{
    size_t n = m->vertex_count;
    float *position = malloc((n + 1) * 3 * sizeof *position), *normal = malloc((n + 1) * 3 * sizeof *normal);
    float *colour = malloc((n + 1) * 3 * sizeof *colour), *lux = malloc((n + 1) * sizeof *lux);
    if (!position || !normal || !colour || !lux) {
        b->status = cdl_error_out_of_memory(b->err);
    } else {
        for (size_t v = 0; v < n; ++v) {
            to_gltf(&m->xyz[3 * v], &position[3 * v]);
            /* Unit in single precision too (the validator holds normals to it). */
            double d[3] = {m->normal[3 * v], m->normal[3 * v + 1], m->normal[3 * v + 2]};
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (int k = 0; k < 3; ++k) d[k] = len > 0.0 ? d[k] / len : (k == 2 ? 1.0 : 0.0);
            to_gltf(d, &normal[3 * v]);
            for (int k = 0; m->rgb && k < 3; ++k) colour[3 * v + k] = srgb_to_linear(m->rgb[3 * v + k]);
            lux[v] = m->E_lx ? (float)m->E_lx[v] : 0.0f;
        }
    }
    cJSON *attributes = cJSON_CreateObject();
    cJSON_AddNumberToObject(attributes, "POSITION", add_float_accessor(b, position, n, 3, 1));
    cJSON_AddNumberToObject(attributes, "NORMAL", add_float_accessor(b, normal, n, 3, 0));
    if (m->rgb) cJSON_AddNumberToObject(attributes, "COLOR_0", add_float_accessor(b, colour, n, 3, 0));
    if (m->rgb && m->E_lx) cJSON_AddNumberToObject(attributes, "_ILLUMINANCE_LX", add_float_accessor(b, lux, n, 1, 0));
    free(position);
    free(normal);
    free(colour);
    free(lux);
    cJSON *primitive = cJSON_CreateObject();
    cJSON_AddItemToObject(primitive, "attributes", attributes);
    cJSON_AddNumberToObject(primitive, "indices", add_index_accessor(b, m->triangles, 3 * m->triangle_count));
    cJSON_AddNumberToObject(primitive, "material", m->rgb ? MATERIAL_FALSE_COLOUR : MATERIAL_UNMAPPED);
    cJSON_AddNumberToObject(primitive, "mode", GL_TRIANGLES);
    cJSON *mesh = cJSON_CreateObject();
    if (m->name) cJSON_AddStringToObject(mesh, "name", m->name);
    cJSON_AddItemToArray(cJSON_AddArrayToObject(mesh, "primitives"), primitive);
    cJSON_AddItemToArray(meshes, mesh);
    return cJSON_GetArraySize(meshes) - 1;
}

/* The markers' octahedron: unit width, a flat-shaded face each (3 vertices
 * of its own, with the face's normal), counter-clockwise from outside. */
static int add_marker_mesh(glb_builder *b, cJSON *meshes)
{
    static const double axis[6][3] = {{0.5, 0, 0}, {-0.5, 0, 0}, {0, 0.5, 0}, {0, -0.5, 0}, {0, 0, 0.5}, {0, 0, -0.5}};
    double xyz[24][3], normal[24][3];
    uint32_t tri[24];
    for (int f = 0; f < 8; ++f) {
        int sx = f & 1, sy = (f >> 1) & 1, sz = (f >> 2) & 1;
        const double *a = axis[sx], *c = axis[2 + sy], *e = axis[4 + sz];
        /* (x, y, z) corners: counter-clockwise from outside when the sign count is even. */
        int even = (sx + sy + sz) % 2 == 0;
        const double *corner[3] = {a, even ? c : e, even ? e : c};
        for (int k = 0; k < 3; ++k) {
            memcpy(xyz[3 * f + k], corner[k], sizeof xyz[0]);
            double s = 1.0 / sqrt(3.0);
            normal[3 * f + k][0] = sx ? -s : s;
            normal[3 * f + k][1] = sy ? -s : s;
            normal[3 * f + k][2] = sz ? -s : s;
            tri[3 * f + k] = (uint32_t)(3 * f + k);
        }
    }
    cdl_gltf_mesh m = {"luminaire marker", &xyz[0][0], &normal[0][0], 24, tri, 8, NULL, NULL};
    int index = add_surface(b, meshes, &m);
    cJSON *primitive = cJSON_GetArrayItem(cJSON_GetObjectItem(cJSON_GetArrayItem(meshes, index), "primitives"), 0);
    cJSON_ReplaceItemInObject(primitive, "material", cJSON_CreateNumber(MATERIAL_LUMINAIRE));
    return index;
}

static void add_node(cJSON *nodes, cJSON *scene_nodes, const char *name, int mesh)
{
    cJSON *node = cJSON_CreateObject();
    if (name) cJSON_AddStringToObject(node, "name", name);
    cJSON_AddNumberToObject(node, "mesh", mesh);
    cJSON_AddItemToArray(scene_nodes, cJSON_CreateNumber(cJSON_GetArraySize(nodes)));
    cJSON_AddItemToArray(nodes, node);
}

static void add_json_head(cJSON *root, const cdl_gltf_scene *scene)
{
    cJSON *asset = cJSON_AddObjectToObject(root, "asset");
    cJSON_AddStringToObject(asset, "version", "2.0");
    if (scene->generator) cJSON_AddStringToObject(asset, "generator", scene->generator);
    cJSON *extras = cJSON_AddObjectToObject(asset, "extras");
    cJSON_AddStringToObject(extras, "length_unit", "m");
    cJSON_AddStringToObject(extras, "_ILLUMINANCE_LX", "illuminance on the surface's front, lux");
    cJSON_AddStringToObject(extras, "axes", "glTF (x, y, z) = Candela (x, z, -y): Candela's +z is up");
    cJSON *ext = cJSON_AddArrayToObject(root, "extensionsUsed");
    cJSON_AddItemToArray(ext, cJSON_CreateString("KHR_materials_unlit"));
    cJSON *materials = cJSON_AddArrayToObject(root, "materials");
    const double white[3] = {1, 1, 1}, grey[3] = {0.5, 0.5, 0.5}, yellow[3] = {1.0, 0.8, 0.1};
    cJSON_AddItemToArray(materials, material("false colour", white, 1, 0, 0));
    cJSON_AddItemToArray(materials, material("unmapped surface", grey, 0, 0, 1));
    cJSON_AddItemToArray(materials, material("luminaire", yellow, 1, 1, 1));
}

static void add_markers(glb_builder *b, cJSON *meshes, cJSON *nodes, cJSON *scene_nodes, const cdl_gltf_scene *scene)
{
    if (scene->marker_count == 0) return;
    int marker = add_marker_mesh(b, meshes);
    double size = scene->marker_size > 0.0 ? scene->marker_size : 0.1;
    for (size_t i = 0; i < scene->marker_count; ++i) {
        add_node(nodes, scene_nodes, scene->markers[i].name, marker);
        cJSON *node = cJSON_GetArrayItem(nodes, cJSON_GetArraySize(nodes) - 1);
        cdl_vec3 p = scene->markers[i].position;
        double t[3] = {p.x, p.z, -p.y}, s[3] = {size, size, size}; /* (x, z, -y), as to_gltf */
        cJSON_AddItemToObject(node, "translation", cJSON_CreateDoubleArray(t, 3));
        cJSON_AddItemToObject(node, "scale", cJSON_CreateDoubleArray(s, 3));
    }
}

/* The GLB container: header, JSON chunk (padded with spaces), BIN chunk
 * (padded with zeros) (glTF 2.0, 4.4). */
static cdl_status pack(const char *json, const uint8_t *bin, size_t bin_size, uint8_t **bytes, size_t *size,
                       cdl_error *err)
{
    size_t json_size = strlen(json), json_padded = (json_size + 3) & ~(size_t)3;
    size_t bin_padded = (bin_size + 3) & ~(size_t)3;
    size_t total = 12 + 8 + json_padded + (bin_size ? 8 + bin_padded : 0);
    if (total > UINT32_MAX)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "the scene is too large for one glTF binary (%zu bytes)", total);
    uint8_t *out = calloc(total, 1);
    if (!out) return cdl_error_out_of_memory(err);
    uint32_t head[5] = {GLB_MAGIC, GLB_VERSION, (uint32_t)total, (uint32_t)json_padded, GLB_CHUNK_JSON};
    memcpy(out, head, sizeof head);
    memcpy(out + 20, json, json_size);
    memset(out + 20 + json_size, ' ', json_padded - json_size);
    if (bin_size) {
        uint32_t chunk[2] = {(uint32_t)bin_padded, GLB_CHUNK_BIN};
        memcpy(out + 20 + json_padded, chunk, sizeof chunk);
        memcpy(out + 28 + json_padded, bin, bin_size);
    }
    *bytes = out;
    *size = total;
    return CDL_OK;
}

cdl_status cdl_gltf_encode(const cdl_gltf_scene *scene, uint8_t **bytes, size_t *size, cdl_error *err)
{
    *bytes = NULL;
    *size = 0;
    for (size_t i = 0; i < scene->mesh_count; ++i) {
        cdl_status st = check_mesh(&scene->meshes[i], err);
        if (st != CDL_OK) return st;
    }
    glb_builder b = {NULL, 0, 0, cJSON_CreateObject(), NULL, NULL, err, CDL_OK};
    if (!b.root) return cdl_error_out_of_memory(err);
    add_json_head(b.root, scene);
    cJSON_AddNumberToObject(b.root, "scene", 0);
    cJSON *the_scene = cJSON_CreateObject();
    cJSON_AddItemToArray(cJSON_AddArrayToObject(b.root, "scenes"), the_scene);
    cJSON *scene_nodes = cJSON_AddArrayToObject(the_scene, "nodes");
    cJSON *nodes = cJSON_AddArrayToObject(b.root, "nodes");
    cJSON *meshes = cJSON_AddArrayToObject(b.root, "meshes");
    b.accessors = cJSON_AddArrayToObject(b.root, "accessors");
    b.views = cJSON_AddArrayToObject(b.root, "bufferViews");
    for (size_t i = 0; i < scene->mesh_count && b.status == CDL_OK; ++i) {
        if (scene->meshes[i].triangle_count == 0) continue;
        add_node(nodes, scene_nodes, scene->meshes[i].name, add_surface(&b, meshes, &scene->meshes[i]));
    }
    add_markers(&b, meshes, nodes, scene_nodes, scene);
    cdl_status st = b.status;
    if (st == CDL_OK && b.size) {
        cJSON *buffer = cJSON_CreateObject();
        cJSON_AddNumberToObject(buffer, "byteLength", (double)b.size);
        cJSON_AddItemToArray(cJSON_AddArrayToObject(b.root, "buffers"), buffer);
    }
    /* Empty arrays are not allowed (glTF 2.0, 5: arrays have at least one item). */
    const char *optional[] = {"nodes", "meshes", "accessors", "bufferViews"};
    for (size_t k = 0; k < sizeof optional / sizeof *optional; ++k)
        if (cJSON_GetArraySize(cJSON_GetObjectItem(b.root, optional[k])) == 0)
            cJSON_DeleteItemFromObject(b.root, optional[k]);
    if (cJSON_GetArraySize(scene_nodes) == 0) cJSON_DeleteItemFromObject(the_scene, "nodes");
    char *json = st == CDL_OK ? cJSON_PrintUnformatted(b.root) : NULL;
    if (st == CDL_OK && !json) st = cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = pack(json, b.bin, b.size, bytes, size, err);
    free(json);
    free(b.bin);
    cJSON_Delete(b.root);
    return st;
}

cdl_status cdl_gltf_write(const char *path, const cdl_gltf_scene *scene, cdl_error *err)
{
    uint8_t *bytes;
    size_t size;
    cdl_status st = cdl_gltf_encode(scene, &bytes, &size, err);
    if (st == CDL_OK) st = cdl_atomic_file_write_all(path, bytes, size, err);
    if (st != CDL_OK) cdl_error_prefix(err, "%s: ", path);
    free(bytes);
    return st;
}
