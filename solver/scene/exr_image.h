/* exr_image.h - float images in OpenEXR files, through the OpenEXR Core C API.
 *
 * Writes single-part scanline files (ZIP compression, 32-bit float channels)
 * with string attributes, atomically: the library writes a temporary file and
 * renames it, so an interrupted run never leaves a half-written image.
 * Reads scanline and tiled (level 0) files with HALF or FLOAT channels into
 * 32-bit floats. Pixels are row-major, top row first (y down, as EXR).
 */
#ifndef CANDELA_SOLVER_EXR_IMAGE_H
#define CANDELA_SOLVER_EXR_IMAGE_H

#include <stddef.h>

#include "base/error.h"

typedef struct cdl_exr_channel {
    const char *name;    /* e.g. "Y", "E_direct" */
    const float *pixels; /* width x height */
} cdl_exr_channel;

typedef struct cdl_exr_attribute {
    const char *name;  /* e.g. "units" */
    const char *value; /* e.g. "lx" */
} cdl_exr_attribute;

cdl_status cdl_exr_write(const char *path, int width, int height, const cdl_exr_channel *channels,
                         size_t channel_count, const cdl_exr_attribute *attributes, size_t attribute_count,
                         cdl_error *err);

typedef struct cdl_exr_image {
    int width, height;
    size_t channel_count;
    char **channel_names;  /* as in the file (sorted by name) */
    float **channels;      /* channel_count planes of width x height */
} cdl_exr_image;

cdl_status cdl_exr_read(const char *path, cdl_exr_image *out, cdl_error *err);

/* The plane of channel `name`, or NULL. */
const float *cdl_exr_image_channel(const cdl_exr_image *image, const char *name);

/* Value of string attribute `name` read from the file into buf; CDL_ERR_INPUT if absent. */
cdl_status cdl_exr_read_string_attribute(const char *path, const char *name, char *buf, size_t size,
                                         cdl_error *err);

void cdl_exr_image_release(cdl_exr_image *image);

#endif
