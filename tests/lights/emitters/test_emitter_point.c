/* Point emitter: the inverse-square and cosine law at every scale, its
 * flux three ways, and its refusal of bad parameters. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"

static cdl_emitter *make_point(cdl_vec3 pos, double cd)
{
    cdl_point_params p = {pos, cdl_candelas(cd)};
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_point(&p, &e, &err), &err);
    return e;
}

/* E = I cos / d^2 evaluated in long double from the same double inputs. */
static double reference_E(double I, cdl_vec3 light, cdl_vec3 p, cdl_vec3 n)
{
    long double dx = (long double)light.x - p.x, dy = (long double)light.y - p.y, dz = (long double)light.z - p.z;
    long double d2 = dx * dx + dy * dy + dz * dz, d = sqrtl(d2);
    long double c = (n.x * dx + n.y * dy + n.z * dz) / d;
    return c > 0 ? (double)(I * c / d2) : 0.0;
}

static void test_inverse_square_and_cosine_law(void)
{
    /* Distances 1e-4 .. 1e5 m, intensities 1e-6 .. 1e9 cd, angles of
     * incidence 0 .. 89.9 degrees, at an arbitrary (non-origin) receiver.
     * The problem's own condition number is ~1/cos(theta) (cos from a dot
     * product of a rounded direction): 573 at 89.9 degrees, so the
     * tolerance is 8 ulp x 1/cos, i.e. "no loss of relative precision"
     * beyond what the inputs themselves carry. */
    double ds[] = {1e-4, 3.3e-3, 0.25, 1.0, 7.7, 420.0, 1e5};
    double Is[] = {1e-6, 1e-3, 1.0, 1234.5, 1e9};
    double angles[] = {0.0, 15.0, 45.0, 60.0, 80.0, 89.0, 89.9};
    /* p.z = 0 so that light = p + (0, 0, d) is exact and d is the true distance. */
    cdl_vec3 p = {1.25, -2.5, 0.0};
    int count = 0;
    for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a)
        for (size_t i = 0; i < sizeof ds / sizeof ds[0]; ++i)
            for (size_t k = 0; k < sizeof Is / sizeof Is[0]; ++k) {
                double th = angles[a] * CDL_DEG_TO_RAD, d = ds[i];
                /* Light straight above p; receiver tilted by theta about a skew axis. */
                cdl_vec3 light = cdl_vec3_add(p, cdl_vec3_make(0.0, 0.0, d));
                cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(sin(th) * 0.6, sin(th) * 0.8, cos(th)));
                cdl_emitter *e = make_point(light, Is[k]);
                cdl_delta_light dl;
                CHECK(cdl_emitter_eval_delta(e, p, n, &dl) == 1);
                double tol = 8.0 * DBL_EPSILON / cos(th);
                CHECK_REL(dl.E.lx, reference_E(Is[k], light, p, n), tol);
                /* ... and against the textbook formula with exact cos(theta). */
                CHECK_REL(dl.E.lx, Is[k] * cos(th) / (d * d), tol + 1e-15 / cos(th));
                CHECK_REL(dl.distance, d, 4 * DBL_EPSILON * (1.0 + cdl_vec3_length(p) / d));
                CHECK_ABS(dl.to_light.z, 1.0, 1e-15);
                /* exact_illuminance of a delta emitter is the same number. */
                cdl_illuminance Ex;
                CHECK_OK(cdl_emitter_exact_illuminance(e, p, n, &Ex, NULL), &(cdl_error){0});
                CHECK(Ex.lx == dl.E.lx);
                cdl_emitter_release(e);
                ++count;
            }
    CHECK(count == 7 * 7 * 5);
    /* Light along an oblique line from an off-origin receiver: the
     * difference light - p is rounded, so the long double reference is the
     * fair one (same double inputs). */
    cdl_vec3 dir = cdl_vec3_normalize(cdl_vec3_make(0.3, -0.7, 0.5));
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; ++i) {
        cdl_vec3 light = cdl_vec3_madd(p, ds[i], dir);
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.1, 0.2, 1.0));
        cdl_emitter *e = make_point(light, 500.0);
        cdl_delta_light dl;
        cdl_emitter_eval_delta(e, p, n, &dl);
        CHECK_REL(dl.E.lx, reference_E(500.0, light, p, n), 16 * DBL_EPSILON);
        cdl_emitter_release(e);
    }
}

static void test_behind_and_degenerate(void)
{
    cdl_emitter *e = make_point(cdl_vec3_make(0, 0, 1), 100.0);
    cdl_delta_light dl;
    /* Light behind the receiving plane, in the plane, and at the receiver. */
    CHECK(cdl_emitter_eval_delta(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), &dl) == 0);
    CHECK(dl.E.lx == 0.0);
    CHECK(cdl_emitter_eval_delta(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(1, 0, 0), &dl) == 0);
    CHECK(cdl_emitter_eval_delta(e, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), &dl) == 0);
    CHECK(dl.E.lx == 0.0 && isfinite(dl.to_light.x));
    /* A delta emitter has no samples and no radiance. */
    cdl_light_sample s;
    CHECK(cdl_emitter_sample(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), 0.5, 0.5, &s) == 0);
    double pdf = 1.0;
    CHECK(cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), &pdf).cd_m2 ==
          0.0);
    CHECK(pdf == 0.0);
    CHECK(cdl_emitter_is_delta(e));
    CHECK(cdl_emitter_get_kind(e) == CDL_EMITTER_POINT);
    CHECK(cdl_emitter_has_exact_illuminance(e));
    cdl_emitter_release(e);
}

/* Flux through a sphere of radius r around the light from eval_delta at
 * points on it with inward normals: int E dA = Phi (every ray crosses it once). */
static void test_flux_three_ways(void)
{
    double I = 321.0;
    cdl_vec3 c = {0.4, -1.0, 2.0};
    cdl_emitter *e = make_point(c, I);
    double Phi = cdl_emitter_flux(e).lm;
    /* 1. Closed form 4 pi I. */
    CHECK_REL(Phi, CDL_FOUR_PI * I, 1e-15);
    /* 2. Quadrature of I(w) over the sphere: the integrand is constant, so
     * the equal-area midpoint rule is exact up to summation rounding. */
    CHECK_REL(sphere_quadrature(intensity_of, e, 200), Phi, 1e-12);
    /* 3. Monte Carlo: uniform points on a sphere of radius 3 m around the
     * light, E from eval_delta with inward normals, times 4 pi r^2. E is the
     * same everywhere on it, so the estimate has zero variance: it tests the
     * inverse-square law's normalisation against the flux exactly. */
    double mean, se;
    delta_flux_on_sphere(e, c, 3.0, 4096, 5, &mean, &se);
    CHECK_REL(mean, Phi, 1e-12);
    CHECK(se < 1e-12 * Phi);
    cdl_emitter_release(e);
}

static void test_bad_parameters(void)
{
    cdl_emitter *e = (cdl_emitter *)1;
    cdl_error err;
    cdl_point_params p = {{0, 0, 0}, cdl_candelas(-1.0)};
    CHECK(cdl_emitter_create_point(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK(e == NULL);
    CHECK_MSG(strstr(err.message, "intensity") && strstr(err.message, "-1"), "%s", err.message);
    p.intensity = cdl_candelas(NAN);
    CHECK(cdl_emitter_create_point(&p, &e, &err) == CDL_ERR_INPUT);
    p.intensity = cdl_candelas(1.0);
    p.position.y = INFINITY;
    CHECK(cdl_emitter_create_point(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "position"), "%s", err.message);
    cdl_emitter_release(NULL);
}

int main(void)
{
    test_inverse_square_and_cosine_law();
    test_behind_and_degenerate();
    test_flux_three_ways();
    test_bad_parameters();
    return check_finish();
}
