/* lux_scale.h - the lux scales of false-colour maps: linear (the default) or logarithmic.
 *
 * Linear (cdl_lux_scale_linear_for_values): from 0, or, where nearly all
 * the grid is bright (its 2nd-percentile value at least half its maximum),
 * from that value rounded down, so a uniform field shows its variation and
 * a single dark point (a 0 lx corner) does not flatten the rest; to the
 * maximum rounded up; ticks at a 1-2-5 step giving about six intervals.
 * Values below the bottom show in the bottom colour (the legend says "<=").
 *
 * Logarithmic, on request:
 *
 * A map shows illuminance on a log scale, because the eye and lighting
 * practice both judge light in ratios: the step from 100 to 200 lx matters as
 * much as the step from 500 to 1000 lx. The scale runs between two round
 * values of the 1-2-5 sequence (... 0.5, 1, 2, 5, 10, 20, 50 ... lx) that
 * bracket the data, so legend ticks fall on numbers a designer reads at a
 * glance. Values are numbered by step k:
 *
 *   value(k) = {1, 2, 5}[k mod 3] x 10^floor(k / 3) lx    (k = 0: 1 lx, k = 8: 500 lx, k = -1: 0.5 lx)
 *
 * computed as m x 10^e or m / 10^-e, so value(-1) is the double nearest 0.5
 * and value(-2) the double nearest 0.2, exactly as the literals.
 */
#ifndef CANDELA_SOLVER_LUX_SCALE_H
#define CANDELA_SOLVER_LUX_SCALE_H

#include <stddef.h>

#include "radiometry/units.h"

/* Steps are kept within 1e-20 lx .. 1e20 lx; values beyond sit at the ends. */
#define CDL_LUX_SCALE_MIN_STEP (-60)
#define CDL_LUX_SCALE_MAX_STEP 60
/* The widest range chosen from data: 12 steps, four decades. Values below
 * the bottom of the range show in the bottom colour. */
#define CDL_LUX_SCALE_MAX_STEPS 12

typedef enum cdl_lux_scale_kind { CDL_LUX_SCALE_LOG, CDL_LUX_SCALE_LINEAR } cdl_lux_scale_kind;

typedef struct cdl_lux_scale {
    cdl_lux_scale_kind kind;
    int lo_step, hi_step;     /* log: lo_step < hi_step */
    cdl_illuminance lo, hi;   /* log: value(lo_step), value(hi_step); linear: the ends, multiples of tick */
    double tick_lx;           /* linear: distance between ticks, a 1-2-5 value */
    int clipped;              /* linear: some value lies below lo */
    int clipped_top;          /* linear, of areas: some value lies above hi */
} cdl_lux_scale;

/* The linear scale for `count` illuminances (finite values; see above).
 * All zero or empty: 0 .. 10 lx. */
cdl_lux_scale cdl_lux_scale_linear_for_values(const double *E_lx, size_t count);

/* The linear scale of values that stand for areas (a surface map's
 * vertices, area[i] the area each stands for): as above, but its top is
 * the value 99 % of the area lies at or below, when the rest goes higher
 * (clipped_top): a luminaire's hot spot on a wall, a small part of the
 * area where the mesh is densest, must not flatten the colours of the
 * rest. Values above the top show in the top colour. */
cdl_lux_scale cdl_lux_scale_linear_for_areas(const double *E_lx, const double *area, size_t count);

/* A linear scale's label of `lx`: "480 lx", "0.25 lx", "12.5k lx" (k from 10 000 lx). */
size_t cdl_lux_scale_value_label(double lx, char *buf, size_t size);

/* The 1-2-5 value of step k (clamped to the step limits). */
cdl_illuminance cdl_lux_scale_step_value(int step);

/* The largest step whose value is <= E, and the smallest whose value is >= E
 * (E > 0; clamped to the step limits). */
int cdl_lux_scale_step_at_or_below(cdl_illuminance E);
int cdl_lux_scale_step_at_or_above(cdl_illuminance E);

/* The scale for `count` illuminances in lux (finite values):
 *   hi = the smallest 1-2-5 value >= the largest E;
 *   lo = the largest 1-2-5 value <= the smallest positive E, but no more than
 *        CDL_LUX_SCALE_MAX_STEPS steps below hi;
 *   when lo = hi (constant data on a round value) the range opens one step
 *   each way (500 lx -> 200 .. 1000 lx);
 *   with no positive value (all zero, or empty) it is 1 .. 10 lx. */
cdl_lux_scale cdl_lux_scale_for_values(const double *E_lx, size_t count);

/* Position of E on the scale in [0, 1]: log(E / lo) / log(hi / lo), or
 * (E - lo) / (hi - lo) on a linear scale, clamped; 0 for E <= lo
 * (including zero and negative values). */
double cdl_lux_scale_position(const cdl_lux_scale *scale, cdl_illuminance E);

/* The legend label of step k: "500 lx", "0.05 lx", "20k lx" (k = thousands,
 * for 10 000 lx and up). Digits, '.', 'k', ' ', 'l', 'x' only. Written into
 * buf (truncated to size - 1 characters); returns the full length. */
size_t cdl_lux_scale_step_label(int step, char *buf, size_t size);

#endif
