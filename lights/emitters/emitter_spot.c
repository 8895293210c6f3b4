/* emitter_spot.c - the spot: a point source with a rotationally symmetric beam.
 *
 *   parameter        meaning                                unit  default  range
 *   position         where the source is                    m     -        finite
 *   direction        beam axis                              -     -        non-zero
 *   intensity        I0, on the axis                        cd    -        >= 0
 *   use_exponent     0: smoothstep profile, 1: cos^n        -     0        0 or 1
 *   half_angle       smoothstep: no light beyond            deg   -        (0, 180]
 *   falloff_start    smoothstep: full intensity within      deg   -        [0, half_angle]
 *   exponent         cos^n: n                               -     -        >= 0
 *
 * Smoothstep profile (DESIGN.md): with alpha the angle to the axis and
 * t = (cos alpha - cos h) / (cos f - cos h), I = I0 (3 t^2 - 2 t^3) for
 * f < alpha < h, I0 inside f, 0 beyond h; f = h is a hard edge.
 * Cosine-power profile: I = I0 cos^n(alpha) in front, 0 behind.
 */
#include <math.h>

#include "base/error_report.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"

typedef struct spot_emitter {
    cdl_emitter base;
    cdl_vec3 position;
    cdl_vec3 axis;               /* unit */
    double I0;                   /* cd */
    int use_exponent;
    double half_angle, falloff;  /* radians */
    double smooth_span;          /* (cos f - cos h) / 2 = sin((h+f)/2) sin((h-f)/2) */
    double exponent;
} spot_emitter;

static const spot_emitter *as_spot(const cdl_emitter *e)
{
    return (const spot_emitter *)e;
}

/* Fraction of I0 at angle alpha (radians) from the axis, alpha in [0, pi]. */
static double smoothstep_profile(const spot_emitter *s, double alpha)
{
    if (alpha <= s->falloff) return 1.0;
    if (alpha >= s->half_angle) return 0.0;
    /* cos a - cos b = 2 sin((b + a)/2) sin((b - a)/2): differences of
     * cosines as products of sines keep full precision for narrow beams. */
    double t = sin(0.5 * (s->half_angle + alpha)) * sin(0.5 * (s->half_angle - alpha)) / s->smooth_span;
    if (t >= 1.0) return 1.0;
    /* Hermite smoothstep 3t^2 - 2t^3 (DESIGN.md, as in pbrt-v4 SpotLight::I). */
    return t * t * (3.0 - 2.0 * t);
}

static cdl_luminous_intensity spot_intensity(const cdl_emitter *e, cdl_vec3 unit_dir)
{
    const spot_emitter *s = as_spot(e);
    double c = cdl_vec3_dot(unit_dir, s->axis);
    if (s->use_exponent) {
        if (!(c > 0.0)) return cdl_candelas(0.0);
        return cdl_candelas(s->I0 * (s->exponent == 0.0 ? 1.0 : pow(c, s->exponent)));
    }
    /* The angle from atan2(|d x a|, d.a) is accurate at every angle, unlike acos. */
    double alpha = atan2(cdl_vec3_length(cdl_vec3_cross(unit_dir, s->axis)), c);
    return cdl_candelas(s->I0 * smoothstep_profile(s, alpha));
}

static cdl_luminous_flux spot_flux(const cdl_emitter *e)
{
    const spot_emitter *s = as_spot(e);
    if (s->use_exponent) {
        /* Phi = 2 pi I0 int_0^1 mu^n dmu = 2 pi I0 / (n + 1). */
        return cdl_lumens(CDL_TWO_PI * s->I0 / (s->exponent + 1.0));
    }
    /* Phi = 2 pi I0 int_{cos h}^1 profile(mu) dmu. Inside f the profile is 1:
     * 1 - cos f = 2 sin^2(f/2). Between, t is linear in mu = cos alpha, so
     * the part is (cos f - cos h) int_0^1 (3t^2 - 2t^3) dt = (cos f - cos h)/2
     * (as pbrt-v4's SpotLight::Phi). */
    double sf = sin(0.5 * s->falloff);
    return cdl_lumens(CDL_TWO_PI * s->I0 * (2.0 * sf * sf + s->smooth_span));
}

static int spot_eval_delta(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    return cdl_emitter_eval_positional(e, as_spot(e)->position, spot_intensity, p, n, out);
}

/* No light where cos(alpha) <= cos(half angle) (smoothstep profile) or
 * cos(alpha) <= 0 (cos^n, zero behind). */
static int spot_cone(const cdl_emitter *e, cdl_vec3 *position, cdl_vec3 *axis, double *cos_min)
{
    const spot_emitter *s = as_spot(e);
    *position = s->position;
    *axis = s->axis;
    *cos_min = s->use_exponent ? 0.0 : cos(s->half_angle);
    return 1;
}

static const cdl_emitter_ops spot_ops = {spot_flux, spot_intensity, spot_eval_delta, NULL, NULL, NULL, NULL,
                                         spot_cone, NULL};

cdl_status cdl_emitter_create_spot(const cdl_spot_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status st;
    cdl_vec3 axis;
    if ((st = cdl_emitter_check_position(p->position, "spot emitter: position", err)) != CDL_OK) return st;
    if ((st = cdl_emitter_check_direction(p->direction, "spot emitter: direction", &axis, err)) != CDL_OK) return st;
    if ((st = cdl_emitter_check_nonnegative(p->intensity.cd, "spot emitter: intensity", "cd", err)) != CDL_OK)
        return st;
    if (p->use_exponent) {
        if ((st = cdl_emitter_check_nonnegative(p->exponent, "spot emitter: exponent", "", err)) != CDL_OK) return st;
    } else {
        if (!(isfinite(p->half_angle_deg) && p->half_angle_deg > 0.0 && p->half_angle_deg <= 180.0))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "spot emitter: half_angle: expected a number in (0, 180] degrees, found %g",
                                 p->half_angle_deg);
        if ((st = cdl_emitter_check_range(p->falloff_start_deg, 0.0, p->half_angle_deg,
                                          "spot emitter: falloff_start (at most half_angle)", "degrees", err)) != CDL_OK)
            return st;
    }
    spot_emitter *e = cdl_emitter_alloc(sizeof *e, CDL_EMITTER_SPOT, &spot_ops, err);
    if (!e) return CDL_ERR_INTERNAL;
    e->position = p->position;
    e->axis = axis;
    e->I0 = p->intensity.cd;
    e->use_exponent = p->use_exponent ? 1 : 0;
    if (!e->use_exponent) {
        e->half_angle = p->half_angle_deg * CDL_DEG_TO_RAD;
        e->falloff = p->falloff_start_deg * CDL_DEG_TO_RAD;
        e->smooth_span = sin(0.5 * (e->half_angle + e->falloff)) * sin(0.5 * (e->half_angle - e->falloff));
    } else {
        e->exponent = p->exponent;
    }
    *out = &e->base;
    return CDL_OK;
}
