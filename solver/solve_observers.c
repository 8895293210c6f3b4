/* solve_observers.c - the observers of a scene, planned for the glare integrator.
 *
 * Rated: goniometric luminaires whose file gives a luminous opening (its
 * luminance I / A_p towards the eye, CIE 117 4.5), and area luminaires
 * (their luminance; shapes of up to CDL_GLARE_PARTS_MAX triangles). Not
 * rated, said per luminaire: point and spot luminaires, goniometric files
 * without an opening and parallel light, which have no luminous area.
 * Skies and emitting surfaces are the background: their direct light
 * counts in the background luminance with all interreflected light.
 */
#include "solver/solve_observers.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"

static const char *const no_area = "no luminous area: a point source cannot be rated (CIE 117 weighs the luminance "
                                   "of the luminous parts)";
static const char *const no_opening = "its file gives no luminous opening (a point): it cannot be rated (CIE 117 "
                                      "weighs the luminance of the luminous parts)";
static const char *const parallel = "parallel light has no luminous area: it cannot be rated";
static const char *const many_triangles = "an area luminaire of more than 6 triangles cannot be rated yet";

/* The factor between a goniometric luminaire's emitter and its table
 * (multiplier, maintenance, output and tilt factors, a flux rescale), read
 * at the table's brightest direction. */
static double emitter_scale(const cdl_solve_state *state, size_t k, const cdl_glare_luminaire *g)
{
    const cdl_emitter *e = NULL;
    for (size_t l = 0; l < state->lights.count && !e; ++l)
        if (state->lights.lights[l].luminaire == k) e = state->lights.lights[l].emitter;
    cdl_photometry_table t;
    cdl_photometry_get_table(g->photometry, &t);
    size_t best = 0, n = t.horizontal_count * t.vertical_count;
    for (size_t i = 1; i < n; ++i)
        if (t.candela[i] > t.candela[best]) best = i;
    cdl_vec3 local = cdl_photometry_direction(t.type, t.horizontal_deg[best / t.vertical_count],
                                              t.vertical_deg[best % t.vertical_count]);
    cdl_vec3 world = cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(g->axis[0], local.x), cdl_vec3_scale(g->axis[1], local.y)),
                                  cdl_vec3_scale(g->axis[2], local.z));
    double table = cdl_photometry_intensity(g->photometry, local).cd;
    return e && table > 0.0 ? cdl_emitter_intensity(e, world).cd / table : 0.0;
}

/* An area luminaire's shape as one-sided pieces, its centre and radius. */
static void area_parts(const cdl_solve_state *state, size_t k, cdl_glare_rated *r)
{
    size_t n = state->pieces;
    const cdl_geometry_piece *gp = NULL;
    size_t id = 0;
    for (size_t i = 0; i < n && !gp; ++i) {
        const cdl_geometry_piece *p = cdl_scene_geometry_piece(state->geometry, i);
        if (p->is_luminaire && !p->is_body && p->source_index == k) gp = p, id = i;
    }
    if (!gp) {
        r->reason = no_area;
        return;
    }
    r->is_area = 1;
    r->owner = (uint32_t)id;
    r->luminance_cd_m2 = gp->luminance_cd_m2;
    const cdl_shape *s = &gp->shape;
    cdl_glare_parts *parts = &r->parts;
    parts->count = 0;
    if (s->kind == CDL_SHAPE_RECT) {
        cdl_vec3 hu = cdl_vec3_scale(s->u, 0.5), hv = cdl_vec3_scale(s->v, 0.5);
        r->centre = cdl_vec3_add(s->origin, cdl_vec3_add(hu, hv));
        r->radius = 0.5 * cdl_vec3_length(cdl_vec3_add(s->u, s->v)) + 0.5 * cdl_vec3_length(cdl_vec3_sub(s->u, s->v));
        parts->piece[parts->count++] = (cdl_glare_piece){CDL_GLARE_PIECE_PARALLELOGRAM, r->centre, hu, hv, 1};
    } else if (s->kind == CDL_SHAPE_DISK) {
        cdl_vec3 nn = cdl_vec3_normalize(s->normal);
        cdl_vec3 a = fabs(nn.z) < 0.9 ? cdl_vec3_make(0, 0, 1) : cdl_vec3_make(1, 0, 0);
        cdl_vec3 u = cdl_vec3_normalize(cdl_vec3_cross(a, nn)), v = cdl_vec3_cross(nn, u); /* u x v = n */
        r->centre = s->center;
        r->radius = s->radius;
        parts->piece[parts->count++] = (cdl_glare_piece){CDL_GLARE_PIECE_ELLIPSE, s->center,
                                                          cdl_vec3_scale(u, s->radius), cdl_vec3_scale(v, s->radius), 1};
    } else if (s->kind == CDL_SHAPE_TRIANGLES && s->triangle_count <= CDL_GLARE_PARTS_MAX) {
        double area = 0.0;
        cdl_vec3 c = {0, 0, 0};
        for (size_t t = 0; t < s->triangle_count; ++t) {
            const uint32_t *tri = &s->triangles[3 * t];
            cdl_vec3 v[3];
            for (int m = 0; m < 3; ++m)
                v[m] = cdl_vec3_make(s->vertices[3 * tri[m]], s->vertices[3 * tri[m] + 1], s->vertices[3 * tri[m] + 2]);
            double a = 0.5 * cdl_vec3_length(cdl_vec3_cross(cdl_vec3_sub(v[1], v[0]), cdl_vec3_sub(v[2], v[0])));
            c = cdl_vec3_madd(c, a / 3.0, cdl_vec3_add(v[0], cdl_vec3_add(v[1], v[2])));
            area += a;
            parts->piece[parts->count++] = (cdl_glare_piece){CDL_GLARE_PIECE_TRIANGLE, v[0], v[1], v[2], 1};
        }
        r->centre = cdl_vec3_scale(c, 1.0 / area);
        for (size_t i = 0; i < s->vertex_count; ++i)
            r->radius = fmax(r->radius, cdl_vec3_distance(r->centre, cdl_vec3_make(s->vertices[3 * i], s->vertices[3 * i + 1],
                                                                                   s->vertices[3 * i + 2])));
    } else {
        r->is_area = 0;
        r->reason = many_triangles;
    }
}

/* How luminaire k is rated (above). */
static void rate_luminaire(const cdl_solve_state *state, size_t k, cdl_glare_rated *r)
{
    const cdl_luminaire_spec *sp = &state->scene->luminaires[k];
    memset(r, 0, sizeof *r);
    r->owner = UINT32_MAX;
    switch (sp->kind) {
    case CDL_LUMINAIRE_POINT:
    case CDL_LUMINAIRE_SPOT: r->reason = no_area; return;
    case CDL_LUMINAIRE_DIRECTIONAL: r->reason = parallel; return;
    case CDL_LUMINAIRE_ENVIRONMENT: r->background = 1; return;
    case CDL_LUMINAIRE_AREA: area_parts(state, k, r); return;
    case CDL_LUMINAIRE_GONIOMETRIC: break;
    }
    const cdl_photometry *ph = state->lights.luminaire_photometry[k];
    const cdl_luminous_opening *o = ph ? cdl_photometry_opening(ph) : NULL;
    if (!o || !cdl_luminous_opening_is_spread(o)) {
        r->reason = no_opening;
        return;
    }
    r->gonio.photometry = ph;
    r->owner = cdl_scene_geometry_luminaire_body(state->geometry, k);
    r->gonio.position = r->centre = sp->position;
    cdl_emitter_rotation_columns(sp->rotation_deg, r->gonio.axis);
    r->gonio.scale = emitter_scale(state, k, &r->gonio);
    r->radius = 0.5 * cdl_luminous_opening_largest_m(o);
}

/* Why no luminaire can be rated: each named, with its reason. */
static cdl_status refuse_unrated(const cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    char list[700] = "";
    size_t used = 0;
    for (size_t k = 0; k < scene->luminaire_count && used < sizeof list - 1; ++k) {
        if (state->rated[k].background) continue;
        char label[200];
        cdl_luminaire_spec_label(&scene->luminaires[k], label, sizeof label);
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s: %s", used ? "; " : "", label,
                                 state->rated[k].reason);
    }
    return cdl_error_set(err, CDL_ERR_INPUT,
                         "%s: observers: expected a luminaire whose glare can be rated (a goniometric luminaire whose "
                         "file gives a luminous opening, or an area luminaire), found %s",
                         scene->path, used ? list : "no luminaire");
}

/* An eye on a surface, or inside a closed box or sphere, sees nothing. */
static cdl_status check_eye(const cdl_solve_state *state, const cdl_observer_spec *o, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    cdl_vec3 e = o->eye;
    for (size_t i = 0; i < scene->surface_count; ++i) {
        const cdl_surface_spec *s = &scene->surfaces[i];
        int inside = 0;
        if (s->kind == CDL_SURFACE_BOX && !s->inward) {
            int closed = 1;
            for (int f = 0; f < CDL_BOX_FACES; ++f) closed &= !s->face_open[f];
            inside = closed && e.x > s->box_min.x && e.x < s->box_max.x && e.y > s->box_min.y &&
                     e.y < s->box_max.y && e.z > s->box_min.z && e.z < s->box_max.z;
        } else if (s->kind == CDL_SURFACE_SPHERE && !s->inward) {
            inside = cdl_vec3_distance(e, s->center) < s->radius;
        }
        if (inside)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s (%s): expected the eye in open air, found [%.10g, %.10g, %.10g] inside %s "
                                 "(a closed %s)",
                                 scene->path, o->json_path, o->name, e.x, e.y, e.z, s->json_path,
                                 s->kind == CDL_SURFACE_BOX ? "box" : "sphere");
    }
    if (state->occluders) {
        double tol = 4.0 * cdl_scene_geometry_resolution(state->geometry, e);
        cdl_vec3 d = {tol, tol, tol};
        if (cdl_occluder_index_surface_in_box(state->occluders, cdl_vec3_sub(e, d), cdl_vec3_add(e, d)))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s (%s): expected the eye in open air, found [%.10g, %.10g, %.10g] on a surface",
                                 scene->path, o->json_path, o->name, e.x, e.y, e.z);
    }
    return CDL_OK;
}

/* The lights of the background: skies and emitting surfaces. */
static cdl_status background_lights(cdl_solve_state *state, cdl_error *err)
{
    size_t n = state->lights.count, m = 0;
    state->background_lights = calloc(n ? n : 1, sizeof *state->background_lights);
    if (!state->background_lights) return cdl_error_out_of_memory(err);
    for (size_t l = 0; l < n; ++l) {
        const cdl_scene_light *light = &state->lights.lights[l];
        if (light->luminaire == SIZE_MAX ||
            state->scene->luminaires[light->luminaire].kind == CDL_LUMINAIRE_ENVIRONMENT)
            state->background_lights[m++] = *light;
    }
    state->background = state->direct;
    state->background.lights = state->background_lights;
    state->background.light_count = m;
    return CDL_OK;
}

cdl_status cdl_solve_plan_observers(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    size_t n = scene->observer_count;
    if (n == 0) return CDL_OK;
    state->rated = calloc(scene->luminaire_count ? scene->luminaire_count : 1, sizeof *state->rated);
    if (!state->rated) return cdl_error_out_of_memory(err);
    size_t rated = 0;
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        rate_luminaire(state, k, &state->rated[k]);
        rated += !state->rated[k].reason && !state->rated[k].background;
    }
    if (rated == 0) return refuse_unrated(state, err);
    for (size_t i = 0; i < n; ++i) {
        cdl_status st = check_eye(state, &scene->observers[i], err);
        if (st != CDL_OK) return st;
    }
    /* the job: the eyes as points facing their lines of sight */
    cdl_grid_spec *spec = &state->observer_spec;
    memset(spec, 0, sizeof *spec);
    snprintf(spec->json_path, sizeof spec->json_path, "observers");
    spec->name = "observers";
    spec->kind = CDL_GRID_POINTS;
    spec->points = malloc(n * sizeof *spec->points);
    spec->normals = malloc(n * sizeof *spec->normals);
    if (!spec->points || !spec->normals) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < n; ++i) {
        spec->points[i] = scene->observers[i].eye;
        spec->normals[i] = scene->observers[i].view;
    }
    spec->point_count = n;
    cdl_status st = cdl_grid_build(spec, &state->observer_points.grid, err);
    if (st == CDL_OK) st = cdl_grid_solution_alloc(&state->observer_points, 0, err);
    if (st != CDL_OK) return st;
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, "observers", 9);
    state->observer_plan.key = h.value;
    /* a few points: paths, the unbiased reference, rather than a cache */
    state->observer_plan.method = state->indirect ? CDL_METHOD_PATHTRACE : CDL_METHOD_DIRECT;
    return background_lights(state, err);
}

void cdl_solve_observers_release(cdl_solve_state *state)
{
    free(state->observer_spec.points);
    free(state->observer_spec.normals);
    cdl_grid_solution_release(&state->observer_points);
    free(state->background_lights);
    free(state->rated);
}
