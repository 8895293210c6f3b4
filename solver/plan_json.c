/* plan_json.c - the plan of a solve as JSON (plan_json.h).
 *
 * The keys and their order are those of summary.json's "plan": 
 * "interreflection" (modelled, why, grids, then the totals), "method",
 * "vertical", "direct" (one entry per light with its grids), "note" for a
 * scene without light, "environment", "geometry", "evaluations", "cache".
 */
#include "solver/plan_json.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/near_field_bound.h"
#include "solver/auto_method.h"
#include "solver/output/json_numbers.h"
#include "solver/solve_cache.h"

struct cdl_plan_json {
    cJSON *root;
    cJSON *inter_grids;       /* "interreflection"."grids" */
    cJSON *vertical;          /* "vertical" */
    cJSON **light_grids;      /* each light's "grids" */
    size_t light_count;
};

/* Why interreflection is or is not computed, for the method asked. */
static void method_why(const cdl_solve_state *state, char *why, size_t size)
{
    const char *reflector = state->reflector;
    double rho = state->reflector_rho * 100.0;
    switch (state->scene->settings.method) {
    case CDL_METHOD_DIRECT:
        if (reflector)
            snprintf(why, size, "method \"direct\" asks for direct light only (%s reflects %g %%)", reflector, rho);
        else
            snprintf(why, size, "method \"direct\"; no surface reflects light, so none would be interreflected");
        return;
    case CDL_METHOD_AUTO:
        if (!reflector) {
            snprintf(why, size, "no surface reflects light: direct light is the whole answer");
            return;
        }
        snprintf(why, size,
                 "%s reflects %g %%: interreflected light to the target, each grid by the method cheaper for it "
                 "(see grids: the irradiance cache where points x target error >= %g, path tracing below)",
                 reflector, rho, CDL_AUTO_CACHE_SCORE);
        return;
    case CDL_METHOD_PATHTRACE:
        if (reflector)
            snprintf(why, size, "method \"pathtrace\": %s reflects %g %%, paths traced from each point to the target",
                     reflector, rho);
        else
            snprintf(why, size, "method \"pathtrace\", but no surface reflects light: direct light is the whole "
                                "answer and no path is traced");
        return;
    case CDL_METHOD_ICACHE:
        if (reflector)
            snprintf(why, size, "method \"icache\": %s reflects %g %%, records gathered and interpolated to "
                                "the target", reflector, rho);
        else
            snprintf(why, size, "method \"icache\", but no surface reflects light: direct light is the whole "
                                "answer and no record is gathered");
        return;
    }
    snprintf(why, size, "unknown method");
}

cdl_status cdl_plan_json_create(const cdl_solve_state *state, cdl_plan_json **out, cdl_error *err)
{
    *out = NULL;
    cdl_plan_json *plan = calloc(1, sizeof *plan);
    if (!plan || !(plan->root = cJSON_CreateObject())) {
        free(plan);
        return cdl_error_out_of_memory(err);
    }
    char why[320];
    method_why(state, why, sizeof why);
    cJSON *inter = cJSON_AddObjectToObject(plan->root, "interreflection");
    cJSON_AddBoolToObject(inter, "modelled", state->indirect);
    cJSON_AddStringToObject(inter, "why", why);
    cJSON_AddStringToObject(plan->root, "method", cdl_method_name(state->out->method));
    plan->inter_grids = cJSON_AddObjectToObject(inter, "grids");
    plan->vertical = cJSON_AddObjectToObject(plan->root, "vertical");
    *out = plan;
    return CDL_OK;
}

void cdl_plan_json_daylight_factor(cdl_plan_json *plan, const char *grid, const char *words)
{
    cJSON *df = cJSON_GetObjectItemCaseSensitive(plan->root, "daylight_factor");
    if (!df) df = cJSON_AddObjectToObject(plan->root, "daylight_factor");
    if (df) cJSON_AddStringToObject(df, grid, words);
}

/* A goniometric luminaire's body (scene_bodies.h): its shape, reflectance
 * and the route the exact direct light takes past it. */
static void describe_body(cJSON *item, const cdl_solve_state *state, const cdl_scene_light *light)
{
    if (light->luminaire == SIZE_MAX) return;
    const cdl_luminaire_spec *sp = &state->scene->luminaires[light->luminaire];
    if (sp->kind != CDL_LUMINAIRE_GONIOMETRIC) return;
    if (!light->has_body) {
        cJSON_AddStringToObject(item, "body", sp->body ? "none: the file gives no luminous opening (a point)"
                                                       : "none: \"body\": false");
        return;
    }
    const cdl_geometry_piece *piece = cdl_scene_geometry_piece(state->geometry, light->body);
    char shape[160];
    cdl_luminaire_body_describe(cdl_scene_geometry_luminaire_body_shape(state->geometry, light->luminaire), shape,
                                sizeof shape);
    cJSON *body = cJSON_AddObjectToObject(item, "body");
    cJSON_AddStringToObject(body, "shape", shape);
    cJSON_AddNumberToObject(body, "reflectance", piece->reflectance);
    cJSON_AddStringToObject(body, "own_light", "passes it: the luminaire's light leaves through its opening");
    cJSON_AddStringToObject(body, "as_occluder",
                            cdl_geometry_piece_is_curved(piece)
                                ? "curved: other lights past it are sampled with shadow rays to the target"
                                : "planar: other lights past it stay exact (shadow rays for points, the visible "
                                  "polygon for extended lights)");
}

cdl_status cdl_plan_json_lights(cdl_plan_json *plan, const cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene_lights *lights = &state->lights;
    cJSON *direct = cJSON_AddArrayToObject(plan->root, "direct");
    /* Each light's "grids" object, kept at hand: looking it up in the array
     * for every grid cost lights^2 x grids (minutes for thousands of each). */
    plan->light_grids = calloc(lights->count ? lights->count : 1, sizeof *plan->light_grids);
    if (!plan->light_grids) return cdl_error_out_of_memory(err);
    plan->light_count = lights->count;
    for (size_t l = 0; l < lights->count; ++l) {
        cJSON *item = cJSON_CreateObject();
        cJSON_AddStringToObject(item, "light", lights->lights[l].label);
        cJSON_AddStringToObject(item, "kind", lights->kinds[l]);
        if (lights->lights[l].model) cJSON_AddStringToObject(item, "model", lights->lights[l].model);
        if (lights->lights[l].near_field_unspread)
            cJSON_AddStringToObject(item, "near_field",
                                    "\"always\" asked, but the file gives no luminous opening that is spread "
                                    "(rectangle, circle, ellipse, box with luminous sides, vertical or horizontal "
                                    "(elliptic) cylinder, sphere or ellipsoid of non-zero size): lit as a point");
        if (lights->lights[l].near_part) {
            /* where the luminaire is spread, and what the point model may err by beyond */
            cJSON_AddNumberToObject(item, "near_field_distance_m", lights->lights[l].near_radius);
            cJSON_AddNumberToObject(item, "point_model_error_bound", lights->lights[l].near_model_error);
        }
        describe_body(item, state, &lights->lights[l]);
        plan->light_grids[l] = cJSON_AddObjectToObject(item, "grids");
        cJSON_AddItemToArray(direct, item);
    }
    if (lights->count == 0)
        cJSON_AddStringToObject(plan->root, "note",
                                "the scene has no luminaire and no emitting surface: all grids are dark");
    cJSON_AddStringToObject(plan->root, "environment",
                            lights->has_environment ? "modelled (see direct)" : "none in the scene: no environment work");
    cJSON_AddStringToObject(plan->root, "geometry",
                            state->pieces ? "surfaces present: visibility tested (see each light's strategy)"
                                          : "no surfaces: nothing can cast a shadow, no rays are traced");
    return CDL_OK;
}

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
             "; near field \"auto\": %s at %zu of %zu points (%s %.3g m from its centre: beyond, the point model "
             "errs by at most %.2g %%, %g of the target, and never within %g x the opening's largest dimension)",
             light->near_part > 0 ? "spread over its luminous opening" : "a point", lit, grid->count,
             light->near_part > 0 ? "nearer than" : "at or beyond", light->near_radius,
             100.0 * light->near_model_error, CDL_NEAR_FIELD_SHARE, CDL_NEAR_FIELD_DISTANCES);
}

/* Each light's strategy on the grid, and the routes its points took (exact
 * past occluders, or sampled and why). */
static void grid_lights(cdl_plan_json *plan, const cdl_solve_state *state, const cdl_grid_job *job)
{
    for (size_t l = 0; l < state->lights.count; ++l) {
        char text[768], routes_text[512];
        if (state->lights.lights[l].sealed_by) {
            snprintf(text, sizeof text,
                     "not modelled: it lies outside %s, a closed box that holds every point of the solve, so none "
                     "of its light can reach them (0 lx, exactly)",
                     state->lights.lights[l].sealed_by);
            cJSON_AddStringToObject(plan->light_grids[l], job->spec->name, text);
            continue;
        }
        cdl_direct_route_describe(&state->routes[l], routes_text, sizeof routes_text);
        snprintf(text, sizeof text, "%s%s%s",
                 cdl_light_strategy_describe(state->strategies[l], &state->lights.lights[l]),
                 routes_text[0] ? "; " : "", routes_text);
        describe_near_field(&state->lights.lights[l], &job->gs->grid, text, sizeof text);
        cJSON_AddStringToObject(plan->light_grids[l], job->spec->name, text);
    }
}

static void grid_interreflection(cdl_plan_json *plan, const cdl_solve_state *state, const cdl_grid_job *job)
{
    cdl_method gm = job->plan->method;
    cJSON *gi = cJSON_AddObjectToObject(plan->inter_grids, job->spec->name);
    cJSON_AddStringToObject(gi, "method", cdl_method_name(gm));
    if (gm == CDL_METHOD_ICACHE) {
        cJSON_AddNumberToObject(gi, "records", (double)job->records);
        cJSON_AddNumberToObject(gi, "placement_passes", (double)job->passes);
        cJSON_AddNumberToObject(gi, "points_served_alone", (double)job->alone);
    } else {
        cJSON_AddNumberToObject(gi, "paths", (double)job->paths);
        const cdl_pathtrace_convergence *c = &job->convergence;
        cJSON *conv = cJSON_AddObjectToObject(gi, "convergence");
        cJSON_AddNumberToObject(conv, "alpha", c->alpha);
        cJSON_AddNumberToObject(conv, "points_measured", (double)c->measured);
        cJSON_AddNumberToObject(conv, "spread", c->spread);
        cJSON_AddNumberToObject(conv, "reach_paths", c->reach_paths);
        cJSON_AddNumberToObject(conv, "alpha_beyond", c->alpha_beyond);
        cJSON_AddNumberToObject(conv, "points_measured_beyond", (double)c->measured_beyond);
        char why[320];
        if (c->measured >= 3 && !c->agreed)
            snprintf(why, sizeof why,
                     "each point's paths planned as if its variance fell as 1/N: the exponents measured at %zu of "
                     "its points spread over %.2f between their quartiles (heavy-tailed paths), too far to plan by",
                     c->measured, c->spread);
        else if (c->measured >= 3 && c->measured_beyond >= 3)
            snprintf(why, sizeof why,
                     "each point's paths planned as if its variance fell as N^-%.3f up to %.0f paths (the median "
                     "over %zu of its points of a pilot against a round of 8 pilots) and as N^-%.3f beyond (over "
                     "%zu, a round of 8 pilots against one of 64)",
                     c->alpha, c->reach_paths, c->measured, c->alpha_beyond, c->measured_beyond);
        else if (c->measured >= 3)
            snprintf(why, sizeof why,
                     "each point's paths planned as if its variance fell as N^-%.3f, the median over %zu of its "
                     "points of a pilot against a round 8 times larger (too few plans reach 64 pilots to read it "
                     "further)",
                     c->alpha, c->measured);
        else
            snprintf(why, sizeof why,
                     "each point's paths planned as if its variance fell as 1/N: %zu of its points asked for 8 "
                     "pilots or more, too few to measure the exponent on",
                     c->measured);
        cJSON_AddStringToObject(conv, "why", why);
    }
    if (state->scene->settings.method == CDL_METHOD_AUTO) {
        char why[200];
        snprintf(why, sizeof why,
                 gm == CDL_METHOD_ICACHE
                     ? "%zu points x target %g = %.3g >= %g: records interpolated cost less than paths per point"
                     : "%zu points x target %g = %.3g < %g: paths per point cost less than gathering records",
                 job->gs->grid.count, state->target, job->plan->score, CDL_AUTO_CACHE_SCORE);
        cJSON_AddStringToObject(gi, "why", why);
    }
}

static void grid_vertical(cdl_plan_json *plan, const cdl_solve_state *state, const cdl_grid_job *job)
{
    const cdl_grid_solution *gs = job->gs;
    if (gs->Ez_stderr || gs->Esz_stderr) {
        char why[300];
        snprintf(why, sizeof why,
                 "exact for point, spot, goniometric and directional lights; extended emitters, skies%s sampled "
                 "to the target (%llu rays), with a stated error (Ez_stderr_lx, Esz_stderr_lx)",
                 state->indirect ? " and interreflected light" : "", (unsigned long long)job->vertical_rays);
        cJSON_AddStringToObject(plan->vertical, job->spec->name, why);
    } else if (gs->Ez || gs->Esz) {
        cJSON_AddStringToObject(plan->vertical, job->spec->name,
                                "exact: every light is a point, spot, goniometric or directional light and "
                                "nothing reflects");
    }
}

void cdl_plan_json_grid(cdl_plan_json *plan, const cdl_solve_state *state, const cdl_grid_job *job)
{
    grid_lights(plan, state, job);
    if (state->indirect) grid_interreflection(plan, state, job);
    grid_vertical(plan, state, job);
}

/* The plan's "cache": the file, and whether its records were used. */
static void describe_cache(cJSON *root, const cdl_solve_cache *cache)
{
    cJSON *c = cJSON_AddObjectToObject(root, "cache");
    cJSON_AddStringToObject(c, "file", cache->path);
    cJSON_AddBoolToObject(c, "reused", cache->reused);
    cJSON_AddNumberToObject(c, "records_read", (double)cache->records_read);
    cJSON_AddNumberToObject(c, "grids", (double)cache->count);
    cJSON_AddStringToObject(c, "why", cache->reused
                                          ? "the file was made for this scene, these settings and this Candela: "
                                            "its records were used, none gathered"
                                          : "the file did not exist: records gathered, then written to it");
}

void cdl_plan_json_totals(cdl_plan_json *plan, const cdl_solve_state *state)
{
    cJSON *counts = cJSON_AddObjectToObject(plan->root, "evaluations");
    cJSON_AddNumberToObject(counts, "closed_form", (double)state->direct_stats.exact_evaluations);
    cJSON_AddNumberToObject(counts, "sampled", (double)state->direct_stats.sampled_evaluations);
    if (state->indirect) {
        cJSON *inter = cJSON_GetObjectItem(plan->root, "interreflection");
        cdl_path_stats all = state->pathtrace_stats;
        cdl_path_stats_add(&all, &state->icache_stats.paths);
        int bounces = state->scene->settings.bounces;
        char text[200];
        if (bounces == CDL_BOUNCES_AUTO)
            snprintf(text, sizeof text,
                     "auto: paths end by Russian roulette (unbiased); the longest followed %llu reflections",
                     (unsigned long long)all.longest);
        else
            snprintf(text, sizeof text, "at most %d reflections (the scene's limit)", bounces);
        cJSON_AddStringToObject(inter, "bounces", text);
        cJSON_AddNumberToObject(inter, "bounces_modelled", bounces == CDL_BOUNCES_AUTO ? (double)all.longest : bounces);
        cJSON_AddNumberToObject(inter, "energy_left_out", cdl_path_left_out(&all));
        cJSON_AddNumberToObject(inter, "paths", (double)all.paths);
        cJSON_AddNumberToObject(inter, "path_vertices", (double)all.vertices);
        cJSON_AddNumberToObject(inter, "records", (double)state->icache_stats.records);
    }
    if (state->cache.path) describe_cache(plan->root, &state->cache);
    if (state->scene->observer_count > 0) {
        cJSON *glare = cJSON_AddObjectToObject(plan->root, "glare");
        cJSON_AddNumberToObject(glare, "observers", (double)state->scene->observer_count);
        cJSON_AddStringToObject(glare, "rating", "UGR by CIE 117:1995 eq. 4.1, Guth's position index from its Table 4.1");
        cJSON_AddStringToObject(glare, "background",
                                state->indirect ? "E at each eye facing its line of sight from skies and emitting "
                                                  "surfaces (direct) and all interreflected light (paths), the "
                                                  "luminaires' direct light left out"
                                                : "E at each eye facing its line of sight from skies and emitting "
                                                  "surfaces; nothing reflects");
        cJSON *w = cJSON_AddObjectToObject(glare, "solid_angles");
        cJSON_AddNumberToObject(w, "exact", (double)state->glare_exact);
        cJSON_AddNumberToObject(w, "sampled", (double)state->glare_sampled);
        cJSON_AddNumberToObject(w, "rays", (double)state->glare_stats.rays);
        cJSON_AddStringToObject(w, "why", "exact where no surface can come between an eye and a luminaire's "
                                          "luminous parts; else the visible fraction sampled by shadow rays to the "
                                          "target");
    }
}

void cdl_plan_json_surfaces(cdl_plan_json *plan, const cdl_solve_state *state)
{
    const cdl_surface_mesh_stats *m = &state->surface_stats;
    cJSON *o = cJSON_AddObjectToObject(plan->root, "surface_maps");
    cJSON_AddNumberToObject(o, "maps", (double)state->out->surface_count);
    cJSON_AddNumberToObject(o, "vertices", (double)m->vertices);
    cJSON_AddNumberToObject(o, "triangles", (double)m->triangles);
    cJSON_AddNumberToObject(o, "evaluations", (double)m->evaluations);
    cJSON_AddNumberToObject(o, "refinement_rounds", (double)m->rounds);
    cJSON_AddNumberToObject(o, "edges_at_finest", (double)m->unresolved);
    cJSON_AddNumberToObject(o, "outline_vertices_joined", (double)m->joined);
    if (m->mesh_as_given) cJSON_AddNumberToObject(o, "meshes_as_given", (double)m->mesh_as_given);
    cJSON_AddBoolToObject(o, "vertex_budget_reached", m->budget_reached);
    const char *how = state->surface_method == CDL_METHOD_ICACHE      ? "icache"
                      : state->surface_method == CDL_METHOD_PATHTRACE ? "pathtrace"
                                                                      : "none";
    cJSON_AddStringToObject(o, "interreflection", how);
    if (state->surface_method == CDL_METHOD_ICACHE)
        cJSON_AddNumberToObject(o, "records", (double)state->surface_records);
    char why[400];
    snprintf(why, sizeof why,
             "meshed from the EN 12464-1 spacing and refined where linear interpolation along an edge is off by more "
             "than the target (relative to E, or to half the surface's mean where E is below it), down to a "
             "sixteenth of the coarsest edges (at least 1 cm); direct light as at grid points%s",
             state->surface_method == CDL_METHOD_ICACHE
                 ? "; interreflected light from the solve's one irradiance cache, whose records the grids share"
             : state->surface_method == CDL_METHOD_PATHTRACE ? "; interreflected light by paths from every vertex"
                                                              : "");
    cJSON_AddStringToObject(o, "why", why);
}

cdl_status cdl_plan_json_print(const cdl_plan_json *plan, char **out, cdl_error *err)
{
    cdl_json_numbers_exact(plan->root);
    *out = cJSON_PrintUnformatted(plan->root);
    return *out ? CDL_OK : cdl_error_out_of_memory(err);
}

void cdl_plan_json_release(cdl_plan_json *plan)
{
    if (!plan) return;
    cJSON_Delete(plan->root);
    free(plan->light_grids);
    free(plan);
}
