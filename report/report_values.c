/* report_values.c - each grid's values at its points, on request (report_sections.h).
 *
 * A rect grid's values as its map lays them out: a row per row of points
 * from the map's top, a column per column from its left, headed by the
 * points' coordinates along the map's axes (the world coordinate when the
 * axis is one of x, y, z, else the distance from the grid's corner), in
 * blocks of VALUES_COLUMNS columns. A polygon grid's points (which do not
 * fall on rows and columns) and a points grid's as a list: x, y, z and the
 * value, several points to a row. Every value is printed to the decimal
 * place of the grid's mean stated error (report_numbers.h), so the table
 * shows no digit the error does not support.
 */
#include "report/report_sections.h"

#include <math.h>
#include <stdio.h>

#include "report/report_numbers.h"

#define VALUES_COLUMNS 12   /* values per row of a rect grid's block */
#define LIST_GROUPS 3       /* points per row of a list */

/* The coordinate along a map axis: world x, y or z when the axis is one,
 * else the distance from the raster's corner. */
static void axis_coordinate(cdl_vec3 axis, cdl_vec3 corner, double offset, char *name, size_t name_size,
                            double *value_of_offset)
{
    const double c[3] = {axis.x, axis.y, axis.z}, o[3] = {corner.x, corner.y, corner.z};
    for (int k = 0; k < 3; ++k)
        if (fabs(c[k]) > 1.0 - 1e-9) {
            snprintf(name, name_size, "%c", 'x' + k);
            *value_of_offset = o[k] + c[k] * offset;
            return;
        }
    snprintf(name, name_size, "distance");
    *value_of_offset = offset;
}

static void matrix(cdl_report_builder *b, const cdl_report_grid *g, const cdl_report_field *f, int decimals)
{
    const cdl_grid *grid = &g->grid;
    int w = grid->raster_width, h = grid->raster_height;
    /* blocks of at most VALUES_COLUMNS columns, as even as they can be */
    int blocks = (w + VALUES_COLUMNS - 1) / VALUES_COLUMNS, per_block = (w + blocks - 1) / blocks;
    for (int first = 0; first < w; first += per_block) {
        int columns = w - first < per_block ? w - first : per_block;
        cdl_report_block *t = cdl_report_table(b, (size_t)columns + 1, (size_t)h + 1, 1);
        char across[16], up[16];
        double coordinate = 0.0;
        axis_coordinate(grid->raster_right, grid->raster_corner, 0.0, across, sizeof across, &coordinate);
        axis_coordinate(grid->raster_up, grid->raster_corner, 0.0, up, sizeof up, &coordinate);
        cdl_report_cell(b, t, 0, 0, "%s \\ %s (m)", up, across);
        for (int c = 0; c < columns; ++c) {
            axis_coordinate(grid->raster_right, grid->raster_corner, (first + c + 0.5) * grid->pixel_width_m, across,
                            sizeof across, &coordinate);
            cdl_report_cell(b, t, 0, (size_t)c + 1, "%.3f", coordinate);
        }
        for (int r = 0; r < h; ++r) {
            axis_coordinate(grid->raster_up, grid->raster_corner, (h - r - 0.5) * grid->pixel_height_m, up, sizeof up,
                            &coordinate);
            cdl_report_cell(b, t, (size_t)r + 1, 0, "%.3f", coordinate);
            for (int c = 0; c < columns; ++c) {
                int32_t i = grid->raster_index[(size_t)r * (size_t)w + (size_t)(first + c)];
                if (i < 0) cdl_report_cell(b, t, (size_t)r + 1, (size_t)c + 1, "-");
                else cdl_report_cell(b, t, (size_t)r + 1, (size_t)c + 1, "%.*f", decimals, f->values[i]);
            }
        }
    }
}

static void list(cdl_report_builder *b, const cdl_report_grid *g, const cdl_report_field *f, int decimals)
{
    size_t n = g->grid.count, rows = (n + LIST_GROUPS - 1) / LIST_GROUPS;
    cdl_report_block *t = cdl_report_table(b, 4 * LIST_GROUPS, rows + 1, 1);
    for (size_t k = 0; k < LIST_GROUPS; ++k) {
        cdl_report_cell(b, t, 0, 4 * k, "x (m)");
        cdl_report_cell(b, t, 0, 4 * k + 1, "y (m)");
        cdl_report_cell(b, t, 0, 4 * k + 2, "z (m)");
        cdl_report_cell(b, t, 0, 4 * k + 3, "%s%s%s%s", f->symbol, f->unit[0] ? " (" : "", f->unit,
                        f->unit[0] ? ")" : "");
    }
    for (size_t i = 0; i < rows * LIST_GROUPS; ++i) {
        size_t r = i / LIST_GROUPS + 1, c = 4 * (i % LIST_GROUPS);
        if (i >= n) {
            for (size_t k = 0; k < 4; ++k) cdl_report_cell(b, t, r, c + k, " ");
            continue;
        }
        cdl_vec3 p = g->grid.points[i];
        cdl_report_cell(b, t, r, c, "%.3f", p.x);
        cdl_report_cell(b, t, r, c + 1, "%.3f", p.y);
        cdl_report_cell(b, t, r, c + 2, "%.3f", p.z);
        cdl_report_cell(b, t, r, c + 3, "%.*f", decimals, f->values[i]);
    }
}

void cdl_report_values_section(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Values at the grid points");
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Each grid's values at its points. A rectangular grid's as its map shows them: rows from the "
                    "map's top, columns from its left, headed by the points' coordinates (in metres along the map's "
                    "axes: the world coordinate where the axis is x, y or z). A polygon or points grid's points as "
                    "a list. Each value is printed to the decimal place of the grid's mean stated error.");
    for (size_t k = 0; k < in->grid_count; ++k) {
        const cdl_report_grid *g = &in->grids[k];
        for (size_t q = 0; q < g->field_count; ++q) {
            const cdl_report_field *f = &g->fields[q];
            int decimals = cdl_report_decimals(f->avg, f->avg * f->stderr_mean_rel);
            cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s: %s %s%s%s%s", g->spec->name, f->what, f->symbol,
                            f->unit[0] ? " (" : "", f->unit, f->unit[0] ? ")" : "");
            if (g->spec->kind == CDL_GRID_RECT) matrix(b, g, f, decimals);
            else list(b, g, f, decimals);
        }
    }
}
