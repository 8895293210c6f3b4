/* emitter_spread.c - what a goniometric luminaire spread over a shape (its
 * flat opening or luminous solid) shares: the point model it carries. The
 * file's I(w) is the whole luminaire's far-field intensity, so the spread
 * emitter's flux and intensity are the point's exactly; only the light
 * near it, how it arrives from the shape, is its own. */
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"

void *cdl_spread_emitter_create(size_t size, const cdl_emitter_ops *ops, const cdl_goniometric_params *p,
                                cdl_status *status, cdl_error *err)
{
    cdl_emitter *point = NULL;
    *status = cdl_emitter_create_goniometric(p, &point, err);
    if (*status != CDL_OK) return NULL;
    cdl_spread_emitter *s = cdl_emitter_alloc(size, CDL_EMITTER_GONIOMETRIC_OPENING, ops, err);
    if (!s) {
        cdl_emitter_release(point);
        *status = CDL_ERR_INTERNAL;
        return NULL;
    }
    s->point = point;
    return s;
}

cdl_luminous_flux cdl_spread_emitter_flux(const cdl_emitter *e)
{
    return cdl_emitter_flux(((const cdl_spread_emitter *)e)->point);
}

cdl_luminous_intensity cdl_spread_emitter_intensity(const cdl_emitter *e, cdl_vec3 unit_dir)
{
    return cdl_emitter_intensity(((const cdl_spread_emitter *)e)->point, unit_dir);
}

void cdl_spread_emitter_destroy(cdl_emitter *e)
{
    cdl_emitter_release(((cdl_spread_emitter *)e)->point);
}

const cdl_emitter *cdl_emitter_far_field(const cdl_emitter *emitter)
{
    if (!emitter || cdl_emitter_get_kind(emitter) != CDL_EMITTER_GONIOMETRIC_OPENING) return NULL;
    return ((const cdl_spread_emitter *)emitter)->point;
}
