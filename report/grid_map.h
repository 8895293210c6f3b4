/* grid_map.h - a grid's illuminance as the report draws it.
 *
 * The false-colour map of a rect or polygon grid (the colours of NAME.png:
 * a linear lux scale and the OCIO false-colour view), with
 *   - a lux legend beside it,
 *   - isolux lines labelled in lux (contour.h, round levels between Emin
 *     and Emax),
 *   - the plan: every surface's outline and every luminaire's position
 *     (area luminaires by their outline) projected orthographically onto
 *     the grid's plane, clipped to the map,
 *   - the points of Emin and Emax marked with their values,
 *   - a scale bar in metres and the directions of the map's axes.
 * Drawn with cairo as a figure (graphics/figure.h) in points. Errors from
 * cdl_grid_map_prepare: the OCIO config's, memory. Ownership: the map
 * borrows the input and the grid; release frees what prepare made.
 */
#ifndef CANDELA_REPORT_GRID_MAP_H
#define CANDELA_REPORT_GRID_MAP_H

#include <cairo.h>

#include "graphics/figure.h"
#include "report/contour.h"
#include "report/report_input.h"
#include "solver/output/lux_scale.h"

#define CDL_GRID_MAP_MAX_LEVELS 8

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
