/* Ambient occlusion ("outputs": ["ao"]) against its closed form: the
 * cosine-weighted fraction of a floor point's hemisphere from which rays
 * leave the scene is 1 - F, F the configuration factor from the point to
 * what hides the sky. Here a 2 x 2 m plate 1 m above the floor; for a
 * differential element facing a parallel rectangle with one corner above
 * it, sides a and b at height h (A = a / h, B = b / h),
 *     F = 1 / (2 pi) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2))
 *                   + B / sqrt(1 + B^2) atan(A / sqrt(1 + B^2))]
 * (Howell's catalogue of configuration factors, B-5), and any rectangle by
 * adding and subtracting four such corners.
 *  - Every grid, whichever method serves its interreflection, casts each
 *    point's own rays: AO is a mean of N cosine-distributed 0/1 samples,
 *    whose standard deviation is at most sqrt(AO (1 - AO) / N)
 *    (stratification only lowers it); each value within four of those of
 *    1 - F (and 1e-3 for the finite ground's far edge, 50 m away: below
 *    1e-3 of the hemisphere). Taken from the irradiance cache's gathers
 *    instead it missed the sharp edges (0.093 off, RMS 0.035).
 *  - Its stated error (AO_stderr) covers the truth: at least 95 % of points
 *    within two stated sigmas (the Beta posterior's spread, above the
 *    stratified error), none stated 0, and the stated error not more than
 *    twice the binomial bound (an error stated far too wide says nothing). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/solve_fixture.h"

static double corner(double a, double b, double h)
{
    double A = a / h, B = b / h;
    return (A / sqrt(1.0 + A * A) * atan(B / sqrt(1.0 + A * A)) + B / sqrt(1.0 + B * B) * atan(A / sqrt(1.0 + B * B))) /
           (2.0 * CDL_PI);
}

/* A signed corner: the rectangle from the point's foot to (X, Y). */
static double signed_corner(double X, double Y, double h)
{
    return copysign(1.0, X) * copysign(1.0, Y) * corner(fabs(X), fabs(Y), h);
}

/* F from (x, y, 0), facing up, to the plate [-1, 1]^2 at height 1. */
static double plate_factor(double x, double y)
{
    return signed_corner(1 - x, 1 - y, 1.0) - signed_corner(-1 - x, 1 - y, 1.0) - signed_corner(1 - x, -1 - y, 1.0) +
           signed_corner(-1 - x, -1 - y, 1.0);
}

static void test_plate(const char *method)
{
    char json[2048];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": ["
             "{\"type\": \"rect\", \"origin\": [-50,-50,0], \"u\": [100,0,0], \"v\": [0,100,0], \"reflectance\": 0.3},"
             "{\"type\": \"rect\", \"origin\": [-1,-1,1], \"u\": [2,0,0], \"v\": [0,2,0], \"reflectance\": 0.5}],"
             " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 1000}],"
             " \"grids\": [{\"name\": \"g\", \"type\": \"rect\", \"origin\": [-3,-3,0], \"u\": [6,0,0], \"v\": [0,6,0], "
             "\"nu\": 24, \"nv\": 24, \"outputs\": [\"ao\"]}],"
             " \"solver\": {\"method\": \"%s\", \"quality\": \"normal\"}}",
             method);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK(g->ao != NULL && g->ao_stderr != NULL);
    double n = (double)sol.settings.ao_samples, worst = 0.0, lowest = 1.0;
    size_t within2 = 0, zero = 0, wide = 0;
    for (size_t i = 0; g->ao && g->ao_stderr && i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double expected = 1.0 - plate_factor(p.x, p.y);
        double binomial = sqrt(expected * (1.0 - expected) / n);
        double tol = 4.0 * binomial + 1e-3;
        CHECK_MSG(fabs(g->ao[i] - expected) <= tol, "%s: AO at (%.2f, %.2f) %.4f, expected %.4f +- %.4f", method, p.x,
                  p.y, g->ao[i], expected, tol);
        within2 += fabs(g->ao[i] - expected) <= 2.0 * g->ao_stderr[i];
        zero += !(g->ao_stderr[i] > 0.0);
        /* a point with no sky hidden still states 1 / N; the bound there is 0 */
        wide += g->ao_stderr[i] > 2.0 * binomial + 2.0 / n;
        worst = fmax(worst, fabs(g->ao[i] - expected));
        lowest = fmin(lowest, expected);
    }
    /* The plate hides a good part of the sky under it: a test that means something. */
    CHECK(lowest < 0.75);
    double share = (double)within2 / (double)g->grid.count;
    CHECK_MSG(share >= 0.95, "%s: %.1f %% of points within 2 stated sigma", method, 100.0 * share);
    CHECK_MSG(zero == 0, "%s: %zu points state an AO error of 0", method, zero);
    CHECK_MSG(wide == 0, "%s: %zu points state more than twice the binomial error", method, wide);
    printf("%s: AO of %zu points within %.4f of 1 - F, %.1f %% within 2 stated sigma\n", method, g->grid.count,
           worst, 100.0 * share);
    fixture_release(scene, &sol);
}

int main(void)
{
    test_plate("direct");
    test_plate("icache");
    return check_finish();
}
