/* daylight_coefficients.c - sky patches' and suns' coefficients at grid points (see the header). */
#include "solver/daylight/daylight_coefficients.h"


#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/error_report.h"
#include "base/rng.h"
#include "lights/emitters/projected_solid_angle.h"
#include "lights/emitters/spherical_triangle.h"
#include "radiometry/constants.h"
#include "radiometry/estimate.h"
#include "radiometry/frame.h"
#include "radiometry/sampling.h"
#include "solver/geometry/visible_polygon.h"
#include "solver/pool.h"
#include "solver/scene/scene_occluders.h"
#include "solver/transport/path.h"
#include "solver/transport/surface_hit.h"

/* Strata per side of a point's pilot round: 8 x 8 cells, 128 paths (as the
 * path tracer's, pathtrace.c). */
#define PILOT_SIDE 8

/* Russian roulette below this throughput (as transport/path.c). */
#define RR_THRESHOLD 0.1

/* ---- the scene ------------------------------------------------------------------ */

cdl_status cdl_daylight_scene_build(const cdl_scene *scene, cdl_daylight_scene *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    out->scene = scene;
    if (scene->luminaire_count > 0)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: %s: expected no luminaires in an annual study (the sky and the sun come from the "
                             "weather file): remove them",
                             scene->path, scene->luminaires[0].json_path);
    for (size_t i = 0; i < scene->surface_count; ++i)
        if (scene->surfaces[i].luminance_cd_m2 > 0.0)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s.luminance_cd_m2: expected no emitting surfaces in an annual study (the sky "
                                 "and the sun come from the weather file)",
                                 scene->path, scene->surfaces[i].json_path);
    if (scene->grid_count == 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: grids: expected at least one grid for an annual study",
                             scene->path);
    cdl_status st = cdl_scene_geometry_build(scene, &out->geometry, err);
    if (st == CDL_OK && cdl_scene_geometry_piece_count(out->geometry) > 0) {
        st = cdl_scene_occluders_build(out->geometry, &out->occluders, err);
        if (st == CDL_OK) {
            out->direct.geometry = out->geometry;
            cdl_scene_geometry_ray_offsets(out->geometry, &out->direct.offsets);
            out->direct.rays = cdl_scene_geometry_rays(out->geometry);
            out->direct.occluders = out->occluders;
        }
    }
    if (st == CDL_OK && !(out->grids = calloc(scene->grid_count, sizeof *out->grids))) st = cdl_error_out_of_memory(err);
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) {
        st = cdl_grid_build(&scene->grids[g], &out->grids[g], err);
        if (st != CDL_OK) cdl_error_prefix(err, "%s: ", scene->path);
    }
    if (st != CDL_OK) cdl_daylight_scene_release(out);
    return st;
}

void cdl_daylight_scene_release(cdl_daylight_scene *ds)
{
    if (!ds) return;
    for (size_t g = 0; ds->grids && g < ds->scene->grid_count; ++g) cdl_grid_release(&ds->grids[g]);
    free(ds->grids);
    cdl_occluder_index_release(ds->occluders);
    cdl_scene_geometry_release(ds->geometry);
    memset(ds, 0, sizeof *ds);
}

/* ---- one point ------------------------------------------------------------------ */

/* Directions drawn over the visible sky to weigh it with the panes' transmittance. */
#define GLASS_SAMPLES 1024

/* A visible piece, kept for the panes' weights. */
typedef struct sky_piece {
    int count;
    cdl_vec3 v[CDL_VISIBLE_MAX_VERTICES];
} sky_piece;

/* What a worker keeps from point to point. */
typedef struct worker {
    double *direct;           /* patches: the exact direct part */
    double *t_num, *t_den;    /* patches: the panes' transmittance, cosine-weighted sums */
    sky_piece *pieces;        /* the point's visible pieces */
    size_t piece_count, piece_cap;
    double *acc;              /* patches: the reported stage's escapes, summed */
    double *sun_acc;          /* suns: its next-event sums */
    double *full;             /* patches: the whole hemisphere's Q for full_n */
    cdl_vec3 full_n;
    int has_full;
    uint64_t paths, rays;
    cdl_daylight_routes routes;
} worker;

typedef struct job {
    const cdl_daylight_scene *ds;
    const cdl_daylight_coefficient_options *o;
    const cdl_grid *grid;
    uint64_t grid_key;
    cdl_daylight_grid_coefficients *out;
    const cdl_rank_deal *deal;            /* point i's outputs at row cdl_rank_deal_row(deal, i) */
} job;

typedef struct piece_sink {
    const cdl_reinhart_patches *p;        /* NULL: keep the pieces only */
    cdl_vec3 n;
    worker *w;
    int overflow;
} piece_sink;

/* A visible piece: its patches' parts in closed form, and kept. */
static void add_piece(void *user, const cdl_vec3 *dirs, int count)
{
    piece_sink *sink = user;
    worker *w = sink->w;
    if (sink->p) cdl_reinhart_add_polygon(sink->p, dirs, count, sink->n, 1.0, w->direct);
    if (w->piece_count == w->piece_cap) {
        size_t cap = w->piece_cap ? 2 * w->piece_cap : 16;
        sky_piece *more = realloc(w->pieces, cap * sizeof *more);
        if (!more) {
            sink->overflow = 1;
            return;
        }
        w->pieces = more;
        w->piece_cap = cap;
    }
    sky_piece *pc = &w->pieces[w->piece_count++];
    pc->count = count;
    memcpy(pc->v, dirs, (size_t)count * sizeof *dirs);
}

/* The panes seen: each patch's closed-form part times the mean
 * transmittance over it, T_k = int_k T cos dw / int_k cos dw, estimated by
 * GLASS_SAMPLES directions drawn uniformly in solid angle over the pieces'
 * fan triangles (Arvo's map), each triangle its share, a ray each for T;
 * a patch no direction fell in takes the mean over all. T varies slowly
 * with the angle of incidence, so the ratio is close whatever the draw. */
static void weigh_glass(const job *jb, worker *w, uint64_t stream, cdl_vec3 p, cdl_vec3 n)
{
    const cdl_reinhart_patches *pt = jb->o->patches;
    size_t K = (size_t)pt->count;
    memset(w->t_num, 0, K * sizeof *w->t_num);
    memset(w->t_den, 0, K * sizeof *w->t_den);
    double total = 0.0, all_num = 0.0, all_den = 0.0;
    for (size_t i = 0; i < w->piece_count; ++i)
        for (int t = 1; t + 1 < w->pieces[i].count; ++t)
            total += cdl_triangle_solid_angle(w->pieces[i].v[0], w->pieces[i].v[t], w->pieces[i].v[t + 1]);
    uint64_t draw = 0;
    for (size_t i = 0; i < w->piece_count && total > 0.0; ++i)
        for (int t = 1; t + 1 < w->pieces[i].count; ++t) {
            cdl_spherical_triangle tri;
            double omega = cdl_spherical_triangle_init(&tri, w->pieces[i].v[0], w->pieces[i].v[t],
                                                       w->pieces[i].v[t + 1]);
            if (!(omega > 1e-9)) continue; /* Arvo's map is imprecise there; its patch takes the mean */
            int m = (int)ceil(GLASS_SAMPLES * omega / total);
            for (int j = 0; j < m; ++j) {
                double u[2];
                cdl_rng_uniform2((cdl_rng_key){jb->o->seed, stream}, draw++, u);
                cdl_vec3 d = cdl_spherical_triangle_sample(&tri, (j + u[0]) / m, u[1]);
                double c = cdl_vec3_dot(n, d);
                if (!(c > 0.0)) continue;
                w->rays++;
                double T = cdl_scene_geometry_transmission(jb->ds->geometry, p, d, INFINITY);
                int k = cdl_reinhart_patch_of(pt, d);
                w->t_num[k] += omega / m * T * c;
                w->t_den[k] += omega / m * c;
                all_num += omega / m * T * c;
                all_den += omega / m * c;
            }
        }
    double mean = all_den > 0.0 ? all_num / all_den : 0.0;
    for (size_t k = 0; k < K; ++k)
        if (w->direct[k] > 0.0) w->direct[k] *= w->t_den[k] > 0.0 ? w->t_num[k] / w->t_den[k] : mean;
}

/* The direct part at p exactly where the exact route can say what p sees
 * (through glass: weighed with the panes' transmittance): 1 with
 * w->direct filled, 0 (w->direct zero) where it is to be sampled. */
static int direct_exact(const job *jb, worker *w, uint64_t stream, cdl_vec3 p, cdl_vec3 n)
{
    const cdl_reinhart_patches *pt = jb->o->patches;
    size_t K = (size_t)pt->count;
    memset(w->direct, 0, K * sizeof *w->direct);
    w->piece_count = 0;
    piece_sink sink = {pt, n, w, 0};
    int glass = 0;
    cdl_direct_route route = cdl_direct_visible_sky_through_glass(&jb->ds->direct, p, n, add_piece, &sink, &glass);
    if (route == CDL_ROUTE_VISIBLE_POLYGON && sink.overflow) route = CDL_ROUTE_TOO_COMPLEX;
    if (route == CDL_ROUTE_VISIBLE_POLYGON) {
        if (glass) {
            weigh_glass(jb, w, cdl_rng_stream_id(stream, 0, 0x676c617373 /* "glass" */), p, n);
            w->routes.through_glass++;
        } else {
            w->routes.exact++;
        }
        return 1;
    }
    if (route != CDL_ROUTE_FULL_VIEW) {
        memset(w->direct, 0, K * sizeof *w->direct);
        w->routes.sampled[route]++;
        return 0;
    }
    /* the whole hemisphere: each patch's closed form, kept for the next
     * point of the same normal (a flat grid's) */
    if (!w->has_full || memcmp(&w->full_n, &n, sizeof n) != 0) {
        for (size_t k = 0; k < K; ++k) w->full[k] = cdl_reinhart_projected_solid_angle(pt, (int)k, n);
        w->full_n = n;
        w->has_full = 1;
    }
    memcpy(w->direct, w->full, K * sizeof *w->direct);
    w->routes.exact++;
    return 1;
}

/* One path's sums: f_sky under the reference sky (a uniform one of 1 cd/m^2
 * unless the options give one), f_sun over the suns. */
typedef struct path_sums {
    double f_sky, f_sun;
} path_sums;

/* The reference sky's luminance of patch k (1 without one). */
static double reference(const cdl_daylight_coefficient_options *o, int k)
{
    return o->reference_sky ? o->reference_sky[k] : 1.0;
}

/* Next-event estimation towards the sky from a reflection at hit (throughput
 * wt): one direction drawn in the sky the hit sees, as the exact route finds
 * it (panes taken as clear, then their transmittance along the direction):
 * a fan triangle of its pieces with probability proportional to its
 * projected solid angle Omega_p,t, a direction uniform in its solid angle
 * Omega_t, so that Omega_t cos T / P_t estimates int T cos dw over the sky
 * seen (unbiased; no shadow ray misses a window). Returns 0, adding
 * nothing, where the exact route cannot say what the hit sees: the path's
 * next escape counts instead. */
static int sky_at(const job *jb, worker *w, const cdl_surface_hit *hit, double wt, cdl_rng_key key, int depth,
                  double *acc, path_sums *s)
{
    w->piece_count = 0;
    piece_sink sink = {NULL, hit->n, w, 0};
    int glass = 0;
    cdl_direct_route route =
        cdl_direct_visible_sky_through_glass(&jb->ds->direct, hit->p, hit->n, add_piece, &sink, &glass);
    double u[2];
    cdl_rng_uniform2(key, (uint64_t)(0x10000 + 2 * depth), u);
    if (route == CDL_ROUTE_FULL_VIEW) {
        /* the whole hemisphere: a cosine-weighted direction, pi L a sample */
        cdl_frame f = cdl_frame_from_normal(hit->n);
        cdl_vec3 d = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u[0], u[1]));
        double v = CDL_PI * wt;
        int k = cdl_reinhart_patch_of(jb->o->patches, d);
        if (acc) acc[k] += v;
        s->f_sky += v * reference(jb->o, k);
        return 1;
    }
    if (route != CDL_ROUTE_VISIBLE_POLYGON || sink.overflow) return 0;
    double total = 0.0;
    for (size_t i = 0; i < w->piece_count; ++i)
        for (int t = 1; t + 1 < w->pieces[i].count; ++t) {
            const cdl_vec3 tri[3] = {w->pieces[i].v[0], w->pieces[i].v[t], w->pieces[i].v[t + 1]};
            total += fabs(cdl_projected_solid_angle_polygon(tri, 3, hit->n));
        }
    if (!(total > 0.0)) return 1; /* it sees no sky */
    double pick = u[0] * total;
    for (size_t i = 0; i < w->piece_count; ++i)
        for (int t = 1; t + 1 < w->pieces[i].count; ++t) {
            const cdl_vec3 tri[3] = {w->pieces[i].v[0], w->pieces[i].v[t], w->pieces[i].v[t + 1]};
            double q = fabs(cdl_projected_solid_angle_polygon(tri, 3, hit->n));
            if (pick >= q && !(i + 1 == w->piece_count && t + 2 == w->pieces[i].count)) {
                pick -= q;
                continue;
            }
            cdl_spherical_triangle st;
            double omega = cdl_spherical_triangle_init(&st, tri[0], tri[1], tri[2]);
            if (!(omega > 0.0) || !(q > 0.0)) return 1;
            double u2[2];
            cdl_rng_uniform2(key, (uint64_t)(0x10001 + 2 * depth), u2);
            cdl_vec3 d = cdl_spherical_triangle_sample(&st, u2[0], u2[1]);
            double c = cdl_vec3_dot(hit->n, d);
            if (!(c > 0.0)) return 1;
            w->rays++;
            double T = glass ? cdl_scene_geometry_transmission(jb->ds->geometry, hit->p, d, INFINITY) : 1.0;
            double v = wt * omega * c * T * total / q;
            int k = cdl_reinhart_patch_of(jb->o->patches, d);
            if (acc) acc[k] += v;
            s->f_sky += v * reference(jb->o, k);
            return 1;
        }
    return 1;
}

/* Next-event estimation towards every sun from a reflection at hit
 * (throughput w, the hit's reflectance and panes included). */
static void suns_at(const job *jb, worker *w, const cdl_surface_hit *hit, double wt, double *sun_acc, path_sums *s)
{
    const cdl_daylight_coefficient_options *o = jb->o;
    for (size_t k = 0; k < o->sun_count; ++k) {
        double c = cdl_vec3_dot(hit->n, o->suns[k]);
        if (!(c > 0.0)) continue;
        w->rays++;
        double T = cdl_scene_geometry_transmission(jb->ds->geometry, hit->p, o->suns[k], INFINITY);
        if (!(T > 0.0)) continue;
        double v = wt * c * T;
        if (sun_acc) sun_acc[k] += v;
        s->f_sun += v;
    }
}

/* One path from p leaving along dir (the first direction drawn cosine-
 * weighted): its escapes into acc by patch (the first one only when the
 * direct part is sampled), its suns into sun_acc; either may be NULL (the
 * pilot). Random numbers from key, counter 0 left to the caller. */
static path_sums trace_path(const job *jb, worker *w, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir,
                            int first_escape_counts, double *acc, double *sun_acc)
{
    path_sums s = {0.0, 0.0};
    double wt = 1.0;
    cdl_vec3 origin = p, origin_n = n;
    int escape_counts = first_escape_counts;
    w->paths++;
    for (int depth = 0; depth < CDL_PATH_MAX_DEPTH; ++depth) {
        cdl_surface_hit hit;
        w->rays++;
        if (!cdl_transport_trace(jb->ds->geometry, origin, origin_n, dir, &hit)) {
            /* E = int L cos dw by cosine-weighted directions: pi L a sample
             * (unless the sky was reached by next-event estimation) */
            if (escape_counts) {
                double v = CDL_PI * wt * hit.transmission;
                int k = cdl_reinhart_patch_of(jb->o->patches, dir);
                if (acc) acc[k] += v;
                s.f_sky += v * reference(jb->o, k);
            }
            break;
        }
        /* a Lambertian reflection: pi L_r = rho E at the hit */
        wt *= hit.transmission * hit.reflectance;
        if (!(wt > 0.0)) break;
        suns_at(jb, w, &hit, wt, sun_acc, &s);
        escape_counts = !sky_at(jb, w, &hit, wt, key, depth, acc, &s);
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)(1 + 2 * depth), u);
        double q = wt < RR_THRESHOLD ? wt / RR_THRESHOLD : 1.0;
        if (q > 0.99) q = 0.99;
        if (u[0] >= q) break;
        wt /= q;
        cdl_rng_uniform2(key, (uint64_t)(2 + 2 * depth), u);
        cdl_frame f = cdl_frame_from_normal(hit.n);
        dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u[0], u[1]));
        origin = hit.p;
        origin_n = hit.n;
    }
    return s;
}

/* A round of k x k strata of the first direction, two paths each, paths
 * numbered from `base`; its two estimates (uniform sky, suns). */
static void path_round(const job *jb, worker *w, uint64_t stream, uint64_t base, cdl_vec3 p, cdl_vec3 n, int k,
                       int first_escape_counts, double *acc, double *sun_acc, cdl_estimate *sky, cdl_estimate *sun)
{
    cdl_frame f = cdl_frame_from_normal(n);
    cdl_round rs = {0.0, 0.0, 0.0, 0}, ru = {0.0, 0.0, 0.0, 0};
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            path_sums v[2];
            for (int t = 0; t < 2; ++t) {
                uint64_t path = base + (uint64_t)(2 * (j * k + i) + t);
                cdl_rng_key key = {jb->o->seed, cdl_rng_stream_id(stream, path, 0x6461796c /* "dayl" */)};
                double u[2];
                cdl_rng_uniform2(key, 0, u);
                cdl_vec3 dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere((i + u[0]) / k, (j + u[1]) / k));
                v[t] = trace_path(jb, w, key, p, n, dir, first_escape_counts, acc, sun_acc);
            }
            cdl_round_add_pair(&rs, v[0].f_sky, v[1].f_sky);
            cdl_round_add_pair(&ru, v[0].f_sun, v[1].f_sun);
        }
    cdl_estimate_add_round(sky, &rs);
    cdl_estimate_add_round(sun, &ru);
}

static void point_coefficients(const job *jb, worker *w, size_t i)
{
    const cdl_daylight_coefficient_options *o = jb->o;
    cdl_daylight_grid_coefficients *out = jb->out;
    size_t K = (size_t)o->patches->count, S = o->sun_count;
    cdl_vec3 p = jb->grid->points[i], n = jb->grid->normals[i];
    uint64_t stream = cdl_rng_stream_id(jb->grid_key, (uint64_t)i, 0x636f6566 /* "coef" */);
    size_t row = cdl_rank_deal_row(jb->deal, i);
    int exact = direct_exact(jb, w, stream, p, n);
    out->exact[row] = (unsigned char)exact;
    if (out->direct)
        for (size_t k = 0; k < K; ++k) out->direct[row * K + k] = (float)w->direct[k];
    double E_direct = 0.0;
    for (size_t k = 0; k < K; ++k) E_direct += w->direct[k] * reference(o, (int)k);
    memset(w->acc, 0, K * sizeof *w->acc);
    if (S) memset(w->sun_acc, 0, S * sizeof *w->sun_acc);
    double sky_var = 0.0, sun_mean = 0.0, sun_var = 0.0, stage = 0.0;
    if (!o->direct_only && jb->ds->geometry && cdl_scene_geometry_piece_count(jb->ds->geometry) > 0) {
        /* The pilot only plans (estimate.h): how many paths the point needs
         * for the sampled part under a uniform sky to meet the target. */
        cdl_estimate ps = {0.0, 0.0, 0.0, 0}, pu = {0.0, 0.0, 0.0, 0};
        path_round(jb, w, stream, 0, p, n, PILOT_SIDE, !exact, NULL, NULL, &ps, &pu);
        double R = E_direct + cdl_estimate_mean(&ps), want = 0.0;
        if (R > 0.0) {
            double budget = o->target * o->target * R * R;
            want = cdl_estimate_plan(&ps, budget, 2.0 * PILOT_SIDE * PILOT_SIDE);
        }
        if (want < 2.0 * PILOT_SIDE * PILOT_SIDE) want = 2.0 * PILOT_SIDE * PILOT_SIDE;
        if (want > o->max_paths) want = o->max_paths;
        cdl_estimate es = {0.0, 0.0, 0.0, 0}, eu = {0.0, 0.0, 0.0, 0};
        path_round(jb, w, stream, (uint64_t)ps.samples, p, n, cdl_estimate_side_for(want, PILOT_SIDE, 1 << 12),
                   !exact, w->acc, S ? w->sun_acc : NULL, &es, &eu);
        stage = es.samples;
        sky_var = cdl_estimate_variance(&es);
        sun_mean = cdl_estimate_mean(&eu);
        sun_var = cdl_estimate_variance(&eu);
    }
    float *sky = out->sky + row * out->patches;
    double E_reference = E_direct;
    for (size_t k = 0; k < K; ++k) {
        double c = w->direct[k] + (stage > 0.0 ? w->acc[k] / stage : 0.0);
        if (!o->collapse) sky[k] = (float)c;
        E_reference += (stage > 0.0 ? w->acc[k] / stage : 0.0) * reference(o, (int)k);
    }
    if (o->collapse) sky[0] = (float)E_reference;
    out->sky_rel_stderr[row] = E_reference > 0.0 ? sqrt(sky_var) / E_reference : 0.0;
    if (S) {
        float *srow = out->sun + row * S;
        for (size_t s = 0; s < S; ++s) srow[s] = (float)(stage > 0.0 ? w->sun_acc[s] / stage : 0.0);
        out->sun_rel_stderr[row] = sun_mean > 0.0 ? sqrt(sun_var) / sun_mean : 0.0;
    }
}

static cdl_status run_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)err;
    const job *jb = shared;
    worker *w = local;
    for (size_t i = begin; i < end; ++i) point_coefficients(jb, w, i);
    return CDL_OK;
}

/* ---- a grid --------------------------------------------------------------------- */

static uint64_t grid_key(const char *name)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, name, strlen(name));
    return h.value;
}

static void workers_release(worker *w, int threads)
{
    for (int t = 0; w && t < threads; ++t) {
        free(w[t].direct);
        free(w[t].acc);
        free(w[t].sun_acc);
        free(w[t].full);
        free(w[t].t_num);
        free(w[t].t_den);
        free(w[t].pieces);
    }
    free(w);
}

cdl_status cdl_daylight_coefficients_compute(const cdl_daylight_scene *ds, size_t g,
                                             const cdl_daylight_coefficient_options *o,
                                             cdl_daylight_grid_coefficients *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    const cdl_grid *grid = &ds->grids[g];
    size_t N = grid->count, K = (size_t)o->patches->count, S = o->sun_count;
    int threads = o->threads > 0 ? o->threads : 1;
    out->points = N;
    out->patches = o->collapse ? 1 : K;
    out->suns = S;
    /* rank 0 (or one process) a row for every point, another rank its own points' */
    cdl_rank_deal deal = cdl_daylight_coefficients_deal(o->ranks, N);
    size_t rows = cdl_rank_deal_rows(&deal) ? cdl_rank_deal_rows(&deal) : 1;
    out->sky = malloc(rows * out->patches * sizeof *out->sky);
    out->sky_rel_stderr = calloc(rows, sizeof *out->sky_rel_stderr);
    out->exact = calloc(rows, sizeof *out->exact);
    if (o->keep_direct) out->direct = malloc(rows * K * sizeof *out->direct);
    if (S) {
        out->sun = malloc(rows * S * sizeof *out->sun);
        out->sun_rel_stderr = calloc(rows, sizeof *out->sun_rel_stderr);
    }
    worker *w = calloc((size_t)threads, sizeof *w);
    int ok = out->sky && out->sky_rel_stderr && out->exact && (!o->keep_direct || out->direct) &&
             (!S || (out->sun && out->sun_rel_stderr)) && w;
    for (int t = 0; ok && t < threads; ++t) {
        w[t].direct = malloc(K * sizeof(double));
        w[t].acc = malloc(K * sizeof(double));
        w[t].full = malloc(K * sizeof(double));
        w[t].sun_acc = malloc((S ? S : 1) * sizeof(double));
        w[t].t_num = malloc(K * sizeof(double));
        w[t].t_den = malloc(K * sizeof(double));
        ok = w[t].direct && w[t].acc && w[t].full && w[t].sun_acc && w[t].t_num && w[t].t_den;
    }
    /* every rank goes on to the shared task, or none does */
    cdl_status st = cdl_rank_agree(o->ranks, ok ? CDL_OK : cdl_error_out_of_memory(err), err);
    if (st != CDL_OK) {
        workers_release(w, threads);
        cdl_daylight_coefficients_release(out);
        return st;
    }
    job jb = {ds, o, grid, grid_key(ds->scene->grids[g].name), out, &deal};
    char stage[160];
    snprintf(stage, sizeof stage, "grid %s: daylight coefficients", ds->scene->grids[g].name);
    cdl_pool_task task = {.count = N, .chunk = deal.unit, .run = run_points, .shared = &jb, .locals = w,
                          .local_size = sizeof *w, .stage = stage,
                          .outputs = {{out->sky, out->patches * sizeof *out->sky},
                                      {out->sky_rel_stderr, sizeof *out->sky_rel_stderr},
                                      {out->exact, sizeof *out->exact},
                                      {out->direct, K * sizeof *out->direct},
                                      {out->sun, S * sizeof *out->sun},
                                      {out->sun_rel_stderr, sizeof *out->sun_rel_stderr}}};
    cdl_workers workers = {.threads = threads, .progress = &o->progress, .ranks = o->ranks};
    st = cdl_pool_run_dealt(&task, &workers, &deal, err);
    /* the counts, per route reason then the totals, over the ranks */
    uint64_t counts[CDL_ROUTE_COUNT + 4] = {0};
    for (int t = 0; t < threads; ++t) {
        for (int r = 0; r < CDL_ROUTE_COUNT; ++r) counts[r] += w[t].routes.sampled[r];
        counts[CDL_ROUTE_COUNT] += w[t].routes.exact;
        counts[CDL_ROUTE_COUNT + 1] += w[t].routes.through_glass;
        counts[CDL_ROUTE_COUNT + 2] += w[t].paths;
        counts[CDL_ROUTE_COUNT + 3] += w[t].rays;
    }
    workers_release(w, threads);
    if (st == CDL_OK) st = cdl_rank_sum_u64(o->ranks, counts, sizeof counts / sizeof *counts, err);
    for (int r = 0; r < CDL_ROUTE_COUNT; ++r) out->routes.sampled[r] = (size_t)counts[r];
    out->routes.exact = (size_t)counts[CDL_ROUTE_COUNT];
    out->routes.through_glass = (size_t)counts[CDL_ROUTE_COUNT + 1];
    out->paths = counts[CDL_ROUTE_COUNT + 2];
    out->rays = counts[CDL_ROUTE_COUNT + 3];
    if (st != CDL_OK) cdl_daylight_coefficients_release(out);
    return st;
}

/* Points differ a hundredfold in cost (those far from a window take the
 * most paths): units of 2 points keep threads busy and deal every rank
 * points from the whole grid. */
cdl_rank_deal cdl_daylight_coefficients_deal(cdl_rank_group *ranks, size_t points)
{
    return cdl_rank_deal_make(ranks, points, 2);
}

void cdl_daylight_coefficients_release(cdl_daylight_grid_coefficients *c)
{
    if (!c) return;
    free(c->sky);
    free(c->sun);
    free(c->sky_rel_stderr);
    free(c->direct);
    free(c->exact);
    free(c->sun_rel_stderr);
    memset(c, 0, sizeof *c);
}

void cdl_daylight_direct_sun(const cdl_daylight_scene *ds, size_t g, cdl_vec3 to_sun, float *out)
{
    const cdl_grid *grid = &ds->grids[g];
    int has_geometry = ds->geometry && cdl_scene_geometry_piece_count(ds->geometry) > 0;
    for (size_t i = 0; i < grid->count; ++i) {
        double c = cdl_vec3_dot(grid->normals[i], to_sun);
        double T = c > 0.0 && has_geometry
                       ? cdl_scene_geometry_transmission(ds->geometry, grid->points[i], to_sun, INFINITY)
                       : 1.0;
        out[i] = c > 0.0 ? (float)(c * T) : 0.0f;
    }
}
