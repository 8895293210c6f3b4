/* The 1-2-5 lux scale of false-colour maps: steps, ranges chosen from data,
 * log positions and legend labels, against hand-worked values. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/output/lux_scale.h"

static cdl_lux_scale scale_of(const double *E, size_t n)
{
    return cdl_lux_scale_for_values(E, n);
}

static int label_is(int step, const char *expected)
{
    char buf[64];
    size_t n = cdl_lux_scale_step_label(step, buf, sizeof buf);
    return n == strlen(expected) && strcmp(buf, expected) == 0;
}

/* The linear scale: from 0 for a grid with dark parts; from its 2nd
 * percentile, rounded down to the tick, where nearly all of it is bright,
 * whatever a single dark point says; ticks a 1-2-5 step for about six
 * intervals; all dark: 0 .. 10 lx. */
static void test_linear(void)
{
    double E[100];
    for (int i = 0; i < 100; ++i) E[i] = 30.0 + 7.5 * i; /* 30 .. 772.5 lx */
    cdl_lux_scale s = cdl_lux_scale_linear_for_values(E, 100);
    /* 2nd percentile 45 lx < half of 772.5: from 0; (772.5 - 0) / 6 = 129 -> step 200; top 800. */
    CHECK(s.kind == CDL_LUX_SCALE_LINEAR && s.lo.lx == 0.0 && s.tick_lx == 200.0 && s.hi.lx == 800.0 && !s.clipped);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(400.0)) == 0.5);
    for (int i = 0; i < 100; ++i) E[i] = 480.0 + 0.4 * i; /* 480 .. 519.6 */
    E[37] = 0.0;
    s = cdl_lux_scale_linear_for_values(E, 100);
    /* the 2nd point up is 480.4 (the dark one left out): (519.6 - 480.4) / 6 = 6.5 -> step 10; 480 .. 520 */
    CHECK_MSG(s.lo.lx == 480.0 && s.hi.lx == 520.0 && s.tick_lx == 10.0 && s.clipped, "%g .. %g by %g", s.lo.lx,
              s.hi.lx, s.tick_lx);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(0.0)) == 0.0);
    double dark[3] = {0, 0, 0};
    s = cdl_lux_scale_linear_for_values(dark, 3);
    CHECK(s.lo.lx == 0.0 && s.hi.lx == 10.0);
    char label[32];
    cdl_lux_scale_value_label(0.6000000000000001, label, sizeof label);
    CHECK(strcmp(label, "0.6 lx") == 0);
    cdl_lux_scale_value_label(12500.0, label, sizeof label);
    CHECK(strcmp(label, "12.5k lx") == 0);
}

int main(void)
{
    test_linear();
    /* Step values are the doubles nearest the decimal values, exactly as literals. */
    CHECK(cdl_lux_scale_step_value(0).lx == 1.0);
    CHECK(cdl_lux_scale_step_value(1).lx == 2.0);
    CHECK(cdl_lux_scale_step_value(2).lx == 5.0);
    CHECK(cdl_lux_scale_step_value(8).lx == 500.0);
    CHECK(cdl_lux_scale_step_value(12).lx == 10000.0);
    CHECK(cdl_lux_scale_step_value(-1).lx == 0.5);
    CHECK(cdl_lux_scale_step_value(-2).lx == 0.2);
    CHECK(cdl_lux_scale_step_value(-3).lx == 0.1);
    CHECK(cdl_lux_scale_step_value(-7).lx == 0.005);
    CHECK(cdl_lux_scale_step_value(-9).lx == 0.001);

    /* Bracketing steps, including values that are steps themselves and the
     * awkward 0.3 (= 0.1 + 0.2 is not 0.3 in double, but both lie in (0.2, 0.5)). */
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(500.0)) == 8);
    CHECK(cdl_lux_scale_step_at_or_above(cdl_lux(500.0)) == 8);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(499.999)) == 7);
    CHECK(cdl_lux_scale_step_at_or_above(cdl_lux(500.001)) == 9);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(1000.0)) == 9);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(999.9999999)) == 8);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(0.1)) == -3);
    CHECK(cdl_lux_scale_step_at_or_above(cdl_lux(0.1)) == -3);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(0.1 + 0.2)) == -2);
    CHECK(cdl_lux_scale_step_at_or_above(cdl_lux(0.3)) == -1);
    /* Beyond the limits: clamped. */
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(1e-300)) == CDL_LUX_SCALE_MIN_STEP);
    CHECK(cdl_lux_scale_step_at_or_above(cdl_lux(1e300)) == CDL_LUX_SCALE_MAX_STEP);
    CHECK(cdl_lux_scale_step_at_or_below(cdl_lux(0.0)) == CDL_LUX_SCALE_MIN_STEP);

    /* Ranges chosen from data, worked by hand. */
    const double a[] = {300, 400, 350};
    cdl_lux_scale s = scale_of(a, 3);
    CHECK(s.lo.lx == 200.0 && s.hi.lx == 500.0 && s.lo_step == 7 && s.hi_step == 8);
    const double b[] = {500};
    s = scale_of(b, 1); /* a round constant opens one step each way */
    CHECK(s.lo.lx == 200.0 && s.hi.lx == 1000.0);
    const double c[] = {0, 0, 0};
    s = scale_of(c, 3); /* nothing lit: 1 .. 10 lx */
    CHECK(s.lo.lx == 1.0 && s.hi.lx == 10.0);
    s = scale_of(NULL, 0);
    CHECK(s.lo.lx == 1.0 && s.hi.lx == 10.0);
    const double d[] = {0, 0.3, 7};
    s = scale_of(d, 3); /* zeros are ignored for the bottom end */
    CHECK(s.lo.lx == 0.2 && s.hi.lx == 10.0);
    const double e[] = {1e-9, 1000};
    s = scale_of(e, 2); /* at most four decades: 0.1 .. 1000 lx */
    CHECK(s.lo.lx == 0.1 && s.hi.lx == 1000.0 && s.hi_step - s.lo_step == CDL_LUX_SCALE_MAX_STEPS);
    const double f[] = {12345};
    s = scale_of(f, 1);
    CHECK(s.lo.lx == 10000.0 && s.hi.lx == 20000.0);
    const double g[] = {0.5};
    s = scale_of(g, 1);
    CHECK(s.lo.lx == 0.2 && s.hi.lx == 1.0);
    const double h[] = {-5, 80}; /* a negative value (not illuminance) does not set the bottom */
    s = scale_of(h, 2);
    CHECK(s.lo.lx == 50.0 && s.hi.lx == 100.0);
    const double sun[] = {1e30};
    s = scale_of(sun, 1); /* beyond 1e20 lx: the top step, still lo < hi */
    CHECK(s.hi_step == CDL_LUX_SCALE_MAX_STEP && s.lo_step < s.hi_step);

    /* Positions: log(E / lo) / log(hi / lo). On 10 .. 1000 lx, 100 lx is
     * halfway and 10^1.5 = 31.62 lx a quarter; one rounding in log and one
     * in the division, so 1e-15 absolute holds. */
    const double ten_to_thousand[] = {10, 1000};
    s = scale_of(ten_to_thousand, 2);
    CHECK(s.lo.lx == 10.0 && s.hi.lx == 1000.0);
    CHECK_ABS(cdl_lux_scale_position(&s, cdl_lux(100.0)), 0.5, 1e-15);
    CHECK_ABS(cdl_lux_scale_position(&s, cdl_lux(pow(10.0, 1.5))), 0.25, 1e-15);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(10.0)) == 0.0);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(1000.0)) == 1.0);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(5.0)) == 0.0);   /* below: clamped */
    CHECK(cdl_lux_scale_position(&s, cdl_lux(0.0)) == 0.0);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(-3.0)) == 0.0);
    CHECK(cdl_lux_scale_position(&s, cdl_lux(5000.0)) == 1.0); /* above: clamped */
    /* equal ratios, equal distances: 20 -> 40 lx as far as 200 -> 400 lx */
    double d1 = cdl_lux_scale_position(&s, cdl_lux(40.0)) - cdl_lux_scale_position(&s, cdl_lux(20.0));
    double d2 = cdl_lux_scale_position(&s, cdl_lux(400.0)) - cdl_lux_scale_position(&s, cdl_lux(200.0));
    CHECK_ABS(d1, d2, 1e-15);

    /* Labels: exact decimals built from digits. */
    CHECK(label_is(0, "1 lx"));
    CHECK(label_is(8, "500 lx"));
    CHECK(label_is(9, "1000 lx"));
    CHECK(label_is(11, "5000 lx"));
    CHECK(label_is(12, "10k lx"));
    CHECK(label_is(13, "20k lx"));
    CHECK(label_is(15, "100k lx"));
    CHECK(label_is(-1, "0.5 lx"));
    CHECK(label_is(-3, "0.1 lx"));
    CHECK(label_is(-4, "0.05 lx"));
    CHECK(label_is(-9, "0.001 lx"));
    /* Truncation keeps a terminated string and reports the full length. */
    char small[4];
    CHECK(cdl_lux_scale_step_label(8, small, sizeof small) == 6);
    CHECK(strcmp(small, "500") == 0);
    return check_finish();
}
