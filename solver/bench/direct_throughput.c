/* direct_throughput.c - shadow-ray throughput of the direct solver against plain
 * Embree occlusion queries on exactly the rays the solver cast. */
#include "solver/bench/direct_throughput.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "base/error_report.h"
#include "radiometry/constants.h"
#include "solver/direct/direct.h"
#include "solver/geometry/ray_scene.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"
#include "solver/solve_internal.h"

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A hall of side `side` m: a floor, and a field of UV spheres (rings x
 * segments) between the grid (z = 0.8) and the luminaires (z = 3.0), enough
 * of them for about `triangles` triangles in all. Written as an OBJ file. */
static cdl_status write_hall_obj(const char *path, size_t triangles, double side, size_t *written, cdl_error *err)
{
    FILE *f = fopen(path, "w");
    if (!f) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot write the benchmark mesh", path);
    const int rings = 20, segments = 40;
    const size_t per_sphere = (size_t)(2 * segments * (rings - 1));
    size_t spheres = triangles > 2 ? (triangles - 2) / per_sphere : 0;
    if (spheres == 0) spheres = 1;
    size_t across = (size_t)ceil(sqrt((double)spheres));
    double pitch = side / (double)across, radius = 0.3 * pitch;
    fprintf(f, "# Candela direct benchmark hall: floor and %zu spheres\n", spheres);
    fprintf(f, "v 0 0 0\nv %g 0 0\nv %g %g 0\nv 0 %g 0\nf 1 2 3\nf 1 3 4\n", side, side, side, side);
    size_t base = 5, count = 2;
    for (size_t s = 0; s < spheres; ++s) {
        /* deterministic jitter of centres and heights */
        double jx = 0.2 * sin(1.7 * (double)s), jy = 0.2 * cos(2.3 * (double)s), jz = 0.4 * sin(0.9 * (double)s);
        double cx = ((double)(s % across) + 0.5 + jx) * pitch, cy = ((double)(s / across) + 0.5 + jy) * pitch;
        double cz = 1.9 + jz;
        fprintf(f, "v %.9g %.9g %.9g\n", cx, cy, cz + radius); /* north pole */
        for (int r = 1; r < rings; ++r) {
            double th = CDL_PI * r / rings;
            for (int k = 0; k < segments; ++k) {
                double ph = CDL_TWO_PI * k / segments;
                fprintf(f, "v %.9g %.9g %.9g\n", cx + radius * sin(th) * cos(ph), cy + radius * sin(th) * sin(ph),
                        cz + radius * cos(th));
            }
        }
        fprintf(f, "v %.9g %.9g %.9g\n", cx, cy, cz - radius); /* south pole */
        size_t north = base, first = base + 1, south = base + 1 + (size_t)((rings - 1) * segments);
        for (int k = 0; k < segments; ++k) {
            fprintf(f, "f %zu %zu %zu\n", north, first + (size_t)k, first + (size_t)((k + 1) % segments));
            size_t last = first + (size_t)((rings - 2) * segments);
            fprintf(f, "f %zu %zu %zu\n", south, last + (size_t)((k + 1) % segments), last + (size_t)k);
        }
        for (int r = 0; r < rings - 2; ++r)
            for (int k = 0; k < segments; ++k) {
                size_t a = first + (size_t)(r * segments + k), b = first + (size_t)(r * segments + (k + 1) % segments);
                size_t c = a + (size_t)segments, d = b + (size_t)segments;
                fprintf(f, "f %zu %zu %zu\nf %zu %zu %zu\n", a, c, d, a, d, b);
            }
        base = south + 1;
        count += per_sphere;
    }
    *written = count;
    if (fclose(f) != 0) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: write failed", path);
    return CDL_OK;
}

static cdl_status write_scene_json(const char *path, const char *obj, const char *ies, size_t luminaires, double side,
                                   size_t points, cdl_error *err)
{
    FILE *f = fopen(path, "w");
    if (!f) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot write the benchmark scene", path);
    fprintf(f, "{\"version\": 1, \"surfaces\": [{\"type\": \"mesh\", \"file\": \"%s\", \"reflectance\": 0}],\n", obj);
    fprintf(f, " \"luminaires\": [\n");
    size_t cols = (size_t)ceil(sqrt((double)luminaires * 2.0)), rows = (luminaires + cols - 1) / cols;
    for (size_t i = 0; i < luminaires; ++i) {
        double x = ((double)(i % cols) + 0.5) * side / (double)cols, y = ((double)(i / cols) + 0.5) * side / (double)rows;
        fprintf(f, "  {\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [%.6g, %.6g, 3.0], \"near_field\": \"never\", \"body\": false}%s\n", ies, x, y,
                i + 1 < luminaires ? "," : "");
    }
    size_t n = (size_t)ceil(sqrt((double)points));
    fprintf(f, " ],\n \"grids\": [{\"name\": \"hall\", \"type\": \"rect\", \"origin\": [0, 0, 0.8], \"u\": [%g, 0, 0], "
               "\"v\": [0, %g, 0], \"nu\": %zu, \"nv\": %zu}],\n",
            side, side, n, n);
    fprintf(f, " \"solver\": {\"method\": \"direct\", \"seed\": 1}}\n");
    if (fclose(f) != 0) return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: write failed", path);
    return CDL_OK;
}

cdl_status cdl_bench_direct_run(const cdl_bench_direct_config *cfg, cdl_bench_direct_result *r, cdl_error *err)
{
    memset(r, 0, sizeof *r);
    char dir[] = "/tmp/candela-bench-XXXXXX";
    if (!mkdtemp(dir)) return cdl_error_set(err, CDL_ERR_INTERNAL, "cannot create a temporary folder");
    char obj[256], json[256];
    snprintf(obj, sizeof obj, "%s/hall.obj", dir);
    snprintf(json, sizeof json, "%s/hall.json", dir);
    const double side = 40.0;
    cdl_scene *scene = NULL;
    cdl_scene_geometry *geometry = NULL;
    cdl_solution sol;
    memset(&sol, 0, sizeof sol);
    cdl_ray_log log;
    memset(&log, 0, sizeof log);
    unsigned char *blocked = NULL, *single = NULL;

    cdl_status st = write_hall_obj(obj, cfg->triangles, side, &r->triangles, err);
    if (st == CDL_OK) st = write_scene_json(json, obj, cfg->ies_path, cfg->luminaires, side, cfg->points, err);
    if (st == CDL_OK) st = cdl_scene_load(json, &scene, err);
    if (st != CDL_OK) goto done;

    /* 1. Record the rays (untimed, one thread). */
    cdl_solve_options rec = CDL_SOLVE_OPTIONS_INIT;
    cdl_solve_debug debug = CDL_SOLVE_DEBUG_NONE;
    debug.ray_log = &log;
    st = cdl_solve_scene_into(scene, &rec, &debug, &sol, err);
    if (st != CDL_OK) goto done;
    if (log.overflow) {
        st = cdl_error_out_of_memory(err);
        goto done;
    }
    cdl_solution_clear(&sol);

    /* 2. and 3., interleaved seven times, keeping the fastest of each so
     *    that other load on the machine disturbs both alike: the solver,
     *    timed on the grid computation only, and plain occlusion queries on
     *    the same rays and scene on one thread (the physical limit per core). */
    st = cdl_scene_geometry_build(scene, &geometry, err);
    if (st != CDL_OK) goto done;
    const cdl_ray_scene *rays = cdl_scene_geometry_rays(geometry);
    cdl_solve_options timed = CDL_SOLVE_OPTIONS_INIT;
    timed.threads = cfg->threads;
    r->solver_seconds = r->embree_seconds = r->stream_seconds = INFINITY;
    blocked = malloc(log.count ? log.count : 1);
    single = malloc(log.count ? log.count : 1);
    if (!blocked || !single) {
        st = cdl_error_out_of_memory(err);
        goto done;
    }
    for (int round = 0; round < 7; ++round) {
        st = cdl_solve_scene_into(scene, &timed, NULL, &sol, err);
        if (st != CDL_OK) goto done;
        r->points = sol.grids[0].grid.count;
        r->solver_seconds = fmin(r->solver_seconds, sol.compute_seconds);
        r->solver_rays = sol.rays;
        cdl_solution_clear(&sol);

        /* single rays, each answer kept (a byte per ray: the timing is
         * of the queries) */
        size_t occluded = 0;
        double t0 = now_seconds();
        for (size_t i = 0; i < log.count; ++i) {
            const cdl_ray_record *q = &log.rays[i];
            single[i] = (unsigned char)cdl_ray_scene_occluded_except(rays, q->origin, q->dir, q->t_near, q->t_far,
                                                                     q->exclude);
            occluded += single[i];
        }
        r->embree_seconds = fmin(r->embree_seconds, now_seconds() - t0);
        r->embree_rays = log.count;
        r->occluded_fraction = log.count ? (double)occluded / (double)log.count : 0.0;

        /* the same rays in the solver's order as streams (blocks of the
         * same size as the solver's, though not ending where its chunks
         * end), and the same answer ray for ray */
        t0 = now_seconds();
        cdl_ray_scene_occluded_many(rays, log.rays, log.count, blocked);
        r->stream_seconds = fmin(r->stream_seconds, now_seconds() - t0);
        for (size_t i = 0; i < log.count; ++i)
            if (blocked[i] != single[i]) {
                st = cdl_error_set(err, CDL_ERR_INTERNAL, "ray %zu: %s as a stream, %s alone", i,
                                   blocked[i] ? "blocked" : "clear", single[i] ? "blocked" : "clear");
                goto done;
            }
    }

done:
    cdl_solution_clear(&sol);
    cdl_scene_geometry_release(geometry);
    cdl_scene_release(scene);
    free(log.rays);
    free(blocked);
    free(single);
    remove(obj);
    remove(json);
    rmdir(dir);
    return st;
}
