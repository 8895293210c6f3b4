/* surface_mesh.c - surface meshes refined to a field (surface_mesh.h):
 * the rounds of evaluation and splitting, and the meshes they leave. */
#include "solver/geometry/surface_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "solver/geometry/surface_patch.h"
#include "base/error_report.h"

/* Rounds of refinement at most: each halves the edges it splits, so this
 * takes an edge from a room's size to far below a millimetre; the vertex
 * budget or min_edge stops refinement long before. */
#define MAX_ROUNDS 48

/* An edge's deviation counts as curvature only beyond this many sigmas of
 * its noise: below, the values' noise could have made it. */
#define NOISE_SIGMAS 2.0

typedef struct candidate {
    size_t patch;
    uint64_t edge;
    double score;             /* |d| / tolerance */
} candidate;

typedef struct refinement {
    const cdl_surface_mesh_request *request;
    cdl_patch_state *states;
    double *floor;            /* per surface: the absolute tolerance */
    candidate *candidates;
    size_t candidate_count, candidate_capacity;
    cdl_surface_mesh_stats *stats;
} refinement;

/* ---- evaluation ------------------------------------------------------------------- */

typedef struct pending {
    size_t patch, index;
    int is_test;
} pending;

static cdl_status evaluate(refinement *r, cdl_error *err)
{
    const cdl_surface_mesh_request *q = r->request;
    size_t n = 0;
    for (size_t p = 0; p < q->patch_count; ++p) {
        const cdl_patch_state *ps = &r->states[p];
        for (size_t s = 0; s < ps->slot_count; ++s) n += !ps->slots[s].known;
        for (size_t t = 0; t < ps->test_count; ++t) n += !ps->tests[t].known;
    }
    if (n == 0) return CDL_OK;
    size_t channels = (size_t)q->settings.aux_channels;
    pending *which = malloc(n * sizeof *which);
    cdl_field_probe *probes = malloc(n * sizeof *probes);
    double *value = malloc(n * sizeof *value), *sigma = malloc(n * sizeof *sigma), *noise = malloc(n * sizeof *noise);
    double *aux = channels ? calloc(n * channels, sizeof *aux) : NULL;
    cdl_status st =
        which && probes && value && sigma && noise && (aux || !channels) ? CDL_OK : cdl_error_out_of_memory(err);
    for (size_t i = 0; noise && i < n; ++i) noise[i] = -1.0;
    size_t k = 0;
    for (size_t p = 0; st == CDL_OK && p < q->patch_count; ++p) {
        const cdl_patch_state *ps = &r->states[p];
        size_t surface = ps->spec->surface;
        for (size_t s = 0; s < ps->slot_count; ++s)
            if (!ps->slots[s].known) {
                which[k] = (pending){p, s, 0};
                probes[k++] = (cdl_field_probe){cdl_patch_state_position(ps, ps->slots[s].vertex), ps->slots[s].normal,
                                                surface, 1, r->floor[surface] / q->settings.rel_tol};
            }
        for (size_t t = 0; t < ps->test_count; ++t)
            if (!ps->tests[t].known) {
                which[k] = (pending){p, t, 1};
                probes[k++] = (cdl_field_probe){ps->tests[t].position, ps->tests[t].normal, surface, 0,
                                                r->floor[surface] / q->settings.rel_tol};
            }
    }
    if (st == CDL_OK) st = q->field(q->user, probes, n, value, sigma, noise, aux, err);
    for (size_t i = 0; st == CDL_OK && i < n; ++i) {
        if (!isfinite(value[i]) || !(sigma[i] >= 0.0) || !isfinite(sigma[i])) {
            st = cdl_error_set(err, CDL_ERR_INTERNAL,
                               "the field gave no finite value at (%.6g, %.6g, %.6g) m (value %g, sigma %g)",
                               probes[i].position.x, probes[i].position.y, probes[i].position.z, value[i], sigma[i]);
            break;
        }
        cdl_patch_state *ps = &r->states[which[i].patch];
        double *v = which[i].is_test ? &ps->tests[which[i].index].value : &ps->slots[which[i].index].value;
        double *s = which[i].is_test ? &ps->tests[which[i].index].sigma : &ps->slots[which[i].index].sigma;
        double *z = which[i].is_test ? &ps->tests[which[i].index].noise : &ps->slots[which[i].index].noise;
        double *a = which[i].is_test ? ps->tests[which[i].index].aux : ps->slots[which[i].index].aux;
        *v = value[i];
        *s = sigma[i];
        *z = noise[i] < 0.0 || !isfinite(noise[i]) ? sigma[i] : fmin(noise[i], sigma[i]);
        for (size_t c = 0; c < channels; ++c) a[c] = aux[channels * i + c];
        if (which[i].is_test) ps->tests[which[i].index].known = 1;
        else ps->slots[which[i].index].known = 1;
    }
    r->stats->evaluations += n;
    free(which);
    free(probes);
    free(value);
    free(sigma);
    free(noise);
    free(aux);
    return st;
}

/* ---- the tolerance and the edges to split ------------------------------------------- */

static double triangle_area(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    return 0.5 * cdl_vec3_length(cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
}

/* Each surface's floor: rel_tol floor_fraction Em, Em its area-weighted
 * mean over the linear interpolant. */
static void update_floors(refinement *r)
{
    const cdl_surface_mesh_request *q = r->request;
    double *area = calloc(q->surface_count + 1, sizeof *area);
    double *integral = calloc(q->surface_count + 1, sizeof *integral);
    for (size_t p = 0; area && integral && p < q->patch_count; ++p) {
        const cdl_patch_state *ps = &r->states[p];
        for (size_t t = 0; t < ps->tri_count; ++t) {
            const uint32_t *v = &ps->tri[3 * t];
            double a = triangle_area(cdl_patch_state_position(ps, v[0]), cdl_patch_state_position(ps, v[1]),
                                     cdl_patch_state_position(ps, v[2]));
            double sum = 0.0;
            for (size_t k = 0; k < 3; ++k) sum += ps->slots[cdl_patch_state_slot(ps, v[k], ps->tri_region[t])].value;
            area[ps->spec->surface] += a;
            integral[ps->spec->surface] += a * sum / 3.0;
        }
    }
    for (size_t s = 0; s < q->surface_count; ++s) {
        double mean = area && integral && area[s] > 0.0 ? fabs(integral[s] / area[s]) : 0.0;
        r->floor[s] = q->settings.rel_tol * q->settings.floor_fraction * mean;
    }
    free(area);
    free(integral);
}

/* The midpoint deviation of edge ab in region and whether it asks to be
 * split (ignoring its length): 1 split, 0 not. */
static int edge_deviation(const refinement *r, const cdl_patch_state *ps, uint32_t a, uint32_t b, uint32_t region,
                          double *deviation, double *score)
{
    const cdl_patch_slot *sa = &ps->slots[cdl_patch_state_slot(ps, a, region)];
    const cdl_patch_slot *sb = &ps->slots[cdl_patch_state_slot(ps, b, region)];
    const cdl_patch_test *t = &ps->tests[cdl_patch_state_test(ps, a, b, region)];
    double interpolated = 0.5 * (sa->value + sb->value);
    *deviation = t->value - interpolated;
    double noise = sqrt(t->noise * t->noise + 0.25 * (sa->noise * sa->noise + sb->noise * sb->noise));
    double tolerance = fmax(r->request->settings.rel_tol * fabs(interpolated), r->floor[ps->spec->surface]);
    double d = fabs(*deviation);
    *score = tolerance > 0.0 ? d / tolerance : (d > 0.0 ? INFINITY : 0.0);
    return d > tolerance && d > NOISE_SIGMAS * noise;
}

static cdl_status add_candidate(refinement *r, size_t patch, uint64_t edge, double score, cdl_error *err)
{
    if (cdl_grow(&r->candidates, &r->candidate_capacity, r->candidate_count + 1, sizeof *r->candidates, 256, err) !=
        CDL_OK)
        return CDL_ERR_INTERNAL;
    r->candidates[r->candidate_count++] = (candidate){patch, edge, score};
    return CDL_OK;
}

static int by_patch_edge(const void *pa, const void *pb)
{
    const candidate *a = pa, *b = pb;
    if (a->patch != b->patch) return a->patch < b->patch ? -1 : 1;
    if (a->edge != b->edge) return a->edge < b->edge ? -1 : 1;
    return (a->score < b->score) - (a->score > b->score);
}

static int by_score(const void *pa, const void *pb)
{
    const candidate *a = pa, *b = pb;
    if (a->score != b->score) return a->score > b->score ? -1 : 1;
    return by_patch_edge(pa, pb);
}

/* The edges to split, one candidate each (sorted by patch and edge);
 * counts the edges too short to split that still ask for it. */
static cdl_status choose_edges(refinement *r, size_t *unresolved, cdl_error *err)
{
    const cdl_surface_mesh_request *q = r->request;
    r->candidate_count = 0;
    *unresolved = 0;
    for (size_t p = 0; p < q->patch_count; ++p) {
        const cdl_patch_state *ps = &r->states[p];
        for (size_t t = 0; t < ps->tri_count; ++t)
            for (size_t k = 0; k < 3; ++k) {
                uint32_t a = ps->tri[3 * t + k], b = ps->tri[3 * t + (k + 1) % 3];
                double deviation, score;
                if (!edge_deviation(r, ps, a, b, ps->tri_region[t], &deviation, &score)) continue;
                double length = cdl_vec3_distance(cdl_patch_state_position(ps, a), cdl_patch_state_position(ps, b));
                if (length <= q->settings.min_edge) {
                    ++*unresolved;
                    continue;
                }
                if (add_candidate(r, p, cdl_key_pair(a, b), score, err) != CDL_OK) return CDL_ERR_INTERNAL;
            }
    }
    /* One entry per edge (an inner edge is seen from both its triangles). */
    if (r->candidate_count == 0) return CDL_OK;
    qsort(r->candidates, r->candidate_count, sizeof *r->candidates, by_patch_edge);
    size_t kept = 0;
    for (size_t i = 0; i < r->candidate_count; ++i)
        if (kept == 0 || r->candidates[kept - 1].patch != r->candidates[i].patch ||
            r->candidates[kept - 1].edge != r->candidates[i].edge)
            r->candidates[kept++] = r->candidates[i];
    r->candidate_count = kept;
    return CDL_OK;
}

/* Hold the splits to the vertex budget: each split adds a vertex, and
 * Delaunay refinement or bisection on the way about as many again. */
static void apply_budget(refinement *r)
{
    const cdl_surface_mesh_request *q = r->request;
    size_t vertices = 0;
    for (size_t p = 0; p < q->patch_count; ++p) vertices += r->states[p].slot_count;
    size_t room = vertices < q->settings.max_vertices ? (q->settings.max_vertices - vertices) / 2 : 0;
    if (r->candidate_count <= room) return;
    r->stats->budget_reached = 1;
    qsort(r->candidates, r->candidate_count, sizeof *r->candidates, by_score);
    r->candidate_count = room;
    qsort(r->candidates, r->candidate_count, sizeof *r->candidates, by_patch_edge);
}

static cdl_status split_chosen(refinement *r, cdl_error *err)
{
    const cdl_surface_mesh_request *q = r->request;
    uint64_t *edges = malloc((r->candidate_count + 1) * sizeof *edges);
    if (!edges) return cdl_error_out_of_memory(err);
    cdl_status st = CDL_OK;
    for (size_t i = 0; st == CDL_OK && i < r->candidate_count;) {
        size_t p = r->candidates[i].patch, n = 0;
        while (i < r->candidate_count && r->candidates[i].patch == p) edges[n++] = r->candidates[i++].edge;
        st = cdl_patch_state_split(&r->states[p], edges, n, 4 * q->settings.max_vertices, err);
    }
    free(edges);
    return st;
}

/* ---- the meshes left -------------------------------------------------------------- */

/* The rms interpolation error over a triangle from its midpoint deviations
 * (surface_mesh.h). */
static double triangle_rms_error(const double d[3])
{
    double squares = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double products = d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    return sqrt(fmax(0.0, 16.0 / 90.0 * (squares + products)));
}

static cdl_status allocate_mesh(cdl_surface_mesh *m, size_t nv, size_t nt, int channels, cdl_error *err)
{
    if (channels && !(m->aux = malloc((nv + 1) * (size_t)channels * sizeof *m->aux))) return cdl_error_out_of_memory(err);
    if (!(m->patch = malloc((nv + 1) * sizeof *m->patch))) return cdl_error_out_of_memory(err);
    m->xyz = malloc((nv + 1) * 3 * sizeof *m->xyz);
    m->normal = malloc((nv + 1) * 3 * sizeof *m->normal);
    m->value = malloc((nv + 1) * sizeof *m->value);
    m->sigma = malloc((nv + 1) * sizeof *m->sigma);
    m->interpolation = calloc(nv + 1, sizeof *m->interpolation);
    m->on_outline = calloc(nv + 1, 1);
    m->triangles = malloc((nt + 1) * 3 * sizeof *m->triangles);
    if (!m->xyz || !m->normal || !m->value || !m->sigma || !m->interpolation || !m->on_outline || !m->triangles)
        return cdl_error_out_of_memory(err);
    return CDL_OK;
}

/* Append patch ps's slots and triangles to its surface's mesh. */
static void append_patch(const refinement *r, const cdl_patch_state *ps, cdl_surface_mesh *m)
{
    size_t base = m->vertex_count, channels = (size_t)r->request->settings.aux_channels;
    uint32_t patch = (uint32_t)(ps - r->states);
    for (size_t s = 0; s < ps->slot_count; ++s) {
        const cdl_patch_slot *slot = &ps->slots[s];
        size_t v = base + s;
        cdl_vec3 p = cdl_patch_state_position(ps, slot->vertex);
        m->xyz[3 * v] = p.x;
        m->xyz[3 * v + 1] = p.y;
        m->xyz[3 * v + 2] = p.z;
        m->normal[3 * v] = slot->normal.x;
        m->normal[3 * v + 1] = slot->normal.y;
        m->normal[3 * v + 2] = slot->normal.z;
        m->value[v] = slot->value;
        m->sigma[v] = slot->sigma;
        for (size_t c = 0; c < channels; ++c) m->aux[channels * v + c] = slot->aux[c];
        m->patch[v] = patch;
        m->on_outline[v] = (unsigned char)cdl_patch_state_on_outline(ps, slot->vertex);
    }
    m->vertex_count += ps->slot_count;
    for (size_t t = 0; t < ps->tri_count; ++t) {
        const uint32_t *v = &ps->tri[3 * t];
        uint32_t region = ps->tri_region[t];
        double d[3], score;
        uint32_t *out = &m->triangles[3 * m->triangle_count++];
        for (size_t k = 0; k < 3; ++k) {
            out[k] = (uint32_t)(base + cdl_patch_state_slot(ps, v[k], region));
            edge_deviation(r, ps, v[k], v[(k + 1) % 3], region, &d[k], &score);
        }
        double e = triangle_rms_error(d);
        for (size_t k = 0; k < 3; ++k) m->interpolation[out[k]] = fmax(m->interpolation[out[k]], e);
    }
}

static double mesh_area(const cdl_surface_mesh *m)
{
    double area = 0.0;
    for (size_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *v = &m->triangles[3 * t];
        cdl_vec3 p[3];
        for (size_t k = 0; k < 3; ++k) p[k] = cdl_vec3_make(m->xyz[3 * v[k]], m->xyz[3 * v[k] + 1], m->xyz[3 * v[k] + 2]);
        area += triangle_area(p[0], p[1], p[2]);
    }
    return area;
}

static cdl_status assemble(const refinement *r, cdl_surface_mesh *out, cdl_error *err)
{
    const cdl_surface_mesh_request *q = r->request;
    for (size_t s = 0; s < q->surface_count; ++s) {
        size_t nv = 0, nt = 0;
        for (size_t p = 0; p < q->patch_count; ++p)
            if (r->states[p].spec->surface == s) {
                nv += r->states[p].slot_count;
                nt += r->states[p].tri_count;
            }
        if (allocate_mesh(&out[s], nv, nt, q->settings.aux_channels, err) != CDL_OK) return CDL_ERR_INTERNAL;
        for (size_t p = 0; p < q->patch_count; ++p)
            if (r->states[p].spec->surface == s) append_patch(r, &r->states[p], &out[s]);
    }
    if (cdl_surface_mesh_snap(out, q->surface_count, q->settings.join_tolerance, err) != CDL_OK) return CDL_ERR_INTERNAL;
    for (size_t s = 0; s < q->surface_count; ++s) {
        out[s].area = mesh_area(&out[s]);
        r->stats->vertices += out[s].vertex_count;
        r->stats->triangles += out[s].triangle_count;
    }
    return CDL_OK;
}

/* ---- the rounds ---------------------------------------------------------------------- */

static cdl_status check_request(const cdl_surface_mesh_request *q, cdl_error *err)
{
    const cdl_surface_mesh_settings *s = &q->settings;
    if (!(s->rel_tol > 0.0) || !(s->floor_fraction >= 0.0) || !(s->min_edge > 0.0) || !(s->join_tolerance > 0.0) ||
        !(s->feature_angle_deg > 0.0 && s->feature_angle_deg < 180.0) || s->max_vertices == 0 || !q->field ||
        s->aux_channels < 0 || s->aux_channels > CDL_FIELD_AUX_MAX)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "surface meshing: settings out of range (rel_tol %g, floor_fraction %g, min_edge %g m, "
                             "join_tolerance %g m, feature angle %g deg, max_vertices %zu)",
                             s->rel_tol, s->floor_fraction, s->min_edge, s->join_tolerance, s->feature_angle_deg,
                             s->max_vertices);
    for (size_t p = 0; p < q->patch_count; ++p)
        if (q->patches[p].surface >= q->surface_count)
            return cdl_error_set(err, CDL_ERR_INPUT, "surface meshing: patch %zu names surface %zu of %zu", p,
                                 q->patches[p].surface, q->surface_count);
    return CDL_OK;
}

static cdl_status refine(refinement *r, cdl_error *err)
{
    const cdl_surface_mesh_request *q = r->request;
    for (int round = 0;; ++round) {
        cdl_status st = cdl_patch_join(r->states, q->patch_count, q->settings.join_tolerance,
                                       4 * q->settings.max_vertices, &r->stats->joined, err);
        if (st != CDL_OK) return st;
        for (size_t p = 0; p < q->patch_count; ++p)
            if (cdl_patch_state_refresh(&r->states[p], err) != CDL_OK) return CDL_ERR_INTERNAL;
        st = evaluate(r, err);
        if (st != CDL_OK) return st;
        update_floors(r);
        if (choose_edges(r, &r->stats->unresolved, err) != CDL_OK) return CDL_ERR_INTERNAL;
        if (r->candidate_count == 0 || round == MAX_ROUNDS || r->stats->budget_reached) return CDL_OK;
        apply_budget(r);
        if (r->candidate_count == 0) return CDL_OK;
        st = split_chosen(r, err);
        if (st != CDL_OK) return st;
        ++r->stats->rounds;
    }
}

cdl_status cdl_surface_mesh_build(const cdl_surface_mesh_request *request, cdl_surface_mesh *out,
                                  cdl_surface_mesh_stats *stats, cdl_error *err)
{
    memset(out, 0, request->surface_count * sizeof *out);
    memset(stats, 0, sizeof *stats);
    cdl_status st = check_request(request, err);
    if (st != CDL_OK) return st;
    refinement r = {request, calloc(request->patch_count + 1, sizeof *r.states),
                    calloc(request->surface_count + 1, sizeof *r.floor), NULL, 0, 0, stats};
    if (!r.states || !r.floor) st = cdl_error_out_of_memory(err);
    for (size_t p = 0; st == CDL_OK && p < request->patch_count; ++p) {
        st = cdl_patch_state_init(&r.states[p], &request->patches[p], &request->settings, err);
        if (st != CDL_OK) cdl_error_prefix(err, "surface meshing, patch %zu: ", p);
        stats->mesh_as_given += r.states[p].as_given;
    }
    if (st == CDL_OK) st = refine(&r, err);
    if (st == CDL_OK) st = assemble(&r, out, err);
    for (size_t p = 0; r.states && p < request->patch_count; ++p) cdl_patch_state_release(&r.states[p]);
    free(r.states);
    free(r.floor);
    free(r.candidates);
    if (st != CDL_OK)
        for (size_t s = 0; s < request->surface_count; ++s) cdl_surface_mesh_release(&out[s]);
    return st;
}

void cdl_surface_mesh_release(cdl_surface_mesh *mesh)
{
    if (!mesh) return;
    free(mesh->xyz);
    free(mesh->normal);
    free(mesh->value);
    free(mesh->sigma);
    free(mesh->interpolation);
    free(mesh->aux);
    free(mesh->patch);
    free(mesh->on_outline);
    free(mesh->triangles);
    memset(mesh, 0, sizeof *mesh);
}
