/* Goniometric luminaires spread over a luminous solid (IES LM-63 box with
 * luminous sides, vertical cylinder, sphere): tables of uniform luminance
 * against closed-form configuration factors (a sphere to facing and tilted
 * elements, a box face by face with Lambert's polygon formula), a
 * non-uniform cylinder against an independent quadrature over its faces,
 * the flux through an enclosing sphere, the far field against the point
 * model, and the sampler's pdf against cdl_emitter_radiance. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "sphere_factor.h"
#include "lights/emitter.h"
#include "lights/photometry.h"
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
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_DEFAULT;
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

/* ---- closed forms ------------------------------------------------------------ */

/* Illuminance at p (normal n) from a Lambertian convex polygon of
 * luminance L lying wholly in front of p's plane, by Lambert's contour
 * integral (Siegel and Howell, Thermal Radiation Heat Transfer, the
 * polygon-to-element factor): E = (L / 2) |sum_i beta_i n.u_i|. */
static double lambert_polygon(const cdl_vec3 *v, int count, double L, cdl_vec3 p, cdl_vec3 n)
{
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        cdl_vec3 a = cdl_vec3_sub(v[i], p), b = cdl_vec3_sub(v[(i + 1) % count], p), x = cdl_vec3_cross(a, b);
        double lx = cdl_vec3_length(x);
        if (lx > 0.0) sum += atan2(lx, cdl_vec3_dot(a, b)) * cdl_vec3_dot(n, x) / lx;
    }
    return 0.5 * L * fabs(sum);
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
        double E = 0.0;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = -1; side <= 1; side += 2) {
                double q[3] = {at[k].x, at[k].y, at[k].z};
                if (q[axis] * side <= h[axis]) continue; /* p behind this face's plane */
                int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
                cdl_vec3 v[4];
                for (int m = 0; m < 4; ++m) {
                    double w[3];
                    w[axis] = side * h[axis];
                    w[a1] = (m == 1 || m == 2) ? h[a1] : -h[a1];
                    w[a2] = m >= 2 ? h[a2] : -h[a2];
                    v[m] = cdl_vec3_add(c, cdl_vec3_make(w[0], w[1], w[2]));
                }
                E += lambert_polygon(v, 4, LUM, p, n);
            }
        /* the table at 1-degree steps in C and gamma: bilinear interpolation of
         * |cos|, |sin| terms is within (1 deg)^2 / 8 = 4e-5 of them, plus the
         * kinks at the axes, which lie on nodes: 1e-4 */
        check_estimate(sampled(e, p, n, 24, 16, (uint64_t)k), E, 1e-4, "uniform box");
    }
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* Illuminance at p (normal n) from a vertical cylinder (radius CYL_R,
 * height CYL_H, centred at c) whose luminance towards w is I(w) /
 * A_proj(w), by a midpoint rule over its faces in the area measure:
 * E = sum L(w_x) cos(theta_o) cos(theta_r) / r^2 dA (w_x from the element
 * x to p). Independent of the emitter's solid-angle sampling. */
static double cylinder_quadrature(cdl_vec3 c, cdl_vec3 p, cdl_vec3 n, int steps)
{
    double E = 0.0;
    for (int face = 0; face < 3; ++face)
        for (int i = 0; i < steps; ++i)
            for (int j = 0; j < steps; ++j) {
                double a = (i + 0.5) / steps, b = (j + 0.5) / steps, dA;
                cdl_vec3 x, m;
                if (face == 0) { /* the side: angle a, height b */
                    double phi = CDL_TWO_PI * a;
                    m = cdl_vec3_make(cos(phi), sin(phi), 0.0);
                    x = cdl_vec3_add(c, cdl_vec3_make(CYL_R * m.x, CYL_R * m.y, (b - 0.5) * CYL_H));
                    dA = CDL_TWO_PI * CYL_R * CYL_H / ((double)steps * steps);
                } else { /* a cap: radius by sqrt for equal areas, angle b */
                    double rho = CYL_R * sqrt(a), phi = CDL_TWO_PI * b, z = face == 1 ? -0.5 * CYL_H : 0.5 * CYL_H;
                    m = cdl_vec3_make(0.0, 0.0, face == 1 ? -1.0 : 1.0);
                    x = cdl_vec3_add(c, cdl_vec3_make(rho * cos(phi), rho * sin(phi), z));
                    dA = CDL_PI * CYL_R * CYL_R / ((double)steps * steps);
                }
                cdl_vec3 r = cdl_vec3_sub(p, x);
                double r2 = cdl_vec3_dot(r, r), rl = sqrt(r2);
                cdl_vec3 w = cdl_vec3_scale(r, 1.0 / rl);
                double co = cdl_vec3_dot(w, m), cr = -cdl_vec3_dot(w, n);
                if (co <= 0.0 || cr <= 0.0) continue;
                double cg = w.z, sg = sqrt(fmax(0.0, 1.0 - cg * cg));
                double gamma = acos(-cg) / CDL_DEG_TO_RAD; /* gamma from the nadir */
                double A = 2.0 * CYL_R * CYL_H * sg + CDL_PI * CYL_R * CYL_R * fabs(cg);
                E += cylinder_table(0.0, gamma) / A * co * cr / r2 * dA;
            }
    return E;
}

static void test_cylinder(void)
{
    cdl_photometry *ph = solid_file(-2.0 * CYL_R, -2.0 * CYL_R, CYL_H, cylinder_table, 0.0);
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER);
    cdl_vec3 c = cdl_vec3_make(1.0, 2.0, 3.0);
    cdl_emitter *e = spread(ph, c, 0);
    const cdl_vec3 at[4] = {{0.0, 0.0, -0.5}, {0.3, 0.0, -0.1}, {0.15, 0.2, 0.05}, {-0.4, 0.3, 0.6}};
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 p = cdl_vec3_add(c, at[k]);
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(-at[k].x, -at[k].y + 0.2, -at[k].z));
        /* the midpoint rule at 400 x 400 cells per face: error below 1e-4 of E
         * at these distances (it halves... by 4 per doubling; 200 vs 400 checked below) */
        double q = cylinder_quadrature(c, p, n, 400), q2 = cylinder_quadrature(c, p, n, 200);
        CHECK_MSG(fabs(q - q2) <= 4e-4 * q, "quadrature not converged: %g vs %g", q, q2);
        /* bias: the quadrature's error (a quarter of |q - q2|) plus the
         * 1-degree table's interpolation, 1e-4 */
        double bias = 1e-4 + 0.25 * fabs(q - q2) / q;
        check_estimate(sampled(e, p, n, 24, 16, (uint64_t)k), q, bias, "cylinder");
    }
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* The flux through an enclosing sphere is the file's: E on the sphere's
 * inner face, Gauss-Legendre in cos(polar angle) by uniform azimuths
 * (exact for the smooth field to far below the sampling error), summed
 * over its area. */
static void test_flux_and_far_field(void)
{
    cdl_photometry *ph = solid_file(BOX_W, BOX_L, BOX_H, box_table, 1.0);
    cdl_vec3 c = cdl_vec3_make(0.0, 0.0, 0.0);
    cdl_emitter *e = spread(ph, c, 0), *point = spread(ph, c, 1);
    static const double x8[8] = {-0.96028985649753623, -0.79666647741362674, -0.52553240991632899,
                                 -0.18343464249564980, 0.18343464249564980,  0.52553240991632899,
                                 0.79666647741362674,  0.96028985649753623};
    static const double w8[8] = {0.10122853629037626, 0.22238103445337447, 0.31370664587788729,
                                 0.36268378143772038, 0.36268378143772038, 0.31370664587788729,
                                 0.22238103445337447, 0.10122853629037626};
    /* 3 x 8 Gauss points in each third of [-1, 1] (the field's kinks at the box's planes smoothed by distance) */
    double R = 1.0, flux = 0.0, var = 0.0;
    const int azimuths = 48;
    for (int third = 0; third < 3; ++third)
        for (int g = 0; g < 8; ++g) {
            double mu = -1.0 + (2.0 * third + 1.0 + x8[g]) / 3.0, wmu = w8[g] / 3.0, s = sqrt(1.0 - mu * mu);
            for (int a = 0; a < azimuths; ++a) {
                double phi = CDL_TWO_PI * (a + 0.5) / azimuths;
                cdl_vec3 out = cdl_vec3_make(s * cos(phi), s * sin(phi), mu);
                estimate E = sampled(e, cdl_vec3_scale(out, R), cdl_vec3_neg(out), 8, 4, (uint64_t)((third * 8 + g) * azimuths + a));
                double dA = R * R * wmu * CDL_TWO_PI / azimuths;
                flux += E.mean * dA;
                var += E.se * E.se * dA * dA;
            }
        }
    double want = cdl_emitter_flux(point).lm;
    CHECK_MSG(fabs(flux - want) <= 4.0 * sqrt(var) + 2e-3 * want && sqrt(var) <= 0.005 * want,
              "flux through a sphere: %.6g +- %.2g lm, the file's %.6g lm", flux, sqrt(var), want);
    /* far away the box is the point: E differs by about (size / d)^2 */
    double size = sqrt(BOX_L * BOX_L + BOX_W * BOX_W + BOX_H * BOX_H), d = 15.0 * size;
    cdl_vec3 dirs[3] = {{0, 0, -1}, {0.6, 0, -0.8}, {0.3, 0.7, -0.648}};
    for (int k = 0; k < 3; ++k) {
        cdl_vec3 u = cdl_vec3_normalize(dirs[k]), p = cdl_vec3_scale(u, d), n = cdl_vec3_neg(u);
        cdl_delta_light dl;
        CHECK(cdl_emitter_eval_delta(point, p, n, &dl));
        estimate got = sampled(e, p, n, 32, 16, (uint64_t)k);
        double far = dl.E.lx;
        CHECK_MSG(fabs(got.mean - far) <= 4.0 * got.se + (size / d) * (size / d) * far,
                  "far field at %g m: %.6g +- %.2g lx, point %.6g lx", d, got.mean, got.se, far);
    }
    cdl_emitter_release(e);
    cdl_emitter_release(point);
    cdl_photometry_release(ph);
}

/* Shapes not spread are refused, not silently made points. */
static void test_refused(void)
{
    cdl_photometry *ph = solid_file(-0.2, 0.5, -0.2, sphere_table, 0.0); /* horizontal cylinder along */
    CHECK(!cdl_luminous_opening_is_spread(&cdl_photometry_get_metadata(ph)->opening));
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.photometry = ph;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK(cdl_emitter_create_goniometric_opening(&p, &e, &err) == CDL_ERR_INPUT && e == NULL);
    CHECK(strstr(err.message, "horizontal") != NULL);
    cdl_photometry_release(ph);
}

int main(void)
{
    test_sphere();
    test_box();
    test_cylinder();
    test_flux_and_far_field();
    test_refused();
    return check_finish();
}
