/* spherical_triangle.c - triangle solid angles and uniform sampling (see the header). */
#include "lights/emitters/spherical_triangle.h"

#include <math.h>

double cdl_triangle_solid_angle(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    double la = cdl_vec3_length(a), lb = cdl_vec3_length(b), lc = cdl_vec3_length(c);
    /* a . (b x c) = a . ((b - a) x (c - a)): edges, not long position vectors, are crossed. */
    double triple = cdl_vec3_dot(a, cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
    double den = la * lb * lc + cdl_vec3_dot(a, b) * lc + cdl_vec3_dot(a, c) * lb + cdl_vec3_dot(b, c) * la;
    /* Van Oosterom-Strackee; atan2 takes the branch for solid angles above pi. */
    return 2.0 * atan2(fabs(triple), den);
}

/* Unit vector along v minus its component along unit u (a tangent at u). */
static cdl_vec3 tangent(cdl_vec3 u, cdl_vec3 v)
{
    return cdl_vec3_normalize(cdl_vec3_madd(v, -cdl_vec3_dot(v, u), u));
}

double cdl_spherical_triangle_init(cdl_spherical_triangle *t, cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    t->S = cdl_triangle_solid_angle(a, b, c);
    t->A = cdl_vec3_normalize(a);
    t->B = cdl_vec3_normalize(b);
    t->C = cdl_vec3_normalize(c);
    /* The interior angle at A, between the tangents towards B and towards C. */
    cdl_vec3 tB = tangent(t->A, t->B);
    t->tC = tangent(t->A, t->C);
    t->alpha = atan2(cdl_vec3_length(cdl_vec3_cross(tB, t->tC)), cdl_vec3_dot(tB, t->tC));
    t->cos_alpha = cos(t->alpha);
    t->sin_alpha = sin(t->alpha);
    t->cos_c = cdl_vec3_dot(t->A, t->B);
    return t->S;
}

cdl_vec3 cdl_spherical_triangle_sample(const cdl_spherical_triangle *t, double u1, double u2)
{
    /* Arvo 1995, fig. 2: choose the sub-triangle A B C' of area u1 S (its
     * vertex C' on the arc AC), then a point on the arc B C' so that the
     * area swept is linear in u2. */
    double area = u1 * t->S;
    double s = sin(area - t->alpha), c = cos(area - t->alpha);
    double u = c - t->cos_alpha, v = s + t->sin_alpha * t->cos_c;
    double den = (v * s + u * c) * t->sin_alpha;
    double q = den != 0.0 ? ((v * c - u * s) * t->cos_alpha - v) / den : 1.0;
    q = fmax(-1.0, fmin(1.0, q));
    cdl_vec3 Cp = cdl_vec3_add(cdl_vec3_scale(t->A, q), cdl_vec3_scale(t->tC, sqrt(fmax(0.0, 1.0 - q * q))));
    double z = 1.0 - u2 * (1.0 - cdl_vec3_dot(Cp, t->B));
    z = fmax(-1.0, fmin(1.0, z));
    cdl_vec3 tb = cdl_vec3_madd(Cp, -cdl_vec3_dot(Cp, t->B), t->B);
    double len = cdl_vec3_length(tb);
    if (!(len > 0.0)) return t->B;
    return cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_scale(t->B, z), cdl_vec3_scale(tb, sqrt(fmax(0.0, 1.0 - z * z)) / len)));
}
