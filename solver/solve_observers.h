/* solve_observers.h - glare: the observers planned as a job of the
 * integrators' table, and how each luminaire is rated.
 *
 * Not public.
 */
#ifndef CANDELA_SOLVER_SOLVE_OBSERVERS_H
#define CANDELA_SOLVER_SOLVE_OBSERVERS_H

#include <stdint.h>

#include "base/error.h"
#include "glare/glare_source.h"
#include "solver/integrate/integrator.h"

/* How one luminaire of the scene takes part in glare. */
typedef struct cdl_glare_rated {
    const char *reason;            /* NULL: it is rated; else why not (static text) */
    int background;                /* 1: a sky, part of the background, neither rated nor excluded */
    int is_area;                   /* 1: an area luminaire (parts, luminance), 0: goniometric (gonio) */
    cdl_glare_luminaire gonio;     /* goniometric: its photometry, placement and every factor on its intensity */
    cdl_glare_parts parts;         /* area: its shape as one-sided pieces */
    double luminance_cd_m2;        /* area: what its front emits */
    cdl_vec3 centre;               /* where its position index is taken */
    double radius;                 /* a sphere about centre holding its luminous parts */
    uint32_t owner;                /* area: the geometry piece of its surface; goniometric: its body's;
                                    * UINT32_MAX for none (the eye sees past neither) */
} cdl_glare_rated;

/* Plan the observers (after the grids; nothing to do without any): which
 * luminaires can be rated - a scene with observers and none is refused
 * (CDL_ERR_INPUT, naming each luminaire and why) -, every eye checked (in
 * open air: not on a surface, not inside a closed box or sphere), the
 * job's points (the eyes, the lines of sight as normals), its result arrays,
 * its plan (interreflection by paths) and its background light (every
 * light but the luminaires: skies and emitting surfaces). */
cdl_status cdl_solve_plan_observers(cdl_solve_state *state, cdl_error *err);

/* Free what the state holds for the observers. */
void cdl_solve_observers_release(cdl_solve_state *state);

#endif
