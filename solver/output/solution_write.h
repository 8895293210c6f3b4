/* solution_write.h - a solve's files: CSV, EXR and PNG per grid, summary.json.
 *
 * Per grid NAME.csv, NAME.exr and NAME.png (EXR and PNG for rect and
 * polygon grids), and summary.json; each written atomically (to a
 * temporary name in the same folder, renamed when complete).
 *
 * Ownership: the scene and solution are borrowed for the call. Thread
 * safety: no state; different folders may be written at once (two writes
 * into one folder race for its files). Errors: as each function says; a
 * failed write leaves no partial file under its final name. */
#ifndef CANDELA_SOLVER_SOLUTION_WRITE_H
#define CANDELA_SOLVER_SOLUTION_WRITE_H

#include "base/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"

/* Make out_dir ready for the results: created with its parents when
 * missing, and writable. Callers run it before a long solve. CDL_ERR_INPUT
 * when the path cannot be the folder (empty, an existing file or a file
 * among its parents, no permission, a read-only file system), with a
 * message naming the path and what was found; CDL_ERR_INTERNAL for the
 * machine's failures (no space, I/O errors). */
cdl_status cdl_solution_prepare_folder(const char *out_dir, cdl_error *err);

/* How the files are written. Start from CDL_SOLUTION_WRITE_OPTIONS_INIT
 * (it sets `size`, so that fields added later keep their defaults for a
 * program built before them). */
typedef struct cdl_solution_write_options {
    size_t size;                      /* sizeof(cdl_solution_write_options) */
    const char *ocio_config;          /* the OpenColorIO config for the PNG maps (default: Candela's) */
    int map_log_scale;                /* 1: the maps on a logarithmic lux scale; 0 (default) linear */
} cdl_solution_write_options;
#define CDL_SOLUTION_WRITE_OPTIONS_INIT {.size = sizeof(cdl_solution_write_options), .ocio_config = NULL, .map_log_scale = 0}

/* Write the files into out_dir (prepared as by cdl_solution_prepare_folder);
 * options may be NULL for the defaults. */
cdl_status cdl_solution_write(const cdl_scene *scene, const cdl_solution *solution, const char *out_dir,
                              const cdl_solution_write_options *options, cdl_error *err);

/* The OCIO config shipped with Candela (data/ocio/config.ocio), installed
 * as DATADIR/candela/ocio/config.ocio and found relative to libcandela.so
 * or to the program linking libcandela.a.
 * Static storage, found once; thread-safe; never NULL. When the
 * installation lacks it, the path where it was expected is returned and
 * writing the PNG maps fails with a message naming it. */
const char *cdl_default_ocio_config(void);

#endif
