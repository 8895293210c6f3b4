/* test_bench_ladder.c - the ladder's measurements on hand-made solutions
 * (at every point and over a sample of them), the sample of the
 * reference's points, the time interpolation, the reference reader, the
 * reference's key, and bench.csv's "<ref". */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "solver/bench/bench_ladder.h"
#include "solver/bench/bench_report.h"
#include "solver/grid/grid.h"

/* A one-grid solution of n points with the given E and E_stderr. */
static void fake_solution(cdl_solution *s, cdl_grid_solution *g, double *E, double *sd, size_t n)
{
    memset(s, 0, sizeof *s);
    memset(g, 0, sizeof *g);
    g->grid.count = n;
    g->E = E;
    g->E_stderr = sd;
    s->grids = g;
    s->grid_count = 1;
    s->seconds = 1.5;
    s->rays = 1000;
    s->records = 7;
}

/* A sample of `count` of `total` points of one grid, at index[0]. */
static void fake_sample(cdl_bench_sample *s, size_t *grid_of, size_t **index, size_t total, size_t count)
{
    memset(s, 0, sizeof *s);
    s->total = total;
    s->count = count;
    s->grid_of = grid_of;
    s->index = index;
}

static void test_measure(void)
{
    double Er[4] = {100, 100, 100, 100}, sr[4] = {0, 0, 0, 0};
    double Ex[4] = {101, 99, 102, 97}, sx[4] = {1, 1, 1, 1};
    cdl_solution ref, sol;
    cdl_grid_solution gr, gx;
    fake_solution(&ref, &gr, Er, sr, 4);
    fake_solution(&sol, &gx, Ex, sx, 4);
    cdl_bench_rung r;
    cdl_bench_rung_measure(&sol, &ref, NULL, &r);
    /* relative errors 0.01, -0.01, 0.02, -0.03: RMS sqrt(15e-4 / 4) */
    CHECK_REL(r.rms, sqrt(15e-4 / 4.0), 1e-12);
    CHECK_REL(r.worst, 0.03, 1e-12);
    /* |d| <= 2 x 1 at the first three points, not at the fourth */
    CHECK_REL(r.within2, 0.75, 1e-12);
    /* stated: E_stderr / E at each point */
    double st = sqrt((1.0 / (101.0 * 101) + 1.0 / (99.0 * 99) + 1.0 / (102.0 * 102) + 1.0 / (97.0 * 97)) / 4.0);
    CHECK_REL(r.stated_rms, st, 1e-12);
    CHECK(r.seconds == 1.5 && r.rays == 1000 && r.records == 7);

    /* The reference's own noise (1 % at every point) comes off in quadrature. */
    double sr1[4] = {1, 1, 1, 1};
    fake_solution(&ref, &gr, Er, sr1, 4);
    cdl_bench_rung_measure(&sol, &ref, NULL, &r);
    CHECK_REL(r.rms, sqrt((15e-4 - 4e-4) / 4.0), 1e-12);
    /* ... never below zero */
    fake_solution(&sol, &gx, Er, sx, 4);
    cdl_bench_rung_measure(&sol, &ref, NULL, &r);
    CHECK(r.rms == 0.0);
}

/* A reference at two of four points (a sample): the rung is measured
 * there only, and its RMS has a standard error as an estimate of the RMS
 * over all four. */
static void test_measure_sample(void)
{
    double Ex[4] = {101, 99, 102, 97}, sx[4] = {1.01, 0.99, 1.02, 0.97};
    double Er[2] = {100, 100}, sr[2] = {0.5, 0.5};
    cdl_solution ref, sol;
    cdl_grid_solution gr, gx;
    fake_solution(&sol, &gx, Ex, sx, 4);
    fake_solution(&ref, &gr, Er, sr, 2);
    size_t idx[2] = {1, 2}, grid_of[1] = {0};
    size_t *index[1] = {idx};
    cdl_bench_sample sample;
    fake_sample(&sample, grid_of, index, 4, 2);
    cdl_bench_rung r;
    cdl_bench_rung_measure(&sol, &ref, &sample, &r);
    /* points 1 and 2: rel -0.01 and 0.02, the reference's 0.005 each:
     * y = 1e-4 - 25e-6 and 4e-4 - 25e-6 */
    double y1 = 1e-4 - 25e-6, y2 = 4e-4 - 25e-6, m = 0.5 * (y1 + y2);
    CHECK_REL(r.rms, sqrt(m), 1e-12);
    /* S^2 = (y1 - y2)^2 / 2 (n - 1 = 1), held to at least the 2 m^2 of
     * normal errors (x is the same everywhere: 2 R^2 X2 = 2 m^2);
     * Var(mean) = (1 - 2/4) S^2 / 2 */
    double S2 = fmax(0.5 * (y1 - y2) * (y1 - y2), 2.0 * m * m);
    CHECK(S2 > 0.5 * (y1 - y2) * (y1 - y2)); /* the floor is what this checks */
    double var_mean = 0.5 * S2 / 2.0;
    CHECK_REL(r.rms_sd, sqrt(var_mean) / (2.0 * sqrt(m)), 1e-9);
    CHECK_REL(r.worst, 0.02, 1e-12);
    /* |d| <= 2 sqrt(0.99^2 + 0.25) and 2 sqrt(1.02^2 + 0.25) */
    CHECK(r.within2 == 1.0);
    /* the stated RMS is the rung's own, over all its points */
    CHECK_REL(r.stated_rms, 0.01, 1e-12);

    /* every point sampled: no sampling error */
    sample.total = 2;
    cdl_bench_rung_measure(&sol, &ref, &sample, &r);
    CHECK(r.rms_sd == 0.0);
}

/* The sampling standard error is calibrated: a population of 600 points
 * whose relative errors are normal with sigmas spread by `spread` (from
 * 0.1 % up; 1: all alike, as a solver holding every point to its target
 * makes them), 4000 simple random samples of 24 points (the default
 * --reference-points), each RMS estimate within 2 of its stated standard
 * error of the population's RMS about 95 % of the time. The delta method
 * and a 24-point variance are approximate for a skewed quantity (the mean
 * of squares), so the share is held to [0.90, 0.98]: 4000 draws put its
 * own noise at 0.35 %, so this fails for an error stated a quarter too
 * small or too large. Not checked, as it is not met: with sigmas spread
 * by 3 the share is 0.90, by 20 only 0.80 (a small sample misses the few
 * points of large error and understates both the RMS and its spread). */
static void test_measure_sample_calibrated(double spread)
{
    enum { N = 600, n = 24, TRIALS = 4000 };
    static double Ex[N], sx[N];
    double sum2 = 0.0;
    uint64_t state = 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < N; ++i) {
        /* xorshift64 for the test's own draws (Marsaglia 2003) */
        double u[3];
        for (int k = 0; k < 3; ++k) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            u[k] = ((double)(state >> 11) + 0.5) / 9007199254740992.0;
        }
        double sigma = 0.001 * pow(spread, u[0]);
        /* a normal deviate by Box-Muller */
        double e = sigma * sqrt(-2.0 * log(u[1])) * cos(2.0 * 3.141592653589793 * u[2]);
        Ex[i] = 100.0 * (1.0 + e);
        sx[i] = 100.0 * sigma;
        sum2 += e * e;
    }
    double truth = sqrt(sum2 / N);
    int within = 0, order[N];
    for (int t = 0; t < TRIALS; ++t) {
        for (int i = 0; i < N; ++i) order[i] = i;
        size_t idx[n];
        for (int k = 0; k < n; ++k) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            int j = k + (int)(state % (uint64_t)(N - k));
            int tmp = order[k];
            order[k] = order[j];
            order[j] = tmp;
        }
        /* the sample's indices rising, as cdl_bench_sample has them */
        int m = 0;
        for (int i = 0; i < N; ++i)
            for (int k = 0; k < n; ++k)
                if (order[k] == i) idx[m++] = (size_t)i;
        double Er[n], sr[n];
        for (int k = 0; k < n; ++k) {
            Er[k] = 100.0;
            sr[k] = 0.0;
        }
        cdl_solution ref, sol;
        cdl_grid_solution gr, gx;
        fake_solution(&sol, &gx, Ex, sx, N);
        fake_solution(&ref, &gr, Er, sr, n);
        size_t grid_of[1] = {0};
        size_t *index[1] = {idx};
        cdl_bench_sample sample;
        fake_sample(&sample, grid_of, index, N, n);
        cdl_bench_rung r;
        cdl_bench_rung_measure(&sol, &ref, &sample, &r);
        within += fabs(r.rms - truth) <= 2.0 * r.rms_sd;
    }
    double share = (double)within / TRIALS;
    CHECK_MSG(share >= 0.90 && share <= 0.98, "%.3f of sampled RMS within 2 stated sigma of the RMS over all points",
              share);
    printf("sampled RMS within 2 stated sigma: %.3f (RMS over all points %.4f %%)\n", share, 100.0 * truth);
}

static void test_time_at_rms(void)
{
    cdl_bench_rung pt[2];
    memset(pt, 0, sizeof pt);
    pt[0].rms = 0.02;
    pt[0].seconds = 1.0;
    pt[1].rms = 0.01;
    pt[1].seconds = 4.0;
    /* halfway in log RMS: halfway in log time */
    CHECK_REL(cdl_bench_time_at_rms(pt, 2, sqrt(0.02 * 0.01)), 2.0, 1e-12);
    /* past the ends: t ~ RMS^-2 */
    CHECK_REL(cdl_bench_time_at_rms(pt, 2, 0.005), 16.0, 1e-12);
    CHECK_REL(cdl_bench_time_at_rms(pt, 2, 0.04), 0.25, 1e-12);
}

static const char *scene_json(double rho)
{
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
             "\"inward\": true, \"reflectance\": %g}], \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0], "
             "\"flux_lm\": 1000}], \"grids\": [{\"name\": \"wall\", \"type\": \"points\", \"points\": "
             "[{\"p\": [0, 0, -0.9], \"n\": [0, 0, 1]}, {\"p\": [0.9, 0, 0], \"n\": [-1, 0, 0]}]}]}",
             rho);
    return buf;
}

static void test_key(void)
{
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *a = NULL, *b = NULL, *c = NULL;
    CHECK(cdl_scene_load_string(scene_json(0.5), "a.json", &a, &err) == CDL_OK);
    CHECK(cdl_scene_load_string(scene_json(0.5), "b.json", &b, &err) == CDL_OK);
    CHECK(cdl_scene_load_string(scene_json(0.6), "c.json", &c, &err) == CDL_OK);
    if (!a || !b || !c) return;
    uint64_t ka = 0, kb = 1, kc = 0, kt = 0, ks = 0;
    CHECK(cdl_bench_reference_key(a, 2e-4, &ka, &err) == CDL_OK);
    CHECK(cdl_bench_reference_key(b, 2e-4, &kb, &err) == CDL_OK);
    CHECK(cdl_bench_reference_key(c, 2e-4, &kc, &err) == CDL_OK);
    CHECK(cdl_bench_reference_key(a, 1e-4, &kt, &err) == CDL_OK);
    b->settings.seed = 2;
    CHECK(cdl_bench_reference_key(b, 2e-4, &ks, &err) == CDL_OK);
    CHECK_MSG(ka == kb, "the same scene under another name: the same key");
    CHECK_MSG(ka != kc, "another reflectance: another key");
    CHECK_MSG(ka != kt, "another target: another key");
    CHECK_MSG(ka != ks, "another seed: another key");
    b->grids[0].points[1].x = 0.8;
    CHECK(cdl_bench_reference_key(b, 2e-4, &kb, &err) == CDL_OK);
    CHECK_MSG(kb != ks, "a moved point: another key");
    cdl_scene_release(a);
    cdl_scene_release(b);
    cdl_scene_release(c);
}

static void test_reference_read(void)
{
    char dir[512], path[600];
    CHECK(fixture_folder("bench_ladder", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/wall.csv", dir);
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *s = NULL;
    CHECK(cdl_scene_load_string(scene_json(0.5), "a.json", &s, &err) == CDL_OK);
    if (!s) return;
    cdl_solution ref;
    CHECK(cdl_bench_reference_read(dir, s, &ref, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "wall.csv: cannot be read") != NULL);
    fixture_write_file(path, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx\n"
                             "0,0,-0.9,0,0,1,180,100,80,0.5\n0.9,0,0,-1,0,0,181,100,81,0.25\n");
    cdl_error_clear(&err);
    CHECK(cdl_bench_reference_read(dir, s, &ref, &err) == CDL_OK);
    if (err.status == CDL_OK) {
        CHECK(ref.grid_count == 1 && ref.grids[0].grid.count == 2);
        CHECK(ref.grids[0].E[1] == 181 && ref.grids[0].E_stderr[1] == 0.25 && ref.grids[0].E_indirect[0] == 80);
        cdl_solution_clear(&ref);
    }
    fixture_write_file(path, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx\n"
                             "0,0,-0.9,0,0,1,180,100,80,0.5\n0.8,0,0,-1,0,0,181,100,81,0.25\n");
    cdl_error_clear(&err);
    CHECK(cdl_bench_reference_read(dir, s, &ref, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "wall.csv line 3: not the scene's point 1") != NULL, "%s", err.message);
    fixture_write_file(path, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx\n0,0,-0.9,0,0,1,180,100,80,0.5\n");
    cdl_error_clear(&err);
    CHECK(cdl_bench_reference_read(dir, s, &ref, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "1 points, the scene has 2") != NULL, "%s", err.message);
    cdl_scene_release(s);
}

/* Two grids, 6 + 4 points: samples of them. */
static void test_sample(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
        "\"inward\": true, \"reflectance\": 0.5}], \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0], "
        "\"flux_lm\": 1000}], \"grids\": [{\"name\": \"a\", \"type\": \"rect\", \"origin\": [-0.5, -0.5, -0.5], "
        "\"u\": [1, 0, 0], \"v\": [0, 1, 0], \"nu\": 3, \"nv\": 2, \"outputs\": [\"ao\"]}, {\"name\": \"b\", "
        "\"type\": \"points\", \"points\": [{\"p\": [0, 0, 0.1], \"n\": [0, 0, 1]}, {\"p\": [0, 0, 0.2], \"n\": [0, 1, 0]}, "
        "{\"p\": [0, 0, 0.3], \"n\": [1, 0, 0]}, {\"p\": [0, 0, 0.4], \"n\": [0, 0, -1]}]}]}";
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    CHECK(cdl_scene_load_string(json, "s.json", &scene, &err) == CDL_OK);
    if (!scene) return;
    cdl_grid full[2];
    CHECK(cdl_grid_build(&scene->grids[0], &full[0], &err) == CDL_OK);
    CHECK(cdl_grid_build(&scene->grids[1], &full[1], &err) == CDL_OK);

    /* every point (0, or at least as many as there are): the scene's own grids */
    cdl_bench_sample all;
    CHECK(cdl_bench_sample_build(scene, 0, &all, &err) == CDL_OK);
    CHECK(all.total == 10 && all.count == 10 && all.scene.grids == scene->grids && all.scene.grid_count == 2);
    CHECK(all.index[0][5] == 5 && all.index[1][3] == 3 && all.grid_of[1] == 1);
    CHECK_MSG(all.scene.settings.seed == cdl_bench_reference_seed(scene->settings.seed) &&
                  all.scene.settings.seed != scene->settings.seed,
              "the reference has a seed of its own");
    cdl_bench_sample_release(&all);
    CHECK(cdl_bench_sample_build(scene, 10, &all, &err) == CDL_OK);
    CHECK(all.count == 10 && all.scene.grids == scene->grids);
    cdl_bench_sample_release(&all);

    /* 4 of 10: points grids of the chosen points, as the originals have them */
    for (size_t n = 1; n < 10; ++n) {
        cdl_bench_sample s, t;
        CHECK(cdl_bench_sample_build(scene, n, &s, &err) == CDL_OK);
        CHECK(cdl_bench_sample_build(scene, n, &t, &err) == CDL_OK);
        CHECK(s.total == 10 && s.count == n);
        size_t seen = 0;
        for (size_t g = 0; g < s.scene.grid_count; ++g) {
            const cdl_grid_spec *spec = &s.scene.grids[g];
            const cdl_grid *orig = &full[s.grid_of[g]];
            CHECK(spec->kind == CDL_GRID_POINTS && spec->point_count > 0 && !spec->want_ao);
            CHECK(strcmp(spec->name, scene->grids[s.grid_of[g]].name) == 0);
            CHECK(g == 0 || s.grid_of[g] > s.grid_of[g - 1]);
            for (size_t j = 0; j < spec->point_count; ++j) {
                size_t i = s.index[g][j];
                CHECK(i < orig->count && (j == 0 || i > s.index[g][j - 1]));
                CHECK(cdl_vec3_length(cdl_vec3_sub(spec->points[j], orig->points[i])) == 0.0);
                CHECK(cdl_vec3_length(cdl_vec3_sub(spec->normals[j], orig->normals[i])) == 0.0);
            }
            seen += spec->point_count;
            /* the same scene, the same sample */
            CHECK(g < t.scene.grid_count && t.grid_of[g] == s.grid_of[g] &&
                  memcmp(t.index[g], s.index[g], spec->point_count * sizeof *s.index[g]) == 0);
        }
        CHECK_MSG(seen == n, "%zu points sampled, %zu asked", seen, n);
        cdl_bench_sample_release(&s);
        cdl_bench_sample_release(&t);
    }
    cdl_grid_release(&full[0]);
    cdl_grid_release(&full[1]);
    cdl_scene_release(scene);
}

/* bench.csv: a rung the reference cannot resolve has "<ref" for its RMS,
 * one it can has the figure. */
static void test_csv_below_reference(void)
{
    char dir[512], path[600];
    CHECK(fixture_folder("bench_csv", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/bench.csv", dir);
    cdl_bench_row rows[3];
    memset(rows, 0, sizeof rows);
    const char *labels[3] = {"pathtrace_draft", "pathtrace_high", "icache_high"};
    for (int k = 0; k < 3; ++k) {
        snprintf(rows[k].label, sizeof rows[k].label, "%s", labels[k]);
        rows[k].quality = k ? "high" : "draft";
        rows[k].rung.method = k < 2 ? CDL_METHOD_PATHTRACE : CDL_METHOD_ICACHE;
        rows[k].rung.target = k ? 0.001 : 0.02;
        rows[k].rung.rms = k ? 1.5e-4 : 0.0213;
        rows[k].rung.worst = 0.05;
        rows[k].rung.within2 = 0.95;
    }
    rows[1].below_reference = 1;
    rows[2].skipped = 1;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_bench_report_write_csv(path, rows, 3, &err) == CDL_OK);
    size_t len = 0;
    char *text = fixture_read_file(path, &len);
    CHECK(text != NULL);
    if (!text) return;
    CHECK_MSG(strcmp(text, "label,method,quality,target_error,seconds,rays,records,rms_rel_error,max_rel_error,"
                           "within_2_sigma\n"
                           "pathtrace_draft,pathtrace,draft,0.02,0.000,0,0,0.0213,0.05,0.95\n"
                           "pathtrace_high,pathtrace,high,0.001,0.000,0,0,<ref,0.05,0.95\n") == 0,
              "%s", text);
    free(text);
}

int main(void)
{
    test_measure();
    test_measure_sample();
    test_measure_sample_calibrated(1.0);
    test_measure_sample_calibrated(2.0);
    test_sample();
    test_csv_below_reference();
    test_time_at_rms();
    test_key();
    test_reference_read();
    return check_finish();
}
