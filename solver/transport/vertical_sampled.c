/* vertical_sampled.c - cylindrical and semicylindrical illuminance from extended emitters, skies and interreflection.
 *
 * The exact per-light terms of direct_vertical.c cover delta lights. The
 * rest of the light reaching a point is a radiance field L(w): extended
 * emitters and skies seen along w, and the light surfaces reflect towards
 * the point. Cylindrical and semicylindrical illuminance are its moments
 * (EN 12464-1:2021, 3.2.6; CIE 136:2000), with theta the angle of w from
 * the vertical and alpha the horizontal angle between w and the
 * semicylinder's facing direction f:
 *     E_z  = (1 / pi) int_S2 L(w) sin(theta) dw
 *     E_sz = (1 / pi) int_S2 L(w) sin(theta) (1 + cos alpha) dw
 * (each facet of the cylinder, normal m, receives L max(0, w.m) dw; the
 * mean of max(0, w.m) over the full circle of m is sin(theta) / pi, over
 * the half facing f sin(theta) (1 + cos alpha) / pi). Directions are drawn
 * with pdf sin(theta) / pi^2 (int_S2 sin(theta) dw = 2 pi int_0^pi
 * sin^2 = pi^2), so one sample of E_z is pi L(w) and of E_sz pi L(w) (1 +
 * cos alpha); theta by inverting its distribution F(theta) = (theta -
 * sin theta cos theta) / pi, phi uniform (from the semicylinder's facing
 * direction); stratified in (F, phi).
 *
 * L(w): a sky's luminance when nothing is hit along w (Embree); and where
 * interreflection is modelled, one path from the point along w
 * (transport/path.h) estimates pi times the reflected radiance of the
 * first surface hit. Area emitters and emitting surfaces, often small,
 * are sampled on themselves instead (their own samplers, emitter.h),
 * each sample w with its solid-angle pdf adding L (sin theta / pi) / pdf
 * to E_z and L (sin theta + w_h . f) / (pi pdf) to E_sz when unshadowed;
 * the samplers cover one half-space of directions at a time, so each
 * sample is drawn twice, for the half-spaces either side of the plane
 * across the direction to the emitter, and the two added (each direction
 * lies in exactly one). Each point is sampled as the path
 * tracer samples E: a pilot of 8 x 8 strata decides how many samples the
 * point needs for the target on E_z and on E_sz (the larger), one stage of
 * that many is reported with its standard error (radiometry/estimate.h).
 */
#include "solver/transport/vertical_sampled.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/bounds.h"
#include "radiometry/constants.h"
#include "radiometry/estimate.h"
#include "base/rng.h"

#define PILOT_SIDE 8

/* theta in [0, pi] with F(theta) = (theta - sin theta cos theta) / pi = u:
 * Newton's method on a monotone function, safeguarded by bisection. */
static double theta_from_uniform(double u)
{
    double lo = 0.0, hi = CDL_PI, t = CDL_PI * u;
    for (int k = 0; k < 60; ++k) {
        double f = t - sin(t) * cos(t) - CDL_PI * u;
        if (f > 0.0) hi = t;
        else lo = t;
        double d = 2.0 * sin(t) * sin(t);
        double next = d > 1e-12 ? t - f / d : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (fabs(next - t) < 1e-15) break;
        t = next;
    }
    return t;
}

/* The point sampled: where it is, the way its semicylinder faces, and
 * when it lies on a surface (hidden = 1) the normal of that surface's
 * plane, behind which it sees nothing. */
typedef struct receiver {
    cdl_vec3 p, facing, n;
    int hidden;
} receiver;

/* Is w hidden by the surface the point lies on? */
static int behind_surface(const receiver *r, cdl_vec3 w)
{
    return r->hidden && !(cdl_vec3_dot(w, r->n) > 0.0);
}

typedef struct sample_value {
    double L;          /* radiance along w, cd/m^2 (emitted plus one path's reflected estimate) */
    double potential;  /* what it could have been with nothing in the way (for dark points) */
} sample_value;

static sample_value radiance_along(const cdl_vertical_context *ctx, cdl_rng_key key, const receiver *r, cdl_vec3 w,
                                   cdl_path_stats *stats)
{
    sample_value s = {0.0, 0.0};
    /* Certainly dark, not a direction that could have missed light. */
    if (behind_surface(r, w)) return s;
    cdl_vec3 p = r->p;
    const cdl_direct_context *d = ctx->path.direct;
    cdl_ray_hit hit;
    int hit_any = ctx->path.geometry && cdl_scene_geometry_intersect(ctx->path.geometry, p, w, w, INFINITY, &hit);
    if (ctx->path.geometry) stats->rays++;
    /* the sky through whatever panes of glass are in the way (none: 1 when nothing is) */
    double sky_T = !hit_any ? 1.0 : cdl_scene_geometry_has_glass(ctx->path.geometry)
                                        ? cdl_scene_geometry_transmission(ctx->path.geometry, p, w, INFINITY)
                                        : 0.0;
    for (size_t l = 0; l < d->light_count; ++l) {
        const cdl_scene_light *light = &d->lights[l];
        if (!light->is_environment || light->sealed_by) continue; /* area emitters: emitter_samples */
        double L = cdl_emitter_radiance(light->emitter, p, w, w, NULL).cd_m2;
        if (!(L > 0.0)) continue;
        s.potential += CDL_PI * L;
        s.L += L * sky_T;
    }
    if (ctx->indirect && hit_any) {
        cdl_path_result r;
        cdl_transport_path(&ctx->path, key, p, w, w, &r, stats);
        /* one sample of pi x the reflected radiance of the surface hit */
        s.L += r.value / CDL_PI;
        s.potential += r.potential;
    }
    return s;
}

/* The area emitters' part of one sample (u in [0, 1)^2): E_z and E_sz
 * contributions, and what they would be unshadowed (*potential). */
static void emitter_samples(const cdl_vertical_context *ctx, const receiver *r, const double u[2], double *fz,
                            double *fsz, double *potential, cdl_path_stats *stats)
{
    cdl_vec3 p = r->p, facing = r->facing;
    const cdl_direct_context *d = ctx->path.direct;
    for (size_t l = 0; l < d->light_count; ++l) {
        const cdl_scene_light *light = &d->lights[l];
        if (light->is_environment || cdl_emitter_is_delta(light->emitter) || !cdl_scene_light_applies(light, p))
            continue;
        /* towards the emitter (the sun's disk: its axis; it has no bounds) */
        cdl_vec3 a = light->is_sun_disk ? light->sun_dir : cdl_vec3_sub(cdl_bounds3_centre(light->bounds), p);
        double len = cdl_vec3_length(a);
        a = len > 0.0 ? cdl_vec3_scale(a, 1.0 / len) : cdl_vec3_make(0, 0, 1);
        for (int h = 0; h < 2; ++h) {
            cdl_vec3 n = h ? cdl_vec3_neg(a) : a;
            cdl_light_sample smp;
            if (!cdl_emitter_sample(light->emitter, p, n, u[0], u[1], &smp) || !(smp.pdf > 0.0)) continue;
            if (!(cdl_vec3_dot(n, smp.to_light) > 0.0)) continue;
            cdl_vec3 w = smp.to_light;
            if (behind_surface(r, w)) continue;
            double st = sqrt(w.x * w.x + w.y * w.y);
            double gz = smp.L.cd_m2 * st / (CDL_PI * smp.pdf);
            double gsz = smp.L.cd_m2 * (st + w.x * facing.x + w.y * facing.y) / (CDL_PI * smp.pdf);
            *potential += gz;
            double T = 1.0; /* through glass, a fraction */
            if (ctx->path.geometry) {
                stats->rays++;
                T = cdl_scene_geometry_transmission_except(ctx->path.geometry, p, w, smp.distance,
                                                           cdl_scene_light_own_piece(light));
                if (!(T > 0.0)) continue;
            }
            *fz += gz * T;
            *fsz += gsz * T;
        }
    }
}

/* One round of k x k strata, two samples each. */
static void vertical_round(const cdl_vertical_context *ctx, uint64_t stream, uint64_t base, const receiver *r, int k,
                           cdl_estimate *ez, cdl_estimate *esz, double *potential_sum, cdl_path_stats *stats)
{
    cdl_round rz = {0.0, 0.0, 0.0, 0}, rsz = {0.0, 0.0, 0.0, 0};
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double fz[2], fsz[2];
            for (int s = 0; s < 2; ++s) {
                uint64_t index = base + (uint64_t)(2 * (j * k + i) + s);
                cdl_rng_key key = {ctx->path.seed, cdl_rng_stream_id(stream, index, 0x63796c /* "cyl" */)};
                double u[2];
                cdl_rng_uniform2(key, 0, u);
                double theta = theta_from_uniform((i + u[0]) / k), phi = 2.0 * CDL_PI * (j + u[1]) / k;
                double st = sin(theta);
                /* phi from the facing direction f, then f's perpendicular */
                double cf = cos(phi), sf = sin(phi);
                cdl_vec3 w = cdl_vec3_make(st * (cf * r->facing.x - sf * r->facing.y),
                                           st * (cf * r->facing.y + sf * r->facing.x), cos(theta));
                sample_value v = radiance_along(ctx, key, r, w, stats);
                /* pi L, and pi L (1 + cos alpha) with sin(theta) cos(alpha) = w_h . f */
                double cos_alpha = st > 0.0 ? (w.x * r->facing.x + w.y * r->facing.y) / st : 0.0;
                fz[s] = CDL_PI * v.L;
                fsz[s] = CDL_PI * v.L * (1.0 + cos_alpha);
                *potential_sum += v.potential;
                /* the area emitters, on the same stratum of their own samplers */
                double ue[2];
                cdl_rng_uniform2(key, 1, ue);
                double ue_s[2] = {(i + ue[0]) / k, (j + ue[1]) / k};
                emitter_samples(ctx, r, ue_s, &fz[s], &fsz[s], potential_sum, stats);
            }
            cdl_round_add_pair(&rz, fz[0], fz[1]);
            cdl_round_add_pair(&rsz, fsz[0], fsz[1]);
        }
    cdl_estimate_add_round(ez, &rz);
    cdl_estimate_add_round(esz, &rsz);
}

/* Strata per side of a stage of about `samples` samples: a multiple of 4,
 * so that the horizon (F = 1/2) and the quarter turns from the facing
 * direction (phi = +-pi/2, pi) are strata edges. A point on a floor or a
 * wall, or under an upper-hemisphere sky, then has no stratum split between
 * light and the dark behind its surface: those halves cost no error. */
static int stage_side(double samples)
{
    int k = cdl_estimate_side_for(samples, PILOT_SIDE, 1 << 12);
    return (k + 3) & ~3;
}

/* The variance of a mean, at least what samples that all gave nothing
 * could have missed (estimate.h). */
static double honest_variance(const cdl_estimate *e, double potential)
{
    double v = cdl_estimate_variance(e);
    if (e->nonzero == 0) v = fmax(v, cdl_estimate_unseen_variance(e->samples, potential));
    return v;
}

void cdl_vertical_sampled_point(const cdl_vertical_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                                cdl_vec3 facing, int on_surface, double Ez_exact, cdl_vertical_estimate *out,
                                cdl_path_stats *stats)
{
    receiver r = {p, facing, n, on_surface};
    cdl_estimate pz = {0.0, 0.0, 0.0, 0}, psz = {0.0, 0.0, 0.0, 0};
    double potential_sum = 0.0;
    vertical_round(ctx, stream, 0, &r, PILOT_SIDE, &pz, &psz, &potential_sum, stats);
    double potential = potential_sum / pz.samples;
    /* E_z and E_sz = exact + sampled, each held to the target (the stage
     * is as large as the needier of the two asks); a dark point to a
     * thousandth of what its samples could carry. E_z's exact part stands
     * in for E_sz's, which lies between 0 and twice it. */
    double want = 2.0 * PILOT_SIDE * PILOT_SIDE;
    for (int k = 0; k < 2; ++k) {
        const cdl_estimate *pilot = k ? &psz : &pz;
        double reach = k ? 2.0 * potential : potential;
        double R = fmax(Ez_exact + cdl_estimate_mean(pilot), 1e-3 * reach);
        double budget = ctx->target * ctx->target * R * R;
        if (!(budget > 0.0)) continue;
        if (pilot->nonzero == 0) {
            /* nothing seen: enough that what was missed fits the budget (estimate.h) */
            want = fmax(want, cdl_estimate_plan_unseen(reach, budget, want));
        } else {
            cdl_estimate planning = *pilot;
            planning.var_num = honest_variance(pilot, reach) * pilot->samples * pilot->samples;
            want = fmax(want, cdl_estimate_plan(&planning, budget, want));
        }
    }
    if (want > ctx->max_samples) want = ctx->max_samples;
    /* The reported stage, its size fixed by the pilot alone. */
    cdl_estimate ez = {0.0, 0.0, 0.0, 0}, esz = {0.0, 0.0, 0.0, 0};
    double stage_potential = 0.0;
    vertical_round(ctx, stream, (uint64_t)pz.samples, &r, stage_side(want), &ez, &esz, &stage_potential, stats);
    out->Ez = cdl_estimate_mean(&ez);
    out->Esz = cdl_estimate_mean(&esz);
    out->Ez_var = honest_variance(&ez, potential);
    out->Esz_var = honest_variance(&esz, 2.0 * potential);
    out->samples = (uint64_t)(pz.samples + ez.samples);
}

/* ---- a grid on the worker pool ------------------------------------------------ */

typedef struct grid_job {
    const cdl_vertical_context *ctx;
    const cdl_grid *grid;
    size_t grid_index;
    double *Ez, *Esz, *Ez_stderr, *Esz_stderr;
    const unsigned char *on_surface;
} grid_job;

static cdl_status sample_points(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)err;
    const grid_job *job = shared;
    cdl_path_stats *stats = local;
    for (size_t i = begin; i < end; ++i) {
        uint64_t stream = cdl_rng_stream_id((uint64_t)job->grid_index, (uint64_t)i, 0x7665727469 /* "verti" */);
        cdl_vec3 facing = cdl_vec3_make(1, 0, 0);
        cdl_direct_facing_direction(job->grid->normals[i], &facing);
        cdl_vertical_estimate e;
        cdl_vertical_sampled_point(job->ctx, stream, job->grid->points[i], job->grid->normals[i], facing,
                                   job->on_surface && job->on_surface[i], job->Ez ? job->Ez[i] : 0.0, &e, stats);
        if (job->Ez) {
            job->Ez[i] += e.Ez;
            job->Ez_stderr[i] = sqrt(e.Ez_var);
        }
        if (job->Esz) {
            job->Esz[i] += e.Esz;
            job->Esz_stderr[i] = sqrt(e.Esz_var);
        }
    }
    return CDL_OK;
}

cdl_status cdl_vertical_sampled_grid(const cdl_vertical_context *ctx, const cdl_grid *grid, size_t grid_index,
                                     const unsigned char *on_surface, double *Ez, double *Esz, double *Ez_stderr,
                                     double *Esz_stderr, const cdl_workers *workers, const char *stage,
                                     cdl_path_stats *stats, cdl_error *err)
{
    int threads = workers->threads < 1 ? 1 : workers->threads;
    cdl_path_stats *locals = calloc((size_t)threads, sizeof *locals);
    if (!locals) return cdl_error_out_of_memory(err);
    grid_job job = {ctx, grid, grid_index, Ez, Esz, Ez_stderr, Esz_stderr, on_surface};
    cdl_pool_task task = {.count = grid->count,
                          .chunk = 2,
                          .run = sample_points,
                          .shared = &job,
                          .locals = locals,
                          .local_size = sizeof *locals,
                          .stage = stage,
                          .outputs = {{Ez, sizeof *Ez},
                                      {Esz, sizeof *Esz},
                                      {Ez_stderr, sizeof *Ez_stderr},
                                      {Esz_stderr, sizeof *Esz_stderr}}};
    cdl_status st = cdl_pool_run_shared(&task, workers, err);
    cdl_path_stats sum = {0};
    for (int t = 0; t < threads; ++t) cdl_path_stats_add(&sum, &locals[t]);
    if (st == CDL_OK) st = cdl_path_stats_share(workers->ranks, &sum, err);
    if (st == CDL_OK) cdl_path_stats_add(stats, &sum);
    free(locals);
    return st;
}
