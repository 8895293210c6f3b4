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

#include "solver/bench/bench_ladder.h"
#include "solver/solve_internal.h"

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

typedef cdl_bench_rung rung;

static const char *method_name(cdl_method m)
{
    return m == CDL_METHOD_ICACHE ? "icache" : "pathtrace";
}

static int solve(cdl_scene *scene, cdl_method method, double target, int threads, cdl_solution *sol)
{
    cdl_error err;
    cdl_error_clear(&err);
    if (cdl_bench_solve_rung(scene, method, target, threads, sol, &err) != CDL_OK) {
        fprintf(stderr, "bench_icache: %s\n", err.message);
        return 1;
    }
    return 0;
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
        if (cdl_bench_reference_read(ref_dir, scene, &ref, &err) != CDL_OK) {
            fprintf(stderr, "bench_icache: %s\n", err.message);
            return 1;
        }
        printf("reference: %s\n", ref_dir);
    } else {
        if (solve(scene, CDL_METHOD_PATHTRACE, ref_target, threads, &ref)) return 1;
        printf("reference: pathtrace to %.3g %%, %.1f s, %llu rays\n", 100.0 * ref_target, ref.seconds,
               (unsigned long long)ref.rays);
    }
    for (size_t g = 0; g < ref.grid_count; ++g) points += ref.grids[g].grid.count;
    printf("scene %s: %zu grids, %zu points; the reference's own RMS stated error %.3f %%\n", file, ref.grid_count,
           points, 100.0 * cdl_bench_stated_rms(&ref));

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
            cdl_bench_rung_measure(&sol, &ref, NULL, r);
            cdl_solution_clear(&sol);
            printf("%-10s %7.2f%% %9.2f %12llu %8llu %8.3f%% %8.2f%% %8.1f%%\n", method_name(r->method),
                   100.0 * r->target, r->seconds, (unsigned long long)r->rays, (unsigned long long)r->records, 100.0 * r->rms, 100.0 * r->worst,
                   100.0 * r->within2);
            fflush(stdout);
        }

    /* The cache at normal (0.5 %) against path tracing at its error. */
    const rung *normal = NULL;
    for (int k = 0; k < rungs; ++k)
        if (targets[k] == 0.005) normal = &ladder[1][k];
    double t_pt = cdl_bench_time_at_rms(ladder[0], rungs, normal->rms);
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
    cdl_solution_clear(&one);
    cdl_solution_clear(&all);
    cdl_solution_clear(&ref);
    cdl_scene_release(scene);
    return same ? 0 : 1;
}
