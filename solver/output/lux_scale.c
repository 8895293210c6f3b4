/* lux_scale.c - 1-2-5 steps and the log position of an illuminance. */
#include "solver/output/lux_scale.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort_doubles.h"

static const int step_mantissa[3] = {1, 2, 5};

static int clamp_step(int k)
{
    return k < CDL_LUX_SCALE_MIN_STEP ? CDL_LUX_SCALE_MIN_STEP : k > CDL_LUX_SCALE_MAX_STEP ? CDL_LUX_SCALE_MAX_STEP : k;
}

/* k = 3 e + i with i in {0, 1, 2}: floor division, also for negative k. */
static void split_step(int k, int *mantissa, int *exponent)
{
    int e = k >= 0 ? k / 3 : -((-k + 2) / 3);
    *exponent = e;
    *mantissa = step_mantissa[k - 3 * e];
}

cdl_illuminance cdl_lux_scale_step_value(int step)
{
    int m, e;
    split_step(clamp_step(step), &m, &e);
    /* 10^|e| is exact in double for |e| <= 22, so one rounding happens: the
     * result is the double nearest the decimal value. */
    return cdl_lux(e >= 0 ? m * pow(10.0, e) : m / pow(10.0, -e));
}

int cdl_lux_scale_step_at_or_below(cdl_illuminance E)
{
    if (!(E.lx > 0.0)) return CDL_LUX_SCALE_MIN_STEP;
    if (E.lx >= cdl_lux_scale_step_value(CDL_LUX_SCALE_MAX_STEP).lx) return CDL_LUX_SCALE_MAX_STEP;
    double d = floor(log10(E.lx)); /* decade; in [-324, 309) for a positive finite double */
    int k = clamp_step(3 * (int)d);
    /* log10 may be off by one near powers of ten: walk to the exact answer. */
    while (k > CDL_LUX_SCALE_MIN_STEP && cdl_lux_scale_step_value(k).lx > E.lx) --k;
    while (k < CDL_LUX_SCALE_MAX_STEP && cdl_lux_scale_step_value(k + 1).lx <= E.lx) ++k;
    return k;
}

int cdl_lux_scale_step_at_or_above(cdl_illuminance E)
{
    int k = cdl_lux_scale_step_at_or_below(E);
    if (k < CDL_LUX_SCALE_MAX_STEP && cdl_lux_scale_step_value(k).lx < E.lx) ++k;
    return k;
}

static cdl_lux_scale make_scale(int lo_step, int hi_step)
{
    cdl_lux_scale s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_LUX_SCALE_LOG;
    s.lo_step = lo_step;
    s.hi_step = hi_step;
    s.lo = cdl_lux_scale_step_value(lo_step);
    s.hi = cdl_lux_scale_step_value(hi_step);
    return s;
}

cdl_lux_scale cdl_lux_scale_for_values(const double *E_lx, size_t count)
{
    double max = 0.0, min_positive = INFINITY;
    for (size_t i = 0; i < count; ++i) {
        double e = E_lx[i];
        if (!(e > 0.0) || !isfinite(e)) continue;
        if (e > max) max = e;
        if (e < min_positive) min_positive = e;
    }
    if (!(max > 0.0)) return make_scale(0, 3); /* 1 .. 10 lx */

    int hi = cdl_lux_scale_step_at_or_above(cdl_lux(max));
    int lo = cdl_lux_scale_step_at_or_below(cdl_lux(min_positive));
    if (lo >= hi) {
        lo = hi - 1;
        hi = hi + 1;
    }
    if (hi - lo > CDL_LUX_SCALE_MAX_STEPS) lo = hi - CDL_LUX_SCALE_MAX_STEPS;
    if (hi > CDL_LUX_SCALE_MAX_STEP) {
        lo -= hi - CDL_LUX_SCALE_MAX_STEP;
        hi = CDL_LUX_SCALE_MAX_STEP;
    }
    if (lo < CDL_LUX_SCALE_MIN_STEP) {
        hi += CDL_LUX_SCALE_MIN_STEP - lo;
        lo = CDL_LUX_SCALE_MIN_STEP;
    }
    return make_scale(lo, hi);
}

cdl_lux_scale cdl_lux_scale_linear_for_values(const double *E_lx, size_t count)
{
    cdl_lux_scale s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_LUX_SCALE_LINEAR;
    double *sorted = malloc((count ? count : 1) * sizeof *sorted);
    size_t n = 0;
    for (size_t i = 0; sorted && i < count; ++i)
        if (isfinite(E_lx[i])) sorted[n++] = E_lx[i];
    double max = 0.0, low = 0.0;
    if (n > 0) {
        cdl_sort_doubles(sorted, n);
        max = sorted[n - 1];
        /* The 2nd percentile, leaving out at least the darkest point of a
         * grid of ten or more: one dark corner must not set the scale. */
        size_t k = n >= 10 ? (size_t)fmax(1.0, floor(0.02 * (double)n)) : 0;
        low = sorted[k];
    }
    free(sorted);
    if (!(max > 0.0)) {
        s.lo = cdl_lux(0.0);
        s.hi = cdl_lux(10.0);
        s.tick_lx = 2.0;
        return s;
    }
    double lo = low >= 0.5 * max ? low : 0.0;
    /* About six intervals of a 1-2-5 step. */
    double raw = (max - lo) / 6.0;
    if (!(raw > 0.0)) raw = max / 6.0;
    double tick = cdl_lux_scale_step_value(cdl_lux_scale_step_at_or_above(cdl_lux(raw))).lx;
    s.tick_lx = tick;
    s.lo = cdl_lux(floor(lo / tick) * tick);
    double hi = ceil(max / tick) * tick;
    if (!(hi > s.lo.lx)) hi = s.lo.lx + tick;
    s.hi = cdl_lux(hi);
    for (size_t i = 0; i < count; ++i)
        if (E_lx[i] < s.lo.lx) s.clipped = 1;
    return s;
}

size_t cdl_lux_scale_value_label(double lx, char *buf, size_t size)
{
    /* Six digits: multiples of a 1-2-5 tick print without binary noise. */
    int n = fabs(lx) >= 10000.0 ? snprintf(buf, size, "%.6gk lx", lx / 1000.0) : snprintf(buf, size, "%.6g lx", lx);
    return n > 0 ? (size_t)n : 0;
}

double cdl_lux_scale_position(const cdl_lux_scale *scale, cdl_illuminance E)
{
    if (!(E.lx > scale->lo.lx)) return 0.0;
    if (E.lx >= scale->hi.lx) return 1.0;
    if (scale->kind == CDL_LUX_SCALE_LINEAR) {
        /* Linear map: equal differences of illuminance take equal distances. */
        double t = (E.lx - scale->lo.lx) / (scale->hi.lx - scale->lo.lx);
        return t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    }
    /* Logarithmic map: equal ratios of illuminance take equal distances. */
    double t = log(E.lx / scale->lo.lx) / log(scale->hi.lx / scale->lo.lx);
    return t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
}

/* Append c to buf at position *n (counting characters that do not fit). */
static void put_char(char *buf, size_t size, size_t *n, char c)
{
    if (*n + 1 < size) buf[*n] = c;
    ++*n;
}

size_t cdl_lux_scale_step_label(int step, char *buf, size_t size)
{
    int m, e;
    split_step(clamp_step(step), &m, &e);
    size_t n = 0;
    /* Built from the digits, not printed from the double: the label is the
     * exact decimal of the step whatever the binary value. */
    if (e < 0) {
        put_char(buf, size, &n, '0');
        put_char(buf, size, &n, '.');
        for (int i = 0; i < -e - 1; ++i) put_char(buf, size, &n, '0');
        put_char(buf, size, &n, (char)('0' + m));
    } else {
        int zeros = e >= 4 ? e - 3 : e;
        put_char(buf, size, &n, (char)('0' + m));
        for (int i = 0; i < zeros; ++i) put_char(buf, size, &n, '0');
        if (e >= 4) put_char(buf, size, &n, 'k');
    }
    put_char(buf, size, &n, ' ');
    put_char(buf, size, &n, 'l');
    put_char(buf, size, &n, 'x');
    if (size > 0) buf[n < size ? n : size - 1] = '\0';
    return n;
}

typedef struct weighted {
    double E, area;
} weighted;

static int compare_weighted(const void *a, const void *b)
{
    double x = ((const weighted *)a)->E, y = ((const weighted *)b)->E;
    return (x > y) - (x < y);
}

cdl_lux_scale cdl_lux_scale_linear_for_areas(const double *E_lx, const double *area, size_t count)
{
    weighted *w = malloc((count ? count : 1) * sizeof *w);
    double *clamped = calloc(count ? count : 1, sizeof *clamped);
    if (!w || !clamped) {
        free(w);
        free(clamped);
        return cdl_lux_scale_linear_for_values(E_lx, count);
    }
    size_t n = 0;
    double total = 0.0;
    for (size_t i = 0; i < count; ++i)
        if (isfinite(E_lx[i]) && area[i] > 0.0) {
            w[n++] = (weighted){E_lx[i], area[i]};
            total += area[i];
        }
    qsort(w, n, sizeof *w, compare_weighted);
    double top = n ? w[n - 1].E : 0.0, below = 0.0;
    for (size_t i = 0; i < n; ++i) {
        below += w[i].area;
        if (below >= 0.99 * total) {
            top = w[i].E;
            break;
        }
    }
    for (size_t i = 0; i < count; ++i) clamped[i] = isfinite(E_lx[i]) && E_lx[i] > top && top > 0.0 ? top : E_lx[i];
    cdl_lux_scale s = cdl_lux_scale_linear_for_values(clamped, count);
    for (size_t i = 0; i < count; ++i)
        if (E_lx[i] > s.hi.lx) s.clipped_top = 1;
    free(w);
    free(clamped);
    return s;
}
