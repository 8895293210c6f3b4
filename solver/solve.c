/* solve.c - the solve: choose the method, plan each light per grid, dispatch, collect. */
#include "solver/solve.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "radiometry/constants.h"
#include "base/content_hash.h"
#include "base/rng.h"
#include "solver/direct/direct.h"
#include "solver/direct/direct_grid.h"
#include "solver/geometry/occluder_index.h"
#include "solver/icache/icache.h"
#include "solver/icache/icache_file.h"
#include "solver/pathtrace/pathtrace.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_hash.h"
#include "solver/scene/scene_lights.h"
#include "solver/scene/scene_occluders.h"
#include "solver/solve_checks.h"
#include "solver/transport/vertical_sampled.h"

/* Ambient-occlusion samples per point implied by the quality level (an
 * explicit ao_samples overrides). Direct light samples to the target. */
static int quality_ao_samples(cdl_quality q)
{
    static const int ao[] = {64, 256, 1024, 4096};
    return ao[q];
}

const char *cdl_solve_first_reflector(const cdl_scene *scene, double *rho)
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

/* Under "auto", a grid takes the irradiance cache when its point count
 * times the target relative error is at least CDL_AUTO_CACHE_SCORE, else
 * path tracing. Why a product: path tracing costs points / t^2; the cache
 * costs records / t^2 (each record gathered to about a point's variance),
 * and its records, spaced in proportion to sqrt t (icache.c), number about
 * 1 / t over a grid's area, so the ratio goes as points t. Measured (user
 * CPU seconds at equal RMS error against path tracing to 0.05 % or finer):
 *  - the Radiance peer's room, 81 points, high (0.1 %): path tracing 0.3 s
 *    for the cache's 0.14 % RMS, the cache 1.2 s (points t = 0.08);
 *  - the office work plane, 60 points, normal (0.5 %): the cache 0.26 s for
 *    0.41 % RMS, path tracing about 0.32 s (points t = 0.3); at 240 points
 *    the cache 0.57 s, path tracing 2.3 s at its (smaller) stated error;
 *  - the closed cube's 10 000 floor and 2500 wall points at normal: the
 *    cache several times cheaper (bench_icache).
 * The crossing lies near points t = 0.3 to 0.4. */
#define CDL_AUTO_CACHE_SCORE 0.4

/* The method that computes a grid's interreflection, and the point count
 * times the target that chose it under "auto". */
/* A near-field light's part of a grid, appended to its plan text: an
 * opening everywhere ("always"), or for a split luminaire ("auto") how
 * many points each part lights and why (the opening within
 * CDL_NEAR_FIELD_DISTANCES opening sizes, the point beyond). */
static void describe_near_field(const cdl_scene_light *light, const cdl_grid *grid, char *text, size_t size)
{
    size_t used = strlen(text);
    if (!light->near_part) {
        if (cdl_emitter_get_kind(light->emitter) == CDL_EMITTER_GONIOMETRIC_OPENING)
            snprintf(text + used, size - used, "; near field \"always\": spread over its luminous opening at every point");
        return;
    }
    size_t lit = 0;
    for (size_t i = 0; i < grid->count; ++i) lit += (size_t)cdl_scene_light_applies(light, grid->points[i]);
    snprintf(text + used, size - used,
             "; near field \"auto\": %s at %zu of %zu points (%s %.3g m = %g x the opening's largest dimension "
             "from its centre)",
             light->near_part > 0 ? "spread over its luminous opening" : "a point", lit, grid->count,
             light->near_part > 0 ? "nearer than" : "at or beyond", light->near_radius, CDL_NEAR_FIELD_DISTANCES);
}

static cdl_method grid_method(cdl_method method, const cdl_grid *grid, double target, double *score)
{
    *score = (double)grid->count * target;
    if (method == CDL_METHOD_ICACHE || method == CDL_METHOD_PATHTRACE) return method;
    return *score >= CDL_AUTO_CACHE_SCORE ? CDL_METHOD_ICACHE : CDL_METHOD_PATHTRACE;
}

/* The method, and whether interreflection is computed at all (*indirect),
 * with the reason in the plan. */
static cdl_status choose_method(const cdl_scene *scene, cdl_method *method, int *indirect, cJSON *plan,
                                cdl_error *err)
{
    double rho = 0.0;
    const char *reflector = cdl_solve_first_reflector(scene, &rho);
    cJSON *inter = cJSON_AddObjectToObject(plan, "interreflection");
    char why[320];
    *indirect = 0;
    *method = scene->settings.method;
    switch (scene->settings.method) {
    case CDL_METHOD_DIRECT:
        if (reflector)
            snprintf(why, sizeof why, "method \"direct\" asks for direct light only (%s reflects %g %%)", reflector,
                     rho * 100.0);
        else
            snprintf(why, sizeof why, "method \"direct\"; no surface reflects light, so none would be interreflected");
        break;
    case CDL_METHOD_AUTO:
        if (!reflector) {
            *method = CDL_METHOD_DIRECT;
            snprintf(why, sizeof why, "no surface reflects light: direct light is the whole answer");
            break;
        }
        *indirect = 1;
        snprintf(why, sizeof why,
                 "%s reflects %g %%: interreflected light to the target, each grid by the method cheaper for it "
                 "(see grids: the irradiance cache where points x target error >= %g, path tracing below)",
                 reflector, rho * 100.0, CDL_AUTO_CACHE_SCORE);
        break;
    case CDL_METHOD_PATHTRACE:
        *indirect = reflector != NULL;
        if (reflector)
            snprintf(why, sizeof why, "method \"pathtrace\": %s reflects %g %%, paths traced from each point to the target",
                     reflector, rho * 100.0);
        else
            snprintf(why, sizeof why, "method \"pathtrace\", but no surface reflects light: direct light is the whole "
                                      "answer and no path is traced");
        break;
    case CDL_METHOD_ICACHE:
        *indirect = reflector != NULL;
        if (reflector)
            snprintf(why, sizeof why, "method \"icache\": %s reflects %g %%, records gathered and interpolated to "
                                      "the target", reflector, rho * 100.0);
        else
            snprintf(why, sizeof why, "method \"icache\", but no surface reflects light: direct light is the whole "
                                      "answer and no record is gathered");
        break;
    default:
        return cdl_error_set(err, CDL_ERR_INTERNAL, "unknown method");
    }
    cJSON_AddBoolToObject(inter, "modelled", *indirect);
    cJSON_AddStringToObject(inter, "why", why);
    return CDL_OK;
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

/* ---- outputs beyond E ------------------------------------------------------------ */

/* Cylindrical and semicylindrical illuminance: exact for delta lights
 * (direct_vertical.c), sampled for the rest (transport/vertical_sampled.c).
 * A semicylinder needs a horizontal direction to face. *sampled: whether
 * the grid's vertical outputs need the sampled part (extended emitters,
 * skies, or interreflection). */
static cdl_status check_vertical_outputs(const cdl_scene *scene, const cdl_scene_lights *lights, int indirect,
                                         size_t g, const cdl_grid *grid, int *sampled, cdl_error *err)
{
    const cdl_grid_spec *spec = &scene->grids[g];
    *sampled = 0;
    if (!spec->want_cylindrical && !spec->want_semicylindrical) return CDL_OK;
    *sampled = indirect;
    for (size_t l = 0; l < lights->count; ++l)
        if (!cdl_emitter_is_delta(lights->emitters[l])) *sampled = 1;
    if (spec->want_semicylindrical)
        for (size_t i = 0; i < grid->count; ++i) {
            cdl_vec3 facing;
            if (!cdl_direct_facing_direction(grid->normals[i], &facing))
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: %s.outputs: expected points facing a horizontal direction for "
                                     "semicylindrical illuminance (it faces the horizontal part of each point's "
                                     "normal), found point %zu with the vertical normal [%.6g, %.6g, %.6g]: give the "
                                     "grid a \"normal\" with a horizontal part",
                                     scene->path, spec->json_path, i, grid->normals[i].x, grid->normals[i].y,
                                     grid->normals[i].z);
        }
    return CDL_OK;
}

/* The reflectance under each point of a grid asking for "luminance". */
static cdl_status find_reflectances(const cdl_scene *scene, const cdl_scene_geometry *geometry,
                                    const cdl_occluder_index *occluders, size_t g, cdl_grid_solution *gs,
                                    cdl_error *err)
{
    const cdl_grid_spec *spec = &scene->grids[g];
    if (!spec->want_luminance) return CDL_OK;
    size_t missing = 0;
    if (cdl_grid_surface_reflectance(&gs->grid, geometry, occluders, gs->rho, &missing) == CDL_OK) return CDL_OK;
    cdl_vec3 p = gs->grid.points[missing];
    return cdl_error_set(err, CDL_ERR_INPUT,
                         "%s: %s.outputs: expected a grid lying on a surface for \"luminance\" (rho E / pi of that "
                         "surface), found point %zu at [%.10g, %.10g, %.10g] on no surface that reflects towards its "
                         "normal",
                         scene->path, spec->json_path, missing, p.x, p.y, p.z);
}

/* ---- the solve ------------------------------------------------------------------ */

/* A grid's key for its random numbers: a hash of its name (FNV-1a, 64
 * bits), not its place in the scene, so that a grid's values do not change
 * when other grids are added, removed or reordered. */
static uint64_t grid_key(const char *name)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, name, strlen(name));
    return h.value;
}

static void release_records(cdl_icache_records *records, size_t count)
{
    for (size_t g = 0; g < count; ++g) cdl_icache_records_release(&records[g]);
    free(records);
}

/* ---- the cache file (icache/icache_file.h) ---------------------------------------- */

typedef struct cache_use {
    const char *path;
    cdl_icache_key key;
    size_t *grids;            /* the grids the irradiance cache solves */
    size_t count;
    int reused;               /* 1: their records were read from the file */
    uint64_t records_read;
} cache_use;

/* A missing cache file is written after the solve: its folder must take it
 * (checked now, not after a long solve). */
static cdl_status check_cache_folder(const char *path, cdl_error *err)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (slash == path ? 1 : (size_t)(slash - path)) : 1;
    char *folder = malloc(n + 1);
    if (!folder) return cdl_error_out_of_memory(err);
    memcpy(folder, slash ? path : ".", n);
    folder[n] = '\0';
    cdl_status st = CDL_OK;
    if (access(folder, W_OK | X_OK) != 0)
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: cannot write the irradiance cache file there: the folder %s is missing or not "
                           "writable", path, folder);
    free(folder);
    return st;
}

/* What the records depend on now; which grids the cache solves; and, when
 * the file exists and was made for them, their records (moved into
 * records[g]). */
static cdl_status cache_open(const cdl_scene *scene, const cdl_scene_lights *lights, const cdl_solve_options *opts,
                             int indirect, const cdl_solution *out, cdl_icache_records *records, cache_use *cache,
                             cdl_error *err)
{
    cache->path = opts->cache_path;
    if (!cache->path[0]) return cdl_error_set(err, CDL_ERR_USAGE, "cache: expected a file name, found an empty string");
    snprintf(cache->key.version, sizeof cache->key.version, "%s", CDL_ICACHE_MAKER);
    cdl_icache_settings *ks = &cache->key.settings;
    ks->method = scene->settings.method;
    ks->target = cdl_solver_settings_target(&scene->settings);
    ks->bounces = scene->settings.bounces;
    ks->seed = scene->settings.seed;
    ks->direct_samples = out->settings.direct_samples;
    ks->exact_route = !opts->no_exact_route;
    ks->gradients = !opts->no_cache_gradients;
    cdl_status st = cdl_scene_hash(scene, lights, &cache->key.scene, err);
    if (st != CDL_OK) return st;
    cache->grids = malloc((scene->grid_count ? scene->grid_count : 1) * sizeof *cache->grids);
    if (!cache->grids) return cdl_error_out_of_memory(err);
    double score;
    for (size_t g = 0; indirect && g < scene->grid_count; ++g)
        if (grid_method(scene->settings.method, &out->grids[g].grid, cdl_solver_settings_target(&scene->settings),
                        &score) == CDL_METHOD_ICACHE)
            cache->grids[cache->count++] = g;

    int found = 0;
    cdl_icache_file file;
    st = cdl_icache_file_load(cache->path, &found, &file, err);
    if (st != CDL_OK) return st;
    if (!found) return check_cache_folder(cache->path, err);
    const char **names = malloc((cache->count ? cache->count : 1) * sizeof *names);
    const cdl_grid **grids = malloc((cache->count ? cache->count : 1) * sizeof *grids);
    size_t *index = malloc((cache->count ? cache->count : 1) * sizeof *index);
    st = names && grids && index ? cdl_icache_file_match_key(&file, cache->path, &cache->key, err)
                                 : cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < cache->count; ++k) {
        names[k] = scene->grids[cache->grids[k]].name;
        grids[k] = &out->grids[cache->grids[k]].grid;
    }
    if (st == CDL_OK)
        st = cdl_icache_file_match_grids(&file, cache->path, names, grids, cache->count, index, err);
    for (size_t k = 0; st == CDL_OK && k < cache->count; ++k) {
        cdl_icache_records *from = &file.grids[index[k]].records;
        records[cache->grids[k]] = *from;
        cache->records_read += from->count;
        memset(from, 0, sizeof *from);
    }
    cache->reused = st == CDL_OK;
    free(names);
    free(grids);
    free(index);
    cdl_icache_file_release(&file);
    return st;
}

/* Write the records the solve gathered. */
static cdl_status cache_save(const cache_use *cache, const cdl_scene *scene, const cdl_solution *out,
                             const cdl_icache_records *records, cdl_error *err)
{
    cdl_icache_file_grid *grids = calloc(cache->count ? cache->count : 1, sizeof *grids);
    if (!grids) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < cache->count; ++k) {
        size_t g = cache->grids[k];
        grids[k].name = scene->grids[g].name;
        grids[k].point_count = out->grids[g].grid.count;
        grids[k].points_hash = cdl_icache_grid_hash(&out->grids[g].grid);
        grids[k].records = records[g];
    }
    cdl_status st = cdl_icache_file_save(cache->path, &cache->key, grids, cache->count, err);
    free(grids);
    return st;
}

/* The plan's "cache": the file, and whether its records were used. */
static void cache_describe(const cache_use *cache, cJSON *plan)
{
    cJSON *c = cJSON_AddObjectToObject(plan, "cache");
    cJSON_AddStringToObject(c, "file", cache->path);
    cJSON_AddBoolToObject(c, "reused", cache->reused);
    cJSON_AddNumberToObject(c, "records_read", (double)cache->records_read);
    cJSON_AddNumberToObject(c, "grids", (double)cache->count);
    cJSON_AddStringToObject(c, "why", cache->reused
                                          ? "the file was made for this scene, these settings and this Candela: "
                                            "its records were used, none gathered"
                                          : "the file did not exist: records gathered, then written to it");
}

cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution *out,
                           cdl_error *err)
{
    memset(out, 0, sizeof *out);
    double t0 = cdl_pool_now_seconds();
    cdl_solve_options opts = CDL_SOLVE_OPTIONS_DEFAULT;
    if (options) opts = *options;

    cJSON *plan = cJSON_CreateObject();
    if (!plan) return cdl_error_out_of_memory(err);
    int indirect = 0;
    cdl_status st = choose_method(scene, &out->method, &indirect, plan, err);
    if (st != CDL_OK) {
        cJSON_Delete(plan);
        return st;
    }
    cJSON_AddStringToObject(plan, "method", cdl_method_name(out->method));
    out->settings = scene->settings;
    if (out->settings.ao_samples <= 0) out->settings.ao_samples = quality_ao_samples(scene->settings.quality);
    double target = cdl_solver_settings_target(&scene->settings);
    int threads = opts.threads >= 0 ? opts.threads : scene->settings.threads;
    if (threads <= 0) threads = cdl_pool_cpu_count();
    if (opts.ray_log) threads = 1;
    out->threads_used = threads;

    cdl_scene_geometry *geometry = NULL;
    cdl_occluder_index *occluders = NULL;
    cdl_scene_lights lights;
    memset(&lights, 0, sizeof lights);
    cdl_light_strategy *strategies = NULL;
    cdl_direct_route_tally *routes = NULL;
    unsigned char *on_surface = NULL;   /* the grid's points lying on a surface, for its vertical outputs */
    cJSON **plan_grids = NULL;
    cache_use cache;
    memset(&cache, 0, sizeof cache);
    cdl_icache_records *records = calloc(scene->grid_count ? scene->grid_count : 1, sizeof *records);
    if (!records) {
        cJSON_Delete(plan);
        return cdl_error_out_of_memory(err);
    }

    cdl_progress stage = {.stage = "geometry"};
    if (cdl_progress_report(&opts.progress, &stage) != 0) {
        st = cdl_error_set(err, CDL_ERR_CANCELLED, "geometry: cancelled by the caller");
        goto fail;
    }
    st = cdl_scene_geometry_build(scene, &geometry, err);
    if (st != CDL_OK) goto fail;
    size_t pieces = cdl_scene_geometry_piece_count(geometry);
    if (pieces > 0) {
        st = cdl_scene_occluders_build(geometry, &occluders, err);
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
    /* Direct light alone: the whole target is its own; with interreflection
     * half the variance of E is the direct part's, half the paths'. */
    ctx.target = indirect ? target / sqrt(2.0) : target;
    cdl_pathtrace_context pt = {.path = {.direct = &ctx,
                                         .geometry = geometry,
                                         .seed = scene->settings.seed,
                                         .bounces = scene->settings.bounces},
                                .target = target,
                                .max_paths = 16777216.0};
    cdl_path_stats pt_stats;
    memset(&pt_stats, 0, sizeof pt_stats);
    cdl_icache_context ic = {.path = pt.path, .target = target, .gradients = !opts.no_cache_gradients};
    cdl_icache_stats ic_stats;
    memset(&ic_stats, 0, sizeof ic_stats);
    cJSON *inter_grids = cJSON_AddObjectToObject(cJSON_GetObjectItem(plan, "interreflection"), "grids");
    cJSON *plan_vertical = cJSON_AddObjectToObject(plan, "vertical");
    cdl_vertical_context vctx = {.path = pt.path, .indirect = indirect && pieces > 0, .target = target,
                                 .max_samples = 1048576.0};
    vctx.path.geometry = pieces > 0 ? geometry : NULL;
    cdl_path_stats vt_stats;
    memset(&vt_stats, 0, sizeof vt_stats);
    ctx.ao_samples = out->settings.ao_samples;
    ctx.seed = scene->settings.seed;
    ctx.log = opts.ray_log;
    ctx.no_exact_route = opts.no_exact_route;

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
        if (lights.lights[l].near_field_unspread)
            cJSON_AddStringToObject(item, "near_field",
                                    "\"always\" asked, but the file gives no luminous opening that is spread "
                                    "(rectangle, circle, ellipse, box with luminous sides, vertical or horizontal "
                                    "(elliptic) cylinder, sphere or ellipsoid of non-zero size): lit as a point");
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
    routes = calloc(lights.count + 1, sizeof *routes);
    if (!out->grids || !strategies || !routes) {
        st = cdl_error_out_of_memory(err);
        goto fail;
    }
    /* Every grid is built before any is solved: a cache file is checked
     * against all of them before the long work starts. */
    for (size_t g = 0; g < scene->grid_count; ++g) {
        st = cdl_grid_build(&scene->grids[g], &out->grids[g].grid, err);
        if (st != CDL_OK) {
            cdl_error_prefix(err, "%s: ", scene->path);
            goto fail;
        }
        st = cdl_grid_solution_alloc(&out->grids[g], scene->grids[g].want_ao, err);
        if (st == CDL_OK) st = cdl_grid_solution_alloc_outputs(&out->grids[g], &scene->grids[g], err);
        int sampled = 0;
        if (st == CDL_OK) st = check_vertical_outputs(scene, &lights, indirect, g, &out->grids[g].grid, &sampled, err);
        if (st == CDL_OK && sampled) st = cdl_grid_solution_alloc_vertical_stderr(&out->grids[g], err);
        if (st == CDL_OK) st = find_reflectances(scene, geometry, occluders, g, &out->grids[g], err);
        if (st != CDL_OK) goto fail;
    }
    if (opts.cache_path) {
        st = cache_open(scene, &lights, &opts, indirect, out, records, &cache, err);
        if (st != CDL_OK) goto fail;
    }
    cdl_direct_sample_stats total = {0};
    for (size_t g = 0; g < scene->grid_count; ++g) {
        const cdl_grid_spec *spec = &scene->grids[g];
        cdl_grid_solution *gs = &out->grids[g];
        gs->edge_point_count = cdl_direct_find_edge_points(&ctx, &gs->grid, &gs->first_edge_point);
        cdl_direct_plan_grid(&ctx, gs->grid.points, gs->grid.count, strategies);
        memset(routes, 0, (lights.count + 1) * sizeof *routes);
        total.routes = routes;
        char stage_name[160];
        snprintf(stage_name, sizeof stage_name, "grid %s", spec->name);
        double tc = cdl_pool_now_seconds();
        /* A grid the cache serves takes its ambient occlusion from the
         * records' gathers (icache.h); the others cast rays of their own. */
        double score;
        cdl_method gm = grid_method(scene->settings.method, &gs->grid, cdl_solver_settings_target(&scene->settings),
                                    &score);
        int ao_from_records = indirect && gm == CDL_METHOD_ICACHE;
        /* E_stderr holds the variance until the grid is done. */
        /* A point lying on a surface sees nothing behind it: the vertical
         * outputs, which look all round, are the limit from the side the
         * point's normal faces (a floor grid's cylinders stand on the floor). */
        size_t on_surface_count = 0;
        if (gs->Ez || gs->Esz) {
            unsigned char *mask = realloc(on_surface, gs->grid.count ? gs->grid.count : 1);
            if (!mask) {
                st = cdl_error_out_of_memory(err);
                goto fail;
            }
            on_surface = mask;
            if (pieces > 0) on_surface_count = cdl_grid_surface_mask(&gs->grid, geometry, occluders, on_surface);
        }
        cdl_direct_vertical_out vertical = {gs->Ez, gs->Esz, on_surface_count ? on_surface : NULL};
        st = cdl_direct_solve_grid(&ctx, strategies, &gs->grid, (size_t)grid_key(spec->name), gs->E_direct, gs->E_stderr,
                                   ao_from_records ? NULL : gs->ao, threads,
                                   &opts.progress, &vertical, stage_name, &total, err);
        out->compute_seconds += cdl_pool_now_seconds() - tc;
        if (st != CDL_OK) goto fail;
        /* Each light's strategy, and the routes its points took (exact
         * past occluders, or sampled and why). */
        for (size_t l = 0; l < lights.count; ++l) {
            char text[768], routes_text[512];
            cdl_direct_route_describe(&routes[l], routes_text, sizeof routes_text);
            snprintf(text, sizeof text, "%s%s%s", cdl_light_strategy_describe(strategies[l], &lights.lights[l]), routes_text[0] ? "; " : "",
                     routes_text);
            describe_near_field(&lights.lights[l], &gs->grid, text, sizeof text);
            cJSON_AddStringToObject(plan_grids[l], spec->name, text);
        }
        if (indirect) {
            /* gs->E holds the indirect part's variance until added. */
            snprintf(stage_name, sizeof stage_name, "grid %s: interreflection (%s)", spec->name,
                     gm == CDL_METHOD_ICACHE ? "records" : "paths");
            tc = cdl_pool_now_seconds();
            cJSON *gi = cJSON_AddObjectToObject(inter_grids, spec->name);
            cJSON_AddStringToObject(gi, "method", cdl_method_name(gm));
            if (gm == CDL_METHOD_ICACHE) {
                cdl_icache_stats before = ic_stats;
                size_t preloaded = records[g].count;
                st = cdl_icache_solve_grid(&ic, &gs->grid, (size_t)grid_key(spec->name), gs->E_direct, gs->E_stderr, gs->E_indirect, gs->E,
                                           gs->ao, &records[g], threads, &opts.progress, stage_name, &ic_stats, err);
                out->records_gathered += records[g].count - preloaded;
                cJSON_AddNumberToObject(gi, "records", (double)(ic_stats.records - before.records));
                cJSON_AddNumberToObject(gi, "placement_passes", (double)ic_stats.passes);
                cJSON_AddNumberToObject(gi, "points_served_alone", (double)(ic_stats.alone - before.alone));
            } else {
                uint64_t paths = pt_stats.paths;
                st = cdl_pathtrace_solve_grid(&pt, &gs->grid, (size_t)grid_key(spec->name), gs->E_direct, gs->E_stderr, gs->E_indirect, gs->E,
                                              threads, &opts.progress, stage_name, &pt_stats, err);
                cJSON_AddNumberToObject(gi, "paths", (double)(pt_stats.paths - paths));
            }
            if (scene->settings.method == CDL_METHOD_AUTO) {
                char why[200];
                snprintf(why, sizeof why,
                         gm == CDL_METHOD_ICACHE
                             ? "%zu points x target %g = %.3g >= %g: records interpolated cost less than paths per point"
                             : "%zu points x target %g = %.3g < %g: paths per point cost less than gathering records",
                         gs->grid.count, cdl_solver_settings_target(&scene->settings), score, CDL_AUTO_CACHE_SCORE);
                cJSON_AddStringToObject(gi, "why", why);
            }
            out->compute_seconds += cdl_pool_now_seconds() - tc;
            if (st != CDL_OK) goto fail;
        }
        for (size_t i = 0; i < gs->grid.count; ++i) {
            double var = gs->E_stderr[i] + (indirect ? gs->E[i] : 0.0);
            if (!indirect) gs->E_indirect[i] = 0.0;
            gs->E[i] = gs->E_direct[i] + gs->E_indirect[i];
            gs->E_stderr[i] = sqrt(var);
            /* Luminance of a Lambertian surface under illuminance E: L = rho E / pi
             * (its exitance rho E spread as pi L over the hemisphere). */
            if (gs->L) gs->L[i] = gs->rho[i] * gs->E[i] / CDL_PI;
        }
        if (gs->Ez_stderr || gs->Esz_stderr) {
            /* The vertical outputs' extended, sky and reflected light, sampled. */
            snprintf(stage_name, sizeof stage_name, "grid %s: cylindrical illuminance", spec->name);
            tc = cdl_pool_now_seconds();
            cdl_path_stats before = vt_stats;
            st = cdl_vertical_sampled_grid(&vctx, &gs->grid, (size_t)grid_key(spec->name), vertical.on_surface,
                                           gs->Ez, gs->Esz, gs->Ez_stderr, gs->Esz_stderr, threads, &opts.progress,
                                           stage_name, &vt_stats, err);
            out->compute_seconds += cdl_pool_now_seconds() - tc;
            if (st != CDL_OK) goto fail;
            char why[300];
            snprintf(why, sizeof why,
                     "exact for point, spot, goniometric and directional lights; extended emitters, skies%s sampled "
                     "to the target (%llu rays), with a stated error (Ez_stderr_lx, Esz_stderr_lx)",
                     indirect ? " and interreflected light" : "",
                     (unsigned long long)(vt_stats.rays - before.rays + vt_stats.direct.rays - before.direct.rays));
            cJSON_AddStringToObject(plan_vertical, spec->name, why);
        } else if (gs->Ez || gs->Esz) {
            cJSON_AddStringToObject(plan_vertical, spec->name,
                                    "exact: every light is a point, spot, goniometric or directional light and "
                                    "nothing reflects");
        }
        st = check_finite(scene, &lights, g, gs, err);
        if (st != CDL_OK) goto fail;
    }
    total.rays += vt_stats.rays + vt_stats.direct.rays;
    {
        cJSON *counts = cJSON_AddObjectToObject(plan, "evaluations");
        cJSON_AddNumberToObject(counts, "closed_form", (double)total.exact_evaluations);
        cJSON_AddNumberToObject(counts, "sampled", (double)total.sampled_evaluations);
    }
    total.routes = NULL;
    if (indirect) {
        cJSON *inter = cJSON_GetObjectItem(plan, "interreflection");
        cdl_path_stats all = pt_stats;
        cdl_path_stats_add(&all, &ic_stats.paths);
        char bounces[200];
        if (scene->settings.bounces == CDL_BOUNCES_AUTO)
            snprintf(bounces, sizeof bounces,
                     "auto: paths end by Russian roulette (unbiased); the longest followed %llu reflections",
                     (unsigned long long)all.longest);
        else
            snprintf(bounces, sizeof bounces, "at most %d reflections (the scene's limit)", scene->settings.bounces);
        cJSON_AddStringToObject(inter, "bounces", bounces);
        cJSON_AddNumberToObject(inter, "bounces_modelled",
                                scene->settings.bounces == CDL_BOUNCES_AUTO ? (double)all.longest
                                                                            : scene->settings.bounces);
        cJSON_AddNumberToObject(inter, "energy_left_out", cdl_path_left_out(&all));
        cJSON_AddNumberToObject(inter, "paths", (double)all.paths);
        cJSON_AddNumberToObject(inter, "path_vertices", (double)all.vertices);
        cJSON_AddNumberToObject(inter, "records", (double)ic_stats.records);
        total.rays += all.rays + all.direct.rays;
        out->records = ic_stats.records;
    }
    out->rays = total.rays;
    for (size_t g = 0; g < scene->grid_count; ++g) {
        const cdl_grid_solution *gs = &out->grids[g];
        if (gs->edge_point_count == 0) continue;
        cdl_vec3 q = gs->grid.points[gs->first_edge_point];
        st = cdl_solution_add_warning(
            out, err,
            "grid '%s': %zu point%s lie%s where two surfaces meet (the first is point %zu at (%.9g, %.9g, %.9g)); a "
            "surface through a point does not say which side the point is on: each reports the limit from the side "
            "its grid is meant for (the inside of a box, the side a surface's front faces); move such points off the "
            "edge if another side is meant (summary.json: edge_points)",
            scene->grids[g].name, gs->edge_point_count, gs->edge_point_count == 1 ? "" : "s",
            gs->edge_point_count == 1 ? "s" : "", gs->first_edge_point, q.x, q.y, q.z);
        if (st != CDL_OK) goto fail;
    }
    st = cdl_solve_check_lights(scene, &ctx, out, err);
    if (st == CDL_OK) st = cdl_solve_check_near_field(scene, &lights, out, err);
    if (st != CDL_OK) goto fail;
    cdl_solve_sum_power(scene, &lights, &out->power);
    if (opts.cache_path) {
        if (!cache.reused) {
            st = cache_save(&cache, scene, out, records, err);
            if (st != CDL_OK) goto fail;
        }
        out->cache_reused = cache.reused;
        cache_describe(&cache, plan);
    }
    out->plan_json = cJSON_PrintUnformatted(plan);
    if (!out->plan_json) {
        st = cdl_error_out_of_memory(err);
        goto fail;
    }
    cJSON_Delete(plan);
    free(plan_grids);
    free(strategies);
    release_records(records, scene->grid_count);
    free(cache.grids);
    free(routes);
    free(on_surface);
    cdl_scene_lights_release(&lights);
    cdl_occluder_index_release(occluders);
    cdl_scene_geometry_release(geometry);
    out->seconds = cdl_pool_now_seconds() - t0;
    return CDL_OK;

fail:
    cJSON_Delete(plan);
    free(plan_grids);
    free(strategies);
    release_records(records, scene->grid_count);
    free(cache.grids);
    free(routes);
    free(on_surface);
    cdl_scene_lights_release(&lights);
    cdl_occluder_index_release(occluders);
    cdl_scene_geometry_release(geometry);
    cdl_solution_release(out);
    return st;
}
