/* Grid statistics against hand computations. */
#include "check.h"
#include "grid_result_fixture.h"

int main(void)
{
    fixture f;
    cdl_grid_stats s;

    /* Three points, the third standing for twice the area:
     * Em = (100 x 1 + 200 x 1 + 400 x 2) / 4 = 275 lx, Emin 100, Emax 400,
     * U0 = 100 / 275 = 4/11, Ud = 100 / 400 = 0.25. Every step is exact or
     * one rounding in double, so 1e-15 relative is a few ulps. */
    CHECK(fixture_rect(&f, 3, 1, 3.0, 1.0, 0.8));
    f.E[0] = 100.0;
    f.E[1] = 200.0;
    f.E[2] = 400.0;
    f.grid.weights[0] = 1.0;
    f.grid.weights[1] = 1.0;
    f.grid.weights[2] = 2.0;
    cdl_grid_result_stats(&f.result, &s);
    CHECK(s.count == 3);
    CHECK_REL(s.E_avg_lx, 275.0, 1e-15);
    CHECK(s.E_min_lx == 100.0 && s.E_max_lx == 400.0);
    CHECK_REL(s.U0, 4.0 / 11.0, 1e-15);
    CHECK_REL(s.Ud, 0.25, 1e-15);

    /* Equal weights: the weighted mean is the plain mean, (100+200+400)/3. */
    for (int i = 0; i < 3; ++i) f.grid.weights[i] = 0.25;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, 700.0 / 3.0, 1e-15);
    CHECK_REL(s.U0, 300.0 / 700.0, 1e-15);

    /* No weights at all (NULL, or all zero): the plain mean. */
    double *w = f.grid.weights;
    f.grid.weights = NULL;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, 700.0 / 3.0, 1e-15);
    f.grid.weights = w;
    for (int i = 0; i < 3; ++i) f.grid.weights[i] = 0.0;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, 700.0 / 3.0, 1e-15);

    /* A dark grid: all zero, U0 and Ud defined as 0 (not 0/0). */
    for (int i = 0; i < 3; ++i) {
        f.E[i] = 0.0;
        f.grid.weights[i] = 1.0;
    }
    cdl_grid_result_stats(&f.result, &s);
    CHECK(s.count == 3 && s.E_avg_lx == 0.0 && s.E_min_lx == 0.0 && s.E_max_lx == 0.0);
    CHECK(s.U0 == 0.0 && s.Ud == 0.0);

    /* A shadowed point: Emin = 0 makes U0 = Ud = 0 while Em > 0. */
    f.E[1] = 300.0;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, 100.0, 1e-15);
    CHECK(s.U0 == 0.0 && s.Ud == 0.0 && s.E_max_lx == 300.0);
    fixture_free(&f);

    /* A uniform 9 x 9 grid: U0 = Ud = 1 exactly. */
    CHECK(fixture_rect(&f, 9, 9, 3.2, 3.2, 0.8));
    for (size_t i = 0; i < f.grid.count; ++i) f.E[i] = 512.5;
    cdl_grid_result_stats(&f.result, &s);
    CHECK(s.count == 81);
    /* 81 equal weights (3.2/9)^2 each: the compensated sums give the mean to
     * an ulp or two. */
    CHECK_REL(s.E_avg_lx, 512.5, 4e-16);
    CHECK_REL(s.U0, 1.0, 4e-16);
    CHECK(s.Ud == 1.0);

    /* A linear ramp E = 100 + 10 k over k = 0 .. 80 with equal weights: the
     * mean is the midpoint 500; Emin 100, Emax 900. */
    for (size_t k = 0; k < f.grid.count; ++k) f.E[k] = 100.0 + 10.0 * (double)k;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, 500.0, 1e-15);
    CHECK_REL(s.U0, 0.2, 1e-15);
    CHECK_REL(s.Ud, 100.0 / 900.0, 1e-15);
    fixture_free(&f);

    /* Compensated summation: one heavy point and many light ones. 1e6 points
     * of 1 lx and one of 1e16 lx, equal weights w ~ 1e-6: the exact mean is
     * (1e16 + 1e6) / (1e6 + 1). In a naive running sum of w E each small term
     * (~1e-6) is rounded against a total of ~1e10 whose ulp is ~2e-6: the
     * mean comes out 9999990001.69 instead of 9999990001.01, a relative error
     * of 7e-11 (computed in Python with the same order of additions). The
     * compensated sum keeps it to a few ulps; 1e-14 separates the two. */
    CHECK(fixture_rect(&f, 1000001, 1, 1.0, 1.0, 0.0));
    f.E[0] = 1e16;
    for (size_t i = 1; i < f.grid.count; ++i) f.E[i] = 1.0;
    cdl_grid_result_stats(&f.result, &s);
    CHECK_REL(s.E_avg_lx, (1e16 + 1e6) / (1e6 + 1.0), 1e-14);
    fixture_free(&f);

    /* An empty grid: all zero, no crash. */
    CHECK(fixture_rect(&f, 0, 0, 1.0, 1.0, 0.0));
    cdl_grid_result_stats(&f.result, &s);
    CHECK(s.count == 0 && s.E_avg_lx == 0.0 && s.U0 == 0.0 && s.Ud == 0.0);
    fixture_free(&f);
    return check_finish();
}
