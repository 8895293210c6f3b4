/* glare_source.c - a luminaire's luminous parts seen from an eye (CIE 117:1995 4.5). */
#include <math.h>
#include <string.h>

#include "glare/glare_source.h"
#include "lights/emitters/spherical_triangle.h"
#include "radiometry/constants.h"

#define ELLIPSE_SIDES 256

void cdl_glare_observer_coordinates(const cdl_glare_observer *o, cdl_vec3 q, double *R, double *T, double *H)
{
    cdl_vec3 d = cdl_vec3_sub(q, o->eye), up = cdl_vec3_make(0.0, 0.0, 1.0);
    cdl_vec3 right = cdl_vec3_cross(o->forward, up);
    *R = cdl_vec3_dot(d, o->forward);
    *T = cdl_vec3_dot(d, right);
    *H = d.z;
}

/* Solid angle at the eye of the parallelogram c +- u +- v (eye-relative c). */
static double parallelogram(cdl_vec3 c, cdl_vec3 u, cdl_vec3 v)
{
    cdl_vec3 a = cdl_vec3_sub(cdl_vec3_sub(c, u), v), b = cdl_vec3_sub(cdl_vec3_add(c, u), v);
    cdl_vec3 d = cdl_vec3_add(cdl_vec3_add(c, u), v), e = cdl_vec3_add(cdl_vec3_sub(c, u), v);
    return cdl_triangle_solid_angle(a, b, d) + cdl_triangle_solid_angle(a, d, e);
}

/* Solid angle of the ellipse c + cos(t) u + sin(t) v (semi-axes u, v): a
 * fan of a regular polygon scaled to the ellipse's area (its radius times
 * sqrt((2 pi / n) / sin(2 pi / n))), whose solid angle then differs from
 * the curve's by O(n^-4) of it. */
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

/* Solid angle of a box's faces the eye sees (it lies outside the box, so
 * they do not overlap): local half sizes h, eye at `eye` in the box's
 * frame about its centre; each side face luminous from the bottom up to its
 * own height. */
static double box(const cdl_glare_luminaire *l, const cdl_luminous_opening *o, cdl_vec3 c)
{
    double h[3] = {0.5 * o->length_m, 0.5 * o->width_m, 0.0};
    for (int k = 0; k < 4; ++k) h[2] = fmax(h[2], 0.5 * cdl_luminous_opening_box_side_height_m(o, k));
    /* the eye in the box's frame (c: the centre relative to the eye) */
    double e[3] = {-cdl_vec3_dot(c, l->axis[0]), -cdl_vec3_dot(c, l->axis[1]), -cdl_vec3_dot(c, l->axis[2])};
    double sum = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(fabs(e[axis]) > h[axis])) continue;
        double side = e[axis] > 0.0 ? 1.0 : -1.0;
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        cdl_vec3 centre = cdl_vec3_add(c, cdl_vec3_scale(l->axis[axis], side * h[axis]));
        cdl_vec3 u = cdl_vec3_scale(l->axis[a1], h[a1]), v = cdl_vec3_scale(l->axis[a2], h[a2]);
        if (axis < 2) {
            /* a side: luminous from the bottom (-h[2]) to its own top */
            int which = axis == 0 ? (side > 0.0 ? 0 : 2) : (side > 0.0 ? 1 : 3);
            double top = -h[2] + cdl_luminous_opening_box_side_height_m(o, which);
            cdl_vec3 z = l->axis[2];
            double mid = 0.5 * (top - h[2]) + 0.0, half = 0.5 * (top + h[2]);
            centre = cdl_vec3_add(centre, cdl_vec3_scale(z, mid));
            if (axis == 0) v = cdl_vec3_scale(z, half); /* a1 = y, a2 = z */
            else u = cdl_vec3_scale(z, half);           /* a1 = z, a2 = x */
            if (!(half > 0.0)) continue;
        }
        sum += parallelogram(centre, u, v);
    }
    return sum;
}

/* The solid angle of the opening at the eye (c: its centre relative to the
 * eye), *exact 1 where it is exact. */
static double opening_solid_angle(const cdl_glare_luminaire *l, const cdl_luminous_opening *o, cdl_vec3 c,
                                  double projected_area, int *exact)
{
    *exact = 1;
    const cdl_vec3 *ax = l->axis;
    double L = o->length_m, W = o->width_m, Hh = o->height_m;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE:
        return parallelogram(c, cdl_vec3_scale(ax[0], 0.5 * L), cdl_vec3_scale(ax[1], 0.5 * W));
    case CDL_LUMINOUS_SHAPE_CIRCLE: return ellipse(c, cdl_vec3_scale(ax[0], 0.5 * W), cdl_vec3_scale(ax[1], 0.5 * W));
    case CDL_LUMINOUS_SHAPE_ELLIPSE:
        return ellipse(c, cdl_vec3_scale(ax[0], 0.5 * L), cdl_vec3_scale(ax[1], 0.5 * W));
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE:
        return ellipse(c, cdl_vec3_scale(ax[1], 0.5 * W), cdl_vec3_scale(ax[2], 0.5 * Hh));
    case CDL_LUMINOUS_SHAPE_BOX: return box(l, o, c);
    case CDL_LUMINOUS_SHAPE_SPHERE: {
        double d = cdl_vec3_length(c), a = 0.5 * W;
        /* the cap a sphere of radius a fills at distance d: 2 pi (1 - cos theta), sin theta = a / d */
        return d > a ? CDL_TWO_PI * (1.0 - sqrt(1.0 - (a / d) * (a / d))) : 0.0;
    }
    default:
        *exact = 0;
        /* CIE 117:1995 4.5: omega = A_p / r^2 */
        return projected_area / cdl_vec3_length_squared(c);
    }
}

void cdl_glare_source_evaluate(const cdl_glare_luminaire *l, const cdl_glare_observer *o, cdl_glare_source *s)
{
    memset(s, 0, sizeof *s);
    cdl_glare_observer_coordinates(o, l->position, &s->R_m, &s->T_m, &s->H_m);
    s->zone = cdl_glare_position_index(s->R_m, s->T_m, s->H_m, &s->p);
    /* the eye's direction from the centre, in the luminaire's frame */
    cdl_vec3 w = cdl_vec3_sub(o->eye, l->position);
    cdl_vec3 local = cdl_vec3_make(cdl_vec3_dot(w, l->axis[0]), cdl_vec3_dot(w, l->axis[1]), cdl_vec3_dot(w, l->axis[2]));
    double len = cdl_vec3_length(local);
    if (!(len > 0.0)) return;
    s->gamma_deg = acos(fmax(-1.0, fmin(1.0, -local.z / len))) * CDL_RAD_TO_DEG;
    s->c_deg = fmod(atan2(local.y, local.x) * CDL_RAD_TO_DEG + 360.0, 360.0);
    s->intensity = cdl_candelas(l->scale * cdl_photometry_intensity(l->photometry, local).cd);
    const cdl_luminous_opening *op = &cdl_photometry_get_metadata(l->photometry)->opening;
    s->projected_area_m2 = cdl_luminous_opening_projected_area(op, local);
    if (s->projected_area_m2 > 0.0) s->luminance = cdl_nits(s->intensity.cd / s->projected_area_m2);
    if (s->projected_area_m2 > 0.0)
        s->omega_sr = opening_solid_angle(l, op, cdl_vec3_neg(w), s->projected_area_m2, &s->omega_exact);
    if (s->zone == CDL_GLARE_IN_VIEW) s->term = cdl_ugr_term_make(s->luminance, 0.0, s->omega_sr, 0.0, s->p);
}
