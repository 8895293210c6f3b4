/* Daylight coefficients (solver/daylight/daylight_coefficients.h) against
 * closed forms:
 *  - a point with nothing around: C_k is patch k's projected solid angle,
 *    exactly (the whole hemisphere route), for a horizontal and a tilted
 *    normal; the coefficients sum to pi (a uniform sky of 1 cd/m^2 gives
 *    pi lx);
 *  - a point on the floor of a black room under a square skylight (a box
 *    with its top face open): the coefficients are exact (visible polygon),
 *    their sum is the skylight's projected solid angle by Lambert's
 *    formula, and each patch's share is the skylight's part in it (the
 *    same polygon given to cdl_reinhart_add_polygon here);
 *  - the same room with glass in the skylight (transmittance 0.8): the
 *    skylight's patches weighed by the pane's mean transmittance, the
 *    uniform sky's E within 1e-3 of L int_window T(theta) cos dw,
 *    integrated here with the pane's own formula (radiometry/glass.h) by a
 *    2-D midpoint rule;
 *  - a point facing down over a grey square floor (rho 0.5) in the open:
 *    under a uniform sky of 1 cd/m^2 the floor is lit by pi and shines
 *    rho L; the point gets rho Omega_p(floor) from it and the rest of its
 *    lower hemisphere from the ground patch, pi - Omega_p(floor); a sun at
 *    altitude a lights the floor with sin a, and the point gets
 *    rho sin(a) Omega_p(floor) / pi per lx of direct normal illuminance;
 *    both within 4 stated sigmas (the ground patch part is exact);
 *  - the direct sun: max(0, n.s) in the open, 0 under the roof, T(theta)
 *    cos theta through the glass;
 *  - refusals: a scene with a luminaire or an emitting surface.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "radiometry/glass.h"
#include "solver/daylight/daylight_coefficients.h"
#include "solver/solve.h"

static int load(const char *json, cdl_scene **scene, cdl_daylight_scene *ds)
{
    cdl_error err;
    cdl_error_clear(&err);
    *scene = NULL;
    memset(ds, 0, sizeof *ds);
    if (cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/annual.json", scene, &err) != CDL_OK ||
        cdl_daylight_scene_build(*scene, ds, &err) != CDL_OK) {
        fprintf(stderr, "%s\n", err.message);
        CHECK(0);
        return 0;
    }
    return 1;
}

static void release(cdl_scene *scene, cdl_daylight_scene *ds)
{
    cdl_daylight_scene_release(ds);
    cdl_scene_release(scene);
}

static cdl_daylight_coefficient_options options(const cdl_reinhart_patches *p, const cdl_vec3 *suns, size_t count,
                                                double target)
{
    cdl_daylight_coefficient_options o = {.patches = p, .suns = suns, .sun_count = count, .target = target,
                                          .seed = 1, .threads = 2, .max_paths = 1 << 20};
    return o;
}

/* Grid 0's coefficients over the patches of subdivision mf (up +z, north +y). */
static void coefficients(const cdl_daylight_scene *ds, cdl_reinhart_patches *p, int mf, const cdl_vec3 *suns,
                         size_t sun_count, double target, cdl_daylight_grid_coefficients *c)
{
    cdl_error err;
    memset(c, 0, sizeof *c);
    CHECK_OK(cdl_reinhart_init(p, mf, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 1, 0), &err), &err);
    cdl_daylight_coefficient_options o = options(p, suns, sun_count, target);
    CHECK_OK(cdl_daylight_coefficients_compute(ds, 0, &o, c, &err), &err);
}

static double row_sum(const cdl_daylight_grid_coefficients *c, size_t i)
{
    double s = 0.0;
    for (size_t k = 0; k < c->patches; ++k) s += c->sky[i * c->patches + k];
    return s;
}

static void test_open(void)
{
    const char *json = "{\"version\": 1, \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": ["
                       "{\"p\": [0,0,0], \"n\": [0,0,1]}, {\"p\": [1,2,3], \"n\": [0.6,0,0.8]}]}]}";
    cdl_scene *scene;
    cdl_daylight_scene ds;
    if (!load(json, &scene, &ds)) return;
    cdl_reinhart_patches p;
    cdl_daylight_grid_coefficients c;
    coefficients(&ds, &p, 2, NULL, 0, 0.005, &c);
    if (c.sky) {
        const cdl_vec3 n[2] = {cdl_vec3_make(0, 0, 1), cdl_vec3_make(0.6, 0, 0.8)};
        for (size_t i = 0; i < 2; ++i) {
            double worst = 0.0;
            for (int k = 0; k < p.count; ++k)
                worst = fmax(worst, fabs(c.sky[i * c.patches + k] - cdl_reinhart_projected_solid_angle(&p, k, n[i])));
            /* stored as float: 6e-8 relative of the largest coefficient (0.04 sr) */
            CHECK_MSG(worst < 1e-8, "point %zu: worst %.3g", i, worst);
            CHECK_REL(row_sum(&c, i), CDL_PI, 1e-6);
            CHECK(c.sky_rel_stderr[i] == 0.0);
        }
        CHECK(c.routes.exact == 2);
    }
    cdl_daylight_coefficients_release(&c);
    /* the direct sun in the open: the cosine */
    float sun[2];
    cdl_vec3 s = cdl_vec3_normalize(cdl_vec3_make(0.3, -0.4, 0.5));
    cdl_daylight_direct_sun(&ds, 0, s, sun);
    CHECK_REL(sun[0], s.z, 1e-7);
    CHECK_REL(sun[1], 0.6 * s.x + 0.8 * s.z, 1e-6);
    release(scene, &ds);
}

/* A 4 x 4 x 3 m black room (reflectance 0) open at the top (a skylight of
 * the whole ceiling), or with a pane in it, one point on the floor. */
static void skylight_scene(char *json, size_t size, int glass)
{
    snprintf(json, size,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], "
             "\"inward\": true, \"reflectance\": 0, \"open\": [\"+z\"]}%s],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"points\", \"points\": [{\"p\": [1.3,2.1,0], \"n\": "
             "[0,0,1]}]}], \"solver\": {\"target_error\": 0.004}}",
             glass ? ", {\"type\": \"rect\", \"origin\": [0,0,3], \"u\": [4,0,0], \"v\": [0,4,0], \"transmittance\": 0.8}"
                   : "");
}

static void test_skylight(void)
{
    char json[1024];
    skylight_scene(json, sizeof json, 0);
    cdl_scene *scene;
    cdl_daylight_scene ds;
    if (!load(json, &scene, &ds)) return;
    cdl_reinhart_patches p;
    cdl_daylight_grid_coefficients c;
    cdl_error err;
    coefficients(&ds, &p, 1, NULL, 0, 0.005, &c);
    cdl_vec3 pt = cdl_vec3_make(1.3, 2.1, 0.0), n = cdl_vec3_make(0, 0, 1);
    cdl_vec3 window[4] = {{-1.3, -2.1, 3.0}, {2.7, -2.1, 3.0}, {2.7, 1.9, 3.0}, {-1.3, 1.9, 3.0}};
    double lambert = fabs(cdl_projected_solid_angle_polygon(window, 4, n)); /* either orientation */
    double want[200] = {0};
    CHECK(cdl_reinhart_add_polygon(&p, window, 4, n, 1.0, want));
    if (c.sky) {
        CHECK(c.routes.exact == 1);
        /* the same closed forms, stored as float */
        CHECK_REL(row_sum(&c, 0), lambert, 1e-6);
        double worst = 0.0;
        for (int k = 0; k < p.count; ++k) worst = fmax(worst, fabs(c.sky[k] - want[k]));
        CHECK_MSG(worst < 1e-7, "worst %.3g", worst);
    }
    cdl_daylight_coefficients_release(&c);
    /* the direct sun: through the opening, or onto the wall */
    float sun;
    cdl_vec3 high = cdl_vec3_normalize(cdl_vec3_make(0.1, 0.1, 1.0)), low = cdl_vec3_normalize(cdl_vec3_make(1, 0, 0.2));
    cdl_daylight_direct_sun(&ds, 0, high, &sun);
    CHECK_REL(sun, high.z, 1e-7);
    cdl_daylight_direct_sun(&ds, 0, low, &sun);
    CHECK(sun == 0.0f);
    release(scene, &ds);
    (void)pt;

    /* glass in the skylight: sampled through the pane */
    skylight_scene(json, sizeof json, 1);
    if (!load(json, &scene, &ds)) return;
    coefficients(&ds, &p, 1, NULL, 0, 0.005, &c);
    cdl_glass pane;
    CHECK_OK(cdl_glass_from_transmittance(0.8, &pane, &err), &err);
    /* int over the window of T(theta) cos(theta) dw, dw = cos(theta) dA / d^2:
     * midpoint rule on 800 x 800 cells (error O(h^2) of a smooth integrand, 1e-6) */
    double integral = 0.0;
    const int m = 800;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            double x = -1.3 + 4.0 * (i + 0.5) / m, y = -2.1 + 4.0 * (j + 0.5) / m, d2 = x * x + y * y + 9.0;
            double ct = 3.0 / sqrt(d2);
            integral += cdl_glass_transmittance(&pane, ct) * ct * ct / d2 * (16.0 / (m * m));
        }
    if (c.sky) {
        double E = row_sum(&c, 0);
        CHECK(c.routes.through_glass == 1 && c.routes.exact == 0);
        /* each patch's exact part times the panes' mean transmittance over it
         * from 1024 directions: T varies by 10 % over the window, its mean
         * per patch to a few 1e-4 (measured 9e-5 of the whole) */
        CHECK_MSG(fabs(E - integral) <= 1e-3 * integral, "through glass: %.6f, expected %.6f", E, integral);
        CHECK(c.sky_rel_stderr[0] == 0.0); /* a black room: nothing sampled */
        fprintf(stderr, "skylight through glass: %.6f sr, expected %.6f (%+.2g)\n", E, integral, E / integral - 1.0);
    }
    cdl_daylight_coefficients_release(&c);
    cdl_daylight_direct_sun(&ds, 0, high, &sun);
    CHECK_REL(sun, high.z * cdl_glass_transmittance(&pane, high.z), 1e-6);
    release(scene, &ds);
}

static void test_floor(void)
{
    /* a 20 x 20 m floor, a point 1 m above its middle facing down */
    const char *json = "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-10,-10,0], \"u\": [20,0,0], "
                       "\"v\": [0,20,0], \"reflectance\": 0.5}],"
                       " \"grids\": [{\"name\": \"down\", \"type\": \"points\", \"points\": [{\"p\": [0.5,0.3,1], "
                       "\"n\": [0,0,-1]}]}]}";
    cdl_scene *scene;
    cdl_daylight_scene ds;
    if (!load(json, &scene, &ds)) return;
    cdl_reinhart_patches p;
    cdl_error err;
    CHECK_OK(cdl_reinhart_init(&p, 1, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 1, 0), &err), &err);
    double alt = 40.0 * CDL_DEG_TO_RAD;
    cdl_vec3 suns[2] = {cdl_reinhart_direction(&p, alt, 2.0), cdl_reinhart_direction(&p, 0.5 * alt, -1.0)};
    cdl_daylight_coefficient_options o = options(&p, suns, 2, 0.005);
    cdl_daylight_grid_coefficients c;
    CHECK_OK(cdl_daylight_coefficients_compute(&ds, 0, &o, &c, &err), &err);
    cdl_vec3 floor[4] = {{-10.5, -10.3, -1}, {9.5, -10.3, -1}, {9.5, 9.7, -1}, {-10.5, 9.7, -1}};
    double omega = fabs(cdl_projected_solid_angle_polygon(floor, 4, cdl_vec3_make(0, 0, -1)));
    if (c.sky) {
        double E = row_sum(&c, 0), sigma = c.sky_rel_stderr[0] * E, want = 0.5 * omega + (CDL_PI - omega);
        CHECK_MSG(fabs(E - want) <= 4.0 * sigma + 1e-6 * want, "uniform sky: %.6f +- %.2g, expected %.6f", E, sigma,
                  want);
        for (int s = 0; s < 2; ++s) {
            double D = c.sun[s], sd = c.sun_rel_stderr[0] * (c.sun[0] + c.sun[1]);
            double wantD = 0.5 * cdl_vec3_dot(suns[s], cdl_vec3_make(0, 0, 1)) * omega / CDL_PI;
            CHECK_MSG(fabs(D - wantD) <= 4.0 * sd, "sun %d: %.6f +- %.2g, expected %.6f", s, D, sd, wantD);
            fprintf(stderr, "floor, sun %d: %.6f +- %.2g, expected %.6f\n", s, D, sd, wantD);
        }
        fprintf(stderr, "floor, uniform sky: %.6f +- %.2g, expected %.6f (%llu paths)\n", E, sigma, want,
                (unsigned long long)c.paths);
    }
    cdl_daylight_coefficients_release(&c);
    release(scene, &ds);
}

/* A glazed side-lit room, its coefficients summed (a uniform sky of 1
 * cd/m^2 all round) against the solver's own solve of that sky with path
 * tracing: two estimators apart (next-event estimation of the environment
 * there, of the visible sky's pieces here), within 4 combined sigmas. */
static void test_room(void)
{
    static const char *const room =
        "{\"version\": 1, \"surfaces\": ["
        "{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,5,3], \"inward\": true, "
        "\"reflectance\": {\"floor\": 0.3, \"walls\": 0.6, \"ceiling\": 0.8}, \"open\": [\"-y\"]},"
        "{\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]], \"holes\": "
        "[[[1,0,1],[3,0,1],[3,0,2.4],[1,0,2.4]]], \"reflectance\": 0.5},"
        "{\"type\": \"rect\", \"origin\": [1,0,1], \"u\": [2,0,0], \"v\": [0,0,1.4], \"transmittance\": 0.75}]%s"
        " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": ["
        "{\"p\": [2,1,0.8], \"n\": [0,0,1]}, {\"p\": [2,3,0.8], \"n\": [0,0,1]}, {\"p\": [0.5,4.5,0.8], "
        "\"n\": [0,0,1]}, {\"p\": [3.9,2.5,1.5], \"n\": [-1,0,0]}, {\"p\": [2,4.9,1.2], \"n\": [0,-1,0]}]}],"
        " \"solver\": {\"method\": \"pathtrace\", \"target_error\": 0.01, \"seed\": 3}}";
    char json[2048];
    snprintf(json, sizeof json, room, ",");
    /* the same room lit by a uniform environment of 1 cd/m^2 */
    char lit[2048];
    snprintf(lit, sizeof lit, room, ", \"luminaires\": [{\"type\": \"environment\", \"luminance_cd_m2\": 1}],");
    cdl_scene *scene;
    cdl_daylight_scene ds;
    if (!load(json, &scene, &ds)) return;
    cdl_reinhart_patches p;
    cdl_daylight_grid_coefficients c;
    cdl_error err;
    coefficients(&ds, &p, 1, NULL, 0, 0.01, &c);
    cdl_scene *ref = NULL;
    cdl_solution *sol = NULL;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    CHECK_OK(cdl_scene_load_string(lit, CANDELA_TEST_TMPDIR "/lit.json", &ref, &err), &err);
    if (ref) CHECK_OK(cdl_solve_scene(ref, &so, &sol, &err), &err);
    if (c.sky && sol) {
        const double *E = cdl_solution_grid_values(sol, 0, CDL_GRID_E);
        const double *S = cdl_solution_grid_values(sol, 0, CDL_GRID_E_STDERR);
        CHECK(c.routes.through_glass == 5);
        for (size_t i = 0; i < c.points; ++i) {
            double mine = row_sum(&c, i), sigma = c.sky_rel_stderr[i] * mine;
            double sd = sqrt(sigma * sigma + S[i] * S[i]);
            CHECK_MSG(fabs(mine - E[i]) <= 4.0 * sd, "point %zu: %.6f +- %.2g, the solve %.6f +- %.2g", i, mine, sigma,
                      E[i], S[i]);
            fprintf(stderr, "room point %zu: coefficients %.6f +- %.2g, solve %.6f +- %.2g (%+.2f sigma)\n", i, mine,
                    sigma, E[i], S[i], (mine - E[i]) / sd);
        }
        fprintf(stderr, "room: %llu paths, %llu rays\n", (unsigned long long)c.paths, (unsigned long long)c.rays);
    }
    cdl_solution_release(sol);
    cdl_scene_release(ref);
    cdl_daylight_coefficients_release(&c);
    release(scene, &ds);
}

static void test_refused(void)
{
    static const char *const bad[2][2] = {
        {"{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,2], \"intensity_cd\": 10}],"
         " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}",
         "annual.json: luminaires[0]: expected no luminaires in an annual study"},
        {"{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0,0,3], \"u\": [1,0,0], \"v\": [0,1,0], "
         "\"reflectance\": 0.5, \"luminance_cd_m2\": 100}],"
         " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}",
         "annual.json: surfaces[0].luminance_cd_m2: expected no emitting surfaces"}};
    for (int i = 0; i < 2; ++i) {
        cdl_scene *scene = NULL;
        cdl_daylight_scene ds;
        cdl_error err;
        CHECK_OK(cdl_scene_load_string(bad[i][0], CANDELA_TEST_TMPDIR "/annual.json", &scene, &err), &err);
        if (!scene) continue;
        CHECK(cdl_daylight_scene_build(scene, &ds, &err) == CDL_ERR_INPUT);
        CHECK_MSG(strstr(err.message, bad[i][1]), "%s", err.message);
        cdl_scene_release(scene);
    }
}

int main(void)
{
    test_open();
    test_skylight();
    test_floor();
    test_room();
    test_refused();
    return check_finish();
}
