/* integrate_surfaces.c - the surface maps: every mapped surface's illuminance on a mesh that follows the light.
 *
 * Run once, before the grids. The mapped surfaces become patches
 * (surfacemap/surface_patches.h) and are meshed and refined round by round
 * (geometry/surface_mesh.h); the field each round asks for, at the new
 * vertices and at the midpoints of the new edges, is the illuminance a
 * grid point there would get: direct light by the direct solver, exactly
 * as at grid points, and interreflected light
 *   - with the irradiance cache (the "auto" and "icache" methods): from the
 *     solve's one cache (icache.h, cdl_icache_shared), which places records
 *     where these points need them; the grids the cache serves then use the
 *     same records, and add their own only where those do not serve them;
 *   - with "pathtrace": by paths from every point, as for grid points;
 * each to the solve's target. Refinement stops where linear interpolation
 * along every edge is within the target (relative to E; absolute, half
 * the target times the surface's mean, where E is below half its mean),
 * or at the finest edges (MIN_EDGE_FRACTION of the typical coarsest). A vertex's stated error joins its value's with
 * the interpolation error around it (the solution's E_stderr).
 *
 * The surfaces not mapped are kept as the ray scene has them, for scene.glb.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/sort_doubles.h"
#include "radiometry/constants.h"
#include "solver/direct/direct_grid.h"
#include "solver/geometry/remesh.h"
#include "solver/integrate/integrator.h"
#include "solver/plan_json.h"
#include "solver/pool.h"
#include "solver/surfacemap/surface_patches.h"
#include "base/error_report.h"

/* The finest edge refinement makes: a sixteenth of the maps' typical
 * coarsest edge (4 cm in a 6 m room), and never below a centimetre. A
 * shadow's hard edge is a step that no edge length resolves: it is refined
 * down to this and its interpolation error stated; finer would only add
 * vertices along it (measured on the example office at draft: edges of
 * 1 cm took 20 670 vertices, 17 683 edges at the finest). */
#define MIN_EDGE_FRACTION (1.0 / 16.0)
#define MIN_EDGE_M 0.01
/* Below half a surface's mean illuminance the tolerance is absolute: the
 * target times half that mean (surface_mesh.h, floor_fraction). */
#define FLOOR_FRACTION 0.5
/* Edges of imported meshes sharper than this are kept as creases, each
 * side mapped with its own normal. */
#define FEATURE_ANGLE_DEG 40.0
/* Vertices over all maps at most: about 400 MB of meshing state, far more
 * than the office's maps take. Refinement stops there and says so. */
#define MAX_VERTICES 2000000

static int applies_surfaces(const cdl_solve_state *state)
{
    for (size_t k = 0; k < state->scene->surface_count; ++k)
        if (state->scene->surfaces[k].mapped) return 1;
    return 0;
}

/* ---- the field the meshes follow -------------------------------------------------- */

typedef struct surface_field {
    cdl_solve_state *state;
    double spacing;           /* the cache's limits for these points: the maps' typical coarsest edge */
    uint64_t base_key;
    size_t batch;
} surface_field;

/* Where a record asked for at p is gathered: p, or, where another surface
 * passes through p (a floor's vertex along the foot of a wall: it lies on
 * both, so a gather there would send rays through the wall unseen, and
 * lose the light that wall returns), a tenth of the maps' spacing away
 * along p's own surface, in front of the other (the direct solver's step
 * off such points, cdl_direct_edge_point, without its part along n). The
 * record still serves p: within its reach, with p's normal, p in its
 * tangent plane (the cache's behind test), and seeing p. */
static cdl_vec3 gather_point(const cdl_solve_state *state, const surface_field *f, cdl_vec3 p, cdl_vec3 n)
{
    cdl_vec3 at;
    cdl_direct_edge_point(&state->direct, p, n, &at);
    cdl_vec3 step = cdl_vec3_sub(at, p);
    step = cdl_vec3_madd(step, -cdl_vec3_dot(step, n), n);
    double len = cdl_vec3_length(step);
    return len > 0.0 ? cdl_vec3_madd(p, 0.1 * f->spacing / len, step) : p;
}

/* The floors of a first round: FLOOR_FRACTION of each surface's mean over
 * its vertices (the first look's E_dir + E_ind), into fl (in order). */
static cdl_status first_floors(const cdl_field_probe *probes, const size_t *order, size_t count, const double *ed,
                               const double *ei, double *fl, cdl_error *err)
{
    size_t surfaces = 0;
    for (size_t i = 0; i < count; ++i)
        if (probes[i].surface + 1 > surfaces) surfaces = probes[i].surface + 1;
    double *sum = calloc(2 * surfaces + 1, sizeof *sum);
    if (!sum) return cdl_error_out_of_memory(err);
    for (size_t j = 0; j < count; ++j) {
        const cdl_field_probe *pr = &probes[order[j]];
        if (!pr->is_vertex) continue;
        sum[2 * pr->surface] += ed[j] + ei[j];
        sum[2 * pr->surface + 1] += 1.0;
    }
    for (size_t j = 0; j < count; ++j) {
        size_t s = probes[order[j]].surface;
        fl[j] = sum[2 * s + 1] > 0.0 ? FLOOR_FRACTION * sum[2 * s] / sum[2 * s + 1] : 0.0;
    }
    free(sum);
    return CDL_OK;
}

/* A round's probes in the order the cache serves them (cached_indirect):
 * positions and normals, where their records are gathered, their direct
 * light, floors and the interreflected light found, group by group. */
typedef struct probe_groups {
    size_t first[5];          /* group g is [first[g], first[g + 1]) */
    cdl_vec3 *pn;             /* count positions, then count normals */
    cdl_vec3 *moved;          /* where a record for each is gathered */
    double *ed, *vd, *ei, *vi, *fl;
    size_t count;
} probe_groups;

/* Serve group g of the probes from the cache: with `look`, records only
 * where no record serves a vertex (a first look), else placed where the
 * points need them (vertices) or where none serves them (midpoints). */
static cdl_status serve_group(cdl_solve_state *state, const surface_field *f, const probe_groups *q, int g, int look,
                              size_t key, const char *stage, cdl_error *err)
{
    size_t from = q->first[g], n = q->first[g + 1] - q->first[g];
    if (n == 0) return CDL_OK;
    cdl_grid grid = {.count = n, .points = q->pn + from, .normals = q->pn + q->count + from};
    cdl_grid gather = {.count = n, .points = q->moved + from, .normals = q->pn + q->count + from};
    /* Points the interpolation leaves above the target state what they get
     * (no record of their own: their number grows with refinement, and
     * such a record costs a whole point's paths). Where surfaces meet,
     * records are interpolated without their gradients: gathered a few
     * centimetres from two walls, a record's translational gradient is
     * dominated by the walls' nearness and extrapolating it, even that
     * far, errs (measured in a furnace at "high": 1.2 % at a room's corner
     * with gradients, within its stated error without). */
    cdl_icache_context ctx = state->icache;
    if (g % 2) ctx.gradients = 0;
    /* Every rank refines the meshes: each needs every point's light. */
    cdl_workers workers = cdl_solve_workers(state, 1);
    cdl_icache_target t = {.points = &grid,
                           .spacing = f->spacing,
                           .key = key + (size_t)g + (look ? 4u : 0u),
                           .E_direct = q->ed + from,
                           .var_direct = q->vd + from,
                           .E_indirect = q->ei + from,
                           .var_indirect = q->vi + from,
                           .floors = q->fl + from,
                           .gather_at = &gather,
                           .only_unserved = g >= 2 || look,
                           .no_own_records = 1,
                           .workers = &workers,
                           .stage = stage,
                           .stats = &state->icache_stats};
    size_t before = cdl_icache_shared_count(state->shared_cache);
    cdl_status st = cdl_icache_solve_shared(&ctx, state->shared_cache, &t, err);
    state->surface_records += cdl_icache_shared_count(state->shared_cache) - before;
    return st;
}

/* The interreflected light at the probes from the solve's one cache:
 * vertices first, for which records are placed where they need them; the
 * edges' midpoints, tested between vertices already served, interpolated,
 * with a record only where none serves one (a record placed for a
 * midpoint would serve little else).
 * Each point's target is relative to its surface's floor as well. */
static cdl_status cached_indirect(cdl_solve_state *state, const surface_field *f, const cdl_field_probe *probes,
                                  size_t count, const cdl_vec3 *points, const double *E_dir, const double *var_dir,
                                  double *E_ind, double *var_ind, size_t key, const char *stage, cdl_error *err)
{
    size_t *order = malloc((count + 1) * sizeof *order);
    cdl_vec3 *pn = malloc((2 * count + 1) * sizeof *pn), *at = malloc((count + 1) * sizeof *at);
    cdl_vec3 *moved = malloc((count + 1) * sizeof *moved);
    double *v = malloc((5 * count + 1) * sizeof *v);
    unsigned char *group = malloc(count + 1);
    cdl_status st = order && pn && at && moved && v && group ? CDL_OK : cdl_error_out_of_memory(err);
    /* Four groups, served in this order: vertices inside their surface,
     * vertices where surfaces meet, then the midpoints likewise. */
    for (size_t i = 0; st == CDL_OK && i < count; ++i) {
        at[i] = gather_point(state, f, points[i], points[count + i]);
        int edge = at[i].x != points[i].x || at[i].y != points[i].y || at[i].z != points[i].z;
        group[i] = (unsigned char)(2 * !probes[i].is_vertex + edge);
    }
    probe_groups q = {{0}, pn, moved, v, v + count, v + 2 * count, v + 3 * count, v + 4 * count, count};
    size_t k = 0;
    for (unsigned char g = 0; st == CDL_OK && g < 4; ++g) {
        q.first[g] = k;
        for (size_t i = 0; i < count; ++i)
            if (group[i] == g) order[k++] = i;
    }
    q.first[4] = k;
    int floorless = 1;
    for (size_t j = 0; st == CDL_OK && j < count; ++j) {
        size_t i = order[j];
        pn[j] = points[i];
        pn[count + j] = points[count + i];
        moved[j] = at[i];
        q.ed[j] = E_dir[i];
        q.vd[j] = var_dir[i];
        q.fl[j] = probes[i].floor;
        floorless &= !(probes[i].floor > 0.0);
    }
    /* The first round knows no surface's mean yet (every floor 0): without
     * floors the darkest corners (the wall behind a cabinet, a ceiling an
     * inch above a panel) held records to a fraction of a lux. A first
     * look, records only where no record serves a vertex, gives each
     * surface's mean, and the floors follow from it (on the 3 m cube of the
     * tests: RMS error at the floor's and a wall's vertices 0.21 % and
     * 0.17 % at "normal", was 0.18 % and 0.33 %). */
    if (st == CDL_OK && floorless) {
        for (int g = 0; st == CDL_OK && g < 2; ++g) st = serve_group(state, f, &q, g, 1, key, stage, err);
        if (st == CDL_OK) st = first_floors(probes, order, count, q.ed, q.ei, q.fl, err);
    }
    for (int g = 0; st == CDL_OK && g < 4; ++g) st = serve_group(state, f, &q, g, 0, key, stage, err);
    for (size_t j = 0; st == CDL_OK && j < count; ++j) {
        E_ind[order[j]] = q.ei[j];
        var_ind[order[j]] = q.vi[j];
    }
    free(order);
    free(pn);
    free(at);
    free(moved);
    free(v);
    free(group);
    return st;
}

static cdl_status field(void *user, const cdl_field_probe *probes, size_t count, double *value, double *sigma,
                        double *noise, double *aux, cdl_error *err)
{
    surface_field *f = user;
    cdl_solve_state *state = f->state;
    cdl_vec3 *points = malloc(2 * count * sizeof *points);
    double *buffers = calloc(4 * count, sizeof *buffers);
    if (!points || !buffers) {
        free(points);
        free(buffers);
        return cdl_error_out_of_memory(err);
    }
    double *E_dir = buffers, *var_dir = buffers + count, *E_ind = buffers + 2 * count, *var_ind = buffers + 3 * count;
    for (size_t i = 0; i < count; ++i) {
        points[i] = probes[i].position;
        points[count + i] = probes[i].normal;
    }
    cdl_grid grid = {.count = count, .points = points, .normals = points + count};
    /* Each batch's random numbers keyed apart from the grids' and from each other. */
    size_t key = (size_t)(f->base_key ^ (0x9e3779b97f4a7c15ull * (uint64_t)(f->batch + 1)));
    char stage[96];
    snprintf(stage, sizeof stage, "surface maps: round %zu (%zu points)", f->batch + 1, count);
    ++f->batch;
    cdl_direct_plan_grid(&state->direct, points, count, state->strategies);
    /* Every rank refines the meshes: each needs every point's light. */
    cdl_workers workers = cdl_solve_workers(state, 1);
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_direct_solve_grid(&state->direct, state->strategies, &grid, key, E_dir, var_dir, &workers,
                                          NULL, stage, &state->direct_stats, err);
    if (st == CDL_OK && state->surface_method == CDL_METHOD_ICACHE)
        st = cached_indirect(state, f, probes, count, points, E_dir, var_dir, E_ind, var_ind, key, stage, err);
    else if (st == CDL_OK && state->surface_method == CDL_METHOD_PATHTRACE)
        st = cdl_pathtrace_solve_grid(&state->pathtrace, &grid, key, E_dir, var_dir, E_ind, var_ind, &workers, stage,
                                      NULL, &state->pathtrace_stats, err);

    state->out->compute_seconds += cdl_pool_now_seconds() - t0;
    for (size_t i = 0; st == CDL_OK && i < count; ++i) {
        value[i] = E_dir[i] + E_ind[i];
        sigma[i] = sqrt(var_dir[i] + var_ind[i]);
        /* All of it, the cache's part too: light interpolated from the
         * records is shared by neighbours, but not smooth (a record enters
         * or leaves a point's sum with a kink, a leak test with a jump);
         * taking it as noise keeps refinement from chasing those (measured
         * on a 4 x 3 m room at draft: 5134 vertices, against 134 504 when
         * only the direct part counted as noise). */
        noise[i] = sigma[i];
        aux[2 * i] = E_dir[i];
        aux[2 * i + 1] = E_ind[i];
    }
    free(points);
    free(buffers);
    return st;
}

/* ---- the shared cache ---------------------------------------------------------------- */

/* Over everything any target will look up: the scene and every grid point. */
static cdl_status make_shared_cache(cdl_solve_state *state, cdl_error *err)
{
    cdl_bounds3 b;
    cdl_scene_geometry_bounds(state->geometry, &b.lo, &b.hi);
    for (size_t g = 0; g < state->out->grid_count; ++g)
        for (size_t i = 0; i < state->out->grids[g].grid.count; ++i)
            cdl_bounds3_grow(&b, state->out->grids[g].grid.points[i]);
    return cdl_icache_shared_create(b, &state->shared_cache, err);
}

/* The maps' typical coarsest edge: the median over their patches. */
static double median_edge(const cdl_surface_patches *p)
{
    double *e = malloc((p->count + 1) * sizeof *e);
    if (!e) return p->count ? p->patches[0].max_edge : 1.0;
    for (size_t i = 0; i < p->count; ++i) e[i] = p->patches[i].max_edge;
    cdl_sort_doubles(e, p->count);
    double m = p->count ? e[p->count / 2] : 1.0;
    free(e);
    return m;
}

/* ---- results ---------------------------------------------------------------------------- */

static double *copy_doubles(const double *from, size_t n)
{
    double *to = malloc((n + 1) * sizeof *to);
    if (to && n) memcpy(to, from, n * sizeof *to);
    return to;
}

/* Map k's solution from its mesh: E and its parts, the stated error with
 * the interpolation's, the reflectance by patch and the luminance. */
static cdl_status take_map(const cdl_surface_patches *p, size_t k, cdl_surface_mesh *m, cdl_surface_solution *out,
                           cdl_error *err)
{
    size_t n = m->vertex_count;
    out->surface = p->scene_surface[k];
    out->vertex_count = n;
    out->triangle_count = m->triangle_count;
    out->area_m2 = m->area;
    out->xyz = m->xyz;
    out->normal = m->normal;
    out->triangles = m->triangles;
    out->E = m->value;
    m->xyz = m->normal = m->value = NULL;
    m->triangles = NULL;
    out->E_direct = malloc((n + 1) * sizeof *out->E_direct);
    out->E_indirect = malloc((n + 1) * sizeof *out->E_indirect);
    out->E_stderr = malloc((n + 1) * sizeof *out->E_stderr);
    out->rho = malloc((n + 1) * sizeof *out->rho);
    out->L = malloc((n + 1) * sizeof *out->L);
    if (!out->E_direct || !out->E_indirect || !out->E_stderr || !out->rho || !out->L)
        return cdl_error_out_of_memory(err);
    for (size_t v = 0; v < n; ++v) {
        out->E_direct[v] = m->aux[2 * v];
        out->E_indirect[v] = m->aux[2 * v + 1];
        out->E_stderr[v] = hypot(m->sigma[v], m->interpolation[v]);
        out->rho[v] = p->reflectance[m->patch[v]];
        /* A Lambertian surface of reflectance rho under E has luminance rho E / pi. */
        out->L[v] = out->rho[v] * out->E[v] / CDL_PI;
    }
    return CDL_OK;
}

/* Area-weighted vertex normals of a piece's triangles (for viewers' shading). */
static void vertex_normals(const double *xyz, size_t nv, const uint32_t *tri, size_t nt, double *normal)
{
    memset(normal, 0, nv * 3 * sizeof *normal);
    for (size_t t = 0; t < nt; ++t) {
        const uint32_t *v = &tri[3 * t];
        cdl_vec3 a = cdl_vec3_make(xyz[3 * v[0]], xyz[3 * v[0] + 1], xyz[3 * v[0] + 2]);
        cdl_vec3 b = cdl_vec3_make(xyz[3 * v[1]], xyz[3 * v[1] + 1], xyz[3 * v[1] + 2]);
        cdl_vec3 c = cdl_vec3_make(xyz[3 * v[2]], xyz[3 * v[2] + 1], xyz[3 * v[2] + 2]);
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a));
        for (int k = 0; k < 3; ++k) {
            normal[3 * v[k]] += n.x;
            normal[3 * v[k] + 1] += n.y;
            normal[3 * v[k] + 2] += n.z;
        }
    }
    for (size_t i = 0; i < nv; ++i) {
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]));
        if (cdl_vec3_length(n) == 0.0) n = cdl_vec3_make(0, 0, 1);
        normal[3 * i] = n.x;
        normal[3 * i + 1] = n.y;
        normal[3 * i + 2] = n.z;
    }
}

/* One piece of an unmapped surface as a shape: its triangles, or a sphere tessellated. */
static cdl_status take_shape(const cdl_solve_state *state, size_t piece, cdl_surface_shape *out, cdl_error *err)
{
    const cdl_geometry_piece *gp = cdl_scene_geometry_piece(state->geometry, piece);
    out->surface = gp->source_index;
    const double *xyz;
    const uint32_t *tri;
    size_t nv, nt = cdl_scene_geometry_piece_triangles(state->geometry, piece, &xyz, &nv, &tri);
    cdl_trimesh sphere = {0};
    if (nt == 0 && gp->shape.kind == CDL_SHAPE_SPHERE) {
        const double c[3] = {gp->shape.center.x, gp->shape.center.y, gp->shape.center.z};
        cdl_status st = cdl_remesh_sphere(c, gp->shape.radius, gp->shape.inward, 0.3 * gp->shape.radius, &sphere, err);
        if (st != CDL_OK) return st;
        xyz = sphere.xyz;
        nv = sphere.vertex_count;
        tri = sphere.triangles;
        nt = sphere.triangle_count;
    }
    out->vertex_count = nv;
    out->triangle_count = nt;
    out->xyz = copy_doubles(xyz, 3 * nv);
    out->normal = malloc((3 * nv + 1) * sizeof *out->normal);
    out->triangles = malloc((3 * nt + 1) * sizeof *out->triangles);
    cdl_status st = out->xyz && out->normal && out->triangles ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) {
        memcpy(out->triangles, tri, 3 * nt * sizeof *tri);
        vertex_normals(out->xyz, nv, out->triangles, nt, out->normal);
    }
    cdl_trimesh_release(&sphere);
    return st;
}

static cdl_status take_shapes(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    size_t pieces = state->pieces, n = 0;
    state->out->shapes = calloc(pieces + 1, sizeof *state->out->shapes);
    if (!state->out->shapes) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < pieces; ++i) {
        const cdl_geometry_piece *gp = cdl_scene_geometry_piece(state->geometry, i);
        if (gp->is_luminaire || scene->surfaces[gp->source_index].mapped) continue;
        cdl_status st = take_shape(state, i, &state->out->shapes[n++], err);
        state->out->shape_count = n;
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

/* ---- the run ------------------------------------------------------------------------------ */

static cdl_surface_mesh_settings mesh_settings(const cdl_solve_state *state, double coarse)
{
    double extent = cdl_scene_geometry_extent(state->geometry);
    cdl_surface_mesh_settings s = {.rel_tol = state->target,
                                   .floor_fraction = FLOOR_FRACTION,
                                   .min_edge = fmax(MIN_EDGE_M, MIN_EDGE_FRACTION * coarse),
                                   .join_tolerance = 1e-9 * fmax(1.0, extent),
                                   .feature_angle_deg = FEATURE_ANGLE_DEG,
                                   .max_vertices = MAX_VERTICES,
                                   .aux_channels = 2};
    return s;
}

static cdl_status run_surfaces(cdl_solve_state *state, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    state->surface_method = !state->indirect ? CDL_METHOD_DIRECT
                            : scene->settings.method == CDL_METHOD_PATHTRACE ? CDL_METHOD_PATHTRACE
                                                                             : CDL_METHOD_ICACHE;
    cdl_surface_patches patches;
    cdl_status st = cdl_surface_patches_build(scene, &patches, err);
    if (st != CDL_OK) return st;
    if (state->surface_method == CDL_METHOD_ICACHE) st = make_shared_cache(state, err);
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, "surface maps", 12);
    surface_field f = {state, median_edge(&patches), h.value, 0};
    cdl_surface_mesh_request request = {patches.patches, patches.count, patches.map_count,
                                        mesh_settings(state, f.spacing), field, &f};
    cdl_surface_mesh *meshes = calloc(patches.map_count + 1, sizeof *meshes);
    state->out->surfaces = calloc(patches.map_count + 1, sizeof *state->out->surfaces);
    if (st == CDL_OK && (!meshes || !state->out->surfaces)) st = cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = cdl_surface_mesh_build(&request, meshes, &state->surface_stats, err);
    for (size_t k = 0; st == CDL_OK && k < patches.map_count; ++k) {
        state->out->surface_count = k + 1;
        st = take_map(&patches, k, &meshes[k], &state->out->surfaces[k], err);
    }
    for (size_t k = 0; meshes && k < patches.map_count; ++k) cdl_surface_mesh_release(&meshes[k]);
    free(meshes);
    cdl_surface_patches_release(&patches);
    if (st == CDL_OK) st = take_shapes(state, err);
    if (st == CDL_OK) cdl_plan_json_surfaces(state->plan, state);
    return st;
}

const cdl_solve_integrator cdl_integrator_surfaces = {"surfaces", applies_surfaces, run_surfaces};
