/* palette.c - a perceptually uniform colour scale through CIELAB (palette.h). */
#include "graphics/palette.h"

#include <math.h>

#include "radiometry/constants.h"

/* CIE 15:2004 Table T.3: the D65 white point, Y = 1. */
static const double white_x = 0.95047, white_y = 1.0, white_z = 1.08883;

void cdl_palette_lab(double t, double lab[3])
{
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double h = (300.0 - 200.0 * t) * CDL_DEG_TO_RAD, c = 23.0 + 145.0 * (t - 0.33) * (t - 0.33);
    lab[0] = 16.0 + 76.0 * t;
    lab[1] = c * cos(h);
    lab[2] = c * sin(h);
}

/* CIE 15:2004 8.2.1, inverted: f^-1(u) = u^3 above 6/29, else its linear
 * part 3 (6/29)^2 (u - 4/29). */
static double lab_f_inverse(double u)
{
    const double d = 6.0 / 29.0;
    return u > d ? u * u * u : 3.0 * d * d * (u - 4.0 / 29.0);
}

/* IEC 61966-2-1:1999 (5.2): linear to encoded sRGB, 8 bits. */
static uint8_t srgb8(double linear)
{
    double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
    v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    return (uint8_t)lround(255.0 * v);
}

void cdl_palette_rgb8(double t, uint8_t rgb[3])
{
    double lab[3];
    cdl_palette_lab(t, lab);
    double fy = (lab[0] + 16.0) / 116.0, fx = fy + lab[1] / 500.0, fz = fy - lab[2] / 200.0;
    double x = white_x * lab_f_inverse(fx), y = white_y * lab_f_inverse(fy), z = white_z * lab_f_inverse(fz);
    /* IEC 61966-2-1:1999 (5.2): XYZ (D65) to linear sRGB */
    rgb[0] = srgb8(3.2406 * x - 1.5372 * y - 0.4986 * z);
    rgb[1] = srgb8(-0.9689 * x + 1.8758 * y + 0.0415 * z);
    rgb[2] = srgb8(0.0557 * x - 0.2040 * y + 1.0570 * z);
}

void cdl_palette_ramp(uint8_t rgb[3 * 256])
{
    for (int k = 0; k < 256; ++k) cdl_palette_rgb8(k / 255.0, rgb + 3 * k);
}
