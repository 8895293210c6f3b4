/* glare_source.c - a luminaire's luminous parts seen from an eye (CIE 117:1995 4.5). */
#include <math.h>
#include <string.h>

#include "glare/glare_source.h"
#include "radiometry/constants.h"

void cdl_glare_observer_coordinates(const cdl_glare_observer *o, cdl_vec3 q, double *R, double *T, double *H)
{
    cdl_vec3 d = cdl_vec3_sub(q, o->eye), up = cdl_vec3_make(0.0, 0.0, 1.0);
    cdl_vec3 right = cdl_vec3_cross(o->forward, up);
    *R = cdl_vec3_dot(d, o->forward);
    *T = cdl_vec3_dot(d, right);
    *H = d.z;
}

static void add(cdl_glare_parts *parts, cdl_glare_piece_kind kind, cdl_vec3 c, cdl_vec3 u, cdl_vec3 v)
{
    cdl_glare_piece p = {kind, c, u, v, 0};
    parts->piece[parts->count++] = p;
}

/* A face of a solid, seen only from outside: u x v along `outward`. */
static void add_face(cdl_glare_parts *parts, cdl_vec3 c, cdl_vec3 u, cdl_vec3 v, cdl_vec3 outward)
{
    if (cdl_vec3_dot(cdl_vec3_cross(u, v), outward) < 0.0) v = cdl_vec3_neg(v);
    add(parts, CDL_GLARE_PIECE_PARALLELOGRAM, c, u, v);
    parts->piece[parts->count - 1].one_sided = 1;
}

/* A box's faces about its centre c (axes ax, half sizes h), each side
 * luminous from the bottom up to its own height (side k faces C0, C90,
 * C180, C270); the eye sees at most three, which do not overlap. */
static void box_parts(const cdl_vec3 ax[3], cdl_vec3 c, const cdl_luminous_opening *o, cdl_glare_parts *parts)
{
    double h[3] = {0.5 * o->length_m, 0.5 * o->width_m, 0.0};
    for (int k = 0; k < 4; ++k) h[2] = fmax(h[2], 0.5 * cdl_luminous_opening_box_side_height_m(o, k));
    for (int z = -1; z <= 1; z += 2)
        add_face(parts, cdl_vec3_madd(c, z * h[2], ax[2]), cdl_vec3_scale(ax[0], h[0]), cdl_vec3_scale(ax[1], h[1]),
                 cdl_vec3_scale(ax[2], z));
    for (int k = 0; k < 4; ++k) {
        int axis = k % 2;           /* 0: an x face (C0, C180), 1: a y face (C90, C270) */
        double side = k < 2 ? 1.0 : -1.0;
        double top = -h[2] + cdl_luminous_opening_box_side_height_m(o, k), half = 0.5 * (top + h[2]);
        if (!(half > 0.0)) continue;
        cdl_vec3 centre = cdl_vec3_madd(cdl_vec3_madd(c, side * h[axis], ax[axis]), 0.5 * (top - h[2]), ax[2]);
        add_face(parts, centre, cdl_vec3_scale(ax[1 - axis], h[1 - axis]), cdl_vec3_scale(ax[2], half),
                 cdl_vec3_scale(ax[axis], side));
    }
}

/* A disk about c facing the eye (unit direction to it: to_eye) of radius r. */
static void facing_disk(cdl_vec3 c, cdl_vec3 to_eye, double r, cdl_glare_parts *parts)
{
    cdl_vec3 a = fabs(to_eye.z) < 0.9 ? cdl_vec3_make(0, 0, 1) : cdl_vec3_make(1, 0, 0);
    cdl_vec3 s = cdl_vec3_normalize(cdl_vec3_cross(a, to_eye)), t = cdl_vec3_cross(to_eye, s);
    add(parts, CDL_GLARE_PIECE_ELLIPSE, c, cdl_vec3_scale(s, r), cdl_vec3_scale(t, r));
}

void cdl_glare_opening_parts(const cdl_glare_luminaire *l, cdl_vec3 eye, cdl_glare_parts *parts, int *exact)
{
    const cdl_luminous_opening *o = cdl_photometry_opening(l->photometry);
    const cdl_vec3 *ax = l->axis;
    cdl_vec3 c = l->position;
    double L = o->length_m, W = o->width_m, Hh = o->height_m;
    parts->count = 0;
    *exact = 1;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE:
        add(parts, CDL_GLARE_PIECE_PARALLELOGRAM, c, cdl_vec3_scale(ax[0], 0.5 * L), cdl_vec3_scale(ax[1], 0.5 * W));
        return;
    case CDL_LUMINOUS_SHAPE_CIRCLE:
        add(parts, CDL_GLARE_PIECE_ELLIPSE, c, cdl_vec3_scale(ax[0], 0.5 * W), cdl_vec3_scale(ax[1], 0.5 * W));
        return;
    case CDL_LUMINOUS_SHAPE_ELLIPSE:
        add(parts, CDL_GLARE_PIECE_ELLIPSE, c, cdl_vec3_scale(ax[0], 0.5 * L), cdl_vec3_scale(ax[1], 0.5 * W));
        return;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE:
        add(parts, CDL_GLARE_PIECE_ELLIPSE, c, cdl_vec3_scale(ax[1], 0.5 * W), cdl_vec3_scale(ax[2], 0.5 * Hh));
        return;
    case CDL_LUMINOUS_SHAPE_BOX: box_parts(ax, c, o, parts); return;
    case CDL_LUMINOUS_SHAPE_POINT:
    case CDL_LUMINOUS_SHAPE_UNKNOWN: return;
    default: break;
    }
    cdl_vec3 w = cdl_vec3_sub(eye, c);
    double d = cdl_vec3_length(w);
    if (!(d > 0.0)) return;
    cdl_vec3 to_eye = cdl_vec3_scale(w, 1.0 / d);
    if (o->shape == CDL_LUMINOUS_SHAPE_SPHERE) {
        /* the tangent cone of a sphere of radius a at distance d cuts the
         * plane through its centre in a circle of radius a d / sqrt(d^2 - a^2) */
        double a = 0.5 * W;
        if (d > a) facing_disk(c, to_eye, a * d / sqrt(d * d - a * a), parts);
        return;
    }
    /* cylinders and ellipsoids: the disk of their projected area */
    cdl_vec3 local = cdl_vec3_make(cdl_vec3_dot(w, ax[0]), cdl_vec3_dot(w, ax[1]), cdl_vec3_dot(w, ax[2]));
    double A = cdl_luminous_opening_projected_area(o, local);
    if (A > 0.0) facing_disk(c, to_eye, sqrt(A / CDL_PI), parts);
    *exact = 0;
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
    const cdl_luminous_opening *op = cdl_photometry_opening(l->photometry);
    s->projected_area_m2 = cdl_luminous_opening_projected_area(op, local);
    if (!(s->projected_area_m2 > 0.0)) return;
    /* L = I / A_p: the luminance of the source seen as a whole */
    s->luminance = cdl_nits(s->intensity.cd / s->projected_area_m2);
    cdl_glare_parts parts;
    cdl_glare_opening_parts(l, o->eye, &parts, &s->omega_exact);
    s->omega_sr = cdl_glare_parts_solid_angle(&parts, o->eye, NULL);
    if (s->zone == CDL_GLARE_IN_VIEW) s->term = cdl_ugr_term_make(s->luminance, 0.0, s->omega_sr, 0.0, s->p);
}
