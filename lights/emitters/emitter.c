/* emitter.c - the one emitter interface: dispatch to the kind, shared checks. */
#include "lights/emitters/emitter.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/conversions.h"

void *cdl_emitter_alloc(size_t size, cdl_emitter_kind kind, const cdl_emitter_ops *ops, cdl_error *err)
{
    cdl_emitter *e = calloc(1, size);
    if (!e) {
        cdl_error_out_of_memory(err);
        return NULL;
    }
    e->kind = kind;
    e->ops = ops;
    return e;
}

cdl_status cdl_emitter_check_position(cdl_vec3 v, const char *what, cdl_error *err)
{
    if (!cdl_vec3_is_finite(v))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected three finite coordinates in metres, found [%g, %g, %g]",
                             what, v.x, v.y, v.z);
    return CDL_OK;
}

cdl_status cdl_emitter_check_direction(cdl_vec3 v, const char *what, cdl_vec3 *unit, cdl_error *err)
{
    if (!cdl_vec3_is_finite(v) || cdl_vec3_length(v) == 0.0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a finite non-zero vector, found [%g, %g, %g]", what,
                             v.x, v.y, v.z);
    *unit = cdl_vec3_normalize(v);
    return CDL_OK;
}

cdl_status cdl_emitter_check_nonnegative(double x, const char *what, const char *unit, cdl_error *err)
{
    if (!(isfinite(x) && x >= 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a finite number >= 0 %s, found %g", what, unit, x);
    return CDL_OK;
}

cdl_status cdl_emitter_check_range(double x, double lo, double hi, const char *what, const char *unit,
                                   cdl_error *err)
{
    if (!(isfinite(x) && x >= lo && x <= hi))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a number in [%g, %g] %s, found %g", what, lo, hi, unit,
                             x);
    return CDL_OK;
}

int cdl_emitter_eval_positional(const cdl_emitter *e, cdl_vec3 position, cdl_emitter_intensity_fn intensity_towards,
                                cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    cdl_vec3 w = cdl_vec3_sub(position, p);
    double d2 = cdl_vec3_dot(w, w);
    out->E = cdl_lux(0.0);
    if (d2 > 1e-290 && d2 < 1e290) {
        /* The common case, one square root and one division: with
         * k = 1 / d, to_light = w k and E = I cos k^2 (a few ulps from
         * I cos / d / d). */
        double d = sqrt(d2), k = 1.0 / d;
        out->to_light = cdl_vec3_scale(w, k);
        out->distance = d;
        double cos_theta = cdl_vec3_dot(n, out->to_light);
        if (!(cos_theta > 0.0)) return 0;
        cdl_luminous_intensity I = intensity_towards(e, cdl_vec3_neg(out->to_light));
        /* Inverse-square and cosine law E = I cos(theta) / d^2 (Lambert,
         * Photometria 1760). */
        out->E = cdl_lux(I.cd * cos_theta * k * k);
        return out->E.lx > 0.0;
    }
    /* Distances whose square leaves the double range: the scaled length and
     * the overflow-safe form of conversions.c. */
    double d = cdl_vec3_length(w);
    out->to_light = d > 0.0 ? cdl_vec3_scale(w, 1.0 / d) : cdl_vec3_make(0.0, 0.0, 0.0);
    out->distance = d;
    if (!(d > 0.0) || !isfinite(d)) return 0;
    double cos_theta = cdl_vec3_dot(n, out->to_light);
    if (!(cos_theta > 0.0)) return 0;
    cdl_luminous_intensity I = intensity_towards(e, cdl_vec3_neg(out->to_light));
    out->E = cdl_illuminance_from_intensity(I, cos_theta, cdl_metres(d));
    return out->E.lx > 0.0;
}

/* ---- public dispatch ------------------------------------------------------ */

void cdl_emitter_release(cdl_emitter *emitter)
{
    if (!emitter) return;
    if (emitter->ops->destroy) emitter->ops->destroy(emitter);
    free(emitter);
}

cdl_emitter_kind cdl_emitter_get_kind(const cdl_emitter *emitter)
{
    return emitter->kind;
}

int cdl_emitter_is_delta(const cdl_emitter *emitter)
{
    return emitter->ops->eval_delta != NULL;
}

void cdl_emitter_eval_delta_many(const cdl_emitter *emitter, const cdl_vec3 *p, const cdl_vec3 *n, size_t count,
                                 cdl_delta_light *out)
{
    if (emitter->ops->eval_delta_many) {
        emitter->ops->eval_delta_many(emitter, p, n, count, out);
        return;
    }
    for (size_t i = 0; i < count; ++i) {
        if (!cdl_emitter_eval_delta(emitter, p[i], n[i], &out[i])) out[i].E = cdl_lux(0.0);
    }
}

int cdl_emitter_emission_cone(const cdl_emitter *emitter, cdl_vec3 *position, cdl_vec3 *axis, double *cos_min)
{
    return emitter->ops->cone ? emitter->ops->cone(emitter, position, axis, cos_min) : 0;
}

cdl_luminous_flux cdl_emitter_flux(const cdl_emitter *emitter)
{
    return emitter->ops->flux(emitter);
}

cdl_luminous_intensity cdl_emitter_intensity(const cdl_emitter *emitter, cdl_vec3 dir)
{
    double len = cdl_vec3_length(dir);
    if (!(len > 0.0) || !isfinite(len) || !emitter->ops->intensity) return cdl_candelas(0.0);
    return emitter->ops->intensity(emitter, cdl_vec3_scale(dir, 1.0 / len));
}

int cdl_emitter_eval_delta(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    if (!emitter->ops->eval_delta) {
        out->to_light = cdl_vec3_make(0.0, 0.0, 0.0);
        out->distance = 0.0;
        out->E = cdl_lux(0.0);
        return 0;
    }
    return emitter->ops->eval_delta(emitter, p, n, out);
}

int cdl_emitter_has_exact_illuminance(const cdl_emitter *emitter)
{
    /* Every kind has one (image environments: the exact pixel sum). */
    return emitter->ops->eval_delta != NULL || emitter->ops->exact != NULL;
}

cdl_status cdl_emitter_exact_illuminance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E,
                                         cdl_error *err)
{
    if (emitter->ops->eval_delta) {
        cdl_delta_light d;
        emitter->ops->eval_delta(emitter, p, n, &d);
        *E = d.E;
        return CDL_OK;
    }
    if (!emitter->ops->exact || !emitter->ops->exact(emitter, p, n, E)) {
        *E = cdl_lux(0.0);
        return cdl_error_set(err, CDL_ERR_USAGE, "exact illuminance: this emitter has no closed form; sample it instead");
    }
    return CDL_OK;
}

int cdl_emitter_sample(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, double u1, double u2,
                       cdl_light_sample *out)
{
    out->to_light = cdl_vec3_make(0.0, 0.0, 0.0);
    out->distance = 0.0;
    out->L = cdl_nits(0.0);
    out->pdf = 0.0;
    if (!emitter->ops->sample) return 0;
    return emitter->ops->sample(emitter, p, n, u1, u2, out);
}

cdl_luminance cdl_emitter_radiance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_vec3 to_light,
                                   double *pdf)
{
    double len = cdl_vec3_length(to_light);
    if (pdf) *pdf = 0.0;
    if (!emitter->ops->radiance || !(len > 0.0) || !isfinite(len)) return cdl_nits(0.0);
    double local_pdf = 0.0;
    cdl_luminance L = emitter->ops->radiance(emitter, p, n, cdl_vec3_scale(to_light, 1.0 / len), &local_pdf);
    if (pdf) *pdf = local_pdf;
    return L;
}
