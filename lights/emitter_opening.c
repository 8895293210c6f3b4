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
 * its points. Exact unoccluded E (cdl_emitter_exact_illuminance): Lambert's
 * contour integral (the area emitter's) where the table is Lambertian on a
 * rectangle or circle, else an adaptive cubature of the integral above
 * (below). Samples (cdl_emitter_sample, for shadows): rectangles and
 * circles by the area emitter's samplers of the face p sees (uniform in
 * solid angle near a rectangle, cosine-weighted near a large disk, by area
 * far away), ellipses by those of their bounding rectangle (samples
 * outside the ellipse carry nothing), each sample's luminance
 * I(w) / (A |cos theta_o|).
 */
#include <math.h>
#include <stdlib.h>
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

/* ---- adaptive cubature of E over the opening ------------------------------ *
 *
 * For tables that are not Lambertian, E(p, n) = (1 / A) int I(w_x)
 * max(0, cos theta_r) / r_x^2 dA_x is integrated over the opening's
 * parameter domain (rectangles: x = c + u X + v Y; circles and ellipses:
 * x = c + a rho cos(phi) X + b rho sin(phi) Y, dA = a b rho drho dphi) by
 * tensor Gauss-Legendre rules on cells, 5 x 5 points against 3 x 3 on the
 * same cell as the cell's error estimate (Davis and Rabinowitz, Methods of
 * Numerical Integration, 2nd ed., 1984, ch. 5-6), the cell with the
 * largest estimate split into four until the estimates sum to the
 * tolerance. The
 * 3-point rule is exact to degree 5, the 5-point to degree 9, so |Q5 - Q3|
 * bounds Q5's error generously wherever the integrand is smooth on the
 * cell; the table's bilinear kinks and the receiver's horizon (where
 * cos theta_r reaches 0) are resolved by the splitting. Tolerance: 1e-5 of
 * E (or of a thousandth of the point model's illuminance scale
 * Phi / (4 pi d^2) where E is far smaller), 1/20 of the finest target the
 * solver offers (2e-4, "reference") and 1/100 of "high": its square adds
 * at most 0.25 % to a point's variance at "reference", so the value
 * stands as exact (zero stated error). 1e-6 was tried: a receiver 0.1 m
 * under a disk with a 1-degree table (a circle of kinks per degree) then
 * needed more than the 4096 cells. Where the
 * splitting would exceed CUBATURE_MAX_CELLS the cubature gives up and the
 * caller samples instead. */

#define CUBATURE_TOLERANCE 1e-5
#define CUBATURE_MAX_CELLS 4096

/* Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz and Stegun 25.4.29) */
static const double gl3_x[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
static const double gl3_w[3] = {0.55555555555555555556, 0.88888888888888888889, 0.55555555555555555556};
static const double gl5_x[5] = {-0.90617984593866399280, -0.53846931010568309104, 0.0, 0.53846931010568309104,
                                0.90617984593866399280};
static const double gl5_w[5] = {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                                0.47862867049936646804, 0.23692688505618908751};

typedef struct cubature {
    const opening_emitter *o;
    cdl_vec3 p, n;
    int polar;               /* circle or ellipse: (rho, phi) */
} cubature;

/* The integrand at parameter (u, v): I(w) cos(theta_r) / r^2 times the
 * area element, over A. */
static double cubature_integrand(const cubature *q, double u, double v)
{
    const opening_emitter *o = q->o;
    double x, y, jacobian;
    if (q->polar) {
        x = o->half_length * u * cos(v);
        y = o->half_width * u * sin(v);
        jacobian = o->half_length * o->half_width * u;
    } else {
        x = u;
        y = v;
        jacobian = 1.0;
    }
    cdl_vec3 point = cdl_vec3_add(o->center, cdl_vec3_add(cdl_vec3_scale(o->axis[0], x), cdl_vec3_scale(o->axis[1], y)));
    cdl_vec3 to_light = cdl_vec3_sub(point, q->p);
    double r2 = cdl_vec3_dot(to_light, to_light);
    double along = cdl_vec3_dot(q->n, to_light);
    if (!(along > 0.0) || !(r2 > 0.0)) return 0.0;
    double r = sqrt(r2);
    /* inverse-square and cosine law, I cos(theta_r) / r^2, for the element */
    double I = cdl_emitter_intensity(o->point, cdl_vec3_neg(to_light)).cd;
    return I * along / (r2 * r) * jacobian / o->area;
}

/* Gauss-Legendre rule of k points per side on [u0, u1] x [v0, v1]. */
static double cubature_rule(const cubature *q, const double *xs, const double *ws, int k, double u0, double u1,
                            double v0, double v1)
{
    double hu = 0.5 * (u1 - u0), hv = 0.5 * (v1 - v0), mu = 0.5 * (u0 + u1), mv = 0.5 * (v0 + v1), sum = 0.0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) sum += ws[i] * ws[j] * cubature_integrand(q, mu + hu * xs[i], mv + hv * xs[j]);
    return sum * hu * hv;
}

typedef struct cell {
    double u0, u1, v0, v1;
    double value, error;     /* Q5, |Q5 - Q3| */
} cell;

static cell cubature_cell(const cubature *q, double u0, double u1, double v0, double v1)
{
    cell c = {u0, u1, v0, v1, 0.0, 0.0};
    c.value = cubature_rule(q, gl5_x, gl5_w, 5, u0, u1, v0, v1);
    c.error = fabs(c.value - cubature_rule(q, gl3_x, gl3_w, 3, u0, u1, v0, v1));
    return c;
}

/* A max-heap of cells by error (heap[0] the worst). */
static void heap_push(cell *heap, int *count, cell c)
{
    int i = (*count)++;
    while (i > 0 && heap[(i - 1) / 2].error < c.error) {
        heap[i] = heap[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    heap[i] = c;
}

static cell heap_pop(cell *heap, int *count)
{
    cell top = heap[0], last = heap[--(*count)];
    int i = 0;
    for (;;) {
        int child = 2 * i + 1;
        if (child >= *count) break;
        if (child + 1 < *count && heap[child + 1].error > heap[child].error) child++;
        if (!(heap[child].error > last.error)) break;
        heap[i] = heap[child];
        i = child;
    }
    if (*count > 0) heap[i] = last;
    return top;
}

/* E by the cubature; 0 when it did not converge within its budget. Global
 * adaptivity (the cell with the largest error estimate split first, until
 * the estimates sum to the tolerance): where a kink crosses the opening the
 * few cells it cuts take the splits, not the whole opening. */
static int opening_cubature(const opening_emitter *o, cdl_vec3 p, cdl_vec3 n, double *E)
{
    cubature q = {o, p, n, o->shape != CDL_LUMINOUS_SHAPE_RECTANGLE};
    /* first cells about square: the long side cut into up to 32 */
    int nu, nv;
    double u_lo, u_hi, v_lo, v_hi;
    if (q.polar) {
        nu = 2;
        nv = 8;
        u_lo = 0.0, u_hi = 1.0, v_lo = 0.0, v_hi = CDL_TWO_PI;
    } else {
        double ratio = o->half_length / o->half_width;
        nu = ratio >= 1.0 ? (int)fmin(32.0, ceil(ratio)) : 1;
        nv = ratio < 1.0 ? (int)fmin(32.0, ceil(1.0 / ratio)) : 1;
        u_lo = -o->half_length, u_hi = o->half_length, v_lo = -o->half_width, v_hi = o->half_width;
    }
    /* most points converge in a few dozen cells: the heap starts on the
     * stack and moves to the heap only when it must grow */
    cell local[64], *heap = local;
    int count = 0, capacity = 64;
    double du = (u_hi - u_lo) / nu, dv = (v_hi - v_lo) / nv, sum = 0.0, error = 0.0;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            cell c = cubature_cell(&q, u_lo + i * du, u_lo + (i + 1) * du, v_lo + j * dv, v_lo + (j + 1) * dv);
            sum += c.value;
            error += c.error;
            heap_push(heap, &count, c);
        }
    /* the scale the tolerance is relative to: E, or a thousandth of the
     * point model's Phi / (4 pi d^2) where E is far smaller (a point the
     * opening barely reaches) */
    cdl_vec3 d = cdl_vec3_sub(p, o->center);
    double d2 = cdl_vec3_dot(d, d);
    double floor = d2 > 0.0 ? 1e-3 * cdl_emitter_flux(o->point).lm / (4.0 * CDL_PI * d2) : 0.0;
    int ok = 1;
    while (error > CUBATURE_TOLERANCE * fmax(fabs(sum), floor)) {
        if (count + 3 > capacity) {
            int grown = 4 * capacity;
            cell *bigger = grown <= CUBATURE_MAX_CELLS ? malloc((size_t)grown * sizeof *bigger) : NULL;
            if (!bigger) {
                ok = 0; /* past the budget (or out of memory): the caller samples */
                break;
            }
            memcpy(bigger, heap, (size_t)count * sizeof *heap);
            if (heap != local) free(heap);
            heap = bigger;
            capacity = grown;
        }
        cell w = heap_pop(heap, &count);
        sum -= w.value;
        error -= w.error;
        double um = 0.5 * (w.u0 + w.u1), vm = 0.5 * (w.v0 + w.v1);
        cell kids[4] = {cubature_cell(&q, w.u0, um, w.v0, vm), cubature_cell(&q, um, w.u1, w.v0, vm),
                        cubature_cell(&q, w.u0, um, vm, w.v1), cubature_cell(&q, um, w.u1, vm, w.v1)};
        for (int k = 0; k < 4; ++k) {
            sum += kids[k].value;
            error += kids[k].error;
            heap_push(heap, &count, kids[k]);
        }
        /* the running sums drift by rounding: recount now and then */
        if (count % 512 < 3) {
            sum = error = 0.0;
            for (int k = 0; k < count; ++k) {
                sum += heap[k].value;
                error += heap[k].error;
            }
        }
    }
    if (heap != local) free(heap);
    if (!ok) return 0;
    *E = sum > 0.0 ? sum : 0.0;
    return 1;
}

static int opening_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    const opening_emitter *o = as_opening(e);
    if (!o->lambertian) {
        double v;
        if (!opening_cubature(o, p, n, &v)) return 0;
        *E = cdl_lux(v);
        return 1;
    }
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

static const cdl_emitter_ops opening_ops = {opening_flux,     opening_intensity, NULL, opening_exact, opening_sample,
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

int cdl_emitter_opening_is_lambertian(const cdl_emitter *emitter)
{
    return emitter->ops == &opening_ops && as_opening(emitter)->lambertian;
}

int cdl_emitter_opening_face(const cdl_emitter *emitter, cdl_shape *face)
{
    if (emitter->kind != CDL_EMITTER_GONIOMETRIC_OPENING) return 0;
    if (emitter->ops != &opening_ops) return cdl_emitter_solid_bounding_sphere(emitter, face);
    *face = face_shape(as_opening(emitter), 0);
    return 1;
}

cdl_status cdl_emitter_create_goniometric_opening(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    if (!p->photometry)
        return cdl_error_set(err, CDL_ERR_USAGE, "goniometric emitter: photometry: expected a table, found NULL");
    const cdl_luminous_opening *op = &cdl_photometry_get_metadata(p->photometry)->opening;
    if (!cdl_luminous_opening_is_spread(op))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "goniometric emitter: opening: expected a rectangle, circle, ellipse, box with luminous "
                             "sides, vertical or horizontal (elliptic) cylinder, sphere or ellipsoid of non-zero size to "
                             "spread the light over, found %s "
                             "%g x %g x %g m",
                             cdl_luminous_shape_name(op->shape), op->width_m, op->length_m, op->height_m);
    if (!cdl_luminous_opening_is_flat(op)) return cdl_emitter_create_goniometric_solid(p, out, err);
    cdl_emitter *point = NULL;
    cdl_status st = cdl_emitter_create_goniometric(p, &point, err);
    if (st != CDL_OK) return st;
    opening_emitter *o = cdl_emitter_alloc(sizeof *o, CDL_EMITTER_GONIOMETRIC_OPENING, &opening_ops, err);
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
        /* the table's I0 with every factor of the placed luminaire */
        o->lambert_luminance = cdl_emitter_intensity(point, cdl_vec3_neg(o->axis[2])).cd / o->area;
    }
    *out = &o->base;
    return CDL_OK;
}
