/* bench_ladder.c - rungs of solves measured against a reference. */
#include "solver/bench/bench_ladder.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiometry/content_hash.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_hash.h"
#include "solver/scene/scene_lights.h"
#include "solver/solve.h"

cdl_status cdl_bench_solve_rung(const cdl_scene *scene, cdl_method method, double target, int threads,
                                cdl_solution *out, cdl_error *err)
{
    cdl_scene copy = *scene; /* shallow: the solve only reads it */
    copy.settings.method = method;
    copy.settings.target_error = target;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_DEFAULT;
    o.threads = threads;
    return cdl_solve_scene(&copy, &o, out, err);
}

double cdl_bench_stated_rms(const cdl_solution *sol)
{
    double sum2 = 0.0;
    size_t n = 0;
    for (size_t g = 0; g < sol->grid_count; ++g)
        for (size_t i = 0; i < sol->grids[g].grid.count; ++i) {
            double E = sol->grids[g].E[i], s = sol->grids[g].E_stderr[i];
            if (!(E > 0.0)) continue;
            sum2 += (s / E) * (s / E);
            n++;
        }
    return n ? sqrt(sum2 / (double)n) : 0.0;
}

/* The RMS has the reference's own noise taken out: for independent
 * estimates E[(x - r)^2] = bias^2 + var_x + var_r (variance of a
 * difference, e.g. Papoulis, Probability, Random Variables and Stochastic
 * Processes, ch. 6), so the reference's mean relative variance is
 * subtracted, never below zero. Within-2-sigma uses the combined sigma
 * sqrt(s_x^2 + s_r^2). */
void cdl_bench_rung_measure(const cdl_solution *sol, const cdl_solution *ref, cdl_bench_rung *r)
{
    double sum2 = 0.0, ref2 = 0.0, worst = 0.0;
    size_t n = 0, within = 0;
    for (size_t g = 0; g < sol->grid_count; ++g) {
        const cdl_grid_solution *a = &sol->grids[g], *b = &ref->grids[g];
        for (size_t i = 0; i < a->grid.count; ++i) {
            if (!(b->E[i] > 0.0)) continue;
            double d = a->E[i] - b->E[i], rel = d / b->E[i], rs = b->E_stderr[i] / b->E[i];
            sum2 += rel * rel;
            ref2 += rs * rs;
            worst = fmax(worst, fabs(rel));
            within += fabs(d) <= 2.0 * sqrt(a->E_stderr[i] * a->E_stderr[i] + b->E_stderr[i] * b->E_stderr[i]);
            n++;
        }
    }
    r->rms = n ? sqrt(fmax(sum2 - ref2, 0.0) / (double)n) : 0.0;
    r->worst = worst;
    r->within2 = n ? (double)within / (double)n : 0.0;
    r->seconds = sol->seconds;
    r->rays = sol->rays;
    r->records = sol->records;
    r->stated_rms = cdl_bench_stated_rms(sol);
}

/* Monte Carlo's error falls as N^-1/2 (Kalos and Whitlock, Monte Carlo
 * Methods, ch. 2), so time at fixed cost per sample goes as RMS^-2;
 * between measured rungs, log-log interpolation. */
double cdl_bench_time_at_rms(const cdl_bench_rung *pt, int count, double rms)
{
    if (rms >= pt[0].rms) return pt[0].seconds * pow(pt[0].rms / rms, 2.0);
    for (int k = 0; k + 1 < count; ++k)
        if (rms >= pt[k + 1].rms) {
            double s = log(pt[k].rms / rms) / log(pt[k].rms / pt[k + 1].rms);
            return exp(log(pt[k].seconds) + s * (log(pt[k + 1].seconds) - log(pt[k].seconds)));
        }
    return pt[count - 1].seconds * pow(pt[count - 1].rms / rms, 2.0);
}

static cdl_status read_grid_csv(const char *path, cdl_grid_solution *r, cdl_error *err)
{
    char line[2048];
    FILE *f = fopen(path, "r");
    if (!f) return cdl_error_set(err, CDL_ERR_INPUT, "%s: cannot be read", path);
    if (!fgets(line, sizeof line, f)) {
        fclose(f);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: empty, expected a header line", path);
    }
    size_t i = 0;
    while (fgets(line, sizeof line, f)) {
        double x, y, z, nx, ny, nz, E, Ed, Ei, s;
        if (i >= r->grid.count) {
            fclose(f);
            return cdl_error_set(err, CDL_ERR_INPUT, "%s: more points than the scene's %zu", path, r->grid.count);
        }
        cdl_vec3 p = r->grid.points[i];
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &x, &y, &z, &nx, &ny, &nz, &E, &Ed, &Ei, &s) != 10 ||
            fabs(x - p.x) > 1e-9 || fabs(y - p.y) > 1e-9 || fabs(z - p.z) > 1e-9) {
            fclose(f);
            return cdl_error_set(err, CDL_ERR_INPUT, "%s line %zu: not the scene's point %zu", path, i + 2, i);
        }
        r->E[i] = E;
        r->E_direct[i] = Ed;
        r->E_indirect[i] = Ei;
        r->E_stderr[i] = s;
        i++;
    }
    fclose(f);
    if (i != r->grid.count)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %zu points, the scene has %zu", path, i, r->grid.count);
    return CDL_OK;
}

cdl_status cdl_bench_reference_read(const char *dir, const cdl_scene *scene, cdl_solution *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    out->method = CDL_METHOD_PATHTRACE;
    out->grids = calloc(scene->grid_count ? scene->grid_count : 1, sizeof *out->grids);
    if (!out->grids) return cdl_error_out_of_memory(err);
    out->grid_count = scene->grid_count;
    cdl_status st = CDL_OK;
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) {
        cdl_grid_solution *r = &out->grids[g];
        st = cdl_grid_build(&scene->grids[g], &r->grid, err);
        if (st == CDL_OK) st = cdl_grid_solution_alloc(r, 0, err);
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.csv", dir, scene->grids[g].name);
        if (st == CDL_OK) st = read_grid_csv(path, r, err);
    }
    if (st != CDL_OK) cdl_solution_release(out);
    return st;
}

cdl_status cdl_bench_reference_key(const cdl_scene *scene, double target, uint64_t *key, cdl_error *err)
{
    cdl_scene_geometry *geometry = NULL;
    cdl_scene_lights lights;
    memset(&lights, 0, sizeof lights);
    cdl_scene_hashes sh;
    cdl_status st = cdl_scene_geometry_build(scene, &geometry, err);
    if (st != CDL_OK) return st;
    st = cdl_scene_lights_build(scene, geometry, &lights, err);
    if (st == CDL_OK) {
        st = cdl_scene_hash(scene, &lights, &sh, err);
        cdl_scene_lights_release(&lights);
    }
    cdl_scene_geometry_release(geometry);
    if (st != CDL_OK) return st;

    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&h, sh.geometry);
    cdl_content_hash_u64(&h, sh.materials);
    cdl_content_hash_u64(&h, sh.lights);
    cdl_content_hash_f64(&h, target);
    cdl_content_hash_u64(&h, scene->settings.seed);
    cdl_content_hash_u64(&h, (uint64_t)(int64_t)scene->settings.bounces);
    cdl_content_hash_u64(&h, (uint64_t)(int64_t)scene->settings.direct_samples);
    cdl_content_hash_u64(&h, scene->grid_count);
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) {
        size_t len = strlen(scene->grids[g].name);
        cdl_content_hash_u64(&h, len);
        cdl_content_hash_raw(&h, scene->grids[g].name, len);
        cdl_grid grid;
        st = cdl_grid_build(&scene->grids[g], &grid, err);
        if (st != CDL_OK) break;
        cdl_content_hash_u64(&h, grid.count);
        for (size_t i = 0; i < grid.count; ++i) {
            cdl_content_hash_vec3(&h, grid.points[i]);
            cdl_content_hash_vec3(&h, grid.normals[i]);
        }
        cdl_grid_release(&grid);
    }
    *key = h.value;
    return st;
}
