/* exr_output.c - NAME.exr: the grid's raster as float channels of lux. */
#include "solver/output/grid_result.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "solver/scene/exr_image.h"

/* The channels a result may have; the optional ones (Ez, Esz, L, DF) are
 * written only when given. */
enum { CH_E, CH_Y, CH_DIRECT, CH_INDIRECT, CH_STDERR, CH_EZ, CH_ESZ, CH_L, CH_DF, CH_MASK, CHANNELS };
static const char *const channel_name[CHANNELS] = {"E", "Y", "E_direct", "E_indirect", "E_stderr",
                                                   "Ez", "Esz", "L", "DF", "mask"};

/* A value that float cannot hold would become inf in the file. */
static cdl_status check_float_range(const double *values, size_t n, const char *column, const char *path,
                                    cdl_error *err)
{
    for (size_t i = 0; i < n; ++i)
        if (fabs(values[i]) > FLT_MAX)
            return cdl_error_set(err, CDL_ERR_INTERNAL,
                                 "%s: %s of point %zu is %g, beyond the range of a 32-bit float; refusing to write it",
                                 path, column, i, values[i]);
    return CDL_OK;
}

static cdl_status check_attributes(const cdl_key_value *attributes, size_t count, const char *path, cdl_error *err)
{
    for (size_t a = 0; a < count; ++a) {
        const char *key = attributes[a].key;
        if (!key || !*key || !attributes[a].value)
            return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: attribute %zu has no key or no value", path, a);
        if (strcmp(key, "units") == 0 || strcmp(key, "quantity") == 0)
            return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: attribute '%s' is reserved (written as units=lx, quantity=illuminance)",
                                 path, key);
    }
    return CDL_OK;
}

cdl_status cdl_grid_result_write_exr(const cdl_grid_result *result, const char *path, const cdl_key_value *attributes,
                                     size_t attribute_count, cdl_error *err)
{
    cdl_status st = cdl_grid_result_check_with_raster(result, path, err);
    if (st != CDL_OK) return st;
    const cdl_grid *grid = result->grid;
    const double *source[CHANNELS] = {result->E,  result->E,   result->E_direct, result->E_indirect, result->E_stderr,
                                      result->Ez, result->Esz, result->L,        result->DF,         NULL};
    for (int c = CH_E; c < CH_MASK && st == CDL_OK; ++c)
        if (source[c]) st = check_float_range(source[c], grid->count, channel_name[c], path, err);
    if (st == CDL_OK) st = check_attributes(attributes, attribute_count, path, err);
    if (st != CDL_OK) return st;

    size_t pixels = (size_t)grid->raster_width * (size_t)grid->raster_height;
    float *planes = calloc(pixels * CHANNELS, sizeof(float));
    cdl_exr_attribute *attrs = malloc((attribute_count + 2) * sizeof *attrs);
    if (!planes || !attrs) {
        free(planes);
        free(attrs);
        return cdl_error_out_of_memory(err);
    }
    for (size_t p = 0; p < pixels; ++p) {
        int32_t idx = grid->raster_index[p];
        if (idx < 0) continue; /* outside: 0 in every channel, mask included */
        for (int c = CH_E; c < CH_MASK; ++c)
            if (source[c]) planes[(size_t)c * pixels + p] = (float)source[c][idx];
        planes[(size_t)CH_MASK * pixels + p] = 1.0f;
    }
    cdl_exr_channel channels[CHANNELS];
    int used = 0;
    for (int c = 0; c < CHANNELS; ++c) {
        if (c != CH_MASK && !source[c]) continue;
        channels[used].name = channel_name[c];
        channels[used].pixels = planes + (size_t)c * pixels;
        ++used;
    }
    attrs[0].name = "units";
    attrs[0].value = "lx";
    attrs[1].name = "quantity";
    attrs[1].value = "illuminance";
    for (size_t a = 0; a < attribute_count; ++a) {
        attrs[a + 2].name = attributes[a].key;
        attrs[a + 2].value = attributes[a].value;
    }
    /* cdl_exr_write goes through OpenEXR's temporary-file mode: the file
     * appears under its name only when complete. Its errors name the path. */
    st = cdl_exr_write(path, grid->raster_width, grid->raster_height, channels, (size_t)used, attrs,
                       attribute_count + 2, err);
    free(planes);
    free(attrs);
    return st;
}
