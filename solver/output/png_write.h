/* png_write.h - an 8-bit sRGB image as a PNG file, written atomically.
 *
 * rgb: width x height pixels, 3 bytes each (R, G, B), row-major, top row
 * first, sRGB-encoded (the file says so, with an sRGB chunk). description
 * goes into the file's "Description" text; "Software" is Candela and its
 * version. Errors: CDL_ERR_INTERNAL naming the path (encoder or write
 * failures), or as cdl_atomic_file_open reports them. Used by the grids'
 * false-colour maps (png_output.c) and the bench's plot. */
#ifndef CANDELA_SOLVER_PNG_WRITE_H
#define CANDELA_SOLVER_PNG_WRITE_H

#include <stdint.h>

#include "base/error.h"

cdl_status cdl_png_write_rgb(const char *path, const uint8_t *rgb, int width, int height, const char *description,
                             cdl_error *err);

#endif
