/* solve.c - the direct-illuminance solve: plan, compute on threads, collect. */
#include "solver/solve.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "radiometry/constants.h"
#include "radiometry/rng.h"
#include "solver/direct/direct.h"
#include "solver/geometry/occluder_index.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

const char *cdl_default_ocio_config(void)
{
    return CANDELA_DEFAULT_OCIO_CONFIG;
}

/* Sample counts implied by the quality level (explicit knobs override).
 * Direct: per partly hidden extended light and point; the standard error of
 * the hidden part falls as 1/sqrt(n). AO: per point. */
static void quality_defaults(cdl_quality q, int *direct_samples, int *ao_samples)
{
    static const int direct[] = {16, 64, 256, 1024};
    static const int ao[] = {64, 256, 1024, 4096};
    *direct_samples = direct[q];
    *ao_samples = ao[q];
}

/* Does light reflect anywhere? Returns the JSON path of the first reflecting
 * surface, or NULL. */
static const char *first_reflector(const cdl_scene *scene, double *rho)
{
    for (size_t i = 0; i < scene->surface_count; ++i) {
        const cdl_surface_spec *s = &scene->surfaces[i];
        if (s->kind == CDL_SURFACE_BOX) {
            for (int f = 0; f < CDL_BOX_FACES; ++f)
                if (!s->face_open[f] && s->face_reflectance[f] > 0.0) {
                    *rho = s->face_reflectance[f];
                    return s->json_path;
                }
        } else if (s->reflectance > 0.0) {
            *rho = s->reflectance;
            return s->json_path;
        }
    }
    for (size_t i = 0; i < scene->luminaire_count; ++i)
        if (scene->luminaires[i].kind == CDL_LUMINAIRE_AREA && scene->luminaires[i].reflectance > 0.0) {
            *rho = scene->luminaires[i].reflectance;
            return scene->luminaires[i].json_path;
        }
    return NULL;
}

static cdl_status choose_method(const cdl_scene *scene, cdl_method *method, cJSON *plan, cdl_error *err)
{
    double rho = 0.0;
    const char *reflector = first_reflector(scene, &rho);
    cJSON *inter = cJSON_AddObjectToObject(plan, "interreflection");
    char why[256];
    switch (scene->settings.method) {
    case CDL_METHOD_DIRECT:
        *method = CDL_METHOD_DIRECT;
        cJSON_AddBoolToObject(inter, "modelled", 0);
        if (reflector)
            snprintf(why, sizeof why, "method \"direct\" asks for direct light only (%s reflects %g %%)", reflector,
                     rho * 100.0);
        else
            snprintf(why, sizeof why, "method \"direct\"; no surface reflects light, so none would be interreflected");
        cJSON_AddStringToObject(inter, "why", why);
        return CDL_OK;
    case CDL_METHOD_AUTO:
        if (reflector)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: solver.method: \"auto\" needs interreflected light here (%s reflects %g %%), "
                                 "which needs the irradiance cache or the path tracer, not built in this version; "
                                 "set \"method\": \"direct\" to compute direct light only",
                                 scene->path, reflector, rho * 100.0);
        *method = CDL_METHOD_DIRECT;
        cJSON_AddBoolToObject(inter, "modelled", 0);
        cJSON_AddStringToObject(inter, "why", "no surface reflects light: direct light is the whole answer");
        return CDL_OK;
    case CDL_METHOD_ICACHE:
    case CDL_METHOD_PATHTRACE:
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: solver.method: \"%s\" is not built in this version; use \"direct\" (direct light "
                             "only) or \"auto\" for scenes without reflecting surfaces",
                             scene->path, cdl_method_name(scene->settings.method));
    }
    return cdl_error_set(err, CDL_ERR_INTERNAL, "unknown method");
}

static int cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- occluder index from the geometry pieces ------------------------------ */

static cdl_status build_occluders(const cdl_scene_geometry *g, cdl_occluder_index **out, cdl_error *err)
{
    size_t pieces = cdl_scene_geometry_piece_count(g);
    size_t tri_cap = 0, vert_cap = 0, sph = 0;
    /* Disks enter as circumscribed 32-gons: a superset, so never a missed occluder. */
    const int disk_sides = 32;
    for (size_t i = 0; i < pieces; ++i) {
        const cdl_shape *s = &cdl_scene_geometry_piece(g, i)->shape;
        switch (s->kind) {
        case CDL_SHAPE_TRIANGLES: tri_cap += s->triangle_count; vert_cap += s->vertex_count; break;
        case CDL_SHAPE_RECT: tri_cap += 2; vert_cap += 4; break;
        case CDL_SHAPE_DISK: tri_cap += disk_sides; vert_cap += disk_sides + 1; break;
        case CDL_SHAPE_SPHERE: sph++; break;
        }
    }
    double *v = malloc((vert_cap + 1) * 3 * sizeof(double));
    uint32_t *t = malloc((tri_cap + 1) * 3 * sizeof(uint32_t));
    uint32_t *towner = malloc((tri_cap + 1) * sizeof(uint32_t));
    double *sc = malloc((sph + 1) * 3 * sizeof(double));
    double *sr = malloc((sph + 1) * sizeof(double));
    uint32_t *sowner = malloc((sph + 1) * sizeof(uint32_t));
    cdl_status st = CDL_OK;
    if (!v || !t || !towner || !sc || !sr || !sowner) {
        st = cdl_error_out_of_memory(err);
        goto done;
    }
    size_t nv = 0, nt = 0, ns = 0;
#define PUSH_V(p)                  \
    do {                           \
        v[3 * nv] = (p).x;         \
        v[3 * nv + 1] = (p).y;     \
        v[3 * nv + 2] = (p).z;     \
        nv++;                      \
    } while (0)
#define PUSH_T(a, b, c, o)         \
    do {                           \
        t[3 * nt] = (uint32_t)(a); \
        t[3 * nt + 1] = (uint32_t)(b); \
        t[3 * nt + 2] = (uint32_t)(c); \
        towner[nt] = (o);          \
        nt++;                      \
    } while (0)
    for (size_t i = 0; i < pieces; ++i) {
        const cdl_shape *s = &cdl_scene_geometry_piece(g, i)->shape;
        uint32_t o = (uint32_t)i;
        size_t base = nv;
        switch (s->kind) {
        case CDL_SHAPE_TRIANGLES:
            for (size_t k = 0; k < s->vertex_count; ++k)
                PUSH_V(cdl_vec3_make(s->vertices[3 * k], s->vertices[3 * k + 1], s->vertices[3 * k + 2]));
            for (size_t k = 0; k < s->triangle_count; ++k)
                PUSH_T(base + s->triangles[3 * k], base + s->triangles[3 * k + 1], base + s->triangles[3 * k + 2], o);
            break;
        case CDL_SHAPE_RECT:
            PUSH_V(s->origin);
            PUSH_V(cdl_vec3_add(s->origin, s->u));
            PUSH_V(cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v));
            PUSH_V(cdl_vec3_add(s->origin, s->v));
            PUSH_T(base, base + 1, base + 2, o);
            PUSH_T(base, base + 2, base + 3, o);
            break;
        case CDL_SHAPE_DISK: {
            cdl_vec3 n = cdl_vec3_normalize(s->normal);
            cdl_vec3 e1 = fabs(n.x) < 0.9 ? cdl_vec3_normalize(cdl_vec3_cross(n, cdl_vec3_make(1, 0, 0)))
                                          : cdl_vec3_normalize(cdl_vec3_cross(n, cdl_vec3_make(0, 1, 0)));
            cdl_vec3 e2 = cdl_vec3_cross(n, e1);
            double R = s->radius / cos(CDL_PI / disk_sides);
            PUSH_V(s->center);
            for (int k = 0; k < disk_sides; ++k) {
                double a = CDL_TWO_PI * k / disk_sides;
                PUSH_V(cdl_vec3_add(s->center, cdl_vec3_add(cdl_vec3_scale(e1, R * cos(a)), cdl_vec3_scale(e2, R * sin(a)))));
            }
            for (int k = 0; k < disk_sides; ++k) PUSH_T(base, base + 1 + k, base + 1 + (k + 1) % disk_sides, o);
            break;
        }
        case CDL_SHAPE_SPHERE:
            sc[3 * ns] = s->center.x;
            sc[3 * ns + 1] = s->center.y;
            sc[3 * ns + 2] = s->center.z;
            sr[ns] = s->radius;
            sowner[ns] = o;
            ns++;
            break;
        }
    }
#undef PUSH_V
#undef PUSH_T
    cdl_occluder_input in = {v, t, towner, nt, sc, sr, sowner, ns};
    st = cdl_occluder_index_build(&in, out, err);
done:
    free(v);
    free(t);
    free(towner);
    free(sc);
    free(sr);
    free(sowner);
    return st;
}

/* ---- the worker pool -------------------------------------------------------- */

typedef struct grid_job {
    const cdl_direct_context *ctx;
    const cdl_light_strategy *strategies;
    cdl_grid_solution *gs;
    size_t grid_index;
    int want_ao;
    atomic_size_t next;           /* next chunk start */
    size_t chunk;
} grid_job;


typedef struct worker_state {
    grid_job *job;
    cdl_direct_sample_stats stats;
    uint32_t *active;             /* light indices for the current chunk */
    cdl_direct_scratch scratch;
    cdl_status status;            /* CDL_OK unless the worker failed */
    cdl_error err;
} worker_state;

static void *worker_main(void *arg)
{
    worker_state *w = arg;
    grid_job *job = w->job;
    const cdl_grid *grid = &job->gs->grid;
    for (;;) {
        size_t start = atomic_fetch_add(&job->next, job->chunk);
        if (start >= grid->count) break;
        size_t end = start + job->chunk < grid->count ? start + job->chunk : grid->count;
        /* Skip, once for the whole chunk, the lights that cannot reach it. */
        cdl_vec3 lo = grid->points[start], hi = grid->points[start];
        for (size_t i = start + 1; i < end; ++i) {
            cdl_vec3 q = grid->points[i];
            lo.x = q.x < lo.x ? q.x : lo.x;
            lo.y = q.y < lo.y ? q.y : lo.y;
            lo.z = q.z < lo.z ? q.z : lo.z;
            hi.x = q.x > hi.x ? q.x : hi.x;
            hi.y = q.y > hi.y ? q.y : hi.y;
            hi.z = q.z > hi.z ? q.z : hi.z;
        }
        size_t active = cdl_direct_select_lights(job->ctx, cdl_vec3_scale(cdl_vec3_add(lo, hi), 0.5),
                                                 0.5 * cdl_vec3_distance(lo, hi), w->active);
        uint64_t streams[CDL_DIRECT_CHUNK_MAX];
        double var[CDL_DIRECT_CHUNK_MAX];
        for (size_t i = start; i < end; ++i)
            streams[i - start] =
                cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x6772696470ull /* "gridp" */);
        w->status = cdl_direct_illuminance_chunk(job->ctx, job->strategies, w->active, active, streams,
                                                 grid->points + start, grid->normals + start, end - start,
                                                 job->gs->E + start, var, &w->stats, &w->scratch, &w->err);
        if (w->status != CDL_OK) break;
        for (size_t i = start; i < end; ++i) {
            job->gs->E_direct[i] = job->gs->E[i];
            job->gs->E_indirect[i] = 0.0;
            job->gs->E_stderr[i] = sqrt(var[i - start]);
            if (job->want_ao)
                job->gs->ao[i] = cdl_direct_ambient_occlusion(job->ctx, streams[i - start], grid->points[i],
                                                              grid->normals[i], &w->stats);
        }
    }
    return NULL;
}

static cdl_status run_grid(grid_job *job, int threads, cdl_direct_sample_stats *total, cdl_error *err)
{
    worker_state *ws = calloc((size_t)threads, sizeof *ws);
    pthread_t *tid = calloc((size_t)threads, sizeof *tid);
    if (!ws || !tid) {
        free(ws);
        free(tid);
        return cdl_error_out_of_memory(err);
    }
    int started = 0;
    uint32_t *active = malloc((size_t)threads * (job->ctx->light_count + 1) * sizeof(uint32_t));
    if (!active) {
        free(ws);
        free(tid);
        return cdl_error_out_of_memory(err);
    }
    for (int i = 0; i < threads; ++i) {
        ws[i].job = job;
        ws[i].active = active + (size_t)i * (job->ctx->light_count + 1);
        if (i == 0) continue; /* the calling thread works too */
        if (pthread_create(&tid[i], NULL, worker_main, &ws[i]) != 0) break;
        started = i;
    }
    worker_main(&ws[0]);
    for (int i = 1; i <= started; ++i) pthread_join(tid[i], NULL);
    cdl_status st = CDL_OK;
    for (int i = 0; i < threads; ++i) {
        total->rays += ws[i].stats.rays;
        total->exact_evaluations += ws[i].stats.exact_evaluations;
        total->sampled_evaluations += ws[i].stats.sampled_evaluations;
        if (st == CDL_OK && ws[i].status != CDL_OK) {
            st = ws[i].status;
            if (err) *err = ws[i].err;
        }
        cdl_direct_scratch_release(&ws[i].scratch);
    }
    free(active);
    free(ws);
    free(tid);
    return st;
}

/* ---- results a double cannot hold ------------------------------------------------ */

/* A light closer to a grid point than a double's range allows (1e-200 m)
 * makes I cos / d^2 infinite; a result file cannot hold that. Say which
 * point and which light, as bad input, instead of failing at writing. */
static cdl_status check_finite(const cdl_scene *scene, const cdl_scene_lights *lights, size_t g,
                               const cdl_grid_solution *gs, cdl_error *err)
{
    const cdl_grid_spec *spec = &scene->grids[g];
    for (size_t i = 0; i < gs->grid.count; ++i) {
        if (isfinite(gs->E[i]) && isfinite(gs->E_stderr[i])) continue;
        cdl_vec3 p = gs->grid.points[i], n = gs->grid.normals[i];
        const char *culprit = NULL;
        for (size_t l = 0; l < lights->count && !culprit; ++l) {
            cdl_illuminance E;
            if (cdl_emitter_exact_illuminance(lights->emitters[l], p, n, &E, NULL) == CDL_OK && !isfinite(E.lx))
                culprit = lights->lights[l].label;
        }
        const char *what = isfinite(gs->E[i]) ? "its standard error" : "the illuminance";
        if (culprit)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s (%s) point %zu at [%.10g, %.10g, %.10g]: expected a finite illuminance, found "
                                 "%s beyond the range of a double: %s is too close to the point (or too bright)",
                                 scene->path, spec->json_path, spec->name, i, p.x, p.y, p.z, what, culprit);
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: %s (%s) point %zu at [%.10g, %.10g, %.10g]: expected a finite illuminance, found %s "
                             "beyond the range of a double: a light is too close to the point (or too bright)",
                             scene->path, spec->json_path, spec->name, i, p.x, p.y, p.z, what);
    }
    return CDL_OK;
}

/* ---- the solve ------------------------------------------------------------------ */

/* A point's rays start one epsilon along its normal n (ray_offsets in
 * scene_geometry.h). That moves the start off every surface through the
 * point by epsilon x |cos| of the angle between n and the surface's normal:
 * the whole epsilon for the surface the point faces, nothing for one whose
 * plane contains n (a wall standing on the floor a point lies on). A surface
 * within an eighth of an epsilon of the start (an axis-aligned box: within
 * 0.125 to 0.22 epsilon) therefore passes through the point nearly along n,
 * and which side of it the point is on is unknown: an edge point. */
static void find_edge_points(const cdl_direct_context *ctx, cdl_grid_solution *gs)
{
    gs->edge_point_count = 0;
    gs->first_edge_point = 0;
    for (size_t i = 0; i < gs->grid.count; ++i) {
        cdl_vec3 p = gs->grid.points[i];
        double eps = cdl_ray_offsets_epsilon(&ctx->offsets, p);
        cdl_vec3 o = cdl_vec3_madd(p, eps, gs->grid.normals[i]);
        cdl_vec3 h = cdl_vec3_make(0.125 * eps, 0.125 * eps, 0.125 * eps);
        if (cdl_occluder_index_surface_in_box(ctx->occluders, cdl_vec3_sub(o, h), cdl_vec3_add(o, h))) {
            if (gs->edge_point_count++ == 0) gs->first_edge_point = i;
        }
    }
}

static cdl_status alloc_grid_arrays(cdl_grid_solution *gs, int want_ao, cdl_error *err)
{
    size_t n = gs->grid.count ? gs->grid.count : 1;
    gs->E = calloc(n, sizeof(double));
    gs->E_direct = calloc(n, sizeof(double));
    gs->E_indirect = calloc(n, sizeof(double));
    gs->E_stderr = calloc(n, sizeof(double));
    gs->ao = want_ao ? calloc(n, sizeof(double)) : NULL;
    if (!gs->E || !gs->E_direct || !gs->E_indirect || !gs->E_stderr || (want_ao && !gs->ao))
        return cdl_error_out_of_memory(err);
    return CDL_OK;
}

cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution *out,
                           cdl_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = now_seconds();
    cdl_solve_options opts = CDL_SOLVE_OPTIONS_DEFAULT;
    if (options) opts = *options;

    cJSON *plan = cJSON_CreateObject();
    if (!plan) return cdl_error_out_of_memory(err);
    cdl_status st = choose_method(scene, &out->method, plan, err);
    if (st != CDL_OK) {
        cJSON_Delete(plan);
        return st;
    }
    cJSON_AddStringToObject(plan, "method", cdl_method_name(out->method));
    out->settings = scene->settings;
    int ds, as;
    quality_defaults(scene->settings.quality, &ds, &as);
    if (out->settings.direct_samples <= 0) out->settings.direct_samples = ds;
    if (out->settings.ao_samples <= 0) out->settings.ao_samples = as;
    int threads = opts.threads >= 0 ? opts.threads : scene->settings.threads;
    if (threads <= 0) threads = cpu_count();
    if (opts.ray_log) threads = 1;
    out->threads_used = threads;

    cdl_scene_geometry *geometry = NULL;
    cdl_occluder_index *occluders = NULL;
    cdl_scene_lights lights;
    memset(&lights, 0, sizeof lights);
    cdl_light_strategy *strategies = NULL;
    cJSON **plan_grids = NULL;

    if (opts.progress) opts.progress(opts.progress_user, "geometry", 0, 1);
    st = cdl_scene_geometry_build(scene, &geometry, err);
    if (st != CDL_OK) goto fail;
    size_t pieces = cdl_scene_geometry_piece_count(geometry);
    if (pieces > 0) {
        st = build_occluders(geometry, &occluders, err);
        if (st != CDL_OK) goto fail;
    }
    st = cdl_scene_lights_build(scene, geometry, &lights, err);
    if (st != CDL_OK) goto fail;

    cdl_direct_context ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.geometry = pieces > 0 ? geometry : NULL;
    if (ctx.geometry) cdl_scene_geometry_ray_offsets(geometry, &ctx.offsets);
    ctx.rays = pieces > 0 ? cdl_scene_geometry_rays(geometry) : NULL;
    ctx.occluders = occluders;
    ctx.lights = lights.lights;
    ctx.light_count = lights.count;
    ctx.samples = out->settings.direct_samples;
    ctx.ao_samples = out->settings.ao_samples;
    ctx.seed = scene->settings.seed;
    ctx.log = opts.ray_log;

    cJSON *direct = cJSON_AddArrayToObject(plan, "direct");
    /* Each light's "grids" object, kept at hand: looking it up in the array
     * for every grid cost lights^2 x grids (minutes for thousands of each). */
    plan_grids = calloc(lights.count ? lights.count : 1, sizeof *plan_grids);
    if (!plan_grids) {
        st = cdl_error_out_of_memory(err);
        goto fail;
    }
    for (size_t l = 0; l < lights.count; ++l) {
        cJSON *item = cJSON_CreateObject();
        cJSON_AddStringToObject(item, "light", lights.lights[l].label);
        cJSON_AddStringToObject(item, "kind", lights.kinds[l]);
        plan_grids[l] = cJSON_AddObjectToObject(item, "grids");
        cJSON_AddItemToArray(direct, item);
    }
    if (lights.count == 0)
        cJSON_AddStringToObject(plan, "note", "the scene has no luminaire and no emitting surface: all grids are dark");
    cJSON_AddStringToObject(plan, "environment",
                            lights.has_environment ? "modelled (see direct)" : "none in the scene: no environment work");
    cJSON_AddStringToObject(plan, "geometry",
                            pieces ? "surfaces present: visibility tested (see each light's strategy)"
                                   : "no surfaces: nothing can cast a shadow, no rays are traced");

    out->grid_count = scene->grid_count;
    out->grids = calloc(scene->grid_count ? scene->grid_count : 1, sizeof *out->grids);
    strategies = calloc(lights.count ? lights.count : 1, sizeof *strategies);
    if (!out->grids || !strategies) {
        st = cdl_error_out_of_memory(err);
        goto fail;
    }
    cdl_direct_sample_stats total = {0, 0, 0};
    for (size_t g = 0; g < scene->grid_count; ++g) {
        const cdl_grid_spec *spec = &scene->grids[g];
        cdl_grid_solution *gs = &out->grids[g];
        st = cdl_grid_build(spec, &gs->grid, err);
        if (st != CDL_OK) {
            cdl_error_prefix(err, "%s: ", scene->path);
            goto fail;
        }
        st = alloc_grid_arrays(gs, spec->want_ao, err);
        if (st != CDL_OK) goto fail;
        if (ctx.occluders) find_edge_points(&ctx, gs);
        cdl_direct_plan_grid(&ctx, gs->grid.points, gs->grid.count, strategies);
        for (size_t l = 0; l < lights.count; ++l)
            cJSON_AddStringToObject(plan_grids[l], spec->name, cdl_light_strategy_name(strategies[l]));
        if (opts.progress) opts.progress(opts.progress_user, spec->name, 0, gs->grid.count);
        grid_job job;
        job.ctx = &ctx;
        job.strategies = strategies;
        job.gs = gs;
        job.grid_index = g;
        job.want_ao = spec->want_ao;
        atomic_init(&job.next, 0);
        job.chunk = 16;
        double tc = now_seconds();
        st = run_grid(&job, threads, &total, err);
        out->compute_seconds += now_seconds() - tc;
        if (st == CDL_OK) st = check_finite(scene, &lights, g, gs, err);
        if (st != CDL_OK) goto fail;
        if (opts.progress) opts.progress(opts.progress_user, spec->name, gs->grid.count, gs->grid.count);
    }
    {
        cJSON *counts = cJSON_AddObjectToObject(plan, "evaluations");
        cJSON_AddNumberToObject(counts, "closed_form", (double)total.exact_evaluations);
        cJSON_AddNumberToObject(counts, "sampled", (double)total.sampled_evaluations);
    }
    out->rays = total.rays;
    out->plan_json = cJSON_PrintUnformatted(plan);
    if (!out->plan_json) {
        st = cdl_error_out_of_memory(err);
        goto fail;
    }
    cJSON_Delete(plan);
    free(plan_grids);
    free(strategies);
    cdl_scene_lights_release(&lights);
    cdl_occluder_index_release(occluders);
    cdl_scene_geometry_release(geometry);
    out->seconds = now_seconds() - t0;
    return CDL_OK;

fail:
    cJSON_Delete(plan);
    free(plan_grids);
    free(strategies);
    cdl_scene_lights_release(&lights);
    cdl_occluder_index_release(occluders);
    cdl_scene_geometry_release(geometry);
    cdl_solution_release(out);
    return st;
}

void cdl_solution_release(cdl_solution *s)
{
    if (!s) return;
    for (size_t g = 0; g < s->grid_count && s->grids; ++g) {
        cdl_grid_solution *gs = &s->grids[g];
        cdl_grid_release(&gs->grid);
        free(gs->E);
        free(gs->E_direct);
        free(gs->E_indirect);
        free(gs->E_stderr);
        free(gs->ao);
    }
    free(s->grids);
    free(s->plan_json);
    memset(s, 0, sizeof *s);
}
