/* false_colour.h - positions on a lux scale as 8-bit sRGB false colours.
 *
 * The colours of the maps (NAME.png) and of the report's maps: a position
 * t in [0, 1] on a lux scale (lux_scale.h) goes as a grey value through the
 * OpenColorIO "False colour" view (display_transform.h), whose 1D LUT gives
 * each channel its own ramp, and the display-referred result is rounded to
 * 8-bit code values. Errors: as cdl_display_transform_apply; memory.
 * Thread safety: as the view's (shared OCIO CPU processors are safe).
 */
#ifndef CANDELA_SOLVER_FALSE_COLOUR_H
#define CANDELA_SOLVER_FALSE_COLOUR_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/output/display_transform.h"

/* The colours of t[0 .. n) into out[3 n] (R, G, B). */
cdl_status cdl_false_colour_rgb8(const cdl_display_transform *view, const double *t, size_t n, uint8_t *out,
                                 cdl_error *err);

#endif
