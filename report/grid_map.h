/* grid_map.h - a grid's quantity as the report draws it.
 *
 * The false-colour map of a rect or polygon grid's E (or of another
 * quantity it asked for: Ez, Esz, L, AO), with
 *   - a legend beside it, on a linear scale from 0 (or from the 2nd
 *     percentile where nearly all the grid is bright, lux_scale.h; AO 0 to
 *     1) in the report's perceptually uniform palette (palette.h: lightness
 *     rises in equal steps, so the map shows no false ridge),
 *   - contour (isolux) lines at round levels between the minimum and the
 *     maximum (contour.h),
 *   - the plan, projected orthographically onto the grid's plane and
 *     clipped to the map: every surface's outline (a box's open faces, its
 *     windows and doors, in blue), every luminaire as its footprint, with
 *     aiming lines and masts (plan_symbols.h),
 *   - the points of the minimum and the maximum marked with their values,
 *   - labels (the contour levels, the min and max values) placed so that
 *     none covers another, a luminaire or a marker (label_layout.h): a
 *     level whose every place is taken goes unlabelled, never overprinted,
 *   - a scale bar in metres and the directions of the map's axes.
 * Drawn with cairo as a figure (graphics/figure.h) in points. Errors from
 * cdl_grid_map_prepare: memory. Ownership: the map borrows the input and
 * the grid; release frees what prepare made.
 */
#ifndef CANDELA_REPORT_GRID_MAP_H
#define CANDELA_REPORT_GRID_MAP_H

#include <cairo.h>

#include "graphics/figure.h"
#include "report/contour.h"
#include "report/label_layout.h"
#include "report/report_input.h"
#include "solver/output/lux_scale.h"

#define CDL_GRID_MAP_MAX_LEVELS 8
#define CDL_GRID_MAP_MAX_LABELS (CDL_GRID_MAP_MAX_LEVELS + 2)

/* A label on the map: its text and, when placed, its box (points). */
typedef struct cdl_grid_map_label {
    char text[64];
    double size;                   /* the text's size, points */
    cdl_label_box box;
    int placed;
} cdl_grid_map_label;

typedef struct cdl_grid_map {
    const cdl_report_input *input;
    const cdl_report_grid *grid;
    const cdl_report_field *field;  /* the quantity shown: grid->fields[k] */
    cdl_lux_scale scale;
    cairo_surface_t *image;        /* the false colours, each raster pixel `zoom` x `zoom` */
    int zoom;
    uint8_t legend_rgb[3 * 256];   /* the legend's ramp, bottom (t = 0) to top */
    double levels[CDL_GRID_MAP_MAX_LEVELS];
    size_t level_count;
    cdl_contour_segment *segments[CDL_GRID_MAP_MAX_LEVELS];
    size_t segment_count[CDL_GRID_MAP_MAX_LEVELS];
    /* layout, points */
    double metres_to_points;
    double map_x, map_y, map_w, map_h;
    double width, height;
    char title[160];
    /* the plan's luminaires, the min and max markers and every label, on the figure */
    struct cdl_plan_symbol *symbols;
    size_t symbol_count;
    double min_x, min_y, max_x, max_y;
    cdl_grid_map_label labels[CDL_GRID_MAP_MAX_LABELS]; /* 0 the min's, 1 the max's, 2 + k level k's */
    size_t label_count;
} cdl_grid_map;

/* The map of grid->fields[field] (0: E). */
cdl_status cdl_grid_map_prepare(cdl_grid_map *map, const cdl_report_input *input, const cdl_report_grid *grid,
                                size_t field, cdl_error *err);
cdl_figure cdl_grid_map_figure(const cdl_grid_map *map);
void cdl_grid_map_release(cdl_grid_map *map);

/* A raster position (x right, y down, in pixels) of a world point
 * projected onto the grid's plane. */
void cdl_grid_map_raster_position(const cdl_grid *grid, cdl_vec3 p, double *x, double *y);

#endif
