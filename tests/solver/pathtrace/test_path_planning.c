/* Path tracing plans each point's paths from its pilot with the exponent
 * measured on its grid (solver/pathtrace/pathtrace.c): Var(N) = v (n / N)^alpha.
 *
 * The one-bounce room: 4 x 4 x 3 m, floor and walls black, the ceiling
 * white (rho 0.8), an isotropic 1000 cd point 1 m above the floor. The
 * floor's interreflected light comes from the ceiling alone, once:
 *     E_ind(p) = int_ceiling (rho / pi) E_c(x) cos(theta_p) cos(theta_x) / r^2 dA,
 *     E_c(x) = I h_c / d^3 (the point's light on the ceiling, h_c = 2 m,
 *     d its distance), cos(theta_p) = cos(theta_x) = 3 / r,
 * computed here by a 64 x 64 Gauss-Legendre product rule (8 panels of 8
 * points a side; the integrand is smooth over the ceiling, the rule's
 * error below 1e-9 relative). A path's value is then a function of its
 * first direction alone (the ceiling's light, 0 where it meets a wall), whose
 * strata the walls' edges cross: its variance falls faster than 1 / N.
 * Checked:
 *  - the plan reports alpha >= 1.3 there (it measures at the cap, 1.5),
 *    and the paths it took are at least 1.3 times fewer than those of the
 *    same solve planned as 1/N (the solve's debug switch; measured 1.39 to
 *    1.49 over seeds 3 to 7, the 12 calibration rounds included);
 *  - both are calibrated against the quadrature (at least 56 of 64 points
 *    within 2 stated sigma, 2.8 binomial sigma under 95 %; the RMS error in
 *    sigmas 0.6 to 1.3), and the measured exponent's stated errors are
 *    nearer the target (median stated / target 0.5 to 1.05; 0.57 to 0.62
 *    measured: the cap holds the plan short of the faster fall here) than
 *    1/N leaves them (its median at most 0.85 of the measured one's; 0.68
 *    to 0.81 measured);
 *  - with heavy-tailed paths (the room's ceiling white but its point 0.2 m
 *    under it: the bright spot above it is found by few paths) the
 *    points' exponents disagree (their quartile spread above 0.35, measured
 *    0.49 to 1.9 over four seeds) and the grid plans as 1/N;
 *  - in the open white furnace (every surface white: the light of many
 *    bounces, whose variance the first direction's strata barely reduce)
 *    the measured exponent stays near 1 (at most 1.15), its points (which
 *    plan hundreds of pilots) read the exponent beyond the first 8 pilots
 *    from rounds of 8 and 64 (never above the first), and the points are
 *    still calibrated against E = pi L. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gauss_legendre.h"
#include "solver/solve_fixture.h"

#ifndef SEED
#define SEED "3"
#endif
#define ROOM_JSON                                                                                                     \
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [4, 4, 3], \"inward\": true,"   \
    " \"reflectance\": {\"floor\": 0, \"walls\": 0, \"ceiling\": 0.8}}],"                                             \
    " \"luminaires\": [{\"type\": \"point\", \"position\": [2, 2, 1], \"intensity_cd\": 1000}],"                      \
    " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0.25, 0.25, 0], \"u\": [3.5, 0, 0],"        \
    " \"v\": [0, 3.5, 0], \"nu\": 8, \"nv\": 8}],"                                                                    \
    " \"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.002, \"seed\": " SEED "}}"

#define FURNACE_JSON                                                                                                  \
    WHITE_FURNACE_SCENE                                                                                               \
    " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0.2, 0.2, 1], \"u\": [1.6, 0, 0],"           \
    " \"v\": [0, 1.6, 0], \"nu\": 5, \"nv\": 5}],"                                                                    \
    " \"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.005, \"seed\": 3}}"

/* The ceiling's reflected light at floor point (x, y). */
static double one_bounce_exact(double x, double y)
{
    const double rho = 0.8, I = 1000.0, h_light = 2.0, h_floor = 3.0;
    double sum = 0.0;
    for (int pi = 0; pi < 8; ++pi)
        for (int qi = 0; qi < 8; ++qi)
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    double cx = 0.5 * (pi + gl8_x[a]), cy = 0.5 * (qi + gl8_x[b]);
                    double wgt = 0.25 * gl8_w[a] * gl8_w[b];
                    double dl2 = (cx - 2) * (cx - 2) + (cy - 2) * (cy - 2) + h_light * h_light;
                    double Ec = I * h_light / (dl2 * sqrt(dl2));
                    double r2 = (cx - x) * (cx - x) + (cy - y) * (cy - y) + h_floor * h_floor;
                    sum += wgt * rho / CDL_PI * Ec * h_floor * h_floor / (r2 * r2);
                }
    return sum;
}

/* The plan's "alpha" and "paths" of the grid (its only one). */
static void plan_numbers(const char *plan, double *alpha, double *paths)
{
    *alpha = *paths = NAN;
    const char *g = plan ? strstr(plan, "\"convergence\"") : NULL;
    const char *a = g ? strstr(g, "\"alpha\"") : NULL;
    if (a) *alpha = strtod(strchr(a, ':') + 1, NULL);
    const char *p = plan ? strstr(plan, "\"grids\"") : NULL;
    p = p ? strstr(p, "\"paths\"") : NULL;
    if (p) *paths = strtod(strchr(p, ':') + 1, NULL);
}

typedef struct outcome {
    double alpha, paths, median_stated, rms_z, mean_z, spread, alpha_beyond;
    size_t within2, count, measured, measured_beyond;
} outcome;

/* A number of the plan's "convergence" object (NAN when absent). */
static double convergence_number(const char *plan, const char *key)
{
    const char *g = plan ? strstr(plan, "\"convergence\"") : NULL;
    const char *k = g ? strstr(g, key) : NULL;
    return k ? strtod(strchr(k, ':') + 1, NULL) : NAN;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Solve json (planned as 1/N when one_over_n) and measure it against
 * exact(x, y) (NULL: E = pi 2000 everywhere, the furnace). */
static int solve_measured(const char *json, int one_over_n, double target, double (*exact)(double, double),
                          outcome *out)
{
    cdl_scene *scene;
    cdl_solution sol;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = 2;
    cdl_solve_debug debug = CDL_SOLVE_DEBUG_NONE;
    debug.paths_as_one_over_n = one_over_n;
    if (!fixture_solve_debug(json, &scene, &sol, &o, &debug)) return 0;
    const cdl_grid_solution *g = &sol.grids[0];
    plan_numbers(sol.plan_json, &out->alpha, &out->paths);
    const char *sp = sol.plan_json ? strstr(sol.plan_json, "\"spread\"") : NULL;
    out->spread = sp ? strtod(strchr(sp, ':') + 1, NULL) : NAN;
    out->alpha_beyond = convergence_number(sol.plan_json, "\"alpha_beyond\"");
    double measured = convergence_number(sol.plan_json, "\"points_measured\"");
    double beyond = convergence_number(sol.plan_json, "\"points_measured_beyond\"");
    out->measured = measured >= 0.0 ? (size_t)measured : 0;
    out->measured_beyond = beyond >= 0.0 ? (size_t)beyond : 0;
    double *stated = malloc(g->grid.count * sizeof *stated), z2 = 0.0, z1 = 0.0;
    out->within2 = 0;
    out->count = g->grid.count;
    for (size_t i = 0; stated && i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        /* the room: the point's direct light is exact, so the interreflected
         * part against the quadrature, with the stated error of the sum;
         * the furnace: the whole E against pi L */
        double truth = exact ? exact(p.x, p.y) : CDL_PI * 2000.0;
        double value = exact ? g->E_indirect[i] : g->E[i];
        double z = (value - truth) / g->E_stderr[i];
        z2 += z * z;
        z1 += z;
        out->within2 += fabs(z) <= 2.0;
        stated[i] = g->E_stderr[i] / g->E[i] / target;
    }
    if (stated) {
        qsort(stated, g->grid.count, sizeof *stated, compare_doubles);
        out->median_stated = stated[g->grid.count / 2];
    }
    out->rms_z = sqrt(z2 / (double)g->grid.count);
    out->mean_z = z1 / (double)g->grid.count;
    free(stated);
    fixture_release(scene, &sol);
    return 1;
}

static void test_one_bounce(void)
{
    outcome m, u;
    if (!solve_measured(ROOM_JSON, 0, 0.002, one_bounce_exact, &m) ||
        !solve_measured(ROOM_JSON, 1, 0.002, one_bounce_exact, &u))
        return;
    printf("one bounce: spread of the points' exponents %.3f\n", m.spread);
    printf("one bounce: measured alpha %.3f, %.0f paths, median stated/target %.2f, %zu/%zu within 2 sigma, RMS "
           "%.2f sigma, mean %+.2f\n",
           m.alpha, m.paths, m.median_stated, m.within2, m.count, m.rms_z, m.mean_z);
    printf("one bounce, as 1/N: alpha %.3f, %.0f paths, median stated/target %.2f, %zu/%zu within 2 sigma, RMS "
           "%.2f sigma, mean %+.2f\n",
           u.alpha, u.paths, u.median_stated, u.within2, u.count, u.rms_z, u.mean_z);
    CHECK_MSG(m.alpha >= 1.3, "one bounce: measured alpha %.3f (the points' spread %.3f)", m.alpha, m.spread);
    CHECK_MSG(u.alpha == 1.0, "one bounce, as 1/N: alpha %.3f", u.alpha);
    CHECK_MSG(m.paths * 1.3 <= u.paths, "one bounce: %.0f paths measured against %.0f as 1/N", m.paths, u.paths);
    const outcome *both[2] = {&m, &u};
    for (int k = 0; k < 2; ++k) {
        const outcome *o = both[k];
        CHECK_MSG(o->within2 * 8 >= o->count * 7, "one bounce (%s): %zu of %zu within 2 sigma",
                  k ? "1/N" : "measured", o->within2, o->count);
        CHECK_MSG(o->rms_z >= 0.6 && o->rms_z <= 1.3, "one bounce (%s): RMS error %.2f sigma", k ? "1/N" : "measured",
                  o->rms_z);
    }
    CHECK_MSG(m.median_stated >= 0.5 && m.median_stated <= 1.05, "one bounce: median stated/target %.2f",
              m.median_stated);
    CHECK_MSG(u.median_stated <= 0.85 * m.median_stated, "one bounce: median stated/target %.2f as 1/N, %.2f measured",
              u.median_stated, m.median_stated);
}

#define HEAVY_JSON                                                                                                    \
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": true,"   \
    " \"reflectance\": 0.5}], \"luminaires\": [{\"type\": \"point\", \"position\": [3, 2.5, 2.8],"                  \
    " \"intensity_cd\": 1000}], \"grids\": [{\"name\": \"wp\", \"type\": \"rect\", \"origin\": [0.5, 0.5, 0.8],"   \
    " \"u\": [5, 0, 0], \"v\": [0, 4, 0], \"nu\": 6, \"nv\": 5}],"                                                       \
    " \"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.01, \"seed\": 1}}"

static void test_heavy_tails(void)
{
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(HEAVY_JSON, &scene, &sol, 2)) return;
    double alpha, paths, spread = NAN;
    plan_numbers(sol.plan_json, &alpha, &paths);
    const char *sp = sol.plan_json ? strstr(sol.plan_json, "\"spread\"") : NULL;
    if (sp) spread = strtod(strchr(sp, ':') + 1, NULL);
    printf("heavy tails: alpha %.3f, spread %.3f, %.0f paths\n", alpha, spread, paths);
    CHECK_MSG(spread > 0.35 && alpha == 1.0, "heavy tails: alpha %.3f, the exponents' spread %.3f", alpha, spread);
    /* Here pilots misjudge the paths' spread (a few bright paths off the
     * white ceiling): a point whose stage states more than the target is
     * traced anew, so that none states more (pathtrace.c, STAGE_RETRIES;
     * without it 1.1 to 1.3 times the target at some points). */
    const cdl_grid_solution *g = &sol.grids[0];
    size_t over = 0;
    double worst = 0.0;
    for (size_t i = 0; i < g->grid.count; ++i) {
        double rel = g->E_stderr[i] / g->E[i] / 0.01;
        over += rel > 1.0 + 1e-9;
        if (rel > worst) worst = rel;
    }
    printf("heavy tails: %zu of %zu points state more than the target, at most %.3f times it\n", over, g->grid.count,
           worst);
    CHECK_MSG(over == 0, "heavy tails: %zu points state more than the target, up to %.3f times it", over, worst);
    fixture_release(scene, &sol);
}

static void test_furnace(void)
{
    outcome m;
    if (!solve_measured(FURNACE_JSON, 0, 0.005, NULL, &m)) return;
    printf("furnace: measured alpha %.3f (beyond 8 pilots %.3f, %zu of %zu points), %.0f paths, median "
           "stated/target %.2f, %zu/%zu within 2 sigma, RMS %.2f sigma\n",
           m.alpha, m.alpha_beyond, m.measured_beyond, m.measured, m.paths, m.median_stated, m.within2, m.count,
           m.rms_z);
    CHECK_MSG(m.alpha >= 1.0 && m.alpha <= 1.15, "furnace: measured alpha %.3f", m.alpha);
    /* its points plan hundreds of pilots: the exponent beyond the first 8
     * is read between rounds of 8 and 64 pilots, at every calibration
     * point that measured alpha, and is never above alpha */
    CHECK_MSG(m.measured >= 3 && m.measured_beyond == m.measured, "furnace: %zu points measured alpha, %zu beyond",
              m.measured, m.measured_beyond);
    CHECK_MSG(m.alpha_beyond >= 1.0 && m.alpha_beyond <= m.alpha, "furnace: alpha %.3f, beyond %.3f", m.alpha,
              m.alpha_beyond);
    /* 25 points: 21 within 2 sigma is 2.4 binomial sigma under 95 % */
    CHECK_MSG(m.within2 >= 21, "furnace: %zu of %zu within 2 sigma", m.within2, m.count);
    CHECK_MSG(m.rms_z >= 0.5 && m.rms_z <= 1.4, "furnace: RMS error %.2f sigma", m.rms_z);
}

int main(void)
{
    test_one_bounce();
    test_heavy_tails();
    test_furnace();
    return check_finish();
}
