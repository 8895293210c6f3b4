/* The sun as a disk of 0.533 degrees past a straight edge: its penumbra.
 *
 * The sun straight overhead (E_n = 100 klx normal to its rays), a black
 * sheet at 10 m covering x < 0, floor points across the shadow's edge.
 * Seen from a floor point at x, the sheet hides the directions whose tangent
 * u (on the plane at unit distance above) has x + 10 u < 0: the disk of
 * radius r = tan(alpha) is visible beyond the line u = d = -x / 10, a
 * circular segment of area
 *     A(d) = r^2 acos(d / r) - d sqrt(r^2 - d^2),
 * so E = E_n A(d) / (pi r^2) (the weight cos^4 of a point of the disk seen
 * on that plane is 1 within 2 r^2 = 4.3e-5). The exact route takes the
 * disk as a 240-gon of its area, within 1e-4 of the circle's fraction
 * (direct_exact_route.c): checked to 1.5e-4 E_n, with no stated error
 * (measured within 1.5e-6 E_n). With the route off the disk is sampled
 * with shadow rays: within 4 stated sigmas, each sigma at most 1.5 times
 * the target where the cap of samples lets it. The plan says which.
 *
 * Cylindrical and semicylindrical illuminance under the disk (nothing in the
 * way; the disk is sampled about its own axis): a parallel beam of E_n at
 * zenith angle z gives E_z = E_n sin z / pi, and on the half cylinder facing
 * the beam's horizontal direction E_sz = 2 E_n sin z / pi, facing away 0;
 * the disk's spread changes these by the mean square of its angular radius,
 * (r^2 / 4) / sin^2 z ~ 2e-5 relative at z = 30 deg.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/solve_fixture.h"

#define E_N 100000.0
#define HEIGHT 10.0

static const double fractions[] = {-1.5, -0.9, -0.5, 0.0, 0.4, 0.8, 0.99, 1.5}; /* d / r */
enum { POINTS = sizeof fractions / sizeof fractions[0] };

static double segment_fraction(double d, double r)
{
    if (d <= -r) return 1.0;
    if (d >= r) return 0.0;
    return (r * r * acos(d / r) - d * sqrt(r * r - d * d)) / (CDL_PI * r * r);
}

static void run(int no_route)
{
    double r = tan(0.5 * 0.533 * CDL_DEG_TO_RAD);
    char points[2048] = "";
    for (int i = 0; i < POINTS; ++i) {
        char one[96];
        snprintf(one, sizeof one, "%s{\"p\": [%.17g, 0, 0], \"n\": [0, 0, 1]}", i ? ", " : "",
                 -fractions[i] * r * HEIGHT);
        strcat(points, one);
    }
    char json[4096];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-50, -50, %g], \"u\": [50, 0, 0], "
             "\"v\": [0, 100, 0], \"reflectance\": 0}],"
             " \"luminaires\": [{\"type\": \"directional\", \"direction\": [0, 0, -1], \"illuminance_lx\": %g, "
             "\"angular_diameter_deg\": 0.533}],"
             " \"grids\": [{\"name\": \"edge\", \"type\": \"points\", \"points\": [%s]}],"
             " \"solver\": {\"method\": \"direct\", \"quality\": \"normal\"}}",
             HEIGHT, E_N, points);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve_route(json, &scene, &sol, 2, no_route)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    for (int i = 0; i < POINTS; ++i) {
        double want = E_N * segment_fraction(fractions[i] * r, r);
        double E = g->E[i], s = g->E_stderr[i];
        if (!no_route) {
            CHECK_MSG(fabs(E - want) <= 1.5e-4 * E_N, "d/r %g: E %.9g, expected %.9g", fractions[i], E, want);
            CHECK(s == 0.0);
        } else {
            CHECK_MSG(fabs(E - want) <= 4.0 * s + 1e-9 * E_N, "sampled, d/r %g: E %.9g +- %.3g, expected %.9g",
                      fractions[i], E, s, want);
            /* sigma near the target, where the cap of samples does not hold the
             * point (at d / r = 0.99 the disk is 99.9 % hidden: E_0 - H with
             * H from 2^18 samples is held there, and the plan says so) */
            if (E > 0.01 * E_N)
                CHECK_MSG(s <= 1.5 * 0.005 * E, "sampled, d/r %g: sigma %.3g", fractions[i], s);
        }
        fprintf(stderr, "%s d/r %5.2f: E %12.4f, expected %12.4f (%+.2e E_n), sigma %.3g\n",
                no_route ? "sampled" : "exact  ", fractions[i], E, want, (E - want) / E_N, s);
    }
    const char *plan = sol.plan_json;
    CHECK(plan && strstr(plan, no_route ? "exact route turned off" : "exact: visible polygon"));
    CHECK(plan && strstr(plan, "the disk as a 240-gon"));
    fixture_release(scene, &sol);
}

static void vertical(void)
{
    /* the sun 30 degrees from the zenith towards +x: light travels to -x */
    double z = 30.0 * CDL_DEG_TO_RAD;
    char json[1024];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [{\"type\": \"directional\", \"direction\": [%.17g, 0, %.17g], "
             "\"illuminance_lx\": %g, \"angular_diameter_deg\": 0.533}],"
             " \"grids\": [{\"name\": \"v\", \"type\": \"points\", \"points\": [{\"p\": [0,0,1], \"n\": [1,0,1]}, "
             "{\"p\": [0,0,1], \"n\": [-1,0,1]}], \"outputs\": [\"cylindrical\", \"semicylindrical\"]}],"
             " \"solver\": {\"method\": \"direct\", \"quality\": \"high\"}}",
             -sin(z), -cos(z), E_N);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    double ez = E_N * sin(z) / CDL_PI, esz[2] = {2.0 * ez, 0.0};
    for (int i = 0; i < 2; ++i) {
        /* 4 stated sigmas, and the disk's spread (2e-5 relative, above) */
        CHECK_MSG(fabs(g->Ez[i] - ez) <= 4.0 * g->Ez_stderr[i] + 1e-4 * ez, "point %d: Ez %.9g +- %.3g, expected %.9g",
                  i, g->Ez[i], g->Ez_stderr[i], ez);
        CHECK_MSG(fabs(g->Esz[i] - esz[i]) <= 4.0 * g->Esz_stderr[i] + 1e-4 * ez,
                  "point %d: Esz %.9g +- %.3g, expected %.9g", i, g->Esz[i], g->Esz_stderr[i], esz[i]);
        fprintf(stderr, "vertical %d: Ez %.6f +- %.3g (%.6f), Esz %.6f +- %.3g (%.6f)\n", i, g->Ez[i],
                g->Ez_stderr[i], ez, g->Esz[i], g->Esz_stderr[i], esz[i]);
    }
    fixture_release(scene, &sol);
}

int main(void)
{
    run(0);
    run(1);
    vertical();
    return check_finish();
}
