/* Goniometric luminaires spread over a luminous solid (IES LM-63 box with
 * luminous sides, vertical cylinder and elliptic cylinder, sphere,
 * ellipsoid, horizontal cylinders along and across): tables of uniform
 * luminance against closed-form configuration factors (a sphere to facing
 * and tilted elements, a box face by face with Lambert's polygon formula)
 * and, for the ellipsoid and the elliptic cylinders, against an independent
 * quadrature over their surfaces; a non-uniform cylinder against the same
 * kind of quadrature; rotated luminaires against it with the receiver
 * turned back; the flux through an enclosing sphere, the far field
 * against the point model, the sampler's pdf against cdl_emitter_radiance
 * (pointwise and as a density, on the bounding box's and the bounding
 * sphere's paths), and the IES sign codes of each new shape read into the
 * sizes whose outline, ray by ray, is the projected area. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "polygon_factor.h"
#include "sphere_factor.h"
#include "lights/emitters/emitter.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"

/* ---- photometric files in memory ------------------------------------------ */

typedef double (*table_fn)(double c_deg, double gamma_deg);

/* An LM-63-2002 file of opening (W, L, H) in metres (negative: round, as
 * the file writes it) and I(C, gamma) = f, C every c_step degrees over
 * [0, 360] (one plane when c_step is 0), gamma every degree. */
static cdl_photometry *solid_file(double W, double L, double H, table_fn f, double c_step)
{
    int planes = c_step > 0.0 ? (int)lround(360.0 / c_step) + 1 : 1, angles = 181;
    size_t cap = 64 + (size_t)planes * angles * 28 + 8192, used = 0;
    char *text = malloc(cap);
    CHECK(text != NULL);
    used += (size_t)snprintf(text, cap, "IESNA:LM-63-2002\n[TEST] luminous solid\nTILT=NONE\n"
                                        "1 -1 1 %d %d 1 2 %.17g %.17g %.17g\n1 1 0\n",
                             angles, planes, W, L, H);
    for (int g = 0; g < angles; ++g) used += (size_t)snprintf(text + used, cap - used, "%d ", g);
    used += (size_t)snprintf(text + used, cap - used, "\n");
    for (int c = 0; c < planes; ++c) used += (size_t)snprintf(text + used, cap - used, "%.17g ", c * c_step);
    for (int c = 0; c < planes; ++c) {
        used += (size_t)snprintf(text + used, cap - used, "\n");
        for (int g = 0; g < angles; ++g)
            used += (size_t)snprintf(text + used, cap - used, "%.17g ", f(c * c_step, (double)g));
    }
    cdl_photometry *ph = NULL;
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_error err;
    CHECK_OK(cdl_photometry_read_memory(text, used, "solid.ies", &opt, &ph, &err), &err);
    free(text);
    return ph;
}

static cdl_emitter *spread(const cdl_photometry *ph, cdl_vec3 at, int as_point)
{
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.photometry = ph;
    p.position = at;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(as_point ? cdl_emitter_create_goniometric(&p, &e, &err) : cdl_emitter_create_goniometric_opening(&p, &e, &err),
             &err);
    return e;
}

/* ---- the shapes' tables ---------------------------------------------------- */

#define LUM 2000.0 /* cd/m^2 */
#define SPHERE_R 0.15
#define BOX_L 0.6
#define BOX_W 0.2
#define BOX_H 0.1
#define CYL_R 0.1
#define CYL_H 0.4

/* a sphere of luminance LUM: I = LUM pi r^2 in every direction */
static double sphere_table(double c, double g)
{
    (void)c, (void)g;
    return LUM * CDL_PI * SPHERE_R * SPHERE_R;
}

/* a box of luminance LUM: I = LUM A_proj(C, gamma) */
static double box_table(double c, double g)
{
    double sg = sin(g * CDL_DEG_TO_RAD), cg = cos(g * CDL_DEG_TO_RAD), cc = cos(c * CDL_DEG_TO_RAD),
           sc = sin(c * CDL_DEG_TO_RAD);
    return LUM * (fabs(sg * cc) * BOX_W * BOX_H + fabs(sg * sc) * BOX_L * BOX_H + fabs(cg) * BOX_L * BOX_W);
}

/* a cylinder brighter below: I = 1000 (1 + cos gamma)^2 cd */
static double cylinder_table(double c, double g)
{
    (void)c;
    double k = 1.0 + cos(g * CDL_DEG_TO_RAD);
    return 1000.0 * k * k;
}

/* ---- estimators ---------------------------------------------------------- */

typedef struct estimate {
    double mean, se; /* the mean of L cos / pdf and its standard error */
} estimate;

/* E at p on the plane of n from `reps` independent runs of k x k
 * stratified samples of the emitter (xorshift64 jitter from `seed`, so
 * that estimates at different points do not share their errors); the
 * standard error from the spread of the runs (a stratified run's variance
 * is not its samples' variance). */
static estimate sampled(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, int k, int reps, uint64_t seed)
{
    uint64_t x = 0x2545f4914f6cdd1dull ^ (seed * 0x9e3779b97f4a7c15ull);
    double s1 = 0.0, s2 = 0.0;
    for (int r = 0; r < reps; ++r) {
        double run = 0.0;
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) {
                /* xorshift64 (Marsaglia 2003) jitter within the stratum */
                x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                double a = (double)(x >> 11) * 0x1.0p-53;
                x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                double b = (double)(x >> 11) * 0x1.0p-53;
                cdl_light_sample s;
                if (!cdl_emitter_sample(e, p, n, (i + a) / k, (j + b) / k, &s)) continue;
                run += s.L.cd_m2 * fmax(0.0, cdl_vec3_dot(n, s.to_light)) / s.pdf;
                /* the radiance query must agree with the sample */
                double pdf;
                cdl_luminance L = cdl_emitter_radiance(e, p, n, s.to_light, &pdf);
                CHECK(fabs(L.cd_m2 - s.L.cd_m2) <= 1e-9 * s.L.cd_m2 && fabs(pdf - s.pdf) <= 1e-9 * s.pdf);
            }
        run /= (double)k * k;
        s1 += run;
        s2 += run * run;
    }
    double mean = s1 / reps;
    estimate out = {mean, sqrt(fmax(0.0, (s2 / reps - mean * mean) / (reps - 1)))};
    return out;
}

/* The estimate within 4 standard errors plus `bias` (relative: the table's
 * interpolation) of the exact value, and its standard error small enough
 * (below 1 %) for the check to mean something. */
static void check_estimate(estimate got, double exact, double bias, const char *what)
{
    CHECK_MSG(fabs(got.mean - exact) <= 4.0 * got.se + bias * fabs(exact) && got.se <= 0.01 * fabs(exact),
              "%s: sampled %.6g +- %.2g, exact %.6g", what, got.mean, got.se, exact);
}

/* ---- tests ----------------------------------------------------------------- */

/* A uniform sphere seen by a facing element is a point for any d > r:
 * E = I / d^2 exactly; a tilted element gets L pi F (the factor above),
 * down to an element that sees only a sliver of it. */
static void test_sphere(void)
{
    cdl_photometry *ph = solid_file(-2.0 * SPHERE_R, -2.0 * SPHERE_R, -2.0 * SPHERE_R, sphere_table, 0.0);
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_SPHERE);
    cdl_vec3 c = cdl_vec3_make(0.3, -0.2, 2.5);
    cdl_emitter *e = spread(ph, c, 0);
    CHECK(cdl_emitter_get_kind(e) == CDL_EMITTER_GONIOMETRIC_OPENING && cdl_emitter_has_exact_illuminance(e));
    double I = LUM * CDL_PI * SPHERE_R * SPHERE_R;
    /* the table is constant: its interpolation is exact (1e-12 for rounding) */
    const double d[4] = {1.05 * SPHERE_R, 1.5 * SPHERE_R, 4.0 * SPHERE_R, 30.0 * SPHERE_R};
    cdl_vec3 toward = cdl_vec3_normalize(cdl_vec3_make(0.2, 0.5, -1.0));
    for (int i = 0; i < 4; ++i) {
        cdl_vec3 p = cdl_vec3_madd(c, d[i], toward);
        check_estimate(sampled(e, p, cdl_vec3_neg(toward), 16, 16, (uint64_t)i), I / (d[i] * d[i]), 1e-12, "sphere facing");
        /* the cone's cubature: converged to 1e-5 by its own estimate, held to 2e-5 */
        cdl_illuminance exact;
        CHECK_OK(cdl_emitter_exact_illuminance(e, p, cdl_vec3_neg(toward), &exact, NULL), &(cdl_error){0});
        CHECK_REL(exact.lx, I / (d[i] * d[i]), 2e-5);
        /* tilted about an axis across the line to the centre: theta from 0 to past the horizon */
        cdl_frame f = cdl_frame_from_normal(cdl_vec3_neg(toward));
        for (int t = 1; t <= 5; ++t) {
            double theta = t * 0.35; /* 0.35 .. 1.75 rad, the last beyond 90 degrees */
            cdl_vec3 n = cdl_frame_to_world(&f, cdl_vec3_make(sin(theta), 0.0, cos(theta)));
            double E = LUM * CDL_PI * sphere_factor(SPHERE_R, d[i], theta);
            /* whole in view: the cubature; wholly behind the plane: 0; cut by
             * the horizon: declined (then sampled) */
            cdl_illuminance exact;
            int whole = theta <= acos(SPHERE_R / d[i]), none = theta >= 0.5 * CDL_PI + asin(SPHERE_R / d[i]);
            CHECK_MSG((cdl_emitter_exact_illuminance(e, p, n, &exact, NULL) == CDL_OK) == (whole || none),
                      "d %g theta %g", d[i], theta);
            if (whole || none) CHECK_REL(exact.lx, E, 2e-5);
            if (E <= 0.0) continue;
            estimate got = sampled(e, p, n, 16, 16, (uint64_t)(10 * i + t));
            /* a sliver of the sphere has a large relative error: checked absolutely against the facing E */
            CHECK_MSG(fabs(got.mean - E) <= 4.0 * got.se + 1e-9 * I / (d[i] * d[i]) && got.se <= 0.01 * I / (d[i] * d[i]),
                      "sphere tilted %.2f rad at d = %g: sampled %.6g +- %.2g, exact %.6g", theta, d[i], got.mean,
                      got.se, E);
        }
    }
    /* inside the sphere nothing is lit */
    cdl_light_sample s;
    CHECK(!cdl_emitter_sample(e, c, cdl_vec3_make(0, 0, 1), 0.3, 0.6, &s));
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* A box of uniform luminance is a Lambertian box: E is the sum of
 * Lambert's polygon formula over the faces p sees (those whose plane p is
 * in front of), each clipped by nothing when the receiver faces the box. */
static void test_box(void)
{
    cdl_photometry *ph = solid_file(BOX_W, BOX_L, BOX_H, box_table, 1.0);
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_BOX);
    cdl_vec3 c = cdl_vec3_make(0.0, 0.0, 3.0);
    cdl_emitter *e = spread(ph, c, 0);
    CHECK(!cdl_emitter_has_exact_illuminance(e));
    const double h[3] = {0.5 * BOX_L, 0.5 * BOX_W, 0.5 * BOX_H};
    /* receivers around the box, each facing its centre (so every visible face is in front of it) */
    const cdl_vec3 at[5] = {{0.0, 0.0, -0.3}, {0.5, 0.1, -0.2}, {-0.4, 0.35, 0.1}, {0.2, -0.25, 0.4}, {1.5, 0.8, -1.2}};
    for (int k = 0; k < 5; ++k) {
        cdl_vec3 p = cdl_vec3_add(c, at[k]), n = cdl_vec3_normalize(cdl_vec3_neg(at[k]));
        const double tops[4] = {h[2], h[2], h[2], h[2]};
        double E = lambert_box(c, h, tops, LUM, p, n);
        /* the table at 1-degree steps in C and gamma: bilinear interpolation of
         * |cos|, |sin| terms is within (1 deg)^2 / 8 = 4e-5 of them, plus the
         * kinks at the axes, which lie on nodes: 1e-4 */
        check_estimate(sampled(e, p, n, 24, 16, (uint64_t)k), E, 1e-4, "uniform box");
    }
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* ---- the solids by their surfaces ------------------------------------------ */

/* A solid of LM-63 Table 1 by its semi-axes along the luminaire's x, y, z
 * (a box's half sides, a cylinder's half length on its axis) and its
 * cylinder axis (-1: an ellipsoid or a box, by `shape`); `file` is W, L, H
 * as a 2002 file writes them, whose signs give the shape. */
typedef struct solid_case {
    const char *name;
    cdl_luminous_shape shape;
    double half[3];
    int axis;
    double file[3];
} solid_case;

static double sq(double x) { return x * x; }

/* The projected area along the unit u (luminaire frame). An ellipsoid is
 * the unit sphere under D = diag(a), its shadow pi |cof(D) u| = pi sqrt(sum
 * (a_j a_k u_i)^2); a cylinder of axis k shows a cap, pi a_i a_j |u_k|, and
 * half its side: (1/2) int |m.u| dA = (1/2) 2 a_k int_0^2pi |a_j u_i cos phi
 * + a_i u_j sin phi| d phi = 4 a_k sqrt(a_j^2 u_i^2 + a_i^2 u_j^2). */
static double case_projected_area(const solid_case *sc, cdl_vec3 w)
{
    const double *a = sc->half;
    double u[3] = {w.x, w.y, w.z};
    int k = sc->axis;
    /* a box shows a face across each axis, 4 a_i a_j |u_m| */
    if (sc->shape == CDL_LUMINOUS_SHAPE_BOX)
        return 4.0 * (a[1] * a[2] * fabs(u[0]) + a[0] * a[2] * fabs(u[1]) + a[0] * a[1] * fabs(u[2]));
    if (k < 0) return CDL_PI * sqrt(sq(a[1] * a[2] * u[0]) + sq(a[0] * a[2] * u[1]) + sq(a[0] * a[1] * u[2]));
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return CDL_PI * a[i] * a[j] * fabs(u[k]) + 4.0 * a[k] * sqrt(sq(a[j] * u[i]) + sq(a[i] * u[j]));
}

/* The bounding sphere about the centre: a box's half diagonal, a cylinder's rim, an ellipsoid's longest semi-axis. */
static double case_bound(const solid_case *sc)
{
    const double *a = sc->half;
    int k = sc->axis;
    if (sc->shape == CDL_LUMINOUS_SHAPE_BOX) return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return k < 0 ? fmax(a[0], fmax(a[1], a[2])) : hypot(fmax(a[(k + 1) % 3], a[(k + 2) % 3]), a[k]);
}

/* The point x, outward unit normal m and area dA of the cell at (u, v) of
 * an n x n grid on [0, 1]^2 over part `part` of the solid centred at c.
 * An ellipsoid is one part: x = D s, s = (sqrt(1 - mu^2) cos phi, ..., mu)
 * on the unit sphere (mu = 2u - 1, phi = 2 pi v; d mu d phi is the unit
 * sphere's area, Archimedes), dA = |cof(D) s| d mu d phi and m along
 * cof(D) s (the cofactor matrix carries oriented areas). A cylinder of
 * axis k: its side (part 0; phi = 2 pi u, x_k = (2v - 1) a_k, dA =
 * |dx/dphi| d phi dx_k, m along (a_j cos phi, a_i sin phi)) and its caps
 * (parts 1 and 2 at x_k = -a_k, +a_k; radius sqrt(u) of the ellipse so
 * the cells share the area pi a_i a_j / n^2). A box: its six faces (part
 * 2m and 2m + 1 at x_m = -a_m, +a_m), cells of 4 a_i a_j / n^2. */
static void surface_cell(const solid_case *sc, cdl_vec3 c, int part, double u, double v, int n, cdl_vec3 *x,
                         cdl_vec3 *m, double *dA)
{
    const double *a = sc->half;
    double px[3], pm[3], cells = (double)n * n;
    int k = sc->axis;
    if (sc->shape == CDL_LUMINOUS_SHAPE_BOX) {
        int f = part / 2, i = (f + 1) % 3, j = (f + 2) % 3;
        double side = part % 2 ? 1.0 : -1.0;
        px[f] = side * a[f], px[i] = (2.0 * u - 1.0) * a[i], px[j] = (2.0 * v - 1.0) * a[j];
        pm[f] = side, pm[i] = pm[j] = 0.0;
        *dA = 4.0 * a[i] * a[j] / cells;
    } else if (k < 0) {
        double mu = 2.0 * u - 1.0, st = sqrt(fmax(0.0, 1.0 - mu * mu)), phi = CDL_TWO_PI * v;
        double s[3] = {st * cos(phi), st * sin(phi), mu};
        double g[3] = {a[1] * a[2] * s[0], a[0] * a[2] * s[1], a[0] * a[1] * s[2]};
        double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        for (int q = 0; q < 3; ++q) {
            px[q] = a[q] * s[q];
            pm[q] = g[q] / gl;
        }
        *dA = gl * 2.0 * CDL_TWO_PI / cells;
    } else {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        if (part == 0) {
            double phi = CDL_TWO_PI * u, ni = a[j] * cos(phi), nj = a[i] * sin(phi), nl = hypot(ni, nj);
            px[i] = a[i] * cos(phi), px[j] = a[j] * sin(phi), px[k] = (2.0 * v - 1.0) * a[k];
            pm[i] = ni / nl, pm[j] = nj / nl, pm[k] = 0.0;
            *dA = nl * CDL_TWO_PI * 2.0 * a[k] / cells;
        } else {
            double rho = sqrt(u), phi = CDL_TWO_PI * v, side = part == 1 ? -1.0 : 1.0;
            px[i] = a[i] * rho * cos(phi), px[j] = a[j] * rho * sin(phi), px[k] = side * a[k];
            pm[i] = pm[j] = 0.0, pm[k] = side;
            *dA = CDL_PI * a[i] * a[j] / cells;
        }
    }
    *x = cdl_vec3_add(c, cdl_vec3_make(px[0], px[1], px[2]));
    *m = cdl_vec3_make(pm[0], pm[1], pm[2]);
}

/* Illuminance at p (normal n) from the solid centred at c (unrotated) with
 * the intensity of ph, by the midpoint rule over n x n cells of each part
 * in the area measure: E = sum L(w_x) cos(theta_o) cos(theta_r) / r^2 dA
 * over the cells that face p (on a convex solid, those p sees) and lie in
 * front of the receiver, w_x from the cell x to p and L(w) = I(w) /
 * A_proj(w) with this file's own A_proj. The table's I as the photometry
 * interpolates it, so that its interpolation, common to both, is no
 * error here. Independent of the emitter's solid-angle sampling, its ray
 * entry and its projected area. */
static double surface_quadrature(const solid_case *sc, const cdl_photometry *ph, cdl_vec3 c, cdl_vec3 p, cdl_vec3 n,
                                 int steps)
{
    double E = 0.0;
    int parts = sc->shape == CDL_LUMINOUS_SHAPE_BOX ? 6 : sc->axis < 0 ? 1 : 3;
    for (int part = 0; part < parts; ++part)
        for (int i = 0; i < steps; ++i)
            for (int j = 0; j < steps; ++j) {
                cdl_vec3 x, m;
                double dA;
                surface_cell(sc, c, part, (i + 0.5) / steps, (j + 0.5) / steps, steps, &x, &m, &dA);
                cdl_vec3 r = cdl_vec3_sub(p, x);
                double r2 = cdl_vec3_dot(r, r);
                cdl_vec3 w = cdl_vec3_scale(r, 1.0 / sqrt(r2));
                double co = cdl_vec3_dot(w, m), cr = -cdl_vec3_dot(w, n);
                if (co > 0.0 && cr > 0.0)
                    E += cdl_photometry_intensity(ph, w).cd / case_projected_area(sc, w) * co * cr / r2 * dA;
            }
    return E;
}

static void test_cylinder(void)
{
    const solid_case cyl = {"vertical cylinder", CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER, {CYL_R, CYL_R, 0.5 * CYL_H}, 2,
                            {-2.0 * CYL_R, -2.0 * CYL_R, CYL_H}};
    cdl_photometry *ph = solid_file(cyl.file[0], cyl.file[1], cyl.file[2], cylinder_table, 0.0);
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER);
    cdl_vec3 c = cdl_vec3_make(1.0, 2.0, 3.0);
    cdl_emitter *e = spread(ph, c, 0);
    const cdl_vec3 at[4] = {{0.0, 0.0, -0.5}, {0.3, 0.0, -0.1}, {0.15, 0.2, 0.05}, {-0.4, 0.3, 0.6}};
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 p = cdl_vec3_add(c, at[k]);
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(-at[k].x, -at[k].y + 0.2, -at[k].z));
        /* the midpoint rule at 400 x 400 cells per face: error below 1e-4 of E
         * at these distances (it falls by 4 per doubling; 200 vs 400 checked below) */
        double q = surface_quadrature(&cyl, ph, c, p, n, 400), q2 = surface_quadrature(&cyl, ph, c, p, n, 200);
        CHECK_MSG(fabs(q - q2) <= 4e-4 * q, "quadrature not converged: %g vs %g", q, q2);
        /* bias: the quadrature's error (a quarter of |q - q2|); the table's
         * interpolation is the quadrature's too */
        double bias = 0.25 * fabs(q - q2) / q;
        check_estimate(sampled(e, p, n, 24, 16, (uint64_t)k), q, bias, "cylinder");
    }
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* The new solids, sized so that none is round and each cylinder's
 * cross-section differs from its length: a 0.6 x 0.3 x 0.2 m ellipsoid,
 * a 0.5 x 0.2 m elliptic cylinder 0.3 m tall, a 0.8 m cylinder along x of
 * elliptic section 0.2 (y) x 0.12 (z), a 0.6 m cylinder along y of round
 * section 0.15 m. */
static const solid_case solids[4] = {
    {"ellipsoid", CDL_LUMINOUS_SHAPE_ELLIPSOID, {0.3, 0.15, 0.1}, -1, {-0.3, -0.6, -0.2}},
    {"vertical elliptic cylinder", CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER, {0.25, 0.1, 0.15}, 2,
     {-0.2, -0.5, 0.3}},
    {"horizontal cylinder along", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG, {0.4, 0.1, 0.06}, 0,
     {-0.2, 0.8, -0.12}},
    {"horizontal cylinder across", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS, {0.075, 0.3, 0.075}, 1,
     {0.6, -0.15, -0.15}},
};

/* the box of test_box as a solid_case */
static const solid_case box_case = {"box", CDL_LUMINOUS_SHAPE_BOX, {0.5 * BOX_L, 0.5 * BOX_W, 0.5 * BOX_H}, -1,
                                    {BOX_W, BOX_L, BOX_H}};

/* a solid of luminance LUM: I = LUM A_proj(C, gamma), C0 along x */
static double uniform_table(int which, double c, double g)
{
    double sg = sin(g * CDL_DEG_TO_RAD), cg = cos(g * CDL_DEG_TO_RAD);
    cdl_vec3 w = cdl_vec3_make(sg * cos(c * CDL_DEG_TO_RAD), sg * sin(c * CDL_DEG_TO_RAD), -cg);
    return LUM * case_projected_area(&solids[which], w);
}
static double ellipsoid_table(double c, double g) { return uniform_table(0, c, g); }
static double elliptic_cylinder_table(double c, double g) { return uniform_table(1, c, g); }
static double along_table(double c, double g) { return uniform_table(2, c, g); }
static double across_table(double c, double g) { return uniform_table(3, c, g); }
static const table_fn solid_tables[4] = {ellipsoid_table, elliptic_cylinder_table, along_table, across_table};

/* v turned by `deg` about the fixed world x, then y, then z axes (sign
 * -1: the inverse, z first), by elementary rotations. */
static cdl_vec3 turn(cdl_vec3 v, const double deg[3], int sign)
{
    for (int step = 0; step < 3; ++step) {
        int axis = sign > 0 ? step : 2 - step;
        double t = sign * deg[axis] * CDL_DEG_TO_RAD, c = cos(t), s = sin(t);
        if (axis == 0) v = cdl_vec3_make(v.x, c * v.y - s * v.z, s * v.y + c * v.z);
        if (axis == 1) v = cdl_vec3_make(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
        if (axis == 2) v = cdl_vec3_make(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
    }
    return v;
}

/* The emitter's E, sampled on k x k strata x 16 runs, at c + off facing
 * the centre (tilt 0) and tilted by `tilt` rad towards `across`, against
 * the surface quadrature at 400 and 200 cells a side (with `rot`, the
 * emitter turned by it: the quadrature's receiver turned back). The
 * midpoint rule converges at least linearly (the integrand is continuous,
 * with kinks at the outline and the horizon), so |q - q2| bounds the
 * error of q; held to 4 standard errors plus that, the standard error
 * below 1 % of the facing E (a tilted receiver may see a sliver). worst[]
 * keeps the largest error and its tolerance, over the facing E. */
static void check_receiver(const cdl_emitter *e, const solid_case *sc, const cdl_photometry *ph, cdl_vec3 c,
                           cdl_vec3 off, cdl_vec3 across, double tilt, const double *rot, int k, uint64_t seed,
                           double worst[2])
{
    cdl_vec3 p = cdl_vec3_add(c, off), toward = cdl_vec3_normalize(cdl_vec3_neg(off));
    double facing = 0.0;
    for (int t = 0; t < 2; ++t) {
        cdl_vec3 n = toward;
        if (t) n = cdl_vec3_add(cdl_vec3_scale(toward, cos(tilt)), cdl_vec3_scale(across, sin(tilt)));
        cdl_vec3 pl = rot ? cdl_vec3_add(c, turn(off, rot, -1)) : p, nl = rot ? turn(n, rot, -1) : n;
        double q = surface_quadrature(sc, ph, c, pl, nl, 400), q2 = surface_quadrature(sc, ph, c, pl, nl, 200);
        if (!t) facing = q;
        CHECK_MSG(fabs(q - q2) <= 2e-3 * facing, "%s: quadrature not converged: %g vs %g", sc->name, q, q2);
        estimate got = sampled(e, p, n, k, 16, seed + (uint64_t)t);
        double tol = 4.0 * got.se + fabs(q - q2);
        CHECK_MSG(fabs(got.mean - q) <= tol && got.se <= 0.01 * facing,
                  "%s%s at %g m, tilt %d: sampled %.6g +- %.2g, surface %.6g (tolerance %.2g)", rot ? "rotated " : "",
                  sc->name, cdl_vec3_length(off), t, got.mean, got.se, q, tol);
        if (fabs(got.mean - q) / facing > worst[0]) worst[0] = fabs(got.mean - q) / facing, worst[1] = tol / facing;
    }
}

/* Uniform ellipsoid and elliptic cylinders against the surface
 * quadrature (check_receiver), at receivers facing the centre and tilted
 * 1 rad from it (the horizon cutting the solid near it), from just outside
 * the solid (inside its bounding sphere) to 7 bounding radii away. */
static void test_solids_uniform(void)
{
    /* offsets from the centre in bounding radii */
    const cdl_vec3 at[6] = {{0.0, 0.1, -0.75}, {0.15, 0.1, -1.3}, {1.4, 0.5, -0.3},
                            {-0.5, 1.2, 0.6},  {0.7, -0.8, 1.1},  {3.5, 2.0, -4.0}};
    for (int s = 0; s < 4; ++s) {
        const solid_case *sc = &solids[s];
        cdl_photometry *ph = solid_file(sc->file[0], sc->file[1], sc->file[2], solid_tables[s], 1.0);
        CHECK_MSG(cdl_photometry_get_metadata(ph)->opening.shape == sc->shape, "%s: read as %s", sc->name,
                  cdl_luminous_shape_name(cdl_photometry_get_metadata(ph)->opening.shape));
        cdl_vec3 c = cdl_vec3_make(0.4, -0.3, 2.0);
        cdl_emitter *e = spread(ph, c, 0);
        CHECK(!cdl_emitter_has_exact_illuminance(e));
        double R = case_bound(sc), worst[2] = {0.0, 0.0};
        for (int k = 0; k < 6; ++k) {
            cdl_vec3 off = cdl_vec3_scale(at[k], R);
            cdl_vec3 across = cdl_vec3_normalize(cdl_vec3_cross(off, cdl_vec3_make(0.3, 1.0, 0.2)));
            /* the nearest receiver, inside the bounding sphere, sees the
             * solid over a wide angle, its edges cutting many strata: 4
             * times the strata there */
            check_receiver(e, sc, ph, c, off, across, 1.0, NULL, k == 0 ? 48 : 24, (uint64_t)(100 * s + 10 * k), worst);
        }
        printf("%s: worst |sampled - surface| %.2e of the facing E (tolerance there %.2e)\n", sc->name, worst[0],
               worst[1]);
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
}

/* A rotated luminaire's solid is the unrotated one turned about its
 * centre (rotation about the fixed x, y, z axes: world = Rz Ry Rx
 * luminaire), so E at p (normal n) from the rotated emitter is the surface
 * quadrature of the unrotated solid at the receiver turned back, c + R^T
 * (p - c) with normal R^T n. The box and the four new solids, receivers
 * facing the centre and tilted (check_receiver). */
static void test_rotated_solids(void)
{
    const double rot[3] = {25.0, -40.0, 70.0};
    const cdl_vec3 at[3] = {{0.2, -1.4, -0.5}, {1.1, 0.9, 0.4}, {-0.3, 0.4, 1.6}};
    cdl_vec3 c = cdl_vec3_make(-0.7, 1.2, 2.4);
    for (int s = -1; s < 4; ++s) {
        const solid_case *sc = s < 0 ? &box_case : &solids[s];
        cdl_photometry *ph = solid_file(sc->file[0], sc->file[1], sc->file[2], s < 0 ? box_table : solid_tables[s], 1.0);
        cdl_goniometric_params gp = CDL_GONIOMETRIC_PARAMS_DEFAULT;
        gp.photometry = ph;
        gp.position = c;
        memcpy(gp.rotation_deg, rot, sizeof rot);
        cdl_emitter *e = NULL;
        cdl_error err;
        CHECK_OK(cdl_emitter_create_goniometric_opening(&gp, &e, &err), &err);
        double R = case_bound(sc), worst[2] = {0.0, 0.0};
        for (int k = 0; k < 3; ++k) {
            cdl_vec3 off = cdl_vec3_scale(at[k], R);
            cdl_vec3 across = cdl_vec3_normalize(cdl_vec3_cross(off, cdl_vec3_make(0.7, -0.2, 0.5)));
            check_receiver(e, sc, ph, c, off, across, 0.9, rot, 24, (uint64_t)(1000 + 10 * k), worst);
        }
        printf("rotated %s: worst |sampled - surface| %.2e of the facing E (tolerance there %.2e)\n", sc->name,
               worst[0], worst[1]);
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
}

/* The flux through a sphere of radius R about the emitter's centre c
 * (which encloses it) is the file's: E on the sphere's inner face,
 * Gauss-Legendre in cos(polar angle) by uniform azimuths (exact for the
 * smooth field to far below the sampling error), summed over its area. */
static void check_flux(const cdl_emitter *e, const cdl_emitter *point, cdl_vec3 c, double R, const char *what)
{
    static const double x8[8] = {-0.96028985649753623, -0.79666647741362674, -0.52553240991632899,
                                 -0.18343464249564980, 0.18343464249564980,  0.52553240991632899,
                                 0.79666647741362674,  0.96028985649753623};
    static const double w8[8] = {0.10122853629037626, 0.22238103445337447, 0.31370664587788729,
                                 0.36268378143772038, 0.36268378143772038, 0.31370664587788729,
                                 0.22238103445337447, 0.10122853629037626};
    /* 3 x 8 Gauss points in each third of [-1, 1] (the field's kinks at the solid's planes smoothed by distance) */
    double flux = 0.0, var = 0.0;
    const int azimuths = 48;
    for (int third = 0; third < 3; ++third)
        for (int g = 0; g < 8; ++g) {
            double mu = -1.0 + (2.0 * third + 1.0 + x8[g]) / 3.0, wmu = w8[g] / 3.0, s = sqrt(1.0 - mu * mu);
            for (int a = 0; a < azimuths; ++a) {
                double phi = CDL_TWO_PI * (a + 0.5) / azimuths;
                cdl_vec3 out = cdl_vec3_make(s * cos(phi), s * sin(phi), mu);
                estimate E = sampled(e, cdl_vec3_madd(c, R, out), cdl_vec3_neg(out), 8, 4,
                                     (uint64_t)((third * 8 + g) * azimuths + a));
                double dA = R * R * wmu * CDL_TWO_PI / azimuths;
                flux += E.mean * dA;
                var += E.se * E.se * dA * dA;
            }
        }
    double want = cdl_emitter_flux(point).lm;
    CHECK_MSG(fabs(flux - want) <= 4.0 * sqrt(var) + 2e-3 * want && sqrt(var) <= 0.005 * want,
              "%s: flux through a sphere: %.6g +- %.2g lm, the file's %.6g lm", what, flux, sqrt(var), want);
    printf("%s: flux %.6g +- %.2g lm, the file's %.6g lm (relative error %.1e, tolerance %.1e)\n", what, flux,
           sqrt(var), want, fabs(flux - want) / want, (4.0 * sqrt(var) + 2e-3 * want) / want);
}

/* The solid's extent from its centre along the unit u (luminaire frame),
 * max x.u over its points: a box's sum a_i |u_i|, an ellipsoid's |D u|, a
 * cylinder's a_k |u_k| (its length) plus its section's sqrt(a_i^2 u_i^2 +
 * a_j^2 u_j^2). */
static double case_support(const solid_case *sc, cdl_vec3 w)
{
    const double *a = sc->half;
    double u[3] = {w.x, w.y, w.z};
    int k = sc->axis;
    if (sc->shape == CDL_LUMINOUS_SHAPE_BOX) return a[0] * fabs(u[0]) + a[1] * fabs(u[1]) + a[2] * fabs(u[2]);
    if (k < 0) return sqrt(sq(a[0] * u[0]) + sq(a[1] * u[1]) + sq(a[2] * u[2]));
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return a[k] * fabs(u[k]) + sqrt(sq(a[i] * u[i]) + sq(a[j] * u[j]));
}

/* Far away a solid of uniform luminance is the point. From p at distance d
 * along u the solid's solid angle is its perspective shadow on the plane
 * through the centre across u, over d^2 (to (R / d)^2); each of its points
 * x lands at x_perp d / (d - x.u) there, and |x.u| <= h (its extent along
 * u), so the shadow lies between the parallel one, A_proj, scaled by d /
 * (d + h) and by d / (d - h) (a convex shadow about the centre). E = L
 * times that, cos(theta_r) within (R / d)^2 / 2 of 1, against the point's
 * L A_proj / d^2: within (d / (d - h))^2 - 1 + (R / d)^2, first order in h
 * / d (the visible half of a solid lies nearer than its centre: a
 * cylinder seen from below is its bottom cap, h nearer). At 20 bounding
 * diameters, h <= R: up to 5 %; the estimate's standard error held to a
 * fifth of it so that the check can fail. */
static void check_far_field(const cdl_emitter *e, const cdl_emitter *point, const solid_case *sc, cdl_vec3 c, double d)
{
    cdl_vec3 dirs[3] = {{0, 0, -1}, {0.6, 0, -0.8}, {0.3, 0.7, -0.648}};
    cdl_shape bound;
    CHECK(cdl_emitter_opening_face(e, &bound));
    double R = bound.radius, worst = 0.0, worst_tol = 0.0;
    for (int k = 0; k < 3; ++k) {
        cdl_vec3 u = cdl_vec3_normalize(dirs[k]), p = cdl_vec3_madd(c, d, u), n = cdl_vec3_neg(u);
        double h = case_support(sc, u), tol = sq(d / (d - h)) - 1.0 + sq(R / d);
        cdl_delta_light dl;
        CHECK(cdl_emitter_eval_delta(point, p, n, &dl));
        estimate got = sampled(e, p, n, 96, 16, (uint64_t)k);
        double far = dl.E.lx;
        CHECK_MSG(fabs(got.mean - far) <= 4.0 * got.se + tol * far && got.se <= 0.2 * tol * far,
                  "%s: far field at %g m: %.6g +- %.2g lx, point %.6g lx", sc->name, d, got.mean, got.se, far);
        if (fabs(got.mean - far) / far > worst) worst = fabs(got.mean - far) / far, worst_tol = tol;
    }
    printf("%s: far field at %.3g bounding diameters: worst relative difference %.1e (tolerance there %.1e + 4 se)\n",
           sc->name, d / (2.0 * R), worst, worst_tol);
}

static void test_flux_and_far_field(void)
{
    cdl_vec3 c = cdl_vec3_make(0.0, 0.0, 0.0);
    for (int s = -1; s < 4; ++s) {
        /* the box (s = -1), then the new solids; each at 20 bounding diameters */
        const solid_case *sc = s < 0 ? &box_case : &solids[s];
        table_fn table = s < 0 ? box_table : solid_tables[s];
        cdl_photometry *ph = solid_file(sc->file[0], sc->file[1], sc->file[2], table, 1.0);
        cdl_emitter *e = spread(ph, c, 0), *point = spread(ph, c, 1);
        double size = sqrt(BOX_L * BOX_L + BOX_W * BOX_W + BOX_H * BOX_H);
        if (s >= 0) size = 2.0 * case_bound(sc);
        check_flux(e, point, c, 1.0, sc->name);
        check_far_field(e, point, sc, c, 20.0 * size);
        cdl_emitter_release(e);
        cdl_emitter_release(point);
        cdl_photometry_release(ph);
    }
}

/* The sampler's density is the pdf cdl_emitter_radiance reports: the
 * chance that a sample succeeds (meets the solid in front of the
 * receiver) is int pdf(omega) d omega over those directions, here over
 * 2^16 stratified directions uniform on the sphere (4 pi pdf averaged).
 * Both are means of 2^16 jittered stratified draws (independent jitters),
 * whose variance is at most the independent draws' (equal strata): the
 * binomial P (1 - P) / N for the count, the sample variance of 4 pi pdf /
 * N for the integral; held to 4 such standard errors. This checks the
 * pdf's normalisation over what the sampler reaches; how the samples
 * spread within it, the unbiased E of the other tests. Every solid, from
 * outside and inside its bounding sphere and, but for the box, from
 * inside its bounding box. */
static double pdf_integral_check(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, const char *what)
{
    const int k = 256;
    double hits = 0.0, s1 = 0.0, s2 = 0.0, jitter[4];
    uint64_t x = 0x9e3779b97f4a7c15ull;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            /* xorshift64 jitter within the stratum, apart for the two estimates */
            for (int m = 0; m < 4; ++m) {
                x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                jitter[m] = (double)(x >> 11) * 0x1.0p-53;
            }
            cdl_light_sample ls;
            hits += cdl_emitter_sample(e, p, n, (i + jitter[0]) / k, (j + jitter[1]) / k, &ls);
            /* uniform on the sphere: z = 2u - 1 (Archimedes) */
            double u = (i + jitter[2]) / k, v = (j + jitter[3]) / k;
            double z = 2.0 * u - 1.0, st = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * v, pdf;
            cdl_vec3 dir = cdl_vec3_make(st * cos(phi), st * sin(phi), z);
            cdl_luminance L = cdl_emitter_radiance(e, p, n, dir, &pdf);
            double f = L.cd_m2 > 0.0 && cdl_vec3_dot(dir, n) > 0.0 ? 4.0 * CDL_PI * pdf : 0.0;
            s1 += f;
            s2 += f * f;
        }
    double N = (double)k * k, P = hits / N, I = s1 / N;
    double se = sqrt(P * (1.0 - P) / N + fmax(0.0, s2 / N - I * I) / N);
    CHECK_MSG(fabs(P - I) <= 4.0 * se + 1e-12 && P > 0.0,
              "%s: samples succeed %.5f of the time, the pdf integrates to %.5f (se %.1e)", what, P, I, se);
    return fabs(P - I) / fmax(se, 1e-300);
}

static void test_pdf_density(void)
{
    cdl_vec3 c = cdl_vec3_make(0.0, 0.0, 0.0);
    double worst = 0.0;
    for (int s = -3; s < 4; ++s) {
        const double r2 = -2.0 * SPHERE_R;
        cdl_photometry *ph = s == -3   ? solid_file(BOX_W, BOX_L, BOX_H, box_table, 1.0)
                             : s == -2 ? solid_file(-2.0 * CYL_R, -2.0 * CYL_R, CYL_H, cylinder_table, 0.0)
                             : s == -1 ? solid_file(r2, r2, r2, sphere_table, 0.0)
                                       : solid_file(solids[s].file[0], solids[s].file[1], solids[s].file[2],
                                                    solid_tables[s], 1.0);
        cdl_emitter *e = spread(ph, c, 0);
        cdl_shape bound;
        CHECK(cdl_emitter_opening_face(e, &bound) && bound.kind == CDL_SHAPE_SPHERE);
        const char *what = s == -3 ? "box" : s == -2 ? "cylinder" : s == -1 ? "sphere" : solids[s].name;
        /* beside the solid, tilted; far below, facing up; inside the bounding sphere (not for the sphere) */
        double R = bound.radius;
        worst = fmax(worst, pdf_integral_check(e, cdl_vec3_make(1.3 * R, 0.4 * R, -0.5 * R),
                                               cdl_vec3_normalize(cdl_vec3_make(-1.0, 0.3, 0.6)), what));
        worst = fmax(worst,
                     pdf_integral_check(e, cdl_vec3_make(0.2 * R, -0.1 * R, -6.0 * R), cdl_vec3_make(0, 0, 1), what));
        if (s != -1) {
            /* a point below the solid yet inside its bounding sphere */
            double below = s == -3 ? BOX_H : s == -2 ? CYL_H : 2.0 * solids[s].half[2];
            double z = -0.5 * (0.5 * below + R);
            worst = fmax(worst, pdf_integral_check(e, cdl_vec3_make(0.0, 0.0, z), cdl_vec3_make(0.2, 0, 1), what));
        }
        if (s >= -2) {
            /* inside the bounding box, outside the solid: near an edge of the box */
            const double *a = s == -2 ? (const double[3]){CYL_R, CYL_R, 0.5 * CYL_H}
                              : s == -1 ? (const double[3]){SPHERE_R, SPHERE_R, SPHERE_R}
                                        : solids[s].half;
            cdl_vec3 q = cdl_vec3_make(0.75 * a[0], 0.75 * a[1], -0.75 * a[2]); /* 0.75^2 x 2 > 1: outside */
            worst = fmax(worst, pdf_integral_check(e, q, cdl_vec3_normalize(cdl_vec3_neg(q)), what));
        }
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
    printf("sampler density against the radiance pdf: worst %.2f standard errors (tolerance 4)\n", worst);
}

/* Each new shape read from its 1995 and its 2002 sign code (the 1995
 * horizontal cylinders give one diameter and a 0: a round section) into
 * the sizes the emitter spreads over: the shape and sizes, the bounding
 * sphere, and the outline the emitter's rays meet against
 * cdl_luminous_opening_projected_area. The outline is counted on a grid of
 * 600 x 600 parallel rays over the bounding sphere's square (side 2 R,
 * cell h): only cells within h / sqrt 2 of the outline can be counted
 * wrongly, a band of area at most 2 (h / sqrt 2) P + pi h^2 / 2 for an
 * outline of perimeter P <= 2 pi R (convex, inside the bounding disk). */
static void test_sign_codes(void)
{
    static const struct {
        const char *tag, *wlh;
        cdl_luminous_shape shape;
        double W, L, H; /* metres, as read */
    } codes[] = {
        {"IESNA:LM-63-1995", "-0.3 0.6 -0.2", CDL_LUMINOUS_SHAPE_ELLIPSOID, 0.3, 0.6, 0.2},
        {"IESNA:LM-63-2002", "-0.3 -0.6 -0.2", CDL_LUMINOUS_SHAPE_ELLIPSOID, 0.3, 0.6, 0.2},
        {"IESNA:LM-63-1995", "0.2 -0.5 0.3", CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER, 0.2, 0.5, 0.3},
        {"IESNA:LM-63-2002", "-0.2 -0.5 0.3", CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER, 0.2, 0.5, 0.3},
        {"IESNA:LM-63-1995", "0 0.8 -0.12", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG, 0.12, 0.8, 0.12},
        {"IES:LM-63-2019", "-0.2 0.8 -0.12", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG, 0.2, 0.8, 0.12},
        {"IESNA:LM-63-1995", "0.6 0 -0.15", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS, 0.6, 0.15, 0.15},
        {"IESNA:LM-63-2002", "0.6 -0.25 -0.15", CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS, 0.6, 0.25, 0.15},
    };
    const cdl_vec3 views[3] = {{0.3, 0.5, -0.81}, {0.8, -0.2, 0.56}, {-0.45, 0.62, 0.3}};
    double worst = 0.0, worst_tol = 0.0;
    for (size_t m = 0; m < sizeof codes / sizeof codes[0]; ++m) {
        char text[256];
        snprintf(text, sizeof text, "%s\n[TEST] code\nTILT=NONE\n1 -1 1 2 1 1 2 %s\n1 1 10\n0 90\n0\n10 5\n", codes[m].tag,
                 codes[m].wlh);
        cdl_photometry *ph = NULL;
        cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
        cdl_error err;
        CHECK_OK(cdl_photometry_read_memory(text, strlen(text), "code.ies", &opt, &ph, &err), &err);
        if (!ph) continue;
        const cdl_luminous_opening *o = &cdl_photometry_get_metadata(ph)->opening;
        CHECK_MSG(o->shape == codes[m].shape && fabs(o->width_m - codes[m].W) <= 1e-12 &&
                      fabs(o->length_m - codes[m].L) <= 1e-12 && fabs(o->height_m - codes[m].H) <= 1e-12,
                  "%s %s: read %s %g x %g x %g m", codes[m].tag, codes[m].wlh, cdl_luminous_shape_name(o->shape),
                  o->width_m, o->length_m, o->height_m);
        CHECK(cdl_luminous_opening_is_spread(o));
        /* the solid's semi-axes: length along x, width along y, height along z */
        solid_case sc = {"", o->shape, {0.5 * codes[m].L, 0.5 * codes[m].W, 0.5 * codes[m].H}, -1, {0, 0, 0}};
        sc.axis = o->shape == CDL_LUMINOUS_SHAPE_ELLIPSOID                     ? -1
                  : o->shape == CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER  ? 2
                  : o->shape == CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG ? 0
                                                                               : 1;
        cdl_vec3 c = cdl_vec3_make(-1.0, 0.5, 2.0);
        cdl_emitter *e = spread(ph, c, 0);
        cdl_shape bound;
        CHECK(cdl_emitter_opening_face(e, &bound) && bound.kind == CDL_SHAPE_SPHERE);
        double R = case_bound(&sc);
        CHECK_REL(bound.radius, R, 1e-12);
        for (int v = 0; v < 3; ++v) {
            cdl_vec3 w = cdl_vec3_normalize(views[v]);
            cdl_frame f = cdl_frame_from_normal(w);
            const int k = 600;
            double h = 2.0 * R / k, count = 0.0;
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    cdl_vec3 at = cdl_vec3_make(-R + (i + 0.5) * h, -R + (j + 0.5) * h, 3.0 * R);
                    cdl_vec3 from = cdl_vec3_add(c, cdl_frame_to_world(&f, at));
                    double pdf;
                    cdl_emitter_radiance(e, from, cdl_vec3_neg(w), cdl_vec3_neg(w), &pdf);
                    count += pdf > 0.0;
                }
            double A = cdl_luminous_opening_projected_area(o, w);
            double band = CDL_TWO_PI * R * sqrt(2.0) * h + 0.5 * CDL_PI * h * h;
            CHECK_MSG(fabs(count * h * h - A) <= band,
                      "%s %s seen along (%g, %g, %g): rays meet %.6g m^2, A_proj %.6g m^2", codes[m].tag, codes[m].wlh,
                      w.x, w.y, w.z, count * h * h, A);
            if (fabs(count * h * h - A) / A > worst) worst = fabs(count * h * h - A) / A, worst_tol = band / A;
            /* and the library's A_proj is the closed form */
            CHECK_REL(A, case_projected_area(&sc, w), 1e-12);
        }
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
    printf("sign codes: the rays' outline against A_proj: worst relative difference %.1e (tolerance there %.1e)\n",
           worst, worst_tol);
}

/* Shapes not spread are refused, not silently made points: a code in no
 * table, and a point. */
static void test_refused(void)
{
    const double codes[2][3] = {{0.0, -0.63, 0.0}, {0.0, 0.0, 0.0}};
    for (int m = 0; m < 2; ++m) {
        cdl_photometry *ph = solid_file(codes[m][0], codes[m][1], codes[m][2], sphere_table, 0.0);
        CHECK(!cdl_luminous_opening_is_spread(&cdl_photometry_get_metadata(ph)->opening));
        cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
        p.photometry = ph;
        cdl_emitter *e = NULL;
        cdl_error err;
        CHECK(cdl_emitter_create_goniometric_opening(&p, &e, &err) == CDL_ERR_INPUT && e == NULL);
        CHECK(strstr(err.message, m == 0 ? "unknown" : "point") != NULL);
        cdl_photometry_release(ph);
    }
}

/* ---- a box whose sides are luminous to different heights (EULUMDAT) ------- */

/* Sides facing C0, C90, C180, C270 luminous to these heights from the
 * bottom of the box, which is as tall as the tallest; the luminous area
 * (lines 16-17) 0.2 m long (the IES width, along y) by 0.6 m wide (the
 * IES length, along x: FORMAT_NOTES 3.3's swap, as the reader takes it). */
static const double side_h[4] = {0.10, 0.06, 0.02, 0.08};
#define SIDES_W 0.2 /* along y */
#define SIDES_L 0.6 /* along x */

/* Its projected luminous area along the unit w (luminaire frame), by the
 * test's own reckoning: the bottom or top W L |w.z|, and the one side
 * across each horizontal axis that faces w, at its own height. */
static double sides_projected_area(cdl_vec3 w)
{
    double hx = w.x > 0.0 ? side_h[0] : side_h[2], hy = w.y > 0.0 ? side_h[1] : side_h[3];
    return SIDES_W * SIDES_L * fabs(w.z) + SIDES_W * hx * fabs(w.x) + SIDES_L * hy * fabs(w.y);
}

/* An EULUMDAT file of that box with I = LUM x its projected area (one
 * luminance over every luminous part), no symmetry, C and gamma every
 * degree, 1000 lm so that cd/klm are cd. */
static cdl_photometry *sides_file(void)
{
    size_t cap = 1 << 21, n = 0;
    char *t = malloc(cap);
    CHECK(t != NULL);
    n += (size_t)snprintf(t + n, cap - n, "Candela tests\n1\n0\n360\n1\n181\n1\nreport\nsides\n1\nsides.ldt\n"
                                          "2026-11-24 / tests\n600\n200\n100\n%g\n%g\n",
                          SIDES_W * 1000.0, SIDES_L * 1000.0);
    for (int k = 0; k < 4; ++k) n += (size_t)snprintf(t + n, cap - n, "%g\n", side_h[k] * 1000.0);
    n += (size_t)snprintf(t + n, cap - n, "50\n100\n1\n0\n1\n1\nLED\n1000\n3000\n80\n10\n");
    for (int k = 0; k < 10; ++k) n += (size_t)snprintf(t + n, cap - n, "0.5\n");
    for (int c = 0; c < 360; ++c) n += (size_t)snprintf(t + n, cap - n, "%d\n", c);
    for (int g = 0; g <= 180; ++g) n += (size_t)snprintf(t + n, cap - n, "%d\n", g);
    for (int c = 0; c < 360; ++c)
        for (int g = 0; g <= 180; ++g) {
            double C = c * CDL_DEG_TO_RAD, G = g * CDL_DEG_TO_RAD;
            /* type C: C0 along x, gamma from the nadir */
            cdl_vec3 w = cdl_vec3_make(sin(G) * cos(C), sin(G) * sin(C), -cos(G));
            n += (size_t)snprintf(t + n, cap - n, "%.17g\n", LUM * sides_projected_area(w));
        }
    cdl_photometry *ph = NULL;
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_error err;
    CHECK_OK(cdl_photometry_read_memory(t, n, "sides.ldt", &opt, &ph, &err), &err);
    free(t);
    return ph;
}

/* The file read: a box, each side's height kept (the mean as LM-63's one
 * height). Lit from every luminous part at one luminance, so at receivers
 * around it, each facing the box's centre, E is LUM times Lambert's factor
 * of every luminous face part in front of it (the bottom and top whole,
 * each side from the bottom to its height), sampled within 4 standard
 * errors plus the table's interpolation (1e-4 as for the uniform box).
 * The sides' dark parts show: were every side lit to the box's top, these
 * probes would get up to five times their light. The flux through an
 * enclosing sphere is the file's, which is LUM pi times the luminous area
 * (Cauchy: the mean projected area of a convex body is a quarter of its
 * surface), here 2 W L + W (h0 + h2) + L (h1 + h3). */
static void test_box_side_heights(void)
{
    cdl_photometry *ph = sides_file();
    if (!ph) return;
    const cdl_luminous_opening *o = &cdl_photometry_get_metadata(ph)->opening;
    CHECK(o->shape == CDL_LUMINOUS_SHAPE_BOX);
    CHECK_REL(o->height_m, 0.065, 1e-12);
    for (int k = 0; k < 4; ++k) CHECK_REL(cdl_luminous_opening_box_side_height_m(o, k), side_h[k], 1e-12);
    double area = 2.0 * SIDES_W * SIDES_L + SIDES_W * (side_h[0] + side_h[2]) + SIDES_L * (side_h[1] + side_h[3]);
    /* the table's flux: 1-degree steps, within 1e-4 of the closed form */
    CHECK_REL(cdl_photometry_flux(ph).lm, LUM * CDL_PI * area, 1e-4);
    cdl_vec3 c = cdl_vec3_make(1.0, -2.0, 3.0);
    cdl_emitter *e = spread(ph, c, 0), *point = spread(ph, c, 1);
    const double h[3] = {0.5 * SIDES_L, 0.5 * SIDES_W, 0.5 * side_h[0]}; /* the tallest side: 0.1 m */
    const cdl_vec3 at[6] = {{0.0, 0.0, -0.3}, {0.5, 0.05, -0.01}, {-0.5, 0.02, 0.0},
                            {0.1, 0.4, 0.02}, {-0.2, -0.3, 0.0}, {1.2, 0.9, 0.6}};
    for (int k = 0; k < 6; ++k) {
        cdl_vec3 p = cdl_vec3_add(c, at[k]), n = cdl_vec3_normalize(cdl_vec3_neg(at[k]));
        double tops[4];
        for (int m = 0; m < 4; ++m) tops[m] = -h[2] + side_h[m];
        double E = lambert_box(c, h, tops, LUM, p, n);
        check_estimate(sampled(e, p, n, 24, 16, (uint64_t)(100 + k)), E, 1e-4, "box with sides of their own heights");
    }
    check_flux(e, point, c, 1.0, "box with sides of their own heights");
    cdl_emitter_release(e);
    cdl_emitter_release(point);
    cdl_photometry_release(ph);
}

int main(void)
{
    test_sphere();
    test_box();
    test_cylinder();
    test_solids_uniform();
    test_rotated_solids();
    test_flux_and_far_field();
    test_pdf_density();
    test_sign_codes();
    test_refused();
    test_box_side_heights();
    return check_finish();
}
