/* mesh_file.h - triangle meshes from OBJ, OFF and PLY files.
 *
 *   OBJ  "v x y z" (also "v x y z w", divided by w, and "v x y z r g b"),
 *        "f" with the forms i, i/t, i//n, i/t/n, negative (relative)
 *        indices, polygons fan-triangulated; comments and the statements
 *        vt vn vp g o s usemtl mtllib l p are read past. Free-form geometry
 *        (curv, surf, ...) is refused: it would silently be missing.
 *   OFF  "OFF" (or COFF, NOFF, CNOFF: extra per-vertex values are skipped),
 *        counts "V F [E]" (optionally on the header line), V vertex lines,
 *        F face lines "n i0 ... i(n-1) [colour]", 0-based, # comments.
 *   PLY  ascii, binary_little_endian or binary_big_endian 1.0; element
 *        "vertex" with scalar properties x, y, z (any numeric type), element
 *        "face" with a list property vertex_indices (or vertex_index), any
 *        integer count and index types; other elements and properties are
 *        skipped.
 *
 * Polygons are fan-triangulated (v0, vi, vi+1), which keeps the orientation:
 * counter-clockwise seen from the front stays so. Faces with fewer than three
 * vertices, indices out of range and non-finite coordinates are errors.
 * Triangles of zero area (repeated indices, collinear points) are dropped:
 * they neither block nor emit light; a file with no triangle of non-zero area
 * left is an error.
 *
 * Errors (CDL_ERR_INPUT) name the file and the line ("column.obj:12: expected
 * ..., found ..."), or for binary PLY the element and its index ("mesh.ply:
 * face 7: ..."). Files that cannot be read are CDL_ERR_INPUT too.
 */
#ifndef CANDELA_SOLVER_MESH_FILE_H
#define CANDELA_SOLVER_MESH_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

typedef enum cdl_mesh_format { CDL_MESH_OBJ, CDL_MESH_OFF, CDL_MESH_PLY } cdl_mesh_format;

typedef struct cdl_mesh_data {
    double *vertices;        /* xyz, vertex_count x 3, metres */
    size_t vertex_count;
    uint32_t *triangles;     /* triangle_count x 3 */
    size_t triangle_count;
} cdl_mesh_data;

/* Format from the file name's extension (.obj, .off, .ply, any case);
 * returns 0 when it is none of these. */
int cdl_mesh_file_format_from_name(const char *path, cdl_mesh_format *format);

/* Read a file; the format comes from its extension. */
cdl_status cdl_mesh_file_read(const char *path, cdl_mesh_data *out, cdl_error *err);

/* Parse `size` bytes already in memory; `name` is used in messages. */
cdl_status cdl_mesh_file_parse(const char *data, size_t size, cdl_mesh_format format, const char *name,
                               cdl_mesh_data *out, cdl_error *err);

void cdl_mesh_data_release(cdl_mesh_data *mesh);

#endif
