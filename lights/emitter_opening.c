/* emitter_opening.c - a goniometric luminaire spread over its luminous opening.
 *
 *   parameter   meaning                                        unit  range
 *   (all of cdl_goniometric_params; the opening is the photometry's)
 *
 * Near a luminaire its size matters: the file's distribution I(w) is the
 * far-field intensity of the whole opening. Spread over a flat opening of
 * area A (rectangle, circle or ellipse, in the luminaire's z = 0 plane
 * around the photometric centre; length along C0-C180 = luminaire x, width
 * along C90-C270 = y), every element dA emits the intensity dI(w) =
 * I(w) dA / A towards w, the same distribution from every point (the
 * model of IES LM-63's luminous opening as Radiance, DIALux and Relux use
 * it). Its luminance is L(w) = dI / (dA |cos theta_o|) = I(w) / (A |cos
 * theta_o|), theta_o between w and the opening's normal: the light going
 * down (gamma < 90) leaves the lower face, any going up the upper face, so
 * the flux is the file's exactly. A Lambertian table I = I0 cos(gamma) on
 * the lower face is a Lambertian area emitter of luminance I0 / A.
 *
 * Illuminance at p on the plane of n (the inverse-square law summed over
 * the opening's elements):
 *     E(p, n) = (1 / A) int_opening I(w_x) cos(theta_r) / r_x^2 dA_x,
 * the mean over the opening of the point-source illuminance from each of
 * its points. Closed form where the table is Lambertian on a rectangle or
 * circle (Lambert's contour integral, the area emitter's; exact
 * illuminance below); otherwise sampled (cdl_emitter_sample): rectangles
 * and circles by the area emitter's samplers of the face p sees (uniform
 * in solid angle near a rectangle, cosine-weighted near a large disk, by
 * area far away), ellipses by those of their bounding rectangle (samples
 * outside the ellipse carry nothing), each sample's luminance
 * I(w) / (A |cos theta_o|).
 */
#include <math.h>
#include <string.h>

#include "lights/emitter.h"
#include "lights/emitter_internal.h"
#include "radiometry/constants.h"

/* Relative tolerance of a table sample from I0 cos(gamma) for the table to
 * count as Lambertian: the closed form then differs from the sampled
 * integral of the interpolated table by the table's interpolation error
 * (about (step)^2 / 8 relative for linear steps, 4e-5 at 1 degree). */
#define LAMBERT_TOLERANCE 1e-6

typedef struct opening_emitter {
    cdl_emitter base;
    cdl_emitter *point;        /* the same luminaire as a point: I(w) */
    cdl_emitter *face[2];      /* unit-luminance area emitters (an ellipse's bounding rectangle): [0] faces the nadir, [1] up */
    cdl_luminous_shape shape;
    cdl_vec3 center;
    cdl_vec3 axis[3];          /* the luminaire's x (length), y (width), z (up) in world */
    double half_length, half_width;
    double area;
    int lambertian;            /* I = I0 cos(gamma) below, 0 above: closed form */
    double lambert_luminance;  /* I0 / A */
} opening_emitter;

static const opening_emitter *as_opening(const cdl_emitter *e)
{
    return (const opening_emitter *)e;
}

static cdl_luminous_flux opening_flux(const cdl_emitter *e)
{
    return cdl_emitter_flux(as_opening(e)->point);
}

static cdl_luminous_intensity opening_intensity(const cdl_emitter *e, cdl_vec3 unit_dir)
{
    return cdl_emitter_intensity(as_opening(e)->point, unit_dir);
}

/* Luminance along the emission direction w (unit, away from the opening):
 * L = I(w) / (A |cos theta_o|). */
static double opening_luminance_towards(const opening_emitter *o, cdl_vec3 w)
{
    /* A Lambertian table is taken as the cosine it samples, the same for
     * its samples as for its closed form (the table's linear interpolation
     * lies up to (step)^2 / 8 below it: 4e-5 at 1-degree steps), so that a
     * partly hidden opening's E_0 - H is exactly 0 where all of it is hidden. */
    if (o->lambertian) return cdl_vec3_dot(w, o->axis[2]) < 0.0 ? o->lambert_luminance : 0.0;
    double c = fabs(cdl_vec3_dot(w, o->axis[2]));
    if (!(c > 0.0)) return 0.0;
    return cdl_emitter_intensity(o->point, w).cd / (o->area * c);
}

static int opening_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    const opening_emitter *o = as_opening(e);
    cdl_illuminance unit;
    if (cdl_emitter_exact_illuminance(o->face[0], p, n, &unit, NULL) != CDL_OK) return 0;
    /* E = L Omega_p (Lambert), L = I0 / A */
    *E = cdl_lux(unit.lx * o->lambert_luminance);
    return 1;
}

/* The face p sees: 0 below the opening's plane, 1 above, -1 in it. */
static int face_seen(const opening_emitter *o, cdl_vec3 p)
{
    double s = cdl_vec3_dot(cdl_vec3_sub(p, o->center), o->axis[2]);
    return s < 0.0 ? 0 : s > 0.0 ? 1 : -1;
}

/* Is the point of the opening's plane that the ray from p along unit dir
 * meets inside the ellipse? (Rectangles and circles: always, their face
 * emitters already tested it.) */
static int inside_opening(const opening_emitter *o, cdl_vec3 p, cdl_vec3 dir)
{
    if (o->shape != CDL_LUMINOUS_SHAPE_ELLIPSE) return 1;
    double along = cdl_vec3_dot(dir, o->axis[2]);
    /* the ray meets the plane at t = (c - p).z / dir.z */
    double t = cdl_vec3_dot(cdl_vec3_sub(o->center, p), o->axis[2]) / along;
    if (!(t > 0.0) || !isfinite(t)) return 0;
    cdl_vec3 h = cdl_vec3_sub(cdl_vec3_madd(p, t, dir), o->center);
    double x = cdl_vec3_dot(h, o->axis[0]) / o->half_length, y = cdl_vec3_dot(h, o->axis[1]) / o->half_width;
    return x * x + y * y <= 1.0;
}

/* Samples of the face p sees (an ellipse: of its bounding rectangle, those
 * outside the ellipse carrying nothing), each with the luminance
 * I(w) / (A |cos theta_o|) of its direction. */
static int opening_sample(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out)
{
    const opening_emitter *o = as_opening(e);
    int f = face_seen(o, p);
    if (f < 0 || !cdl_emitter_sample(o->face[f], p, n, u1, u2, out) || !inside_opening(o, p, out->to_light)) return 0;
    out->L = cdl_nits(opening_luminance_towards(o, cdl_vec3_neg(out->to_light)));
    return out->L.cd_m2 > 0.0 && out->pdf > 0.0;
}

static cdl_luminance opening_radiance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double *pdf)
{
    const opening_emitter *o = as_opening(e);
    *pdf = 0.0;
    int f = face_seen(o, p);
    if (f < 0 || !inside_opening(o, p, dir) || !(cdl_emitter_radiance(o->face[f], p, n, dir, pdf).cd_m2 > 0.0))
        return cdl_nits(0.0);
    return cdl_nits(opening_luminance_towards(o, cdl_vec3_neg(dir)));
}

static void opening_destroy(cdl_emitter *e)
{
    opening_emitter *o = (opening_emitter *)e;
    cdl_emitter_release(o->point);
    cdl_emitter_release(o->face[0]);
    cdl_emitter_release(o->face[1]);
}

/* Lambertian tables have the closed form; others are sampled only. */
static const cdl_emitter_ops lambertian_ops = {opening_flux,     opening_intensity, NULL, opening_exact, opening_sample,
                                               opening_radiance, opening_destroy,   NULL, NULL};
static const cdl_emitter_ops sampled_ops = {opening_flux,     opening_intensity, NULL, NULL, opening_sample,
                                            opening_radiance, opening_destroy,   NULL, NULL};

/* Is the table I0 cos(gamma) for gamma <= 90 and dark above, in every
 * plane (type C)? *I0 receives the table's nadir value. */
static int table_is_lambertian(const cdl_photometry *ph, double *I0)
{
    cdl_photometry_table t;
    cdl_photometry_get_table(ph, &t);
    if (t.type != CDL_PHOTOMETRIC_TYPE_C || t.vertical_count < 2 || t.vertical_deg[0] != 0.0) return 0;
    double i0 = t.candela[0];
    if (!(i0 > 0.0)) return 0;
    for (size_t h = 0; h < t.horizontal_count; ++h)
        for (size_t v = 0; v < t.vertical_count; ++v) {
            double g = t.vertical_deg[v];
            double want = g < 90.0 ? i0 * cos(g * CDL_DEG_TO_RAD) : 0.0;
            if (fabs(t.candela[h * t.vertical_count + v] - want) > LAMBERT_TOLERANCE * i0) return 0;
        }
    *I0 = i0;
    return 1;
}

/* The opening (an ellipse: its bounding rectangle) as an area shape
 * facing -z (down) or +z. */
static cdl_shape face_shape(const opening_emitter *o, int up)
{
    cdl_shape shape;
    memset(&shape, 0, sizeof shape);
    cdl_shape *a = &shape;
    cdl_vec3 x = cdl_vec3_scale(o->axis[0], 2.0 * o->half_length), y = cdl_vec3_scale(o->axis[1], 2.0 * o->half_width);
    if (o->shape != CDL_LUMINOUS_SHAPE_CIRCLE) {
        a->kind = CDL_SHAPE_RECT;
        a->origin = cdl_vec3_sub(o->center, cdl_vec3_scale(cdl_vec3_add(x, y), 0.5));
        /* the emitting side is u x v: y x x = -z (down), x x y = +z (up) */
        a->u = up ? x : y;
        a->v = up ? y : x;
    } else {
        a->kind = CDL_SHAPE_DISK;
        a->center = o->center;
        a->normal = up ? o->axis[2] : cdl_vec3_neg(o->axis[2]);
        a->radius = o->half_width;
    }
    return shape;
}

/* A unit-luminance area emitter over the opening facing -z (down) or +z. */
static cdl_status make_face(const opening_emitter *o, int up, cdl_emitter **out, cdl_error *err)
{
    cdl_area_params a;
    memset(&a, 0, sizeof a);
    a.luminance = cdl_nits(1.0);
    a.shape = face_shape(o, up);
    return cdl_emitter_create_area(&a, out, err);
}

int cdl_emitter_opening_face(const cdl_emitter *emitter, cdl_shape *face)
{
    if (emitter->kind != CDL_EMITTER_GONIOMETRIC_OPENING) return 0;
    *face = face_shape(as_opening(emitter), 0);
    return 1;
}

cdl_status cdl_emitter_create_goniometric_opening(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    if (!p->photometry)
        return cdl_error_set(err, CDL_ERR_USAGE, "goniometric emitter: photometry: expected a table, found NULL");
    const cdl_luminous_opening *op = &cdl_photometry_get_metadata(p->photometry)->opening;
    if (!cdl_luminous_opening_is_flat(op))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "goniometric emitter: opening: expected a rectangle, circle or ellipse of non-zero size "
                             "to spread the light over, found %s %g x %g x %g m",
                             cdl_luminous_shape_name(op->shape), op->width_m, op->length_m, op->height_m);
    cdl_emitter *point = NULL;
    cdl_status st = cdl_emitter_create_goniometric(p, &point, err);
    if (st != CDL_OK) return st;
    opening_emitter *o = cdl_emitter_alloc(sizeof *o, CDL_EMITTER_GONIOMETRIC_OPENING, &sampled_ops, err);
    if (!o) {
        cdl_emitter_release(point);
        return CDL_ERR_INTERNAL;
    }
    o->point = point;
    o->shape = op->shape;
    o->center = p->position;
    cdl_emitter_rotation_columns(p->rotation_deg, o->axis);
    o->half_length = 0.5 * (op->shape == CDL_LUMINOUS_SHAPE_CIRCLE ? op->width_m : op->length_m);
    o->half_width = 0.5 * op->width_m;
    /* rectangle L W; circle and ellipse pi a b */
    o->area = op->shape == CDL_LUMINOUS_SHAPE_RECTANGLE ? 4.0 * o->half_length * o->half_width
                                                         : CDL_PI * o->half_length * o->half_width;
    for (int up = 0; up < 2 && st == CDL_OK; ++up) st = make_face(o, up, &o->face[up], err);
    if (st != CDL_OK) {
        cdl_emitter_release(&o->base);
        return st;
    }
    double I0;
    if (op->shape != CDL_LUMINOUS_SHAPE_ELLIPSE && table_is_lambertian(p->photometry, &I0)) {
        o->lambertian = 1;
        o->base.ops = &lambertian_ops;
        /* the table's I0 with every factor of the placed luminaire */
        o->lambert_luminance = cdl_emitter_intensity(point, cdl_vec3_neg(o->axis[2])).cd / o->area;
    }
    *out = &o->base;
    return CDL_OK;
}
