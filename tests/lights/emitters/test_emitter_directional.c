/* Directional emitter: E = E_n cos(theta) on any plane; its "flux" (E_n
 * through 1 m^2 of beam section) three ways. */
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

int main(void)
{
    test_cosine_law();
    test_flux_three_ways();
    test_bad_parameters();
    return check_finish();
}
