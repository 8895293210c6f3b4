/* solve_fixture.h - solve a scene given as JSON text, and tally how honest
 * the stated errors are against known answers.
 *
 * Calibration (DESIGN.md): over points with known answers, about two thirds
 * should lie within one stated sigma and about 95 % within two. */
#ifndef CANDELA_TESTS_SOLVE_FIXTURE_H
#define CANDELA_TESTS_SOLVE_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/solve_internal.h"

/* Solve `json` (relative paths against CANDELA_TEST_TMPDIR); 0 on failure,
 * reported as a failed check. With no_exact_route set, partly hidden lights
 * are sampled even where the visible polygon would be exact (the tests of
 * the sampler). */
static inline int fixture_solve_debug(const char *json, cdl_scene **scene, cdl_solution *sol,
                                      const cdl_solve_options *o, const cdl_solve_debug *debug)
{
    cdl_error err;
    cdl_error_clear(&err);
    *scene = NULL;
    if (cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/inline.json", scene, &err) != CDL_OK) {
        fprintf(stderr, "scene load failed: %s\n", err.message);
        CHECK(0);
        return 0;
    }
    if (cdl_solve_scene_into(*scene, o, debug, sol, &err) != CDL_OK) {
        fprintf(stderr, "solve failed: %s\n", err.message);
        CHECK(0);
        cdl_scene_release(*scene);
        *scene = NULL;
        return 0;
    }
    return 1;
}

static inline int fixture_solve_options(const char *json, cdl_scene **scene, cdl_solution *sol,
                                        const cdl_solve_options *o)
{
    return fixture_solve_debug(json, scene, sol, o, NULL);
}

static inline int fixture_solve_route(const char *json, cdl_scene **scene, cdl_solution *sol, int threads,
                                      int no_exact_route)
{
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = threads;
    cdl_solve_debug debug = CDL_SOLVE_DEBUG_NONE;
    debug.no_exact_route = no_exact_route;
    return fixture_solve_debug(json, scene, sol, &o, &debug);
}

static inline int fixture_solve(const char *json, cdl_scene **scene, cdl_solution *sol, int threads)
{
    return fixture_solve_route(json, scene, sol, threads, 0);
}

static inline void fixture_release(cdl_scene *scene, cdl_solution *sol)
{
    cdl_solution_clear(sol);
    cdl_scene_release(scene);
}

/* The open white furnace (both GI methods' tests): three white (rho 1)
 * two-sided plates under a uniform sky of 2000 cd/m2, E = pi L everywhere.
 * The opening of a scene: grids and solver follow. */
#define WHITE_FURNACE_SCENE                                                                                     \
    "{\"version\": 1, \"surfaces\": ["                                                                         \
    "{\"type\": \"rect\", \"origin\": [0,0,1], \"u\": [2,0,0], \"v\": [0,2,0], \"reflectance\": 1},"          \
    "{\"type\": \"rect\", \"origin\": [0,0,1.5], \"u\": [2,0,0], \"v\": [0,2,0], \"reflectance\": 1},"        \
    "{\"type\": \"rect\", \"origin\": [2,0,0], \"u\": [0,2,0], \"v\": [0,0,2], \"reflectance\": 1}],"         \
    " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 2000}],"

/* Points whose sampled stage the cap of samples held short of its plan, by
 * the plan's words ("... held N points short of the target"), summed over
 * its lights and grids. */
static inline size_t fixture_capped_points(const char *plan_json)
{
    size_t total = 0;
    for (const char *at = plan_json; at && (at = strstr(at, " held ")) != NULL; at += 6) {
        unsigned long n = 0;
        char word[8] = "";
        if (sscanf(at, " held %lu %7s", &n, word) == 2 && strcmp(word, "points") == 0) total += n;
    }
    return total;
}

/* ---- closed forms both GI methods are held to --------------------------------- */

/* n well-spread unit vectors (a Fibonacci sphere). */
static inline cdl_vec3 fixture_spread(int i, int n)
{
    double z = 1.0 - (2.0 * i + 1.0) / n;
    double r = sqrt(fmax(0.0, 1.0 - z * z));
    double phi = i * 3.14159265358979323846 * (3.0 - sqrt(5.0));
    return cdl_vec3_make(r * cos(phi), r * sin(phi), z);
}

/* Append point p with normal n to a JSON points list; the new length. */
static inline int fixture_append_point(char *buf, size_t size, int at, int first, cdl_vec3 p, cdl_vec3 n)
{
    int k = snprintf(buf + at, size - (size_t)at, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}",
                     first ? "" : ", ", p.x, p.y, p.z, n.x, n.y, n.z);
    return k > 0 ? at + k : at;
}

/* The integrating sphere: radius 1 about the origin, inward, reflectance
 * rho, lit by `luminaire` (JSON); n points on the wall facing the centre;
 * solved by `method` to `target`. */
static inline void fixture_sphere_scene(char *json, size_t size, double rho, const char *luminaire, int n,
                                        const char *method, double target)
{
    int at = snprintf(json, size,
                      "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, "
                      "\"inward\": true, \"reflectance\": %.17g}], \"luminaires\": [%s], \"grids\": [{\"name\": "
                      "\"wall\", \"type\": \"points\", \"points\": [",
                      rho, luminaire);
    for (int i = 0; i < n; ++i) {
        cdl_vec3 u = fixture_spread(i, n);
        at = fixture_append_point(json, size, at, i == 0, u, cdl_vec3_scale(u, -1.0));
    }
    snprintf(json + at, size - (size_t)at, "]}], \"solver\": {\"method\": \"%s\", \"target_error\": %.17g}}", method,
             target);
}

typedef struct calibration {
    size_t count, within1, within2;
    double worst;             /* largest |error| / sigma */
    double sigma_over_target_min, sigma_over_target_max;
    double zsum;              /* of signed errors in sigmas: a bias shows as a mean away from 0 */
    double z2sum;             /* of their squares: sqrt(z2sum / count) near 1 when the stated sigma is right */
} calibration;

#define CALIBRATION_INIT {0, 0, 0, 0.0, INFINITY, 0.0, 0.0, 0.0}

/* One point with a known answer: its error in stated sigmas; also how the
 * stated sigma compares with the target (relative to `expected`). */
static inline void calibration_add(calibration *c, double value, double expected, double sigma, double target)
{
    double z = sigma > 0.0 ? fabs(value - expected) / sigma : (value == expected ? 0.0 : INFINITY);
    c->count++;
    if (sigma > 0.0) c->zsum += (value - expected) / sigma;
    if (sigma > 0.0) c->z2sum += z * z;
    c->within1 += z <= 1.0;
    c->within2 += z <= 2.0;
    if (z > c->worst) c->worst = z;
    if (target > 0.0 && expected > 0.0) {
        double r = sigma / (target * expected);
        if (r < c->sigma_over_target_min) c->sigma_over_target_min = r;
        if (r > c->sigma_over_target_max) c->sigma_over_target_max = r;
    }
}

/* Check a tally of n points: with independent normal errors the fraction
 * within one sigma has mean 0.683 and standard deviation
 * sqrt(0.683 x 0.317 / n), within two 0.954 and sqrt(0.954 x 0.046 / n);
 * the bounds allow four of those deviations either way (a false alarm
 * about once in 16 000 runs), so a sigma too large (almost every point
 * within one) fails as surely as one too small. */
static inline void calibration_check(const calibration *c, const char *what)
{
    double n = (double)c->count;
    double f1 = (double)c->within1 / n, f2 = (double)c->within2 / n;
    double s1 = sqrt(0.683 * 0.317 / n), s2 = sqrt(0.954 * 0.046 / n);
    printf("%s: %zu points, %.1f %% within 1 sigma, %.1f %% within 2, worst %.2f sigma, mean error %+.3f sigma; "
           "sigma / target %.2f .. %.2f\n",
           what, c->count, 100.0 * f1, 100.0 * f2, c->worst, c->zsum / n, c->sigma_over_target_min,
           c->sigma_over_target_max);
    CHECK_MSG(fabs(f1 - 0.683) <= 4.0 * s1, "%s: %.3f within one sigma, expected 0.683 +- %.3f", what, f1, 4.0 * s1);
    CHECK_MSG(fabs(f2 - 0.954) <= 4.0 * s2 + 0.005, "%s: %.3f within two sigma, expected 0.954 +- %.3f", what, f2,
              4.0 * s2 + 0.005);
    /* A bias shows in the mean signed error: of n independent standard
     * normal errors it has standard deviation 1 / sqrt n. */
    CHECK_MSG(fabs(c->zsum / n) <= 4.0 / sqrt(n), "%s: mean error %+.3f sigma, expected 0 +- %.3f", what, c->zsum / n,
              4.0 / sqrt(n));
}

/* Every point of every grid against an expected value (`indirect`: its
 * E_indirect, else E) within 5 stated sigma (and 1e-9 relative, for exact
 * points), each sampled point tallied. */
static inline void fixture_check_all(const cdl_solution *sol, double expected, int indirect, calibration *tally,
                                     double target, const char *what)
{
    for (size_t g = 0; g < sol->grid_count; ++g) {
        const cdl_grid_solution *gs = &sol->grids[g];
        for (size_t i = 0; i < gs->grid.count; ++i) {
            double v = indirect ? gs->E_indirect[i] : gs->E[i];
            CHECK_MSG(fabs(v - expected) <= 5.0 * gs->E_stderr[i] + 1e-9 * expected,
                      "%s: grid %zu point %zu: %.6g +- %.3g, expected %.6g", what, g, i, v, gs->E_stderr[i], expected);
            if (gs->E_stderr[i] > 0.0) calibration_add(tally, v, expected, gs->E_stderr[i], target);
        }
    }
}

/* The integrating sphere (fixture_sphere_scene, n points) solved by
 * `method` to `target` on 2 threads, every point's E_indirect against the
 * sphere's equation rho Phi / (A (1 - rho)), A = 4 pi r^2 (r = 1; e.g.
 * Ohno, OSA Handbook of Optics, "Integrating sphere"), `flux` the light's
 * Phi, each sampled point tallied. */
static inline void fixture_sphere_check(double rho, const char *luminaire, double flux, int n, const char *method,
                                        double target, calibration *tally, const char *label)
{
    static char json[32768];
    fixture_sphere_scene(json, sizeof json, rho, luminaire, n, method, target);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    fixture_check_all(&sol, rho * flux / (4.0 * CDL_PI * (1.0 - rho)), 1, tally, 0.0, label);
    fixture_release(scene, &sol);
}

#endif
