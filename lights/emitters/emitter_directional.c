/* emitter_directional.c - light from infinitely far away: parallel, or from a
 * distant disk (the sun).
 *
 *   parameter          meaning                               unit    default  range
 *   direction          direction the light travels           -       -        non-zero
 *   illuminance        E_n, on a plane normal to the beam    lx      -        >= 0
 *   angular_diameter   the disk's angular diameter           degree  0        0 (parallel) or (0, 10]
 *
 * Parallel: on a plane with unit normal n, E = E_n cos(theta), theta the
 * angle between n and the direction towards the light (Lambert's cosine
 * law), 0 from behind; a delta emitter (one direction, one shadow ray).
 *
 * Disk of half-angle alpha about the axis s (towards the light), uniform
 * luminance L: the cap's vector irradiance is int_cap w dw = pi sin^2(alpha)
 * s, so E_n = L pi sin^2(alpha) and L = E_n / (pi sin^2 alpha). On a plane
 * the whole cap lies above (theta + alpha <= 90 degrees) E = L n . int_cap w
 * dw = E_n cos(theta) exactly, as for parallel light. Where the plane cuts
 * the cap, E = L int over the part above it of n.w dw: about s, with w =
 * cos t s + sin t (cos psi e1 + sin psi e2), n.w = A cos t + B(psi) sin t
 * is positive on one interval of t for each psi, and the integral over t is
 * the closed form L [A sin^2 t / 2 + B (t / 2 - sin 2t / 4)] between its
 * ends; over psi a Gauss-Legendre rule on the panels between the angles
 * where the interval's end changes from alpha to the plane's edge.
 * Samples: uniform in the cap's solid angle, pdf 1 / (2 pi (1 - cos alpha)).
 * "Flux" is the flux through 1 m^2 of beam section: E_n x 1 m^2.
 */
#include <math.h>
#include <stdlib.h>

#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "radiometry/sampling.h"

typedef struct directional_emitter {
    cdl_emitter base;
    cdl_vec3 to_light;  /* unit, against the direction of travel */
    double E_normal;    /* lx */
    /* the disk (alpha > 0) */
    double alpha, cos_alpha;
    double L;           /* cd/m^2 */
    cdl_frame frame;    /* n: to_light */
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

/* ---- the disk ------------------------------------------------------------------- */

/* int over t in [t0, t1] of (A cos t + B sin t) sin t dt */
static double cap_strip(double A, double B, double t0, double t1)
{
    double s0 = sin(t0), s1 = sin(t1);
    return 0.5 * A * (s1 * s1 - s0 * s0) + B * (0.5 * (t1 - t0) - 0.25 * (sin(2.0 * t1) - sin(2.0 * t0)));
}

/* The part of [0, alpha] where A cos t + B sin t > 0 (the arc of positive
 * values ends at atan2(A, -B) for A > 0, starts at atan2(-A, B) for A < 0). */
static double clipped_strip(double A, double B, double alpha)
{
    double t0 = 0.0, t1 = alpha;
    if (A > 0.0) t1 = fmin(alpha, atan2(A, -B));
    else if (A < 0.0) t0 = atan2(-A, B);
    else if (!(B > 0.0)) return 0.0;
    return t1 > t0 ? cap_strip(A, B, t0, t1) : 0.0;
}

static int cmp_angle(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* E on the plane of n from the disk, nothing in the way. */
static double disk_illuminance(const directional_emitter *d, cdl_vec3 n)
{
    double A = cdl_vec3_dot(n, d->frame.n), p = cdl_vec3_dot(n, d->frame.s), q = cdl_vec3_dot(n, d->frame.t);
    double R = hypot(p, q);
    double sin_alpha = sin(d->alpha);
    /* the whole cap above the plane (theta + alpha <= 90 deg: cos theta >= sin alpha) */
    if (A >= sin_alpha) return d->E_normal * A;
    if (A <= -sin_alpha) return 0.0; /* the whole cap below */
    /* psi where the interval's end meets alpha: B(psi) = -A / tan(alpha) */
    double breaks[3] = {0.0, 0.0, 0.0};
    int count = 0;
    double c = -A / tan(d->alpha);
    if (R > 0.0 && fabs(c) < R) {
        double base = atan2(q, p), half = acos(c / R);
        for (int k = 0; k < 2; ++k) {
            double v = fmod(base + (k ? half : -half), CDL_TWO_PI);
            breaks[count++] = v < 0.0 ? v + CDL_TWO_PI : v;
        }
        qsort(breaks, 2, sizeof *breaks, cmp_angle);
    } else {
        breaks[count++] = 0.0;
    }
    /* 20-point Gauss-Legendre on each panel (the integrand is smooth there) */
    static const double x[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                                 0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513259,
                                 0.9639719272779138, 0.9931285991850949};
    static const double w[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820, 0.1316886384491766,
                                 0.1181945319615184, 0.1019301198172404, 0.0832767415767048, 0.0626720483341091,
                                 0.0406014298003869, 0.0176140071391521};
    double total = 0.0;
    for (int b = 0; b < count; ++b) {
        double a0 = breaks[b], a1 = b + 1 < count ? breaks[b + 1] : breaks[0] + CDL_TWO_PI;
        double mid = 0.5 * (a0 + a1), half = 0.5 * (a1 - a0);
        for (int i = 0; i < 10; ++i)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double psi = mid + sgn * half * x[i];
                total += w[i] * half * clipped_strip(A, p * cos(psi) + q * sin(psi), d->alpha);
            }
    }
    return d->L * total;
}

static int disk_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    (void)p;
    *E = cdl_lux(disk_illuminance(as_directional(e), n));
    return 1;
}

static int disk_sample(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out)
{
    (void)p;
    const directional_emitter *d = as_directional(e);
    cdl_vec3 w = cdl_frame_to_world(&d->frame, cdl_sample_uniform_cone(d->cos_alpha, u1, u2));
    if (!(cdl_vec3_dot(n, w) > 0.0) || !(d->L > 0.0)) return 0;
    out->to_light = w;
    out->distance = INFINITY;
    out->L = cdl_nits(d->L);
    out->pdf = 1.0 / (CDL_TWO_PI * (1.0 - d->cos_alpha));
    return 1;
}

static cdl_luminance disk_radiance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 w, double *pdf)
{
    (void)p;
    (void)n;
    const directional_emitter *d = as_directional(e);
    int inside = cdl_vec3_dot(cdl_vec3_normalize(w), d->to_light) >= d->cos_alpha;
    if (pdf) *pdf = inside ? 1.0 / (CDL_TWO_PI * (1.0 - d->cos_alpha)) : 0.0;
    return cdl_nits(inside ? d->L : 0.0);
}

static const cdl_emitter_ops disk_ops = {directional_flux, NULL, NULL, disk_exact, disk_sample, disk_radiance,
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
    double diameter = p->angular_diameter_deg;
    if (diameter != 0.0 && (st = cdl_emitter_check_range(diameter, 1e-6, 10.0, "directional emitter: angular_diameter",
                                                         "degrees", err)) != CDL_OK)
        return st;
    directional_emitter *e = cdl_emitter_alloc(sizeof *e, CDL_EMITTER_DIRECTIONAL,
                                               diameter > 0.0 ? &disk_ops : &directional_ops, err);
    if (!e) return CDL_ERR_INTERNAL;
    e->to_light = cdl_vec3_neg(dir);
    e->E_normal = p->illuminance.lx;
    if (diameter > 0.0) {
        e->alpha = 0.5 * diameter * CDL_DEG_TO_RAD;
        e->cos_alpha = cos(e->alpha);
        double s = sin(e->alpha);
        /* E_n = L pi sin^2(alpha) (the cap's vector irradiance) */
        e->L = e->E_normal / (CDL_PI * s * s);
        e->frame = cdl_frame_from_normal(e->to_light);
    }
    *out = &e->base;
    return CDL_OK;
}

int cdl_emitter_directional_disk(const cdl_emitter *emitter, cdl_vec3 *to_light, double *half_angle_rad)
{
    if (!emitter || emitter->ops != &disk_ops) return 0;
    const directional_emitter *d = as_directional(emitter);
    *to_light = d->to_light;
    *half_angle_rad = d->alpha;
    return 1;
}
