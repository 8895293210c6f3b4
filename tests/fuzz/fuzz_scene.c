/* fuzz_scene - libFuzzer harness over scene loading, geometry and the direct solve.
 *
 * Input: a scene JSON, optionally followed by the line "--8<--" and the
 * bytes of one attached file. Each input is written into a private
 * temporary folder (created once per process, removed at exit) as
 * scene.json; an attachment is written there as fuzz.obj, fuzz.off,
 * fuzz.ply, fuzz.ies, fuzz.ldt and fuzz.exr, so a scene can name it as a
 * mesh, a photometric file or an environment image. The folder also holds copies of the project's fixture
 * meshes and photometric files and a small sky.exr, so the seed scenes'
 * relative paths resolve.
 *
 * cdl_scene_load reads the scene file. A rejection must carry a message and
 * be CDL_ERR_INPUT. A scene that loads is made small enough to solve in a
 * few milliseconds (here, not in the library: grids of at most a few
 * hundred points, a few samples per point, one thread; method "direct",
 * so reflecting surfaces are not refused), then solved with
 * cdl_solve_scene and written with cdl_solution_write. The solve must
 * either succeed or fail with a message (CDL_ERR_INPUT, or CDL_ERR_INTERNAL
 * only for a lack of memory); a result must hold finite numbers, E >= 0,
 * a standard error >= 0, E_indirect = 0 and AO in [0, 1]. And E must lie
 * between bounds found without the solver's shortcuts (plans, culling,
 * visibility regions): at least the sum of the delta lights (point, spot,
 * goniometric, directional) that a plain shadow ray finds unoccluded (for
 * a point the solver may value as an edge point, from the point and from
 * six points around it: robust_delta_sum), at
 * most the sum of those not clearly blocked (a hit well inside the
 * segment) plus the unoccluded closed forms of the other lights (plus ten
 * standard errors where the solver sampled). A violated
 * invariant aborts (a finding), as do crashes, hangs, leaks and sanitizer
 * reports. */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lights/emitters/emitter.h"
#include "solver/scene/exr_image.h"
#include "solver/grid/grid.h"
#include "solver/output/grid_result.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"
#include "solver/output/solution_write.h"
#include "solver/solve_internal.h"

/* Budget of one input: points over all grids, samples per point. */
#define FUZZ_MAX_POINTS 256
#define FUZZ_MAX_SAMPLES 16
/* The loosest target a fuzzed solve is held to, at least: the fuzzer hunts
 * crashes and broken invariants (checked against the stated errors, whatever
 * their size), and the sampled routes cost 1 / target (a dark point's
 * samples) to 1 / target^2: at a quarter, the office with a cylindrical grid
 * moved outside its room solves in a few seconds under ASan, within
 * libFuzzer's 10 s timeout. */
#define FUZZ_MIN_TARGET 0.25

/* The marker between the scene and an attached file. */
static const char attachment_marker[] = "\n--8<--\n";

/* The private folder (the harness's only state; set up once). */
static char work_dir[PATH_MAX];

static void require(int ok, const char *what, const char *detail)
{
    if (!ok) {
        fprintf(stderr, "fuzz_scene: invariant broken: %s (%s)\n", what, detail ? detail : "");
        abort();
    }
}

static void join(char *out, const char *dir, const char *name)
{
    int n = snprintf(out, PATH_MAX, "%s/%s", dir, name);
    require(n > 0 && n < PATH_MAX, "path fits", name);
}

static void write_file(const char *dir, const char *name, const void *data, size_t size)
{
    char path[PATH_MAX];
    join(path, dir, name);
    FILE *f = fopen(path, "wb");
    require(f != NULL, "temporary file opens", path);
    require(fwrite(data, 1, size, f) == size && fclose(f) == 0, "temporary file written", path);
}

static void copy_folder(const char *from)
{
    DIR *d = opendir(from);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        char src[PATH_MAX];
        struct stat st;
        join(src, from, e->d_name);
        if (e->d_name[0] == '.' || stat(src, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (1 << 22)) continue;
        FILE *f = fopen(src, "rb");
        if (!f) continue;
        char *buf = malloc((size_t)st.st_size + 1);
        size_t n = buf ? fread(buf, 1, (size_t)st.st_size, f) : 0;
        fclose(f);
        if (buf) write_file(work_dir, e->d_name, buf, n);
        free(buf);
    }
    closedir(d);
}

/* Remove the files of a folder (one level: the output folder is emptied first). */
static void clear_folder(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        char p[PATH_MAX];
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        join(p, dir, e->d_name);
        if (unlink(p) != 0) {
            clear_folder(p);
            rmdir(p);
        }
    }
    closedir(d);
}

static void remove_work_dir(void)
{
    clear_folder(work_dir);
    rmdir(work_dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    const char *tmp = getenv("TMPDIR");
    snprintf(work_dir, sizeof work_dir, "%s/candela-fuzz-scene-XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    require(mkdtemp(work_dir) != NULL, "private temporary folder", work_dir);
    atexit(remove_work_dir);
    copy_folder(CANDELA_SOURCE_DIR "/data/office");
    copy_folder(CANDELA_SOURCE_DIR "/tests/data/scene");
    copy_folder(CANDELA_SOURCE_DIR "/tests/data/photometric");
    /* A small sky: luminance rising towards the zenith, one dark pixel. */
    float sky[8 * 4];
    for (int i = 0; i < 8 * 4; ++i) sky[i] = (float)(1000.0 * (4 - i / 8));
    sky[5] = 0.0f;
    cdl_exr_channel ch = {"Y", sky};
    cdl_error err;
    char path[PATH_MAX];
    join(path, work_dir, "sky.exr");
    require(cdl_exr_write(path, 8, 4, &ch, 1, NULL, 0, &err) == CDL_OK, "sky.exr written", err.message);
    join(path, work_dir, "out");
    require(mkdir(path, 0700) == 0, "output folder", path);
    return 0;
}

/* Make a loaded scene cheap to solve: at most FUZZ_MAX_POINTS points over
 * all grids (coarser rect and polygon grids, fewer listed points),
 * FUZZ_MAX_SAMPLES samples per point, a target of FUZZ_MIN_TARGET. */
static void shrink(cdl_scene *scene)
{
    size_t share = FUZZ_MAX_POINTS / scene->grid_count;
    if (share < 1) share = 1;
    for (size_t g = 0; g < scene->grid_count; ++g) {
        cdl_grid_spec *s = &scene->grids[g];
        switch (s->kind) {
        case CDL_GRID_RECT:
            while ((size_t)s->nu * (size_t)s->nv > share) {
                if (s->nu >= s->nv) s->nu = (s->nu + 1) / 2;
                else s->nv = (s->nv + 1) / 2;
                if (s->nu == 1 && s->nv == 1) break;
            }
            break;
        case CDL_GRID_POINTS:
            if (s->point_count > share) s->point_count = share;
            break;
        case CDL_GRID_POLYGON: {
            /* About 5 points per spacing^2 (grid.c); the outer ring's
             * bounding-box diagonal d bounds the area by d^2 and the
             * automatic spacing from below by cdl_grid_auto_spacing(d / 3). */
            cdl_vec3 lo = s->outer.points[0], hi = lo;
            for (size_t i = 1; i < s->outer.count; ++i) {
                cdl_vec3 p = s->outer.points[i];
                lo = cdl_vec3_make(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
                hi = cdl_vec3_make(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
            }
            double d = cdl_vec3_distance(lo, hi);
            double p = s->spacing > 0.0 ? s->spacing : cdl_grid_auto_spacing(d / 3.0);
            if (!(p > 0.0) || 5.0 * d * d / (p * p) > (double)share) s->spacing = d * sqrt(5.0 / (double)share);
            break;
        }
        }
    }
    cdl_solver_settings *st = &scene->settings;
    st->method = CDL_METHOD_DIRECT;
    if (st->direct_samples <= 0 || st->direct_samples > FUZZ_MAX_SAMPLES) st->direct_samples = FUZZ_MAX_SAMPLES;
    if (st->ao_samples <= 0 || st->ao_samples > FUZZ_MAX_SAMPLES) st->ao_samples = FUZZ_MAX_SAMPLES;
    if (cdl_solver_settings_target(st) < FUZZ_MIN_TARGET) st->target_error = FUZZ_MIN_TARGET;
    st->threads = 1;
}

/* FUZZ_SCENE_VERBOSE=1 in the environment: say what happened to each input. */
static void report(const char *stage, cdl_status st, const cdl_error *err)
{
    const char *v = getenv("FUZZ_SCENE_VERBOSE");
    if (v && v[0] == '1') fprintf(stderr, "fuzz_scene: %s: %s%s%s\n", stage, cdl_status_name(st), st ? ": " : "", st ? err->message : "");
}

static int is_out_of_memory(const cdl_error *err)
{
    return err->status == CDL_ERR_INTERNAL && strstr(err->message, "out of memory") != NULL;
}

static void check_solution(const cdl_scene *scene, const cdl_solution *sol)
{
    require(sol->grid_count == scene->grid_count, "one result per grid", NULL);
    require(sol->plan_json != NULL, "a plan", NULL);
    for (size_t g = 0; g < sol->grid_count; ++g) {
        const cdl_grid_solution *gs = &sol->grids[g];
        const char *name = scene->grids[g].name;
        require(gs->grid.count > 0, "a grid has points", name);
        for (size_t i = 0; i < gs->grid.count; ++i) {
            cdl_vec3 p = gs->grid.points[i], n = gs->grid.normals[i];
            require(isfinite(p.x) && isfinite(p.y) && isfinite(p.z), "finite point", name);
            require(fabs(cdl_vec3_length(n) - 1.0) < 1e-9, "unit normal", name);
            require(isfinite(gs->grid.weights[i]) && gs->grid.weights[i] >= 0.0, "finite weight >= 0", name);
            require(isfinite(gs->E[i]) && gs->E[i] >= 0.0, "finite E >= 0", name);
            require(isfinite(gs->E_direct[i]) && gs->E_direct[i] >= 0.0, "finite E_direct >= 0", name);
            require(gs->E_indirect[i] == 0.0, "no indirect light from the direct method", name);
            require(isfinite(gs->E_stderr[i]) && gs->E_stderr[i] >= 0.0, "finite standard error >= 0", name);
            if (gs->ao) require(gs->ao[i] >= 0.0 && gs->ao[i] <= 1.0, "AO in [0, 1]", name);
        }
        cdl_grid_result r;
        cdl_grid_solution_result(gs, &r);
        cdl_grid_stats s;
        cdl_grid_result_stats(&r, &s);
        require(isfinite(s.E_avg_lx) && isfinite(s.E_min_lx) && isfinite(s.E_max_lx), "finite statistics", name);
        require(s.U0 >= 0.0 && s.U0 <= 1.0 + 1e-12 && s.Ud >= 0.0 && s.Ud <= 1.0, "uniformities in [0, 1]", name);
    }
}

/* What every light would give at p with nothing in the way (delta lights
 * and the closed forms of the others); *bounded = 0 when a light has no
 * closed form. */
static double unoccluded_sum(const cdl_scene_lights *lights, cdl_vec3 p, cdl_vec3 n, int *bounded)
{
    double sum = 0.0;
    *bounded = 1;
    for (size_t l = 0; l < lights->count; ++l) {
        const cdl_emitter *e = lights->emitters[l];
        if (!cdl_scene_light_applies(&lights->lights[l], p)) continue; /* the other part of a near-field split */
        if (cdl_emitter_is_delta(e)) {
            cdl_delta_light d;
            if (cdl_emitter_eval_delta(e, p, n, &d) && d.E.lx > 0.0) sum += d.E.lx;
            continue;
        }
        cdl_illuminance exact;
        if (cdl_emitter_exact_illuminance(e, p, n, &exact, NULL) == CDL_OK) sum += exact.lx;
        else *bounded = 0;
    }
    return sum;
}

/* How far E may move between p and the point an edge point is valued at
 * (direct_grid.c: 8 float resolutions off p, towards the grid's side, in
 * a direction d the harness does not repeat). To first order
 * |U(p + delta d) - U(p)| <= delta sum_k |dU/dx_k| (|d_k| <= 1), each
 * partial taken as a difference over the same step delta along the axis;
 * doubled for the second-order term. U is the unoccluded sum: the bounds
 * are sums of the same per-light terms. */
static double edge_move_slack(const cdl_scene_geometry *geometry, const cdl_scene_lights *lights, cdl_vec3 p,
                              cdl_vec3 n)
{
    int bounded;
    double delta = 8.0 * cdl_scene_geometry_resolution(geometry, p);
    double u0 = unoccluded_sum(lights, p, n, &bounded), slack = 0.0;
    for (int k = 0; k < 3; ++k) {
        cdl_vec3 step = cdl_vec3_make(k == 0 ? delta : 0.0, k == 1 ? delta : 0.0, k == 2 ? delta : 0.0);
        double up = unoccluded_sum(lights, cdl_vec3_add(p, step), n, &bounded);
        double down = unoccluded_sum(lights, cdl_vec3_sub(p, step), n, &bounded);
        slack += fmax(fabs(up - u0), fabs(down - u0));
    }
    return 2.0 * slack;
}

/* The lower bound for a point that may be an edge point: the delta lights
 * unoccluded from p and from p moved 16 float resolutions (twice the
 * solver's edge move) either way along each axis. A surface through p (a
 * wall whose plane holds the point) has one of those six moves on each of
 * its sides, so a light it hides from either side is not counted: the
 * solver values such a point as the limit from the grid's side, which the
 * plain shadow ray from p, grazing the surface, cannot tell. */
static double robust_delta_sum(const cdl_scene_geometry *geometry, const cdl_scene_lights *lights, cdl_vec3 p,
                               cdl_vec3 n)
{
    double delta = 16.0 * cdl_scene_geometry_resolution(geometry, p), sum = 0.0;
    for (size_t l = 0; l < lights->count; ++l) {
        const cdl_emitter *e = lights->emitters[l];
        if (!cdl_scene_light_applies(&lights->lights[l], p)) continue; /* the other part of a near-field split */
        cdl_delta_light d;
        if (!cdl_emitter_is_delta(e) || !cdl_emitter_eval_delta(e, p, n, &d) || !(d.E.lx > 0.0)) continue;
        int seen = !cdl_scene_geometry_ray_occluded(geometry, p, n, d.to_light, d.distance);
        for (int k = 0; seen && k < 6; ++k) {
            double s = (k & 1) ? -delta : delta;
            cdl_vec3 q = cdl_vec3_add(p, cdl_vec3_make(k / 2 == 0 ? s : 0.0, k / 2 == 1 ? s : 0.0, k / 2 == 2 ? s : 0.0));
            cdl_delta_light dq;
            if (!cdl_emitter_eval_delta(e, q, n, &dq) || !(dq.E.lx > 0.0)) continue;
            seen = !cdl_scene_geometry_ray_occluded(geometry, q, n, dq.to_light, dq.distance);
        }
        if (seen) sum += d.E.lx;
    }
    return sum;
}

/* Bounds on E at every point from the emitters and plain ray queries (see
 * the top of this file). */
static void check_against_rays(const cdl_scene *scene, const cdl_solution *sol)
{
    cdl_error err;
    cdl_scene_geometry *geometry = NULL;
    cdl_scene_lights lights;
    memset(&lights, 0, sizeof lights);
    require(cdl_scene_geometry_build(scene, &geometry, &err) == CDL_OK, "geometry builds again", err.message);
    require(cdl_scene_lights_build(scene, geometry, &lights, &err) == CDL_OK, "lights build again", err.message);
    int has_surfaces = cdl_scene_geometry_piece_count(geometry) > 0;
    for (size_t g = 0; g < sol->grid_count; ++g) {
        const cdl_grid_solution *gs = &sol->grids[g];
        for (size_t i = 0; i < gs->grid.count; ++i) {
            cdl_vec3 p = gs->grid.points[i], n = gs->grid.normals[i];
            double lo = 0.0, hi = 0.0;
            int bounded = 1;
            for (size_t l = 0; l < lights.count; ++l) {
                const cdl_emitter *e = lights.emitters[l];
                /* A luminaire split by "near_field": "auto" is its opening
                 * near it and its point beyond; each part counts where the
                 * solver uses it. */
                if (!cdl_scene_light_applies(&lights.lights[l], p)) continue;
                if (!cdl_emitter_is_delta(e)) {
                    cdl_illuminance exact;
                    if (cdl_emitter_exact_illuminance(e, p, n, &exact, NULL) == CDL_OK) hi += exact.lx;
                    else bounded = 0;
                    continue;
                }
                cdl_delta_light d;
                if (!cdl_emitter_eval_delta(e, p, n, &d) || !(d.E.lx > 0.0)) continue;
                if (!has_surfaces || !cdl_scene_geometry_ray_occluded(geometry, p, n, d.to_light, d.distance)) {
                    lo += d.E.lx;
                    hi += d.E.lx;
                    continue;
                }
                /* Blocked for sure: a hit more than 16 float resolutions from
                 * both ends of the segment (an edge point is evaluated 8 of
                 * them off the point, direct_grid.c). */
                cdl_ray_hit hit;
                double near = 16.0 * cdl_scene_geometry_resolution(geometry, p);
                double far = isfinite(d.distance)
                                 ? 16.0 * cdl_scene_geometry_resolution(geometry, cdl_vec3_madd(p, d.distance, d.to_light))
                                 : 0.0;
                int blocked = cdl_scene_geometry_intersect(geometry, p, n, d.to_light, d.distance, &hit) &&
                              hit.t > near && d.distance - hit.t > far;
                if (!blocked) hi += d.E.lx;
            }
            char where[160];
            snprintf(where, sizeof where, "%s point %zu: E %.17g, bounds [%.17g, %.17g]", scene->grids[g].name, i,
                     gs->E[i], lo, hi);
            /* A point near a surface may be an edge point, valued a few
             * float resolutions off: the slack of that move, only where
             * the plain bounds fail (it costs seven evaluations). */
            double slack = 0.0;
            int low = !(gs->E[i] >= lo * (1.0 - 1e-9));
            /* Sampled parts may exceed their closed form by their noise. */
            int high = bounded && !(gs->E[i] <= hi * (1.0 + 1e-9) + 10.0 * gs->E_stderr[i] + 1e-300);
            if ((low || high) && has_surfaces) {
                slack = edge_move_slack(geometry, &lights, p, n);
                if (low) lo = robust_delta_sum(geometry, &lights, p, n);
                snprintf(where, sizeof where, "%s point %zu: E %.17g, bounds [%.17g, %.17g], edge slack %.3g",
                         scene->grids[g].name, i, gs->E[i], lo, hi, slack);
            }
            require(gs->E[i] >= lo * (1.0 - 1e-9) - slack, "E at least the unoccluded delta lights", where);
            if (bounded)
                require(gs->E[i] <= hi * (1.0 + 1e-9) + slack + 10.0 * gs->E_stderr[i] + 1e-300,
                        "E at most what is not clearly blocked", where);
        }
    }
    cdl_scene_lights_release(&lights);
    cdl_scene_geometry_release(geometry);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const uint8_t *attachment = NULL;
    size_t scene_size = size, attachment_size = 0, marker = sizeof attachment_marker - 1;
    for (size_t i = 0; i + marker <= size; ++i)
        if (memcmp(data + i, attachment_marker, marker) == 0) {
            scene_size = i;
            attachment = data + i + marker;
            attachment_size = size - i - marker;
            break;
        }
    write_file(work_dir, "scene.json", data, scene_size);
    if (attachment) {
        static const char *const names[] = {"fuzz.obj", "fuzz.off", "fuzz.ply", "fuzz.ies", "fuzz.ldt", "fuzz.exr"};
        for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
            write_file(work_dir, names[i], attachment, attachment_size);
    }

    char path[PATH_MAX], out_dir[PATH_MAX];
    join(path, work_dir, "scene.json");
    join(out_dir, work_dir, "out");
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    cdl_status st = cdl_scene_load(path, &scene, &err);
    report("load", st, &err);
    if (st != CDL_OK) {
        require(scene == NULL, "no scene after a rejection", NULL);
        require(err.message[0] != '\0', "a rejection has a message", NULL);
        require(st == CDL_ERR_INPUT || is_out_of_memory(&err), "a bad scene is bad input", err.message);
        return 0;
    }
    shrink(scene);
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    so.threads = 1;
    cdl_solution sol;
    cdl_error_clear(&err);
    st = cdl_solve_scene_into(scene, &so, NULL, &sol, &err);
    report("solve", st, &err);
    if (st != CDL_OK) {
        require(err.message[0] != '\0', "a refused solve has a message", NULL);
        require(st == CDL_ERR_INPUT || is_out_of_memory(&err), "a refused solve is bad input", err.message);
    } else {
        check_solution(scene, &sol);
        check_against_rays(scene, &sol);
        st = cdl_solution_write(scene, &sol, out_dir, NULL, &err);
        require(st == CDL_OK, "a solution is written", err.message);
        cdl_solution_clear(&sol);
        clear_folder(out_dir);
    }
    cdl_scene_release(scene);
    return 0;
}
