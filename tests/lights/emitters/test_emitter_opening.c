/* Goniometric luminaires spread over their luminous opening (near field):
 * a Lambertian table on rectangles and disks against the closed-form
 * configuration factors, the sampler against the same, far-field agreement
 * with the point model, flux, rotation, and the opening's luminance. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ellipse_segment.h"
#include "lights/emitters/emitter.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"

/* ---- photometric files in memory ------------------------------------------ */

/* An IES file (LM-63 `version`: "2002" or "1995") with the opening (W, L, H)
 * in metres and the table I(C, gamma) = f(C, gamma): one plane when
 * `planes` is 1, else C every c_step degrees over [0, 360] (make_ies: 15);
 * gamma every `step` degrees. */
static cdl_photometry *make_ies_planes(const char *version, double W, double L, double H,
                                       double (*f)(double, double), int planes, double c_step, double step)
{
    size_t cap = 1 << 23, n = 0;
    char *s = malloc(cap);
    int ng = (int)lround(180.0 / step) + 1, nh = planes == 1 ? 1 : (int)lround(360.0 / c_step) + 1;
    n += (size_t)snprintf(s + n, cap - n, "IESNA:LM-63-%s\n[TEST] near field\nTILT=NONE\n", version);
    n += (size_t)snprintf(s + n, cap - n, "1 -1 1 %d %d 1 2 %.17g %.17g %.17g\n1 1 0\n", ng, nh, W, L, H);
    for (int j = 0; j < ng; ++j) n += (size_t)snprintf(s + n, cap - n, "%.17g ", j * step);
    n += (size_t)snprintf(s + n, cap - n, "\n");
    for (int i = 0; i < nh; ++i) n += (size_t)snprintf(s + n, cap - n, "%.17g ", c_step * i);
    n += (size_t)snprintf(s + n, cap - n, "\n");
    for (int i = 0; i < nh; ++i) {
        for (int j = 0; j < ng; ++j) n += (size_t)snprintf(s + n, cap - n, "%.17g ", f(c_step * i, j * step));
        n += (size_t)snprintf(s + n, cap - n, "\n");
    }
    cdl_photometry *ph = NULL;
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_error err;
    CHECK_OK(cdl_photometry_read_memory(s, n, "near.ies", &opt, &ph, &err), &err);
    free(s);
    return ph;
}

static cdl_photometry *make_ies(const char *version, double W, double L, double H, double (*f)(double, double),
                                int planes, double step)
{
    return make_ies_planes(version, W, L, H, f, planes, 15.0, step);
}

#define I0 1000.0

/* I = I0 cos(gamma) below the horizontal, none above */
static double lambert(double C, double g)
{
    (void)C;
    return g < 90.0 ? I0 * cos(g * CDL_DEG_TO_RAD) : 0.0;
}

/* An asymmetric distribution: brighter towards C = 0 than C = 180 */
static double asymmetric(double C, double g)
{
    double r = g * CDL_DEG_TO_RAD;
    return g < 90.0 ? I0 * cos(r) * (1.0 + 0.6 * sin(r) * cos(C * CDL_DEG_TO_RAD)) : 0.0;
}

static cdl_emitter *make_opening(const cdl_photometry *ph, cdl_vec3 position, double rx, double ry, double rz)
{
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.photometry = ph;
    p.position = position;
    p.rotation_deg[0] = rx;
    p.rotation_deg[1] = ry;
    p.rotation_deg[2] = rz;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_goniometric_opening(&p, &e, &err), &err);
    return e;
}

static cdl_emitter *make_point(const cdl_photometry *ph, cdl_vec3 position)
{
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.photometry = ph;
    p.position = position;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, &err), &err);
    return e;
}

/* ---- independent closed forms ---------------------------------------------- */

/* The polygon v[0..n) clipped to the half-space (x - p).m >= 0
 * (Sutherland-Hodgman); returns the new count (out has room for 2 n). */
static int clip_polygon(const cdl_vec3 *v, int n, cdl_vec3 p, cdl_vec3 m, cdl_vec3 *out)
{
    int k = 0;
    for (int i = 0; i < n; ++i) {
        cdl_vec3 a = v[i], b = v[(i + 1) % n];
        double da = cdl_vec3_dot(cdl_vec3_sub(a, p), m), db = cdl_vec3_dot(cdl_vec3_sub(b, p), m);
        if (da >= 0.0) out[k++] = a;
        if ((da >= 0.0) != (db >= 0.0)) out[k++] = cdl_vec3_add(a, cdl_vec3_scale(cdl_vec3_sub(b, a), da / (da - db)));
    }
    return k;
}

/* Illuminance at p (normal n) from a Lambertian polygon of luminance L, by
 * the configuration factor of a polygon to a differential element (the
 * contour integral: Siegel and Howell, Thermal Radiation Heat Transfer,
 * appendix; Lambert 1760): E = (L / 2) |sum_i beta_i n.u_i|, beta_i the
 * angle subtended by edge i at p, u_i the unit normal of the plane through
 * p and that edge. The polygon is first clipped to p's hemisphere. */
static double polygon_E(const cdl_vec3 *v, int n, double L, cdl_vec3 p, cdl_vec3 nrm)
{
    cdl_vec3 c[16];
    int k = clip_polygon(v, n, p, nrm, c);
    double sum = 0.0;
    for (int i = 0; i < k; ++i) {
        cdl_vec3 a = cdl_vec3_sub(c[i], p), b = cdl_vec3_sub(c[(i + 1) % k], p);
        cdl_vec3 x = cdl_vec3_cross(a, b);
        double lx = cdl_vec3_length(x);
        if (!(lx > 0.0)) continue;
        double beta = atan2(lx, cdl_vec3_dot(a, b));
        sum += beta * cdl_vec3_dot(nrm, x) / lx;
    }
    return 0.5 * L * fabs(sum);
}

/* Illuminance at height h below the centre-offset a of a horizontal
 * Lambertian disk of radius r and luminance L on a plane parallel to it:
 * E = pi L F, F = (1/2) (1 - (h^2 + a^2 - r^2) / sqrt((h^2 + a^2 + r^2)^2
 * - 4 a^2 r^2)) (differential element parallel to a disk; Siegel and
 * Howell, configuration factor B-13). */
static double disk_E(double L, double r, double h, double a)
{
    double s = h * h + a * a + r * r;
    return CDL_PI * L * 0.5 * (1.0 - (h * h + a * a - r * r) / sqrt(s * s - 4.0 * a * a * r * r));
}

/* splitmix64 (Steele, Lea and Flood 2014): the tests' own random numbers. */
static double next_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* Mean of L cos / pdf over k x k strata of the emitter's sampler, one
 * random sample in each (seeded). */
static double sampled_E_seeded(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, int k, uint64_t seed)
{
    uint64_t state = seed;
    double sum = 0.0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            double u1 = (i + next_uniform(&state)) / k, u2 = (j + next_uniform(&state)) / k;
            cdl_light_sample s;
            if (!cdl_emitter_sample(e, p, n, u1, u2, &s)) continue;
            double c = cdl_vec3_dot(n, s.to_light);
            if (c > 0.0) sum += s.L.cd_m2 * c / s.pdf;
        }
    return sum / ((double)k * k);
}

static double sampled_E(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, int k)
{
    return sampled_E_seeded(e, p, n, k, 12345);
}

/* ---- probes ------------------------------------------------------------------ */

/* Receiver normals: facing up (horizontal), tilted 40 degrees about y and
 * about x, and vertical facing -x and +y. */
static const double normals[5][3] = {
    {0, 0, 1}, {0.64278760968653925, 0, 0.76604444311897801}, {0, -0.64278760968653925, 0.76604444311897801},
    {-1, 0, 0}, {0, 1, 0}};

/* Probe positions relative to the opening (at the origin, facing down):
 * depths from 2 cm to 10 m, on axis, off along the length (x) and across
 * (y), and beyond the end. */
static const double depths[] = {0.02, 0.05, 0.1, 0.3, 0.7, 1.3, 2.0, 4.0, 10.0};
static const double offsets[][2] = {{0, 0}, {0.4, 0}, {0, 0.1}, {0.9, 0.25}, {-1.5, 0.6}};

/* A Lambertian table on a 1.2 m x 0.3 m rectangle (length along the
 * luminaire's x) is a Lambertian rectangle of luminance I0 / A: the
 * emitter's closed form against the contour integral at every probe, to
 * 1e-9 relative (two exact forms differing only in rounding; the largest
 * sums cancel to about 1e-12). The sampler (the one non-Lambertian tables
 * use) agrees with it to 0.2 % over 256^2 strata: its relative spread over
 * 8 seeds at 128^2 strata was at most 6.6e-4 (2 cm from the opening,
 * vertical receivers: the hemisphere's edge crosses the opening), about
 * 2.5e-4 at 256^2, so 0.2 % is eight sigma. The solver's stated errors are
 * tested in tests/solver/direct/test_near_field.c. */
static void test_lambertian_rectangle(void)
{
    cdl_photometry *ph = make_ies("2002", 0.3, 1.2, 0.0, lambert, 1, 1.0);
    if (!ph) return;
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_RECTANGLE);
    cdl_vec3 c = cdl_vec3_make(0, 0, 0);
    cdl_emitter *e = make_opening(ph, c, 0, 0, 0);
    if (!e) return;
    CHECK(!cdl_emitter_is_delta(e));
    CHECK(cdl_emitter_has_exact_illuminance(e));
    double L = I0 / (1.2 * 0.3);
    cdl_vec3 v[4] = {{-0.6, -0.15, 0}, {0.6, -0.15, 0}, {0.6, 0.15, 0}, {-0.6, 0.15, 0}};
    double worst_exact = 0.0, worst_sampled = 0.0;
    for (size_t d = 0; d < sizeof depths / sizeof *depths; ++d)
        for (size_t o = 0; o < sizeof offsets / sizeof *offsets; ++o)
            for (int k = 0; k < 5; ++k) {
                cdl_vec3 p = cdl_vec3_make(offsets[o][0], offsets[o][1], -depths[d]);
                cdl_vec3 n = cdl_vec3_make(normals[k][0], normals[k][1], normals[k][2]);
                double want = polygon_E(v, 4, L, p, n);
                cdl_illuminance E;
                CHECK(cdl_emitter_exact_illuminance(e, p, n, &E, NULL) == CDL_OK);
                if (want < 1e-9 * L) {
                    CHECK(E.lx < 1e-9 * L);
                    continue;
                }
                worst_exact = fmax(worst_exact, fabs(E.lx / want - 1.0));
                CHECK_REL(E.lx, want, 1e-9);
                if (want > 1e-4 * L) {
                    double s = sampled_E(e, p, n, 256);
                    worst_sampled = fmax(worst_sampled, fabs(s / want - 1.0));
                    CHECK_REL(s, want, 2e-3);
                }
            }
    printf("Lambertian rectangle: closed form within %.2g, sampler within %.2g of the contour integral\n",
           worst_exact, worst_sampled);
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* A Lambertian table on a 0.6 m disk: the closed form against the
 * parallel-disk configuration factor (horizontal receivers on and off
 * axis, 2 cm to 10 m) to 1e-9; the same disk written with the 1995
 * ellipse code (W < 0, L > 0: an ellipse of equal axes, no closed form)
 * by its adaptive cubature within the table's interpolation error, and
 * within 0.2 % by its sampler (its bounding rectangle's) at 256^2 strata:
 * its relative spread over 16 seeds at 128^2 strata was at most 1.1e-3
 * (5 cm under the rim; the rim's hit-or-miss edge, falling as N^-0.75),
 * about 4e-4 at 256^2, so 0.2 % is five sigma. The solver's stated errors
 * for it are tested in tests/solver/direct/test_near_field.c. */
static void test_lambertian_disk(void)
{
    cdl_photometry *ph = make_ies("2002", -0.6, -0.6, 0.0, lambert, 1, 1.0);
    cdl_photometry *el = make_ies("1995", -0.6, 0.6, 0.0, lambert, 1, 1.0);
    if (!ph || !el) return;
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_CIRCLE);
    CHECK(cdl_photometry_get_metadata(el)->opening.shape == CDL_LUMINOUS_SHAPE_ELLIPSE);
    cdl_vec3 c = cdl_vec3_make(0, 0, 0), up = cdl_vec3_make(0, 0, 1);
    cdl_emitter *e = make_opening(ph, c, 0, 0, 0), *s = make_opening(el, c, 0, 0, 0);
    if (!e || !s) return;
    CHECK(cdl_emitter_has_exact_illuminance(e) && cdl_emitter_opening_is_lambertian(e));
    CHECK(cdl_emitter_has_exact_illuminance(s) && !cdl_emitter_opening_is_lambertian(s));
    double L = I0 / (CDL_PI * 0.09);
    const double lateral[] = {0.0, 0.1, 0.29, 0.31, 0.8, 2.5};
    int converged = 0;
    for (size_t d = 0; d < sizeof depths / sizeof *depths; ++d)
        for (size_t a = 0; a < sizeof lateral / sizeof *lateral; ++a) {
            cdl_vec3 p = cdl_vec3_make(lateral[a] * 0.6, lateral[a] * 0.8, -depths[d]);
            double want = disk_E(L, 0.3, depths[d], lateral[a]);
            cdl_illuminance E;
            CHECK(cdl_emitter_exact_illuminance(e, p, up, &E, NULL) == CDL_OK);
            CHECK_REL(E.lx, want, 1e-9);
            /* the cubature integrates the table as interpolated, linear in
             * gamma between 1-degree samples: up to (1 degree)^2 / 8 =
             * 3.8e-5 below the cosine, plus its own 1e-5 */
            if (cdl_emitter_exact_illuminance(s, p, up, &E, NULL) == CDL_OK) {
                CHECK_REL(E.lx, want, 5e-5);
                converged++;
            } else {
                /* within centimetres the table's kinks (a circle of them
                 * per degree of gamma) need more than its 4096 cells: it
                 * declines, and the solver samples */
                CHECK_MSG(depths[d] < 0.1, "cubature declined at depth %g, offset %g", depths[d], lateral[a]);
            }
            CHECK_REL(sampled_E(s, p, up, 256), want, 2e-3);
        }
    printf("cubature of the disk as an ellipse: converged at %d of %zu probes\n", converged,
           sizeof depths / sizeof *depths * sizeof lateral / sizeof *lateral);
    CHECK(converged >= 36);
    cdl_emitter_release(e);
    cdl_emitter_release(s);
    cdl_photometry_release(ph);
    cdl_photometry_release(el);
}

/* Far away the opening is a point: on the axis of a disk of radius r the
 * ratio of the extended to the point model is exactly d^2 / (d^2 + r^2)
 * (the closed form above over I0 / d^2), 0.25 % short at ten diameters and
 * 1e-4 at fifty: the models converge as (size / d)^2, not faster. Off axis
 * and for a rectangle the same order holds: |E_ext / E_point - 1| <=
 * (largest dimension / d)^2 / 2 at every probe from 10 sizes out, and
 * below 1e-4 from 100 sizes. The flux is the point's exactly. */
static void test_far_field(void)
{
    cdl_photometry *disk = make_ies("2002", -0.6, -0.6, 0.0, lambert, 1, 1.0);
    cdl_photometry *rect = make_ies("2002", 0.3, 1.2, 0.0, asymmetric, 25, 1.0);
    if (!disk || !rect) return;
    cdl_vec3 c = cdl_vec3_make(0, 0, 0), up = cdl_vec3_make(0, 0, 1);
    cdl_emitter *e = make_opening(disk, c, 0, 0, 0), *pt = make_point(disk, c);
    const double ratios[] = {10, 20, 50, 100};
    for (size_t k = 0; k < 4; ++k) {
        double d = ratios[k] * 0.6;
        cdl_vec3 p = cdl_vec3_make(0, 0, -d);
        cdl_illuminance E;
        cdl_delta_light dl;
        CHECK(cdl_emitter_exact_illuminance(e, p, up, &E, NULL) == CDL_OK);
        CHECK(cdl_emitter_eval_delta(pt, p, up, &dl));
        CHECK_REL(E.lx / dl.E.lx, d * d / (d * d + 0.09), 1e-9);
    }
    CHECK_REL(cdl_emitter_flux(e).lm, cdl_emitter_flux(pt).lm, 1e-15);
    cdl_emitter_release(e);
    cdl_emitter_release(pt);

    e = make_opening(rect, c, 0, 0, 0);
    pt = make_point(rect, c);
    double size = cdl_luminous_opening_largest_m(&cdl_photometry_get_metadata(rect)->opening);
    CHECK_REL(size, sqrt(1.44 + 0.09), 1e-12);
    CHECK_REL(cdl_emitter_flux(e).lm, cdl_emitter_flux(pt).lm, 1e-15);
    for (size_t k = 0; k < 4; ++k) {
        double d = ratios[k] * size;
        for (int dir = 0; dir < 4; ++dir) {
            /* straight down, and 30 degrees off towards +x, -x and +y */
            double s = dir == 0 ? 0.0 : 0.5, ch = sqrt(1.0 - s * s);
            cdl_vec3 w = cdl_vec3_make(dir == 1 ? s : dir == 2 ? -s : 0.0, dir == 3 ? s : 0.0, -ch);
            cdl_vec3 p = cdl_vec3_scale(w, d), n = cdl_vec3_neg(w);
            cdl_delta_light dl;
            CHECK(cdl_emitter_eval_delta(pt, p, n, &dl));
            double ext = sampled_E(e, p, n, 64);
            double bound = ratios[k] >= 100 ? 1e-4 : 0.5 / (ratios[k] * ratios[k]);
            CHECK_MSG(fabs(ext / dl.E.lx - 1.0) <= bound, "far field at %g sizes, direction %d: extended / point - 1 = %.3g > %.3g",
                      ratios[k], dir, ext / dl.E.lx - 1.0, bound);
        }
    }
    cdl_emitter_release(e);
    cdl_emitter_release(pt);
    cdl_photometry_release(disk);
    cdl_photometry_release(rect);
}

/* Flux: the illuminance integrated over a sphere of radius 1 m around a
 * 1.2 m opening (which pokes through nowhere: the sphere encloses it) is
 * the luminaire's flux. Midpoint quadrature in (cos theta, phi) over 400 x
 * 400 cells of the sampled estimate: converged to 0.2 % (halving the grid
 * moved it by 0.03 %). */
static void test_flux_through_sphere(void)
{
    cdl_photometry *ph = make_ies("2002", 0.3, 1.2, 0.0, asymmetric, 25, 1.0);
    if (!ph) return;
    cdl_vec3 c = cdl_vec3_make(0, 0, 0);
    cdl_emitter *e = make_opening(ph, c, 0, 0, 0);
    if (!e) return;
    int m = 200;
    double R = 1.0, sum = 0.0;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            double z = -1.0 + 2.0 * (j + 0.5) / m, phi = CDL_TWO_PI * (i + 0.5) / m, s = sqrt(1.0 - z * z);
            cdl_vec3 w = cdl_vec3_make(s * cos(phi), s * sin(phi), z);
            sum += sampled_E_seeded(e, cdl_vec3_scale(w, R), cdl_vec3_neg(w), 6, (uint64_t)(j * m + i));
        }
    double flux = sum * 4.0 * CDL_PI * R * R / ((double)m * m);
    CHECK_REL(flux, cdl_emitter_flux(e).lm, 2e-3);
    printf("flux through a 1 m sphere: %.6g lm, the luminaire's %.6g lm\n", flux, cdl_emitter_flux(e).lm);
    cdl_emitter_release(e);
    cdl_photometry_release(ph);
}

/* Columns of Rz Ry Rx (degrees), for turning probes the way DESIGN.md
 * turns luminaires. */
static cdl_vec3 turn(const double r[3], cdl_vec3 v)
{
    double a = r[0] * CDL_DEG_TO_RAD, b = r[1] * CDL_DEG_TO_RAD, g = r[2] * CDL_DEG_TO_RAD;
    cdl_vec3 x = cdl_vec3_make(v.x, cos(a) * v.y - sin(a) * v.z, sin(a) * v.y + cos(a) * v.z);
    cdl_vec3 y = cdl_vec3_make(cos(b) * x.x + sin(b) * x.z, x.y, -sin(b) * x.x + cos(b) * x.z);
    return cdl_vec3_make(cos(g) * y.x - sin(g) * y.y, sin(g) * y.x + cos(g) * y.y, y.z);
}

/* E at p (normal n) from the unturned asymmetric table on the 1.2 x 0.3 m
 * rectangle at the origin, by the model's definition: the mean over the
 * opening of I(w) cos / r^2, midpoint rule on 600 x 150 cells (converged
 * to 1e-4 at these probes, 0.25 m and more from the opening), with I from
 * the table's own interpolation. */
static double asymmetric_reference(const cdl_photometry *ph, cdl_vec3 p, cdl_vec3 n)
{
    int nx = 600, ny = 150;
    double sum = 0.0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            cdl_vec3 x = cdl_vec3_make(-0.6 + 1.2 * (i + 0.5) / nx, -0.15 + 0.3 * (j + 0.5) / ny, 0.0);
            cdl_vec3 w = cdl_vec3_sub(p, x);
            double r2 = cdl_vec3_dot(w, w), r = sqrt(r2), c = -cdl_vec3_dot(n, w) / r;
            if (c > 0.0) sum += cdl_photometry_intensity(ph, w).cd * c / r2;
        }
    return sum / ((double)nx * ny);
}

/* Orientation: the asymmetric table on the long opening, turned by a
 * rotation and moved, lights the turned probes as the unturned opening
 * lights the probes (the reference integral above): the opening turns with
 * the distribution. Sampled to 0.1 % (256^2 strata, spread below 0.02 %);
 * the adaptive cubature (converged to 1e-5) within 1e-4, the midpoint
 * reference's own error (it moved by 3e-5 when its cells were halved). */
static void test_rotation(void)
{
    cdl_photometry *ph = make_ies("2002", 0.3, 1.2, 0.0, asymmetric, 25, 5.0);
    if (!ph) return;
    const double rot[3][3] = {{0, 0, 90}, {0, -30, 40}, {20, 10, -120}};
    cdl_vec3 at = cdl_vec3_make(1.5, -2.0, 2.8);
    const double probes[4][6] = {{0.9, 0.1, -0.3, 0, 0, 1},
                                 {-0.5, 0.4, -0.6, 0.3, -0.2, 0.93273790530888145},
                                 {0.0, -0.8, -0.25, 0, 1, 0},
                                 {1.6, 0.0, -1.0, -0.6, 0, 0.8}};
    for (int r = 0; r < 3; ++r) {
        cdl_emitter *e = make_opening(ph, at, rot[r][0], rot[r][1], rot[r][2]);
        if (!e) continue;
        for (int k = 0; k < 4; ++k) {
            cdl_vec3 p = cdl_vec3_make(probes[k][0], probes[k][1], probes[k][2]);
            cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(probes[k][3], probes[k][4], probes[k][5]));
            double want = asymmetric_reference(ph, p, n);
            cdl_vec3 pw = cdl_vec3_add(at, turn(rot[r], p)), nw = turn(rot[r], n);
            CHECK_REL(sampled_E(e, pw, nw, 256), want, 1e-3);
            cdl_illuminance E;
            CHECK(cdl_emitter_exact_illuminance(e, pw, nw, &E, NULL) == CDL_OK);
            CHECK_REL(E.lx, want, 1e-4);
        }
        cdl_emitter_release(e);
    }
    cdl_photometry_release(ph);
}

/* Luminance of the opening: I / projected area, the same from every part
 * of a flat opening; zero edge-on and for a point. */
static void test_luminance(void)
{
    cdl_photometry *ph = make_ies("2002", 0.3, 1.2, 0.0, lambert, 1, 1.0);
    if (!ph) return;
    cdl_luminance avg, max;
    cdl_photometry_opening_luminance(ph, 0.0, 0.0, &avg, &max);
    CHECK_REL(avg.cd_m2, I0 / 0.36, 1e-12);
    CHECK_REL(max.cd_m2, avg.cd_m2, 1e-15);
    /* Lambertian: the same luminance at any gamma below 90 */
    cdl_photometry_opening_luminance(ph, 30.0, 65.0, &avg, &max);
    CHECK_REL(avg.cd_m2, I0 / 0.36, 1e-3);
    cdl_photometry_opening_luminance(ph, 0.0, 90.0, &avg, &max);
    CHECK(avg.cd_m2 == 0.0);
    /* a box seen from (C 90, gamma 60): W L cos 60 + L H sin 60 */
    cdl_luminous_opening box = {CDL_LUMINOUS_SHAPE_BOX, 0.3, 1.2, 0.1, {0, 0, 0}, 2, {0, 0, 0, 0}};
    cdl_vec3 dir = cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, 90.0, 60.0);
    CHECK_REL(cdl_luminous_opening_projected_area(&box, dir), 0.36 * 0.5 + 0.12 * sqrt(0.75), 1e-12);
    cdl_luminous_opening sphere = {CDL_LUMINOUS_SHAPE_SPHERE, 0.2, 0.2, 0.2, {0, 0, 0}, 2, {0, 0, 0, 0}};
    CHECK_REL(cdl_luminous_opening_projected_area(&sphere, dir), CDL_PI * 0.01, 1e-12);
    cdl_photometry_release(ph);
}

/* A file without a flat opening cannot be spread: a clear error. */
static void test_refused(void)
{
    cdl_photometry *ph = make_ies("2002", 0.0, 0.0, 0.0, lambert, 1, 1.0);
    if (!ph) return;
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.photometry = ph;
    cdl_emitter *e = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_emitter_create_goniometric_opening(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK(e == NULL);
    CHECK(strstr(err.message, "opening") != NULL);
    cdl_photometry_release(ph);
}


/* ---- a partly visible opening ----------------------------------------------- */

/* The part of a polygon's square [x0, x1] x [y0, y1] at height z, in world
 * coordinates, as the four corners the partial illuminance takes. */
static void square_corners(double x0, double x1, double y0, double y1, double z, cdl_vec3 *c)
{
    c[0] = cdl_vec3_make(x0, y0, z);
    c[1] = cdl_vec3_make(x1, y0, z);
    c[2] = cdl_vec3_make(x1, y1, z);
    c[3] = cdl_vec3_make(x0, y1, z);
}

/* A partly visible circle and ellipse (cdl_emitter_opening_partial_
 * illuminance, what the solver's exact route hands the part of an opening
 * a point sees): the part x <= cut of a Lambertian circle (radius 0.3 m)
 * and of an ellipse (0.4 x 0.2 m semi-axes) 2 m above probes on and off
 * the axis, against the segment's integral above: within the cubature's
 * 1e-5 (plus, for the ellipse, whose table the cubature interpolates, the
 * linear interpolation's (1 deg)^2 / 8 = 3.8e-5 below the cosine). The
 * whole bounding square gives the unoccluded value; two triangles that
 * split it (each cut by the circle into arcs and edges) sum to it; a
 * square inside the circle is the Lambertian polygon's closed form; a
 * square outside it gives nothing. */
static void test_partial(void)
{
    for (int shape = 0; shape < 2; ++shape) {
        double ra = shape ? 0.4 : 0.3, rb = shape ? 0.2 : 0.3, tol = shape ? 6e-5 : 1.5e-5;
        /* the circle with the 2002 code, the ellipse with the 1995 one */
        cdl_photometry *ph = shape ? make_ies("1995", -2.0 * rb, 2.0 * ra, 0.0, lambert, 1, 1.0)
                                   : make_ies("2002", -0.6, -0.6, 0.0, lambert, 1, 1.0);
        if (!ph) return;
        cdl_emitter *e = make_opening(ph, cdl_vec3_make(0, 0, 2), 0, 0, 0);
        if (!e) return;
        double L = I0 / (CDL_PI * ra * rb);
        const double probes[4][2] = {{0, 0}, {0.35, 0.1}, {-0.6, 0.3}, {1.5, -0.8}};
        const double cuts[4] = {-0.25, 0.0, 0.15, 0.3};
        cdl_vec3 n = cdl_vec3_make(0, 0, 1);
        cdl_error err;
        for (int k = 0; k < 4; ++k) {
            cdl_vec3 p = cdl_vec3_make(probes[k][0], probes[k][1], 0.0);
            cdl_vec3 c[8];
            int counts[2] = {4, 4};
            cdl_illuminance E, E2;
            for (int j = 0; j < 4; ++j) {
                double cut = cuts[j] * ra / 0.3;
                square_corners(-ra, cut, -rb, rb, 2.0, c);
                CHECK_OK(cdl_emitter_opening_partial_illuminance(e, p, n, c, counts, 1, &E, &err), &err);
                CHECK_REL(E.lx, ellipse_segment_E(L, ra, rb, 2.0, p.x, p.y, cut), tol);
            }
            /* the whole square, and the same as two parts in one call */
            double whole = ellipse_segment_E(L, ra, rb, 2.0, p.x, p.y, ra);
            square_corners(-ra, ra, -rb, rb, 2.0, c);
            CHECK_OK(cdl_emitter_opening_partial_illuminance(e, p, n, c, counts, 1, &E, &err), &err);
            CHECK_REL(E.lx, whole, tol);
            cdl_vec3 tri[6] = {c[0], c[1], c[2], c[0], c[2], c[3]};
            int three[2] = {3, 3};
            CHECK_OK(cdl_emitter_opening_partial_illuminance(e, p, n, tri, three, 2, &E2, &err), &err);
            CHECK_REL(E2.lx, whole, tol);
            /* inside: a square of the Lambertian polygon's closed form */
            square_corners(-0.1 * ra, 0.1 * ra, -0.2 * rb, 0.3 * rb, 2.0, c);
            CHECK_OK(cdl_emitter_opening_partial_illuminance(e, p, n, c, counts, 1, &E, &err), &err);
            if (shape == 0) CHECK_REL(E.lx, polygon_E(c, 4, L, p, n), 1e-5);
            else CHECK_REL(E.lx, polygon_E(c, 4, L, p, n), 6e-5);
            /* outside the ellipse, inside its bounding square: nothing */
            square_corners(0.9 * ra, ra, 0.9 * rb, rb, 2.0, c);
            CHECK_OK(cdl_emitter_opening_partial_illuminance(e, p, n, c, counts, 1, &E, &err), &err);
            CHECK(E.lx == 0.0);
        }
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
}

/* I = I0 |sin(gamma) cos(C)|: Lambertian about the C0 axis on both sides */
static double lambert_c0(double C, double g)
{
    return I0 * fabs(sin(g * CDL_DEG_TO_RAD) * cos(C * CDL_DEG_TO_RAD));
}

/* LM-63-2019's vertical circle facing the photometric horizontal (W = H =
 * -0.4, L = 0: a disk of radius 0.2 m in the luminaire's y-z plane),
 * spread with a table Lambertian about the C0 axis on both sides: each
 * face a Lambertian disk of luminance I0 / A. Probes in front of either
 * face, normal towards the disk, against the configuration factor of a
 * parallel disk (disk_E); within the table's bilinear interpolation of
 * |sin(gamma) cos(C)| at 1-degree steps, (1 deg)^2 / 8 = 3.8e-5 in each
 * angle, twice that with the cubature's 1e-5. Far away (20 m) the point
 * model's I0 / d^2 within the d^2 / (d^2 + R^2) the disk differs by. */
static void test_vertical_circle(void)
{
    cdl_photometry *ph = make_ies_planes("2002", -0.4, 0.0, -0.4, lambert_c0, 0, 1.0, 1.0);
    if (!ph) return;
    CHECK(cdl_photometry_get_metadata(ph)->opening.shape == CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE);
    cdl_vec3 at = cdl_vec3_make(1, 2, 3);
    cdl_emitter *e = make_opening(ph, at, 0, 0, 0);
    if (!e) return;
    double R = 0.2, L = I0 / (CDL_PI * R * R);
    const double probes[5][3] = {{0.3, 0, 0}, {1.0, 0.1, -0.05}, {-0.5, 0, 0.15}, {-2.0, 0.3, 0}, {0.05, 0, 0}};
    for (int k = 0; k < 5; ++k) {
        double d = fabs(probes[k][0]), a = hypot(probes[k][1], probes[k][2]);
        cdl_vec3 p = cdl_vec3_add(at, cdl_vec3_make(probes[k][0], probes[k][1], probes[k][2]));
        cdl_vec3 n = cdl_vec3_make(probes[k][0] > 0 ? -1.0 : 1.0, 0, 0);
        cdl_illuminance E;
        CHECK(cdl_emitter_exact_illuminance(e, p, n, &E, NULL) == CDL_OK);
        CHECK_REL(E.lx, disk_E(L, R, d, a), 1e-4);
        CHECK_REL(sampled_E(e, p, n, 256), disk_E(L, R, d, a), 2e-3);
    }
    /* far away on the axis: I0 / (d^2 + R^2), the point model's I0 / d^2 times d^2 / (d^2 + R^2) */
    cdl_vec3 far = cdl_vec3_add(at, cdl_vec3_make(20.0, 0, 0)), n = cdl_vec3_make(-1, 0, 0);
    cdl_illuminance E;
    CHECK(cdl_emitter_exact_illuminance(e, far, n, &E, NULL) == CDL_OK);
    CHECK_REL(E.lx, I0 / (400.0 + R * R), 1e-4);
    cdl_photometry_release(ph);
    cdl_emitter_release(e);
}

int main(void)
{
    test_lambertian_rectangle();
    test_lambertian_disk();
    test_far_field();
    test_flux_through_sphere();
    test_rotation();
    test_luminance();
    test_refused();
    test_partial();
    test_vertical_circle();
    return check_finish();
}
