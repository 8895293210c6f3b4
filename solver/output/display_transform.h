/* display_transform.h - colour transforms through OpenColorIO, behind a C API.
 *
 * Candela ships a small OCIO config in data/ocio/ (an sRGB display with a
 * "Standard" view and a "False colour" view); a studio can point Candela at
 * its own config instead. Pixels are packed RGB floats, transformed in place.
 */
#ifndef CANDELA_SOLVER_DISPLAY_TRANSFORM_H
#define CANDELA_SOLVER_DISPLAY_TRANSFORM_H

#include <stddef.h>

#include "base/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cdl_display_transform cdl_display_transform;

/* Open the processor for colour space `source` viewed on `display`/`view`
 * of the config file at `config_path`. */
cdl_status cdl_display_transform_open(const char *config_path, const char *source, const char *display,
                                      const char *view, cdl_display_transform **out, cdl_error *err);

/* Transform pixel_count packed RGB triples in place. Thread-safe for a
 * shared transform (OCIO CPU processors are). */
cdl_status cdl_display_transform_apply(const cdl_display_transform *transform, float *rgb, size_t pixel_count,
                                       cdl_error *err);

void cdl_display_transform_release(cdl_display_transform *transform);

#ifdef __cplusplus
}
#endif

#endif
