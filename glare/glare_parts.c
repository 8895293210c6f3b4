/* glare_parts.c - flat luminous pieces seen from an eye: solid angles and points. */
#include <math.h>

#include "glare/glare_parts.h"
#include "lights/emitters/spherical_triangle.h"
#include "radiometry/constants.h"

#define ELLIPSE_SIDES 256

/* The piece's unnormalised normal (its plane's orientation). */
static cdl_vec3 piece_normal(const cdl_glare_piece *p)
{
    if (p->kind == CDL_GLARE_PIECE_TRIANGLE) return cdl_vec3_cross(cdl_vec3_sub(p->u, p->c), cdl_vec3_sub(p->v, p->c));
    return cdl_vec3_cross(p->u, p->v);
}

/* Solid angle of the ellipse c + cos(t) u + sin(t) v (eye-relative c): a
 * fan of a regular polygon scaled to the ellipse's area (its radius times
 * sqrt((2 pi / n) / sin(2 pi / n))), whose solid angle differs from the
 * curve's by O(n^-4) of it. */
static double ellipse(cdl_vec3 c, cdl_vec3 u, cdl_vec3 v)
{
    double step = CDL_TWO_PI / ELLIPSE_SIDES, k = sqrt(step / sin(step)), sum = 0.0;
    cdl_vec3 prev = cdl_vec3_add(c, cdl_vec3_scale(u, k));
    for (int i = 1; i <= ELLIPSE_SIDES; ++i) {
        double t = i * step;
        cdl_vec3 next = cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(u, k * cos(t)), cdl_vec3_scale(v, k * sin(t))));
        sum += cdl_triangle_solid_angle(c, prev, next);
        prev = next;
    }
    return sum;
}

double cdl_glare_piece_solid_angle(const cdl_glare_piece *p, cdl_vec3 eye)
{
    cdl_vec3 n = piece_normal(p), c = cdl_vec3_sub(p->c, eye);
    double side = -cdl_vec3_dot(n, c); /* > 0: the eye is on the side n faces */
    if (side == 0.0 || (p->one_sided && side < 0.0)) return 0.0;
    switch (p->kind) {
    case CDL_GLARE_PIECE_PARALLELOGRAM: {
        cdl_vec3 a = cdl_vec3_sub(cdl_vec3_sub(c, p->u), p->v), b = cdl_vec3_sub(cdl_vec3_add(c, p->u), p->v);
        cdl_vec3 d = cdl_vec3_add(cdl_vec3_add(c, p->u), p->v), e = cdl_vec3_add(cdl_vec3_sub(c, p->u), p->v);
        return cdl_triangle_solid_angle(a, b, d) + cdl_triangle_solid_angle(a, d, e);
    }
    case CDL_GLARE_PIECE_ELLIPSE: return ellipse(c, p->u, p->v);
    case CDL_GLARE_PIECE_TRIANGLE:
        return cdl_triangle_solid_angle(c, cdl_vec3_sub(p->u, eye), cdl_vec3_sub(p->v, eye));
    }
    return 0.0;
}

double cdl_glare_parts_solid_angle(const cdl_glare_parts *parts, cdl_vec3 eye, double omega[CDL_GLARE_PARTS_MAX])
{
    double total = 0.0;
    for (int i = 0; i < parts->count; ++i) {
        double w = cdl_glare_piece_solid_angle(&parts->piece[i], eye);
        if (omega) omega[i] = w;
        total += w;
    }
    return total;
}

int cdl_glare_parts_sample(const cdl_glare_parts *parts, const double omega[CDL_GLARE_PARTS_MAX], double total,
                           cdl_vec3 eye, const double u[3], cdl_vec3 *point, double *weight)
{
    /* the piece, in proportion to its solid angle */
    double pick = u[0] * total, acc = 0.0;
    int i = 0;
    for (; i < parts->count - 1; ++i) {
        acc += omega[i];
        if (pick < acc) break;
    }
    const cdl_glare_piece *p = &parts->piece[i];
    if (!(omega[i] > 0.0)) return 0;
    double area;
    cdl_vec3 n = piece_normal(p);
    switch (p->kind) {
    case CDL_GLARE_PIECE_PARALLELOGRAM:
        *point = cdl_vec3_add(p->c, cdl_vec3_add(cdl_vec3_scale(p->u, 2.0 * u[1] - 1.0),
                                                  cdl_vec3_scale(p->v, 2.0 * u[2] - 1.0)));
        area = 4.0 * cdl_vec3_length(n);
        break;
    case CDL_GLARE_PIECE_ELLIPSE: {
        /* uniform over the disk, mapped to the ellipse */
        double r = sqrt(u[1]), t = CDL_TWO_PI * u[2];
        *point = cdl_vec3_add(p->c, cdl_vec3_add(cdl_vec3_scale(p->u, r * cos(t)), cdl_vec3_scale(p->v, r * sin(t))));
        area = CDL_PI * cdl_vec3_length(n);
        break;
    }
    default: {
        /* uniform over the triangle (the square folded along its diagonal) */
        double s = u[1], t = u[2];
        if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
        *point = cdl_vec3_add(p->c, cdl_vec3_add(cdl_vec3_scale(cdl_vec3_sub(p->u, p->c), s),
                                                  cdl_vec3_scale(cdl_vec3_sub(p->v, p->c), t)));
        area = 0.5 * cdl_vec3_length(n);
        break;
    }
    }
    cdl_vec3 d = cdl_vec3_sub(*point, eye);
    double r2 = cdl_vec3_length_squared(d);
    if (!(r2 > 0.0) || !(area > 0.0)) return 0;
    /* dOmega / dA = |cos theta| / r^2, over the pdf (omega_i / total) / area */
    double cos_theta = fabs(cdl_vec3_dot(d, n)) / (sqrt(r2) * cdl_vec3_length(n));
    *weight = cos_theta / r2 * area * total / omega[i];
    return 1;
}
