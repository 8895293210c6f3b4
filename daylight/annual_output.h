/* annual_output.h - the files of an annual study (not public).
 *
 * Per grid NAME, in the output folder:
 *   NAME.hourly.bin   every hour's illuminance at every point (below);
 *   NAME.sun.bin      --sky perez: the direct sun alone, the same way (ASE's
 *                     input: no sky, no interreflection);
 *   NAME.csv          one row per point, in grid order: x,y,z,nx,ny,nz, then
 *                     area_m2 (polygon grids), DA300_percent,
 *                     UDI_fell_short_percent, UDI_percent,
 *                     UDI_exceeded_percent, ASE_hours,
 *                     EN17037_target_percent (of the daylight hours),
 *                     coefficient_rel_stderr, and DF_percent (cie_overcast);
 *   NAME_DA300.png, NAME_UDI.png, NAME_ASE.png, NAME_EN17037.png
 *                     (rect and polygon grids): false-colour maps of the
 *                     metric (solver/output's maps, 0 to 100 % or to the
 *                     most ASE hours).
 * And annual.csv, a row per grid: grid,points,sDA300_percent,
 * ASE1000_percent,DA300_mean_percent,UDI_fell_short_percent,UDI_percent,
 * UDI_exceeded_percent,EN17037_level,EN17037_minimum_met,
 * EN17037_medium_met,EN17037_high_met,stderr_mean_rel,stderr_max_rel
 * (annual.c), and summary.json.
 * The hourly files (little-endian):
 *   bytes 0-7    "CDLHOUR1"
 *   8-11         uint32 hours (the weather file's rows, 8760 or 8784)
 *   12-15        uint32 points (the grid's, in its CSV order)
 *   16-19        uint32 quantity: 1 illuminance, 2 the direct sun alone (lx)
 *   20-23        uint32 0 (reserved)
 *   24-          float32 values, hour by hour: hour h's points at
 *                24 + 4 (h points + i)
 * Every file is written atomically (base/atomic_file.h).
 */
#ifndef CANDELA_DAYLIGHT_ANNUAL_OUTPUT_H
#define CANDELA_DAYLIGHT_ANNUAL_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "daylight/annual_metrics.h"
#include "solver/grid/grid.h"

#define CDL_HOURLY_MAGIC "CDLHOUR1"
#define CDL_HOURLY_HEADER_BYTES 24
enum { CDL_HOURLY_ILLUMINANCE = 1, CDL_HOURLY_DIRECT_SUN = 2 };

/* Write an hourly file: hour h's values are rows[row_of_hour[h] * points ..]
 * (0 where row_of_hour[h] < 0). */
cdl_status cdl_annual_write_hourly(const char *path, uint32_t quantity, size_t hours, size_t points,
                                   const int *row_of_hour, const float *rows, cdl_error *err);

/* Read one back: *values (hours x points, the caller frees), checking the
 * header and the size (CDL_ERR_INPUT naming the file and what was wrong). */
cdl_status cdl_annual_read_hourly(const char *path, uint32_t *quantity, size_t *hours, size_t *points,
                                  float **values, cdl_error *err);

/* One grid's results as the writers take them. */
typedef struct cdl_annual_grid_files {
    const char *name;
    int polygon;                          /* 1: area_m2 in the CSV */
    const cdl_grid *grid;
    const cdl_point_metrics *metrics;     /* per point */
    const double *rel_stderr;             /* per point */
    const double *DF;                     /* per point (cie_overcast), or NULL */
    double ase_hours_max;                 /* the ASE map's top */
} cdl_annual_grid_files;

/* NAME.csv and the maps. */
cdl_status cdl_annual_write_grid(const char *out_dir, const cdl_annual_grid_files *g, const char *ocio_config,
                                 cdl_error *err);

#endif
