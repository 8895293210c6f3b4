/* grid_result_check.c - refuse a result that would write a non-number or a broken raster. */
#include "base/error_report.h"
#include "solver/output/grid_result.h"

#include <math.h>

static cdl_status not_finite(cdl_error *err, const char *path, const char *column, size_t point, double value)
{
    return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: %s of point %zu is %s, not a finite number; refusing to write it",
                         path, column, point, isnan(value) ? "NaN" : value > 0 ? "+infinity" : "-infinity");
}

/* index of the first non-finite value in values[0..n), or n */
static size_t first_non_finite(const double *values, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(values[i])) return i;
    return n;
}

cdl_status cdl_grid_result_check(const cdl_grid_result *result, const char *path, cdl_error *err)
{
    if (!path) path = "(unnamed output)";
    const cdl_grid *grid = result ? result->grid : NULL;
    if (!grid) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: the result has no grid", path);
    size_t n = grid->count;
    if (n > 0 && (!grid->points || !grid->normals))
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: the grid has %zu points but no point or normal array", path, n);

    const struct {
        const char *name;
        const double *values;
        int required;
    } columns[] = {
        {"E_lx", result->E, 1},          {"E_direct_lx", result->E_direct, 1}, {"E_indirect_lx", result->E_indirect, 1},
        {"E_stderr_lx", result->E_stderr, 1}, {"AO", result->ao, 0}, {"AO_stderr", result->ao_stderr, 0}, {"area_m2", result->area_m2, 0},
        {"Ez_lx", result->Ez, 0}, {"Esz_lx", result->Esz, 0}, {"L_cd_m2", result->L, 0},
        {"Ez_stderr_lx", result->Ez_stderr, 0}, {"Esz_stderr_lx", result->Esz_stderr, 0},
        {"DF_percent", result->DF, 0},
    };
    for (size_t c = 0; c < sizeof columns / sizeof columns[0]; ++c) {
        if (!columns[c].values) {
            if (columns[c].required && n > 0)
                return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: the result has no %s values", path, columns[c].name);
            continue;
        }
        size_t i = first_non_finite(columns[c].values, n);
        if (i < n) return not_finite(err, path, columns[c].name, i, columns[c].values[i]);
    }
    static const char *const coordinate[6] = {"x", "y", "z", "nx", "ny", "nz"};
    for (size_t i = 0; i < n; ++i) {
        const double v[6] = {grid->points[i].x,  grid->points[i].y,  grid->points[i].z,
                             grid->normals[i].x, grid->normals[i].y, grid->normals[i].z};
        size_t k = first_non_finite(v, 6);
        if (k < 6) return not_finite(err, path, coordinate[k], i, v[k]);
    }

    if (grid->raster_width < 0 || grid->raster_height < 0)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: raster size %d x %d is negative", path, grid->raster_width,
                             grid->raster_height);
    size_t pixels = (size_t)grid->raster_width * (size_t)grid->raster_height;
    if (pixels > 0 && !grid->raster_index)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: raster of %d x %d pixels has no index array", path,
                             grid->raster_width, grid->raster_height);
    for (size_t p = 0; p < pixels; ++p) {
        int32_t idx = grid->raster_index[p];
        if (idx < -1 || (idx >= 0 && (size_t)idx >= n))
            return cdl_error_set(err, CDL_ERR_INTERNAL,
                                 "%s: raster pixel (%zu, %zu) refers to point %ld; expected -1 or 0 .. %zu", path,
                                 p % (size_t)grid->raster_width, p / (size_t)grid->raster_width, (long)idx,
                                 n > 0 ? n - 1 : 0);
    }
    return CDL_OK;
}

cdl_status cdl_grid_result_check_with_raster(const cdl_grid_result *result, const char *path, cdl_error *err)
{
    cdl_status st = cdl_grid_result_check(result, path, err);
    if (st != CDL_OK) return st;
    const cdl_grid *grid = result->grid;
    if (grid->raster_width == 0 || grid->raster_height == 0)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: grid '%s' has no raster (a points grid): no image to make of it",
                             path ? path : "(unnamed output)", result->name ? result->name : "");
    return CDL_OK;
}
