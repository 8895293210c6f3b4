/* The annual metrics' definitions (daylight/annual_metrics.h) on hand-made
 * hourly data whose counts are known in closed form:
 *  - 20 hours, the even ones occupied (10), three points: one at 50 lx
 *    always (DA 0, UDI fell short 100 %); one at 100 h lx in hour h (the
 *    occupied values 0, 200, ..., 1800: DA300 8/10, fell short 1/10 (only 0
 *    is below 100), useful 9/10); one at exactly 300 lx in the occupied
 *    hours but the last, where it is exactly 3000 (both thresholds met
 *    as written: DA 100 %, UDI 100 %), and 3000.5 lx in the unoccupied
 *    ones (which do not count);
 *  - sDA with weights 1, 2, 1: the second and third points pass (DA >= 50 %),
 *    3 of 4 = 75 %; the UDI means weighted likewise;
 *  - ASE: 600 hours all occupied, direct sun of exactly 1000 lx at point 0
 *    for 251 hours (more than 250: counted), at point 1 for 250 (not), so
 *    ASE1000,250h is point 0's share;
 *  - EN 17037: four points over six daylight hours with known shares above
 *    each level's thresholds, the hours that count and the level met;
 *  - the daylight hours: the half with the greatest diffuse illuminance,
 *    ties to the earlier hour;
 *  - no occupied hour, no daylight hour: refused.
 */
#include <string.h>

#include "check.h"
#include "daylight/annual_metrics.h"

static void test_da_udi(void)
{
    enum { H = 20, N = 3 };
    float E[H * N];
    unsigned char occ[H], day[H];
    for (int h = 0; h < H; ++h) {
        occ[h] = h % 2 == 0;
        day[h] = 1;
        E[h * N + 0] = 50.0f;
        E[h * N + 1] = 100.0f * h;
        E[h * N + 2] = occ[h] ? (h == 18 ? 3000.0f : 300.0f) : 3000.5f;
    }
    double w[N] = {1.0, 2.0, 1.0};
    cdl_annual_input in = {H, N, E, NULL, NULL, occ, day, w};
    cdl_point_metrics m[N];
    cdl_grid_annual_metrics g;
    cdl_error err;
    CHECK_OK(cdl_annual_metrics_compute(&in, m, &g, &err), &err);
    CHECK(g.occupied_hours == 10 && g.daylight_hours == 20);
    CHECK(m[0].DA300 == 0.0 && m[0].UDI_fell_short == 100.0 && m[0].UDI == 0.0 && m[0].UDI_exceeded == 0.0);
    CHECK(m[1].DA300 == 80.0 && m[1].UDI_fell_short == 10.0 && m[1].UDI == 90.0 && m[1].UDI_exceeded == 0.0);
    CHECK(m[2].DA300 == 100.0 && m[2].UDI == 100.0 && m[2].UDI_exceeded == 0.0);
    CHECK(m[0].ASE_hours == 0.0);
    /* exact sums of quarters */
    CHECK_ABS(g.sDA300, 75.0, 1e-12);
    CHECK_ABS(g.UDI_fell_short, (100.0 + 2.0 * 10.0) / 4.0, 1e-12);
    CHECK_ABS(g.UDI, (0.0 + 2.0 * 90.0 + 100.0) / 4.0, 1e-12);
    CHECK_ABS(g.DA300_mean, (0.0 + 2.0 * 80.0 + 100.0) / 4.0, 1e-12);
    /* EN 17037 per point: all 20 hours are daylight hours; point 1 has
     * 100 h >= 300 for h >= 3: 17 of 20 */
    CHECK_ABS(m[1].EN17037_target, 85.0, 1e-12);

    /* the same year kept as rows of the even hours only, the odd ones dark
     * (row -1): as the full table with the odd hours at 0 lx */
    float rows[10 * N], full[H * N];
    int row_of[H];
    for (int h = 0; h < H; ++h) {
        row_of[h] = h % 2 ? -1 : h / 2;
        for (int i = 0; i < N; ++i) {
            full[h * N + i] = h % 2 ? 0.0f : E[h * N + i];
            if (h % 2 == 0) rows[(h / 2) * N + i] = E[h * N + i];
        }
    }
    cdl_point_metrics a[N], b[N];
    cdl_grid_annual_metrics ga, gb;
    cdl_annual_input compact = {H, N, rows, NULL, row_of, occ, day, w}, plain = {H, N, full, NULL, NULL, occ, day, w};
    CHECK_OK(cdl_annual_metrics_compute(&compact, a, &ga, &err), &err);
    CHECK_OK(cdl_annual_metrics_compute(&plain, b, &gb, &err), &err);
    CHECK(memcmp(a, b, sizeof a) == 0 && ga.sDA300 == gb.sDA300 && ga.UDI == gb.UDI);
    CHECK_ABS(a[1].EN17037_target, 40.0, 1e-12); /* the even hours from 4 on: 8 of 20 */
}

static void test_ase(void)
{
    enum { H = 600, N = 2 };
    static float E[H * N], S[H * N];
    unsigned char occ[H], day[H];
    for (int h = 0; h < H; ++h) {
        occ[h] = day[h] = 1;
        E[h * N] = E[h * N + 1] = 2000.0f;
        S[h * N + 0] = h < 251 ? 1000.0f : 999.9f;
        S[h * N + 1] = h < 250 ? 5000.0f : 0.0f;
    }
    cdl_annual_input in = {H, N, E, S, NULL, occ, day, NULL};
    cdl_point_metrics m[N];
    cdl_grid_annual_metrics g;
    cdl_error err;
    CHECK_OK(cdl_annual_metrics_compute(&in, m, &g, &err), &err);
    CHECK(m[0].ASE_hours == 251.0 && m[1].ASE_hours == 250.0);
    CHECK_ABS(g.ASE1000, 50.0, 1e-12);
    /* unoccupied hours do not count */
    for (int h = 0; h < 10; ++h) occ[h] = 0;
    CHECK_OK(cdl_annual_metrics_compute(&in, m, &g, &err), &err);
    CHECK(m[0].ASE_hours == 241.0 && g.ASE1000 == 0.0);
}

static void test_en17037(void)
{
    /* 4 points, 6 daylight hours (and 2 others that must not count) */
    enum { H = 8, N = 4 };
    static const float rows[H][N] = {
        {800, 800, 600, 120},  /* >=750: 2 (50 %): high target; >=500 3 (75 %) < 95 %: no high minimum;
                                  >=300 3 < 95 %: no medium minimum; >=100 4: minimum minimum */
        {800, 800, 800, 800},  /* every threshold */
        {310, 310, 310, 90},   /* >=300: 75 %: minimum target; >=100 75 % < 95 %: no minimum minimum */
        {310, 310, 90, 90},    /* >=300 50 %: minimum target; nothing else */
        {600, 600, 600, 600},  /* >=500 all: medium target and minimum, high minimum; not high target */
        {50, 50, 50, 50},      /* nothing */
        {5000, 5000, 5000, 5000}, /* not a daylight hour */
        {0, 0, 0, 0}};            /* not a daylight hour */
    float E[H * N];
    unsigned char occ[H], day[H];
    for (int h = 0; h < H; ++h) {
        occ[h] = 1;
        day[h] = h < 6;
        for (int i = 0; i < N; ++i) E[h * N + i] = rows[h][i];
    }
    cdl_annual_input in = {H, N, E, NULL, NULL, occ, day, NULL};
    cdl_point_metrics m[N];
    cdl_grid_annual_metrics g;
    cdl_error err;
    CHECK_OK(cdl_annual_metrics_compute(&in, m, &g, &err), &err);
    CHECK(g.daylight_hours == 6);
    /* minimum (300 / 100): target counts in hours 0, 1, 2, 3, 4 (5 of 6);
     * minimum (>= 100 over 95 %) in 0, 1, 4 (3 of 6): both >= 50 %: met */
    CHECK_ABS(g.en_target_hours[0], 500.0 / 6.0, 1e-12);
    CHECK_ABS(g.en_minimum_hours[0], 50.0, 1e-12);
    CHECK(g.en_met[0]);
    /* medium (500 / 300): target in 0, 1, 4 (3); minimum (>= 300 over 95 %) in 1, 4 (2): not met */
    CHECK_ABS(g.en_target_hours[1], 50.0, 1e-12);
    CHECK_ABS(g.en_minimum_hours[1], 200.0 / 6.0, 1e-12);
    CHECK(!g.en_met[1]);
    /* high (750 / 500): target in 0, 1 (2); minimum (>= 500 over 95 %) in 1, 4 (2) */
    CHECK_ABS(g.en_target_hours[2], 200.0 / 6.0, 1e-12);
    CHECK_ABS(g.en_minimum_hours[2], 200.0 / 6.0, 1e-12);
    CHECK(!g.en_met[2]);
    CHECK(strcmp(g.en_level, "minimum") == 0);
    /* per point: point 3's hours >= 300 among the daylight ones: 1, 4 */
    CHECK_ABS(m[3].EN17037_target, 200.0 / 6.0, 1e-12);
}

static void test_daylight_hours(void)
{
    const double diffuse[9] = {0, 500, 200, 500, 900, 0, 200, 100, 50};
    unsigned char day[9];
    cdl_error err;
    CHECK_OK(cdl_annual_daylight_hours(diffuse, 9, day, &err), &err);
    /* 4 of 9: 900 (4), 500 (1), 500 (3), then 200: the earlier, hour 2 */
    const unsigned char want[9] = {0, 1, 1, 1, 1, 0, 0, 0, 0};
    CHECK(memcmp(day, want, sizeof want) == 0);
}

static void test_refused(void)
{
    float E[2] = {1.0f, 2.0f};
    unsigned char none[2] = {0, 0}, all[2] = {1, 1};
    cdl_point_metrics m[1];
    cdl_grid_annual_metrics g;
    cdl_error err;
    cdl_annual_input in = {2, 1, E, NULL, NULL, none, all, NULL};
    CHECK(cdl_annual_metrics_compute(&in, m, &g, &err) == CDL_ERR_INPUT && strstr(err.message, "occupied hour"));
    in.occupied = all;
    in.daylight = none;
    CHECK(cdl_annual_metrics_compute(&in, m, &g, &err) == CDL_ERR_INPUT && strstr(err.message, "daylight hour"));
}

int main(void)
{
    test_da_udi();
    test_ase();
    test_en17037();
    test_daylight_hours();
    test_refused();
    return check_finish();
}
