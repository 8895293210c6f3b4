/* bench_environment.c - time per point to reach a relative standard error
 * on an image sky seen through an opening, before and after the per-normal
 * environment sampler, in one process.
 *
 *   bench_environment [--points N] [--target T] [--width W] [--depth D] [--sun 0|1] [--solver-only 0|1]
 *
 * A black well 2 x 2 m, D m deep (default 1.5), open at the top, under a
 * W x W/2 lat-long sky (default 512: a gradient, a dark band and, unless
 * --sun 0, a small bright sun), upper hemisphere; N floor points (default 32) facing up.
 * Each point is sampled in batches of 1024 until the standard error of its
 * mean is at most T (default 0.001) of its value, two ways:
 *   before: the emitter's own sampler (pixels by L x solid angle) and the
 *           plain estimator E = mean of L cos / pdf x V, the only route an
 *           image sky had without a closed form;
 *   after:  the sampler for the point's normal (pixels by L x projected
 *           solid angle, lights/environment/environment_sampler.h) and E = E_0 - mean
 *           of L cos / pdf x (1 - V), E_0 the exact pixel sum; its set-up
 *           (one pass over the pixels) is counted in the time.
 * Both use independent samples (no strata), the same shadow rays through
 * the solver's geometry, and the same stopping rule. Reported: samples and
 * microseconds per point each way and their ratios (left out with
 * --solver-only 1: at small targets they take minutes); then the whole
 * direct solver at the same target on the same points, the exact route
 * off and on: time, shadow rays and stated sigma / target per point, the
 * points the cap of samples held short of the target, and the route the
 * plan names. With the sun, the route on takes the sun's pixels exactly
 * over the visible sky and samples the rest there (no rays). Ratios, not
 * wall-clock figures, are what to compare between machines.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "lights/environment/environment_sampler.h"
#include "radiometry/constants.h"
#include "base/rng.h"
#include "solver/scene/exr_image.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"
#include "solver/solve_internal.h"

#define MAX_SAMPLES 67108864.0 /* 2^26: a point that needs more stops there (reported) */

static double arg_num(int argc, char **argv, const char *name, double dflt)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], name) == 0) return strtod(argv[i + 1], NULL);
    return dflt;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct run {
    double E, se, samples;
} run;

/* Sample one point until se <= target E (or MAX_SAMPLES). after = 0: the
 * emitter's sampler, E = mean f V; after = 1: the per-normal sampler,
 * E = E_0 - mean f (1 - V). */
static run sample_point(const cdl_emitter *sky, const cdl_environment_sampler *s, double E0, const cdl_ray_scene *rays,
                        const cdl_ray_offsets *off, cdl_vec3 p, cdl_vec3 n, double target, uint64_t stream, int after)
{
    cdl_rng_key key = {1, stream};
    double sum = 0.0, sum2 = 0.0, N = 0.0;
    run r = {0.0, INFINITY, 0.0};
    while (N < MAX_SAMPLES) {
        for (int b = 0; b < 1024; ++b) {
            double u[2], f = 0.0;
            cdl_rng_uniform2(key, (uint64_t)N + (uint64_t)b, u);
            cdl_light_sample ls;
            int ok = after ? cdl_environment_sampler_sample(s, u[0], u[1], &ls)
                           : cdl_emitter_sample(sky, p, n, u[0], u[1], &ls);
            double c = ok ? cdl_vec3_dot(n, ls.to_light) : 0.0;
            if (c > 0.0 && ls.pdf > 0.0) {
                cdl_vec3 o;
                double t0, t1;
                int hidden = cdl_ray_offsets_shadow_ray(off, p, n, ls.to_light, INFINITY, &o, &t0, &t1) &&
                             cdl_ray_scene_occluded(rays, o, ls.to_light, t0, t1);
                if (after ? hidden : !hidden) f = ls.L.cd_m2 * c / ls.pdf;
            }
            sum += f;
            sum2 += f * f;
        }
        N += 1024.0;
        double mean = sum / N, var = fmax(0.0, sum2 / N - mean * mean) / (N - 1.0);
        r.E = after ? E0 - mean : mean;
        r.se = sqrt(var);
        r.samples = N;
        if (r.se <= target * r.E) break;
    }
    return r;
}

/* The points the plan says the cap of samples held short ("... held N
 * points short"), 0 if it says none. */
static size_t capped_points(const char *plan)
{
    const char *at = plan ? strstr(plan, " held ") : NULL;
    return at ? (size_t)strtoull(at + 6, NULL, 10) : 0;
}

/* The floor grid's route text from the plan ("floor": "..."), or "". */
static const char *route_text(const char *plan)
{
    static char text[1024];
    const char *at = plan ? strstr(plan, "\"floor\":\"") : NULL;
    text[0] = '\0';
    if (!at) return text;
    at += 9;
    size_t k = 0;
    while (at[k] && at[k] != '"' && k + 1 < sizeof text) {
        text[k] = at[k];
        k++;
    }
    text[k] = '\0';
    return text;
}

/* The sky: luminance in cd/m^2, a zenith-bright gradient with an azimuthal
 * swing, a dark band of columns and a 2 x 2 pixel sun at 1e6. */
static int write_sky(const char *path, int W, int H, int sun)
{
    float *Y = malloc((size_t)W * H * sizeof *Y);
    if (!Y) return 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double v = 4000.0 * (1.0 - 0.7 * j / H) * (1.0 + 0.3 * cos(CDL_TWO_PI * i / W));
            if (i >= W * 5 / 8 && i < W * 11 / 16) v = 0.0;
            if (sun && i >= W / 2 + W / 16 && i < W / 2 + W / 16 + 2 && j >= H / 6 && j < H / 6 + 2) v = 1e6;
            Y[j * W + i] = (float)v;
        }
    cdl_exr_channel ch = {"Y", Y};
    cdl_error err;
    int ok = cdl_exr_write(path, W, H, &ch, 1, NULL, 0, &err) == CDL_OK;
    if (!ok) fprintf(stderr, "bench_environment: %s\n", err.message);
    free(Y);
    return ok;
}

int main(int argc, char **argv)
{
    int points = (int)arg_num(argc, argv, "--points", 32);
    double target = arg_num(argc, argv, "--target", 0.001);
    int W = (int)arg_num(argc, argv, "--width", 512);
    double depth = arg_num(argc, argv, "--depth", 1.5);
    int sun = (int)arg_num(argc, argv, "--sun", 1);
    int solver_only = (int)arg_num(argc, argv, "--solver-only", 0);
    if (points < 1 || W < 4 || !(target > 0.0) || !(depth > 0.0)) {
        fprintf(stderr, "bench_environment: expected --points >= 1, --width >= 4, --target > 0, --depth > 0\n");
        return 2;
    }
    char dir[] = "/tmp/bench_environment_XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_environment: mkdtemp");
        return 3;
    }
    char sky_path[512], scene_path[512];
    snprintf(sky_path, sizeof sky_path, "%s/sky.exr", dir);
    snprintf(scene_path, sizeof scene_path, "%s/well.json", dir);
    if (!write_sky(sky_path, W, W / 2, sun)) return 3;

    /* Floor points spread by a golden-ratio sequence, 0.1 m from the walls. */
    size_t cap = 4096 + (size_t)points * 64;
    char *json = malloc(cap);
    if (!json) return 3;
    int len = snprintf(json, cap,
                       "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [2, 2, %g],"
                       " \"inward\": true, \"open\": [\"+z\"], \"reflectance\": 0}],"
                       " \"luminaires\": [{\"type\": \"environment\", \"file\": \"sky.exr\", \"hemisphere\": \"upper\"}],"
                       " \"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"points\": [",
                       depth);
    for (int i = 0; i < points; ++i) {
        double x = 0.1 + 1.8 * (i + 0.5) / points, y = 0.1 + 1.8 * fmod(0.618034 * (i + 1), 1.0);
        len += snprintf(json + len, cap - (size_t)len, "%s{\"p\": [%.6f, %.6f, 0], \"n\": [0, 0, 1]}", i ? ", " : "", x,
                        y);
    }
    snprintf(json + len, cap - (size_t)len, "]}], \"solver\": {\"method\": \"direct\", \"target_error\": %g}}", target);

    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    cdl_scene_geometry *geometry = NULL;
    cdl_scene_lights lights;
    memset(&lights, 0, sizeof lights);
    if (cdl_scene_load_string(json, scene_path, &scene, &err) != CDL_OK ||
        cdl_scene_geometry_build(scene, &geometry, &err) != CDL_OK ||
        cdl_scene_lights_build(scene, geometry, &lights, &err) != CDL_OK) {
        fprintf(stderr, "bench_environment: %s\n", err.message);
        return 3;
    }
    const cdl_emitter *sky = lights.lights[0].emitter;
    const cdl_ray_scene *rays = cdl_scene_geometry_rays(geometry);
    cdl_ray_offsets off;
    cdl_scene_geometry_ray_offsets(geometry, &off);

    double t_before = 0.0, t_after = 0.0, n_before = 0.0, n_after = 0.0, worst_gap = 0.0;
    int capped = 0;
    cdl_vec3 n = {0, 0, 1};
    for (int i = 0; i < (solver_only ? 0 : points); ++i) {
        double x = 0.1 + 1.8 * (i + 0.5) / points, y = 0.1 + 1.8 * fmod(0.618034 * (i + 1), 1.0);
        cdl_vec3 p = {x, y, 0};
        double t0 = now_seconds();
        run b = sample_point(sky, NULL, 0.0, rays, &off, p, n, target, (uint64_t)i, 0);
        double t1 = now_seconds();
        cdl_environment_sampler *s = NULL;
        if (cdl_environment_sampler_create(sky, n, &s, &err) != CDL_OK) {
            fprintf(stderr, "bench_environment: %s\n", err.message);
            return 3;
        }
        run a = sample_point(sky, s, cdl_environment_sampler_illuminance(s).lx, rays, &off, p, n, target,
                             (uint64_t)i + 1000003u, 1);
        cdl_environment_sampler_release(s);
        double t2 = now_seconds();
        t_before += t1 - t0;
        t_after += t2 - t1;
        n_before += b.samples;
        n_after += a.samples;
        capped += (b.samples >= MAX_SAMPLES) + (a.samples >= MAX_SAMPLES);
        /* The two estimates of the same E, in units of their combined error. */
        double gap = fabs(a.E - b.E) / hypot(a.se, b.se);
        if (gap > worst_gap) worst_gap = gap;
    }
    printf("scene: black well 2 x 2 x %g m under a %d x %d image sky; %d floor points; target %g\n", depth, W, W / 2,
           points, target);
    if (!solver_only) {
    printf("before (L x solid angle, plain):           %10.0f samples/point  %10.1f us/point\n", n_before / points,
           1e6 * t_before / points);
    printf("after  (L x projected solid angle, E0 - H): %10.0f samples/point  %10.1f us/point\n", n_after / points,
           1e6 * t_after / points);
    printf("ratio before / after: samples %.2f, time %.2f   (largest gap between the two: %.2f combined sigma; %d "
           "runs hit the 2^26 cap)\n",
           n_before / n_after, t_before / t_after, worst_gap, capped);
    }

    /* The whole direct solver at the same target, one thread: the exact
     * route off (the per-normal sampler with shadow rays, E0 - H) and on
     * (the visible sky found past the well's walls and sampled itself, no
     * rays: solver/direct/sky_region.h). Where the cap of samples held a
     * point short of the target its stated sigma is larger: reported. */
    double us[2] = {0.0, 0.0};
    for (int route_off = 1; route_off >= 0; --route_off) {
        cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
        o.threads = 1;
        cdl_solve_debug dbg = CDL_SOLVE_DEBUG_NONE;
        dbg.no_exact_route = route_off;
        cdl_solution sol;
        double t3 = now_seconds();
        if (cdl_solve_scene_into(scene, &o, &dbg, &sol, &err) != CDL_OK) {
            fprintf(stderr, "bench_environment: %s\n", err.message);
            return 3;
        }
        double t4 = now_seconds(), worst = 0.0, mean = 0.0;
        const cdl_grid_solution *g = &sol.grids[0];
        for (size_t i = 0; i < g->grid.count; ++i) {
            double r = g->E[i] > 0.0 ? g->E_stderr[i] / (target * g->E[i]) : 0.0;
            worst = fmax(worst, r);
            mean += r / (double)g->grid.count;
        }
        us[route_off] = 1e6 * (t4 - t3) / points;
        printf("direct solver, exact route %s: %10.1f us/point, %8.0f shadow rays/point; stated sigma / target: mean "
               "%.2f, worst %.2f; the cap held %zu points\n",
               route_off ? "off (E0 - H, rays)  " : "on (visible sky)   ", us[route_off], (double)sol.rays / points,
               mean, worst, capped_points(sol.plan_json));
        if (!route_off) printf("  plan: %s\n", route_text(sol.plan_json));
        cdl_solution_clear(&sol);
    }
    printf("ratio route off / on: time %.2f\n", us[1] / us[0]);
    cdl_scene_lights_release(&lights);
    cdl_scene_geometry_release(geometry);
    cdl_scene_release(scene);
    free(json);
    unlink(sky_path);
    rmdir(dir);
    return 0;
}
