/* test_bench_ladder.c - the ladder's measurements on hand-made solutions,
 * the time interpolation, the reference reader and the reference's key. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "solver/bench/bench_ladder.h"

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

static void test_measure(void)
{
    double Er[4] = {100, 100, 100, 100}, sr[4] = {0, 0, 0, 0};
    double Ex[4] = {101, 99, 102, 97}, sx[4] = {1, 1, 1, 1};
    cdl_solution ref, sol;
    cdl_grid_solution gr, gx;
    fake_solution(&ref, &gr, Er, sr, 4);
    fake_solution(&sol, &gx, Ex, sx, 4);
    cdl_bench_rung r;
    cdl_bench_rung_measure(&sol, &ref, &r);
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
    cdl_bench_rung_measure(&sol, &ref, &r);
    CHECK_REL(r.rms, sqrt((15e-4 - 4e-4) / 4.0), 1e-12);
    /* ... never below zero */
    fake_solution(&sol, &gx, Er, sx, 4);
    cdl_bench_rung_measure(&sol, &ref, &r);
    CHECK(r.rms == 0.0);
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
        cdl_solution_release(&ref);
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

int main(void)
{
    test_measure();
    test_time_at_rms();
    test_key();
    test_reference_read();
    return check_finish();
}
