/* A path vertex's next-event estimate with one light drawn
 * (cdl_direct_estimate_one_light) against the estimate that samples every
 * light (cdl_direct_estimate_point): both are unbiased estimates of the same
 * direct illuminance, so their means over many draws must agree within
 * their standard errors, at points lit, half hidden and dark, for every
 * kind of light (spot, point, a near-field downlight's opening, a linear
 * luminaire's opening, a Lambertian panel), and at a
 * point beside the downlight's opening that its far-field guess calls dark
 * while the opening's near edge lights it (only the even share of the draw
 * reaches it there). With delta lights alone the draw is in proportion to
 * their exact values: a point seeing them all reads their sum exactly,
 * and one seeing none reads exactly 0. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "base/rng.h"
#include "solver/direct/direct.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

#define ROOM                                                                                                          \
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": true,"   \
    " \"reflectance\": 0}, {\"type\": \"sphere\", \"center\": [3, 2.5, 1.4], \"radius\": 0.35, \"reflectance\": 0},"  \
    " {\"type\": \"rect\", \"origin\": [1, 1, 1.1], \"u\": [1.5, 0, 0], \"v\": [0, 0.8, 0], \"reflectance\": 0}],"    \
    " \"luminaires\": [{\"type\": \"spot\", \"position\": [2, 2, 2.9], \"direction\": [0.2, 0.1, -1],"                \
    " \"intensity_cd\": 3000, \"half_angle\": 35, \"falloff_start\": 25},"                                            \
    " {\"type\": \"point\", \"position\": [4.5, 3.5, 2.5], \"intensity_cd\": 400}"

#define GRID                                                                                                          \
    " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [1, 1, 0], \"n\": [0, 0, 1]}]}],"       \
    " \"solver\": {\"method\": \"direct\"}}"

static const char *mixed_json =
    ROOM ", {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/downlight.ies\", "
         "\"position\": [3, 2.5, 2.95], \"body\": false},"
         " {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/linear.ies\", "
         "\"position\": [1.5, 3.5, 2.4], \"rotation\": [0, 0, 30], \"body\": false},"
         " {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [4, 1, 2.99], \"u\": [0, 0.6, 0], "
         "\"v\": [0.6, 0, 0]}, \"luminance_cd_m2\": 2500}]," GRID;

static const char *delta_json = ROOM "]," GRID;

/* The downlight and a faint point across the room. */
static const char *beside_json =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": true,"
    " \"reflectance\": 0}], \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR
    "/data/office/downlight.ies\", \"position\": [3, 2.5, 2.95], \"body\": false},"
    " {\"type\": \"point\", \"position\": [0.5, 0.5, 2.5], \"intensity_cd\": 10}]," GRID;

typedef struct fixture {
    cdl_scene *scene;
    cdl_scene_geometry *geometry;
    cdl_scene_lights lights;
    cdl_direct_context ctx;
} fixture;

static int fixture_open(fixture *f, const char *json)
{
    cdl_error err;
    memset(f, 0, sizeof *f);
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/one_light.json", &f->scene, &err), &err);
    if (!f->scene) return 0;
    CHECK_OK(cdl_scene_geometry_build(f->scene, &f->geometry, &err), &err);
    CHECK_OK(cdl_scene_lights_build(f->scene, f->geometry, &f->lights, &err), &err);
    f->ctx.geometry = f->geometry;
    f->ctx.rays = cdl_scene_geometry_rays(f->geometry);
    cdl_scene_geometry_ray_offsets(f->geometry, &f->ctx.offsets);
    f->ctx.lights = f->lights.lights;
    f->ctx.light_count = f->lights.count;
    f->ctx.seed = 11;
    return 1;
}

static void fixture_close(fixture *f)
{
    cdl_scene_lights_release(&f->lights);
    cdl_scene_geometry_release(f->geometry);
    cdl_scene_release(f->scene);
}

typedef struct moments {
    double mean, var_of_mean;
} moments;

/* The mean of `draws` estimates at (p, n) and its variance: one = 0 every
 * light, 1 one light drawn, 2 one light drawn with the closed forms apart. */
static moments average(const fixture *f, int one, cdl_vec3 p, cdl_vec3 n, size_t point, size_t draws)
{
    int apart = one == 2;
    double sum = 0.0, sum2 = 0.0;
    cdl_direct_sample_stats stats = {0};
    for (size_t k = 0; k < draws; ++k) {
        cdl_rng_key key = {f->ctx.seed, cdl_rng_stream_id((uint64_t)point, (uint64_t)k, 0x6f6e65 + (uint64_t)one)};
        double e = one ? cdl_direct_estimate_one_light(&f->ctx, key, p, n, apart, NULL, &stats)
                       : cdl_direct_estimate_point(&f->ctx, key, p, n, NULL, &stats);
        sum += e;
        sum2 += e * e;
    }
    moments m;
    m.mean = sum / (double)draws;
    m.var_of_mean = fmax(0.0, sum2 / (double)draws - m.mean * m.mean) / (double)(draws - 1);
    return m;
}

static void test_unbiased(void)
{
    fixture f;
    if (!fixture_open(&f, mixed_json)) return;
    /* The floor on a lattice (lit, in the sphere's and the plate's
     * shadows), the walls and the ceiling, the plate's top and underside. */
    cdl_vec3 p[64], n[64];
    size_t count = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 5; ++j) {
            p[count] = cdl_vec3_make(0.5 + i, 0.5 + j, 0.0);
            n[count++] = cdl_vec3_make(0, 0, 1);
        }
    const double walls[][6] = {{0, 2.5, 1.5, 1, 0, 0}, {6, 1.5, 2.0, -1, 0, 0}, {3, 0, 1.0, 0, 1, 0},
                               {2, 5, 2.5, 0, -1, 0},  {3, 2.5, 3, 0, 0, -1},   {1.7, 1.4, 1.1, 0, 0, 1},
                               {1.7, 1.4, 1.1, 0, 0, -1}, {3, 2.5, 1.05, 0, 0, -1}, {2.2, 1.2, 0.6, 0.3, 0.2, 0.9}};
    for (size_t w = 0; w < sizeof walls / sizeof *walls; ++w) {
        p[count] = cdl_vec3_make(walls[w][0], walls[w][1], walls[w][2]);
        n[count++] = cdl_vec3_normalize(cdl_vec3_make(walls[w][3], walls[w][4], walls[w][5]));
    }
    const size_t draws = 40000;
    size_t lit = 0;
    double worst = 0.0;
    for (size_t i = 0; i < count; ++i) {
        moments all = average(&f, 0, p[i], n[i], i, draws);
        lit += all.mean > 0.0;
        for (int mode = 1; mode <= 2; ++mode) {
            moments one = average(&f, mode, p[i], n[i], i, draws);
            double sd = sqrt(one.var_of_mean + all.var_of_mean);
            double z = sd > 0.0 ? (one.mean - all.mean) / sd : (one.mean == all.mean ? 0.0 : INFINITY);
            worst = fmax(worst, fabs(z));
            /* 78 comparisons: a Gaussian |z| beyond 4.5 has odds 7e-6 each. */
            CHECK_MSG(fabs(z) <= 4.5, "point %zu (%.3f, %.3f, %.3f), %s: one light %.6g +- %.3g, every light %.6g +- %.3g",
                      i, p[i].x, p[i].y, p[i].z, mode == 2 ? "closed forms apart" : "all drawn", one.mean,
                      sqrt(one.var_of_mean), all.mean, sqrt(all.var_of_mean));
        }
    }
    fprintf(stderr, "one light against every light: %zu points (%zu lit), worst |z| %.2f\n", count, lit, worst);
    CHECK(lit + 4 >= count);
    fixture_close(&f);
}

/* Beside the downlight's opening, 1.3 cm under its plane and 0.13 m from
 * its axis: 84 degrees from the nadir seen from its centre (the file is
 * dark beyond 80), so its far-field guess is 0, but 77 from its near rim,
 * which lights the point. Only the even share of the draw reaches it; the
 * faint point across the room takes the rest. */
static void test_beside_opening(void)
{
    fixture f;
    if (!fixture_open(&f, beside_json)) return;
    cdl_vec3 p = cdl_vec3_make(3.13, 2.5, 2.937), n = cdl_vec3_normalize(cdl_vec3_make(-1, 0, 0.3));
    moments one = average(&f, 1, p, n, 0, 40000), all = average(&f, 0, p, n, 0, 40000);
    double sd = sqrt(one.var_of_mean + all.var_of_mean);
    fprintf(stderr, "beside the opening: one light %.6g +- %.3g lx, every light %.6g +- %.3g lx\n", one.mean,
            sqrt(one.var_of_mean), all.mean, sqrt(all.var_of_mean));
    /* The opening gives far more than the faint point (10 cd at 3.3 m: under 1 lx). */
    CHECK_MSG(all.mean > 10.0, "beside the opening: %.3g lx, expected the rim's light", all.mean);
    CHECK_MSG(fabs(one.mean - all.mean) <= 4.5 * sd, "beside the opening: %.6g against %.6g (sd %.3g)", one.mean,
              all.mean, sd);
    fixture_close(&f);
}

static void test_delta_lights(void)
{
    fixture f;
    if (!fixture_open(&f, delta_json)) return;
    cdl_direct_sample_stats stats = {0};
    /* Seeing both (the floor under the spot, in the point's view): their sum. */
    cdl_vec3 p = cdl_vec3_make(2.3, 2.2, 0.0), n = cdl_vec3_make(0, 0, 1);
    double sum = 0.0;
    for (size_t l = 0; l < f.lights.count; ++l) {
        cdl_delta_light d;
        if (cdl_emitter_eval_delta(f.lights.lights[l].emitter, p, n, &d)) sum += d.E.lx;
    }
    CHECK(sum > 0.0);
    for (uint64_t k = 0; k < 64; ++k) {
        cdl_rng_key key = {3, cdl_rng_stream_id(1, k, 2)};
        double e = cdl_direct_estimate_one_light(&f.ctx, key, p, n, 0, NULL, &stats);
        CHECK_MSG(fabs(e - sum) <= 1e-12 * sum, "draw %llu: %.17g against the sum %.17g", (unsigned long long)k, e,
                  sum);
    }
    /* Inside the sphere: nothing arrives, exactly 0 whichever light is drawn. */
    p = cdl_vec3_make(3, 2.5, 1.4);
    for (uint64_t k = 0; k < 64; ++k) {
        cdl_rng_key key = {3, cdl_rng_stream_id(2, k, 2)};
        double e = cdl_direct_estimate_one_light(&f.ctx, key, p, n, 0, NULL, &stats);
        CHECK_MSG(e == 0.0, "inside the sphere, draw %llu: %.17g", (unsigned long long)k, e);
    }
    /* One shadow ray per estimate: 128 estimates, 128 rays at most. */
    CHECK_MSG(stats.rays <= 128, "%llu shadow rays for 128 estimates", (unsigned long long)stats.rays);
    fixture_close(&f);
}

int main(void)
{
    test_unbiased();
    test_beside_opening();
    test_delta_lights();
    return check_finish();
}
