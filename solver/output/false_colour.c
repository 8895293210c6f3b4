/* false_colour.c - lux-scale positions through the false-colour view (false_colour.h). */
#include "base/error_report.h"
#include "solver/output/false_colour.h"

#include <stdlib.h>

/* Display-referred float in [0, 1] to an 8-bit code value, rounded to nearest. */
static uint8_t to_8bit(float v)
{
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (uint8_t)(v * 255.0f + 0.5f);
}

cdl_status cdl_false_colour_rgb8(const cdl_display_transform *view, const double *t, size_t n, uint8_t *out,
                                 cdl_error *err)
{
    float *rgb = malloc((n ? n : 1) * 3 * sizeof(float));
    if (!rgb) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < n; ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = (float)t[i];
    cdl_status st = cdl_display_transform_apply(view, rgb, n, err);
    for (size_t i = 0; st == CDL_OK && i < 3 * n; ++i) out[i] = to_8bit(rgb[i]);
    free(rgb);
    return st;
}
