/* grid_result.h - illuminance results of one grid, their statistics, and
 * the files `candela solve` writes for them (DESIGN.md, "Outputs of solve").
 *
 * Every file is written atomically: to a temporary name in the same folder,
 * flushed, then renamed over the final name, so an interrupted run leaves
 * earlier results intact and never a half-written file.
 */
#ifndef CANDELA_SOLVER_GRID_RESULT_H
#define CANDELA_SOLVER_GRID_RESULT_H

#include <stddef.h>
#include <stdio.h>

#include "radiometry/error.h"
#include "solver/grid.h"

typedef struct cdl_grid_result {
    const char *name;
    const cdl_grid *grid;     /* points, normals, weights, raster */
    const double *E;          /* total illuminance, lux, grid->count values */
    const double *E_direct;
    const double *E_indirect;
    const double *E_stderr;   /* standard error of E (0 where exact) */
    const double *ao;         /* NULL unless the grid asked for "ao" */
} cdl_grid_result;

typedef struct cdl_grid_stats {
    size_t count;
    double E_avg_lx;          /* area-weighted mean (Em) */
    double E_min_lx;
    double E_max_lx;
    double U0;                /* uniformity Emin / Em (0 when Em = 0) */
    double Ud;                /* diversity Emin / Emax (0 when Emax = 0) */
} cdl_grid_stats;

void cdl_grid_result_stats(const cdl_grid_result *result, cdl_grid_stats *stats);

/* NAME.csv: header x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx
 * (plus AO when requested), one row per point in grid order, numbers with
 * 17 significant digits ("%.17g") so a closed-form result survives. */
cdl_status cdl_grid_result_write_csv(const cdl_grid_result *result, const char *path, cdl_error *err);

/* NAME.exr: float channels E (total lux, also written as Y for viewers),
 * E_direct, E_indirect, E_stderr and mask (1 inside the grid), with string
 * attributes units=lx, quantity=illuminance and each key/value given. */
typedef struct cdl_key_value {
    const char *key;
    const char *value;
} cdl_key_value;
cdl_status cdl_grid_result_write_exr(const cdl_grid_result *result, const char *path, const cdl_key_value *attributes,
                                     size_t attribute_count, cdl_error *err);

/* NAME.png: false-colour map of E (log scale between round lux values
 * bracketing the data) with a lux legend, through the OpenColorIO config
 * (display "sRGB", view "False colour"). */
cdl_status cdl_grid_result_write_png(const cdl_grid_result *result, const char *path, const char *ocio_config,
                                     cdl_error *err);

/* Atomic text output: write through `fp`, then commit (fsync + rename) or
 * abort (remove the temporary file). */
typedef struct cdl_atomic_file {
    FILE *fp;
    char *final_path;
    char *temp_path;
} cdl_atomic_file;
cdl_status cdl_atomic_file_open(cdl_atomic_file *file, const char *path, cdl_error *err);
cdl_status cdl_atomic_file_commit(cdl_atomic_file *file, cdl_error *err);
void cdl_atomic_file_abort(cdl_atomic_file *file);

#endif
