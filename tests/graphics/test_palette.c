/* The report's colour scale (palette.h) is perceptually uniform in
 * lightness: read back from its 8-bit sRGB colours by the inverse of
 * IEC 61966-2-1 and CIE 15:2004's L* (computed here, not by the code under
 * test), lightness rises monotonically along the scale in steps of equal
 * size, from dark to light; the legend's ramp is the scale; the ends are
 * the colours the path names (indigo, yellow). */
#include <math.h>
#include <stdint.h>

#include "check.h"
#include "graphics/palette.h"

/* CIE 15:2004 8.2.1: L*, a*, b* of an 8-bit sRGB colour (IEC 61966-2-1:1999
 * decoding and its inverse matrix, D65 white (0.95047, 1, 1.08883)). */
static void lab_of(const uint8_t rgb[3], double lab[3])
{
    double lin[3];
    for (int k = 0; k < 3; ++k) {
        double v = rgb[k] / 255.0;
        lin[k] = v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
    }
    double x = 0.4124 * lin[0] + 0.3576 * lin[1] + 0.1805 * lin[2];
    double y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
    double z = 0.0193 * lin[0] + 0.1192 * lin[1] + 0.9505 * lin[2];
    const double d = 6.0 / 29.0;
    double f[3] = {x / 0.95047, y, z / 1.08883};
    for (int k = 0; k < 3; ++k) f[k] = f[k] > d * d * d ? cbrt(f[k]) : f[k] / (3.0 * d * d) + 4.0 / 29.0;
    lab[0] = 116.0 * f[1] - 16.0;
    lab[1] = 500.0 * (f[0] - f[1]);
    lab[2] = 200.0 * (f[1] - f[2]);
}

int main(void)
{
    /* The path itself: L* linear in t, 16 to 92. */
    for (int k = 0; k <= 100; ++k) {
        double lab[3];
        cdl_palette_lab(k / 100.0, lab);
        CHECK_ABS(lab[0], 16.0 + 0.76 * k, 1e-12); /* the formula, to rounding */
    }
    /* The 8-bit colours, read back: 16 equal steps of t are 16 equal steps
     * of lightness, 76 / 16 = 4.75 L* each. Rounding each channel to 8 bits
     * moves L* by at most about 0.25 at either end of a step (one level of
     * sRGB near black is 0.5 L*, half a level at most is rounded away),
     * so a step may differ from 4.75 by up to 0.5. */
    enum { STEPS = 16 };
    double previous = -1.0, worst = 0.0;
    for (int k = 0; k <= STEPS; ++k) {
        uint8_t rgb[3];
        double lab[3];
        cdl_palette_rgb8((double)k / STEPS, rgb);
        lab_of(rgb, lab);
        if (k > 0) {
            double step = lab[0] - previous;
            CHECK_MSG(step > 0.0, "lightness falls from step %d to %d", k - 1, k);
            CHECK_ABS(step, 76.0 / STEPS, 0.5); /* 8-bit rounding, above */
            worst = fmax(worst, fabs(step - 76.0 / STEPS));
        }
        previous = lab[0];
    }
    printf("lightness steps of 4.75 L*: worst %.3f off\n", worst);
    /* At the legend's resolution (256 colours, 0.3 L* apart) lightness
     * never falls by more than 8-bit rounding can make it (measured: 0.045
     * L* at worst), ten times below a just-noticeable difference of lightness
     * (about 1 L*): the legend shows no band visibly darker than the one
     * below it. */
    uint8_t ramp[3 * 256];
    cdl_palette_ramp(ramp);
    double lo[3];
    lab_of(ramp, lo);
    for (int k = 1; k < 256; ++k) {
        double lab[3];
        lab_of(ramp + 3 * k, lab);
        CHECK_MSG(lab[0] >= lo[0] - 0.1, "the legend darkens at entry %d (%.3f after %.3f)", k, lab[0], lo[0]);
        lo[0] = lab[0];
        uint8_t direct[3];
        cdl_palette_rgb8(k / 255.0, direct);
        CHECK(direct[0] == ramp[3 * k] && direct[1] == ramp[3 * k + 1] && direct[2] == ramp[3 * k + 2]);
    }
    /* The ends: dark indigo (blue above red above green) and light yellow. */
    uint8_t first[3], last[3], below[3], above[3];
    cdl_palette_rgb8(0.0, first);
    cdl_palette_rgb8(1.0, last);
    cdl_palette_rgb8(-3.0, below);
    cdl_palette_rgb8(7.0, above);
    CHECK(first[2] > first[0] && first[0] > first[1] && first[2] < 128);
    CHECK(last[0] > 200 && last[1] > 200 && last[2] < 80);
    CHECK(below[0] == first[0] && below[1] == first[1] && below[2] == first[2]);
    CHECK(above[0] == last[0] && above[1] == last[1] && above[2] == last[2]);
    return check_finish();
}
