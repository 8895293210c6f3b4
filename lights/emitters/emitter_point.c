/* emitter_point.c - the isotropic point source.
 *
 *   parameter   meaning                         unit   default   range
 *   position    where the source is             m      -         finite
 *   intensity   the same in every direction     cd     -         >= 0
 *
 * Closed-form flux Phi = 4 pi I. Illuminance E = I cos(theta) / d^2, exact,
 * one shadow ray (the caller's).
 */
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/conversions.h"

typedef struct point_emitter {
    cdl_emitter base;
    cdl_vec3 position;
    cdl_luminous_intensity intensity;
} point_emitter;

static const point_emitter *as_point(const cdl_emitter *e)
{
    return (const point_emitter *)e;
}

static cdl_luminous_flux point_flux(const cdl_emitter *e)
{
    /* Isotropic source: Phi = 4 pi I (the sphere subtends 4 pi sr). */
    return cdl_isotropic_flux_from_intensity(as_point(e)->intensity);
}

static cdl_luminous_intensity point_intensity(const cdl_emitter *e, cdl_vec3 unit_dir)
{
    (void)unit_dir;
    return as_point(e)->intensity;
}

static int point_eval_delta(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    return cdl_emitter_eval_positional(e, as_point(e)->position, point_intensity, p, n, out);
}

static const cdl_emitter_ops point_ops = {point_flux, point_intensity, point_eval_delta, NULL, NULL, NULL, NULL, NULL, NULL};

cdl_status cdl_emitter_create_point(const cdl_point_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status s;
    if ((s = cdl_emitter_check_position(p->position, "point emitter: position", err)) != CDL_OK) return s;
    if ((s = cdl_emitter_check_nonnegative(p->intensity.cd, "point emitter: intensity", "cd", err)) != CDL_OK)
        return s;
    point_emitter *e = cdl_emitter_alloc(sizeof *e, CDL_EMITTER_POINT, &point_ops, err);
    if (!e) return CDL_ERR_INTERNAL;
    e->position = p->position;
    e->intensity = p->intensity;
    *out = &e->base;
    return CDL_OK;
}
