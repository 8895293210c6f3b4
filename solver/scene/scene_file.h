/* scene_file.h - limits of the files the scene loader reads (not a public interface). */
#ifndef CANDELA_SOLVER_SCENE_FILE_H
#define CANDELA_SOLVER_SCENE_FILE_H

#include <stddef.h>

/* Largest mesh file read (a mesh of ~10 million triangles). */
#define CDL_SCENE_MAX_FILE_BYTES ((size_t)1 << 30)

/* Largest scene (JSON) file read: 256 MiB. A parsed JSON document takes
 * about 21 times its text in memory (measured: 1.28 GB for a 60 MB list of
 * points), so a 1 GiB scene would need over 20 GB; 256 MiB holds inline
 * meshes of millions of triangles and points grids of millions of points
 * in about 5.5 GB. Larger meshes belong in OBJ, OFF or PLY files. */
#define CDL_SCENE_MAX_JSON_BYTES ((size_t)1 << 28)

#endif
