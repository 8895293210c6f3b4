/* scene_file.h - limits of the files the scene loader reads (not a public interface). */
#ifndef CANDELA_SOLVER_SCENE_FILE_H
#define CANDELA_SOLVER_SCENE_FILE_H

#include <stddef.h>

/* Largest scene or mesh file read (a mesh of ~10 million triangles). */
#define CDL_SCENE_MAX_FILE_BYTES ((size_t)1 << 30)

#endif
