/* grid_result.h - illuminance results of one grid, their statistics, and
 * the files `candela solve` writes for them (DESIGN.md, "Outputs of solve").
 *
 * Every file is written atomically (atomic_file.h): to a temporary name in
 * the same folder, flushed and synced, then renamed over the final name, so
 * an interrupted run leaves earlier results intact and never a half-written
 * file. The writers do not create folders: a missing folder is an error.
 *
 * Before writing anything, every writer checks the result with
 * cdl_grid_result_check and refuses (CDL_ERR_INTERNAL, message naming the
 * file, the column and the point) a missing array or a value that is NaN or
 * infinite: a result file never holds a number that is not one. Errors name
 * the file and what failed; I/O failures are CDL_ERR_INTERNAL.
 *
 * All functions are reentrant; distinct results may be written from
 * distinct threads.
 */
#ifndef CANDELA_SOLVER_GRID_RESULT_H
#define CANDELA_SOLVER_GRID_RESULT_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"
#include "base/atomic_file.h"
#include "solver/grid/grid.h"
#include "solver/output/lux_scale.h"
#include "solver/solution_internal.h"

/* A map of another quantity than illuminance (an annual metric's share
 * of hours, daylight/annual.h): what it is, its unit's label, a fixed
 * linear range with its tick, and the line under the title. */
typedef struct cdl_map_quantity {
    const char *what;         /* "daylight autonomy DA300, % of occupied hours" (the PNG's description) */
    const char *unit;         /* the legend's unit: "%", "h" */
    double lo, hi, tick;      /* the colours' range and the legend's step */
    char stats[160];          /* under the title, instead of Em, Emin, Emax and U0 */
} cdl_map_quantity;

/* The arrays hold grid->count values each, in grid order. E, E_direct,
 * E_indirect and E_stderr are required (a direct-only solve passes zeros for
 * E_indirect); ao is optional. */
typedef struct cdl_grid_result {
    const char *name;
    const cdl_grid *grid;     /* points, normals, weights, raster */
    const double *E;          /* total illuminance, lux, grid->count values */
    const double *E_direct;   /* lux */
    const double *E_indirect; /* lux */
    const double *E_stderr;   /* standard error of E, lux (0 where exact) */
    const double *ao;         /* NULL unless the grid asked for "ao"; [0, 1] */
    const double *ao_stderr;  /* with ao: its standard error */
    /* Optional columns after the fixed ten, in this order when present: */
    const double *area_m2;    /* the area each point stands for (polygon grids), m^2 */
    const double *Ez;         /* cylindrical illuminance, lux ("cylindrical") */
    const double *Esz;        /* semicylindrical illuminance, lux ("semicylindrical") */
    const double *L;          /* luminance rho E / pi, cd/m^2 ("luminance") */
    const double *DF;         /* daylight factor, percent ("daylight_factor") */
    const double *Ez_stderr;  /* with Ez where part of it is sampled: its standard error, lux */
    const double *Esz_stderr; /* with Esz likewise */
    int map_log_scale;        /* NAME.png: 1 a logarithmic lux scale, 0 (default) linear (lux_scale.h) */
    const cdl_map_quantity *quantity; /* NAME.png: NULL for illuminance; else E holds this quantity */
} cdl_grid_result;

/* A solved grid's results as the writers take them: E and its parts, ao,
 * area_m2 (polygon grids' weights, else NULL), Ez, Esz, L; *out borrows the
 * grid solution's arrays. Thread-safe; no errors. */
void cdl_grid_solution_result(const cdl_grid_solution *gs, cdl_grid_result *out);

/* Check a result before it is written to `path` (used in messages): grid and
 * the four required arrays present; every coordinate, normal component and
 * value finite; a raster, if any, of non-negative size whose entries are -1
 * or a point index. CDL_ERR_INTERNAL otherwise (the caller built it). */
cdl_status cdl_grid_result_check(const cdl_grid_result *result, const char *path, cdl_error *err);
/* The same, and the grid must have a raster (rect and polygon grids): for images. */
cdl_status cdl_grid_result_check_with_raster(const cdl_grid_result *result, const char *path, cdl_error *err);

/* Mean (area-weighted as Em), minimum, maximum and Min / mean of one
 * quantity over a grid. */
typedef struct cdl_value_stats {
    double avg, min, max, U0;
} cdl_value_stats;

typedef struct cdl_grid_stats {
    size_t count;
    double area_m2;           /* sum of the points' area weights (0 for points grids) */
    cdl_value_stats Ez, Esz, L, DF; /* of the optional columns given (zeros otherwise) */
    double E_avg_lx;          /* area-weighted mean (Em) */
    double E_min_lx;
    double E_max_lx;
    double U0;                /* uniformity Emin / Em (0 when Em = 0) */
    double Ud;                /* diversity Emin / Emax (0 when Emax = 0) */
    /* The stated error, relative: E_stderr / E over the points with E > 0
     * (a dark point's relative error has no value; its E_stderr_lx is
     * still in the CSV): the area-weighted mean and the worst. */
    double stderr_mean_rel, stderr_max_rel;
    double stderr_max_lx;     /* the worst E_stderr over all points */
} cdl_grid_stats;

/* Statistics of E over the grid (EN 12464-1 terms). Em is weighted by
 * grid->weights (the area each point stands for); with weights NULL, or all
 * zero, it is the plain mean. An empty grid gives all zeros. Expects finite
 * values (cdl_grid_result_check). */
void cdl_grid_result_stats(const cdl_grid_result *result, cdl_grid_stats *stats);

/* The columns every NAME.csv starts with (DESIGN.md), in order. */
#define CDL_GRID_CSV_COLUMNS "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx"

/* NAME.csv: header CDL_GRID_CSV_COLUMNS
 * then, for those given, area_m2, AO, AO_stderr, Ez_lx, Ez_stderr_lx, Esz_lx,
 * Esz_stderr_lx, L_cd_m2, DF_percent; one row per point in grid order, "\n" line
 * ends. Each number is the shortest of "%.15g", "%.16g", "%.17g" that reads
 * back (strtod) as exactly the same double, so a closed-form result
 * survives the trip to text. Expects the "C" numeric locale (the library
 * never changes it). */
cdl_status cdl_grid_result_write_csv(const cdl_grid_result *result, const char *path, cdl_error *err);

/* Enough for "%.17g" of any double: sign, 17 digits, point, "e-308". */
#define CDL_CSV_NUMBER_SIZE 32
/* A number as the CSV files write it: the shortest of 15 to 17 significant
 * digits that reads back as exactly v (csv_output.c). */
void cdl_csv_format_number(double v, char buf[CDL_CSV_NUMBER_SIZE]);
/* One CSV row of n numbers, each as NAME.csv writes them (above), then "\n". */
void cdl_csv_write_numbers(FILE *fp, const double *values, size_t n);

/* NAME.exr (rect and polygon grids; a grid without a raster is refused):
 * 32-bit float channels, one pixel per raster pixel, top row first:
 *   E           total illuminance, lux
 *   Y           the same values, for generic viewers
 *   E_direct    lux
 *   E_indirect  lux
 *   E_stderr    lux
 *   Ez          cylindrical illuminance, lux (when given)
 *   Esz         semicylindrical illuminance, lux (when given)
 *   L           luminance, cd/m^2 (when given)
 *   DF          daylight factor, percent (when given)
 *   mask        1 inside the grid, 0 outside (outside pixels hold 0 in every channel)
 * String attributes units=lx, quantity=illuminance and each key/value given
 * (the solver's settings); a key may not repeat "units" or "quantity". A
 * value beyond the float range is refused rather than written as inf. */
typedef struct cdl_key_value {
    const char *key;
    const char *value;
} cdl_key_value;
cdl_status cdl_grid_result_write_exr(const cdl_grid_result *result, const char *path, const cdl_key_value *attributes,
                                     size_t attribute_count, cdl_error *err);

/* NAME.png (rect and polygon grids; a grid without a raster is refused): an
 * 8-bit sRGB image on a white background, readable on its own. At the top
 * the grid's name and "Em ... lx  Emin ... lx  Emax ... lx  U0 ..." (the
 * statistics of cdl_grid_result_stats). Below, the false-colour map of E:
 * each raster pixel drawn as a square of `cell` image pixels (nearest
 * neighbour, the long side at least 400 pixels), pixels outside the grid
 * left white, with axes in metres along its bottom and left edges (world
 * coordinates where the edge runs along a world axis, then named "+x (m)",
 * "-y (m)", ...; else distances from the corner, "u (m)" and "v (m)").
 * Right, the legend: a colour bar (top = scale.hi, bottom = scale.lo) in a
 * black frame with ticks labelled in lux, as many as fit without
 * overlapping: on the linear scale (the default) at multiples of its tick,
 * the bottom one "<=" when values lie below it; on the logarithmic scale
 * (result->map_log_scale) at 1-2-5 values ("500 lx", "0.2 lx", "20k lx").
 * Colours: E maps to t = cdl_lux_scale_position, and (t, t, t) goes through
 * the OpenColorIO config `ocio_config` from colour space "linear" to
 * display "sRGB", view "False colour"; the result is rounded to 8 bits.
 * A bad config is CDL_ERR_INPUT, prefixed with the PNG's path. */
cdl_status cdl_grid_result_write_png(const cdl_grid_result *result, const char *path, const char *ocio_config,
                                     cdl_error *err);

/* Where things sit in NAME.png, in image pixels (x right, y down). */
typedef struct cdl_png_layout {
    cdl_lux_scale scale;      /* the lux range of the colours */
    int title_y, stats_y;     /* top of the name's line and of the statistics' line (x = map_x) */
    int axis_label_width;     /* room left of the map for the vertical axis' labels */
    int width, height;        /* the whole image */
    int map_x, map_y;         /* top-left corner of the map */
    int cell;                 /* raster pixel (c, r) covers x in [map_x + c cell, map_x + (c+1) cell) */
    int bar_x, bar_y;         /* top-left corner of the colour bar (inside its frame) */
    int bar_width, bar_height;
    int label_x;              /* left edge of the tick labels */
    char unit[8];             /* "" for lux; else the quantity's unit */
} cdl_png_layout;

/* The layout cdl_grid_result_write_png uses for `result` (which must have a
 * raster and pass cdl_grid_result_check). */
void cdl_grid_result_png_layout(const cdl_grid_result *result, cdl_png_layout *layout);

#endif
