/* solve_sealed.c - lights outside a closed box that holds every point of the solve (solve_sealed.h). */
#include "solver/solve_sealed.h"

#include <math.h>


/* Is surface k a closed, opaque box in the ray scene: its six faces there,
 * none of them a pane of glass? */
static int box_is_closed(const cdl_scene_geometry *geometry, size_t k)
{
    int faces = 0;
    size_t n = cdl_scene_geometry_piece_count(geometry);
    for (size_t g = 0; g < n; ++g) {
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(geometry, g);
        if (piece->is_luminaire || piece->source_index != k || piece->box_face < 0) continue;
        if (piece->transmittance > 0.0) return 0;
        faces |= 1 << piece->box_face;
    }
    return faces == (1 << CDL_BOX_FACES) - 1;
}

typedef struct sealing_box {
    double lo[3], hi[3];
    double margin; /* m: within it of a face, a point must lie on the face and look in */
} sealing_box;

/* Does a point with normal n (zero: it looks every way) lie inside the box
 * and look into it? Strictly inside by the margin it may look any way;
 * nearer a face it must lie on the face's inner side and face straight in
 * (a floor's grid, a wall's map), so that no direction of its hemisphere
 * leaves through the face it lies on. */
static int holds_point(const sealing_box *b, cdl_vec3 p, cdl_vec3 n)
{
    double x[3] = {p.x, p.y, p.z}, m[3] = {n.x, n.y, n.z};
    for (int a = 0; a < 3; ++a) {
        double below = x[a] - b->lo[a], above = b->hi[a] - x[a];
        if (below < -b->margin || above < -b->margin) return 0;
        if (below < b->margin && !(m[a] > 1.0 - 1e-9)) return 0;
        if (above < b->margin && !(m[a] < -1.0 + 1e-9)) return 0;
    }
    return 1;
}

/* Every vertex of a mapped surface's triangles, with its triangle's normal;
 * a sphere by its bounding box, strictly inside. */
static int holds_mapped(const sealing_box *b, const cdl_scene_geometry *geometry, size_t g)
{
    const cdl_geometry_piece *piece = cdl_scene_geometry_piece(geometry, g);
    const double *xyz;
    const uint32_t *tri;
    size_t vertices;
    size_t count = cdl_scene_geometry_piece_triangles(geometry, g, &xyz, &vertices, &tri);
    if (count == 0) {
        if (piece->shape.kind != CDL_SHAPE_SPHERE) return 0;
        cdl_vec3 c = piece->shape.center, zero = {0, 0, 0};
        double r = piece->shape.radius + 2.0 * b->margin;
        for (int corner = 0; corner < 8; ++corner) {
            cdl_vec3 q = cdl_vec3_make(c.x + (corner & 1 ? r : -r), c.y + (corner & 2 ? r : -r),
                                       c.z + (corner & 4 ? r : -r));
            if (!holds_point(b, q, zero)) return 0;
        }
        return 1;
    }
    for (size_t t = 0; t < count; ++t) {
        cdl_vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            const double *q = xyz + 3 * tri[3 * t + k];
            v[k] = cdl_vec3_make(q[0], q[1], q[2]);
        }
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_sub(v[1], v[0]), cdl_vec3_sub(v[2], v[0]));
        double len = cdl_vec3_length(n);
        if (!(len > 0.0)) continue;
        n = cdl_vec3_scale(n, 1.0 / len);
        for (int k = 0; k < 3; ++k)
            if (!holds_point(b, v[k], n)) return 0;
    }
    return 1;
}

/* Does the box hold every point the solve evaluates? */
static int holds_everything(const sealing_box *b, const cdl_solve_state *state)
{
    const cdl_scene *scene = state->scene;
    const cdl_solution *out = state->out;
    cdl_vec3 zero = {0, 0, 0};
    for (size_t g = 0; g < out->grid_count; ++g) {
        const cdl_grid *grid = &out->grids[g].grid;
        /* cylindrical outputs look every way, whatever the normal */
        int all_ways = scene->grids[g].want_cylindrical || scene->grids[g].want_semicylindrical;
        for (size_t i = 0; i < grid->count; ++i)
            if (!holds_point(b, grid->points[i], all_ways ? zero : grid->normals[i])) return 0;
    }
    for (size_t i = 0; i < scene->observer_count; ++i)
        if (!holds_point(b, scene->observers[i].eye, zero)) return 0;
    size_t pieces = cdl_scene_geometry_piece_count(state->geometry);
    for (size_t g = 0; g < pieces; ++g) {
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(state->geometry, g);
        if (!piece->is_luminaire && scene->surfaces[piece->source_index].mapped &&
            !holds_mapped(b, state->geometry, g))
            return 0;
    }
    return 1;
}

/* Is the light wholly outside the box, clear of it by the margin? Skies,
 * the sun and parallel light come from outside every bounded box. */
static int outside(const sealing_box *b, const cdl_scene_light *light)
{
    if (!light->bounded) return 1;
    double lo[3] = {light->bounds.lo.x, light->bounds.lo.y, light->bounds.lo.z};
    double hi[3] = {light->bounds.hi.x, light->bounds.hi.y, light->bounds.hi.z};
    for (int a = 0; a < 3; ++a)
        if (hi[a] < b->lo[a] - b->margin || lo[a] > b->hi[a] + b->margin) return 1;
    return 0;
}

void cdl_solve_seal_lights(cdl_solve_state *state)
{
    const cdl_scene *scene = state->scene;
    if (state->pieces == 0 || state->lights.count == 0) return;
    for (size_t k = 0; k < scene->surface_count; ++k) {
        const cdl_surface_spec *s = &scene->surfaces[k];
        if (s->kind != CDL_SURFACE_BOX || !box_is_closed(state->geometry, k)) continue;
        sealing_box b = {{s->box_min.x, s->box_min.y, s->box_min.z}, {s->box_max.x, s->box_max.y, s->box_max.z}, 0.0};
        /* 1e-4 of the diagonal (0.8 mm in a 6 x 4 x 3 m room): far above
         * the ray scene's rounding, below any grid's distance from a wall. */
        b.margin = 1e-4 * cdl_vec3_distance(s->box_min, s->box_max);
        if (!holds_everything(&b, state)) continue;
        for (size_t l = 0; l < state->lights.count; ++l) {
            cdl_scene_light *light = &state->lights.lights[l];
            if (!light->sealed_by && outside(&b, light)) light->sealed_by = s->json_path;
        }
    }
}
