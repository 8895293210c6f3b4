/* integrate_glare.c - the glare integrator: the Unified Glare Rating at every observer (CIE 117:1995).
 *
 * It takes the observers' job after the direct and path integrators have
 * given E at each eye on the plane facing its line of sight from
 * everything but the luminaires' direct light (skies, emitting surfaces,
 * and all interreflected light): the background luminance Lb = E / pi,
 * with E's stated error. Then for every luminaire that can be rated
 * (solve_observers.c), where it lies in the field of view (position
 * index p, CIE 117 Table 4.1), the luminance L of its luminous parts
 * towards the eye, and their solid angle omega less what surfaces hide:
 * exact where the cone from the eye to the sphere holding them is clear
 * of surfaces (the direct solver's region test), else the exact
 * unoccluded solid angle times the visible fraction sampled by shadow rays
 * to points on the parts (glare/glare_parts.h), to the solve's target
 * relative error (at most 2^18 rays per observer and luminaire), with
 * that fraction's standard error. UGR = 8 log10((0.25 / Lb) sum L^2 omega
 * / p^2) and its standard error by glare/ugr.h. Random numbers are keyed
 * by (seed, observer, luminaire, sample): results do not depend on
 * threads.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/rng.h"
#include "radiometry/constants.h"
#include "solver/integrate/integrator.h"
#include "solver/pool.h"
#include "solver/solve_observers.h"

#define GLARE_STREAM 0x676c617265ull /* "glare" */
#define PILOT_SAMPLES 256.0
#define MAX_SAMPLES 262144.0

static const char *const dark = "no light towards the eye";

static int applies_glare(const cdl_solve_state *state, const cdl_grid_job *job)
{
    (void)state;
    return job->observers;
}

/* Is every piece the eye sees in full view: the pyramid from the eye to
 * it (an ellipse's: to its bounding parallelogram) clear of surfaces? */
static int parts_in_view(const cdl_solve_state *state, const cdl_glare_rated *r, const cdl_glare_parts *parts,
                         const double omega[CDL_GLARE_PARTS_MAX], cdl_vec3 eye, cdl_vec3 n)
{
    for (int i = 0; i < parts->count; ++i) {
        if (!(omega[i] > 0.0)) continue;
        const cdl_glare_piece *p = &parts->piece[i];
        cdl_vec3 corner[4];
        int count = 4;
        if (p->kind == CDL_GLARE_PIECE_TRIANGLE) {
            corner[0] = p->c, corner[1] = p->u, corner[2] = p->v;
            count = 3;
        } else {
            corner[0] = cdl_vec3_sub(cdl_vec3_sub(p->c, p->u), p->v);
            corner[1] = cdl_vec3_sub(cdl_vec3_add(p->c, p->u), p->v);
            corner[2] = cdl_vec3_add(cdl_vec3_add(p->c, p->u), p->v);
            corner[3] = cdl_vec3_add(cdl_vec3_sub(p->c, p->u), p->v);
        }
        if (!cdl_direct_polygon_in_view(&state->direct, eye, n, corner, count, r->owner)) return 0;
    }
    return 1;
}

/* The visible fraction f of the parts (seen from eye, solid angles omega,
 * their sum total) and its standard error: exact 1 when the cone to the
 * sphere about them is clear (returns 1), else sampled to relative error
 * `target` (returns 0). */
static int visible_fraction(const cdl_solve_state *state, const cdl_glare_rated *r, const cdl_glare_parts *parts,
                            const double omega[CDL_GLARE_PARTS_MAX], double total, cdl_vec3 eye, uint64_t stream,
                            double *f, double *sigma, uint64_t *rays)
{
    *f = 1.0;
    *sigma = 0.0;
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_sub(r->centre, eye));
    if (parts_in_view(state, r, parts, omega, eye, n) ||
        cdl_direct_sphere_in_view(&state->direct, eye, n, r->centre, r->radius, r->owner))
        return 1;
    cdl_rng_key key = {state->scene->settings.seed, stream};
    double sw = 0.0, swv = 0.0, sww = 0.0, swwv = 0.0, swwvv = 0.0, seen = 0.0, count = 0.0, want = PILOT_SAMPLES;
    while (count < want) {
        double u[4];
        cdl_rng_uniform2(key, (uint64_t)(2.0 * count), u);
        cdl_rng_uniform2(key, (uint64_t)(2.0 * count) + 1, u + 2);
        count += 1.0;
        cdl_vec3 q;
        double w;
        if (!cdl_glare_parts_sample(parts, omega, total, eye, u, &q, &w)) continue;
        cdl_vec3 d = cdl_vec3_sub(q, eye);
        double dist = cdl_vec3_length(d);
        double v = cdl_direct_ray_blocked(&state->direct, eye, n, cdl_vec3_scale(d, 1.0 / dist), dist, r->owner) ? 0.0
                                                                                                               : 1.0;
        ++*rays;
        sw += w, swv += w * v, sww += w * w, swwv += w * w * v, swwvv += w * w * v * v, seen += v;
        if (count >= want && !(sw > 0.0)) {
            /* no point could be drawn on the parts: nothing known of what
             * hides them, said as a visible fraction of 1 +- 1 */
            *sigma = 1.0;
            return 0;
        }
        if (count >= want && want < MAX_SAMPLES) {
            /* the ratio estimator's variance, sum w^2 (v - f)^2 / (sum w)^2;
             * never below a binomial one with half a sample either way, so
             * that samples which all agree are not taken as certain */
            double fr = swv / sw, var = (swwvv - 2.0 * fr * swwv + fr * fr * sww) / (sw * sw);
            double floor_f = (seen + 0.5) / (count + 1.0);
            var = fmax(var, floor_f * (1.0 - floor_f) / count);
            double rel = fr > 0.0 ? sqrt(var) / fr : INFINITY;
            if (rel > state->target) want = fmin(MAX_SAMPLES, ceil(count * (rel / state->target) * (rel / state->target)));
            *f = fr;
            *sigma = sqrt(var);
        }
    }
    return 0;
}

/* One luminaire seen from observer i: a source, or why it is not one. */
static void rate_one(const cdl_solve_state *state, size_t i, size_t k, cdl_observer_result *res, uint64_t *rays,
                     uint64_t *exact)
{
    const cdl_glare_rated *r = &state->rated[k];
    const cdl_observer_spec *o = &state->scene->observers[i];
    cdl_glare_observer obs = {o->eye, o->view};
    if (r->background) return;
    cdl_glare_exclusion *x = &res->excluded[res->excluded_count];
    if (r->reason) {
        *x = (cdl_glare_exclusion){k, r->reason};
        res->excluded_count++;
        return;
    }
    cdl_glare_parts parts;
    double L = 0.0, p = 0.0;
    int closed_form = 1;
    cdl_glare_zone zone;
    if (r->is_area) {
        double R, T, H;
        cdl_glare_observer_coordinates(&obs, r->centre, &R, &T, &H);
        zone = cdl_glare_position_index(R, T, H, &p);
        parts = r->parts;
        L = r->luminance_cd_m2;
    } else {
        cdl_glare_source s;
        cdl_glare_source_evaluate(&r->gonio, &obs, &s);
        zone = s.zone;
        p = s.p;
        L = s.luminance.cd_m2;
        cdl_glare_opening_parts(&r->gonio, o->eye, &parts, &closed_form);
    }
    double omega[CDL_GLARE_PARTS_MAX];
    double total = cdl_glare_parts_solid_angle(&parts, o->eye, omega);
    const char *why = zone != CDL_GLARE_IN_VIEW ? cdl_glare_zone_name(zone) : !(L > 0.0 && total > 0.0) ? dark : NULL;
    if (why) {
        *x = (cdl_glare_exclusion){k, why};
        res->excluded_count++;
        return;
    }
    double f, sigma;
    uint64_t stream = cdl_rng_stream_id(GLARE_STREAM, i, k);
    *exact += (uint64_t)visible_fraction(state, r, &parts, omega, total, o->eye, stream, &f, &sigma, rays);
    cdl_glare_source_result *s = &res->sources[res->source_count++];
    s->luminaire = k;
    s->L_cd_m2 = L;
    s->omega_sr = total * f;
    s->omega_stderr_sr = total * sigma;
    s->omega_exact = closed_form;
    s->p = p;
    cdl_ugr_term t = cdl_ugr_term_make(cdl_nits(L), 0.0, s->omega_sr, s->omega_stderr_sr, p);
    /* a hidden source (omega 0) keeps the error of its sampled solid angle */
    if (!(t.value > 0.0)) t.sigma = L * L * s->omega_stderr_sr / (p * p);
    s->term = t.value;
    s->term_stderr = t.sigma;
}

typedef struct glare_task {
    cdl_solve_state *state;
    const cdl_grid_job *job;
    uint64_t rays;                    /* summed after the run (per-chunk counts added under the pool) */
    uint64_t *chunk_rays;             /* per observer */
    uint64_t *chunk_exact;            /* per observer: sources whose solid angle was exact */
} glare_task;

static cdl_status glare_chunk(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    glare_task *task = shared;
    cdl_solve_state *state = task->state;
    const cdl_grid_job *job = task->job;
    size_t lums = state->scene->luminaire_count;
    for (size_t i = begin; i < end; ++i) {
        cdl_observer_result *res = &state->out->observers[i];
        res->sources = calloc(lums ? lums : 1, sizeof *res->sources);
        res->excluded = calloc(lums ? lums : 1, sizeof *res->excluded);
        if (!res->sources || !res->excluded) return cdl_error_out_of_memory(err);
        /* Lb = E / pi, E from the background alone (direct + interreflected) */
        double E = job->gs->E_direct[i] + job->gs->E_indirect[i];
        double var = job->var_direct[i] + job->var_indirect[i];
        res->background_cd_m2 = E * CDL_INV_PI;
        res->background_stderr_cd_m2 = sqrt(var) * CDL_INV_PI;
        cdl_ugr_sum sum = {0.0, 0.0, 0};
        for (size_t k = 0; k < lums; ++k) {
            rate_one(state, i, k, res, &task->chunk_rays[i], &task->chunk_exact[i]);
            if (res->source_count && res->sources[res->source_count - 1].luminaire == k) {
                const cdl_glare_source_result *s = &res->sources[res->source_count - 1];
                cdl_ugr_sum_add(&sum, (cdl_ugr_term){s->term, s->term_stderr});
            }
        }
        /* keep what was used (the lists were sized for every luminaire) */
        if (res->source_count == 0) free(res->sources), res->sources = NULL;
        if (res->excluded_count == 0) free(res->excluded), res->excluded = NULL;
        cdl_glare_source_result *s = res->sources ? realloc(res->sources, res->source_count * sizeof *s) : NULL;
        cdl_glare_exclusion *x = res->excluded ? realloc(res->excluded, res->excluded_count * sizeof *x) : NULL;
        if (s) res->sources = s;
        if (x) res->excluded = x;
        cdl_ugr u = {0, 0.0, 0.0};
        if (res->background_cd_m2 > 0.0 &&
            cdl_ugr_evaluate(&sum, cdl_nits(res->background_cd_m2), res->background_stderr_cd_m2, &u, NULL) != CDL_OK)
            u.defined = 0;
        res->defined = u.defined;
        res->ugr = u.value;
        res->ugr_stderr = u.sigma;
    }
    return CDL_OK;
}

static cdl_status run_glare(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    size_t n = scene->observer_count;
    cdl_solution *out = state->out;
    out->observers = calloc(n ? n : 1, sizeof *out->observers);
    glare_task task = {state, job, 0, calloc(n ? n : 1, sizeof(uint64_t)), calloc(n ? n : 1, sizeof(uint64_t))};
    if (!out->observers || !task.chunk_rays || !task.chunk_exact) {
        free(task.chunk_rays);
        free(task.chunk_exact);
        return cdl_error_out_of_memory(err);
    }
    out->observer_count = n;
    char stage[160];
    cdl_grid_job_stage(job, "glare", stage, sizeof stage);
    cdl_pool_task pt = {.count = n, .chunk = 1, .run = glare_chunk, .shared = &task, .stage = stage};
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_pool_run(&pt, state->threads, &state->options.progress, err);
    out->compute_seconds += cdl_pool_now_seconds() - t0;
    for (size_t i = 0; i < n; ++i) {
        state->glare_stats.rays += task.chunk_rays[i];
        state->glare_exact += task.chunk_exact[i];
        state->glare_sampled += out->observers[i].source_count - task.chunk_exact[i];
    }
    free(task.chunk_rays);
    free(task.chunk_exact);
    if (st != CDL_OK) return st;
    /* a dark background leaves an observer without a rating: say so */
    for (size_t i = 0; i < n; ++i) {
        const cdl_observer_result *res = &out->observers[i];
        if (res->background_cd_m2 > 0.0 || res->source_count == 0) continue;
        st = cdl_solution_add_warning(out, err,
                                      "%s (%s): the background is dark (nothing reflects, no sky): no UGR, which "
                                      "divides by the background luminance",
                                      scene->observers[i].json_path, scene->observers[i].name);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

const cdl_integrator cdl_integrator_glare = {"glare", applies_glare, run_glare};
