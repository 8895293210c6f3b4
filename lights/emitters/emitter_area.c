/* emitter_area.c - Lambertian, one-sided emitting shapes.
 *
 *   parameter   meaning                                      unit    range
 *   shape       triangles, rect, disk or sphere (emitter.h)  m       non-degenerate
 *   luminance   L, the same in every direction it emits      cd/m^2  >= 0
 *
 * Emission is one-sided: along the shape's normal (rect u x v, disk
 * `normal`, triangles counter-clockwise seen from the emitting side, sphere
 * outward, or inward with `inward`). Flux Phi = pi L A.
 *
 * Exact unoccluded illuminance (projected_solid_angle.h): E = L Omega_p, with
 * Omega_p by Lambert's contour integral over each front-facing triangle or the
 * rect clipped to the receiver's hemisphere, in closed form for disks and
 * spheres; a receiver inside an inward sphere sees L over its whole
 * hemisphere: E = pi L. Self-occlusion of non-convex meshes is NOT accounted
 * for: that is the caller's visibility test (the emitter's own triangles
 * are occluders like any other surface).
 *
 * Sampling (pdf exact, with respect to solid angle at p):
 *  - triangles, meshes of up to SOLID_ANGLE_MAX_TRIANGLES: a triangle facing
 *    p with probability Omega_i / Omega (its share of the solid angle of the
 *    facing triangles), then a direction uniform in its solid angle (Arvo's
 *    map, spherical_triangle.h): pdf = 1 / Omega; a triangle under
 *    TRIANGLE_SOLID_ANGLE_MIN gets a uniform point instead:
 *    pdf = (Omega_i / Omega) d^2 / (A_i cos theta_e);
 *  - larger meshes: a triangle with probability proportional to its area,
 *    a uniform point on it; pdf = d^2 / (A cos theta_e);
 *  - rect with orthogonal sides, subtending at least RECT_SOLID_ANGLE_MIN:
 *    uniform in solid angle (spherical_rectangle.h), pdf = 1 / Omega, so
 *    near a large panel the variance stays that of the cosine alone;
 *    otherwise (far, or a slanted parallelogram) a uniform point (s, t) =
 *    (u1, u2); pdf = d^2 / (A cos theta_e);
 *  - disk filling at least DISK_COSINE_FRACTION of the receiver's
 *    cosine-weighted hemisphere (Omega_p / pi, from the closed form): a
 *    cosine-weighted direction about n, pdf = cos / pi (directions that miss
 *    the disk carry no light; the relative spread is sqrt((1 - f) / f) <= 1,
 *    and vanishes right under the disk); otherwise a uniform point by the
 *    concentric map (stratification-preserving), pdf = d^2 / (A cos theta_e);
 *  - sphere seen from outside: a uniform direction in the cone it
 *    subtends, pdf = 1 / (2 pi (1 - cos sigma)), sin sigma = R/d;
 *  - inside an inward sphere: cosine-weighted about n, pdf = cos / pi.
 * A sample is a point on the emitter, whichever other part of the emitter
 * may hide it: the mean of L cos / pdf is the exact illuminance above.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "lights/emitters/distribution2d.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "lights/emitters/projected_solid_angle.h"
#include "lights/emitters/spherical_rectangle.h"
#include "lights/emitters/spherical_triangle.h"
#include "radiometry/constants.h"
#include "radiometry/conversions.h"
#include "radiometry/frame.h"
#include "radiometry/ray_triangle.h"
#include "radiometry/sampling.h"

typedef struct area_triangle {
    cdl_vec3 v0, e1, e2; /* vertices v0, v0 + e1, v0 + e2 */
    cdl_vec3 normal;     /* unit, emitting side */
    double area;
} area_triangle;

typedef struct area_emitter {
    cdl_emitter base;
    cdl_shape_kind shape;
    double L;         /* cd/m^2 */
    double area;      /* m^2 */
    /* triangles */
    area_triangle *tris;
    double *cdf;      /* cdf[i] = area of triangles 0..i / total */
    size_t tri_count;
    /* rect */
    cdl_vec3 origin, u, v;
    int rect_is_rectangle;   /* u orthogonal to v: solid-angle sampling applies */
    /* disk and sphere */
    cdl_vec3 center;
    double radius;
    int inward;
    /* rect and disk: unit normal and (disk) in-plane frame */
    cdl_frame frame;
} area_emitter;

static const area_emitter *as_area(const cdl_emitter *e)
{
    return (const area_emitter *)e;
}

/* ---- flux and intensity ----------------------------------------------------- */

static cdl_luminous_flux area_flux(const cdl_emitter *e)
{
    const area_emitter *a = as_area(e);
    /* Lambertian emitter: exitance M = pi L, flux Phi = M A. */
    return cdl_lumens(cdl_lambertian_exitance_from_luminance(cdl_nits(a->L)).lm_m2 * a->area);
}

static cdl_luminous_intensity area_intensity(const cdl_emitter *e, cdl_vec3 dir)
{
    const area_emitter *a = as_area(e);
    /* Intensity of a Lambertian surface: I(w) = int L max(0, m.w) dA, which
     * is L times the projected area seen from far away along w. */
    double projected = 0.0;
    switch (a->shape) {
    case CDL_SHAPE_TRIANGLES:
        for (size_t i = 0; i < a->tri_count; ++i)
            projected += a->tris[i].area * fmax(0.0, cdl_vec3_dot(a->tris[i].normal, dir));
        break;
    case CDL_SHAPE_RECT:
    case CDL_SHAPE_DISK:
        projected = a->area * fmax(0.0, cdl_vec3_dot(a->frame.n, dir));
        break;
    case CDL_SHAPE_SPHERE:
        /* Every direction sees a disk of pi R^2 (an inward sphere's inner
         * face too, self-occlusion aside: the convention of the header). */
        projected = CDL_PI * a->radius * a->radius;
        break;
    }
    return cdl_candelas(a->L * projected);
}

/* ---- exact illuminance ---------------------------------------------------------- */

/* Does a receiver at p facing n see the inside of the sphere? Inside it,
 * yes; on its surface (to a few ulps of the radius, as a grid point lying
 * on it is), when n faces inward: a point on a surface belongs to the side
 * its normal faces. */
static int sphere_inside_seen(const area_emitter *a, cdl_vec3 p, cdl_vec3 n)
{
    cdl_vec3 c = cdl_vec3_sub(a->center, p);
    double d = cdl_vec3_length(c), R = a->radius;
    if (d < R) return 1;
    return d <= R * (1.0 + 8.0 * DBL_EPSILON) && cdl_vec3_dot(n, c) > 0.0;
}

static double triangles_projected_solid_angle(const area_emitter *a, cdl_vec3 p, cdl_vec3 n)
{
    double omega = 0.0;
    for (size_t i = 0; i < a->tri_count; ++i) {
        const area_triangle *t = &a->tris[i];
        cdl_vec3 r0 = cdl_vec3_sub(t->v0, p);
        /* One-sided: only triangles whose emitting side faces p. */
        if (!(cdl_vec3_dot(t->normal, r0) < 0.0)) continue;
        cdl_vec3 rel[3] = {r0, cdl_vec3_add(r0, t->e1), cdl_vec3_add(r0, t->e2)};
        omega += cdl_projected_solid_angle_polygon(rel, 3, n);
    }
    return omega;
}

static int area_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    const area_emitter *a = as_area(e);
    double omega = 0.0;
    switch (a->shape) {
    case CDL_SHAPE_TRIANGLES:
        omega = triangles_projected_solid_angle(a, p, n);
        break;
    case CDL_SHAPE_RECT: {
        cdl_vec3 r0 = cdl_vec3_sub(a->origin, p);
        if (cdl_vec3_dot(a->frame.n, r0) < 0.0) {
            cdl_vec3 rel[4] = {r0, cdl_vec3_add(r0, a->u), cdl_vec3_add(cdl_vec3_add(r0, a->u), a->v),
                               cdl_vec3_add(r0, a->v)};
            omega = cdl_projected_solid_angle_polygon(rel, 4, n);
        }
        break;
    }
    case CDL_SHAPE_DISK:
        omega = cdl_projected_solid_angle_disk(cdl_vec3_sub(a->center, p), a->frame.n, a->radius, n);
        break;
    case CDL_SHAPE_SPHERE:
        if (a->inward)
            /* Inside, the emitting inner face fills the whole hemisphere of n. */
            omega = sphere_inside_seen(a, p, n) ? CDL_PI : 0.0;
        else
            omega = cdl_projected_solid_angle_sphere(cdl_vec3_sub(a->center, p), a->radius, n);
        break;
    }
    /* Lambertian source, unoccluded: E = L Omega_p. */
    *E = cdl_lux(a->L * fmax(0.0, omega));
    return 1;
}

/* ---- ray queries ------------------------------------------------------------ */

/* Ray p + t w (t > 0) against the triangle (radiometry/ray_triangle.h). */
static double ray_triangle(const area_triangle *t, cdl_vec3 p, cdl_vec3 w)
{
    return cdl_ray_triangle_distance(t->v0, t->e1, t->e2, p, w);
}

/* Ray against the plane of a rect or disk: distance and in-plane offset from `base`. */
static double ray_plane(const area_emitter *a, cdl_vec3 base, cdl_vec3 p, cdl_vec3 w, cdl_vec3 *offset)
{
    double denom = cdl_vec3_dot(a->frame.n, w);
    if (denom == 0.0) return -1.0;
    double t = cdl_vec3_dot(a->frame.n, cdl_vec3_sub(base, p)) / denom;
    if (!(t > 0.0)) return -1.0;
    *offset = cdl_vec3_sub(cdl_vec3_madd(p, t, w), base);
    return t;
}

/* ---- sampling --------------------------------------------------------------- */

/* Fills `out` for a sampled point at w = x - p on a surface of unit normal m
 * chosen with area density p_A. pdf in solid angle:
 * p_w = p_A d^2 / cos(theta_e) (change of measure dA = d^2 dw / cos theta_e). */
static int finish_point_sample(const area_emitter *a, cdl_vec3 w, cdl_vec3 m, double p_A, cdl_vec3 n,
                               cdl_light_sample *out)
{
    double d = cdl_vec3_length(w);
    if (!(d > 0.0)) return 0;
    cdl_vec3 dir = cdl_vec3_scale(w, 1.0 / d);
    double cos_e = -cdl_vec3_dot(m, dir);
    if (!(cos_e > 0.0) || !(cdl_vec3_dot(n, dir) > 0.0)) return 0;
    out->to_light = dir;
    out->distance = d;
    out->L = cdl_nits(a->L);
    out->pdf = d / cos_e * d * p_A;
    return out->L.cd_m2 > 0.0 && isfinite(out->pdf);
}

/* Meshes of at most this many triangles are sampled by solid angle (the
 * triangles' solid angles are computed for every sample: O(triangles)). */
#define SOLID_ANGLE_MAX_TRIANGLES 64
/* Triangles under this solid angle get area sampling within their share
 * (Arvo's map loses relative precision for tiny spherical triangles). */
#define TRIANGLE_SOLID_ANGLE_MIN 1e-3

/* Solid angle of each triangle facing p (0 for the others); returns the sum. */
static double facing_solid_angles(const area_emitter *a, cdl_vec3 p, double *omega)
{
    double total = 0.0;
    for (size_t i = 0; i < a->tri_count; ++i) {
        const area_triangle *t = &a->tris[i];
        cdl_vec3 r0 = cdl_vec3_sub(t->v0, p);
        omega[i] = cdl_vec3_dot(t->normal, r0) < 0.0
                       ? cdl_triangle_solid_angle(r0, cdl_vec3_add(r0, t->e1), cdl_vec3_add(r0, t->e2))
                       : 0.0;
        total += omega[i];
    }
    return total;
}

/* The solid-angle sampler's density at a point of triangle i seen at
 * distance d with emission cosine cos_e (the mixture described on top). */
static double triangle_solid_angle_pdf(const area_triangle *t, double omega_i, double total, double d, double cos_e)
{
    if (omega_i >= TRIANGLE_SOLID_ANGLE_MIN) return 1.0 / total;
    return omega_i / total * (d / cos_e * d / t->area);
}

static int sample_triangles_by_solid_angle(const area_emitter *a, cdl_vec3 p, cdl_vec3 n, double u1, double u2,
                                           cdl_light_sample *out)
{
    double omega[SOLID_ANGLE_MAX_TRIANGLES];
    double total = facing_solid_angles(a, p, omega);
    if (!(total > 0.0)) return 0;
    /* Triangle i with probability omega_i / total; u1 rescaled within its share. */
    double target = u1 * total, start = 0.0;
    size_t i = 0, last = 0;
    for (; i < a->tri_count; ++i) {
        if (!(omega[i] > 0.0)) continue;
        last = i;
        if (start + omega[i] > target) break;
        start += omega[i];
    }
    if (i == a->tri_count) i = last;
    double ur = fmin(1.0, fmax(0.0, (target - start) / omega[i]));
    const area_triangle *t = &a->tris[i];
    cdl_vec3 r0 = cdl_vec3_sub(t->v0, p);
    cdl_vec3 w;
    if (omega[i] >= TRIANGLE_SOLID_ANGLE_MIN) {
        cdl_spherical_triangle st;
        cdl_spherical_triangle_init(&st, r0, cdl_vec3_add(r0, t->e1), cdl_vec3_add(r0, t->e2));
        cdl_vec3 dir = cdl_spherical_triangle_sample(&st, ur, u2);
        /* Along dir to the triangle's plane. */
        double den = cdl_vec3_dot(t->normal, dir);
        if (!(den < 0.0)) return 0;
        w = cdl_vec3_scale(dir, cdl_vec3_dot(t->normal, r0) / den);
    } else {
        double b0, b1;
        cdl_sample_uniform_triangle(ur, u2, &b0, &b1);
        w = cdl_vec3_madd(cdl_vec3_madd(r0, b1, t->e1), 1.0 - b0 - b1, t->e2);
    }
    if (!finish_point_sample(a, w, t->normal, 1.0 / t->area, n, out)) return 0;
    out->pdf = triangle_solid_angle_pdf(t, omega[i], total, out->distance, -cdl_vec3_dot(t->normal, out->to_light));
    return isfinite(out->pdf) && out->pdf > 0.0;
}

/* Below this solid angle a rect is sampled by area: it is then far enough
 * for area sampling to be nearly uniform in solid angle too, and the angle
 * excess that gives Omega (~1e-15 sr absolute) would lose relative digits. */
#define RECT_SOLID_ANGLE_MIN 1e-3

/* A disk filling at least this fraction of the receiver's cosine-weighted
 * hemisphere is sampled cos-weighted about n. */
#define DISK_COSINE_FRACTION 0.5

static int disk_uses_cosine(const area_emitter *a, cdl_vec3 p, cdl_vec3 n)
{
    /* The disk lies in the ball of its radius r about its centre, seen
     * from p at distance d within a cone of half-angle s, sin s = r / d;
     * nothing in that cone has a projected solid angle above pi sin^2 s
     * (the cone's own, about n). Below the fraction, no need for the
     * exact value: the same decision, cheaper. */
    cdl_vec3 c = cdl_vec3_sub(a->center, p);
    if (a->radius * a->radius < DISK_COSINE_FRACTION * cdl_vec3_dot(c, c)) return 0;
    double omega = cdl_projected_solid_angle_disk(cdl_vec3_sub(a->center, p), a->frame.n, a->radius, n);
    return omega >= DISK_COSINE_FRACTION * CDL_PI;
}

/* Whether p samples the rect by solid angle (the same decision, from the
 * same arithmetic, in sample and radiance, so their pdfs agree). */
static int rect_uses_solid_angle(const area_emitter *a, cdl_vec3 p, cdl_spherical_rectangle *sr)
{
    if (!a->rect_is_rectangle) return 0;
    return cdl_spherical_rectangle_init(sr, p, a->origin, a->u, a->v) >= RECT_SOLID_ANGLE_MIN;
}


/* Shirley and Chiu's concentric map of the square onto the unit disk
 * ("A low distortion map between disk and square", JGT 2(3), 1997). */
static void concentric_disk(double u1, double u2, double *x, double *y)
{
    double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
    if (a == 0.0 && b == 0.0) {
        *x = *y = 0.0;
        return;
    }
    double r, phi;
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = 0.25 * CDL_PI * (b / a);
    } else {
        r = b;
        phi = 0.5 * CDL_PI - 0.25 * CDL_PI * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

/* 1 - cos(sigma) of the cone a sphere of radius R subtends from distance d > R,
 * as sin^2 / (1 + cos): exact for tiny cones. */
static double sphere_cone_one_minus_cos(double d, double R)
{
    double sin2 = (R / d) * (R / d);
    double cos_sigma = sqrt((d - R) * (d + R)) / d;
    return sin2 / (1.0 + cos_sigma);
}

/* Nearer positive root t of |p + t w - c|^2 = R^2 for p outside (b = w.(c-p),
 * q = d^2 - R^2 > 0), as q / (b + sqrt(b^2 - q)) to avoid cancellation; -1 if
 * the ray misses. */
static double sphere_hit_from_outside(double b, double q)
{
    double disc = b * b - q;
    if (!(b > 0.0) || disc < 0.0) return -1.0;
    return q / (b + sqrt(disc));
}

/* Positive root from inside (q = |p-c|^2 - R^2 < 0, b = w.(c - p)). */
static double sphere_hit_from_inside(double b, double q)
{
    double root = sqrt(b * b - q);
    return b > 0.0 ? b + root : -q / (root - b);
}

static int sample_sphere(const area_emitter *a, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out)
{
    cdl_vec3 c = cdl_vec3_sub(a->center, p);
    double d = cdl_vec3_length(c);
    double R = a->radius;
    cdl_vec3 dir;
    double pdf;
    if (a->inward) {
        if (!sphere_inside_seen(a, p, n)) return 0;
        cdl_frame f = cdl_frame_from_normal(n);
        dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u1, u2));
        double cos_r = cdl_vec3_dot(n, dir);
        if (!(cos_r > 0.0)) return 0;
        pdf = cos_r * CDL_INV_PI;
        /* on the surface d may round above R: the root from inside at q = 0 */
        out->distance = sphere_hit_from_inside(cdl_vec3_dot(dir, c), fmin(0.0, (d - R) * (d + R)));
    } else {
        if (!(d > R)) return 0;
        cdl_frame f = cdl_frame_from_normal(cdl_vec3_scale(c, 1.0 / d));
        /* Uniform in the cone: 1 - cos(theta) uniform in [0, 1 - cos sigma]. */
        double omc_max = sphere_cone_one_minus_cos(d, R);
        double omc = u1 * omc_max;
        double sin_t = sqrt(fmax(0.0, omc * (2.0 - omc))), phi = CDL_TWO_PI * u2;
        dir = cdl_frame_to_world(&f, cdl_vec3_make(sin_t * cos(phi), sin_t * sin(phi), 1.0 - omc));
        if (!(cdl_vec3_dot(n, dir) > 0.0)) return 0;
        pdf = 1.0 / (CDL_TWO_PI * omc_max);
        double t = sphere_hit_from_outside(cdl_vec3_dot(dir, c), (d - R) * (d + R));
        /* Rounding can leave a direction at the very rim just outside: take the tangent point. */
        out->distance = t > 0.0 ? t : sqrt((d - R) * (d + R));
    }
    out->to_light = dir;
    out->L = cdl_nits(a->L);
    out->pdf = pdf;
    return a->L > 0.0 && out->distance > 0.0;
}

static int area_sample(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out)
{
    const area_emitter *a = as_area(e);
    switch (a->shape) {
    case CDL_SHAPE_TRIANGLES: {
        if (a->tri_count <= SOLID_ANGLE_MAX_TRIANGLES) return sample_triangles_by_solid_angle(a, p, n, u1, u2, out);
        /* A triangle by area; u1 rescaled within its share keeps (u1, u2) stratified. */
        double ur;
        const area_triangle *t = &a->tris[cdl_distribution_invert_cdf(a->cdf, a->tri_count, u1, &ur)];
        double b0, b1;
        cdl_sample_uniform_triangle(ur, u2, &b0, &b1);
        double b2 = 1.0 - b0 - b1;
        /* x - p = (v0 - p) + b1 e1 + b2 e2 */
        cdl_vec3 w = cdl_vec3_madd(cdl_vec3_madd(cdl_vec3_sub(t->v0, p), b1, t->e1), b2, t->e2);
        return finish_point_sample(a, w, t->normal, 1.0 / a->area, n, out);
    }
    case CDL_SHAPE_RECT: {
        if (!(cdl_vec3_dot(a->frame.n, cdl_vec3_sub(p, a->origin)) > 0.0)) return 0; /* behind: dark */
        cdl_spherical_rectangle sr;
        if (rect_uses_solid_angle(a, p, &sr)) {
            cdl_vec3 w = cdl_spherical_rectangle_sample(&sr, u1, u2);
            if (!finish_point_sample(a, w, a->frame.n, 1.0 / a->area, n, out)) return 0;
            out->pdf = 1.0 / sr.S;
            return 1;
        }
        cdl_vec3 w = cdl_vec3_madd(cdl_vec3_madd(cdl_vec3_sub(a->origin, p), u1, a->u), u2, a->v);
        return finish_point_sample(a, w, a->frame.n, 1.0 / a->area, n, out);
    }
    case CDL_SHAPE_DISK: {
        if (disk_uses_cosine(a, p, n)) {
            cdl_frame f = cdl_frame_from_normal(n);
            cdl_vec3 dir = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u1, u2));
            cdl_vec3 off;
            double t = ray_plane(a, a->center, p, dir, &off);
            if (!(t > 0.0) || cdl_vec3_length(off) > a->radius) return 0; /* missed the disk */
            if (!finish_point_sample(a, cdl_vec3_scale(dir, t), a->frame.n, 1.0 / a->area, n, out)) return 0;
            out->pdf = cdl_vec3_dot(n, out->to_light) * CDL_INV_PI;
            return out->pdf > 0.0;
        }
        double x, y;
        concentric_disk(u1, u2, &x, &y);
        cdl_vec3 w = cdl_vec3_madd(cdl_vec3_madd(cdl_vec3_sub(a->center, p), a->radius * x, a->frame.s),
                                   a->radius * y, a->frame.t);
        return finish_point_sample(a, w, a->frame.n, 1.0 / a->area, n, out);
    }
    case CDL_SHAPE_SPHERE:
        return sample_sphere(a, p, n, u1, u2, out);
    }
    return 0;
}

/* ---- radiance along a ray ------------------------------------------------------ */

static cdl_luminance area_radiance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 w, double *pdf)
{
    const area_emitter *a = as_area(e);
    double t = -1.0;
    cdl_vec3 m = a->frame.n;
    size_t hit = 0;
    switch (a->shape) {
    case CDL_SHAPE_TRIANGLES:
        /* The nearest triangle along the ray is the point seen. */
        for (size_t i = 0; i < a->tri_count; ++i) {
            double ti = ray_triangle(&a->tris[i], p, w);
            if (ti > 0.0 && (t < 0.0 || ti < t)) {
                t = ti;
                hit = i;
                m = a->tris[i].normal;
            }
        }
        break;
    case CDL_SHAPE_RECT: {
        cdl_vec3 off;
        double ti = ray_plane(a, a->origin, p, w, &off);
        if (ti > 0.0) {
            /* Coordinates (s, t) of the hit in the (u, v) basis. */
            double uu = cdl_vec3_dot(a->u, a->u), uv = cdl_vec3_dot(a->u, a->v), vv = cdl_vec3_dot(a->v, a->v);
            double ou = cdl_vec3_dot(off, a->u), ov = cdl_vec3_dot(off, a->v);
            double det = uu * vv - uv * uv;
            double s = (ou * vv - ov * uv) / det, tt = (ov * uu - ou * uv) / det;
            if (s >= 0.0 && s <= 1.0 && tt >= 0.0 && tt <= 1.0) t = ti;
        }
        break;
    }
    case CDL_SHAPE_DISK: {
        cdl_vec3 off;
        double ti = ray_plane(a, a->center, p, w, &off);
        if (ti > 0.0 && cdl_vec3_length(off) <= a->radius) t = ti;
        break;
    }
    case CDL_SHAPE_SPHERE: {
        cdl_vec3 c = cdl_vec3_sub(a->center, p);
        double d = cdl_vec3_length(c), R = a->radius;
        if (a->inward) {
            if (!sphere_inside_seen(a, p, n)) return cdl_nits(0.0);
            *pdf = fmax(0.0, cdl_vec3_dot(n, w)) * CDL_INV_PI;
            return cdl_nits(a->L);
        }
        if (!(d > R) || !(sphere_hit_from_outside(cdl_vec3_dot(w, c), (d - R) * (d + R)) > 0.0))
            return cdl_nits(0.0);
        *pdf = 1.0 / (CDL_TWO_PI * sphere_cone_one_minus_cos(d, R));
        return cdl_nits(a->L);
    }
    }
    if (!(t > 0.0)) return cdl_nits(0.0);
    double cos_e = -cdl_vec3_dot(m, w);
    if (!(cos_e > 0.0)) return cdl_nits(0.0); /* the back of the emitter: dark */
    /* The density sample() gives this point, in solid angle. */
    cdl_spherical_rectangle sr;
    if (a->shape == CDL_SHAPE_TRIANGLES && a->tri_count <= SOLID_ANGLE_MAX_TRIANGLES) {
        double omega[SOLID_ANGLE_MAX_TRIANGLES];
        double total = facing_solid_angles(a, p, omega);
        *pdf = total > 0.0 ? triangle_solid_angle_pdf(&a->tris[hit], omega[hit], total, t, cos_e) : 0.0;
    } else if (a->shape == CDL_SHAPE_RECT && rect_uses_solid_angle(a, p, &sr)) {
        *pdf = 1.0 / sr.S;
    } else if (a->shape == CDL_SHAPE_DISK && disk_uses_cosine(a, p, n)) {
        *pdf = fmax(0.0, cdl_vec3_dot(n, w)) * CDL_INV_PI;
    } else {
        *pdf = t / cos_e * t / a->area;
    }
    return cdl_nits(a->L);
}

/* ---- construction ------------------------------------------------------------- */

static void area_destroy(cdl_emitter *e)
{
    area_emitter *a = (area_emitter *)e;
    free(a->tris);
    free(a->cdf);
}

static const cdl_emitter_ops area_ops = {area_flux, area_intensity, NULL, area_exact, area_sample, area_radiance,
                                         area_destroy, NULL, NULL};

static cdl_status build_triangles(area_emitter *a, const cdl_shape *s, cdl_error *err)
{
    if (s->vertex_count < 3 || s->triangle_count < 1 || !s->vertices || !s->triangles)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "area emitter: triangles: expected at least 3 vertices and 1 triangle, found %zu and %zu",
                             s->vertex_count, s->triangle_count);
    for (size_t i = 0; i < 3 * s->vertex_count; ++i)
        if (!isfinite(s->vertices[i]))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "area emitter: vertex %zu: expected finite coordinates in metres, found %g", i / 3,
                                 s->vertices[i]);
    a->tris = malloc(s->triangle_count * sizeof *a->tris);
    a->cdf = malloc(s->triangle_count * sizeof *a->cdf);
    if (!a->tris || !a->cdf) return cdl_error_out_of_memory(err);
    double total = 0.0;
    size_t kept = 0;
    for (size_t i = 0; i < s->triangle_count; ++i) {
        const uint32_t *idx = &s->triangles[3 * i];
        cdl_vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            if (idx[k] >= s->vertex_count)
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "area emitter: triangle %zu: expected vertex indices below %zu, found %u", i,
                                     s->vertex_count, (unsigned)idx[k]);
            const double *x = &s->vertices[3 * (size_t)idx[k]];
            v[k] = cdl_vec3_make(x[0], x[1], x[2]);
        }
        area_triangle t;
        t.v0 = v[0];
        t.e1 = cdl_vec3_sub(v[1], v[0]);
        t.e2 = cdl_vec3_sub(v[2], v[0]);
        cdl_vec3 cr = cdl_vec3_cross(t.e1, t.e2);
        t.area = 0.5 * cdl_vec3_length(cr);
        if (!(t.area > 0.0)) continue; /* degenerate: emits nothing */
        t.normal = cdl_vec3_normalize(cr);
        a->tris[kept] = t;
        total += t.area;
        a->cdf[kept++] = total;
    }
    if (!(total > 0.0) || !isfinite(total))
        return cdl_error_set(err, CDL_ERR_INPUT, "area emitter: triangles: expected a positive total area, found %g m^2",
                             total);
    for (size_t i = 0; i < kept; ++i) a->cdf[i] /= total;
    a->cdf[kept - 1] = 1.0;
    a->tri_count = kept;
    a->area = total;
    return CDL_OK;
}

static cdl_status build_shape(area_emitter *a, const cdl_shape *s, cdl_error *err)
{
    cdl_status st;
    switch (s->kind) {
    case CDL_SHAPE_TRIANGLES:
        return build_triangles(a, s, err);
    case CDL_SHAPE_RECT: {
        if ((st = cdl_emitter_check_position(s->origin, "area emitter: rect origin", err)) != CDL_OK) return st;
        if ((st = cdl_emitter_check_position(s->u, "area emitter: rect u", err)) != CDL_OK) return st;
        if ((st = cdl_emitter_check_position(s->v, "area emitter: rect v", err)) != CDL_OK) return st;
        cdl_vec3 cr = cdl_vec3_cross(s->u, s->v);
        a->area = cdl_vec3_length(cr);
        if (!(a->area > 0.0) || !isfinite(a->area))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "area emitter: rect: expected non-parallel u and v spanning a positive area, found "
                                 "area %g m^2",
                                 a->area);
        a->origin = s->origin;
        a->u = s->u;
        a->v = s->v;
        /* Orthogonal to rounding: |cos(u, v)| below 1e-12. */
        a->rect_is_rectangle =
            fabs(cdl_vec3_dot(s->u, s->v)) <= 1e-12 * cdl_vec3_length(s->u) * cdl_vec3_length(s->v);
        a->frame.n = cdl_vec3_normalize(cr);
        return CDL_OK;
    }
    case CDL_SHAPE_DISK: {
        cdl_vec3 m;
        if ((st = cdl_emitter_check_position(s->center, "area emitter: disk center", err)) != CDL_OK) return st;
        if ((st = cdl_emitter_check_direction(s->normal, "area emitter: disk normal", &m, err)) != CDL_OK) return st;
        if (!(isfinite(s->radius) && s->radius > 0.0))
            return cdl_error_set(err, CDL_ERR_INPUT, "area emitter: disk radius: expected a finite number > 0 m, found %g",
                                 s->radius);
        a->center = s->center;
        a->radius = s->radius;
        a->frame = cdl_frame_from_normal(m);
        a->area = CDL_PI * s->radius * s->radius;
        return CDL_OK;
    }
    case CDL_SHAPE_SPHERE:
        if ((st = cdl_emitter_check_position(s->center, "area emitter: sphere center", err)) != CDL_OK) return st;
        if (!(isfinite(s->radius) && s->radius > 0.0))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "area emitter: sphere radius: expected a finite number > 0 m, found %g", s->radius);
        a->center = s->center;
        a->radius = s->radius;
        a->inward = s->inward ? 1 : 0;
        a->area = CDL_FOUR_PI * s->radius * s->radius;
        return CDL_OK;
    }
    return cdl_error_set(err, CDL_ERR_INPUT, "area emitter: shape: expected triangles, rect, disk or sphere, found kind %d",
                         (int)s->kind);
}

cdl_status cdl_emitter_create_area(const cdl_area_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status st;
    if ((st = cdl_emitter_check_nonnegative(p->luminance.cd_m2, "area emitter: luminance", "cd/m^2", err)) != CDL_OK)
        return st;
    area_emitter *a = cdl_emitter_alloc(sizeof *a, CDL_EMITTER_AREA, &area_ops, err);
    if (!a) return CDL_ERR_INTERNAL;
    a->shape = p->shape.kind;
    a->L = p->luminance.cd_m2;
    if ((st = build_shape(a, &p->shape, err)) != CDL_OK) {
        cdl_emitter_release(&a->base);
        return st;
    }
    *out = &a->base;
    return CDL_OK;
}
