/* palette.h - the report's colour scale: perceptually uniform, computed in CIELAB.
 *
 * A sequential scale for maps of a quantity: t in [0, 1] (a value's place
 * on the map's scale) to a colour whose CIELAB lightness rises linearly
 * with t, so equal steps of the value look like equal steps of colour and
 * the legend shows no band or step (the eye reads a map's lightness first:
 * a rainbow's yellow band looks like a ridge the light does not have). The
 * path through CIELAB (CIE 15:2004, 8.2.1):
 *   L*(t) = 16 + 76 t                      dark to light, linearly
 *   h(t)  = 300 - 200 t  degrees           indigo, blue, teal, green, yellow
 *                                          (the order of viridis, van der
 *                                          Walt and Smith 2015, which the
 *                                          path resembles; not its table)
 *   C*(t) = 23 + 145 (t - 0.33)^2          inside the sRGB gamut all along
 *                                          (at least 3 units of chroma to
 *                                          spare at every t, checked at 1001
 *                                          steps when the path was chosen)
 * then to XYZ with the D65 white and to sRGB by IEC 61966-2-1:1999 (its
 * matrix and transfer function), rounded to 8 bits. Values of t outside
 * [0, 1] take the end colours. Pure functions; thread-safe.
 */
#ifndef CANDELA_GRAPHICS_PALETTE_H
#define CANDELA_GRAPHICS_PALETTE_H

#include <stdint.h>

/* The colour at t in CIELAB: lab = {L*, a*, b*}. */
void cdl_palette_lab(double t, double lab[3]);

/* The colour at t as 8-bit sRGB. */
void cdl_palette_rgb8(double t, uint8_t rgb[3]);

/* A legend's ramp: 256 colours, entry k at t = k / 255. */
void cdl_palette_ramp(uint8_t rgb[3 * 256]);

#endif
