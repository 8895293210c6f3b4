/* emitter_directional.c - parallel light from infinitely far away (the sun).
 *
 *   parameter     meaning                          unit  default  range
 *   direction     direction the light travels      -     -        non-zero
 *   illuminance   E_n, on a plane normal to beam   lx    -        >= 0
 *
 * On a plane with unit normal n: E = E_n cos(theta), theta the angle between
 * n and the direction towards the light (Lambert's cosine law), 0 from behind.
 * "Flux" is the flux through 1 m^2 of beam section: E_n x 1 m^2.
 */
#include <math.h>

#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"

typedef struct directional_emitter {
    cdl_emitter base;
    cdl_vec3 to_light;  /* unit, against the direction of travel */
    double E_normal;    /* lx */
} directional_emitter;

static const directional_emitter *as_directional(const cdl_emitter *e)
{
    return (const directional_emitter *)e;
}

static cdl_luminous_flux directional_flux(const cdl_emitter *e)
{
    /* Flux through a 1 m^2 section normal to the beam: Phi = E_n A. */
    return cdl_lumens(as_directional(e)->E_normal * 1.0);
}

static int directional_eval_delta(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    (void)p;
    const directional_emitter *d = as_directional(e);
    out->to_light = d->to_light;
    out->distance = INFINITY;
    double c = cdl_vec3_dot(n, d->to_light);
    /* Lambert's cosine law for a collimated beam: E = E_n cos(theta). */
    out->E = cdl_lux(c > 0.0 ? d->E_normal * c : 0.0);
    return out->E.lx > 0.0;
}

static const cdl_emitter_ops directional_ops = {directional_flux, NULL, directional_eval_delta, NULL, NULL, NULL,
                                                NULL, NULL, NULL};

cdl_status cdl_emitter_create_directional(const cdl_directional_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status st;
    cdl_vec3 dir;
    if ((st = cdl_emitter_check_direction(p->direction, "directional emitter: direction", &dir, err)) != CDL_OK)
        return st;
    if ((st = cdl_emitter_check_nonnegative(p->illuminance.lx, "directional emitter: illuminance", "lx", err)) !=
        CDL_OK)
        return st;
    directional_emitter *e = cdl_emitter_alloc(sizeof *e, CDL_EMITTER_DIRECTIONAL, &directional_ops, err);
    if (!e) return CDL_ERR_INTERNAL;
    e->to_light = cdl_vec3_neg(dir);
    e->E_normal = p->illuminance.lx;
    *out = &e->base;
    return CDL_OK;
}
