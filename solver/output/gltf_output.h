/* gltf_output.h - the lit scene as one glTF 2.0 binary file (OUTDIR/scene.glb).
 *
 * glTF 2.0 (Khronos, ISO/IEC 12113:2022) is what Blender, three.js and
 * every glTF viewer open. The file is the binary container (GLB: a 12-byte
 * header, a JSON chunk, a BIN chunk, each padded to 4 bytes) holding:
 *
 *   - one mesh per surface given: positions, unit normals and triangles
 *     (counter-clockwise seen from the front, as glTF's front faces are);
 *     a mapped surface (rgb given) has its vertices' false colours as
 *     COLOR_0 (linear RGB, from the maps' 8-bit sRGB by the sRGB transfer
 *     function, IEC 61966-2-1) on an unlit material (KHR_materials_unlit),
 *     so viewers show the colours of the legend and no shading of their
 *     own, and its illuminance in lux as the application-specific vertex
 *     attribute _ILLUMINANCE_LX (glTF 2.0, 3.7.2.1: names starting with an
 *     underscore); an unmapped surface is mid grey and lit by the viewer;
 *   - a small octahedron per marker (the luminaires), emissive yellow;
 *   - asset.extras: the units (metres, lux) and the axes.
 *
 * Axes: glTF's +y is up (3.4); Candela's is +z. Every point and normal is
 * written as (x, z, -y), the rotation that takes +z to +y and keeps the
 * frame right-handed, so the scene stands upright in any viewer and
 * Blender's importer turns it back to z up.
 *
 * Surfaces with no triangle are left out. Written atomically
 * (atomic_file.h). Errors: CDL_ERR_INTERNAL for a non-finite coordinate,
 * normal or illuminance (never written), memory and I/O, naming the file.
 * Thread safety: reentrant; no state.
 */
#ifndef CANDELA_SOLVER_OUTPUT_GLTF_OUTPUT_H
#define CANDELA_SOLVER_OUTPUT_GLTF_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_gltf_mesh {
    const char *name;
    const double *xyz;            /* vertex_count x 3, metres */
    const double *normal;         /* vertex_count x 3, unit */
    size_t vertex_count;
    const uint32_t *triangles;    /* triangle_count x 3 */
    size_t triangle_count;
    const uint8_t *rgb;           /* vertex_count x 3 sRGB false colours, or NULL: unmapped (grey) */
    const double *E_lx;           /* vertex_count illuminances (with rgb), or NULL */
} cdl_gltf_mesh;

typedef struct cdl_gltf_marker {
    const char *name;
    cdl_vec3 position;            /* metres */
} cdl_gltf_marker;

typedef struct cdl_gltf_scene {
    const cdl_gltf_mesh *meshes;
    size_t mesh_count;
    const cdl_gltf_marker *markers;
    size_t marker_count;
    double marker_size;           /* metres, > 0: the octahedra's width */
    const char *generator;        /* asset.generator, e.g. "Candela 0.1.0" */
} cdl_gltf_scene;

/* The GLB bytes, malloc'ed (*bytes is the caller's to free). */
cdl_status cdl_gltf_encode(const cdl_gltf_scene *scene, uint8_t **bytes, size_t *size, cdl_error *err);

/* Encode and write to path. */
cdl_status cdl_gltf_write(const char *path, const cdl_gltf_scene *scene, cdl_error *err);

#endif
