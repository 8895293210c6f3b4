/* emitter_solid.c - a goniometric luminaire spread over a luminous solid.
 *
 *   parameter   meaning                                        unit  range
 *   (all of cdl_goniometric_params; the solid is the photometry's opening)
 *
 * IES LM-63-2019 (Table 1) gives some luminaires a three-dimensional
 * luminous shape around the photometric centre, in the luminaire's frame
 * (x along the length L, C0-C180; y along the width W; z up, height H):
 *   box ("rectangular with luminous sides")  L x W x H
 *   vertical cylinder                         diameter W, height H
 *   vertical elliptic cylinder                semi-axes L/2 (x), W/2 (y), height H
 *   sphere                                    diameter W
 *   ellipsoid                                 semi-axes L/2 (x), W/2 (y), H/2 (z)
 *   horizontal cylinder along                 axis x, length L; semi-axes W/2 (y), H/2 (z)
 *   horizontal cylinder across                axis y, length W; semi-axes L/2 (x), H/2 (z)
 * (sizes as cdl_photometry_opening_from_ies fills them: a 1995 code's
 * diameter copied into the field it leaves 0). All are convex and
 * luminous all over; photometry_opening.c gives their projected area
 * A_proj(w) (w a unit vector in the luminaire's frame; a, b, c the
 * semi-axes along x, y, z):
 *     box                 |w.x| W H + |w.y| L H + |w.z| W L
 *     cylinder, axis k    pi a_i a_j |w_k| + 4 h_k sqrt(a_i^2 w_j^2 + a_j^2 w_i^2)
 *                         (i, j the other two axes, h_k the half length)
 *     ellipsoid           pi sqrt(b^2 c^2 w_x^2 + a^2 c^2 w_y^2 + a^2 b^2 w_z^2)
 * (the circular cylinder and the sphere their special cases). The file's
 * I(w) is the whole luminaire's intensity, so the solid is
 * given the luminance that is uniform over its outline seen from w:
 *     L(w) = I(w) / A_proj(w)
 * at every surface point that faces w (the luminance of a source seen as
 * a whole, CIE S 017 17-21-050, which cdl_photometry_opening_luminance
 * reports for the same shapes). Then the intensity
 * of the whole solid, int L cos(theta_o) dA over the faces w sees, is
 * A_proj L = I(w) exactly: the far field is the point model and the flux
 * the file's.
 *
 * Where a ray enters: a box by its three slabs; a cylinder of axis k by
 * the quadratic of its elliptic cross-section (x_i / a_i)^2 + (x_j /
 * a_j)^2 = 1 and the slab |x_k| <= h_k; an ellipsoid (and the sphere) as
 * the unit sphere after x -> x / a componentwise. The scaling is affine, so
 * o + t d maps to o' + t d' with the same t: the distance along the ray
 * is read off in the scaled frame.
 *
 * Illuminance at p, E = int L(-omega) cos(theta_r) d omega over the
 * directions omega from p that meet the solid: for a sphere the receiver
 * sees whole, a cubature over its cone (below); otherwise sampled:
 * directions uniform in the solid angle Omega of a region that holds the
 * solid, a direction that misses the solid carrying nothing. The region is
 * the solid's bounding box (in the luminaire's frame: the box itself, a
 * cylinder's or ellipsoid's circumscribed box) where p is outside it and
 * it subtends less than the bounding sphere's cone (and at least 1e-3 sr,
 * where its angle excess keeps its digits): a face p sees chosen by its
 * share of Omega, then uniform in that face's solid angle (Urena, Fajardo
 * and King 2013, spherical_rectangle.h; the faces p sees tile the box's
 * solid angle). Otherwise the bounding sphere's cone (every direction
 * when p is inside that sphere). The pdf, 1 / Omega, is then the same for
 * every direction that meets the solid, and cdl_emitter_radiance makes
 * the same choice from p alone, which keeps it exact. A box and a sphere
 * fill their regions; a cylinder fills its box's outline seen across its
 * axis and pi / 4 of it seen along the axis, an ellipsoid pi / 4 seen
 * along an axis and less obliquely. Misses cost samples, not accuracy.
 */
#include <math.h>
#include <string.h>

#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "lights/emitters/spherical_rectangle.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "lights/photometry/photometry_metadata.h"

typedef struct solid_emitter {
    cdl_spread_emitter spread;   /* .point: the same luminaire as a point, I(w) */
    cdl_luminous_opening opening;
    cdl_vec3 center;
    cdl_vec3 axis[3];            /* the luminaire's x (length), y (width), z (up) in world */
    double half[3];              /* box: half of L, W, H; other solids: semi-axes (a cylinder's half length on its axis) */
    int cylinder;                /* a cylinder's axis (0 x, 1 y, 2 z), -1 for a box, sphere or ellipsoid */
    double bound;                /* radius of the bounding sphere */
    double side_top[4];          /* box: where the sides facing C0, C90, C180, C270 stop being luminous
                                  * (local z; the top of the box unless their heights differ) */
} solid_emitter;

static const solid_emitter *as_solid(const cdl_emitter *e)
{
    return (const solid_emitter *)e;
}

static cdl_vec3 to_local(const solid_emitter *s, cdl_vec3 v)
{
    return cdl_vec3_make(cdl_vec3_dot(v, s->axis[0]), cdl_vec3_dot(v, s->axis[1]), cdl_vec3_dot(v, s->axis[2]));
}

/* The roots t0 <= t1 of a t^2 + 2 b t + c = 0; 0 when there are none. */
static int quadratic(double a, double b, double c, double *t0, double *t1)
{
    double disc = b * b - a * c;
    if (!(disc >= 0.0) || !(a > 0.0)) return 0;
    /* the root of larger magnitude first, the other from the product (no cancellation) */
    double q = -(b + (b >= 0.0 ? sqrt(disc) : -sqrt(disc)));
    double r0 = q / a, r1 = q != 0.0 ? c / q : 0.0;
    *t0 = fmin(r0, r1);
    *t1 = fmax(r0, r1);
    return 1;
}

/* Narrows [*lo, *hi] to the t where o + t d lies in the slab |x| <= h. */
static void slab(double o, double d, double h, double *lo, double *hi)
{
    if (d == 0.0) {
        if (fabs(o) > h) *hi = -INFINITY;
        return;
    }
    double a = (-h - o) / d, b = (h - o) / d;
    *lo = fmax(*lo, fmin(a, b));
    *hi = fmin(*hi, fmax(a, b));
}

/* Narrows [*lo, *hi] to the t where o + t d lies in the quadric
 * sum_m ((o + t d)_m / h_m)^2 <= 1 over the `count` axes idx[m] (two: an
 * elliptic cylinder about the third axis; three: an ellipsoid). Dividing
 * by h is affine, so t is the same before and after; 0 when no t is in. */
static int quadric_span(const double o[3], const double d[3], const double h[3], const int *idx, int count,
                        double *lo, double *hi)
{
    double a = 0.0, b = 0.0, c = -1.0, t0, t1;
    for (int m = 0; m < count; ++m) {
        double os = o[idx[m]] / h[idx[m]], ds = d[idx[m]] / h[idx[m]];
        a += ds * ds;
        b += os * ds;
        c += os * os;
    }
    if (!(a > 0.0)) return c <= 0.0; /* parallel to the axis: in or out for every t */
    if (!quadratic(a, b, c, &t0, &t1)) return 0;
    *lo = fmax(*lo, t0);
    *hi = fmin(*hi, t1);
    return 1;
}

/* Distance along the unit world direction dir from p to where the ray
 * enters the solid; 0 when it misses or p is inside. */
static double solid_entry(const solid_emitter *s, cdl_vec3 p, cdl_vec3 dir)
{
    cdl_vec3 ol = to_local(s, cdl_vec3_sub(p, s->center)), dl = to_local(s, dir);
    double o[3] = {ol.x, ol.y, ol.z}, d[3] = {dl.x, dl.y, dl.z}, lo = -INFINITY, hi = INFINITY;
    int k = s->cylinder;
    if (s->opening.shape == CDL_LUMINOUS_SHAPE_BOX) {
        for (int m = 0; m < 3; ++m) slab(o[m], d[m], s->half[m], &lo, &hi);
    } else if (k >= 0) {
        /* the elliptic cross-section about axis k, then the slab of its length */
        const int across[2] = {(k + 1) % 3, (k + 2) % 3};
        if (!quadric_span(o, d, s->half, across, 2, &lo, &hi)) return 0.0;
        slab(o[k], d[k], s->half[k], &lo, &hi);
    } else {
        /* sphere or ellipsoid */
        const int all[3] = {0, 1, 2};
        if (!quadric_span(o, d, s->half, all, 3, &lo, &hi)) return 0.0;
    }
    return lo <= hi && lo > 0.0 && isfinite(lo) ? lo : 0.0;
}

/* Is the point where the ray from p along dir enters the solid (at
 * distance t) luminous? Everywhere but on a box's side above its own
 * luminous height (EULUMDAT's sides luminous to different heights: the
 * rest of the side is the dark housing). The face entered is the one the
 * entry point lies on, the axis where it is furthest out relative to the
 * box's half size. */
static int solid_entry_lit(const solid_emitter *s, cdl_vec3 p, cdl_vec3 dir, double t)
{
    if (s->opening.shape != CDL_LUMINOUS_SHAPE_BOX) return 1;
    cdl_vec3 q = to_local(s, cdl_vec3_sub(cdl_vec3_madd(p, t, dir), s->center));
    double rx = fabs(q.x) / s->half[0], ry = fabs(q.y) / s->half[1], rz = fabs(q.z) / s->half[2];
    if (rz >= rx && rz >= ry) return 1; /* the top or bottom */
    int side = rx >= ry ? (q.x > 0.0 ? 0 : 2) : (q.y > 0.0 ? 1 : 3);
    /* within a rounding of the box's size of its luminous top: lit */
    return q.z <= s->side_top[side] + 1e-12 * s->bound;
}

/* Luminance arriving at p along dir from the solid: L = I(w) / A_proj(w),
 * w = -dir the direction of emission. */
static double solid_luminance_towards(const solid_emitter *s, cdl_vec3 w)
{
    double A = cdl_luminous_opening_projected_area(&s->opening, to_local(s, w));
    if (!(A > 0.0)) return 0.0;
    return cdl_emitter_intensity(s->spread.point, w).cd / A;
}

/* 1 - cos(theta_max) of the bounding sphere's cone from p (2 inside it:
 * every direction), from sin^2 = R^2 / d^2 without cancellation. */
static double cone_height(const solid_emitter *s, cdl_vec3 p, cdl_vec3 *axis)
{
    cdl_vec3 to = cdl_vec3_sub(s->center, p);
    double d2 = cdl_vec3_dot(to, to), R2 = s->bound * s->bound;
    if (!(d2 > R2)) {
        *axis = s->axis[2];
        return 2.0;
    }
    *axis = cdl_vec3_scale(to, 1.0 / sqrt(d2));
    double sin2 = R2 / d2;
    return sin2 / (1.0 + sqrt(1.0 - sin2));
}

/* Below this solid angle the bounding box's faces are not sampled (the
 * spherical rectangle's angle excess, ~1e-15 sr absolute, would lose
 * relative digits; emitter_area.c's threshold): the cone is. */
#define BOX_SOLID_ANGLE_MIN 1e-3

/* The faces of the solid's bounding box (half[] about the centre, in the
 * luminaire's frame) that p sees, each a spherical rectangle, and their
 * total solid angle. */
typedef struct box_view {
    cdl_spherical_rectangle face[3];
    int count;
    double omega;
} box_view;

/* Fills v for p outside the bounding box: the faces whose plane p lies
 * beyond (on a convex body, those it sees; their solid angles tile the
 * box's). Returns 0 when p is inside the box. */
static int solid_box_view(const solid_emitter *s, cdl_vec3 p, box_view *v)
{
    cdl_vec3 ol = to_local(s, cdl_vec3_sub(p, s->center));
    double o[3] = {ol.x, ol.y, ol.z};
    const double *h = s->half;
    v->count = 0;
    v->omega = 0.0;
    for (int m = 0; m < 3; ++m) {
        if (!(fabs(o[m]) > h[m])) continue;
        int i = (m + 1) % 3, j = (m + 2) % 3;
        /* the face at x_m = +-h_m: corner (-h_i, -h_j), edges 2 h_i and 2 h_j */
        cdl_vec3 corner = cdl_vec3_madd(s->center, o[m] > 0.0 ? h[m] : -h[m], s->axis[m]);
        corner = cdl_vec3_madd(cdl_vec3_madd(corner, -h[i], s->axis[i]), -h[j], s->axis[j]);
        double S = cdl_spherical_rectangle_init(&v->face[v->count], p, corner, cdl_vec3_scale(s->axis[i], 2.0 * h[i]),
                                                cdl_vec3_scale(s->axis[j], 2.0 * h[j]));
        if (S > 0.0) {
            v->omega += S;
            v->count++;
        }
    }
    return v->count > 0;
}

/* The solid angle p samples uniformly (the pdf is its inverse wherever
 * the direction meets the solid): the bounding box's faces (v->count > 0)
 * where p is outside the box and the box subtends less than the bounding
 * sphere's cone and at least BOX_SOLID_ANGLE_MIN; otherwise the cone (h
 * its 1 - cos(theta_max), axis its axis). A sphere always its cone, which
 * it fills. One decision from one arithmetic in sample and radiance, so
 * their pdfs agree. */
static double solid_sampled_region(const solid_emitter *s, cdl_vec3 p, box_view *v, cdl_vec3 *axis, double *h)
{
    *h = cone_height(s, p, axis);
    double cone = CDL_TWO_PI * *h;
    if (s->opening.shape != CDL_LUMINOUS_SHAPE_SPHERE && solid_box_view(s, p, v) && v->omega >= BOX_SOLID_ANGLE_MIN &&
        v->omega < cone)
        return v->omega;
    v->count = 0;
    return cone;
}

static int solid_sample(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out)
{
    const solid_emitter *s = as_solid(e);
    box_view v;
    cdl_vec3 axis, dir;
    double h, omega = solid_sampled_region(s, p, &v, &axis, &h);
    if (v.count > 0) {
        /* a face by its share of the box's solid angle, u1 stretched over
         * that share, then uniform in the face's solid angle (Urena et al.) */
        int f = 0;
        double below = 0.0, at = u1 * omega;
        while (f < v.count - 1 && below + v.face[f].S <= at) below += v.face[f++].S;
        double u = fmin(1.0, fmax(0.0, (at - below) / v.face[f].S));
        dir = cdl_vec3_normalize(cdl_spherical_rectangle_sample(&v.face[f], u, u2));
    } else {
        /* uniform in solid angle within the cone: cos(theta) uniform in [1 - h, 1] */
        double c = 1.0 - u1 * h, st = sqrt(fmax(0.0, (1.0 - c) * (1.0 + c))), phi = CDL_TWO_PI * u2;
        cdl_frame f = cdl_frame_from_normal(axis);
        dir = cdl_vec3_normalize(cdl_frame_to_world(&f, cdl_vec3_make(st * cos(phi), st * sin(phi), c)));
    }
    if (!(cdl_vec3_dot(dir, n) > 0.0)) return 0;
    double t = solid_entry(s, p, dir);
    if (!(t > 0.0) || !solid_entry_lit(s, p, dir, t)) return 0;
    out->to_light = dir;
    out->distance = t;
    out->L = cdl_nits(solid_luminance_towards(s, cdl_vec3_neg(dir)));
    out->pdf = 1.0 / omega;
    return out->L.cd_m2 > 0.0;
}

static cdl_luminance solid_radiance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double *pdf)
{
    (void)n;
    const solid_emitter *s = as_solid(e);
    *pdf = 0.0;
    double t = solid_entry(s, p, dir);
    if (!(t > 0.0)) return cdl_nits(0.0);
    box_view v;
    cdl_vec3 axis;
    double h;
    *pdf = 1.0 / solid_sampled_region(s, p, &v, &axis, &h);
    if (!solid_entry_lit(s, p, dir, t)) return cdl_nits(0.0);
    return cdl_nits(solid_luminance_towards(s, cdl_vec3_neg(dir)));
}

/* ---- the sphere's unoccluded E: a cubature over its cone ------------------ *
 *
 * Where the receiver's plane leaves the whole sphere in front of it (n.a >=
 * sin(theta_max), a towards the centre), E = int_0^2pi int_{cos theta_max}^1
 * L(-omega) (n.omega) d mu d phi has no horizon in it, and is integrated
 * by composite Gauss-Legendre rules, m panels in mu by 4 m in phi, 5 points
 * against 3 per panel as the error estimate (Davis and Rabinowitz, Methods
 * of Numerical Integration, 1984, ch. 5-6), m doubled from 1 to 16 until
 * the estimate is below 1e-5 of E (the flat opening's tolerance,
 * emitter_opening.c); past that (a table whose kinks the panels do not
 * resolve) or where the horizon cuts the sphere it declines and the
 * caller samples. */
#define SPHERE_TOLERANCE 1e-5
#define SPHERE_MAX_PANELS 16

/* Gauss-Legendre nodes and weights on [-1, 1] of 3 and 5 points, from
 * their closed forms (Abramowitz and Stegun 25.4.29) */
static void gauss_rules(double x3[3], double w3[3], double x5[5], double w5[5])
{
    double a = sqrt(0.6), b = sqrt(5.0 - 2.0 * sqrt(10.0 / 7.0)) / 3.0, c = sqrt(5.0 + 2.0 * sqrt(10.0 / 7.0)) / 3.0;
    double wb = (322.0 + 13.0 * sqrt(70.0)) / 900.0, wc = (322.0 - 13.0 * sqrt(70.0)) / 900.0;
    x3[0] = -a, x3[1] = 0.0, x3[2] = a;
    w3[0] = w3[2] = 5.0 / 9.0, w3[1] = 8.0 / 9.0;
    x5[0] = -c, x5[1] = -b, x5[2] = 0.0, x5[3] = b, x5[4] = c;
    w5[0] = w5[4] = wc, w5[1] = w5[3] = wb, w5[2] = 128.0 / 225.0;
}

/* The cone integral with m x 4m panels of a k-point rule. */
static double sphere_rule(const solid_emitter *s, const cdl_frame *f, cdl_vec3 n, double h, int m, const double *x,
                          const double *w, int k)
{
    double sum = 0.0, dmu = h / m, dphi = CDL_TWO_PI / (4 * m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < 4 * m; ++j)
            for (int a = 0; a < k; ++a) {
                /* mu = cos(theta) from 1 - h to 1 */
                double mu = 1.0 - h + dmu * (i + 0.5 + 0.5 * x[a]), st = sqrt(fmax(0.0, (1.0 - mu) * (1.0 + mu)));
                for (int b = 0; b < k; ++b) {
                    double phi = dphi * (j + 0.5 + 0.5 * x[b]);
                    cdl_vec3 dir = cdl_frame_to_world(f, cdl_vec3_make(st * cos(phi), st * sin(phi), mu));
                    double c = cdl_vec3_dot(n, dir);
                    if (c > 0.0) sum += w[a] * w[b] * solid_luminance_towards(s, cdl_vec3_neg(dir)) * c;
                }
            }
    return sum * 0.25 * dmu * dphi;
}

static int solid_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    const solid_emitter *s = as_solid(e);
    cdl_vec3 axis;
    double h = cone_height(s, p, &axis);
    if (h >= 2.0) return 0; /* inside the sphere */
    double sin_max = sqrt(h * (2.0 - h)), na = cdl_vec3_dot(n, axis);
    if (na <= -sin_max) {
        *E = cdl_lux(0.0); /* wholly behind the receiver */
        return 1;
    }
    if (na < sin_max) return 0; /* the receiver's horizon cuts the sphere */
    double x3[3], w3[3], x5[5], w5[5];
    gauss_rules(x3, w3, x5, w5);
    cdl_frame f = cdl_frame_from_normal(axis);
    for (int m = 1; m <= SPHERE_MAX_PANELS; m *= 2) {
        double q5 = sphere_rule(s, &f, n, h, m, x5, w5, 5), q3 = sphere_rule(s, &f, n, h, m, x3, w3, 3);
        if (fabs(q5 - q3) <= SPHERE_TOLERANCE * fabs(q5)) {
            *E = cdl_lux(fmax(0.0, q5));
            return 1;
        }
    }
    return 0;
}

/* The axis (0 x, 1 y, 2 z) of a cylindrical solid; -1 for the others. */
static int solid_cylinder_axis(cdl_luminous_shape shape)
{
    switch (shape) {
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER: return 2;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG: return 0;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS: return 1;
    default: return -1;
    }
}

/* Radius of the sphere about the centre that bounds the solid: a box's
 * half diagonal; a cylinder's rim, its longer cross-section semi-axis
 * beside its half length; an ellipsoid's longest semi-axis. */
static double solid_bounding_radius(const solid_emitter *s)
{
    const double *h = s->half;
    int k = s->cylinder;
    if (s->opening.shape == CDL_LUMINOUS_SHAPE_BOX) return sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (k >= 0) return hypot(fmax(h[(k + 1) % 3], h[(k + 2) % 3]), h[k]);
    return fmax(h[0], fmax(h[1], h[2]));
}

/* boxes, cylinders and ellipsoids have no exact E (they do not fill the
 * bounding cone); spheres the cubature */
static const cdl_emitter_ops solid_ops = {cdl_spread_emitter_flux,    cdl_spread_emitter_intensity, NULL, NULL,
                                          solid_sample,               solid_radiance,
                                          cdl_spread_emitter_destroy, NULL,                         NULL};
static const cdl_emitter_ops sphere_ops = {cdl_spread_emitter_flux,    cdl_spread_emitter_intensity, NULL, solid_exact,
                                           solid_sample,               solid_radiance,
                                           cdl_spread_emitter_destroy, NULL,                         NULL};

int cdl_emitter_solid_bounding_sphere(const cdl_emitter *emitter, cdl_shape *sphere)
{
    if (emitter->ops != &solid_ops && emitter->ops != &sphere_ops) return 0;
    const solid_emitter *s = as_solid(emitter);
    memset(sphere, 0, sizeof *sphere);
    sphere->kind = CDL_SHAPE_SPHERE;
    sphere->center = s->center;
    sphere->radius = s->bound;
    return 1;
}

cdl_status cdl_emitter_create_goniometric_solid(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    const cdl_luminous_opening *op = &cdl_photometry_get_metadata(p->photometry)->opening;
    cdl_status st;
    solid_emitter *s = cdl_spread_emitter_create(
        sizeof *s, op->shape == CDL_LUMINOUS_SHAPE_SPHERE ? &sphere_ops : &solid_ops, p, &st, err);
    if (!s) return st;
    s->opening = *op;
    s->center = p->position;
    cdl_emitter_rotation_columns(p->rotation_deg, s->axis);
    s->cylinder = solid_cylinder_axis(op->shape);
    /* semi-axes along the luminaire's x, y, z: the length, width and height
     * halved, as cdl_luminous_opening_projected_area reads them */
    s->half[0] = 0.5 * op->length_m;
    s->half[1] = 0.5 * op->width_m;
    s->half[2] = 0.5 * op->height_m;
    if (op->shape == CDL_LUMINOUS_SHAPE_BOX) {
        /* as tall as its tallest side (sides luminous to different heights) */
        for (int k = 0; k < 4; ++k)
            s->half[2] = fmax(s->half[2], 0.5 * cdl_luminous_opening_box_side_height_m(op, k));
        for (int k = 0; k < 4; ++k) s->side_top[k] = -s->half[2] + cdl_luminous_opening_box_side_height_m(op, k);
    }
    if (op->shape == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER || op->shape == CDL_LUMINOUS_SHAPE_SPHERE) {
        /* round: the projected area takes the diameter from the width alone */
        s->half[0] = s->half[1] = 0.5 * op->width_m;
        s->opening.length_m = op->width_m;
        if (op->shape == CDL_LUMINOUS_SHAPE_SPHERE) {
            s->half[2] = 0.5 * op->width_m;
            s->opening.height_m = op->width_m;
        }
    }
    s->bound = solid_bounding_radius(s);
    *out = &s->spread.base;
    return CDL_OK;
}
