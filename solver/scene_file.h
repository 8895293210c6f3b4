/* scene_file.h - whole files read into memory, for the scene loader and the
 * mesh readers (not a public interface). */
#ifndef CANDELA_SOLVER_SCENE_FILE_H
#define CANDELA_SOLVER_SCENE_FILE_H

#include <stddef.h>

#include "radiometry/error.h"

/* Largest scene or mesh file read (a mesh of ~10 million triangles). */
#define CDL_SCENE_MAX_FILE_BYTES ((size_t)1 << 30)

/* Read a regular file into *data (NUL-terminated; *size excludes the NUL).
 * `what` names the file's role in messages ("scene file", "mesh file").
 * Missing, unreadable, non-regular or too large files are CDL_ERR_INPUT. */
cdl_status cdl_scene_file_read_bytes(const char *path, const char *what, char **data, size_t *size, cdl_error *err);

#endif
