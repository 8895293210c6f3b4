/* Directional emitter: E = E_n cos(theta) on any plane; its "flux" (E_n
 * through 1 m^2 of beam section) three ways. With a disk (the sun, 0.533
 * degrees): E_n cos(theta) while the whole disk is above the plane; where
 * the plane cuts it, against a quadrature of L cos over the part above
 * written here (in the disk's own polar coordinates, fine enough for 1e-10
 * of E_n); its samples' mean L cos / pdf is that E; radiance and pdf agree
 * with the samples; a diameter out of range is refused. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"

static cdl_emitter *make_sun(cdl_vec3 dir, double E)
{
    cdl_directional_params p = {dir, cdl_lux(E), 0.0};
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_directional(&p, &e, &err), &err);
    return e;
}

static void test_cosine_law(void)
{
    cdl_vec3 travel = {0.3, 0.2, -1.0};
    cdl_emitter *e = make_sun(travel, 80000.0);
    cdl_vec3 to_sun = cdl_vec3_normalize(cdl_vec3_neg(travel));
    /* Planes at 0 .. 89.9 degrees from the beam, around a skew axis, at
     * points far apart (the beam is the same everywhere). */
    double angles[] = {0.0, 30.0, 60.0, 89.9, 90.0, 120.0};
    cdl_frame f = cdl_frame_from_normal(to_sun);
    for (size_t k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
        double t = angles[k] * CDL_DEG_TO_RAD;
        cdl_vec3 n = cdl_frame_to_world(&f, cdl_vec3_make(sin(t) * 0.6, sin(t) * 0.8, cos(t)));
        cdl_delta_light dl;
        int lit = cdl_emitter_eval_delta(e, cdl_vec3_make(1e4 * k, -3.0, 2.0), n, &dl);
        double want = cos(t) > 0.0 ? 80000.0 * cos(t) : 0.0;
        /* n is built from rounded components: ~2 ulp on cos, relative 2e-16/cos. */
        CHECK_ABS(dl.E.lx, want, 80000.0 * 4e-16);
        CHECK(lit == (dl.E.lx > 0.0));
        if (angles[k] > 90.0) CHECK(dl.E.lx == 0.0);
        CHECK(isinf(dl.distance));
        CHECK_ABS(cdl_vec3_dot(dl.to_light, to_sun), 1.0, 1e-15);
    }
    CHECK(cdl_emitter_is_delta(e));
    CHECK(cdl_emitter_intensity(e, to_sun).cd == 0.0);
    cdl_emitter_release(e);
}

/* Flux through a sphere's cross-section: int over the sphere of E(n) dA with
 * outward normals n = pi r^2 E_n (the sphere intercepts the beam section
 * pi r^2); a unit-area section therefore receives Phi = E_n. */
typedef struct sun_ctx { cdl_emitter *e; } sun_ctx;
static double sphere_E(void *ctx, cdl_vec3 w)
{
    cdl_delta_light dl;
    cdl_emitter_eval_delta(((sun_ctx *)ctx)->e, cdl_vec3_scale(w, 2.0), w, &dl);
    return dl.E.lx;
}

static void test_flux_three_ways(void)
{
    cdl_emitter *e = make_sun(cdl_vec3_make(-1, 2, -3), 1000.0);
    double Phi = cdl_emitter_flux(e).lm;
    /* 1. Closed form: E_n x 1 m^2. */
    CHECK_REL(Phi, 1000.0, 1e-15);
    /* 2. Quadrature of E over the unit sphere's surface (in the tilted
     * frame, so the terminator crosses cells: midpoint rule O(h^2) error at
     * the kink, ~1e-6 with 1000 x 2000 cells), divided by the intercepted
     * section pi x 1^2. */
    sun_ctx c = {e};
    CHECK_REL(sphere_quadrature(sphere_E, &c, 1000) / CDL_PI, Phi, 2e-6);
    /* 3. Monte Carlo: uniform points on the unit sphere, pdf 1/(4 pi):
     * mean E x 4 pi / pi; 65536 samples, 5 standard errors. */
    cdl_rng_key key = {3, 1};
    double sum = 0, sum2 = 0;
    int N = 65536;
    for (int i = 0; i < N; ++i) {
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)i, u);
        double z = 1 - 2 * u[0], s = sqrt(1 - z * z), ph = CDL_TWO_PI * u[1];
        double v = sphere_E(&c, cdl_vec3_make(s * cos(ph), s * sin(ph), z)) * 4.0;
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / N, se = sqrt((sum2 / N - mean * mean) / (N - 1));
    CHECK_MSG(fabs(mean - Phi) <= 5 * se, "MC %g vs %g (se %g)", mean, Phi, se);
    CHECK(se < 0.01 * Phi);
    cdl_emitter_release(e);
}

static void test_bad_parameters(void)
{
    cdl_emitter *e = NULL;
    cdl_error err;
    cdl_directional_params p = {{0, 0, 0}, cdl_lux(100.0), 0.0};
    CHECK(cdl_emitter_create_directional(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "direction"), "%s", err.message);
    p.direction = cdl_vec3_make(0, 0, -1);
    p.illuminance = cdl_lux(-5.0);
    CHECK(cdl_emitter_create_directional(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "illuminance"), "%s", err.message);
    CHECK(e == NULL);
}

/* E from the disk by brute force: L int over the cap of max(0, n.w) dw in
 * polar coordinates (t from the axis, psi about it), 2000 x 4000 midpoints
 * (the kink where n.w crosses 0 costs O(h^2) there: about 1e-9 E_n). */
static double disk_reference(cdl_vec3 to_sun, double alpha, double E_n, cdl_vec3 n)
{
    cdl_frame f = cdl_frame_from_normal(to_sun);
    double L = E_n / (CDL_PI * sin(alpha) * sin(alpha)), sum = 0.0;
    const int NT = 2000, NP = 4000;
    for (int i = 0; i < NT; ++i) {
        double t = alpha * (i + 0.5) / NT;
        for (int j = 0; j < NP; ++j) {
            double psi = CDL_TWO_PI * (j + 0.5) / NP;
            cdl_vec3 w = cdl_frame_to_world(&f, cdl_vec3_make(sin(t) * cos(psi), sin(t) * sin(psi), cos(t)));
            double c = cdl_vec3_dot(n, w);
            if (c > 0.0) sum += c * sin(t);
        }
    }
    return L * sum * (alpha / NT) * (CDL_TWO_PI / NP);
}

static void test_disk(void)
{
    cdl_vec3 travel = cdl_vec3_make(-0.2, 0.5, -0.7);
    cdl_directional_params p = {travel, cdl_lux(90000.0), 0.533};
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_directional(&p, &e, &err), &err);
    if (!e) return;
    CHECK(!cdl_emitter_is_delta(e) && cdl_emitter_has_exact_illuminance(e));
    cdl_vec3 to_sun = cdl_vec3_normalize(cdl_vec3_neg(travel)), axis;
    double alpha = 0.5 * 0.533 * CDL_DEG_TO_RAD, half;
    CHECK(cdl_emitter_directional_disk(e, &axis, &half) && cdl_vec3_dot(axis, to_sun) > 1.0 - 1e-15);
    CHECK_REL(half, alpha, 1e-15);
    cdl_frame f = cdl_frame_from_normal(to_sun);
    /* angles from the axis: whole disk above (0, 60, 89.7), cut (89.8 ..
     * 90.2 degrees), wholly below (90.3) */
    const double angles[] = {0.0, 60.0, 89.7, 89.8, 89.9, 90.0, 90.1, 90.2, 90.3};
    for (size_t k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
        double t = angles[k] * CDL_DEG_TO_RAD;
        cdl_vec3 n = cdl_frame_to_world(&f, cdl_vec3_make(sin(t) * 0.8, sin(t) * 0.6, cos(t)));
        cdl_illuminance E;
        CHECK_OK(cdl_emitter_exact_illuminance(e, cdl_vec3_make(3, 4, 5), n, &E, &err), &err);
        double want = t + alpha <= 0.5 * CDL_PI ? 90000.0 * cos(t) : disk_reference(to_sun, alpha, 90000.0, n);
        /* full view: E_n cos theta to rounding; cut: the brute force's 1e-9 E_n */
        CHECK_MSG(fabs(E.lx - want) <= 2e-9 * 90000.0, "%g deg: %.12g vs %.12g", angles[k], E.lx, want);
        if (angles[k] >= 90.3) CHECK(E.lx == 0.0);
        /* the plane through the axis: L x 2 (alpha / 2 - sin(2 alpha) / 4) = E_n 2 alpha / (3 pi) to O(alpha^2) */
        if (angles[k] == 90.0) CHECK_REL(E.lx, 90000.0 * 2.0 * alpha / (3.0 * CDL_PI), 1e-4);
        /* samples: stratified mean of L cos / pdf is E (to 1e-4 of E_n at 64 x 64) */
        double sum = 0.0;
        const int N = 64;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) {
                cdl_light_sample s;
                if (!cdl_emitter_sample(e, cdl_vec3_make(0, 0, 0), n, (i + 0.5) / N, (j + 0.5) / N, &s)) continue;
                double pdf;
                cdl_luminance L = cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), n, s.to_light, &pdf);
                CHECK_REL(L.cd_m2, s.L.cd_m2, 1e-12);
                CHECK_REL(pdf, s.pdf, 1e-12);
                sum += s.L.cd_m2 * cdl_vec3_dot(n, s.to_light) / s.pdf;
            }
        CHECK_MSG(fabs(sum / (N * N) - E.lx) <= 1e-4 * 90000.0, "%g deg: samples %.9g vs %.9g", angles[k],
                  sum / (N * N), E.lx);
    }
    /* outside the disk: no light */
    double pdf = 1.0;
    cdl_vec3 off = cdl_frame_to_world(&f, cdl_vec3_make(sin(2 * alpha), 0.0, cos(2 * alpha)));
    CHECK(cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), to_sun, off, &pdf).cd_m2 == 0.0 && pdf == 0.0);
    CHECK_REL(cdl_emitter_flux(e).lm, 90000.0, 1e-15);
    cdl_emitter_release(e);
    p.angular_diameter_deg = 12.0;
    CHECK(cdl_emitter_create_directional(&p, &e, &err) == CDL_ERR_INPUT && strstr(err.message, "angular_diameter"));
    p.angular_diameter_deg = -1.0;
    CHECK(cdl_emitter_create_directional(&p, &e, &err) == CDL_ERR_INPUT);
}

int main(void)
{
    test_cosine_law();
    test_disk();
    test_flux_three_ways();
    test_bad_parameters();
    return check_finish();
}
