/* bench_ladder.c - rungs of solves measured against a reference. */
#include "solver/bench/bench_ladder.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/error_report.h"
#include "base/rng.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_hash.h"
#include "solver/scene/scene_lights.h"
#include "solver/solve_internal.h"

cdl_status cdl_bench_solve_rung(const cdl_scene *scene, cdl_method method, double target, int threads,
                                cdl_solution *out, cdl_error *err)
{
    cdl_scene copy = *scene; /* shallow: the solve only reads it */
    copy.settings.method = method;
    copy.settings.target_error = target;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = threads;
    return cdl_solve_scene_into(&copy, &o, NULL, out, err);
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

/* The measured quantities of one point: the rung's E and stated error
 * against the reference's. y is the point's squared error with the
 * reference's noise taken out. */
typedef struct point_tally {
    double sum_y, sum_y2, ref2, worst;
    size_t n, within;
} point_tally;

static void tally_point(point_tally *t, double E, double s, double E_ref, double s_ref)
{
    if (!(E_ref > 0.0)) return;
    double d = E - E_ref, rel = d / E_ref, rs = s_ref / E_ref;
    double y = rel * rel - rs * rs;
    t->sum_y += y;
    t->sum_y2 += y * y;
    t->ref2 += rs * rs;
    t->worst = fmax(t->worst, fabs(rel));
    t->within += fabs(d) <= 2.0 * sqrt(s * s + s_ref * s_ref);
    t->n++;
}

/* The RMS has the reference's own noise taken out: for independent
 * estimates E[(x - r)^2] = bias^2 + var_x + var_r (variance of a
 * difference, e.g. Papoulis, Probability, Random Variables and Stochastic
 * Processes, ch. 6), so each point's y = rel^2 - (s_ref/E_ref)^2 has the
 * rung's own squared error as its mean, and their mean is never taken
 * below zero. Within-2-sigma uses the combined sigma sqrt(s_x^2 + s_r^2).
 *
 * Over a simple random sample of n of N points, the mean m of y estimates
 * the mean over all points with variance (1 - n/N) S_y^2 / n (S_y^2 the
 * sample variance; Cochran, Sampling Techniques, 3rd ed., 1977, theorem
 * 2.2). A small sample can understate S_y^2 (y is skewed: a square), so
 * it is held to at least 2 m^2, what n squares of normal errors of one
 * variance have (chi-square of one degree). The RMS's standard error
 * follows by the delta method, sd(sqrt m) = sd(m) / (2 sqrt m). The
 * rung's stated errors, known at every point, are not used as a ratio
 * estimator's auxiliary: the irradiance cache's are conservative by
 * orders of magnitude at a few points, and would inflate the estimate. */
void cdl_bench_rung_measure(const cdl_solution *sol, const cdl_solution *ref, const cdl_bench_sample *sample,
                            cdl_bench_rung *r)
{
    point_tally t;
    memset(&t, 0, sizeof t);
    for (size_t g = 0; g < ref->grid_count; ++g) {
        const cdl_grid_solution *b = &ref->grids[g];
        const cdl_grid_solution *a = &sol->grids[sample ? sample->grid_of[g] : g];
        for (size_t j = 0; j < b->grid.count; ++j) {
            size_t i = sample ? sample->index[g][j] : j;
            tally_point(&t, a->E[i], a->E_stderr[i], b->E[j], b->E_stderr[j]);
        }
    }
    double n = (double)t.n, mean = t.n ? t.sum_y / n : 0.0;
    r->rms = sqrt(fmax(mean, 0.0));
    r->rms_sd = 0.0;
    if (sample && sample->total > t.n && t.n > 1 && r->rms > 0.0) {
        double S2 = fmax((t.sum_y2 - n * mean * mean) / (n - 1.0), 2.0 * mean * mean);
        double var_mean = (1.0 - n / (double)sample->total) * S2 / n;
        r->rms_sd = sqrt(var_mean) / (2.0 * r->rms);
    }
    r->worst = t.worst;
    r->within2 = t.n ? (double)t.within / n : 0.0;
    r->seconds = sol->seconds;
    r->rays = sol->rays;
    r->records = sol->records;
    r->stated_rms = cdl_bench_stated_rms(sol);
}

uint64_t cdl_bench_reference_seed(uint64_t seed)
{
    return cdl_rng_stream_id(seed, 0x726566 /* "ref" */, 0x7365656400 /* "seed" */);
}

/* A point's draw in the sample: a fixed hash of its place in the scene's
 * order; the `count` smallest draws are a simple random sample. */
typedef struct point_draw {
    uint64_t hash;
    size_t global;
} point_draw;

static int draw_compare(const void *pa, const void *pb)
{
    const point_draw *a = pa, *b = pb;
    if (a->hash != b->hash) return a->hash < b->hash ? -1 : 1;
    return a->global < b->global ? -1 : a->global > b->global;
}

void cdl_bench_sample_release(cdl_bench_sample *s)
{
    if (s->index)
        for (size_t g = 0; g < s->scene.grid_count; ++g) free(s->index[g]);
    if (s->owns_grids && s->scene.grids)
        for (size_t g = 0; g < s->scene.grid_count; ++g) {
            free(s->scene.grids[g].points);
            free(s->scene.grids[g].normals);
        }
    if (s->owns_grids) free(s->scene.grids);
    free(s->index);
    free(s->grid_of);
    memset(s, 0, sizeof *s);
}

/* The sample's grids: points grids named as the originals, holding the
 * chosen points (chosen[global] != 0) as the built originals have them. */
static cdl_status sample_grids(const cdl_scene *scene, const cdl_grid *built, const unsigned char *chosen,
                               cdl_bench_sample *s, cdl_error *err)
{
    size_t global = 0;
    for (size_t g = 0; g < scene->grid_count; ++g) {
        const cdl_grid *grid = &built[g];
        size_t k = 0;
        for (size_t i = 0; i < grid->count; ++i) k += chosen[global + i];
        if (k > 0) {
            size_t at = s->scene.grid_count;
            cdl_grid_spec *spec = &s->scene.grids[at];
            memset(spec, 0, sizeof *spec);
            snprintf(spec->json_path, sizeof spec->json_path, "%s", scene->grids[g].json_path);
            spec->name = scene->grids[g].name;
            spec->kind = CDL_GRID_POINTS;
            spec->points = malloc(k * sizeof *spec->points);
            spec->normals = malloc(k * sizeof *spec->normals);
            s->index[at] = malloc(k * sizeof *s->index[at]);
            s->grid_of[at] = g;
            s->scene.grid_count++;
            if (!spec->points || !spec->normals || !s->index[at]) return cdl_error_out_of_memory(err);
            for (size_t i = 0; i < grid->count; ++i)
                if (chosen[global + i]) {
                    spec->points[spec->point_count] = grid->points[i];
                    spec->normals[spec->point_count] = grid->normals[i];
                    s->index[at][spec->point_count++] = i;
                }
        }
        global += grid->count;
    }
    return CDL_OK;
}

cdl_status cdl_bench_sample_build(const cdl_scene *scene, size_t max_points, cdl_bench_sample *s, cdl_error *err)
{
    memset(s, 0, sizeof *s);
    s->scene = *scene; /* shallow: surfaces, luminaires and settings are borrowed */
    s->scene.settings.seed = cdl_bench_reference_seed(scene->settings.seed);
    size_t ng = scene->grid_count;
    cdl_grid *built = calloc(ng ? ng : 1, sizeof *built);
    s->grid_of = calloc(ng ? ng : 1, sizeof *s->grid_of);
    s->index = calloc(ng ? ng : 1, sizeof *s->index);
    if (!built || !s->grid_of || !s->index) {
        free(built);
        s->scene.grid_count = 0;
        cdl_bench_sample_release(s);
        return cdl_error_out_of_memory(err);
    }
    cdl_status st = CDL_OK;
    for (size_t g = 0; st == CDL_OK && g < ng; ++g) {
        st = cdl_grid_build(&scene->grids[g], &built[g], err);
        if (st == CDL_OK) s->total += built[g].count;
    }
    point_draw *draws = NULL;
    unsigned char *chosen = NULL;
    if (st == CDL_OK && (max_points == 0 || max_points >= s->total)) {
        /* every point: the original grids, each point its own index */
        s->count = s->total;
        for (size_t g = 0; st == CDL_OK && g < ng; ++g) {
            s->grid_of[g] = g;
            s->index[g] = malloc((built[g].count ? built[g].count : 1) * sizeof *s->index[g]);
            if (!s->index[g]) st = cdl_error_out_of_memory(err);
            for (size_t i = 0; st == CDL_OK && i < built[g].count; ++i) s->index[g][i] = i;
        }
    } else if (st == CDL_OK) {
        s->count = max_points;
        draws = malloc(s->total * sizeof *draws);
        chosen = calloc(s->total, 1);
        s->scene.grids = calloc(ng, sizeof *s->scene.grids);
        s->scene.grid_count = 0;
        s->owns_grids = 1;
        if (!draws || !chosen || !s->scene.grids) st = cdl_error_out_of_memory(err);
        for (size_t i = 0; st == CDL_OK && i < s->total; ++i)
            draws[i] = (point_draw){cdl_rng_stream_id(i, 0x73616d706c65 /* "sample" */, 0), i};
        if (st == CDL_OK) {
            qsort(draws, s->total, sizeof *draws, draw_compare);
            for (size_t k = 0; k < s->count; ++k) chosen[draws[k].global] = 1;
            st = sample_grids(scene, built, chosen, s, err);
        }
    }
    free(draws);
    free(chosen);
    for (size_t g = 0; g < ng; ++g) cdl_grid_release(&built[g]);
    free(built);
    if (st != CDL_OK) cdl_bench_sample_release(s);
    return st;
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
    if (st != CDL_OK) cdl_solution_clear(out);
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
