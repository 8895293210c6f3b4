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
 *  - The direct method casts each point's own rays: AO is a mean of N
 *    cosine-distributed 0/1 samples, whose standard deviation is at most
 *    sqrt(AO (1 - AO) / N) (stratification only lowers it); the tolerance is
 *    four of those, and 1e-3 for the finite ground's far edge (50 m away:
 *    below 1e-3 of the hemisphere).
 *  - A grid the irradiance cache serves takes AO from the records' gathers,
 *    interpolated (icache.h): its error is the interpolation's across the
 *    shadow's edges, not sampling noise. Measured at normal: worst 0.093,
 *    RMS 0.035; the bounds 0.15 and 0.05 (a cache whose AO were missing, 0,
 *    or ignored the plate, 1, is off by up to 0.4 under it). */
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
    CHECK(g->ao != NULL);
    int interpolated = strcmp(method, "icache") == 0;
    double n = (double)sol.settings.ao_samples, worst = 0.0, lowest = 1.0, sq = 0.0;
    for (size_t i = 0; g->ao && i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double expected = 1.0 - plate_factor(p.x, p.y);
        double tol = interpolated ? 0.15 : 4.0 * sqrt(expected * (1.0 - expected) / n) + 1e-3;
        sq += (g->ao[i] - expected) * (g->ao[i] - expected);
        CHECK_MSG(fabs(g->ao[i] - expected) <= tol, "%s: AO at (%.2f, %.2f) %.4f, expected %.4f +- %.4f", method, p.x,
                  p.y, g->ao[i], expected, tol);
        worst = fmax(worst, fabs(g->ao[i] - expected));
        lowest = fmin(lowest, expected);
    }
    /* The plate hides a good part of the sky under it: a test that means something. */
    CHECK(lowest < 0.75);
    double rms = sqrt(sq / (double)g->grid.count);
    if (interpolated) CHECK_MSG(rms <= 0.05, "%s: AO RMS error %.4f", method, rms);
    printf("%s: AO of %zu points within %.4f of 1 - F, RMS %.4f%s\n", method, g->grid.count, worst, rms,
           interpolated ? " (from the cache's gathers)" : "");
    fixture_release(scene, &sol);
}

int main(void)
{
    test_plate("direct");
    test_plate("icache");
    return check_finish();
}
