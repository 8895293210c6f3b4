/* The panes of a glazed room as portals of the sky (solver/direct/sky_portals.h).
 *
 * The room: 5 x 4 x 3 m, black inside, a 2 x 1.2 m pane of normal
 * transmittance 0.72 in the facade at x = 5. Checked:
 *  - the portals' density in solid angle integrates to 1 over the sphere
 *    (every pane triangle is seen from p along some direction: sum of
 *    A_t / A), by Monte Carlo over uniform directions, and drawing from it
 *    gives the pane's projected solid angle (Lambert's contour integral,
 *    psa_rect) as the mean of cos / pdf;
 *  - cdl_direct_estimate_point with the portals, and with the sky's own
 *    sampler alone, both agree with the direct illuminance computed by
 *    quadrature over the pane, E = int_pane L(w) T(theta) cos(w, n) dw,
 *    dw = |cos theta| dA / d^2 (T: radiometry/glass.h at the pane's angle
 *    of incidence), under a uniform upper-hemisphere sky and the CIE
 *    overcast sky (L = Lz (1 + 2 sin gamma) / 3, Moon and Spencer 1942);
 *  - inside the room the portals cut the estimate's variance at least
 *    tenfold (the pane is a few per cent of the hemisphere);
 *  - outside the building, where the pane leads only into the dark room,
 *    both ways agree with each other (the sky's sampler does the work);
 *  - under the ceiling, which sees the pane only towards the dark ground,
 *    every estimate is exactly 0. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "exact_forms.h"
#include "base/rng.h"
#include "radiometry/glass.h"
#include "radiometry/sampling.h"
#include "solver/direct/direct.h"
#include "solver/direct/sky_portals.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

#define ROOM_JSON(SKY)                                                                                                \
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [5, 4, 3], \"inward\": true,"   \
    " \"reflectance\": 0, \"open\": [\"+x\"]},"                                                                       \
    " {\"type\": \"polygon\", \"vertices\": [[5, 0, 0], [5, 4, 0], [5, 4, 3], [5, 0, 3]],"                            \
    " \"holes\": [[[5, 1, 0.9], [5, 3, 0.9], [5, 3, 2.1], [5, 1, 2.1]]], \"reflectance\": 0},"                        \
    " {\"type\": \"rect\", \"origin\": [5, 1, 0.9], \"u\": [0, 2, 0], \"v\": [0, 0, 1.2], \"transmittance\": 0.72}]," \
    " \"luminaires\": [" SKY "],"                                                                                     \
    " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [1, 1, 0], \"n\": [0, 0, 1]}]}],"       \
    " \"solver\": {\"method\": \"direct\"}}"

#define UNIFORM_L 5000.0
#define ZENITH_L 8000.0

static const char *uniform_json =
    ROOM_JSON("{\"type\": \"environment\", \"luminance_cd_m2\": 5000, \"hemisphere\": \"upper\"}");
static const char *overcast_json =
    ROOM_JSON("{\"type\": \"environment\", \"sky\": \"cie_overcast\", \"zenith_luminance_cd_m2\": 8000}");

static const cdl_vec3 PANE_ORIGIN = {5, 1, 0.9}, PANE_U = {0, 2, 0}, PANE_V = {0, 0, 1.2};

typedef struct fixture {
    cdl_scene *scene;
    cdl_scene_geometry *geometry;
    cdl_scene_lights lights;
    cdl_sky_portals portals;
    cdl_direct_context ctx;
} fixture;

static int fixture_open(fixture *f, const char *json)
{
    cdl_error err;
    memset(f, 0, sizeof *f);
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/sky_portals.json", &f->scene, &err), &err);
    if (!f->scene) return 0;
    CHECK_OK(cdl_scene_geometry_build(f->scene, &f->geometry, &err), &err);
    CHECK_OK(cdl_scene_lights_build(f->scene, f->geometry, &f->lights, &err), &err);
    CHECK_OK(cdl_sky_portals_build(f->geometry, &f->portals, &err), &err);
    f->ctx.geometry = f->geometry;
    f->ctx.rays = cdl_scene_geometry_rays(f->geometry);
    cdl_scene_geometry_ray_offsets(f->geometry, &f->ctx.offsets);
    f->ctx.lights = f->lights.lights;
    f->ctx.light_count = f->lights.count;
    f->ctx.seed = 5;
    f->ctx.portals = &f->portals;
    return 1;
}

static void fixture_close(fixture *f)
{
    cdl_sky_portals_release(&f->portals);
    cdl_scene_lights_release(&f->lights);
    cdl_scene_geometry_release(f->geometry);
    cdl_scene_release(f->scene);
}

/* The sky's luminance towards unit w: 0 below the horizon. */
static double sky_luminance(int overcast, cdl_vec3 w)
{
    if (!(w.z > 0.0)) return 0.0;
    return overcast ? ZENITH_L * (1.0 + 2.0 * w.z) / 3.0 : UNIFORM_L;
}

/* E at (p, n) through the pane alone (the point inside the room), by the
 * midpoint rule over 600 x 600 cells of the pane: the integrand is smooth
 * at the points taken, 0.5 m or more from the pane, and the rule's error
 * (h^2 / 24 times the second derivative, h = 2 mm against distances of
 * 0.5 m and up) is under 1e-5 of E. */
static double pane_exact(const cdl_glass *glass, int overcast, cdl_vec3 p, cdl_vec3 n)
{
    const int cells = 600;
    cdl_vec3 pane_normal = cdl_vec3_normalize(cdl_vec3_cross(PANE_U, PANE_V));
    double dA = cdl_vec3_length(cdl_vec3_cross(PANE_U, PANE_V)) / (double)(cells * cells), E = 0.0;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            cdl_vec3 x = cdl_vec3_madd(cdl_vec3_madd(PANE_ORIGIN, (i + 0.5) / cells, PANE_U), (j + 0.5) / cells,
                                       PANE_V);
            cdl_vec3 d = cdl_vec3_sub(x, p);
            double r2 = cdl_vec3_dot(d, d);
            cdl_vec3 w = cdl_vec3_scale(d, 1.0 / sqrt(r2));
            double c = cdl_vec3_dot(n, w);
            if (!(c > 0.0)) continue;
            double c_pane = fabs(cdl_vec3_dot(pane_normal, w));
            E += sky_luminance(overcast, w) * cdl_glass_transmittance(glass, c_pane) * c * c_pane * dA / r2;
        }
    return E;
}

typedef struct moments {
    double mean, var_of_mean;
} moments;

static moments average(const fixture *f, int with_portals, cdl_vec3 p, cdl_vec3 n, size_t point, size_t draws)
{
    cdl_direct_context ctx = f->ctx;
    if (!with_portals) ctx.portals = NULL;
    cdl_direct_sample_stats stats = {0};
    double sum = 0.0, sum2 = 0.0;
    for (size_t k = 0; k < draws; ++k) {
        cdl_rng_key key = {ctx.seed, cdl_rng_stream_id((uint64_t)point, (uint64_t)k, 0x706f7274 + (uint64_t)with_portals)};
        double e = cdl_direct_estimate_point(&ctx, key, p, n, NULL, &stats);
        /* the sky's closed form less what its sample finds hidden can go
         * below 0; through the portals every term is L cos T / pdf >= 0 */
        CHECK_MSG(isfinite(e) && (e >= 0.0 || !with_portals), "estimate %.17g at (%.2f, %.2f, %.2f)", e, p.x, p.y,
                  p.z);
        sum += e;
        sum2 += e * e;
    }
    moments m;
    m.mean = sum / (double)draws;
    m.var_of_mean = fmax(0.0, sum2 / (double)draws - m.mean * m.mean) / (double)(draws - 1);
    return m;
}

static void test_density(void)
{
    fixture f;
    if (!fixture_open(&f, uniform_json)) return;
    CHECK_MSG(f.portals.count == 2, "%zu portal triangles, expected the pane's 2", f.portals.count);
    CHECK_REL(f.portals.area, 2.4, 1e-12);
    const cdl_vec3 pts[] = {{1, 2, 0}, {4, 2, 1.5}, {7, 2, 0.5}, {2.5, 0.5, 2.8}};
    const cdl_vec3 up = {0, 0, 1};
    for (size_t i = 0; i < sizeof pts / sizeof *pts; ++i) {
        /* int pdf dw over the sphere = E_uniform[4 pi pdf] = 1 */
        const size_t draws = 2000000;
        double sum = 0.0, sum2 = 0.0;
        for (size_t k = 0; k < draws; ++k) {
            double u[2];
            cdl_rng_uniform2((cdl_rng_key){7, cdl_rng_stream_id(i, 0, 1)}, k, u);
            double v = 4.0 * CDL_PI * cdl_sky_portals_pdf(&f.portals, pts[i], cdl_sample_uniform_sphere(u[0], u[1]));
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / draws, sd = sqrt(fmax(0.0, sum2 / draws - mean * mean) / (draws - 1));
        /* 4 points, 4.5 sigma: a Gaussian miss has odds 3e-5 in all */
        CHECK_MSG(fabs(mean - 1.0) <= 4.5 * sd, "point %zu: the density integrates to %.5f +- %.2g", i, mean, sd);
        /* E_portals[cos / pdf] over the half facing up = the projected solid angle */
        double psa = psa_rect(pts[i], up, PANE_ORIGIN, PANE_U, PANE_V);
        sum = sum2 = 0.0;
        for (size_t k = 0; k < draws; ++k) {
            double u[2], pdf;
            cdl_vec3 w;
            cdl_rng_uniform2((cdl_rng_key){7, cdl_rng_stream_id(i, 1, 1)}, k, u);
            double v = 0.0;
            if (cdl_sky_portals_sample(&f.portals, pts[i], u[0], u[1], &w, &pdf)) {
                CHECK_REL(pdf, cdl_sky_portals_pdf(&f.portals, pts[i], w), 1e-12);
                v = fmax(0.0, w.z) / pdf;
            }
            sum += v;
            sum2 += v * v;
        }
        mean = sum / draws;
        sd = sqrt(fmax(0.0, sum2 / draws - mean * mean) / (draws - 1));
        CHECK_MSG(fabs(mean - psa) <= 4.5 * sd + 1e-12,
                  "point %zu: drawn from the panes, projected solid angle %.6f +- %.2g, Lambert %.6f", i, mean, sd,
                  psa);
    }
    fixture_close(&f);
}

static void test_room(const char *json, int overcast)
{
    fixture f;
    if (!fixture_open(&f, json)) return;
    cdl_glass glass;
    cdl_error err;
    CHECK_OK(cdl_glass_from_transmittance(0.72, &glass, &err), &err);
    const char *sky = overcast ? "overcast" : "uniform";
    /* inside: the floor near and far, the work plane beside the window,
     * the back wall facing it, a side wall */
    const double inside[][6] = {{1, 2, 0, 0, 0, 1},   {3.5, 1.5, 0, 0, 0, 1}, {4.5, 2.2, 0.8, 0, 0, 1},
                                {0, 2, 1.5, 1, 0, 0}, {2.5, 0, 1.2, 0, 1, 0}};
    const size_t draws = 40000;
    double gain_min = INFINITY;
    for (size_t i = 0; i < sizeof inside / sizeof *inside; ++i) {
        cdl_vec3 p = cdl_vec3_make(inside[i][0], inside[i][1], inside[i][2]);
        cdl_vec3 n = cdl_vec3_make(inside[i][3], inside[i][4], inside[i][5]);
        double exact = pane_exact(&glass, overcast, p, n);
        CHECK_MSG(exact > 1.0, "%s, point %zu: %.3g lx through the pane", sky, i, exact);
        moments with = average(&f, 1, p, n, i, draws), without = average(&f, 0, p, n, i, draws);
        /* 5 points x 2 ways x 2 skies, 4.5 sigma each */
        CHECK_MSG(fabs(with.mean - exact) <= 4.5 * sqrt(with.var_of_mean),
                  "%s, point %zu: with portals %.6g +- %.3g lx, the pane's quadrature %.6g", sky, i, with.mean,
                  sqrt(with.var_of_mean), exact);
        CHECK_MSG(fabs(without.mean - exact) <= 4.5 * sqrt(without.var_of_mean),
                  "%s, point %zu: the sky's sampler alone %.6g +- %.3g lx, the pane's quadrature %.6g", sky, i,
                  without.mean, sqrt(without.var_of_mean), exact);
        double gain = with.var_of_mean > 0.0 ? without.var_of_mean / with.var_of_mean : INFINITY;
        /* the share of the pane in the point's projected hemisphere: the
         * smaller, the more the sky's sampler misses it (at 0.5 m from the
         * pane, a fifth of the hemisphere, the gain is about 5-fold) */
        double share = psa_rect(p, n, PANE_ORIGIN, PANE_U, PANE_V) / CDL_PI;
        fprintf(stderr, "%s, point %zu: pane %.3f of the hemisphere, %.6g lx, variance cut %.1f-fold\n", sky, i,
                share, exact, gain);
        if (share < 0.1) gain_min = fmin(gain_min, gain);
        CHECK_MSG(gain >= (share < 0.1 ? 10.0 : 2.0), "%s, point %zu (pane %.3f of the hemisphere): the portals cut "
                  "the variance only %.2f-fold", sky, i, share, gain);
    }
    fprintf(stderr, "%s sky inside the room, where the pane is under a tenth of the hemisphere: the portals cut the "
            "variance at least %.1f-fold\n", sky, gain_min);
    /* outside, in front of the facade and beside the building */
    const double outside[][6] = {{7, 2, 0.5, 0, 0, 1}, {6, 2, 1.5, 0, 0, 1}, {5.5, 2, 1.5, -1, 0, 0.2}};
    for (size_t i = 0; i < sizeof outside / sizeof *outside; ++i) {
        cdl_vec3 p = cdl_vec3_make(outside[i][0], outside[i][1], outside[i][2]);
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(outside[i][3], outside[i][4], outside[i][5]));
        moments with = average(&f, 1, p, n, 100 + i, draws), without = average(&f, 0, p, n, 100 + i, draws);
        double sd = sqrt(with.var_of_mean + without.var_of_mean);
        CHECK_MSG(with.mean > 100.0, "%s, outside %zu: %.3g lx of open sky", sky, i, with.mean);
        CHECK_MSG(fabs(with.mean - without.mean) <= 4.5 * sd, "%s, outside %zu: with portals %.6g, without %.6g (sd %.3g)",
                  sky, i, with.mean, without.mean, sd);
    }
    /* under the ceiling: the pane is seen only below the horizon */
    cdl_vec3 p = cdl_vec3_make(3.5, 2, 3), n = cdl_vec3_make(0, 0, -1);
    cdl_direct_sample_stats stats = {0};
    for (uint64_t k = 0; k < 256; ++k) {
        cdl_rng_key key = {9, cdl_rng_stream_id(3, k, 0)};
        double e = cdl_direct_estimate_point(&f.ctx, key, p, n, NULL, &stats);
        CHECK_MSG(e == 0.0, "%s, under the ceiling, draw %llu: %.17g", sky, (unsigned long long)k, e);
    }
    fixture_close(&f);
}

int main(void)
{
    test_density();
    test_room(uniform_json, 0);
    test_room(overcast_json, 1);
    return check_finish();
}
