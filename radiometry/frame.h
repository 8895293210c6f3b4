/* frame.h - orthonormal frames (s, t, n), right-handed: s x t = n.
 * A frame maps local coordinates (z along n) to world and back. */
#ifndef CANDELA_RADIOMETRY_FRAME_H
#define CANDELA_RADIOMETRY_FRAME_H

#include "radiometry/vec3.h"

typedef struct cdl_frame { cdl_vec3 s, t, n; } cdl_frame;

/* A frame whose n is the unit vector `n`, with s and t chosen continuously
 * except across n.z = 0 (Duff et al., "Building an Orthonormal Basis,
 * Revisited", JCGT 6(1), 2017, listing 3). */
static inline cdl_frame cdl_frame_from_normal(cdl_vec3 n)
{
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    cdl_frame f;
    f.s = cdl_vec3_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = cdl_vec3_make(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

/* world = x s + y t + z n */
static inline cdl_vec3 cdl_frame_to_world(const cdl_frame *f, cdl_vec3 local)
{
    return cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(f->s, local.x), cdl_vec3_scale(f->t, local.y)),
                        cdl_vec3_scale(f->n, local.z));
}

static inline cdl_vec3 cdl_frame_to_local(const cdl_frame *f, cdl_vec3 world)
{
    return cdl_vec3_make(cdl_vec3_dot(world, f->s), cdl_vec3_dot(world, f->t), cdl_vec3_dot(world, f->n));
}

#endif
