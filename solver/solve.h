/* solve.h - `candela solve`: a scene in, illuminance on every grid out.
 *
 * cdl_solve_scene computes (in memory); cdl_solution_write writes the files
 * of DESIGN.md ("Outputs of solve") into a folder, each atomically.
 *
 * Methods: "direct" computes direct light only; "auto" picks the cheapest
 * method that gives the whole answer for the quality asked, which is
 * "direct" when nothing in the scene reflects light. A scene that needs a
 * method not built yet (interreflection: the irradiance cache or the path
 * tracer) is refused with a message, never solved with less.
 */
#ifndef CANDELA_SOLVER_SOLVE_H
#define CANDELA_SOLVER_SOLVE_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/error.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene.h"

typedef void (*cdl_solve_progress_fn)(void *user, const char *stage, size_t done, size_t total);

struct cdl_ray_log;

typedef struct cdl_solve_options {
    int threads;                      /* < 0: as the scene says (0 there = all cores) */
    cdl_solve_progress_fn progress;   /* may be NULL; called from the calling thread */
    void *progress_user;
    struct cdl_ray_log *ray_log;      /* benchmarks: record every shadow ray (forces one thread) */
} cdl_solve_options;
#define CDL_SOLVE_OPTIONS_DEFAULT {-1, NULL, NULL, NULL}

typedef struct cdl_grid_solution {
    cdl_grid grid;
    double *E, *E_direct, *E_indirect, *E_stderr;
    double *ao;                       /* NULL unless asked for */
    /* Points lying where two surfaces meet (on the one they face and within a
     * ray epsilon of another, as at the foot of a wall): a surface through
     * the point cannot say which side of it the point is on, so light from
     * beyond it may be counted. Counted and reported, never silently. */
    size_t edge_point_count;
    size_t first_edge_point;          /* index of the first, when any */
} cdl_grid_solution;

typedef struct cdl_solution {
    cdl_method method;                /* the method actually used */
    cdl_solver_settings settings;     /* with quality-derived knobs filled in */
    int threads_used;
    cdl_grid_solution *grids;         /* scene->grid_count */
    size_t grid_count;
    char *plan_json;                  /* the "plan" object, JSON text */
    double seconds;                   /* the whole solve */
    double compute_seconds;           /* the grids' points only (setup excluded) */
    uint64_t rays;
} cdl_solution;

cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution *out,
                           cdl_error *err);
void cdl_solution_release(cdl_solution *solution);

/* Make out_dir ready for the results: created with its parents when
 * missing, and writable. Callers run it before a long solve. CDL_ERR_INPUT
 * when the path cannot be the folder (empty, an existing file or a file
 * among its parents, no permission, a read-only file system), with a
 * message naming the path and what was found; CDL_ERR_INTERNAL for the
 * machine's failures (no space, I/O errors). */
cdl_status cdl_solution_prepare_folder(const char *out_dir, cdl_error *err);

/* Write NAME.csv, NAME.exr and NAME.png per grid (EXR and PNG for rect and
 * polygon grids) and summary.json into out_dir (prepared as by
 * cdl_solution_prepare_folder). ocio_config: the OpenColorIO config for the
 * PNG maps. */
cdl_status cdl_solution_write(const cdl_scene *scene, const cdl_solution *solution, const char *out_dir,
                              const char *ocio_config, cdl_error *err);

/* The OCIO config shipped with Candela (data/ocio/config.ocio). */
const char *cdl_default_ocio_config(void);

#endif
