/* The summary table's numbers and verdicts: each value printed to the
 * decade of its own stated uncertainty (report_numbers.h), exact values to
 * 4 significant digits, and requirements checked with their margins, "within
 * the stated error" when a margin is smaller than the value's uncertainty.
 * Expected strings are worked out by hand from the rules in the headers. */
#include <string.h>

#include "check.h"
#include "report/report_numbers.h"
#include "report/summary_table.h"

static void check_format(double value, double u, const char *expected)
{
    char buf[64];
    cdl_report_format(buf, sizeof buf, value, u);
    CHECK_MSG(strcmp(buf, expected) == 0, "%.17g with uncertainty %g: \"%s\", expected \"%s\"", value, u, buf,
              expected);
}

int main(void)
{
    /* u = 3.7 lx: units are the last meaningful digit. */
    check_format(492.3059, 3.7, "492");
    /* u = 0.37 lx: one decimal. */
    check_format(492.3059, 0.37, "492.3");
    /* u = 0.008: three decimals of a uniformity. */
    check_format(0.53688, 0.008, "0.537");
    /* u = 37 lx: never rounded to tens (0 decimals at least). */
    check_format(492.3059, 37.0, "492");
    /* exact (u = 0): 4 significant digits. */
    check_format(161.90753957975289, 0.0, "161.9");
    check_format(0.58668252240317165, 0.0, "0.5867");
    /* a tiny uncertainty: at most 6 significant digits. */
    check_format(492.3059123, 1e-9, "492.306");

    cdl_grid_spec spec = {0};
    spec.name = "desk";
    spec.kind = CDL_GRID_RECT;
    cdl_report_grid g = {0};
    g.spec = &spec;
    g.count = 32;
    g.spacing_m = 0.5;
    g.Em = 512.34;
    g.Emin = 300.0;
    g.Emax = 700.0;
    g.U0 = 300.0 / 512.34;
    g.Ud = 300.0 / 700.0;
    g.stderr_mean_rel = 0.004; /* u(Em) = 2.05 lx */
    g.stderr_max_rel = 0.01;   /* u(U0) = 0.586 x 0.014 = 0.0082 */
    cdl_report_row row;
    cdl_report_row_of(&g, &row);
    CHECK(strcmp(row.Em, "512") == 0);
    CHECK(strcmp(row.Emin, "300") == 0 && strcmp(row.Emax, "700") == 0);
    CHECK_MSG(strcmp(row.U0, "0.586") == 0, "U0 %s", row.U0);
    CHECK(!row.has_requirements);

    /* Passing by 2.5 %: Em 512.34 against 500 lx, U0 0.586 against 0.4. */
    g.required_Em_lx = 500.0;
    g.required_U0 = 0.4;
    cdl_report_row_of(&g, &row);
    CHECK(row.has_requirements && row.pass);
    CHECK_MSG(strcmp(row.verdict, "pass: Em +2.5 %, U0 +0.186") == 0, "%s", row.verdict);
    CHECK_MSG(strcmp(row.requirements, "Em >= 500 lx, U0 >= 0.4") == 0, "%s", row.requirements);

    /* Failing U0 by 0.014: 0.586 against 0.6. */
    g.required_U0 = 0.6;
    cdl_report_row_of(&g, &row);
    CHECK(!row.pass);
    CHECK_MSG(strcmp(row.verdict, "FAIL: Em +2.5 %, U0 -0.014") == 0, "%s", row.verdict);

    /* Em 1 lx under 513.34 lx, with u(Em) = 2.05 lx: a fail within the stated error. */
    g.required_Em_lx = 513.34;
    g.required_U0 = 0.0;
    cdl_report_row_of(&g, &row);
    CHECK(!row.pass);
    CHECK_MSG(strcmp(row.verdict, "FAIL: Em -0.2 % (within the stated error)") == 0, "%s", row.verdict);
    CHECK_MSG(strcmp(row.requirements, "Em >= 513.34 lx") == 0, "%s", row.requirements);

    /* With the points known, Emin and Emax carry their own points' errors
     * and U0 the darkest point's: a point beside a hard shadow edge stating
     * 13 times its value (a surface map's vertex) no longer blurs U0 to "0".
     * Darkest point 23.24 +- 4.0 lx (17.2 %), Em 102 +- 0.4 lx: u(U0) =
     * 0.2278 x (0.172 + 0.004) = 0.040, two decimals. */
    double E[4] = {23.24, 82.6, 102.0, 200.0}, E_stderr[4] = {4.0, 1074.0, 0.4, 2.0};
    cdl_report_grid m = {0};
    m.spec = &spec;
    m.count = 4;
    m.Em = 102.0;
    m.Emin = 23.24;
    m.Emax = 200.0;
    m.U0 = 23.24 / 102.0;
    m.Ud = 23.24 / 200.0;
    m.stderr_mean_rel = 0.004;
    m.stderr_max_rel = 13.0;
    m.E = E;
    m.E_stderr = E_stderr;
    m.min_index = 0;
    m.max_index = 3;
    m.required_U0 = 0.1;
    cdl_report_row_of(&m, &row);
    CHECK_MSG(strcmp(row.U0, "0.23") == 0, "U0 %s, expected 0.23", row.U0);
    CHECK_MSG(strcmp(row.Emin, "23") == 0 && strcmp(row.Emax, "200") == 0, "Emin %s Emax %s", row.Emin, row.Emax);
    CHECK_MSG(strcmp(row.verdict, "pass: U0 +0.13") == 0, "%s", row.verdict);
    /* Without the points, the worst relative error stands for Emin's. */
    m.E = m.E_stderr = NULL;
    cdl_report_row_of(&m, &row);
    CHECK_MSG(strcmp(row.U0, "0") == 0, "U0 %s without the points", row.U0);
    return check_finish();
}
