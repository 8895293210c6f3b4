/* End-to-end direct illuminance: scenes with closed-form answers, solved
 * through the scene loader, geometry, emitters and the direct solver. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry/photometry.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "solver/scene/exr_image.h"
#include "solver/solve_internal.h"
#include "solver/solve_fixture.h"

/* Point light, no geometry: inverse-square and cosine law over angles
 * 0..89.9 degrees and distances 1e-4..1e5 m, intensities 1e-6..1e9 cd.
 * With nothing to occlude, the result is the closed form to a few ulps. */
static void test_inverse_square_cosine(void)
{
    const double intensities[] = {1e-6, 1234.5, 1e9};
    const double distances[] = {1e-4, 0.37, 1e5};
    const double angles[] = {0.0, 30.0, 60.0, 85.0, 89.9};
    for (int ii = 0; ii < 3; ++ii) {
        char json[8192];
        int n = snprintf(json, sizeof json,
                         "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0], "
                         "\"intensity_cd\": %.17g}], \"grids\": [{\"name\": \"probes\", \"type\": \"points\", "
                         "\"points\": [",
                         intensities[ii]);
        for (int d = 0; d < 3; ++d)
            for (int a = 0; a < 5; ++a) {
                /* point at distance D straight below, normal tilted by the angle
                 * towards +x: cos(theta) between normal and the light direction. */
                double D = distances[d], t = angles[a] * CDL_DEG_TO_RAD;
                n += snprintf(json + n, sizeof json - (size_t)n, "%s{\"p\": [0, 0, %.17g], \"n\": [%.17g, 0, %.17g]}",
                              (d || a) ? ", " : "", -D, sin(t), cos(t));
            }
        snprintf(json + n, sizeof json - (size_t)n, "]}], \"solver\": {\"method\": \"direct\"}}");
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 1)) continue;
        const cdl_grid_solution *g = &sol.grids[0];
        int k = 0;
        for (int d = 0; d < 3; ++d)
            for (int a = 0; a < 5; ++a, ++k) {
                double D = distances[d], t = angles[a] * CDL_DEG_TO_RAD;
                /* the normal as the solver sees it is normalised from (sin t, 0, cos t) */
                double expected = intensities[ii] * cos(t) / (D * D);
                CHECK_REL(g->E[k], expected, 1e-13);
                CHECK(g->E_stderr[k] == 0.0);
            }
        CHECK(sol.rays == 0); /* nothing in the scene: no rays */
        fixture_release(scene, &sol);
    }
}


/* Write a text file into the test folder; returns its path (static storage per name). */
static const char *write_file(const char *name, const char *text)
{
    static char path[4][512];
    static int next;
    char *p = path[next++ % 4];
    snprintf(p, 512, "%s/%s", CANDELA_TEST_TMPDIR, name);
    FILE *f = fopen(p, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return p;
}

/* Spot with a smoothstep edge: full inside falloff_start, the smoothstep
 * 3t^2 - 2t^3 of t = (cos a - cos half)/(cos falloff - cos half) between,
 * nothing beyond half_angle (DESIGN.md). Probes on a sphere of radius 2 m
 * about the spot, facing it. */
static void test_spot_falloff(void)
{
    const double I0 = 5000.0, half = 30.0, falloff = 25.0, R = 2.0;
    const double angles[] = {0.0, 10.0, 24.9, 26.0, 27.5, 29.0, 29.9, 30.5, 45.0, 120.0};
    const int n = (int)(sizeof angles / sizeof angles[0]);
    char json[8192];
    int k = snprintf(json, sizeof json,
                     "{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0, 0, 3], \"direction\": "
                     "[0, 0, -1], \"intensity_cd\": %g, \"half_angle\": %g, \"falloff_start\": %g}], \"grids\": "
                     "[{\"name\": \"arc\", \"type\": \"points\", \"points\": [",
                     I0, half, falloff);
    for (int i = 0; i < n; ++i) {
        double a = angles[i] * CDL_DEG_TO_RAD;
        k += snprintf(json + k, sizeof json - (size_t)k, "%s{\"p\": [%.17g, 0, %.17g], \"n\": [%.17g, 0, %.17g]}",
                      i ? ", " : "", R * sin(a), 3.0 - R * cos(a), -sin(a), cos(a));
    }
    snprintf(json + k, sizeof json - (size_t)k, "]}], \"solver\": {\"method\": \"direct\"}}");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    for (int i = 0; i < n; ++i) {
        double ca = cos(angles[i] * CDL_DEG_TO_RAD), ch = cos(half * CDL_DEG_TO_RAD), cf = cos(falloff * CDL_DEG_TO_RAD);
        double f;
        if (ca >= cf) f = 1.0;
        else if (ca <= ch) f = 0.0;
        else {
            double t = (ca - ch) / (cf - ch);
            f = t * t * (3.0 - 2.0 * t);
        }
        double expected = I0 * f / (R * R); /* receiver faces the spot: cos = 1 */
        if (expected == 0.0)
            CHECK_MSG(sol.grids[0].E[i] == 0.0, "angle %g: E = %g, expected 0", angles[i], sol.grids[0].E[i]);
        else
            CHECK_REL(sol.grids[0].E[i], expected, 1e-12);
    }
    fixture_release(scene, &sol);
}

/* Rotation matrix world_from_luminaire = Rz Ry Rx (fixed axes, x first). */
static cdl_vec3 rotate_xyz(const double deg[3], cdl_vec3 v)
{
    double a = deg[0] * CDL_DEG_TO_RAD, b = deg[1] * CDL_DEG_TO_RAD, c = deg[2] * CDL_DEG_TO_RAD;
    cdl_vec3 x = cdl_vec3_make(v.x, cos(a) * v.y - sin(a) * v.z, sin(a) * v.y + cos(a) * v.z);
    cdl_vec3 y = cdl_vec3_make(cos(b) * x.x + sin(b) * x.z, x.y, -sin(b) * x.x + cos(b) * x.z);
    return cdl_vec3_make(cos(c) * y.x - sin(c) * y.y, sin(c) * y.x + cos(c) * y.y, y.z);
}

/* Goniometric luminaire, rotated: probes along directions that fall on
 * table nodes (C, gamma), so the expected value is the tabulated candela
 * times maintenance factor and multiplier, times cos(theta) / d^2. The table
 * is IES type C, H = 0..350 by 10 degrees, V = 0..180 by 10, with
 * I(H, V) = 100 + 3 V + 2 (H mod 180) + (H >= 180 ? 50 : 0) cd off the poles
 * and 100 + 3 V at the poles (one value each): no symmetry. IES horizontal
 * angles run clockwise seen from above, so the frame's C-plane C holds the
 * file's H = (360 - C) mod 360 (lights/photometry/photometry.h). */
static double gonio_table(int H, int V)
{
    if (V == 0 || V == 180) return 100 + 3 * V;
    return 100 + 3 * V + 2 * (H % 180) + (H >= 180 ? 50 : 0);
}

static void test_goniometric_rotated(void)
{
    char ies[16384];
    int k = snprintf(ies, sizeof ies,
                     "IES:LM-63-2019\n[TEST] candela test\n[TESTLAB] test\n[ISSUEDATE] 2026-11-21\n[MANUFAC] test\n"
                     "TILT=NONE\n1 -1 1 19 36 1 2 0 0 0\n1 1 10\n");
    for (int g = 0; g <= 180; g += 10) k += snprintf(ies + k, sizeof ies - (size_t)k, "%d ", g);
    k += snprintf(ies + k, sizeof ies - (size_t)k, "\n");
    for (int c = 0; c < 360; c += 10) k += snprintf(ies + k, sizeof ies - (size_t)k, "%d ", c);
    k += snprintf(ies + k, sizeof ies - (size_t)k, "\n");
    for (int c = 0; c < 360; c += 10) {
        for (int g = 0; g <= 180; g += 10)
            k += snprintf(ies + k, sizeof ies - (size_t)k, "%g ", gonio_table(c, g));
        k += snprintf(ies + k, sizeof ies - (size_t)k, "\n");
    }
    write_file("gonio_test.ies", ies);

    const double rot[3] = {20.0, -30.0, 45.0};
    const cdl_vec3 pos = cdl_vec3_make(1.0, 2.0, 3.0);
    const int nodes[][2] = {{0, 0}, {30, 40}, {90, 90}, {200, 60}, {270, 130}, {350, 10}, {180, 180}};
    const int n = (int)(sizeof nodes / sizeof nodes[0]);
    const double dist[] = {1.5, 2.0, 3.0, 0.7, 4.0, 2.5, 1.0};
    char json[8192];
    int j = snprintf(json, sizeof json,
                     "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"gonio_test.ies\", "
                     "\"position\": [1, 2, 3], \"rotation\": [20, -30, 45], \"maintenance_factor\": 0.8, "
                     "\"multiplier\": 1.25}], \"grids\": [{\"name\": \"probes\", \"type\": \"points\", \"points\": [");
    cdl_vec3 normals[16];
    for (int i = 0; i < n; ++i) {
        double C = nodes[i][0] * CDL_DEG_TO_RAD, g = nodes[i][1] * CDL_DEG_TO_RAD;
        cdl_vec3 local = cdl_vec3_make(sin(g) * cos(C), sin(g) * sin(C), -cos(g));
        cdl_vec3 w = rotate_xyz(rot, local);
        cdl_vec3 p = cdl_vec3_madd(pos, dist[i], w);
        /* a receiver tilted away from the light direction by ~35 degrees */
        cdl_vec3 nrm = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_neg(w), cdl_vec3_make(0.3, -0.5, 0.2)));
        normals[i] = nrm;
        j += snprintf(json + j, sizeof json - (size_t)j, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}",
                      i ? ", " : "", p.x, p.y, p.z, nrm.x, nrm.y, nrm.z);
    }
    snprintf(json + j, sizeof json - (size_t)j, "]}], \"solver\": {\"method\": \"direct\"}}");
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    for (int i = 0; i < n; ++i) {
        int C = nodes[i][0], g = nodes[i][1];
        double table = gonio_table((360 - C) % 360, g);
        double C_rad = C * CDL_DEG_TO_RAD, g_rad = g * CDL_DEG_TO_RAD;
        cdl_vec3 w = rotate_xyz(rot, cdl_vec3_make(sin(g_rad) * cos(C_rad), sin(g_rad) * sin(C_rad), -cos(g_rad)));
        double cos_theta = cdl_vec3_dot(normals[i], cdl_vec3_neg(w));
        double expected = table * 0.8 * 1.25 * cos_theta / (dist[i] * dist[i]);
        CHECK_MSG(fabs(sol.grids[0].E[i] - expected) <= 1e-9 * expected, "node C=%d g=%d: E = %.12g, expected %.12g",
                  C, g, sol.grids[0].E[i], expected);
    }
    /* The DESIGN.md example: rotation [0, -30, 0] tilts the nadir from -z towards +x. */
    const double tilt[3] = {0.0, -30.0, 0.0};
    cdl_vec3 nadir = rotate_xyz(tilt, cdl_vec3_make(0, 0, -1));
    CHECK(nadir.x > 0.49 && nadir.z < -0.86);
    fixture_release(scene, &sol);
}

/* Configuration factor, differential element to a parallel rectangle a x b
 * with the normal through one corner, at distance h (Howell's catalogue,
 * C-11; Modest, Radiative Heat Transfer, appendix D). */
static double cf_parallel_corner(double a, double b, double h)
{
    double X = a / h, Y = b / h;
    return (X / sqrt(1 + X * X) * atan(Y / sqrt(1 + X * X)) + Y / sqrt(1 + Y * Y) * atan(X / sqrt(1 + Y * Y))) /
           (2.0 * CDL_PI);
}

/* E = L integral of cos(theta_r) cos(theta_e) / d^2 dA over a rectangle, by
 * Gauss-Legendre (16 nodes) on 64 x 64 panels: an independent reference for
 * configurations without a tabulated formula. */
static double rect_quadrature(cdl_vec3 origin, cdl_vec3 u, cdl_vec3 v, double L, cdl_vec3 p, cdl_vec3 n)
{
    static const double x16[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                  0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
    static const double w16[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                  0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
    cdl_vec3 en = cdl_vec3_normalize(cdl_vec3_cross(u, v));
    double area = cdl_vec3_length(cdl_vec3_cross(u, v));
    const int panels = 64;
    double sum = 0.0;
    for (int pi = 0; pi < panels; ++pi)
        for (int pj = 0; pj < panels; ++pj)
            for (int a = 0; a < 16; ++a)
                for (int b = 0; b < 16; ++b) {
                    double xa = a < 8 ? -x16[7 - a] : x16[a - 8], wa = a < 8 ? w16[7 - a] : w16[a - 8];
                    double xb = b < 8 ? -x16[7 - b] : x16[b - 8], wb = b < 8 ? w16[7 - b] : w16[b - 8];
                    double s = (pi + 0.5 + 0.5 * xa) / panels, t = (pj + 0.5 + 0.5 * xb) / panels;
                    cdl_vec3 q = cdl_vec3_add(origin, cdl_vec3_add(cdl_vec3_scale(u, s), cdl_vec3_scale(v, t)));
                    cdl_vec3 d = cdl_vec3_sub(q, p);
                    double r2 = cdl_vec3_dot(d, d), r = sqrt(r2);
                    double cr = cdl_vec3_dot(n, d) / r, ce = -cdl_vec3_dot(en, d) / r;
                    if (cr > 0 && ce > 0) sum += wa * wb * 0.25 * cr * ce / r2;
                }
    return L * sum * area / (panels * panels);
}

/* Lambertian area luminaires: rectangle (parallel and perpendicular
 * receivers) and disk on axis; closed forms with no occluders. */
static void test_lambertian_emitters(void)
{
    const double L = 2000.0, a = 1.2, b = 0.6, h = 1.7;
    const char *json =
        "{\"version\": 1, \"luminaires\": ["
        " {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0, 0, 1.7], \"u\": [0, 0.6, 0], "
        "\"v\": [1.2, 0, 0]}, \"luminance_cd_m2\": 2000}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": ["
        "  {\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [0.6, 0.3, 0], \"n\": [0, 0, 1]},"
        "  {\"p\": [-0.5, 0.3, 1.0], \"n\": [1, 0, 0]}, {\"p\": [0.6, 0.3, 1.69999], \"n\": [0, 0, 1]},"
        "  {\"p\": [0.6, 0.3, -10000], \"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const double *E = sol.grids[0].E;
    /* corner: one rectangle; centre: four quarter rectangles. */
    CHECK_REL(E[0], CDL_PI * L * cf_parallel_corner(a, b, h), 1e-10);
    CHECK_REL(E[1], 4.0 * CDL_PI * L * cf_parallel_corner(a / 2, b / 2, h), 1e-10);
    /* perpendicular receiver beside the luminaire, facing +x: quadrature
     * reference (converged to ~1e-12 for this smooth integrand). */
    double ref = rect_quadrature(cdl_vec3_make(0, 0, 1.7), cdl_vec3_make(0, 0.6, 0), cdl_vec3_make(1.2, 0, 0), L,
                                 cdl_vec3_make(-0.5, 0.3, 1.0), cdl_vec3_make(1, 0, 0));
    CHECK_REL(E[2], ref, 1e-8);
    /* right under the emitter (10 um away): the near field is pi L. */
    CHECK_REL(E[3], CDL_PI * L, 1e-4);
    /* 10 km below: the far field is I cos / d^2 with I = L A. */
    CHECK_REL(E[4], L * a * b / (10001.7 * 10001.7), 1e-6);
    for (int i = 0; i < 5; ++i) CHECK(sol.grids[0].E_stderr[i] == 0.0);
    fixture_release(scene, &sol);

    /* The same rectangle given by flux (Phi = pi L A) and a maintenance
     * factor: L = 0.8 x 3000 lm / (pi x 0.72 m^2). */
    const char *by_flux =
        "{\"version\": 1, \"luminaires\": ["
        " {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0, 0, 1.7], \"u\": [0, 0.6, 0], "
        "\"v\": [1.2, 0, 0]}, \"flux_lm\": 3000, \"maintenance_factor\": 0.8}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    if (!fixture_solve(by_flux, &scene, &sol, 1)) return;
    CHECK_REL(sol.grids[0].E[0], CDL_PI * (0.8 * 3000.0 / (CDL_PI * a * b)) * cf_parallel_corner(a, b, h), 1e-10);
    fixture_release(scene, &sol);

    /* Disk on axis: E = pi L r^2 / (r^2 + h^2). */
    const char *disk =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"disk\", \"center\": [0, 0, 2], "
        "\"normal\": [0, 0, -1], \"radius\": 0.3}, \"luminance_cd_m2\": 1000}], \"grids\": [{\"name\": \"p\", "
        "\"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [0, 0, 1.5], \"n\": [0, 0, 1]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    if (!fixture_solve(disk, &scene, &sol, 1)) return;
    CHECK_REL(sol.grids[0].E[0], CDL_PI * 1000.0 * 0.09 / (0.09 + 4.0), 1e-10);
    CHECK_REL(sol.grids[0].E[1], CDL_PI * 1000.0 * 0.09 / (0.09 + 0.25), 1e-10);
    fixture_release(scene, &sol);
}

/* Uniform sky: pi L on a horizontal plane, pi L / 2 on a vertical one
 * (upper hemisphere only); a full sphere gives pi L on any plane. */
static void test_uniform_sky(void)
{
    const char *json =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 5000, "
        "\"hemisphere\": \"upper\", \"up\": [0, 0, 1]}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", "
        "\"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [3, 0, 0], \"n\": [1, 0, 0]},"
        " {\"p\": [0, 0, 7], \"n\": [0, 0.6, 0.8]}, {\"p\": [0, 1, 0], \"n\": [0, 0, -1]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const double *E = sol.grids[0].E;
    CHECK_REL(E[0], CDL_PI * 5000.0, 1e-12);
    CHECK_REL(E[1], CDL_PI * 5000.0 / 2.0, 1e-12);
    /* tilted by beta (cos 0.8): sky view factor (1 + cos beta) / 2 */
    CHECK_REL(E[2], CDL_PI * 5000.0 * (1.0 + 0.8) / 2.0, 1e-12);
    CHECK(E[3] == 0.0);
    CHECK(sol.rays == 0);
    fixture_release(scene, &sol);
    const char *full =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 300}], \"grids\": "
        "[{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, -1]}, "
        "{\"p\": [0, 0, 0], \"n\": [0.6, 0, 0.8]}]}], \"solver\": {\"method\": \"direct\"}}";
    if (!fixture_solve(full, &scene, &sol, 1)) return;
    CHECK_REL(sol.grids[0].E[0], CDL_PI * 300.0, 1e-12);
    CHECK_REL(sol.grids[0].E[1], CDL_PI * 300.0, 1e-12);
    fixture_release(scene, &sol);
}

/* Shadows from a box: a point light at (0, 0, 4) over a 1 x 1 x 1 box on the
 * floor centred at the origin. The box top (z = 1, |x|,|y| <= 0.5) casts the
 * shadow |x|, |y| <= 0.5 * 4 / 3 on the floor; points inside get nothing,
 * points outside the closed form (nothing else in the way). */
static void test_box_shadow(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-5, -5, 0], \"u\": [10, 0, 0], "
        "\"v\": [0, 10, 0], \"reflectance\": 0.2},"
        " {\"type\": \"box\", \"min\": [-0.5, -0.5, 0], \"max\": [0.5, 0.5, 1], \"reflectance\": 0.5}],"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 4], \"intensity_cd\": 1000}],"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [-2, -2, 0], \"u\": [4, 0, 0], "
        "\"v\": [0, 4, 0], \"nu\": 40, \"nv\": 40}], \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    int shadowed = 0, lit = 0;
    for (size_t i = 0; i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        double half = 0.5 * 4.0 / 3.0;
        int in_shadow = fabs(p.x) < half && fabs(p.y) < half;
        int under_box = fabs(p.x) < 0.5 && fabs(p.y) < 0.5;
        double d2 = p.x * p.x + p.y * p.y + 16.0;
        double expected = (in_shadow || under_box) ? 0.0 : 1000.0 * (4.0 / sqrt(d2)) / d2;
        if (expected == 0.0) {
            CHECK_MSG(g->E[i] == 0.0, "(%g, %g) in shadow: E = %g", p.x, p.y, g->E[i]);
            shadowed++;
        } else {
            CHECK_REL(g->E[i], expected, 1e-12);
            lit++;
        }
    }
    /* cell centres at -1.95 .. 1.95 by 0.1: 14 of them have |x| < 2/3 */
    CHECK(shadowed == 14 * 14 && lit == 1600 - 14 * 14);
    fixture_release(scene, &sol);
}

/* A rectangular emitter half hidden: an opaque plate at half height covers
 * x < 0, so from a receiver on the axis exactly the x < 0 half of the
 * emitter is hidden and E is half the unoccluded closed form. With the
 * exact route turned off the solver must sample here, and its estimate must
 * agree within its standard error (tests/solver/direct/ test the route). */
static void test_half_hidden_emitter(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-10, -10, 1], \"u\": [10, 0, 0], "
        "\"v\": [0, 20, 0], \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [-0.5, -0.5, 2], "
        "\"u\": [0, 1, 0], \"v\": [1, 0, 0]}, \"luminance_cd_m2\": 1000}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}]}],"
        " \"solver\": {\"method\": \"direct\", \"direct_samples\": 4096}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve_route(json, &scene, &sol, 1, 1)) return;
    double full = 4.0 * CDL_PI * 1000.0 * cf_parallel_corner(0.5, 0.5, 2.0);
    double E = sol.grids[0].E[0], se = sol.grids[0].E_stderr[0];
    CHECK_MSG(se > 0.0 && se < 0.01 * full, "stderr %g", se);
    /* within 4 standard errors (the stderr is an i.i.d. estimate, an upper
     * bound for the stratified estimator) */
    CHECK_MSG(fabs(E - 0.5 * full) <= 4.0 * se, "E = %g, expected %g +- %g", E, 0.5 * full, 4.0 * se);
    fixture_release(scene, &sol);
}

/* The same room at 1e-3, 1 and 1e3 times the size: for fixed intensities
 * the illuminance scales as 1/s^2 and the shadow pattern is identical; grid
 * points lie exactly on the floor. */
static void solve_scaled_room(double s, cdl_solution *sol, cdl_scene **scene)
{
    char json[4096];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [%.17g, %.17g, %.17g], "
             "\"inward\": true, \"reflectance\": 0.5},"
             " {\"type\": \"box\", \"min\": [%.17g, %.17g, 0], \"max\": [%.17g, %.17g, %.17g], \"reflectance\": 0.3},"
             " {\"type\": \"rect\", \"origin\": [%.17g, %.17g, %.17g], \"u\": [%.17g, 0, 0], \"v\": [0, %.17g, 0], "
             "\"reflectance\": 0.3}],"
             " \"luminaires\": [{\"type\": \"point\", \"position\": [%.17g, %.17g, %.17g], \"intensity_cd\": 1000},"
             " {\"type\": \"spot\", \"position\": [%.17g, %.17g, %.17g], \"direction\": [-1, -1, -2], "
             "\"intensity_cd\": 3000, \"half_angle\": 40, \"falloff_start\": 30}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [%.17g, 0, 0], "
             "\"v\": [0, %.17g, 0], \"nu\": 32, \"nv\": 32}], \"solver\": {\"method\": \"direct\"}}",
             4 * s, 4 * s, 3 * s, 1.5 * s, 1.5 * s, 2.2 * s, 2.5 * s, 0.8 * s, 0.6 * s, 1.0 * s, 1.2 * s, 2.0 * s,
             0.4 * s, 1.0 * s, 1.3 * s, 2.9 * s, 3.5 * s, 3.5 * s, 2.8 * s, 4 * s, 4 * s);
    fixture_solve(json, scene, sol, 1);
}

static void test_scale_invariance(void)
{
    cdl_scene *s1, *sa, *sb;
    cdl_solution r1, ra, rb;
    solve_scaled_room(1.0, &r1, &s1);
    solve_scaled_room(1e-3, &ra, &sa);
    solve_scaled_room(1e3, &rb, &sb);
    if (!s1 || !sa || !sb) return;
    size_t n = r1.grids[0].grid.count, zeros = 0, mismatched = 0;
    for (size_t i = 0; i < n; ++i) {
        double e1 = r1.grids[0].E[i], ea = ra.grids[0].E[i] * 1e-6, eb = rb.grids[0].E[i] * 1e6;
        if (e1 == 0.0) zeros++;
        /* identical visibility, values equal to rounding */
        if ((e1 == 0.0) != (ea == 0.0) || (e1 == 0.0) != (eb == 0.0) || fabs(ea - e1) > 1e-9 * e1 ||
            fabs(eb - e1) > 1e-9 * e1)
            mismatched++;
    }
    CHECK_MSG(mismatched == 0, "%zu of %zu points differ between scales", mismatched, n);
    CHECK_MSG(zeros > 20 && zeros < n / 2, "%zu shadowed points", zeros); /* the obstacles do cast shadows */
    fixture_release(s1, &r1);
    fixture_release(sa, &ra);
    fixture_release(sb, &rb);
}

/* Results do not depend on the number of threads: bit-identical. */
static void test_thread_determinism(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [4, 3, 2.5], \"inward\": true,"
        " \"reflectance\": 0}, {\"type\": \"sphere\", \"center\": [2, 1.5, 1.2], \"radius\": 0.4, \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1.5, 1, 2.49], "
        "\"u\": [0, 1, 0], \"v\": [1, 0, 0]}, \"luminance_cd_m2\": 3000}, {\"type\": \"point\", \"position\": [1, 1, 2], "
        "\"intensity_cd\": 500}],"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [4, 0, 0], \"v\": [0, 3, 0],"
        " \"nu\": 24, \"nv\": 18, \"outputs\": [\"ao\"]}], \"solver\": {\"method\": \"direct\", \"quality\": \"draft\"}}";
    cdl_scene *s[3];
    cdl_solution r[3];
    const int threads[3] = {1, 2, 3};
    for (int t = 0; t < 3; ++t) fixture_solve(json, &s[t], &r[t], threads[t]);
    if (!s[0] || !s[1] || !s[2]) return;
    size_t n = r[0].grids[0].grid.count;
    for (int t = 1; t < 3; ++t) {
        CHECK(memcmp(r[0].grids[0].E, r[t].grids[0].E, n * sizeof(double)) == 0);
        CHECK(memcmp(r[0].grids[0].E_stderr, r[t].grids[0].E_stderr, n * sizeof(double)) == 0);
        CHECK(memcmp(r[0].grids[0].ao, r[t].grids[0].ao, n * sizeof(double)) == 0);
        CHECK(r[0].rays == r[t].rays);
    }
    /* the sphere hides part of the panel from some points: sampling happened */
    int sampled = 0;
    for (size_t i = 0; i < n; ++i) sampled += r[0].grids[0].E_stderr[i] > 0.0;
    CHECK(sampled > 0);
    for (int t = 0; t < 3; ++t) fixture_release(s[t], &r[t]);
}

/* Ambient occlusion: an open plane sees the whole sky (1); a point on the
 * floor of a closed box sees nothing (0); a point at the bottom of a tall
 * open-topped shaft sees the cosine-weighted fraction of its opening. */
static void test_ambient_occlusion(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-50, -50, 0], \"u\": [100, 0, 0], "
        "\"v\": [0, 100, 0], \"reflectance\": 0},"
        " {\"type\": \"box\", \"min\": [10, 10, 0], \"max\": [12, 12, 2], \"inward\": true, \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 5], \"intensity_cd\": 1}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]},"
        " {\"p\": [11, 11, 0], \"n\": [0, 0, 1]}], \"outputs\": [\"ao\"]}], \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    CHECK(sol.grids[0].ao[0] == 1.0);
    CHECK(sol.grids[0].ao[1] == 0.0);
    fixture_release(scene, &sol);
}

/* Methods: "auto" on a scene with reflecting surfaces computes their
 * interreflection (here, one point, by path tracing: a flat plate cannot
 * light itself, so the point's interreflected part is exactly 0 and its E
 * the direct I cos / d^2 = 1 lx); "icache" with nothing reflecting gathers
 * no record. */
static void test_method_choices(void)
{
    const char *reflecting =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [1, 0, 0], \"v\": [0, 1, 0], "
        "\"reflectance\": 0.5}], \"luminaires\": [{\"type\": \"point\", \"position\": [0.5, 0.5, 1], \"intensity_cd\": 1}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0.5, 0.5, 0], \"n\": [0, 0, 1]}]}]}";
    cdl_scene *scene = NULL;
    cdl_solution refl;
    if (fixture_solve(reflecting, &scene, &refl, 1)) {
        CHECK(refl.method == CDL_METHOD_AUTO);
        CHECK(strstr(refl.plan_json, "surfaces[0] reflects 50 %") != NULL);
        CHECK(strstr(refl.plan_json, "\"p\":{\"method\":\"pathtrace\"") != NULL);
        CHECK_REL(refl.grids[0].E[0], 1.0, 1e-12);
        CHECK(refl.grids[0].E_indirect[0] == 0.0);
        fixture_release(scene, &refl);
    }
    const char *icache =
        "{\"version\": 1, \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], "
        "\"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"icache\"}}";
    cdl_solution ic;
    if (fixture_solve(icache, &scene, &ic, 1)) {
        CHECK(ic.method == CDL_METHOD_ICACHE && ic.records == 0);
        CHECK(strstr(ic.plan_json, "no record is gathered") != NULL);
        fixture_release(scene, &ic);
    }
    /* auto without reflecting surfaces is the direct method */
    const char *dark =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [1, 0, 0], \"v\": [0, 1, 0], "
        "\"reflectance\": 0}], \"luminaires\": [{\"type\": \"point\", \"position\": [0.5, 0.5, 1], \"intensity_cd\": 100}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0.5, 0.5, 0], \"n\": [0, 0, 1]}]}]}";
    cdl_solution sol;
    if (fixture_solve(dark, &scene, &sol, 1)) {
        CHECK(sol.method == CDL_METHOD_DIRECT);
        CHECK_REL(sol.grids[0].E[0], 100.0, 1e-12);
        CHECK(strstr(sol.plan_json, "no surface reflects light") != NULL);
        fixture_release(scene, &sol);
    }
}


/* A lat-long environment image: its top half (polar angle < 90 degrees from
 * up) at 1000 cd/m^2 in Y, the bottom half dark, and in the top half a band
 * of columns u in [0.375, 0.625) - azimuths around +x (phi = pi + 2 pi u)
 * - at 3000 cd/m^2. Nothing hides it, so the solver takes the exact sum
 * over pixels of L times each pixel's projected solid angle (no samples,
 * E_stderr 0); closed forms for comparison, which know nothing of pixels:
 *   upward receiver: pi L over the upper hemisphere plus the band's excess
 *     (2000 cd/m^2 over a quarter of the azimuths: a quarter of pi x 2000);
 *   receivers facing +x and -x: pi L / 2 each from the uniform part, and the
 *     band adds its projected solid angle only for +x. */
static void test_image_environment(void)
{
    const int w = 64, h = 32;
    static float Y[64 * 32];
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            double u = (c + 0.5) / w;
            Y[r * w + c] = r < h / 2 ? ((u >= 0.375 && u < 0.625) ? 3000.0f : 1000.0f) : 0.0f;
        }
    cdl_exr_channel ch = {"Y", Y};
    cdl_error err;
    CHECK_OK(cdl_exr_write(CANDELA_TEST_TMPDIR "/sky_band.exr", w, h, &ch, 1, NULL, 0, &err), &err);
    const char *json =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"file\": \"sky_band.exr\", \"scale\": 1.0}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]},"
        " {\"p\": [0, 0, 0], \"n\": [1, 0, 0]}, {\"p\": [0, 0, 0], \"n\": [-1, 0, 0]}, {\"p\": [0, 0, 0], \"n\": [0, 0, -1]}]}],"
        " \"solver\": {\"method\": \"direct\", \"direct_samples\": 16384}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const double *E = sol.grids[0].E, *se = sol.grids[0].E_stderr;
    /* Upward: uniform 1000 over the hemisphere -> 1000 pi; the band covers
     * azimuths -45..45 degrees: a quarter of the cosine-weighted hemisphere. */
    double up = 1000.0 * CDL_PI + 2000.0 * CDL_PI / 4.0;
    /* Facing +x: the uniform upper quarter-sphere gives 1000 pi / 2; the band
     * (phi in [-45, 45], theta in [0, 90]) adds 2000 x int cos(phi) sin(theta)
     * sin(theta) dtheta dphi = 2000 x (pi/4) x (2 sin 45) = 2000 x pi sqrt(2) / 4. */
    double east = 1000.0 * CDL_PI / 2.0 + 2000.0 * CDL_PI * sqrt(2.0) / 4.0;
    double west = 1000.0 * CDL_PI / 2.0;
    const double expected[3] = {up, east, west};
    for (int i = 0; i < 3; ++i) {
        /* Both exact: rounding over 2048 pixel terms, well below 1e-12. */
        CHECK_REL(E[i], expected[i], 1e-12);
        CHECK(se[i] == 0.0);
    }
    /* facing down: the ground half is black (the band's edges lie on the
     * receiver's horizon: at most rounding) */
    CHECK_ABS(E[3], 0.0, 1e-12 * up);
    CHECK(se[3] == 0.0);
    CHECK(strstr(sol.plan_json, "the exact sum over its pixels") != NULL);
    fixture_release(scene, &sol);
}

/* Model only what the scene needs: a point light and a grid inside a closed
 * box room: no surface can come between them, so no ray is traced, and the
 * plan says so. Add an obstacle between them and shadow rays appear. */
static void test_plan_no_rays(void)
{
    const char *room =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [5, 4, 3], \"inward\": true,"
        " \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [2.5, 2, 2.9], \"intensity_cd\": 800}],"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [5, 0, 0], \"v\": [0, 4, 0],"
        " \"nu\": 10, \"nv\": 8}], \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(room, &scene, &sol, 1)) return;
    CHECK(sol.rays == 0);
    CHECK(strstr(sol.plan_json, "exact, no shadow rays: no surface can come between") != NULL);
    CHECK(strstr(sol.plan_json, "no environment work") != NULL);
    /* points on the floor itself: the closed form everywhere */
    for (size_t i = 0; i < sol.grids[0].grid.count; ++i) {
        cdl_vec3 p = sol.grids[0].grid.points[i];
        double d2 = (p.x - 2.5) * (p.x - 2.5) + (p.y - 2) * (p.y - 2) + 2.9 * 2.9;
        CHECK_REL(sol.grids[0].E[i], 800.0 * 2.9 / sqrt(d2) / d2, 1e-12);
    }
    fixture_release(scene, &sol);
    const char *obstacle =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [5, 4, 3], \"inward\": true,"
        " \"reflectance\": 0}, {\"type\": \"disk\", \"center\": [2.5, 2, 1.5], \"normal\": [0, 0, 1], \"radius\": 0.3,"
        " \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [2.5, 2, 2.9], \"intensity_cd\": 800}],"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [5, 0, 0], \"v\": [0, 4, 0],"
        " \"nu\": 10, \"nv\": 8}], \"solver\": {\"method\": \"direct\"}}";
    if (!fixture_solve(obstacle, &scene, &sol, 1)) return;
    CHECK(sol.rays == 80);
    CHECK(strstr(sol.plan_json, "one shadow ray per point: surfaces may come between") != NULL);
    /* the disk (radius 0.3 at half height) shadows the floor within radius
     * 0.3 x 2.9 / 1.4 = 0.62 m of the centre: the 4 central cells */
    int dark = 0;
    for (size_t i = 0; i < sol.grids[0].grid.count; ++i) dark += sol.grids[0].E[i] == 0.0;
    CHECK(dark == 4);
    fixture_release(scene, &sol);
}


/* Emitting surfaces. A closed box room whose ceiling face glows at L: a
 * point on the floor sees the whole ceiling (the walls are beside it, not
 * between), so E = pi L F with F the sum of the four corner configuration
 * factors of the ceiling rectangle. An inward-emitting sphere is the
 * integrating sphere: every point inside, facing any way, sees luminance L
 * over its whole hemisphere, so E = pi L exactly. The cos^n spot: I0 cos^n. */
static void test_emitting_surfaces(void)
{
    const double L = 700.0;
    const char *room =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [5, 4, 3], \"inward\": true,"
        " \"reflectance\": 0, \"luminance_cd_m2\": 700, \"open\": []},"
        " {\"type\": \"rect\", \"origin\": [0, 0, 3], \"u\": [5, 0, 0], \"v\": [0, 4, 0], \"reflectance\": 0}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [1.5, 1.0, 0], \"n\": [0, 0, 1]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    /* Every face of the box glows (luminance on a box applies to all faces).
     * The extra rect shares the ceiling's plane and must not count as an
     * occluder of the ceiling's light. The floor point's hemisphere is
     * covered exactly by the ceiling and the four walls (the summation rule
     * of configuration factors), so E = pi L x 1. */
    cdl_scene *scene;
    cdl_solution sol;
    if (fixture_solve(room, &scene, &sol, 1)) {
        CHECK_REL(sol.grids[0].E[0], CDL_PI * L, 1e-9);
        fixture_release(scene, &sol);
    }
    /* Only the ceiling glows: a luminous ceiling over a dark room. */
    const char *ceiling =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [5, 4, 3], \"inward\": true,"
        " \"reflectance\": 0, \"open\": [\"ceiling\"]},"
        " {\"type\": \"rect\", \"origin\": [0, 4, 3], \"u\": [5, 0, 0], \"v\": [0, -4, 0], \"reflectance\": 0,"
        " \"luminance_cd_m2\": 700}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [1.5, 1.0, 0], \"n\": [0, 0, 1]},"
        " {\"p\": [2.5, 2.0, 1.2], \"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"direct\"}}";
    if (fixture_solve(ceiling, &scene, &sol, 1)) {
        /* the ceiling rect (normal (5,0,0) x (0,-4,0) = -z: facing down) split at the
         * foot of the normal through each point into four corner rectangles */
        double a1 = 1.5, a2 = 5.0 - 1.5, b1 = 1.0, b2 = 4.0 - 1.0, h = 3.0;
        double F = cf_parallel_corner(a1, b1, h) + cf_parallel_corner(a2, b1, h) + cf_parallel_corner(a1, b2, h) +
                   cf_parallel_corner(a2, b2, h);
        CHECK_REL(sol.grids[0].E[0], CDL_PI * L * F, 1e-10);
        a1 = 2.5; a2 = 2.5; b1 = 2.0; b2 = 2.0; h = 1.8;
        F = 4.0 * cf_parallel_corner(a1, b1, h);
        CHECK_REL(sol.grids[0].E[1], CDL_PI * L * F, 1e-10);
        CHECK(sol.grids[0].E_stderr[0] == 0.0 && sol.rays == 0);
        fixture_release(scene, &sol);
    }
    const char *sphere =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 2, \"inward\": true,"
        " \"reflectance\": 0, \"luminance_cd_m2\": 250}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]},"
        " {\"p\": [0.7, -0.3, 1.1], \"n\": [1, 0, 0]}, {\"p\": [-1.2, 0.4, -0.9], \"n\": [0.3, -0.4, -0.866]}]}],"
        " \"solver\": {\"method\": \"direct\"}}";
    if (fixture_solve(sphere, &scene, &sol, 1)) {
        for (int i = 0; i < 3; ++i) CHECK_REL(sol.grids[0].E[i], CDL_PI * 250.0, 1e-12);
        fixture_release(scene, &sol);
    }
    /* cos^n spot: I0 cos^n(alpha), nothing behind. */
    const char *cosn =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0, 0, 0], \"direction\": [0, 0, -1],"
        " \"intensity_cd\": 400, \"exponent\": 3}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": ["
        " {\"p\": [0, 0, -2], \"n\": [0, 0, 1]}, {\"p\": [1.2855752193730785, 0, -1.532088886237956], \"n\": [-0.6427876096865394, 0, 0.766044443118978]},"
        " {\"p\": [2, 0, 0.5], \"n\": [-1, 0, 0]}]}], \"solver\": {\"method\": \"direct\"}}";
    if (fixture_solve(cosn, &scene, &sol, 1)) {
        CHECK_REL(sol.grids[0].E[0], 400.0 / 4.0, 1e-12);
        double c = cos(40.0 * CDL_DEG_TO_RAD); /* the second point: 2 m away at 40 degrees, facing the spot */
        CHECK_REL(sol.grids[0].E[1], 400.0 * c * c * c / 4.0, 1e-12);
        CHECK(sol.grids[0].E[2] == 0.0);      /* above the spot's horizon */
        fixture_release(scene, &sol);
    }
}

/* Directional light (DESIGN.md: parallel light, illuminance_lx normal to the
 * beam, shadowed by surfaces) over a floor with a unit box on it: a lit
 * point gets E_n x MF x cos(theta) (Lambert's cosine law), a point whose ray
 * towards the light (-direction) meets the box gets nothing. The reference
 * decides shadow by the slab test of that ray against the box (Kay and
 * Kajiya 1986), independently of the solver's ray tracing; points within
 * 1e-6 m of a shadow edge (either answer acceptable) are skipped. */
static int ray_meets_box(cdl_vec3 p, cdl_vec3 w, cdl_vec3 lo, cdl_vec3 hi)
{
    const double o[3] = {p.x, p.y, p.z}, d[3] = {w.x, w.y, w.z}, l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    double t0 = 0.0, t1 = INFINITY;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < l[k] || o[k] > h[k]) return 0;
            continue;
        }
        double a = (l[k] - o[k]) / d[k], b = (h[k] - o[k]) / d[k];
        if (a > b) {
            double t = a;
            a = b;
            b = t;
        }
        t0 = fmax(t0, a);
        t1 = fmin(t1, b);
    }
    return t0 < t1;
}

static void test_directional_shadow(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-5, -5, 0], \"u\": [10, 0, 0], "
        "\"v\": [0, 10, 0], \"reflectance\": 0},"
        " {\"type\": \"box\", \"min\": [-0.5, -0.5, 0], \"max\": [0.5, 0.5, 1], \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"directional\", \"direction\": [0.3, 0.2, -1], \"illuminance_lx\": 80000,"
        " \"maintenance_factor\": 0.9}],"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [-3, -3, 0], \"u\": [6, 0, 0], "
        "\"v\": [0, 6, 0], \"nu\": 48, \"nv\": 48}, {\"name\": \"faces\", \"type\": \"points\", \"points\": ["
        " {\"p\": [0, 0, 1], \"n\": [0, 0, 1]}, {\"p\": [-0.5, 0, 0.5], \"n\": [-1, 0, 0]},"
        " {\"p\": [0.5, 0, 0.5], \"n\": [1, 0, 0]}]}], \"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_vec3 to_light = cdl_vec3_normalize(cdl_vec3_make(-0.3, -0.2, 1.0));
    const double lit = 80000.0 * 0.9 * to_light.z; /* floor normal +z */
    const cdl_grid_solution *g = &sol.grids[0];
    int shadowed = 0, skipped = 0, wrong = 0;
    for (size_t i = 0; i < g->grid.count; ++i) {
        cdl_vec3 p = g->grid.points[i];
        const double m = 1e-6;
        int in_small = ray_meets_box(p, to_light, cdl_vec3_make(-0.5 + m, -0.5 + m, m), cdl_vec3_make(0.5 - m, 0.5 - m, 1 - m));
        int in_large = ray_meets_box(p, to_light, cdl_vec3_make(-0.5 - m, -0.5 - m, -m), cdl_vec3_make(0.5 + m, 0.5 + m, 1 + m));
        if (in_small != in_large) {
            skipped++;
            continue;
        }
        double expected = in_small ? 0.0 : lit;
        shadowed += in_small;
        if (expected == 0.0 ? g->E[i] != 0.0 : fabs(g->E[i] - expected) > 1e-12 * expected) {
            if (wrong++ < 5) fprintf(stderr, "(%g, %g): E = %.17g, expected %.17g\n", p.x, p.y, g->E[i], expected);
        }
    }
    CHECK_MSG(wrong == 0, "%d floor points wrong", wrong);
    /* The box and its shadow: the hull of the unit footprint and the top
     * moved by (0.3, 0.2), 1 + 0.3 + 0.2 = 1.5 m^2, about 96 cells of
     * 0.125 m (give or take the cells along its outline). */
    CHECK_MSG(shadowed >= 80 && shadowed <= 112 && skipped < 10, "%d shadowed, %d skipped", shadowed, skipped);
    /* On the box itself: the top faces the light through nothing; the -x
     * face (the light comes from -x) gets E_n MF cos; the +x face is behind. */
    const double *F = sol.grids[1].E;
    CHECK_REL(F[0], lit, 1e-12);
    CHECK_REL(F[1], 80000.0 * 0.9 * cdl_vec3_dot(cdl_vec3_make(-1, 0, 0), to_light), 1e-12);
    CHECK(F[2] == 0.0);
    /* Exact with one shadow ray per point, never sampled. */
    for (size_t i = 0; i < g->grid.count; ++i) CHECK(g->E_stderr[i] == 0.0);
    CHECK(strstr(sol.plan_json, "exact, one shadow ray per point") != NULL);
    fixture_release(scene, &sol);
}

/* A uniform sky partly hidden: an upper-hemisphere sky of luminance L over a
 * point on the ground at distance a from a long wall of height h. The wall
 * (an infinitely long strip, from the point's plane up to angle atan(h / a))
 * takes the configuration factor F = (1 - a / sqrt(a^2 + h^2)) / 2 from the
 * sky (Hottel's crossed strings for a strip element; Modest, Radiative Heat
 * Transfer, ch. 4), so E = pi L (1 - F). The wall is 200 m long: the part
 * an infinite one would add beyond |y| = 100 m is a h^2 / (3 pi 100^3) ~
 * 1e-7 of the hemisphere, far below the sampling error. With the exact
 * route turned off the solver must sample here (exact minus sampled hidden
 * part) and agree within 4 standard errors. */
static void test_sky_behind_wall(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [1, -100, 0], \"u\": [0, 200, 0], "
        "\"v\": [0, 0, 1], \"reflectance\": 0}],"
        " \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 1000, \"hemisphere\": \"upper\"}],"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]},"
        " {\"p\": [-1, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [3, 0, 0], \"n\": [0, 0, 1]}]}],"
        " \"solver\": {\"method\": \"direct\", \"direct_samples\": 4096}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve_route(json, &scene, &sol, 1, 1)) return;
    const double a[2] = {1.0, 2.0}, h = 1.0;
    for (int i = 0; i < 2; ++i) {
        double F = 0.5 * (1.0 - a[i] / sqrt(a[i] * a[i] + h * h));
        double expected = CDL_PI * 1000.0 * (1.0 - F);
        double E = sol.grids[0].E[i], se = sol.grids[0].E_stderr[i];
        CHECK_MSG(se > 0.0 && se < 0.01 * expected, "point %d: stderr %g", i, se);
        CHECK_MSG(fabs(E - expected) <= 4.0 * se, "point %d: E = %g, expected %g +- %g", i, E, expected, 4.0 * se);
    }
    /* Behind the wall (facing up, the wall beside it): the same F at a = 2. */
    double F = 0.5 * (1.0 - 2.0 / sqrt(5.0));
    CHECK_MSG(fabs(sol.grids[0].E[2] - CDL_PI * 1000.0 * (1.0 - F)) <= 4.0 * sol.grids[0].E_stderr[2],
              "behind: E = %g +- %g", sol.grids[0].E[2], sol.grids[0].E_stderr[2]);
    CHECK(strstr(sol.plan_json, "sampled where partly hidden") != NULL);
    fixture_release(scene, &sol);
}

/* A goniometric luminaire whose IES file takes its TILT table from a
 * separate file (tests/data/photometric/ies_tilt_file.*: rotationally
 * symmetric, I(gamma = 0) = 300 cd, tilt factors 1, 0.95, 0.85, 0.7 at 0, 30,
 * 60, 90 degrees), installed tilted: the tilt factor at the installed tilt
 * (the angle of the turned nadir from -z), linear between table angles
 * (LM-63-2019, 5.4), multiplies the intensity, as do multiplier and
 * maintenance factor; flux_lm first rescales the table to that flux. Probes
 * on the turned nadir (gamma = 0), facing the luminaire: E = I / d^2, the
 * point model ("near_field": "never"; the file has a 0.5 x 0.5 m opening,
 * which "auto" would spread the light over within 3.5 m). */
static void test_goniometric_tilt_and_flux(void)
{
    const char *ies = CANDELA_SOURCE_DIR "/tests/data/photometric/ies_tilt_file.ies";
    cdl_photometry *ph = NULL;
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_error err;
    CHECK_OK(cdl_photometry_read_file(ies, &opt, &ph, &err), &err);
    if (!ph) return;
    double table_flux = cdl_photometry_flux(ph).lm;
    cdl_photometry_release(ph);
    char json[2][2048];
    /* 1: nadir turned 30 degrees towards +x, 2 m away, MF 0.8.
     * 2: 45 degrees about x turns the nadir towards +y; flux_lm and multiplier. */
    snprintf(json[0], sizeof json[0],
             "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 3],"
             " \"rotation\": [0, -30, 0], \"maintenance_factor\": 0.8, \"near_field\": \"never\"}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": ["
             " {\"p\": [1, 0, 1.2679491924311228], \"n\": [-0.5, 0, 0.8660254037844386]}]}],"
             " \"solver\": {\"method\": \"direct\"}}",
             ies);
    snprintf(json[1], sizeof json[1],
             "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 3],"
             " \"rotation\": [45, 0, 0], \"flux_lm\": 2400, \"multiplier\": 0.5, \"near_field\": \"never\"}],"
             " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": ["
             " {\"p\": [0, 1.4142135623730951, 1.5857864376269049], \"n\": [0, -0.70710678118654757, 0.70710678118654757]}]}],"
             " \"solver\": {\"method\": \"direct\"}}",
             ies);
    /* 300 cd x tilt factor 0.95 (at 30 degrees) x 0.8 at 2 m; then the table
     * rescaled to 2400 lm, tilt factor halfway between 0.95 and 0.85 (45
     * degrees), multiplier 0.5, at 2 m. */
    const double expected[2] = {300.0 * 0.95 * 0.8 / 4.0, 300.0 * (2400.0 / table_flux) * 0.9 * 0.5 / 4.0};
    for (int k = 0; k < 2; ++k) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json[k], &scene, &sol, 1)) return;
        CHECK_REL(sol.grids[0].E[0], expected[k], 1e-12);
        fixture_release(scene, &sol);
    }
}

/* An environment image without a Y channel: luminance is the Rec. 709 luma
 * 0.2126 R + 0.7152 G + 0.0722 B, times scale and maintenance factor
 * (DESIGN.md). A uniform RGB image is a uniform sphere of that luminance: pi
 * L on any plane, which the exact pixel sum gives to rounding (nothing
 * hides the sky: no samples, E_stderr 0). */
static void test_environment_rgb_scale(void)
{
    enum { W = 16, H = 8 };
    static float R[W * H], G[W * H], B[W * H];
    for (int i = 0; i < W * H; ++i) {
        R[i] = 1000.0f;
        G[i] = 2000.0f;
        B[i] = 500.0f;
    }
    cdl_exr_channel ch[3] = {{"R", R}, {"G", G}, {"B", B}};
    cdl_error err;
    CHECK_OK(cdl_exr_write(CANDELA_TEST_TMPDIR "/solve_rgb_sky.exr", W, H, ch, 3, NULL, 0, &err), &err);
    const char *json =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"file\": \"solve_rgb_sky.exr\", \"scale\": 2.5,"
        " \"maintenance_factor\": 0.6}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": ["
        " {\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [0, 0, 0], \"n\": [0.6, 0, -0.8]}]}],"
        " \"solver\": {\"method\": \"direct\", \"direct_samples\": 65536}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    double L = (0.2126 * 1000.0 + 0.7152 * 2000.0 + 0.0722 * 500.0) * 2.5 * 0.6;
    for (int i = 0; i < 2; ++i) {
        double E = sol.grids[0].E[i], se = sol.grids[0].E_stderr[i];
        /* The image keeps luminance in float: the luma and the maintenance
         * factor each round it by at most 2^-24 = 6e-8 relative. */
        CHECK_REL(E, CDL_PI * L, 2e-7);
        CHECK(se == 0.0);
    }
    fixture_release(scene, &sol);
}

/* Points where two surfaces meet are found and counted, the rest are not:
 * in a closed room (inward box) with a rect lying on the floor, the foot of
 * a wall (on the floor and in the wall's plane) and a ceiling corner are
 * edge points; a point on the floor, on a wall, and on the rect's corner
 * (the rect lies in the floor's own plane) are not. The sun outside the room
 * reaches none of the ordinary floor points. */
static void test_edge_points(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [4, 4, 3], "
        "\"inward\": true, \"reflectance\": 0.5}, {\"type\": \"rect\", \"origin\": [1, 1, 0], \"u\": [1, 0, 0], "
        "\"v\": [0, 1, 0], \"reflectance\": 0.3}], \"luminaires\": [{\"type\": \"directional\", "
        "\"direction\": [0.3, 0.2, -1], \"illuminance_lx\": 80000}], \"grids\": [{\"name\": \"p\", \"type\": "
        "\"points\", \"points\": [{\"p\": [2, 2, 0], \"n\": [0, 0, 1]}, {\"p\": [0, 2, 0], \"n\": [0, 0, 1]}, "
        "{\"p\": [0, 2, 1.5], \"n\": [1, 0, 0]}, {\"p\": [4, 4, 3], \"n\": [0, 0, -1]}, "
        "{\"p\": [1, 1, 0], \"n\": [0, 0, 1]}, {\"p\": [1e-3, 2, 0], \"n\": [0, 0, 1]}]}], "
        "\"solver\": {\"method\": \"direct\"}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    CHECK_MSG(g->edge_point_count == 2, "edge points: %zu, expected 2 (the wall foot and the ceiling corner)",
              g->edge_point_count);
    CHECK(g->first_edge_point == 1);
    /* closed room: the sun reaches no ordinary floor point, nor one 1 mm from the wall */
    CHECK(g->E[0] == 0.0);
    CHECK(g->E[4] == 0.0);
    CHECK(g->E[5] == 0.0);
    fixture_release(scene, &sol);
}

/* A small box far off under a uniform sky hides a little of it: too little
 * for a handful of samples to find (the exact route turned off: it would
 * find it). The estimate then equals the unhidden
 * pi L, and its error must still say what may be hidden: the hidden part is
 * the box's projected solid angle (the sum over the faces the point sees,
 * which tile its silhouette) times L, and the result must lie within 4
 * reported standard errors of pi L minus it, with a non-zero error. */
static void test_small_hidden_part(void)
{
    const double L = 1000.0;
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [4.8, -0.2, 0], \"max\": [5.2, 0.2, 0.4], "
        "\"reflectance\": 0}], \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 1000, "
        "\"hemisphere\": \"upper\"}], \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": "
        "[{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"direct\", \"direct_samples\": 16}}";
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve_route(json, &scene, &sol, 1, 1)) return;
    /* Faces the origin sees: only the near face x = 4.8 (the top z = 0.4 is
     * above the eye and faces away, the sides y = +-0.2 face away from y = 0). */
    cdl_vec3 face[4] = {cdl_vec3_make(4.8, -0.2, 0.0), cdl_vec3_make(4.8, 0.2, 0.0), cdl_vec3_make(4.8, 0.2, 0.4),
                        cdl_vec3_make(4.8, -0.2, 0.4)};
    double psa = fabs(cdl_projected_solid_angle_polygon(face, 4, cdl_vec3_make(0.0, 0.0, 1.0)));
    double expected = CDL_PI * L - L * psa;
    double E = sol.grids[0].E[0], se = sol.grids[0].E_stderr[0];
    CHECK_MSG(psa > 0.0 && psa < 1e-3 * CDL_PI, "hidden projected solid angle %g", psa);
    CHECK_MSG(se > 0.0, "a partly hidden sky reported with a zero error (E = %.9g, expected %.9g)", E, expected);
    CHECK_MSG(fabs(E - expected) <= 4.0 * se, "E = %.9g, expected %.9g +- %g", E, expected, 4.0 * se);
    CHECK(strstr(sol.plan_json, "sampled where partly hidden") != NULL);
    printf("small hidden part: E = %.9g +- %.3g lx, closed form %.9g lx\n", E, se, expected);
    fixture_release(scene, &sol);
}

/* Points on the inner face of an emitting inward sphere (an integrating
 * sphere's wall): a point on a surface belongs to the side its normal
 * faces, so facing inward it sees the glowing wall over its whole
 * hemisphere, E = pi L (the limit from inside, whatever the tilt), and
 * facing outward nothing. None of them is an edge point: the sphere is the
 * one surface they lie on, and the centre lies on none. */
static void test_points_on_emitting_sphere(void)
{
    const double L = 100.0, R = 1.5;
    char json[2048];
    /* a point on the surface in a general direction, by its unit vector */
    cdl_vec3 u = cdl_vec3_normalize(cdl_vec3_make(0.3, -0.5, 0.7));
    cdl_vec3 q = cdl_vec3_add(cdl_vec3_make(1, 2, 3), cdl_vec3_scale(u, R));
    cdl_vec3 tilted = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_neg(u), cdl_vec3_make(0.6, 0.0, 0.0)));
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [1, 2, 3], \"radius\": %.17g, "
             "\"inward\": true, \"reflectance\": 0, \"luminance_cd_m2\": %.17g}], \"grids\": [{\"name\": \"p\", "
             "\"type\": \"points\", \"points\": [{\"p\": [1, 2, 3], \"n\": [0, 0, 1]}, "
             "{\"p\": [1, 2, %.17g], \"n\": [0, 0, 1]}, {\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}, "
             "{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}, {\"p\": [1, 2, %.17g], \"n\": [0, 0, -1]}]}], "
             "\"solver\": {\"method\": \"direct\"}}",
             R, L, 3.0 - R, q.x, q.y, q.z, -u.x, -u.y, -u.z, q.x, q.y, q.z, tilted.x, tilted.y, tilted.z, 3.0 - R);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 1)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    for (int i = 0; i < 4; ++i) CHECK_MSG(fabs(g->E[i] - CDL_PI * L) <= 1e-12 * CDL_PI * L, "point %d: %.17g", i, g->E[i]);
    CHECK_MSG(g->E[4] == 0.0, "facing out: %g", g->E[4]);
    CHECK_MSG(g->edge_point_count == 0, "edge points: %zu", g->edge_point_count);
    fixture_release(scene, &sol);
}

int main(void)
{
    test_inverse_square_cosine();
    test_spot_falloff();
    test_goniometric_rotated();
    test_lambertian_emitters();
    test_uniform_sky();
    test_box_shadow();
    test_half_hidden_emitter();
    test_scale_invariance();
    test_thread_determinism();
    test_ambient_occlusion();
    test_method_choices();
    test_image_environment();
    test_plan_no_rays();
    test_emitting_surfaces();
    test_directional_shadow();
    test_sky_behind_wall();
    test_goniometric_tilt_and_flux();
    test_environment_rgb_scale();
    test_edge_points();
    test_small_hidden_part();
    test_points_on_emitting_sphere();
    return check_finish();
}
