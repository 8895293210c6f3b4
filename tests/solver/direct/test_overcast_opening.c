/* The CIE standard overcast sky through a roof opening: a black room 12 x
 * 12 x 3 m whose flat roof has a 3 x 3 m square hole, floor points below
 * the hole and off to the side, at "draft", "normal" and "high" (and
 * "reference" with the route on), with the exact route off and on. The
 * sky's luminance varies with height, so one luminance times the visible
 * polygon does not hold. With the route off the hidden part is sampled
 * with shadow rays; with it on, the visible part the route finds (the
 * hole) is sampled itself, no shadow rays (solver/direct/sky_region.h).
 * The plan says which, and the route on gives the same bytes on 1 thread
 * and on 2: the pilots and stage of a point depend on neither.
 *
 * The exact answer, computed here from the CIE formula and nothing of the
 * solver's: seen from a floor point p (normal up) the hole, at height h
 * above it, is all the sky there is. A point q of the hole at distance r
 * from p lies at zenith angle theta with cos theta = h / r (the receiver's
 * cosine too), and its area dA subtends dw = (h / r) dA / r^2 (the hole's
 * normal is vertical). With the overcast sky's L = L_z (1 + 2 cos theta) /
 * 3 (Moon and Spencer 1942, the CIE standard overcast sky since 1955),
 *     E = int L cos theta dw = (L_z / 3) int_hole (h^2 / r^4 + 2 h^3 / r^5) dA,
 * an integrand smooth over the hole, integrated by composite Gauss-Legendre
 * rules (nodes found by Newton's method on the Legendre recurrence) with
 * the panels doubled until two results agree to 1e-13. Both terms also
 * have closed forms, which check the quadrature to 1e-12: the first is pi
 * times the parallel-rectangle configuration factor (exact_forms.h); the
 * second follows from int int dA / r^3 = (1 / h) atan(a b / (h R)) over
 * [0, a] x [0, b] (R^2 = a^2 + b^2 + h^2) by d/dh (r^-3) = -3 h r^-5:
 *     int int h^3 / r^5 dA = (1/3) [atan(a b / (h R))
 *                            + a b h (R^2 + h^2) / (R (h^2 R^2 + a^2 b^2))],
 * odd in a and in b (so any rectangle is a signed sum over its corners),
 * and 2 pi / 3 over the whole plane (int cos^2 dw over the hemisphere).
 *
 * The solver's E is tallied in its stated sigmas over the 25 points at the
 * qualities, each route on its own (calibration_check: about 68 % within
 * one sigma and 95 % within two, within four binomial sigmas; no bias; the
 * stated sigma within 1.5 times the target).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/direct/exact_forms.h"
#include "solver/solve_fixture.h"

#define ZENITH_L 6000.0
#define ROOF_H 3.0
#define HOLE_LO 4.5
#define HOLE_HI 7.5

enum { GL_N = 16 };

/* Gauss-Legendre nodes and weights on [-1, 1]: the roots of P_n by Newton's
 * method from Tricomi's first guess cos(pi (i + 3/4) / (n + 1/2)), P_n and
 * P_n' from the three-term recurrence (k + 1) P_k+1 = (2k + 1) x P_k - k
 * P_k-1; w = 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz and Stegun 25.4.29). */
static void gauss_legendre(double *x, double *w)
{
    for (int i = 0; i < GL_N; ++i) {
        double z = cos(CDL_PI * (i + 0.75) / (GL_N + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = z;
            for (int k = 1; k < GL_N; ++k) {
                double p2 = ((2.0 * k + 1.0) * z * p1 - k * p0) / (k + 1.0);
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (z * p1 - p0) / (z * z - 1.0);
            double step = p1 / dp;
            z -= step;
            if (fabs(step) < 1e-16) break;
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

/* int over [x1, x2] x [y1, y2] (offsets from the foot of p, at height h)
 * of h^2 / r^4 (term 0) or 2 h^3 / r^5 (term 1): m x m panels of the GL
 * rule. */
static double hole_integral(int term, double x1, double x2, double y1, double y2, double h, int m)
{
    double gx[GL_N], gw[GL_N], sum = 0.0;
    gauss_legendre(gx, gw);
    double dx = (x2 - x1) / m, dy = (y2 - y1) / m;
    for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b)
            for (int i = 0; i < GL_N; ++i)
                for (int j = 0; j < GL_N; ++j) {
                    double x = x1 + dx * (a + 0.5 + 0.5 * gx[i]), y = y1 + dy * (b + 0.5 + 0.5 * gx[j]);
                    double r2 = x * x + y * y + h * h, r = sqrt(r2);
                    double f = term == 0 ? h * h / (r2 * r2) : 2.0 * h * h * h / (r2 * r2 * r);
                    sum += f * gw[i] * gw[j] * 0.25 * dx * dy;
                }
    return sum;
}

/* The same, panels doubled until two results agree to 1e-13 relative. */
static double hole_integral_converged(int term, double x1, double x2, double y1, double y2, double h)
{
    double prev = hole_integral(term, x1, x2, y1, y2, h, 1);
    for (int m = 2; m <= 64; m *= 2) {
        double next = hole_integral(term, x1, x2, y1, y2, h, m);
        if (fabs(next - prev) <= 1e-13 * fabs(next)) return next;
        prev = next;
    }
    CHECK_MSG(0, "the quadrature did not converge (%.17g)", prev);
    return prev;
}

/* int int h^3 / r^5 over [0, a] x [0, b] (the closed form above). */
static double cubic_corner(double a, double b, double h)
{
    double R2 = a * a + b * b + h * h, R = sqrt(R2);
    return (atan(a * b / (h * R)) + a * b * h * (R2 + h * h) / (R * (h * h * R2 + a * a * b * b))) / 3.0;
}

/* E at floor point (px, py, 0) under the overcast sky through the hole. */
static double overcast_exact(double px, double py)
{
    double x1 = HOLE_LO - px, x2 = HOLE_HI - px, y1 = HOLE_LO - py, y2 = HOLE_HI - py, h = ROOF_H;
    double first = hole_integral_converged(0, x1, x2, y1, y2, h);
    double second = hole_integral_converged(1, x1, x2, y1, y2, h);
    /* The first term is pi F of the opening (Hottel's parallel rectangles),
     * the second twice the corner sum of cubic_corner. */
    CHECK_REL(first, CDL_PI * cf_parallel_rect(x1, x2, y1, y2, h), 1e-12);
    double corners = cubic_corner(x2, y2, h) - cubic_corner(x1, y2, h) - cubic_corner(x2, y1, h) +
                     cubic_corner(x1, y1, h);
    CHECK_REL(second, 2.0 * corners, 1e-12);
    return ZENITH_L / 3.0 * (first + second);
}

static const char *scene_json =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [12, 12, 3],"
    " \"inward\": true, \"reflectance\": 0, \"open\": [\"+z\"]},"
    " {\"type\": \"polygon\", \"vertices\": [[0, 0, 3], [12, 0, 3], [12, 12, 3], [0, 12, 3]],"
    " \"holes\": [[[4.5, 4.5, 3], [7.5, 4.5, 3], [7.5, 7.5, 3], [4.5, 7.5, 3]]], \"reflectance\": 0}],"
    " \"luminaires\": [{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 6000}],"
    " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [3, 3, 0], \"u\": [6, 0, 0],"
    " \"v\": [0, 6, 0], \"nu\": 5, \"nv\": 5}],"
    " \"solver\": {\"method\": \"direct\", \"quality\": \"%s\"}}";

/* One quality: the route off and on, each tallied; the route on the same
 * bytes on 1 and 2 threads; plans that say which way each went. */
static void test_quality(const char *quality, int route_off_too, calibration *all_off, calibration *all_on)
{
    char json[4096];
    snprintf(json, sizeof json, scene_json, quality);
    cdl_scene *scenes[3] = {NULL, NULL, NULL};
    cdl_solution sols[3];
    /* [0] route on, 1 thread; [1] route on, 2 threads; [2] route off, 2 threads */
    int ok = fixture_solve_route(json, &scenes[0], &sols[0], 1, 0);
    ok = ok && fixture_solve_route(json, &scenes[1], &sols[1], 2, 0);
    ok = ok && (!route_off_too || fixture_solve_route(json, &scenes[2], &sols[2], 2, 1));
    if (ok) {
        double target = cdl_quality_target_error(scenes[0]->settings.quality);
        for (int r = 0; r < (route_off_too ? 2 : 1); ++r) {
            const cdl_grid_solution *g = &sols[r == 0 ? 0 : 2].grids[0];
            calibration tally = CALIBRATION_INIT;
            for (size_t i = 0; i < g->grid.count; ++i) {
                double exact = overcast_exact(g->grid.points[i].x, g->grid.points[i].y);
                calibration_add(r == 0 ? all_on : all_off, g->E[i], exact, g->E_stderr[i], target);
                calibration_add(&tally, g->E[i], exact, g->E_stderr[i], target);
            }
            printf("  %s, route %s: %zu points, %zu within 1 sigma, %zu within 2, worst %.2f sigma; sigma / target "
                   "%.2f .. %.2f\n",
                   quality, r == 0 ? "on" : "off", tally.count, tally.within1, tally.within2, tally.worst,
                   tally.sigma_over_target_min, tally.sigma_over_target_max);
        }
        const cdl_grid_solution *a = &sols[0].grids[0], *b = &sols[1].grids[0];
        for (size_t i = 0; i < a->grid.count; ++i)
            CHECK_MSG(a->E[i] == b->E[i] && a->E_stderr[i] == b->E_stderr[i],
                      "%s point %zu: 1 thread %.17g +- %.3g, 2 threads %.17g +- %.3g", quality, i, a->E[i],
                      a->E_stderr[i], b->E[i], b->E_stderr[i]);
        CHECK_MSG(strstr(sols[0].plan_json, "sampled within the visible sky") != NULL, "%s", sols[0].plan_json);
        CHECK_MSG(fixture_capped_points(sols[0].plan_json) == 0, "%s", sols[0].plan_json);
        if (route_off_too)
            CHECK_MSG(strstr(sols[2].plan_json, "sampled: exact route turned off") != NULL, "%s", sols[2].plan_json);
    }
    for (int k = 0; k < 3; ++k)
        if (scenes[k]) fixture_release(scenes[k], &sols[k]);
}

int main(void)
{
    /* The whole plane: 2 pi / 3 (the corner form's limit, four quadrants). */
    CHECK_REL(4.0 * cubic_corner(1e9, 1e9, 1.0), 2.0 * CDL_PI / 3.0, 1e-9);
    calibration off = CALIBRATION_INIT, on = CALIBRATION_INIT;
    test_quality("draft", 1, &off, &on);
    test_quality("normal", 1, &off, &on);
    test_quality("high", 1, &off, &on);
    test_quality("reference", 0, &off, &on);
    calibration_check(&off, "CIE overcast sky through a roof opening, route off");
    calibration_check(&on, "CIE overcast sky through a roof opening, sampled within the hole");
    return check_finish();
}
