/* solve_plan.c - the first step of a solve: build the scene, choose the method, build and check every grid.
 *
 * Everything a long solve could fail on is checked here, before any grid
 * is computed: the geometry and the lights are built, every grid is built
 * and its outputs checked (a semicylinder needs a horizontal direction to
 * face, a luminance grid a surface under it), each grid's interreflection
 * method is decided, and a cache file is matched against all of them.
 */
#include "solver/solve_plan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/strings.h"
#include "base/error_report.h"
#include "solver/auto_method.h"
#include "solver/daylight_factor.h"
#include "solver/plan_json.h"
#include "solver/pool.h"
#include "solver/scene/scene_occluders.h"
#include "solver/solve_cache.h"
#include "solver/solve_observers.h"
#include "solver/solve_sealed.h"

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

/* The method used, and whether interreflection is computed at all: only
 * where something reflects (a surface, an area luminaire or a luminaire's
 * body) and the method asks for it. */
static cdl_status choose_method(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    state->reflector = cdl_solve_first_reflector(scene, &state->reflector_rho);
    size_t pieces = state->geometry ? cdl_scene_geometry_piece_count(state->geometry) : 0;
    for (size_t i = 0; i < pieces && !state->reflector; ++i) {
        const cdl_geometry_piece *gp = cdl_scene_geometry_piece(state->geometry, i);
        if (!gp->is_body || !(gp->reflectance > 0.0)) continue;
        snprintf(state->reflector_label, sizeof state->reflector_label, "%s's body",
                 scene->luminaires[gp->source_index].json_path);
        state->reflector = state->reflector_label;
        state->reflector_rho = gp->reflectance;
    }
    state->out->method = scene->settings.method;
    switch (scene->settings.method) {
    case CDL_METHOD_DIRECT: state->indirect = 0; return CDL_OK;
    case CDL_METHOD_AUTO:
        if (!state->reflector) state->out->method = CDL_METHOD_DIRECT;
        state->indirect = state->reflector != NULL;
        return CDL_OK;
    case CDL_METHOD_PATHTRACE:
    case CDL_METHOD_ICACHE: state->indirect = state->reflector != NULL; return CDL_OK;
    }
    return cdl_error_set(err, CDL_ERR_INTERNAL, "unknown method");
}

/* The settings the solve runs with: the quality's knobs filled in, the
 * target, the threads. */
static void settle_settings(cdl_solve_state *state)
{
    const cdl_scene *scene = state->scene;
    cdl_solution *out = state->out;
    out->settings = scene->settings;
    if (out->settings.ao_samples <= 0) out->settings.ao_samples = quality_ao_samples(scene->settings.quality);
    state->target = cdl_solver_settings_target(&scene->settings);
    out->target_error = state->target;
    int threads = state->options.threads >= 0 ? state->options.threads : scene->settings.threads;
    /* The default: this process's cores, shared with the ranks beside it. */
    if (threads <= 0) threads = cdl_pool_default_threads(state->ranks ? state->ranks->ranks.local_count : 1);
    if (state->debug.ray_log) threads = 1;
    state->threads = out->threads_used = threads;
}

/* Geometry, occluders and lights, once for the whole solve. */
static cdl_status build_scene(cdl_solve_state *state, cdl_error *err)
{
    cdl_progress stage = {.stage = "geometry"};
    if (cdl_progress_report(&state->options.progress, &stage) != 0)
        return cdl_error_set(err, CDL_ERR_CANCELLED, "geometry: cancelled by the caller");
    cdl_status st = cdl_scene_geometry_build(state->scene, &state->geometry, err);
    if (st != CDL_OK) return st;
    state->pieces = cdl_scene_geometry_piece_count(state->geometry);
    if (state->pieces > 0) {
        st = cdl_scene_occluders_build(state->geometry, &state->occluders, err);
        if (st != CDL_OK) return st;
    }
    st = cdl_scene_lights_build(state->scene, state->geometry, &state->lights, err);
    /* a sky and panes of glass: the panes as the sky's portals at path vertices */
    if (st == CDL_OK && state->lights.has_environment) st = cdl_sky_portals_build(state->geometry, &state->portals, err);
    return st;
}

/* The methods' contexts: direct light, paths, records, vertical outputs. */
static void make_contexts(cdl_solve_state *state)
{
    const cdl_scene *scene = state->scene;
    const cdl_scene_geometry *geometry = state->pieces > 0 ? state->geometry : NULL;
    cdl_direct_context *ctx = &state->direct;
    memset(ctx, 0, sizeof *ctx);
    ctx->geometry = geometry;
    if (geometry) cdl_scene_geometry_ray_offsets(geometry, &ctx->offsets);
    ctx->rays = geometry ? cdl_scene_geometry_rays(geometry) : NULL;
    ctx->occluders = state->occluders;
    ctx->portals = state->portals.count ? &state->portals : NULL;
    ctx->lights = state->lights.lights;
    ctx->light_count = state->lights.count;
    ctx->samples = state->out->settings.direct_samples;
    /* Direct light alone: the whole target is its own; with interreflection
     * half the variance of E is the direct part's, half the paths'. */
    ctx->target = state->indirect ? state->target / sqrt(2.0) : state->target;
    ctx->ao_samples = state->out->settings.ao_samples;
    ctx->seed = scene->settings.seed;
    ctx->log = state->debug.ray_log;
    ctx->no_exact_route = state->debug.no_exact_route;

    cdl_path_context path = {.direct = ctx,
                             .geometry = state->geometry,
                             .seed = scene->settings.seed,
                             .bounces = scene->settings.bounces};
    state->pathtrace = (cdl_pathtrace_context){.path = path,
                                               .target = state->target,
                                               .max_paths = 16777216.0,
                                               .measure_alpha = !state->debug.paths_as_one_over_n};
    state->icache = (cdl_icache_context){.path = path, .target = state->target,
                                         .gradients = !state->debug.no_cache_gradients,
                                         .own_alone = state->debug.cache_own_alone};
    state->vertical = (cdl_vertical_context){.path = path, .indirect = state->indirect && state->pieces > 0,
                                             .target = state->target, .max_samples = 1048576.0};
    state->vertical.path.geometry = geometry;
}

/* Cylindrical and semicylindrical illuminance: exact for delta lights
 * (direct_vertical.c), sampled for the rest (transport/vertical_sampled.c).
 * A semicylinder needs a horizontal direction to face. *sampled: whether
 * the grid's vertical outputs need the sampled part (extended emitters,
 * skies, or interreflection). */
static cdl_status check_vertical_outputs(const cdl_solve_state *state, size_t g, const cdl_grid *grid, int *sampled,
                                         cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    const cdl_grid_spec *spec = &scene->grids[g];
    *sampled = 0;
    if (!spec->want_cylindrical && !spec->want_semicylindrical) return CDL_OK;
    *sampled = state->indirect;
    for (size_t l = 0; l < state->lights.count; ++l)
        if (!cdl_emitter_is_delta(state->lights.emitters[l])) *sampled = 1;
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
static cdl_status find_reflectances(const cdl_solve_state *state, size_t g, cdl_grid_solution *gs, cdl_error *err)
{
    const cdl_grid_spec *spec = &state->scene->grids[g];
    if (!spec->want_luminance) return CDL_OK;
    size_t missing = 0;
    if (cdl_grid_surface_reflectance(&gs->grid, state->geometry, state->occluders, gs->rho, &missing) == CDL_OK)
        return CDL_OK;
    cdl_vec3 p = gs->grid.points[missing];
    return cdl_error_set(err, CDL_ERR_INPUT,
                         "%s: %s.outputs: expected a grid lying on a surface for \"luminance\" (rho E / pi of that "
                         "surface), found point %zu at [%.10g, %.10g, %.10g] on no surface that reflects towards its "
                         "normal",
                         state->scene->path, spec->json_path, missing, p.x, p.y, p.z);
}

/* A grid's key for its random numbers: a hash of its name (FNV-1a, 64
 * bits), not its place in the scene, so that a grid's values do not change
 * when other grids are added, removed or reordered. */
static uint64_t grid_key(const char *name)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, name, strlen(name));
    return h.value;
}

/* One grid: its points, its result arrays, its outputs checked, its plan. */
static cdl_status plan_grid(cdl_solve_state *state, size_t g, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    const cdl_grid_spec *spec = &scene->grids[g];
    cdl_grid_solution *gs = &state->out->grids[g];
    gs->kind = spec->kind;
    if (!(gs->name = cdl_string_copy(spec->name))) return cdl_error_out_of_memory(err);
    cdl_status st = cdl_grid_build(spec, &gs->grid, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", scene->path);
    st = cdl_grid_solution_alloc(gs, spec->want_ao, err);
    if (st == CDL_OK) st = cdl_grid_solution_alloc_outputs(gs, spec, err);
    cdl_grid_plan *plan = &state->grids[g];
    if (st == CDL_OK) st = check_vertical_outputs(state, g, &gs->grid, &plan->vertical_sampled, err);
    if (st == CDL_OK && plan->vertical_sampled) st = cdl_grid_solution_alloc_vertical_stderr(gs, err);
    if (st == CDL_OK) st = find_reflectances(state, g, gs, err);
    if (st == CDL_OK && spec->want_daylight_factor) {
        char words[400];
        st = cdl_daylight_factor_reference(scene, &state->lights, spec, &plan->daylight_E_h, words, sizeof words, err);
        if (st == CDL_OK) cdl_plan_json_daylight_factor(state->plan, spec->name, words);
    }
    if (st != CDL_OK) return st;
    plan->key = grid_key(spec->name);
    cdl_method method = cdl_auto_grid_method(scene->settings.method, gs->grid.count, state->target, &plan->score);
    plan->method = state->indirect ? method : CDL_METHOD_DIRECT;
    return CDL_OK;
}

cdl_status cdl_solve_plan(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    /* the geometry first: a luminaire's body may be what reflects */
    cdl_status st = build_scene(state, err);
    if (st == CDL_OK) st = choose_method(state, err);
    if (st != CDL_OK) return st;
    settle_settings(state);
    size_t grids = scene->grid_count ? scene->grid_count : 1;
    state->records = calloc(grids, sizeof *state->records);
    state->grids = calloc(grids, sizeof *state->grids);
    if (!state->records || !state->grids) return cdl_error_out_of_memory(err);
    st = cdl_plan_json_create(state, &state->plan, err);
    if (st != CDL_OK) return st;
    make_contexts(state);
    st = cdl_plan_json_lights(state->plan, state, err);
    if (st != CDL_OK) return st;

    state->out->grid_count = scene->grid_count;
    state->out->grids = calloc(grids, sizeof *state->out->grids);
    size_t lights = state->lights.count;
    state->strategies = calloc(lights ? lights : 1, sizeof *state->strategies);
    state->routes = calloc(lights + 1, sizeof *state->routes);
    if (!state->out->grids || !state->strategies || !state->routes) return cdl_error_out_of_memory(err);
    /* Every grid is built before any is solved: a cache file is checked
     * against all of them before the long work starts. */
    for (size_t g = 0; g < scene->grid_count; ++g) {
        st = plan_grid(state, g, err);
        if (st != CDL_OK) return st;
    }
    /* before the observers copy the lights */
    cdl_solve_seal_lights(state);
    st = cdl_solve_plan_observers(state, err);
    if (st != CDL_OK) return st;
    if (state->options.cache_path) {
        for (size_t k = 0; k < scene->surface_count; ++k)
            if (scene->surfaces[k].mapped)
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: a cache file (--cache) cannot be used with surface maps yet (%s is mapped): "
                                     "their records are placed as the maps' meshes refine; solve without --cache, or "
                                     "with \"surface_maps\": \"none\" and no surface requirements",
                                     scene->path, scene->surfaces[k].json_path);
        return cdl_solve_cache_open(state, err);
    }
    return CDL_OK;
}
