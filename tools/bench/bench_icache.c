/* bench_icache.c - the dense-map trade: the irradiance cache against path
 * tracing at equal error, on the same scene, in the same process.
 *
 *   bench_icache [--scene FILE] [--reference-target T | --reference DIR] [--threads K] [--small]
 *
 * The scene (default data/bench/cube_dense.json): a closed 4 m cube of
 * reflectance 0.5 with a 10 000 lm isotropic source at its centre, a
 * 100 x 100 floor grid and a 50 x 50 wall grid. Steps:
 *  1. a reference: path tracing to target T (default 0.001, relative
 *     standard error per point), whose own error is reported and
 *     removed from the ladder's errors in quadrature; or, with
 *     --reference DIR, the E_lx and E_stderr_lx columns of DIR/NAME.csv
 *     from an earlier `candela solve` of the same scene (its points must
 *     match to 1e-9 m);
 *  2. a ladder of targets (2 %, 1 %, 0.5 %, 0.25 %) for each method, each
 *     a whole solve with the same seed: seconds, rays, records, RMS and
 *     worst relative error of E against the reference over all points,
 *     share of points within 2 combined sigma;
 *  3. path tracing's time at the cache's RMS error, by log-log
 *     interpolation between its rungs (or its 1/RMS^2 law past the ends),
 *     and the ratio to the cache's time at "normal" (0.5 %): the figure
 *     the interreflection issue asks to be at least 10;
 *  4. the cache at "normal" on one thread and on all: the speed-up.
 * --small shrinks the grids to 20 x 20 and 10 x 10 and the ladder to two
 * rungs (the ctest that keeps this program from rotting). Ratios, never
 * wall-clock limits, are what to compare between versions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solve.h"

static const char *arg_str(int argc, char **argv, const char *name, const char *dflt)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], name) == 0) return argv[i + 1];
    return dflt;
}

static int arg_flag(int argc, char **argv, const char *name)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], name) == 0) return 1;
    return 0;
}

typedef struct rung {
    cdl_method method;
    double target;
    double seconds;
    unsigned long long rays, records;
    double rms, worst, within2;
} rung;

static const char *method_name(cdl_method m)
{
    return m == CDL_METHOD_ICACHE ? "icache" : "pathtrace";
}

static int solve(cdl_scene *scene, cdl_method method, double target, int threads, cdl_solution *sol)
{
    cdl_error err;
    cdl_error_clear(&err);
    scene->settings.method = method;
    scene->settings.target_error = target;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_DEFAULT;
    o.threads = threads;
    if (cdl_solve_scene(scene, &o, sol, &err) != CDL_OK) {
        fprintf(stderr, "bench_icache: %s\n", err.message);
        return 1;
    }
    return 0;
}

/* A solve's errors against the reference over every point of every grid.
 * The RMS has the reference's own noise taken out: E[(x - r)^2] =
 * bias^2 + var_x + var_r, so the reference's mean variance is subtracted
 * (never below zero). Within-2-sigma uses the combined sigma. */
static void measure(const cdl_solution *sol, const cdl_solution *ref, rung *r)
{
    double sum2 = 0.0, ref2 = 0.0, worst = 0.0;
    size_t n = 0, within = 0;
    for (size_t g = 0; g < sol->grid_count; ++g) {
        const cdl_grid_solution *a = &sol->grids[g], *b = &ref->grids[g];
        for (size_t i = 0; i < a->grid.count; ++i) {
            double d = a->E[i] - b->E[i], rel = d / b->E[i], rs = b->E_stderr[i] / b->E[i];
            sum2 += rel * rel;
            ref2 += rs * rs;
            worst = fmax(worst, fabs(rel));
            within += fabs(d) <= 2.0 * sqrt(a->E_stderr[i] * a->E_stderr[i] + b->E_stderr[i] * b->E_stderr[i]);
            n++;
        }
    }
    r->rms = sqrt(fmax(sum2 - ref2, 0.0) / (double)n);
    r->worst = worst;
    r->within2 = (double)within / (double)n;
    r->seconds = sol->seconds;
    r->rays = (unsigned long long)sol->rays;
    r->records = (unsigned long long)sol->records;
}

/* Path tracing's time at a given RMS error: log t is taken as linear in log
 * RMS between the two rungs that bracket it; past the ends, Monte Carlo's
 * law t ~ RMS^-2 from the nearest rung. rungs sorted by falling RMS. */
static double time_at_rms(const rung *pt, int count, double rms)
{
    if (rms >= pt[0].rms) return pt[0].seconds * pow(pt[0].rms / rms, 2.0);
    for (int k = 0; k + 1 < count; ++k)
        if (rms >= pt[k + 1].rms) {
            double s = log(pt[k].rms / rms) / log(pt[k].rms / pt[k + 1].rms);
            return exp(log(pt[k].seconds) + s * (log(pt[k + 1].seconds) - log(pt[k].seconds)));
        }
    return pt[count - 1].seconds * pow(pt[count - 1].rms / rms, 2.0);
}

/* Read a reference from DIR/NAME.csv into ref's arrays (allocated like a
 * solve's, for the same grids as sol's). */
static int read_reference(const char *dir, const cdl_scene *scene, const cdl_solution *sol, cdl_solution *ref)
{
    memset(ref, 0, sizeof *ref);
    ref->grid_count = sol->grid_count;
    ref->grids = calloc(sol->grid_count, sizeof *ref->grids);
    if (!ref->grids) return 1;
    for (size_t g = 0; g < sol->grid_count; ++g) {
        size_t n = sol->grids[g].grid.count;
        cdl_grid_solution *r = &ref->grids[g];
        r->E = malloc(n * sizeof *r->E);
        r->E_stderr = malloc(n * sizeof *r->E_stderr);
        r->grid.count = n;
        char path[1024], line[1024];
        snprintf(path, sizeof path, "%s/%s.csv", dir, scene->grids[g].name);
        FILE *f = fopen(path, "r");
        if (!f || !r->E || !r->E_stderr || !fgets(line, sizeof line, f)) {
            fprintf(stderr, "bench_icache: cannot read %s\n", path);
            if (f) fclose(f);
            return 1;
        }
        size_t i = 0;
        while (i < n && fgets(line, sizeof line, f)) {
            double x, y, z, nx, ny, nz, E, Ed, Ei, s;
            cdl_vec3 p = sol->grids[g].grid.points[i];
            if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &x, &y, &z, &nx, &ny, &nz, &E, &Ed, &Ei, &s) !=
                    10 ||
                fabs(x - p.x) > 1e-9 || fabs(y - p.y) > 1e-9 || fabs(z - p.z) > 1e-9 || !(E > 0.0)) {
                fprintf(stderr, "bench_icache: %s line %zu: not this scene's point %zu\n", path, i + 2, i);
                fclose(f);
                return 1;
            }
            r->E[i] = E;
            r->E_stderr[i] = s;
            i++;
        }
        fclose(f);
        if (i != n) {
            fprintf(stderr, "bench_icache: %s: %zu points, the scene has %zu\n", path, i, n);
            return 1;
        }
    }
    return 0;
}

static void release_reference(cdl_solution *ref)
{
    for (size_t g = 0; g < ref->grid_count; ++g) {
        free(ref->grids[g].E);
        free(ref->grids[g].E_stderr);
    }
    free(ref->grids);
}

/* The small variant: grids shrunk for the ctest. */
static void shrink_grids(cdl_scene *scene)
{
    for (size_t g = 0; g < scene->grid_count; ++g) {
        cdl_grid_spec *spec = &scene->grids[g];
        if (spec->nu > 20) spec->nu = spec->nu / 5;
        if (spec->nv > 20) spec->nv = spec->nv / 5;
    }
}

int main(int argc, char **argv)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/data/bench/cube_dense.json", CANDELA_SOURCE_DIR);
    const char *file = arg_str(argc, argv, "--scene", path);
    double ref_target = atof(arg_str(argc, argv, "--reference-target", "0.001"));
    int threads = atoi(arg_str(argc, argv, "--threads", "0"));
    int small = arg_flag(argc, argv, "--small");
    if (!(ref_target >= CDL_TARGET_ERROR_MIN && ref_target <= 0.01)) {
        fprintf(stderr, "bench_icache: --reference-target is between %g and 0.01\n", CDL_TARGET_ERROR_MIN);
        return 2;
    }
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    if (cdl_scene_load(file, &scene, &err) != CDL_OK) {
        fprintf(stderr, "bench_icache: %s\n", err.message);
        return 1;
    }
    if (small) shrink_grids(scene);
    size_t points = 0;

    const char *ref_dir = arg_str(argc, argv, "--reference", NULL);
    cdl_solution ref;
    if (ref_dir) {
        /* the grids' points, from the cheapest solve */
        cdl_solution probe;
        if (solve(scene, CDL_METHOD_ICACHE, 0.02, threads, &probe)) return 1;
        int bad = read_reference(ref_dir, scene, &probe, &ref);
        cdl_solution_release(&probe);
        if (bad) return 1;
        printf("reference: %s\n", ref_dir);
    } else {
        if (solve(scene, CDL_METHOD_PATHTRACE, ref_target, threads, &ref)) return 1;
        printf("reference: pathtrace to %.3g %%, %.1f s, %llu rays\n", 100.0 * ref_target, ref.seconds,
               (unsigned long long)ref.rays);
    }
    double ref_rel = 0.0;
    for (size_t g = 0; g < ref.grid_count; ++g)
        for (size_t i = 0; i < ref.grids[g].grid.count; ++i, ++points)
            ref_rel += ref.grids[g].E_stderr[i] * ref.grids[g].E_stderr[i] / (ref.grids[g].E[i] * ref.grids[g].E[i]);
    printf("scene %s: %zu grids, %zu points; the reference's own RMS stated error %.3f %%\n", file, ref.grid_count,
           points, 100.0 * sqrt(ref_rel / (double)points));

    static const double full_targets[] = {0.02, 0.01, 0.005, 0.0025};
    static const double small_targets[] = {0.02, 0.005};
    const double *targets = small ? small_targets : full_targets;
    int rungs = small ? 2 : 4;
    rung ladder[2][4];
    const cdl_method methods[2] = {CDL_METHOD_PATHTRACE, CDL_METHOD_ICACHE};
    printf("\n%-10s %8s %9s %12s %8s %9s %9s %9s\n", "method", "target", "seconds", "rays", "records", "rms_rel",
           "max_rel", "within_2s");
    for (int m = 0; m < 2; ++m)
        for (int k = 0; k < rungs; ++k) {
            cdl_solution sol;
            rung *r = &ladder[m][k];
            r->method = methods[m];
            r->target = targets[k];
            if (solve(scene, methods[m], targets[k], threads, &sol)) return 1;
            measure(&sol, &ref, r);
            cdl_solution_release(&sol);
            printf("%-10s %7.2f%% %9.2f %12llu %8llu %8.3f%% %8.2f%% %8.1f%%\n", method_name(r->method),
                   100.0 * r->target, r->seconds, r->rays, r->records, 100.0 * r->rms, 100.0 * r->worst,
                   100.0 * r->within2);
            fflush(stdout);
        }

    /* The cache at normal (0.5 %) against path tracing at its error. */
    const rung *normal = NULL;
    for (int k = 0; k < rungs; ++k)
        if (targets[k] == 0.005) normal = &ladder[1][k];
    double t_pt = time_at_rms(ladder[0], rungs, normal->rms);
    printf("\nicache at normal: %.3f %% RMS in %.2f s; pathtrace at that RMS: %.2f s\n", 100.0 * normal->rms,
           normal->seconds, t_pt);
    printf("ratio (pathtrace / icache, equal RMS): %.1f\n", t_pt / normal->seconds);

    /* Threads: the cache at normal on one thread and on all cores. */
    cdl_solution one, all;
    if (solve(scene, CDL_METHOD_ICACHE, 0.005, 1, &one)) return 1;
    if (solve(scene, CDL_METHOD_ICACHE, 0.005, 0, &all)) return 1;
    int same = 1;
    for (size_t g = 0; g < one.grid_count; ++g)
        same &= memcmp(one.grids[g].E, all.grids[g].E, one.grids[g].grid.count * sizeof(double)) == 0;
    printf("icache at normal: 1 thread %.2f s, %d threads %.2f s, speed-up %.2f (%s bytes)\n", one.seconds,
           all.threads_used, all.seconds, one.seconds / all.seconds, same ? "same" : "DIFFERENT");
    cdl_solution_release(&one);
    cdl_solution_release(&all);
    if (ref_dir)
        release_reference(&ref);
    else
        cdl_solution_release(&ref);
    cdl_scene_release(scene);
    return same ? 0 : 1;
}
