/* solve_checks.c - no silent zeros: lights that light nothing, dark grids, a scene without light; installed power.
 *
 * After a solve, every luminaire (and emitting surface) is asked whether it
 * reaches any grid point: a delta light at a point in front of the point's
 * plane whose shadow ray is clear (the same test E uses); an extended light
 * at a point where its closed form is above 0 and the exact route finds
 * part of it in view (cdl_direct_light_seen), or, where that cannot tell,
 * one of up to 16 stratified samples of it is in view. A light that reaches none is named
 * in a warning that says why: its light meets no grid point (facing away,
 * the grids outside its beam) or surfaces hide it from every point (above
 * a ceiling, outside a closed room), and when its position lies far
 * outside the scene where a thousandth of it would lie inside, that it
 * looks like millimetres in a scene in metres. A luminaire asked for
 * near_field "always" whose file has no opening to spread over is named
 * (it stays a point). A grid at 0 lx everywhere,
 * and a scene with no light at all, are named too. The warnings go to
 * summary.json; `candela solve` prints them and --strict refuses them.
 */
#include "solver/scene/scene_internal.h"
#include "solver/solution_internal.h"
#include "solver/solve_checks.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "solver/geometry/polygon.h"
#include "solver/direct/direct.h"
#include "lights/photometry/photometry_metadata.h"

/* Samples of an extended light tried per point before calling it hidden there. */
#define EXTENDED_PROBES 4

typedef enum reach { REACH_NONE, REACH_HIDDEN, REACH_LIT } reach;

/* Does light l reach point p (normal n)? */
static reach light_reaches(const cdl_direct_context *ctx, size_t l, cdl_light_strategy st, cdl_vec3 p, cdl_vec3 n)
{
    const cdl_scene_light *light = &ctx->lights[l];
    if (!cdl_scene_light_applies(light, p)) return REACH_NONE; /* the other part of a near-field split */
    if (cdl_emitter_is_delta(light->emitter)) {
        cdl_delta_light d;
        if (!cdl_emitter_eval_delta(light->emitter, p, n, &d) || !(d.E.lx > 0.0)) return REACH_NONE;
        if (st != CDL_STRATEGY_DELTA_SHADOWED || !ctx->geometry) return REACH_LIT;
        return cdl_scene_geometry_transmission_except(ctx->geometry, p, d.to_light, d.distance,
                                                      cdl_scene_light_own_piece(light)) > 0.0
                   ? REACH_LIT
                   : REACH_HIDDEN;
    }
    /* Extended: the closed form where the emitter has one (a luminous
     * solid has none); then the visible part as the exact route finds it
     * (a window's sky that the probes below could miss), where it can
     * tell; then probes, which also say whether it is hidden. */
    int closed_form = cdl_emitter_has_exact_illuminance(light->emitter);
    if (closed_form) {
        cdl_illuminance E;
        if (cdl_emitter_exact_illuminance(light->emitter, p, n, &E, NULL) != CDL_OK || !(E.lx > 0.0)) return REACH_NONE;
        if (st == CDL_STRATEGY_EXTENDED_EXACT || !ctx->geometry) return REACH_LIT;
        int route = cdl_direct_light_seen(ctx, light, st, p, n);
        if (route >= 0) return route ? REACH_LIT : REACH_HIDDEN;
    }
    int seen = closed_form;
    for (int j = 0; j < EXTENDED_PROBES; ++j)
        for (int i = 0; i < EXTENDED_PROBES; ++i) {
            cdl_light_sample s;
            double u1 = (i + 0.5) / EXTENDED_PROBES, u2 = (j + 0.5) / EXTENDED_PROBES;
            if (!cdl_emitter_sample(light->emitter, p, n, u1, u2, &s) || !(s.pdf > 0.0) || !(s.L.cd_m2 > 0.0) ||
                !(cdl_vec3_dot(s.to_light, n) > 0.0))
                continue;
            seen = 1;
            if (!ctx->geometry || cdl_scene_geometry_transmission_except(ctx->geometry, p, s.to_light, s.distance,
                                                                         cdl_scene_light_own_piece(light)) > 0.0)
                return REACH_LIT;
        }
    return seen ? REACH_HIDDEN : REACH_NONE;
}

/* The box around every grid point and every surface: where the scene is
 * (the luminaires' bodies go where the luminaires go: left out). */
static cdl_bounds3 scene_box(const cdl_direct_context *ctx, const cdl_solution *out)
{
    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t g = 0; g < out->grid_count; ++g)
        for (size_t i = 0; i < out->grids[g].grid.count; ++i) cdl_bounds3_grow(&box, out->grids[g].grid.points[i]);
    if (ctx->geometry) {
        cdl_vec3 lo, hi;
        cdl_scene_geometry_surface_bounds(ctx->geometry, &lo, &hi);
        if (lo.x <= hi.x) {
            cdl_bounds3_grow(&box, lo);
            cdl_bounds3_grow(&box, hi);
        }
    }
    return box;
}

static int inside(cdl_bounds3 box, cdl_vec3 p, double margin)
{
    return p.x >= box.lo.x - margin && p.x <= box.hi.x + margin && p.y >= box.lo.y - margin &&
           p.y <= box.hi.y + margin && p.z >= box.lo.z - margin && p.z <= box.hi.z + margin;
}

/* A position far outside the scene (beyond ten times its size, and beyond
 * MM_FAR_M whatever its size) that a thousandth of would put in or near it
 * (within half its size and 3 m, the height a luminaire may hang above a
 * work plane): millimetres typed into a scene in metres. The absolute
 * floor keeps a small scene (one probe under a luminaire 2 m up) from
 * calling every luminaire far: a position typed in millimetres is a
 * thousand times its metres, so any luminaire more than 0.1 m from the
 * origin lands beyond 100 m. */
#define MM_FAR_M 100.0
static int looks_like_millimetres(cdl_bounds3 box, cdl_vec3 p)
{
    double size = fmax(cdl_bounds3_diagonal(box), 1e-3);
    cdl_vec3 mm = cdl_vec3_scale(p, 1e-3);
    return !inside(box, p, fmax(10.0 * size, MM_FAR_M)) && inside(box, mm, 0.5 * size + 3.0);
}

cdl_status cdl_solve_check_near_field(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_solution *out,
                                      cdl_error *err)
{
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        const cdl_luminaire_spec *sp = &scene->luminaires[k];
        const cdl_photometry *ph = lights->luminaire_photometry[k];
        /* once per entry: its copies share the file */
        if (sp->copy > 0 || sp->near_field != CDL_NEAR_FIELD_ALWAYS || !ph) continue;
        const cdl_luminous_opening *o = &cdl_photometry_get_metadata(ph)->opening;
        if (cdl_luminous_opening_is_spread(o)) continue;
        cdl_status st = cdl_solution_add_warning(
            out, err,
            "%s: near_field \"always\": %s gives %s %s (%g x %g x %g m): lit as a point (spread are rectangles, "
            "circles, ellipses, boxes with luminous sides, vertical and horizontal (elliptic) cylinders, spheres and "
            "ellipsoids of non-zero size)",
            sp->json_path, sp->file, o->shape == CDL_LUMINOUS_SHAPE_POINT ? "no luminous opening, a" : "the opening",
            cdl_luminous_shape_name(o->shape), o->width_m, o->length_m, o->height_m);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

cdl_status cdl_solve_check_lights(const cdl_scene *scene, const cdl_direct_context *ctx, cdl_solution *out,
                                  cdl_error *err)
{
    cdl_status st = CDL_OK;
    /* a scene of observers alone has no grid point for a light to reach */
    if (out->grid_count == 0) return CDL_OK;
    if (ctx->light_count == 0) {
        return cdl_solution_add_warning(out, err,
                                        "the scene has no luminaire and no emitting surface: every grid is at 0 lx "
                                        "(add \"luminaires\", or \"luminance_cd_m2\" to a surface)");
    }
    cdl_light_strategy *strategies = calloc(ctx->light_count * (out->grid_count ? out->grid_count : 1),
                                            sizeof *strategies);
    reach *best = calloc(ctx->light_count, sizeof *best);
    if (!strategies || !best) {
        free(strategies);
        free(best);
        return cdl_error_out_of_memory(err);
    }
    for (size_t g = 0; g < out->grid_count; ++g)
        cdl_direct_plan_grid(ctx, out->grids[g].grid.points, out->grids[g].grid.count,
                             strategies + g * ctx->light_count);
    for (size_t l = 0; l < ctx->light_count; ++l)
        for (size_t g = 0; g < out->grid_count && best[l] != REACH_LIT; ++g) {
            const cdl_grid *grid = &out->grids[g].grid;
            for (size_t i = 0; i < grid->count && best[l] != REACH_LIT; ++i) {
                reach r = light_reaches(ctx, l, strategies[g * ctx->light_count + l], grid->points[i],
                                        grid->normals[i]);
                if (r > best[l]) best[l] = r;
            }
        }
    /* With surface maps, a luminaire lighting a mapped surface adds something too. */
    cdl_light_strategy *map_strategies = calloc(ctx->light_count, sizeof *map_strategies);
    for (size_t k = 0; map_strategies && k < out->surface_count; ++k) {
        const cdl_surface_solution *m = &out->surfaces[k];
        cdl_vec3 *p = malloc((2 * m->vertex_count + 1) * sizeof *p);
        if (!p) break;
        for (size_t v = 0; v < m->vertex_count; ++v) {
            p[v] = cdl_vec3_make(m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2]);
            p[m->vertex_count + v] = cdl_vec3_make(m->normal[3 * v], m->normal[3 * v + 1], m->normal[3 * v + 2]);
        }
        cdl_direct_plan_grid(ctx, p, m->vertex_count, map_strategies);
        for (size_t l = 0; l < ctx->light_count; ++l)
            for (size_t v = 0; v < m->vertex_count && best[l] != REACH_LIT; ++v) {
                reach r = light_reaches(ctx, l, map_strategies[l], p[v], p[m->vertex_count + v]);
                if (r > best[l]) best[l] = r;
            }
        free(p);
    }
    free(map_strategies);
    /* A luminaire split into its point (far) and its opening (near) parts,
     * adjacent, reaches what either part reaches; the point part speaks
     * for both. */
    for (size_t l = 1; l < ctx->light_count; ++l)
        if (ctx->lights[l].near_part > 0 && ctx->lights[l - 1].near_part < 0) {
            reach r = best[l] > best[l - 1] ? best[l] : best[l - 1];
            best[l] = best[l - 1] = r;
        }
    cdl_bounds3 box = scene_box(ctx, out);
    for (size_t l = 0; l < ctx->light_count && st == CDL_OK; ++l) {
        const cdl_scene_light *light = &ctx->lights[l];
        if (light->near_part > 0 && l > 0 && ctx->lights[l - 1].near_part < 0) continue;
        char mm[200] = "";
        int millimetres = light->bounded && looks_like_millimetres(box, cdl_bounds3_centre(light->bounds));
        if (millimetres) {
            cdl_vec3 c = cdl_bounds3_centre(light->bounds);
            snprintf(mm, sizeof mm,
                     "its position [%.6g, %.6g, %.6g] lies far outside the scene and looks like millimetres: "
                     "the scene is in metres",
                     c.x, c.y, c.z);
        }
        if (light->sealed_by) {
            st = cdl_solution_add_warning(
                out, err,
                "%s adds nothing to any grid%s: it lies outside %s, a closed box that holds every point of the "
                "solve, so none of its light can reach them, and it was left out of the solve (is the room meant "
                "to have a window, an open face or a pane of glass?)%s%s",
                light->label, out->surface_count ? " or surface map" : "", light->sealed_by, millimetres ? "; " : "",
                mm);
            continue;
        }
        if (best[l] == REACH_LIT) {
            /* Lighting something from a kilometre away is still a slip. */
            if (millimetres) st = cdl_solution_add_warning(out, err, "%s: %s", light->label, mm);
            continue;
        }
        st = cdl_solution_add_warning(
            out, err, "%s adds nothing to any grid%s: %s%s%s", light->label,
            out->surface_count ? " or surface map" : "",
            best[l] == REACH_NONE
                ? "its light meets no grid point from the side the point faces (is it facing away, or are the grids "
                  "outside its beam?)"
                : "surfaces hide it from every grid point (is it above the ceiling, or outside a closed room?)",
            millimetres ? "; " : "", mm);
    }
    free(best);
    free(strategies);
    /* Dark grids: 0 lx at every point (any of their outputs included). */
    for (size_t g = 0; g < out->grid_count && st == CDL_OK; ++g) {
        const cdl_grid_solution *gs = &out->grids[g];
        int lit = 0;
        for (size_t i = 0; i < gs->grid.count && !lit; ++i)
            lit = gs->E[i] > 0.0 || (gs->Ez && gs->Ez[i] > 0.0) || (gs->Esz && gs->Esz[i] > 0.0);
        if (!lit && gs->grid.count > 0)
            st = cdl_solution_add_warning(out, err,
                                          "grid '%s' (%s) is dark: 0 lx at every one of its %zu points (no light "
                                          "reaches the side its points face)",
                                          scene->grids[g].name, scene->grids[g].json_path, gs->grid.count);
    }
    return st;
}

/* Even-odd: is (x, y) inside the ring, projected into the plane? */
static int ring_contains(const cdl_polygon_plane *plane, const cdl_ring3 *ring, double x, double y)
{
    int in = 0;
    double x0, y0;
    cdl_polygon_project(plane, ring->points[ring->count - 1], &x0, &y0);
    for (size_t i = 0; i < ring->count; ++i) {
        double x1, y1;
        cdl_polygon_project(plane, ring->points[i], &x1, &y1);
        if ((y1 > y) != (y0 > y) && x < x0 + (x1 - x0) * (y - y0) / (y1 - y0)) in = !in;
        x0 = x1;
        y0 = y1;
    }
    return in;
}

/* Power density is a floor's figure (W per m^2 of the area lit from
 * above, EN 15193 and the energy codes' LPD): only grids facing up, within
 * 30 degrees of the vertical, count the luminaires over them; a wall grid
 * counts none. */
#define POWER_GRID_MIN_UP 0.8660254037844386

/* Does a luminaire at q hang over the grid: the grid facing up, q,
 * projected onto the grid's plane along its normal, within its outline
 * (and outside its holes), on the side its points face? Points grids have
 * no outline. */
static int faces_up(cdl_vec3 n)
{
    double len = cdl_vec3_length(n);
    return len > 0.0 && n.z >= POWER_GRID_MIN_UP * len;
}

static int over_grid(const cdl_grid_spec *spec, cdl_vec3 q)
{
    if (spec->kind == CDL_GRID_RECT) {
        cdl_vec3 m = cdl_vec3_cross(spec->u, spec->v), w = cdl_vec3_sub(q, spec->origin);
        double mm = cdl_vec3_dot(m, m);
        cdl_vec3 facing = spec->has_normal ? spec->normal : m;
        if (!(mm > 0.0) || !(cdl_vec3_dot(w, facing) > 0.0) || !faces_up(facing)) return 0;
        /* q = origin + s u + t v + h m: Cramer's rule with the triple products */
        double s = cdl_vec3_dot(cdl_vec3_cross(w, spec->v), m) / mm;
        double t = cdl_vec3_dot(cdl_vec3_cross(spec->u, w), m) / mm;
        return s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0;
    }
    if (spec->kind != CDL_GRID_POLYGON) return 0;
    cdl_polygon_plane plane;
    if (cdl_polygon_plane_of_checked(&spec->outer, spec->holes, spec->hole_count, &plane, NULL) != CDL_OK) return 0;
    cdl_vec3 facing = spec->has_normal ? spec->normal : plane.normal;
    if (!(cdl_vec3_dot(cdl_vec3_sub(q, plane.origin), facing) > 0.0) || !faces_up(facing)) return 0;
    double x, y;
    cdl_polygon_project(&plane, q, &x, &y);
    if (!ring_contains(&plane, &spec->outer, x, y)) return 0;
    for (size_t h = 0; h < spec->hole_count; ++h)
        if (ring_contains(&plane, &spec->holes[h], x, y)) return 0;
    return 1;
}

/* The centre of an area luminaire's shape: a rect's middle, a disk's
 * centre, the mean of a polygon's outer ring or of a mesh's vertices. */
static cdl_vec3 shape_centre(const cdl_surface_spec *shape)
{
    switch (shape->kind) {
    case CDL_SURFACE_RECT: return cdl_vec3_add(shape->origin, cdl_vec3_scale(cdl_vec3_add(shape->u, shape->v), 0.5));
    case CDL_SURFACE_DISK:
    case CDL_SURFACE_SPHERE: return shape->center;
    case CDL_SURFACE_POLYGON: {
        cdl_vec3 sum = cdl_vec3_make(0.0, 0.0, 0.0);
        for (size_t i = 0; i < shape->outer.count; ++i) sum = cdl_vec3_add(sum, shape->outer.points[i]);
        return shape->outer.count ? cdl_vec3_scale(sum, 1.0 / (double)shape->outer.count) : sum;
    }
    case CDL_SURFACE_MESH: {
        cdl_vec3 sum = cdl_vec3_make(0.0, 0.0, 0.0);
        for (size_t i = 0; i < shape->mesh_vertex_count; ++i)
            sum = cdl_vec3_add(sum, cdl_vec3_make(shape->mesh_vertices[3 * i], shape->mesh_vertices[3 * i + 1],
                                                  shape->mesh_vertices[3 * i + 2]));
        return shape->mesh_vertex_count ? cdl_vec3_scale(sum, 1.0 / (double)shape->mesh_vertex_count) : sum;
    }
    case CDL_SURFACE_BOX: return cdl_vec3_scale(cdl_vec3_add(shape->box_min, shape->box_max), 0.5);
    }
    return shape->origin;
}

static void count_power(cdl_power_summary *power, double watts)
{
    if (watts > 0.0) {
        power->installed_w += watts;
        power->luminaires_counted++;
    } else {
        power->luminaires_without_watts++;
    }
}

void cdl_solve_sum_power(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_solution *out)
{
    memset(&out->power, 0, sizeof out->power);
    for (size_t g = 0; g < out->grid_count; ++g) memset(&out->grids[g].power, 0, sizeof out->grids[g].power);
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        const cdl_luminaire_spec *sp = &scene->luminaires[k];
        if (sp->kind == CDL_LUMINAIRE_DIRECTIONAL || sp->kind == CDL_LUMINAIRE_ENVIRONMENT) continue; /* daylight */
        const cdl_photometry *ph = lights->luminaire_photometry ? lights->luminaire_photometry[k] : NULL;
        double w = ph ? cdl_photometry_get_metadata(ph)->input_watts : 0.0;
        count_power(&out->power, w);
        /* An area luminaire hangs where its shape's centre is. */
        cdl_vec3 q = sp->kind == CDL_LUMINAIRE_AREA ? shape_centre(&sp->shape) : sp->position;
        for (size_t g = 0; g < out->grid_count && g < scene->grid_count; ++g)
            if (over_grid(&scene->grids[g], q)) count_power(&out->grids[g].power, w);
    }
}
