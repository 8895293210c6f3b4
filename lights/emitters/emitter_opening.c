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

#include "base/error_report.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"
#include "lights/photometry/photometry_metadata.h"

/* Relative tolerance of a table sample from I0 cos(gamma) for the table to
 * count as Lambertian: the closed form then differs from the sampled
 * integral of the interpolated table by the table's interpolation error
 * (about (step)^2 / 8 relative for linear steps, 4e-5 at 1 degree). */
#define LAMBERT_TOLERANCE 1e-6

typedef struct opening_emitter {
    cdl_spread_emitter spread; /* .point: the same luminaire as a point, I(w) */
    cdl_emitter *face[2];      /* unit-luminance area emitters (an ellipse's bounding rectangle): [0] faces the nadir, [1] up */
    cdl_luminous_shape shape;
    cdl_vec3 center;
    cdl_vec3 axis[3];          /* the luminaire's x (length), y (width), z (up) in world */
    double half_length, half_width;
    double area;
    int lambertian;            /* I = I0 cos(gamma) below, 0 above: closed form */
    double lambert_luminance;  /* I0 / A */
    double tolerance;          /* the cubature's, relative */
} opening_emitter;

static const cdl_emitter_ops opening_ops; /* defined below the functions it names */

static const opening_emitter *as_opening(const cdl_emitter *e)
{
    return (const opening_emitter *)e;
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
    return cdl_emitter_intensity(o->spread.point, w).cd / (o->area * c);
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
 * largest estimate split into two or four until the estimates sum to
 * the tolerance. The
 * 3-point rule is exact to degree 5, the 5-point to degree 9, so |Q5 - Q3|
 * bounds Q5's error generously wherever the integrand is smooth on the
 * cell; the table's bilinear kinks and the receiver's horizon (where
 * cos theta_r reaches 0) are resolved by the splitting. Tolerance: by
 * default 1e-5 of E (or of a thousandth of the point model's illuminance
 * scale Phi / (4 pi d^2) where E is far smaller), 1/20 of the finest
 * target the solver offers (2e-4, "reference"); a solver may set it to
 * what its target needs (cdl_emitter_opening_set_tolerance: 1/50 of it,
 * whose square adds at most 0.04 % to a point's variance), so the value
 * stands as exact (zero stated error). 1e-6 was tried: a receiver 0.1 m
 * under a disk with a 1-degree table (a circle of kinks per degree) then
 * needed more than the 4096 cells. Where the
 * splitting would exceed CUBATURE_MAX_CELLS the cubature gives up and the
 * caller samples instead. */

#define CUBATURE_TOLERANCE 1e-5
#define CUBATURE_TOLERANCE_MIN 1e-7
#define CUBATURE_TOLERANCE_MAX 1e-3
#define CUBATURE_MAX_CELLS 4096

/* Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz and Stegun 25.4.29) */
static const double gl3_x[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
static const double gl3_w[3] = {0.55555555555555555556, 0.88888888888888888889, 0.55555555555555555556};
static const double gl5_x[5] = {-0.90617984593866399280, -0.53846931010568309104, 0.0, 0.53846931010568309104,
                                0.90617984593866399280};
static const double gl5_w[5] = {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                                0.47862867049936646804, 0.23692688505618908751};

/* The cubature's domains: the opening's own parameters (a rectangle's
 * x, y; a circle's or ellipse's rho, phi), or a fan over the boundary of a
 * convex part of the opening (cdl_emitter_opening_partial_illuminance): a
 * boundary element b(t) (a segment, or an arc of the ellipse) and the
 * fan's apex c inside the part give the cell x(s, t) = c + s (b(t) - c),
 * s in [0, 1], whose area element is s (b(t) - c) x b'(t) ds dt. */
enum { DOMAIN_RECT, DOMAIN_POLAR, DOMAIN_FAN };

/* A boundary element of a convex part, in coordinates scaled by the
 * opening's half sizes (an ellipse is the unit circle there): a segment
 * from a to b (t in [0, 1]), or an arc of the unit circle from angle a[0]
 * to b[0] (t the angle). */
typedef struct fan_element {
    int arc;
    double a[2], b[2];
    double apex[2];          /* the fan's apex of the part it bounds */
} fan_element;

typedef struct cubature {
    const opening_emitter *o;
    cdl_vec3 p, n;
    int domain;
    const fan_element *fan;  /* DOMAIN_FAN: the elements, cells name theirs */
} cubature;

/* The intensity the element dA emits towards w (unit, away from it), as
 * the table gives it, or as the cosine a Lambertian table samples (the
 * same function as its closed form, so that the visible part of a wholly
 * visible opening sums to the closed form). */
static double opening_intensity_towards(const opening_emitter *o, cdl_vec3 w)
{
    if (o->lambertian) {
        double down = -cdl_vec3_dot(w, o->axis[2]);
        return down > 0.0 ? o->lambert_luminance * o->area * down : 0.0;
    }
    return cdl_emitter_intensity(o->spread.point, w).cd;
}

/* The integrand at parameter (u, v) of element `element`: I(w)
 * cos(theta_r) / r^2 times the area element, over A. */
static double cubature_integrand(const cubature *q, int element, double u, double v)
{
    const opening_emitter *o = q->o;
    double x, y, jacobian;
    if (q->domain == DOMAIN_POLAR) {
        x = o->half_length * u * cos(v);
        y = o->half_width * u * sin(v);
        jacobian = o->half_length * o->half_width * u;
    } else if (q->domain == DOMAIN_FAN) {
        const fan_element *f = &q->fan[element];
        double b[2], db[2];
        if (f->arc) {
            b[0] = cos(v), b[1] = sin(v);
            db[0] = -b[1], db[1] = b[0];
        } else {
            db[0] = f->b[0] - f->a[0], db[1] = f->b[1] - f->a[1];
            b[0] = f->a[0] + v * db[0], b[1] = f->a[1] + v * db[1];
        }
        double r0 = b[0] - f->apex[0], r1 = b[1] - f->apex[1];
        x = o->half_length * (f->apex[0] + u * r0);
        y = o->half_width * (f->apex[1] + u * r1);
        /* s (b - c) x b', in the scaled coordinates, times the scale's area */
        jacobian = u * (r0 * db[1] - r1 * db[0]) * o->half_length * o->half_width;
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
    double I = opening_intensity_towards(o, cdl_vec3_scale(to_light, -1.0 / r));
    return I * along / (r2 * r) * jacobian / o->area;
}

/* Gauss-Legendre rule of k points per side on [u0, u1] x [v0, v1]. */
static double cubature_rule(const cubature *q, int element, const double *xs, const double *ws, int k, double u0,
                            double u1, double v0, double v1)
{
    double hu = 0.5 * (u1 - u0), hv = 0.5 * (v1 - v0), mu = 0.5 * (u0 + u1), mv = 0.5 * (v0 + v1), sum = 0.0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i)
            sum += ws[i] * ws[j] * cubature_integrand(q, element, mu + hu * xs[i], mv + hv * xs[j]);
    return sum * hu * hv;
}

typedef struct cell {
    double u0, u1, v0, v1;
    double value, error;     /* Q5, |Q5 - Q3| */
    int element;             /* DOMAIN_FAN: its boundary element */
} cell;

static cell cubature_cell(const cubature *q, int element, double u0, double u1, double v0, double v1)
{
    cell c = {u0, u1, v0, v1, 0.0, 0.0, element};
    c.value = cubature_rule(q, element, gl5_x, gl5_w, 5, u0, u1, v0, v1);
    c.error = fabs(c.value - cubature_rule(q, element, gl3_x, gl3_w, 3, u0, u1, v0, v1));
    return c;
}

/* A max-heap of cells by error (cells[0] the worst), on the stack until it
 * must grow (most points converge in a few dozen cells), never beyond
 * CUBATURE_MAX_CELLS. */
typedef struct cell_heap {
    cell local[64];
    cell *cells;
    int count, capacity;
    int full;                /* past the budget (or out of memory): the caller samples */
    double sum, error;       /* of the cells' values and error estimates */
} cell_heap;

static void heap_init(cell_heap *h)
{
    h->cells = h->local;
    h->count = 0;
    h->capacity = 64;
    h->full = 0;
    h->sum = h->error = 0.0;
}

static void heap_release(cell_heap *h)
{
    if (h->cells != h->local) free(h->cells);
}

static void heap_push(cell_heap *h, cell c)
{
    if (h->count == h->capacity) {
        int grown = 4 * h->capacity;
        cell *bigger = grown <= CUBATURE_MAX_CELLS ? malloc((size_t)grown * sizeof *bigger) : NULL;
        if (!bigger) {
            h->full = 1;
            return;
        }
        memcpy(bigger, h->cells, (size_t)h->count * sizeof *bigger);
        heap_release(h);
        h->cells = bigger;
        h->capacity = grown;
    }
    h->sum += c.value;
    h->error += c.error;
    int i = h->count++;
    while (i > 0 && h->cells[(i - 1) / 2].error < c.error) {
        h->cells[i] = h->cells[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->cells[i] = c;
}

static cell heap_pop(cell_heap *h)
{
    cell top = h->cells[0], last = h->cells[--h->count];
    int i = 0;
    for (;;) {
        int child = 2 * i + 1;
        if (child >= h->count) break;
        if (child + 1 < h->count && h->cells[child + 1].error > h->cells[child].error) child++;
        if (!(h->cells[child].error > last.error)) break;
        h->cells[i] = h->cells[child];
        i = child;
    }
    if (h->count > 0) h->cells[i] = last;
    h->sum -= top.value;
    h->error -= top.error;
    return top;
}

/* Push an element's first cells: the v range cut into nv. */
static void heap_seed(cell_heap *h, const cubature *q, int element, double u0, double u1, int nu, double v0,
                      double v1, int nv)
{
    double du = (u1 - u0) / nu, dv = (v1 - v0) / nv;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
            heap_push(h, cubature_cell(q, element, u0 + i * du, u0 + (i + 1) * du, v0 + j * dv, v0 + (j + 1) * dv));
}

/* The lengths on the opening, in metres, of a cell's sides along u and v
 * (at its middle): a cell more than twice as long one way as the other is
 * split across that way only, so that a long thin opening or fan is not
 * cut into needlessly many cells. */
static void cell_extent(const cubature *q, const cell *c, double *lu, double *lv)
{
    const opening_emitter *o = q->o;
    double du = c->u1 - c->u0, dv = c->v1 - c->v0, um = 0.5 * (c->u0 + c->u1), vm = 0.5 * (c->v0 + c->v1);
    if (q->domain == DOMAIN_RECT) {
        *lu = du, *lv = dv;
    } else if (q->domain == DOMAIN_POLAR) {
        /* rho along the ellipse's larger radius, phi along its arc */
        double a = fmax(o->half_length, o->half_width);
        *lu = du * a, *lv = dv * um * a;
    } else {
        const fan_element *f = &q->fan[c->element];
        double b[2], db[2];
        if (f->arc) {
            b[0] = cos(vm), b[1] = sin(vm), db[0] = -b[1], db[1] = b[0];
        } else {
            db[0] = f->b[0] - f->a[0], db[1] = f->b[1] - f->a[1];
            b[0] = f->a[0] + vm * db[0], b[1] = f->a[1] + vm * db[1];
        }
        /* s runs along b - c, t along s b' (scaled back to metres) */
        *lu = du * hypot((b[0] - f->apex[0]) * o->half_length, (b[1] - f->apex[1]) * o->half_width);
        *lv = dv * um * hypot(db[0] * o->half_length, db[1] * o->half_width);
    }
}

/* Global adaptivity (the cell with the largest error estimate split into
 * two or four first, until the estimates sum to the tolerance): where a kink
 * crosses the opening the few cells it cuts take the splits, not the
 * whole opening. The tolerance is relative to E, or to a thousandth of
 * the point model's Phi / (4 pi d^2) where E is far smaller (a point the
 * opening barely reaches, or sees little of). Returns 0 when it did not
 * converge within CUBATURE_MAX_CELLS. */
static int heap_converge(cell_heap *h, const cubature *q, double *E)
{
    const opening_emitter *o = q->o;
    cdl_vec3 d = cdl_vec3_sub(q->p, o->center);
    double d2 = cdl_vec3_dot(d, d);
    double floor = d2 > 0.0 ? 1e-3 * cdl_emitter_flux(o->spread.point).lm / (4.0 * CDL_PI * d2) : 0.0;
    while (!h->full && h->count > 0 && h->error > o->tolerance * fmax(fabs(h->sum), floor)) {
        cell w = heap_pop(h);
        double um = 0.5 * (w.u0 + w.u1), vm = 0.5 * (w.v0 + w.v1), lu, lv;
        cell_extent(q, &w, &lu, &lv);
        if (lu > 2.0 * lv) {
            heap_push(h, cubature_cell(q, w.element, w.u0, um, w.v0, w.v1));
            heap_push(h, cubature_cell(q, w.element, um, w.u1, w.v0, w.v1));
        } else if (lv > 2.0 * lu) {
            heap_push(h, cubature_cell(q, w.element, w.u0, w.u1, w.v0, vm));
            heap_push(h, cubature_cell(q, w.element, w.u0, w.u1, vm, w.v1));
        } else {
            heap_push(h, cubature_cell(q, w.element, w.u0, um, w.v0, vm));
            heap_push(h, cubature_cell(q, w.element, um, w.u1, w.v0, vm));
            heap_push(h, cubature_cell(q, w.element, w.u0, um, vm, w.v1));
            heap_push(h, cubature_cell(q, w.element, um, w.u1, vm, w.v1));
        }
        /* the running sums drift by rounding: recount now and then */
        if (h->count % 512 < 3) {
            h->sum = h->error = 0.0;
            for (int k = 0; k < h->count; ++k) {
                h->sum += h->cells[k].value;
                h->error += h->cells[k].error;
            }
        }
    }
    if (h->full) return 0;
    *E = h->sum > 0.0 ? h->sum : 0.0;
    return 1;
}

/* E over the whole opening by the cubature; 0 when it did not converge. */
/* A receiver this many of a round opening's radii away starts its cubature
 * with four cells instead of sixteen (opening_cubature). */
#define FAR_SEED_RADII 8.0

static int opening_cubature(const opening_emitter *o, cdl_vec3 p, cdl_vec3 n, double *E)
{
    cubature q = {o, p, n, o->shape == CDL_LUMINOUS_SHAPE_RECTANGLE ? DOMAIN_RECT : DOMAIN_POLAR, NULL};
    cell_heap h;
    heap_init(&h);
    if (q.domain == DOMAIN_POLAR) {
        /* A receiver FAR_SEED_RADII radii away sees the disk's integrand
         * change by a quarter of itself or less across it: four quarters
         * start the cubature, which splits them where its rules disagree
         * (near the opening, sixteen cells keep it from trusting two rules
         * that agree by chance). */
        double a = fmax(o->half_length, o->half_width);
        int far = cdl_vec3_length_squared(cdl_vec3_sub(p, o->center)) >= FAR_SEED_RADII * FAR_SEED_RADII * a * a;
        heap_seed(&h, &q, 0, 0.0, 1.0, far ? 1 : 2, 0.0, CDL_TWO_PI, far ? 4 : 8);
    } else {
        /* first cells at most 4 times as long as wide (the splitting
         * halves them across their long side first) */
        double ratio = o->half_length / o->half_width;
        int nu = ratio >= 1.0 ? (int)fmin(32.0, ceil(ratio / 4.0)) : 1;
        int nv = ratio < 1.0 ? (int)fmin(32.0, ceil(0.25 / ratio)) : 1;
        heap_seed(&h, &q, 0, -o->half_length, o->half_length, nu, -o->half_width, o->half_width, nv);
    }
    int ok = heap_converge(&h, &q, E);
    heap_release(&h);
    return ok;
}

/* ---- a partly visible flat opening ----------------------------------------- *
 *
 * The visible part of the opening is a union of convex polygons in its
 * plane (what a solver keeps of it past planar occluders). Each is
 * clipped to the opening, in coordinates scaled by the half sizes (X =
 * x / a, Y = y / b: a rectangle is the square [-1, 1]^2, an ellipse the
 * unit circle), which keeps it convex; its boundary, segments and arcs of
 * the circle in order, is fanned from the mean of points on it (inside,
 * the part being convex), and the fans are integrated by the same
 * adaptive cubature as the whole opening. */

/* Most corners of a clipped polygon, and most boundary elements of one
 * visible part (a polygon's edges and the arcs between them). */
#define PART_MAX_VERTICES 72
#define PARTS_MAX_ELEMENTS 8192

/* Keep the part of a convex polygon where a x + b y + c >= 0
 * (Sutherland-Hodgman); returns the new count. */
static int clip_half_plane(double (*v)[2], int count, double a, double b, double c)
{
    double out[PART_MAX_VERTICES][2];
    int m = 0;
    for (int i = 0; i < count; ++i) {
        const double *p = v[i], *q = v[(i + 1) % count];
        double fp = a * p[0] + b * p[1] + c, fq = a * q[0] + b * q[1] + c;
        if (fp >= 0.0 && m < PART_MAX_VERTICES) out[m][0] = p[0], out[m][1] = p[1], m++;
        if (((fp >= 0.0) != (fq >= 0.0)) && m < PART_MAX_VERTICES) {
            double t = fp / (fp - fq);
            out[m][0] = p[0] + t * (q[0] - p[0]);
            out[m][1] = p[1] + t * (q[1] - p[1]);
            m++;
        }
    }
    memcpy(v, out, (size_t)m * sizeof out[0]);
    return m;
}

typedef struct fan_list {
    fan_element *items;
    size_t count, capacity;
    int failed;
} fan_list;

static void fan_add(fan_list *l, int arc, const double a[2], const double b[2])
{
    if (l->count == l->capacity) {
        size_t cap = l->capacity ? 2 * l->capacity : 32;
        fan_element *grown = cap <= PARTS_MAX_ELEMENTS ? realloc(l->items, cap * sizeof *grown) : NULL;
        if (!grown) {
            l->failed = 1;
            return;
        }
        l->items = grown;
        l->capacity = cap;
    }
    fan_element *f = &l->items[l->count++];
    f->arc = arc;
    f->a[0] = a[0], f->a[1] = a[1], f->b[0] = b[0], f->b[1] = b[1];
}

/* Add the arc of the unit circle counter-clockwise from angle `from` to
 * angle `to` (the next turn of `to` when it is not past `from`); none
 * where the two meet (a corner of the polygon on the circle). */
static void arc_add(fan_list *l, double from, double to)
{
    while (to < from) to += CDL_TWO_PI;
    if (!(to - from > 1e-12)) return;
    double a[2] = {from, 0.0}, b[2] = {to, 0.0};
    fan_add(l, 1, a, b);
}

/* The elements of a convex polygon (scaled coordinates, counter-clockwise)
 * within the unit circle: the parts of its edges inside the circle, and the
 * arcs of the circle between where the boundary leaves it and re-enters
 * it; the whole circle when it lies inside the polygon. */
static void disk_elements(const double (*v)[2], int count, fan_list *l)
{
    int any = 0, exited = 0, first_entered = 0;
    double exit_angle = 0.0, first_entry = 0.0;
    for (int i = 0; i < count; ++i) {
        const double *p = v[i], *q = v[(i + 1) % count];
        double d[2] = {q[0] - p[0], q[1] - p[1]};
        /* |p + t d|^2 = 1: a t^2 + 2 b t + c = 0 */
        double a = d[0] * d[0] + d[1] * d[1], b = p[0] * d[0] + p[1] * d[1], c = p[0] * p[0] + p[1] * p[1] - 1.0;
        double disc = b * b - a * c;
        if (!(a > 0.0) || !(disc > 0.0)) continue;
        double s = sqrt(disc), lo = fmax(0.0, (-b - s) / a), hi = fmin(1.0, (-b + s) / a);
        if (!(hi > lo)) continue;
        double A[2] = {p[0] + lo * d[0], p[1] + lo * d[1]}, B[2] = {p[0] + hi * d[0], p[1] + hi * d[1]};
        /* the edge comes from the circle (its corner p on it or outside),
         * or leaves it (q on it or outside) */
        int enters = lo > 0.0 || c >= 0.0, leaves = hi < 1.0 || q[0] * q[0] + q[1] * q[1] >= 1.0;
        if (enters) {
            /* enters the circle at A: the arc from the last exit */
            double entry = atan2(A[1], A[0]);
            if (exited) {
                arc_add(l, exit_angle, entry);
            } else if (!any) {
                first_entered = 1;
                first_entry = entry;
            }
        }
        fan_add(l, 0, A, B);
        any = 1;
        exited = leaves;
        if (exited) exit_angle = atan2(B[1], B[0]);
    }
    if (!any) {
        /* no edge inside: the circle inside the polygon, or apart from it */
        for (int i = 0; i < count; ++i) {
            const double *p = v[i], *q = v[(i + 1) % count];
            if ((q[0] - p[0]) * (0.0 - p[1]) - (q[1] - p[1]) * (0.0 - p[0]) < 0.0) return;
        }
        double from[2] = {0.0, 0.0}, to[2] = {CDL_TWO_PI, 0.0};
        fan_add(l, 1, from, to);
        return;
    }
    /* the arc from the last exit round to the first entry */
    if (exited && first_entered) arc_add(l, exit_angle, first_entry);
}

/* The apex of the fan of elements [first, l->count): the mean of points on
 * the boundary (segment ends; an arc's quarter points), inside a convex part. */
static void fan_apex(fan_list *l, size_t first)
{
    double c[2] = {0.0, 0.0}, w = 0.0;
    for (size_t k = first; k < l->count; ++k) {
        const fan_element *f = &l->items[k];
        if (f->arc) {
            for (int j = 1; j <= 3; ++j) {
                double t = f->a[0] + 0.25 * j * (f->b[0] - f->a[0]);
                c[0] += cos(t), c[1] += sin(t), w += 1.0;
            }
        } else {
            c[0] += f->a[0] + f->b[0], c[1] += f->a[1] + f->b[1], w += 2.0;
        }
    }
    for (size_t k = first; k < l->count; ++k) {
        l->items[k].apex[0] = w > 0.0 ? c[0] / w : 0.0;
        l->items[k].apex[1] = w > 0.0 ? c[1] / w : 0.0;
    }
}

/* One visible part (world points in the opening's plane) as fan elements. */
static void part_elements(const opening_emitter *o, const cdl_vec3 *points, int count, fan_list *l)
{
    if (count < 3 || count > PART_MAX_VERTICES / 2) {
        l->failed = count >= 3;
        return;
    }
    double v[PART_MAX_VERTICES][2], area2 = 0.0;
    for (int i = 0; i < count; ++i) {
        cdl_vec3 h = cdl_vec3_sub(points[i], o->center);
        v[i][0] = cdl_vec3_dot(h, o->axis[0]) / o->half_length;
        v[i][1] = cdl_vec3_dot(h, o->axis[1]) / o->half_width;
    }
    for (int i = 0; i < count; ++i)
        area2 += v[i][0] * v[(i + 1) % count][1] - v[(i + 1) % count][0] * v[i][1];
    if (area2 < 0.0) /* counter-clockwise */
        for (int i = 0; i < count / 2; ++i) {
            double t0 = v[i][0], t1 = v[i][1];
            v[i][0] = v[count - 1 - i][0], v[i][1] = v[count - 1 - i][1];
            v[count - 1 - i][0] = t0, v[count - 1 - i][1] = t1;
        }
    size_t first = l->count;
    if (o->shape == CDL_LUMINOUS_SHAPE_RECTANGLE) {
        /* within the square |X|, |Y| <= 1 */
        count = clip_half_plane(v, count, 1.0, 0.0, 1.0);
        count = clip_half_plane(v, count, -1.0, 0.0, 1.0);
        count = clip_half_plane(v, count, 0.0, 1.0, 1.0);
        count = clip_half_plane(v, count, 0.0, -1.0, 1.0);
        for (int i = 0; i < count; ++i) fan_add(l, 0, v[i], v[(i + 1) % count]);
    } else {
        disk_elements((const double(*)[2])v, count, l);
    }
    fan_apex(l, first);
}

cdl_status cdl_emitter_opening_partial_illuminance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n,
                                                   const cdl_vec3 *points, const int *counts, size_t polygons,
                                                   cdl_illuminance *E, cdl_error *err)
{
    *E = cdl_lux(0.0);
    if (emitter->ops != &opening_ops)
        return cdl_error_set(err, CDL_ERR_USAGE, "opening partial illuminance: expected a flat goniometric opening");
    const opening_emitter *o = as_opening(emitter);
    fan_list l = {NULL, 0, 0, 0};
    size_t at = 0;
    for (size_t k = 0; k < polygons && !l.failed; ++k) {
        part_elements(o, points + at, counts[k], &l);
        at += (size_t)counts[k];
    }
    if (l.failed) {
        free(l.items);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "opening partial illuminance: more than %d boundary elements",
                             PARTS_MAX_ELEMENTS);
    }
    cubature q = {o, p, n, DOMAIN_FAN, l.items};
    cell_heap h;
    heap_init(&h);
    for (size_t k = 0; k < l.count && !h.full; ++k) {
        const fan_element *f = &l.items[k];
        /* first cells: an arc by eighths of the circle; a segment by its
         * length over 4 times its distance from the apex (cells at most
         * about 4 times as long as wide) */
        int nv;
        if (f->arc) {
            nv = (int)fmin(8.0, ceil((f->b[0] - f->a[0]) / (0.25 * CDL_PI)));
        } else {
            double dx = f->b[0] - f->a[0], dy = f->b[1] - f->a[1], len = hypot(dx, dy);
            double dist = len > 0.0 ? fabs(dx * (f->apex[1] - f->a[1]) - dy * (f->apex[0] - f->a[0])) / len : 0.0;
            nv = dist > 0.0 ? (int)fmin(32.0, ceil(len / (8.0 * dist))) : 1;
        }
        heap_seed(&h, &q, (int)k, 0.0, 1.0, 1, f->arc ? f->a[0] : 0.0, f->arc ? f->b[0] : 1.0, nv < 1 ? 1 : nv);
    }
    double v = 0.0;
    int ok = !h.full && heap_converge(&h, &q, &v);
    heap_release(&h);
    free(l.items);
    if (!ok)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "opening partial illuminance: the cubature did not converge within "
                                                 "%d cells",
                             CUBATURE_MAX_CELLS);
    *E = cdl_lux(v);
    return CDL_OK;
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
    cdl_spread_emitter_destroy(e);
    cdl_emitter_release(o->face[0]);
    cdl_emitter_release(o->face[1]);
}

static const cdl_emitter_ops opening_ops = {cdl_spread_emitter_flux, cdl_spread_emitter_intensity, NULL,
                                            opening_exact,           opening_sample,               opening_radiance,
                                            opening_destroy,         NULL,                         NULL};

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

int cdl_emitter_opening_set_tolerance(cdl_emitter *emitter, double relative)
{
    if (emitter->ops != &opening_ops || !(relative > 0.0)) return 0;
    ((opening_emitter *)emitter)->tolerance = fmin(CUBATURE_TOLERANCE_MAX, fmax(CUBATURE_TOLERANCE_MIN, relative));
    return 1;
}

int cdl_emitter_opening_bounding_rectangle(const cdl_emitter *emitter, cdl_vec3 corner[4])
{
    if (emitter->ops != &opening_ops) return 0;
    const opening_emitter *o = as_opening(emitter);
    cdl_vec3 x = cdl_vec3_scale(o->axis[0], o->half_length), y = cdl_vec3_scale(o->axis[1], o->half_width);
    corner[0] = cdl_vec3_sub(cdl_vec3_sub(o->center, x), y);
    corner[1] = cdl_vec3_sub(cdl_vec3_add(o->center, x), y);
    corner[2] = cdl_vec3_add(cdl_vec3_add(o->center, x), y);
    corner[3] = cdl_vec3_add(cdl_vec3_sub(o->center, x), y);
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
                             "goniometric emitter: opening: expected a rectangle, circle or ellipse (horizontal or "
                             "vertical), box with luminous sides, vertical or horizontal (elliptic) cylinder, sphere or "
                             "ellipsoid of non-zero size to "
                             "spread the light over, found %s "
                             "%g x %g x %g m",
                             cdl_luminous_shape_name(op->shape), op->width_m, op->length_m, op->height_m);
    if (!cdl_luminous_opening_is_flat(op)) return cdl_emitter_create_goniometric_solid(p, out, err);
    cdl_status st;
    opening_emitter *o = cdl_spread_emitter_create(sizeof *o, &opening_ops, p, &st, err);
    if (!o) return st;
    o->tolerance = CUBATURE_TOLERANCE;
    o->shape = op->shape;
    o->center = p->position;
    cdl_emitter_rotation_columns(p->rotation_deg, o->axis);
    o->half_length = 0.5 * (op->shape == CDL_LUMINOUS_SHAPE_CIRCLE ? op->width_m : op->length_m);
    o->half_width = 0.5 * op->width_m;
    int vertical = op->shape == CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE || op->shape == CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE;
    if (vertical) {
        /* LM-63-2019's vertical circle or ellipse facing the photometric
         * horizontal: in the luminaire's y-z plane (width W along y, height
         * H along z), its faces towards C0 (+x) and C180 (-x). As a flat
         * opening of its own frame: length along z, width along y, normal
         * z x y = -x ("lower" face towards +x). */
        cdl_vec3 x = o->axis[0], z = o->axis[2];
        o->axis[0] = z;
        o->axis[2] = cdl_vec3_neg(x);
        o->half_length = 0.5 * op->height_m;
        o->shape = op->shape == CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE ? CDL_LUMINOUS_SHAPE_CIRCLE : CDL_LUMINOUS_SHAPE_ELLIPSE;
    }
    /* rectangle L W; circle and ellipse pi a b */
    o->area = o->shape == CDL_LUMINOUS_SHAPE_RECTANGLE ? 4.0 * o->half_length * o->half_width
                                                         : CDL_PI * o->half_length * o->half_width;
    for (int up = 0; up < 2 && st == CDL_OK; ++up) st = make_face(o, up, &o->face[up], err);
    if (st != CDL_OK) {
        cdl_emitter_release(&o->spread.base);
        return st;
    }
    double I0;
    if (!vertical && o->shape != CDL_LUMINOUS_SHAPE_ELLIPSE && table_is_lambertian(p->photometry, &I0)) {
        o->lambertian = 1;
        /* the table's I0 with every factor of the placed luminaire */
        o->lambert_luminance = cdl_emitter_intensity(o->spread.point, cdl_vec3_neg(o->axis[2])).cd / o->area;
    }
    *out = &o->spread.base;
    return CDL_OK;
}
