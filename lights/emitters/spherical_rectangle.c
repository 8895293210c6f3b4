/* spherical_rectangle.c - uniform solid-angle sampling of a rectangle (see the header). */
#include "lights/emitters/spherical_rectangle.h"

#include <math.h>

#include "radiometry/constants.h"

/* Interior angle of the spherical polygon at the vertex shared by two edges
 * whose great circles have unit normals a and b (both pointing into the
 * polygon's exterior side consistently): pi minus the angle between the
 * planes, i.e. acos(-a.b), evaluated as atan2(|a x b|, -a.b). */
static double interior_angle(cdl_vec3 a, cdl_vec3 b)
{
    return atan2(cdl_vec3_length(cdl_vec3_cross(a, b)), -cdl_vec3_dot(a, b));
}

double cdl_spherical_rectangle_init(cdl_spherical_rectangle *r, cdl_vec3 p, cdl_vec3 s0, cdl_vec3 ex, cdl_vec3 ey)
{
    double lx = cdl_vec3_length(ex), ly = cdl_vec3_length(ey);
    r->o = p;
    r->x = cdl_vec3_scale(ex, 1.0 / lx);
    r->y = cdl_vec3_scale(ey, 1.0 / ly);
    r->z = cdl_vec3_cross(r->x, r->y);
    cdl_vec3 d = cdl_vec3_sub(s0, p);
    r->z0 = cdl_vec3_dot(d, r->z);
    if (r->z0 > 0.0) {
        /* Keep the rectangle below the receiver in the local frame. */
        r->z = cdl_vec3_neg(r->z);
        r->z0 = -r->z0;
    }
    r->x0 = cdl_vec3_dot(d, r->x);
    r->y0 = cdl_vec3_dot(d, r->y);
    r->x1 = r->x0 + lx;
    r->y1 = r->y0 + ly;
    r->S = 0.0;
    if (!(r->z0 < 0.0)) return 0.0;
    double z0 = r->z0, z2 = z0 * z0;
    /* Normals of the planes through the receiver and each edge, from the
     * cross products of consecutive corners (worked out by hand):
     * y = y0, x = x1, y = y1, x = x0. */
    cdl_vec3 n0 = cdl_vec3_scale(cdl_vec3_make(0.0, z0, -r->y0), 1.0 / sqrt(z2 + r->y0 * r->y0));
    cdl_vec3 n1 = cdl_vec3_scale(cdl_vec3_make(-z0, 0.0, r->x1), 1.0 / sqrt(z2 + r->x1 * r->x1));
    cdl_vec3 n2 = cdl_vec3_scale(cdl_vec3_make(0.0, -z0, r->y1), 1.0 / sqrt(z2 + r->y1 * r->y1));
    cdl_vec3 n3 = cdl_vec3_scale(cdl_vec3_make(z0, 0.0, -r->x0), 1.0 / sqrt(z2 + r->x0 * r->x0));
    double g0 = interior_angle(n0, n1), g1 = interior_angle(n1, n2), g2 = interior_angle(n2, n3),
           g3 = interior_angle(n3, n0);
    /* Girard's theorem: the area of a spherical quadrilateral is its angle excess. */
    r->S = fmax(0.0, g0 + g1 + g2 + g3 - CDL_TWO_PI);
    r->b0 = n0.z;
    r->b1 = n2.z;
    r->k = CDL_TWO_PI - g2 - g3;
    return r->S;
}

cdl_vec3 cdl_spherical_rectangle_sample(const cdl_spherical_rectangle *r, double u, double v)
{
    /* u: the area of the sub-rectangle [x0, xu] is u S, which fixes xu
     * through the angle of the great circle x = xu (Urena et al., sec. 3). */
    double au = u * r->S + r->k;
    double fu = (cos(au) * r->b0 - r->b1) / sin(au);
    double cu = copysign(1.0, fu) / sqrt(fu * fu + r->b0 * r->b0);
    cu = fmin(1.0, fmax(-1.0, cu));
    double xu = -cu * r->z0 / sqrt(fmax(1e-300, 1.0 - cu * cu));
    if (!isfinite(xu)) xu = r->x0 + u * (r->x1 - r->x0); /* sin(au) = 0 and 0/0: only at measure zero */
    xu = fmin(r->x1, fmax(r->x0, xu));
    /* v: uniform in the height h = y / |(xu, y, z0)| along the segment x = xu
     * (its solid angle is linear in h). */
    double dd = sqrt(xu * xu + r->z0 * r->z0);
    double h0 = r->y0 / sqrt(dd * dd + r->y0 * r->y0), h1 = r->y1 / sqrt(dd * dd + r->y1 * r->y1);
    double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
    double yv = hv2 < 1.0 - 1e-15 ? hv * dd / sqrt(1.0 - hv2) : r->y1;
    yv = fmin(r->y1, fmax(r->y0, yv));
    return cdl_vec3_add(cdl_vec3_add(cdl_vec3_scale(r->x, xu), cdl_vec3_scale(r->y, yv)), cdl_vec3_scale(r->z, r->z0));
}
