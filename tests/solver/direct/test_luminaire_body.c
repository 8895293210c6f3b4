/* Luminaire bodies (solver/scene/scene_bodies.h) against closed forms.
 *  - A point source 1 m above a pendant's Lambertian rectangle opening
 *    (1.2 x 0.3 m, near field "always"), probes on the floor: under the
 *    pendant the probe gets only the pendant's own light (Lambert's contour
 *    integral), the point source's shadow exact; beside it both; with
 *    "body": false both everywhere.
 *  - A luminous ceiling panel over the same pendant: the panel past the
 *    rectangle body stays exact (the visible polygon, stated error 0), the
 *    panel's factor less the body's; with "body": false all of it. Over a
 *    disk's curved body it is sampled, within its stated error.
 *  - Flux unchanged: a luminous box (IES luminous sides) radiating 100 cd
 *    in every direction as a point from its centre, inside its own body,
 *    probes on a sphere of 2 m about it: I / d^2 at every one (the body
 *    hides none of its own light); an EULUMDAT housing (1.1 x 0.4 x 0.1 m,
 *    CIE 190's example file) gives every probe around it the same light
 *    with and without its body.
 *  - The body's reflectance in interreflection: a dark luminous box (its
 *    table all 0 cd) under a
 *    uniform sky of luminance L all round; a probe below its bottom face
 *    sees the sky and that face, whose radiance is rho L (it sees the lower
 *    sky alone), so E = pi L - (1 - rho) L Omega_p, Omega_p the face's
 *    projected solid angle: rho 1 (the furnace: pi L), 0.5 and 0 by paths,
 *    within four stated sigmas.
 */
// ctest-timeout: 300
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "polygon_factor.h"
#include "radiometry/constants.h"
#include "solver/solve_fixture.h"

#define I0 1000.0
#define DATA CANDELA_SOURCE_DIR "/tests/data/photometric/"

static char folder[512];

/* LM-63-2002, one plane, every degree of gamma: I0 cos(gamma) below the
 * horizontal, dark above; opening W (across, y) x L (along, x), flat. */
static int write_lambert_rect(const char *path, double W, double L)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] body\nTILT=NONE\n1 -1 1 181 1 1 2 %.17g %.17g 0\n1 1 0\n", W, L);
    for (int g = 0; g <= 180; ++g) fprintf(f, "%d ", g);
    fprintf(f, "\n0\n");
    for (int g = 0; g <= 180; ++g) fprintf(f, "%.17g ", g < 90 ? I0 * cos(g * CDL_DEG_TO_RAD) : 0.0);
    return fprintf(f, "\n") > 0 && fclose(f) == 0;
}

/* A luminous box W x L x H (IES "rectangular with luminous sides"), I cd
 * in every direction. */
static int write_uniform_box(const char *path, double W, double L, double H, double I)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] box\nTILT=NONE\n1 -1 1 3 1 1 2 %g %g %g\n1 1 0\n0 90 180\n0\n%g %g %g\n", W,
            L, H, I, I, I);
    return fclose(f) == 0;
}

/* The rectangle [x0, x1] x [y0, y1] at height z, as corners. */
static void rect_corners(double x0, double x1, double y0, double y1, double z, cdl_vec3 c[4])
{
    c[0] = cdl_vec3_make(x0, y0, z);
    c[1] = cdl_vec3_make(x1, y0, z);
    c[2] = cdl_vec3_make(x1, y1, z);
    c[3] = cdl_vec3_make(x0, y1, z);
}

#define PROBES 4
/* Floor probes: under the pendant (the point source at (0, 0, 3) hidden by
 * it: the line to the source crosses z = 2 inside the 1.2 x 0.3 m opening)
 * and beside it (the line passes outside). */
static const double probe_xy[PROBES][2] = {{0.0, 0.0}, {0.3, 0.1}, {2.0, 0.0}, {0.0, 0.6}};
static const int probe_hidden[PROBES] = {1, 1, 0, 0};

static void probes_json(char *out, size_t size)
{
    size_t used = (size_t)snprintf(out, size, "[");
    for (int i = 0; i < PROBES; ++i)
        used += (size_t)snprintf(out + used, size - used, "%s{\"p\": [%g, %g, 0], \"n\": [0, 0, 1]}", i ? ", " : "",
                                 probe_xy[i][0], probe_xy[i][1]);
    snprintf(out + used, size - used, "]");
}

/* The pendant's own light at a floor probe: Lambert's contour integral of
 * its opening (luminance I0 / A) 2 m up. */
static double pendant_E(int i)
{
    cdl_vec3 c[4];
    rect_corners(-0.6, 0.6, -0.15, 0.15, 2.0, c);
    return lambert_polygon(c, 4, I0 / 0.36, cdl_vec3_make(probe_xy[i][0], probe_xy[i][1], 0.0), cdl_vec3_make(0, 0, 1));
}

/* Solve `other` (a luminaire) with the pendant 2 m up, spread over its
 * opening, with or without its body, at the floor probes (direct light). */
static int solve_with_pendant(const char *other, const char *ies, int body, cdl_scene **scene, cdl_solution *sol)
{
    char probes[1024], json[4096];
    probes_json(probes, sizeof probes);
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [%s,"
             "{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 2], \"near_field\": \"always\"%s}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"points\": %s}],"
             " \"solver\": {\"method\": \"direct\"}}",
             other, ies, body ? "" : ", \"body\": false", probes);
    return fixture_solve(json, scene, sol, 2);
}

static void test_point_shadow(const char *ies)
{
    const double Ip = 500.0;
    char point_source[200];
    snprintf(point_source, sizeof point_source,
             "{\"type\": \"point\", \"position\": [0, 0, 3], \"intensity_cd\": %g}", Ip);
    for (int body = 0; body < 2; ++body) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_with_pendant(point_source, ies, body, &scene, &sol)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        for (int i = 0; i < PROBES; ++i) {
            cdl_vec3 p = cdl_vec3_make(probe_xy[i][0], probe_xy[i][1], 0.0);
            double d2 = cdl_vec3_dot(cdl_vec3_sub(cdl_vec3_make(0, 0, 3), p), cdl_vec3_sub(cdl_vec3_make(0, 0, 3), p));
            /* the point source: I cos / d^2, cos = 3 / d; hidden behind the body when it has one */
            double point = body && probe_hidden[i] ? 0.0 : Ip * 3.0 / (d2 * sqrt(d2));
            double want = point + pendant_E(i);
            /* both exact: the closed forms agree to rounding (1e-9 covers
             * the contour integrals' atan2 sums) */
            CHECK_MSG(g->E_stderr[i] == 0.0 && fabs(g->E[i] - want) <= 1e-9 * want,
                      "body %d, probe (%g, %g): %.12g lx +- %.3g, expected %.12g (point %.6g, pendant %.6g)", body,
                      probe_xy[i][0], probe_xy[i][1], g->E[i], g->E_stderr[i], want, point, pendant_E(i));
        }
        /* the plan names the body and its route */
        CHECK(body ? strstr(sol.plan_json, "rectangle 1.2 x 0.3 m (the luminous opening)") != NULL
                   : strstr(sol.plan_json, "\"body\":\t\"none: \\\"body\\\": false\"") != NULL ||
                         strstr(sol.plan_json, "none: \\\"body\\\": false") != NULL);
        if (body) CHECK(strstr(sol.plan_json, "planar: other lights past it stay exact") != NULL);
        fixture_release(scene, &sol);
    }
}

/* A Lambertian panel 3 x 3 m at z = 3 facing down (luminance Lp) over the
 * pendant: each probe under the pendant sees the panel less the body's
 * central projection on it, which lies inside the panel, so the hidden
 * part's factor is the body rectangle's own. */
static void test_panel_past_body(const char *ies)
{
    const double Lp = 2000.0;
    char panel_light[300];
    snprintf(panel_light, sizeof panel_light,
             "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [-1.5, -1.5, 3], \"u\": [0, 3, 0],"
             " \"v\": [3, 0, 0]}, \"luminance_cd_m2\": %g}",
             Lp);
    cdl_vec3 panel[4], body_rect[4];
    rect_corners(-1.5, 1.5, -1.5, 1.5, 3.0, panel);
    rect_corners(-0.6, 0.6, -0.15, 0.15, 2.0, body_rect);
    for (int body = 0; body < 2; ++body) {
        cdl_scene *scene;
        cdl_solution sol;
        if (!solve_with_pendant(panel_light, ies, body, &scene, &sol)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        for (int i = 0; i < 2; ++i) { /* the probes under the pendant */
            cdl_vec3 p = cdl_vec3_make(probe_xy[i][0], probe_xy[i][1], 0.0), n = cdl_vec3_make(0, 0, 1);
            double hidden = body ? lambert_polygon(body_rect, 4, Lp, p, n) : 0.0;
            double want = lambert_polygon(panel, 4, Lp, p, n) - hidden + pendant_E(i);
            /* exact: the visible polygon's contour integral (1e-9: rounding) */
            CHECK_MSG(g->E_stderr[i] == 0.0 && fabs(g->E[i] - want) <= 1e-9 * want,
                      "panel past the body %d, probe (%g, %g): %.12g lx +- %.3g, expected %.12g", body,
                      probe_xy[i][0], probe_xy[i][1], g->E[i], g->E_stderr[i], want);
        }
        if (body) CHECK(strstr(sol.plan_json, "exact: visible polygon past up to 2 occluders") != NULL);
        fixture_release(scene, &sol);
    }
}

/* E on a plane parallel to a Lambertian disk (radius r, luminance L) at
 * depth h and lateral offset a: pi L F, F the configuration factor of a
 * parallel disk to a differential element (Siegel and Howell B-13). */
static double disk_E(double L, double r, double h, double a)
{
    double s = h * h + a * a + r * r;
    return CDL_PI * L * 0.5 * (1.0 - (h * h + a * a - r * r) / sqrt(s * s - 4.0 * a * a * r * r));
}

/* A curved body: the same panel over a Lambertian disk 0.6 m across (its
 * body a 224-sided fan, as every disk in the ray scene). Light past a
 * curved body is sampled: each probe within four stated sigmas of the
 * panel less the fan's factor (Lambert's contour integral of the polygon
 * the rays see) plus the disk's own light (its closed form), the stated
 * error not 0, and the plan says the body is curved. */
static void test_panel_past_disk(void)
{
    char ies[600], json[4096];
    snprintf(ies, sizeof ies, "%s/disk.ies", folder);
    FILE *f = fopen(ies, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] disk\nTILT=NONE\n1 -1 1 181 1 1 2 -0.6 -0.6 0\n1 1 0\n");
    for (int g = 0; g <= 180; ++g) fprintf(f, "%d ", g);
    fprintf(f, "\n0\n");
    for (int g = 0; g <= 180; ++g) fprintf(f, "%.17g ", g < 90 ? I0 * cos(g * CDL_DEG_TO_RAD) : 0.0);
    CHECK(fprintf(f, "\n") > 0 && fclose(f) == 0);
    const double Lp = 2000.0, r = 0.3;
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": ["
             "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [-1.5, -1.5, 3], \"u\": [0, 3, 0],"
             " \"v\": [3, 0, 0]}, \"luminance_cd_m2\": %g},"
             "{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 2], \"near_field\": \"always\"}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"points\": ["
             "{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}, {\"p\": [0.1, 0, 0], \"n\": [0, 0, 1]}]}],"
             " \"solver\": {\"method\": \"direct\", \"target_error\": 0.001}}",
             Lp, ies);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    cdl_vec3 panel[4], fan[224];
    rect_corners(-1.5, 1.5, -1.5, 1.5, 3.0, panel);
    for (int k = 0; k < 224; ++k)
        fan[k] = cdl_vec3_make(r * cos(CDL_TWO_PI * k / 224), r * sin(CDL_TWO_PI * k / 224), 2.0);
    const cdl_grid_solution *g = &sol.grids[0];
    for (int i = 0; i < 2; ++i) {
        double a = 0.1 * i;
        cdl_vec3 p = cdl_vec3_make(a, 0, 0), n = cdl_vec3_make(0, 0, 1);
        double want = lambert_polygon(panel, 4, Lp, p, n) - lambert_polygon(fan, 224, Lp, p, n) +
                      disk_E(I0 / (CDL_PI * r * r), r, 2.0, a);
        /* sampled: four stated sigmas, and rounding */
        CHECK_MSG(g->E_stderr[i] > 0.0 && fabs(g->E[i] - want) <= 4.0 * g->E_stderr[i] + 1e-9 * want,
                  "panel past a disk body, probe %d: %.9g lx +- %.3g, expected %.9g", i, g->E[i], g->E_stderr[i], want);
    }
    CHECK(strstr(sol.plan_json, "disk 0.6 x 0.6 m (the luminous opening)") != NULL);
    CHECK(strstr(sol.plan_json, "curved: other lights past it are sampled") != NULL);
    fixture_release(scene, &sol);
}

/* Probes on the sphere of radius R about c, facing its centre: a
 * Fibonacci lattice of n directions. */
static void sphere_probes(char *out, size_t size, cdl_vec3 c, double R, int n)
{
    size_t used = (size_t)snprintf(out, size, "[");
    for (int k = 0; k < n; ++k) {
        double z = 1.0 - (2.0 * k + 1.0) / n, r = sqrt(1.0 - z * z), phi = k * CDL_PI * (3.0 - sqrt(5.0));
        cdl_vec3 d = cdl_vec3_make(r * cos(phi), r * sin(phi), z);
        used += (size_t)snprintf(out + used, size - used, "%s{\"p\": [%.17g, %.17g, %.17g], \"n\": [%.17g, %.17g, %.17g]}",
                                 k ? ", " : "", c.x + R * d.x, c.y + R * d.y, c.z + R * d.z, -d.x, -d.y, -d.z);
    }
    snprintf(out + used, size - used, "]");
}

/* A black plate 5 cm square at the corner of the box around a sphere of
 * probes (centre c, radius R): outside the sphere, so that it hides no
 * probe from the centre, but inside the box, so that the probes' light is
 * traced with shadow rays (nothing in the box: no rays at all). */
static void corner_plate(char *out, size_t size, cdl_vec3 c, double R)
{
    snprintf(out, size,
             "\"surfaces\": [{\"type\": \"rect\", \"origin\": [%.17g, %.17g, %.17g], \"u\": [0.05, 0, 0],"
             " \"v\": [0, 0.05, 0], \"reflectance\": 0}],",
             c.x + 0.95 * R, c.y + 0.95 * R, c.z + 0.95 * R);
}

/* Its own light is never blocked: a luminous box (its body the box, the
 * point model's centre inside it) at 100 cd all round, probes 2 m away in
 * every direction: I / R^2 = 25 lx at each, each by a shadow ray that
 * passes the body. */
static void test_own_light_passes(void)
{
    char ies[600], probes[40000], json[44000], plate[400];
    snprintf(ies, sizeof ies, "%s/uniform_box.ies", folder);
    corner_plate(plate, sizeof plate, cdl_vec3_make(1, 2, 3), 2.0);
    CHECK(write_uniform_box(ies, 0.2, 0.6, 0.1, 100.0));
    const int n = 200;
    sphere_probes(probes, sizeof probes, cdl_vec3_make(1, 2, 3), 2.0, n);
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [1, 2, 3],"
             " \"near_field\": \"never\", \"rotation\": [10, 20, 30], \"body\": {\"reflectance\": 0.7}}], %s"
             " \"grids\": [{\"name\": \"sphere\", \"type\": \"points\", \"points\": %s}],"
             " \"solver\": {\"method\": \"direct\"}}",
             ies, plate, probes);
    cdl_scene *scene;
    cdl_solution sol;
    if (!fixture_solve(json, &scene, &sol, 2)) return;
    const cdl_grid_solution *g = &sol.grids[0];
    int bad = 0;
    for (int i = 0; i < n; ++i)
        /* the point model: exact, I / R^2 (rounding only) */
        if (!(fabs(g->E[i] - 25.0) <= 1e-12 * 25.0)) bad++;
    CHECK_MSG(bad == 0, "%d of %d probes about a luminous box do not get its 25 lx (first %.9g)", bad, n, g->E[0]);
    CHECK(strstr(sol.plan_json, "box 0.6 x 0.2 x 0.1 m (the luminous opening)") != NULL);
    CHECK(sol.rays >= (uint64_t)n); /* traced past the body, not spared by the plan */
    fixture_release(scene, &sol);
}

/* The EULUMDAT housing of CIE 190's example (1.1 x 0.4 x 0.1 m above its
 * 1.0 x 0.316 m luminous area): every probe on a sphere about it, spread
 * over its opening or as a point, gets the same light with and without
 * the body, bit for bit (nothing of its own light is blocked, nothing
 * else lights the probes). */
static void test_housing_flux(void)
{
    char probes[40000], json[44000], plate[400];
    const int n = 120;
    sphere_probes(probes, sizeof probes, cdl_vec3_make(0, 0, 2), 1.5, n);
    corner_plate(plate, sizeof plate, cdl_vec3_make(0, 0, 2), 1.5);
    for (int near = 0; near < 2; ++near) {
        double E[2][120];
        for (int body = 0; body < 2; ++body) {
            snprintf(json, sizeof json,
                     "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"" DATA
                     "cie190_example.ldt\", \"position\": [0, 0, 2], \"near_field\": \"%s\", \"body\": %s}], %s"
                     " \"grids\": [{\"name\": \"sphere\", \"type\": \"points\", \"points\": %s}],"
                     " \"solver\": {\"method\": \"direct\", \"quality\": \"draft\"}}",
                     near ? "always" : "never", body ? "true" : "false", plate, probes);
            cdl_scene *scene;
            cdl_solution sol;
            if (!fixture_solve(json, &scene, &sol, 1)) return;
            for (int i = 0; i < n; ++i) E[body][i] = sol.grids[0].E[i];
            if (body) {
                CHECK(strstr(sol.plan_json, "box 0.4 x 1.1 x 0.1 m (the luminaire's size (EULUMDAT))") != NULL);
                CHECK(strstr(sol.plan_json, "\"reflectance\":0.5") != NULL ||
                      strstr(sol.plan_json, "\"reflectance\":\t0.5") != NULL);
            }
            fixture_release(scene, &sol);
        }
        int differ = 0, lit = 0;
        for (int i = 0; i < n; ++i) {
            differ += E[0][i] != E[1][i];
            lit += E[1][i] > 0.0;
        }
        CHECK_MSG(differ == 0, "near field %d: %d of %d probes about the housing differ with its body", near, differ,
                  n);
        CHECK(lit > n / 4); /* the probes are lit, above and below */
    }
}

/* A dark luminous box (a table of zeros) 0.6 x 0.2 x 0.1 m centred 2 m up,
 * under a uniform sky of 1000 cd/m2 all round; probes 0.1 m below its
 * bottom face (z = 1.95), within its outline so that no side is seen. */
static void test_body_reflects(void)
{
    char ies[600], json[4096];
    snprintf(ies, sizeof ies, "%s/dark_box.ies", folder);
    CHECK(write_uniform_box(ies, 0.2, 0.6, 0.1, 0.0));
    const double L = 1000.0, rhos[3] = {1.0, 0.5, 0.0};
    const double probe[3][2] = {{0.0, 0.0}, {0.2, 0.05}, {-0.25, -0.08}};
    cdl_vec3 bottom[4];
    rect_corners(-0.3, 0.3, -0.1, 0.1, 1.95, bottom);
    for (int r = 0; r < 3; ++r) {
        snprintf(json, sizeof json,
                 "{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": %g},"
                 " {\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 2],"
                 " \"body\": {\"reflectance\": %g}}],"
                 " \"grids\": [{\"name\": \"below\", \"type\": \"points\", \"points\": ["
                 "{\"p\": [%g, %g, 1.85], \"n\": [0, 0, 1]}, {\"p\": [%g, %g, 1.85], \"n\": [0, 0, 1]},"
                 " {\"p\": [%g, %g, 1.85], \"n\": [0, 0, 1]}]}],"
                 " \"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.002, \"seed\": 7}}",
                 L, ies, rhos[r], probe[0][0], probe[0][1], probe[1][0], probe[1][1], probe[2][0], probe[2][1]);
        cdl_scene *scene;
        cdl_solution sol;
        if (!fixture_solve(json, &scene, &sol, 2)) return;
        const cdl_grid_solution *g = &sol.grids[0];
        for (int i = 0; i < 3; ++i) {
            cdl_vec3 p = cdl_vec3_make(probe[i][0], probe[i][1], 1.85);
            double face = lambert_polygon(bottom, 4, L, p, cdl_vec3_make(0, 0, 1)); /* L Omega_p */
            double want = CDL_PI * L - (1.0 - rhos[r]) * face;
            /* four stated sigmas (calibrated estimates: a false alarm
             * about once in 16 000 checks) and rounding */
            CHECK_MSG(fabs(g->E[i] - want) <= 4.0 * g->E_stderr[i] + 1e-9 * want,
                      "rho %g, probe (%g, %g): %.7g lx +- %.3g, expected %.7g (the face alone hides %.5g)", rhos[r],
                      probe[i][0], probe[i][1], g->E[i], g->E_stderr[i], want, face);
            /* the face hides a large part: a body left out would be far off */
            CHECK(face > 0.3 * CDL_PI * L);
        }
        fixture_release(scene, &sol);
    }
}

int main(void)
{
    CHECK(fixture_folder("luminaire_body", folder, sizeof folder));
    char ies[600];
    snprintf(ies, sizeof ies, "%s/pendant.ies", folder);
    CHECK(write_lambert_rect(ies, 0.3, 1.2));
    test_point_shadow(ies);
    test_panel_past_body(ies);
    test_panel_past_disk();
    test_own_light_passes();
    test_housing_flux();
    test_body_reflects();
    return check_finish();
}
