/* Area emitters (rect, disk, sphere, triangles): exact illuminance against
 * configuration factors, flux three ways, and importance sampling that
 * reproduces both E and Phi.
 *
 * Configuration factors (Omega_p = pi F, E = L pi F) from Howell's catalogue
 * (3rd ed.): B-2 parallel rectangle over a corner, B-3 perpendicular
 * rectangle, disk on the axis r^2 / (r^2 + h^2), sphere fully above the
 * plane (R/d)^2 cos(beta). Evaluated in long double where they cancel. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"

static cdl_emitter *make_area(cdl_shape shape, double L)
{
    cdl_area_params p;
    memset(&p, 0, sizeof p);
    p.shape = shape;
    p.luminance = cdl_nits(L);
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_area(&p, &e, &err), &err);
    return e;
}

static cdl_shape rect_shape(cdl_vec3 o, cdl_vec3 u, cdl_vec3 v)
{
    cdl_shape s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_SHAPE_RECT;
    s.origin = o;
    s.u = u;
    s.v = v;
    return s;
}

static cdl_shape disk_shape(cdl_vec3 c, cdl_vec3 n, double r)
{
    cdl_shape s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_SHAPE_DISK;
    s.center = c;
    s.normal = n;
    s.radius = r;
    return s;
}

static cdl_shape sphere_shape(cdl_vec3 c, double r, int inward)
{
    cdl_shape s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_SHAPE_SPHERE;
    s.center = c;
    s.radius = r;
    s.inward = inward;
    return s;
}

static cdl_shape triangles_shape(const double *v, size_t nv, const uint32_t *t, size_t nt)
{
    cdl_shape s;
    memset(&s, 0, sizeof s);
    s.kind = CDL_SHAPE_TRIANGLES;
    s.vertices = v;
    s.vertex_count = nv;
    s.triangles = t;
    s.triangle_count = nt;
    return s;
}

static double exact_E(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n)
{
    cdl_illuminance E;
    cdl_error err;
    CHECK_OK(cdl_emitter_exact_illuminance(e, p, n, &E, &err), &err);
    return E.lx;
}


/* ---- exact illuminance ------------------------------------------------------ */

static void test_rect_configuration_factors(void)
{
    double L = 2000.0;
    cdl_vec3 up = {0, 0, 1};
    /* A 1.3 x 0.7 m luminous ceiling panel facing down (u x v = -z) at
     * heights 1e-3 .. 1e4 m above a receiver under its corner, which is
     * placed away from the origin. */
    double hs[] = {1e-3, 0.05, 0.8, 2.2, 40.0, 1e4};
    cdl_vec3 p = {3.0, -1.0, 0.8};
    for (size_t k = 0; k < sizeof hs / sizeof hs[0]; ++k) {
        cdl_emitter *e = make_area(rect_shape(cdl_vec3_add(p, cdl_vec3_make(0, 0, hs[k])), cdl_vec3_make(0, 0.7, 0),
                                              cdl_vec3_make(1.3, 0, 0)),
                                   L);
        CHECK_REL(exact_E(e, p, up), L * CDL_PI * howell_parallel_corner(1.3, 0.7, hs[k]), 1e-12);
        /* From above it is dark (one-sided). */
        CHECK(exact_E(e, cdl_vec3_add(p, cdl_vec3_make(0, 0, hs[k] + 1.0)), cdl_vec3_make(0, 0, -1)) == 0.0);
        cdl_emitter_release(e);
    }
    /* A wall panel perpendicular to the receiver's plane (Howell B-3): the
     * panel x in [0, a], z in [0, c] in the plane y = b, facing -y. */
    double bs[] = {1e-3, 0.8, 3.0, 1e3};
    for (size_t k = 0; k < sizeof bs / sizeof bs[0]; ++k) {
        cdl_emitter *e = make_area(rect_shape(cdl_vec3_make(0, bs[k], 0), cdl_vec3_make(1.1, 0, 0), cdl_vec3_make(0, 0, 0.6)), L);
        CHECK_REL(exact_E(e, cdl_vec3_make(0, 0, 0), up), L * CDL_PI * howell_perpendicular_corner(1.1, bs[k], 0.6), 1e-12);
        cdl_emitter_release(e);
    }
    /* A 1 m^2 panel: right under it at 1e-3 m the whole hemisphere is
     * nearly all emitter, E -> pi L (1 - O(h)); at 1e4 m it is a point
     * source of I = L A: E -> L A cos / d^2 with an O((size/d)^2) = 1e-8
     * relative difference. */
    cdl_emitter *e = make_area(rect_shape(cdl_vec3_make(-0.5, -0.5, 1e-3), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0)), L);
    double En = exact_E(e, cdl_vec3_make(0, 0, 0), up);
    CHECK(En < CDL_PI * L && En > CDL_PI * L * (1 - 3e-3));
    CHECK_REL(En, 4 * L * CDL_PI * howell_parallel_corner(0.5, 0.5, 1e-3), 1e-12);
    cdl_emitter_release(e);
    e = make_area(rect_shape(cdl_vec3_make(-0.5, -0.5, 1e4), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0)), L);
    CHECK_REL(exact_E(e, cdl_vec3_make(0, 0, 0), up), L * 1.0 / 1e8, 1e-7);
    /* ... also off-axis and tilted at 1e4 m: I(w) cos / d^2 with I from the emitter itself. */
    cdl_vec3 q = {3e3, -2e3, -9e3}, nq = cdl_vec3_normalize(cdl_vec3_make(0.2, 0.1, 1.0));
    cdl_vec3 w = cdl_vec3_sub(cdl_vec3_make(0, 0, 1e4), q);
    double d = cdl_vec3_length(w);
    w = cdl_vec3_scale(w, 1 / d);
    double far_field = cdl_emitter_intensity(e, cdl_vec3_neg(w)).cd * cdl_vec3_dot(nq, w) / (d * d);
    CHECK_REL(exact_E(e, q, nq), far_field, 1e-7);
    cdl_emitter_release(e);
}

static void test_disk_and_sphere(void)
{
    double L = 500.0;
    /* Disk on the axis: pi L r^2 / (r^2 + h^2) from 1e-4 m to 1e5 m. */
    double hs[] = {1e-4, 1e-2, 0.3, 1.0, 20.0, 1e3, 1e5};
    for (size_t k = 0; k < sizeof hs / sizeof hs[0]; ++k) {
        double r = 0.4, h = hs[k];
        cdl_emitter *e = make_area(disk_shape(cdl_vec3_make(1, 1, 3), cdl_vec3_make(0, 0, -5), r), L);
        CHECK_REL(exact_E(e, cdl_vec3_make(1, 1, 3 - h), cdl_vec3_make(0, 0, 1)), CDL_PI * L * r * r / (r * r + h * h), 1e-13);
        cdl_emitter_release(e);
    }
    /* Sphere fully above the receiver's plane: pi L (R/d)^2 cos(beta). */
    cdl_emitter *s = make_area(sphere_shape(cdl_vec3_make(0, 0, 5), 0.5, 0), L);
    double betas[] = {0.0, 0.4, 1.2};
    for (size_t k = 0; k < 3; ++k) {
        cdl_vec3 n = {sin(betas[k]), 0, cos(betas[k])};
        CHECK_REL(exact_E(s, cdl_vec3_make(0, 0, 0), n), CDL_PI * L * 0.01 * cos(betas[k]), 1e-13);
    }
    /* Right at the surface looking at it: the hemisphere is all sphere. */
    CHECK_REL(exact_E(s, cdl_vec3_make(0, 0, 4.5 - 1e-9), cdl_vec3_make(0, 0, 1)), CDL_PI * L, 1e-8);
    CHECK(exact_E(s, cdl_vec3_make(0, 0, 5.2), cdl_vec3_make(0, 0, 1)) == 0.0); /* inside an outward sphere */
    cdl_emitter_release(s);
    /* Inward sphere: inside, every direction sees L: pi L for any normal; outside: dark. */
    s = make_area(sphere_shape(cdl_vec3_make(0, 0, 0), 3.0, 1), L);
    CHECK_REL(exact_E(s, cdl_vec3_make(1, -2, 0.5), cdl_vec3_normalize(cdl_vec3_make(1, 1, 1))), CDL_PI * L, 1e-15);
    CHECK(exact_E(s, cdl_vec3_make(0, 0, 4), cdl_vec3_make(0, 0, -1)) == 0.0);
    cdl_emitter_release(s);
}

/* Unit square [0,1]^2 at z = 2 facing down, as two triangles (counter-
 * clockwise seen from below). */
static const double square_v[] = {0, 0, 2, 0, 1, 2, 1, 1, 2, 1, 0, 2};
static const uint32_t square_t[] = {0, 1, 2, 0, 2, 3};
/* Regular octahedron of "radius" 1 about (0, 0, 5), outward (counter-clockwise seen from outside). */
static const double octa_v[] = {1, 0, 5, -1, 0, 5, 0, 1, 5, 0, -1, 5, 0, 0, 6, 0, 0, 4};
static const uint32_t octa_t[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

static void test_triangles(void)
{
    double L = 100.0;
    cdl_emitter *tri = make_area(triangles_shape(square_v, 4, square_t, 2), L);
    cdl_emitter *rect = make_area(rect_shape(cdl_vec3_make(0, 0, 2), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0)), L);
    /* The same surface as a rect and as a mesh: the shared diagonal's terms
     * cancel; the totals agree to rounding, wherever the receiver is
     * (including ones whose plane cuts the square). */
    cdl_vec3 ps[] = {{0.5, 0.5, 0}, {3, -2, 1.5}, {0.2, 0.9, 1.99}, {-40, 10, -30}};
    cdl_vec3 ns[] = {{0, 0, 1}, {-0.6, 0.5, 0.3}, {0.9, 0, 0.1}, {0.7, -0.1, 0.7}};
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 n = cdl_vec3_normalize(ns[k]);
        double a = exact_E(tri, ps[k], n), b = exact_E(rect, ps[k], n);
        CHECK(b > 0.0);
        CHECK_REL(a, b, 1e-12);
    }
    CHECK_REL(cdl_emitter_flux(tri).lm, CDL_PI * L * 1.0, 1e-15);
    cdl_emitter_release(tri);
    cdl_emitter_release(rect);

    /* Index and vertex errors. */
    cdl_area_params p;
    memset(&p, 0, sizeof p);
    p.luminance = cdl_nits(1.0);
    uint32_t bad_t[] = {0, 1, 7};
    p.shape = triangles_shape(square_v, 4, bad_t, 1);
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "triangle 0") && strstr(err.message, "7"), "%s", err.message);
    double nan_v[] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    uint32_t t0[] = {0, 1, 2};
    p.shape = triangles_shape(nan_v, 3, t0, 1);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "vertex 2"), "%s", err.message);
    double flat_v[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    p.shape = triangles_shape(flat_v, 3, t0, 1);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "area"), "%s", err.message);
    CHECK(e == NULL);
}

/* ---- flux three ways ------------------------------------------------------- */

/* Phi from the emitter's own sampling: receivers uniformly on a sphere of
 * radius r about c facing inward, one light sample each: the mean of
 * (L cos / pdf) x 4 pi r^2 estimates the flux crossing the sphere, i.e. all
 * of it (for an inward sphere, nothing leaves: this is not called). */
static void sampled_flux(const cdl_emitter *e, cdl_vec3 c, double r, int N, double *mean, double *se)
{
    cdl_rng_key key = {21, 4};
    double sum = 0, sum2 = 0;
    for (int i = 0; i < N; ++i) {
        uint32_t words[4];
        cdl_rng_words(key, (uint64_t)i, words);
        double u0 = words[0] * 0x1p-32, u1 = words[1] * 0x1p-32, u2 = words[2] * 0x1p-32, u3 = words[3] * 0x1p-32;
        double z = 1 - 2 * u0, s = sqrt(fmax(0, 1 - z * z)), ph = CDL_TWO_PI * u1;
        cdl_vec3 w = {s * cos(ph), s * sin(ph), z};
        cdl_vec3 p = cdl_vec3_madd(c, r, w), n = cdl_vec3_neg(w);
        cdl_light_sample ls;
        double v = 0;
        if (cdl_emitter_sample(e, p, n, u2, u3, &ls)) v = ls.L.cd_m2 * cdl_vec3_dot(n, ls.to_light) / ls.pdf * CDL_FOUR_PI * r * r;
        sum += v;
        sum2 += v * v;
    }
    *mean = sum / N;
    *se = sqrt(fmax(0, sum2 / N - *mean * *mean) / (N - 1));
}

static void test_flux_three_ways(void)
{
    double L = 250.0;
    struct { cdl_shape shape; double area; cdl_vec3 centre; } cases[4];
    cases[0].shape = rect_shape(cdl_vec3_make(-0.3, 0.1, 1.0), cdl_vec3_make(0.6, 0.2, 0.1), cdl_vec3_make(-0.1, 0.4, 0.3));
    cases[0].area = cdl_vec3_length(cdl_vec3_cross(cdl_vec3_make(0.6, 0.2, 0.1), cdl_vec3_make(-0.1, 0.4, 0.3)));
    cases[0].centre = cdl_vec3_make(-0.05, 0.4, 1.2);
    cases[1].shape = disk_shape(cdl_vec3_make(0.2, 0.0, -0.5), cdl_vec3_make(0.3, -0.4, 0.8), 0.45);
    cases[1].area = CDL_PI * 0.45 * 0.45;
    cases[1].centre = cdl_vec3_make(0.2, 0.0, -0.5);
    cases[2].shape = sphere_shape(cdl_vec3_make(1, 2, 3), 0.3, 0);
    cases[2].area = CDL_FOUR_PI * 0.09;
    cases[2].centre = cdl_vec3_make(1, 2, 3);
    cases[3].shape = triangles_shape(octa_v, 6, octa_t, 8);
    cases[3].area = 8 * sqrt(3.0) / 2.0; /* 8 equilateral triangles of side sqrt(2) */
    cases[3].centre = cdl_vec3_make(0, 0, 5);
    for (int k = 0; k < 4; ++k) {
        cdl_emitter *e = make_area(cases[k].shape, L);
        double Phi = cdl_emitter_flux(e).lm;
        /* 1. Closed form pi L A. */
        CHECK_REL(Phi, CDL_PI * L * cases[k].area, 1e-14);
        /* 2. Quadrature of I(w) over the sphere in the tilted frame; the
         * kinks of max(0, m.w) cost the midpoint rule O(h^2): ~1e-6 with
         * 1000 x 2000 cells; 1e-5 leaves margin. The sphere's I is constant. */
        CHECK_REL(sphere_quadrature(intensity_of, e, 1000), Phi, 1e-5);
        /* 3. Importance sampled through E on an enclosing sphere of radius
         * 2 m: 65536 samples, 5 standard errors, and the error bar must be
         * small enough (< 2%) for the check to mean something. */
        double mean, se;
        sampled_flux(e, cases[k].centre, 2.0, 65536, &mean, &se);
        CHECK_MSG(fabs(mean - Phi) <= 5 * se, "shape %d: sampled %g vs %g (se %g)", k, mean, Phi, se);
        CHECK_MSG(se < 0.02 * Phi, "shape %d: se %g", k, se);
        cdl_emitter_release(e);
    }
}

/* ---- sampling reproduces E -------------------------------------------------- */

static void check_sampled_E(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, const char *what)
{
    double E = exact_E(e, p, n);
    mc_result r = mc_illuminance(e, p, n, 256, 1234, 1);
    /* 65536 stratified samples; the sample standard error over-estimates a
     * stratified estimator's, so 5 of them is a safe bound. */
    CHECK_MSG(fabs(r.mean - E) <= 5 * r.stderr_ + 1e-12 * E, "%s: sampled %.9g vs exact %.9g (se %.3g)", what, r.mean, E,
              r.stderr_);
    CHECK_MSG(r.stderr_ < 0.02 * E, "%s: se %.3g of %.9g", what, r.stderr_, E);
    CHECK_MSG(r.pdf_mismatches == 0, "%s: %d samples disagree with radiance()", what, r.pdf_mismatches);
    CHECK_MSG(r.bad_samples == 0, "%s: %d bad samples", what, r.bad_samples);
}

static void test_sampling(void)
{
    double L = 300.0;
    cdl_emitter *rect = make_area(rect_shape(cdl_vec3_make(-1, -0.5, 2.5), cdl_vec3_make(0, 1.2, 0), cdl_vec3_make(2, 0, 0)), L);
    check_sampled_E(rect, cdl_vec3_make(0.3, 0.2, 0), cdl_vec3_make(0, 0, 1), "rect above");
    check_sampled_E(rect, cdl_vec3_make(1.5, 0.2, 2.0), cdl_vec3_normalize(cdl_vec3_make(-1, 0, 0.2)), "rect, plane cuts it");
    check_sampled_E(rect, cdl_vec3_make(0, 0, 2.3), cdl_vec3_make(0, 0, 1), "rect, 0.2 m below");
    check_sampled_E(rect, cdl_vec3_make(0.4, -0.3, 2.49), cdl_vec3_make(0, 0, 1), "rect, 1 cm below");
    check_sampled_E(rect, cdl_vec3_make(0.4, -0.3, 2.49), cdl_vec3_normalize(cdl_vec3_make(1, 0, 0.05)), "rect, 1 cm, grazing");
    check_sampled_E(rect, cdl_vec3_make(-20, 3, -60), cdl_vec3_normalize(cdl_vec3_make(0.3, 0, 1)), "rect, far (area sampling)");
    cdl_emitter *disk = make_area(disk_shape(cdl_vec3_make(0, 0, 2), cdl_vec3_make(0.3, 0, -1), 0.6), L);
    check_sampled_E(disk, cdl_vec3_make(0.5, 0.3, 0), cdl_vec3_make(0, 0, 1), "disk");
    check_sampled_E(disk, cdl_vec3_make(0.9, 0.0, 1.9), cdl_vec3_normalize(cdl_vec3_make(-1, 0.2, 0.3)), "disk, cut");
    /* Close under the disk it fills more than half of the cosine-weighted
     * hemisphere: cosine-weighted sampling, with a small spread. */
    check_sampled_E(disk, cdl_vec3_make(0.1, -0.05, 1.92), cdl_vec3_make(0, 0, 1), "disk, 5 cm below");
    check_sampled_E(disk, cdl_vec3_make(0.45, 0.1, 1.99), cdl_vec3_normalize(cdl_vec3_make(0.2, 0, 1)), "disk, near the rim");
    cdl_emitter *sph = make_area(sphere_shape(cdl_vec3_make(0, 0, 3), 0.5, 0), L);
    check_sampled_E(sph, cdl_vec3_make(0.2, 0, 0), cdl_vec3_make(0, 0, 1), "sphere");
    check_sampled_E(sph, cdl_vec3_make(0, 1.0, 3.0), cdl_vec3_normalize(cdl_vec3_make(0, 0.3, 1)), "sphere, cut");
    cdl_emitter *octa = make_area(triangles_shape(octa_v, 6, octa_t, 8), L);
    check_sampled_E(octa, cdl_vec3_make(0.3, -0.2, 2.0), cdl_vec3_make(0, 0, 1), "octahedron");
    check_sampled_E(octa, cdl_vec3_make(2.0, 0.5, 5.2), cdl_vec3_normalize(cdl_vec3_make(-1, 0, 0.9)), "octahedron, cut");
    /* From 40 m every face subtends < 1e-3 sr: faces chosen by solid angle,
     * points by area within them. */
    check_sampled_E(octa, cdl_vec3_make(30.0, -20.0, -15.0), cdl_vec3_normalize(cdl_vec3_make(-1, 0.5, 1)), "octahedron, far");
    /* A unit square as two triangles, 1 cm below: solid-angle sampling keeps
     * the standard error under 2% with these samples (area sampling's
     * relative spread per sample would be ~50 here, i.e. ~20%). */
    cdl_emitter *sq = make_area(triangles_shape(square_v, 4, square_t, 2), L);
    check_sampled_E(sq, cdl_vec3_make(0.4, 0.3, 1.99), cdl_vec3_make(0, 0, 1), "square mesh, 1 cm below");
    cdl_emitter_release(sq);
    /* The same square as a 10 x 10 grid of 200 triangles (above the
     * solid-angle limit of 64: area sampling) gives the same exact E as the
     * two-triangle mesh, and its samples reproduce it. */
    double gv[121 * 3];
    uint32_t gt[200 * 3];
    for (int j = 0; j <= 10; ++j)
        for (int i = 0; i <= 10; ++i) {
            gv[3 * (j * 11 + i)] = i / 10.0;
            gv[3 * (j * 11 + i) + 1] = j / 10.0;
            gv[3 * (j * 11 + i) + 2] = 2.0;
        }
    for (int j = 0, k = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            uint32_t v00 = (uint32_t)(j * 11 + i), v10 = v00 + 1, v01 = v00 + 11, v11 = v01 + 1;
            /* Counter-clockwise seen from below (emitting down): (v00, v01, v11), (v00, v11, v10). */
            uint32_t tri[6] = {v00, v01, v11, v00, v11, v10};
            for (int q = 0; q < 6; ++q) gt[k++] = tri[q];
        }
    cdl_emitter *grid = make_area(triangles_shape(gv, 121, gt, 200), L);
    sq = make_area(triangles_shape(square_v, 4, square_t, 2), L);
    CHECK_REL(exact_E(grid, cdl_vec3_make(0.3, 0.6, 0.5), cdl_vec3_make(0, 0, 1)),
              exact_E(sq, cdl_vec3_make(0.3, 0.6, 0.5), cdl_vec3_make(0, 0, 1)), 1e-12);
    check_sampled_E(grid, cdl_vec3_make(0.3, 0.6, 0.5), cdl_vec3_make(0, 0, 1), "200-triangle grid");
    cdl_emitter_release(grid);
    cdl_emitter_release(sq);

    /* Inside an inward sphere the cosine-weighted sampler is exact: every
     * sample gives L cos / (cos / pi) = pi L. */
    cdl_emitter *room = make_area(sphere_shape(cdl_vec3_make(0, 0, 0), 4.0, 1), L);
    mc_result r = mc_illuminance(room, cdl_vec3_make(1, 1, -2), cdl_vec3_normalize(cdl_vec3_make(0.2, 0.4, 1)), 16, 1, 1);
    CHECK_REL(r.mean, CDL_PI * L, 1e-12);
    CHECK(r.stderr_ < 1e-9 * L && r.pdf_mismatches == 0 && r.bad_samples == 0);
    /* ... and its samples reach the sphere. */
    cdl_light_sample s;
    cdl_vec3 p = {1, 1, -2};
    CHECK(cdl_emitter_sample(room, p, cdl_vec3_make(0, 0, 1), 0.3, 0.6, &s));
    CHECK_REL(cdl_vec3_length(cdl_vec3_madd(p, s.distance, s.to_light)), 4.0, 1e-14);

    /* radiance(): the back of the rect is dark, a miss is dark. */
    double pdf = 7.0;
    CHECK(cdl_emitter_radiance(rect, cdl_vec3_make(0, 0, 5), cdl_vec3_make(0, 0, -1), cdl_vec3_make(0, 0, -1), &pdf).cd_m2 == 0.0);
    CHECK(pdf == 0.0);
    CHECK(cdl_emitter_radiance(rect, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), cdl_vec3_make(1, 0, 0), &pdf).cd_m2 == 0.0);
    CHECK(cdl_emitter_radiance(rect, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), &pdf).cd_m2 == L);
    /* This rect (x in [-1, 1], y in [-0.5, 0.7] at 2.5 m) subtends more
     * than 1e-3 sr: it is sampled uniformly in solid angle, pdf = 1 / Omega,
     * Omega the sum over the four corner rectangles of
     * atan(x y / (h sqrt(x^2 + y^2 + h^2))). */
    double h = 2.5, omega = 2.0 * atan(0.7 / (h * sqrt(1.0 + 0.49 + h * h))) + 2.0 * atan(0.5 / (h * sqrt(1.0 + 0.25 + h * h)));
    CHECK_REL(pdf, 1.0 / omega, 1e-12);
    /* Far away (Omega < 1e-3 sr) it is sampled by area: pdf = d^2 / (A cos). */
    CHECK(cdl_emitter_radiance(rect, cdl_vec3_make(0, 0, -97.5), cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), &pdf).cd_m2 == L);
    CHECK_REL(pdf, 100.0 * 100.0 / 2.4, 1e-14);
    /* A slanted parallelogram is always sampled by area. */
    cdl_emitter *slanted = make_area(rect_shape(cdl_vec3_make(-1, -0.5, 2.5), cdl_vec3_make(0.5, 1.2, 0), cdl_vec3_make(2, 0, 0)), L);
    CHECK(cdl_emitter_radiance(slanted, cdl_vec3_make(0.5, 0.3, 0), cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), &pdf).cd_m2 == L);
    CHECK_REL(pdf, 2.5 * 2.5 / 2.4, 1e-14);
    check_sampled_E(slanted, cdl_vec3_make(0.3, 0.2, 0.5), cdl_vec3_make(0, 0, 1), "parallelogram");
    cdl_emitter_release(slanted);
    /* Samples behind the receiver are refused. */
    CHECK(!cdl_emitter_sample(rect, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, -1), 0.5, 0.5, &s));
    CHECK(!cdl_emitter_is_delta(rect) && cdl_emitter_has_exact_illuminance(rect));

    cdl_emitter_release(rect);
    cdl_emitter_release(disk);
    cdl_emitter_release(sph);
    cdl_emitter_release(octa);
    cdl_emitter_release(room);
}

static void test_bad_parameters(void)
{
    cdl_area_params p;
    memset(&p, 0, sizeof p);
    cdl_emitter *e = NULL;
    cdl_error err;
    p.shape = rect_shape(cdl_vec3_make(0, 0, 0), cdl_vec3_make(1, 0, 0), cdl_vec3_make(2, 0, 0));
    p.luminance = cdl_nits(10.0);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "rect"), "%s", err.message);
    p.shape = disk_shape(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), 0.0);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "radius"), "%s", err.message);
    p.shape = disk_shape(cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 0), 1.0);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "normal"), "%s", err.message);
    p.shape = sphere_shape(cdl_vec3_make(0, NAN, 0), 1.0, 0);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    p.shape = sphere_shape(cdl_vec3_make(0, 0, 0), 1.0, 0);
    p.luminance = cdl_nits(-3.0);
    CHECK(cdl_emitter_create_area(&p, &e, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "luminance"), "%s", err.message);
    CHECK(e == NULL);
}

int main(void)
{
    test_rect_configuration_factors();
    test_disk_and_sphere();
    test_triangles();
    test_flux_three_ways();
    test_sampling();
    test_bad_parameters();
    return check_finish();
}
