/* Regression tests for scenes that are extreme but valid-looking (found by
 * fuzzing scene loading and solving, and by probing the command line): each
 * must be refused with a message naming the JSON path and what was
 * expected, or solved to finite, correct numbers. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "radiometry/vec3.h"
#include "solver/scene/scene_internal.h"
#include "solver/solve_internal.h"

#define POINTS_GRID "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]"

/* The scene must be refused with CDL_ERR_INPUT and a message containing `fragment`. */
static void check_refused(const char *json, const char *fragment)
{
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = cdl_scene_load_string(json, "robust.json", &scene, &err);
    CHECK_MSG(st == CDL_ERR_INPUT && scene == NULL, "status %d for %s", (int)st, json);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "message '%s' lacks '%s'", err.message, fragment);
    cdl_scene_release(scene);
}

static cdl_scene *load(const char *json)
{
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK_OK(cdl_scene_load_string(json, "robust.json", &scene, &err), &err);
    return scene;
}

/* Sample counts: 2^31 - 1 samples made the stratified k x k square (k =
 * 46341) overflow an int (undefined behaviour, then a loop that never ends).
 * At most 2^24 per point are accepted, for direct light and for AO. */
static void test_sample_limits(void)
{
    check_refused("{\"version\": 1, " POINTS_GRID ", \"solver\": {\"direct_samples\": 2147483647}}",
                  "robust.json: solver.direct_samples: expected an integer in [1, 16777216], found the number "
                  "2147483647");
    check_refused("{\"version\": 1, " POINTS_GRID ", \"solver\": {\"ao_samples\": 16777217}}",
                  "robust.json: solver.ao_samples: expected an integer in [1, 16777216], found the number 16777217");
    cdl_scene *s = load("{\"version\": 1, " POINTS_GRID ", \"solver\": {\"direct_samples\": 16777216, \"ao_samples\": "
                        "16777216}}");
    CHECK(s && s->settings.direct_samples == 16777216 && s->settings.ao_samples == 16777216);
    cdl_scene_release(s);
}

/* Solve a scene (one thread); E and its standard error at the points of
 * grid 0, which must have exactly n points. */
static void solve_grid(const char *json, double *E, double *stderr_lx, size_t n)
{
    for (size_t i = 0; i < n; ++i) E[i] = stderr_lx[i] = NAN;
    cdl_scene *scene = load(json);
    if (!scene) return;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    so.threads = 1;
    cdl_solution sol;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = cdl_solve_scene_into(scene, &so, NULL, &sol, &err);
    CHECK_OK(st, &err);
    if (st == CDL_OK) {
        CHECK(sol.grids[0].grid.count == n);
        for (size_t i = 0; i < n && i < sol.grids[0].grid.count; ++i) {
            E[i] = sol.grids[0].E[i];
            stderr_lx[i] = sol.grids[0].E_stderr[i];
        }
        cdl_solution_clear(&sol);
    }
    cdl_scene_release(scene);
}

/* E at the only point of grid 0. */
static double solve_point(const char *json)
{
    double E, se;
    solve_grid(json, &E, &se, 1);
    return E;
}

/* A spot narrower than about 1e-8 rad: cos(half_angle) rounds to 1, and the
 * solver's emission-cone culling dropped even the points on its axis (E = 0
 * instead of I / d^2). The spot itself is exact on its axis: E = I0 / d^2. */
static void test_narrow_spot(void)
{
#define NARROW_SPOT(point)                                                                                    \
    "{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0,0,3], \"direction\": [0,0,-1], " \
    "\"intensity_cd\": 1000, \"half_angle\": 1e-7}], \"grids\": [{\"name\": \"g\", \"type\": \"points\", "       \
    "\"points\": [{\"p\": " point ", \"n\": [0,0,1]}]}]}"
    /* On the axis: 1000 cd / (3 m)^2, to rounding. */
    CHECK_REL(solve_point(NARROW_SPOT("[0,0,0]")), 1000.0 / 9.0, 1e-12);
    /* 1e-6 m off the axis at 3 m is 3.3e-7 rad, far outside the 1.7e-9 rad beam. */
    CHECK(solve_point(NARROW_SPOT("[1e-6,0,0]")) == 0.0);
#undef NARROW_SPOT
}


/* "Can a surface come between this light and this grid?" was answered with
 * the box around both, shrunk by a tolerance so that the floor under a grid
 * does not count. A box that is flat along an axis - a probe straight below
 * its luminaire, a grid level with its luminaire - shrank to nothing, and
 * the light shone through tables and walls. */
static void test_flat_light_grid_box(void)
{
    /* A table (z = 0.05) between a point light (z = 3) and a probe right below it. */
    const char *probe =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1,-1,0.05], \"u\": [2,0,0], \"v\": [0,2,0], "
        "\"reflectance\": 0}], \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,3], \"intensity_cd\": 1000}], "
        POINTS_GRID "}";
    CHECK(solve_point(probe) == 0.0);
    /* A wall (x = 1) between a point light at 0.8 m and a grid level with
     * it (z = 0.8 m), whose points face the light; then without the wall. */
#define LEVEL_SCENE(surfaces)                                                                                    \
    "{\"version\": 1, " surfaces "\"luminaires\": [{\"type\": \"point\", \"position\": [0,0,0.8], "                  \
    "\"intensity_cd\": 1000}], \"grids\": [{\"name\": \"g\", \"type\": \"rect\", \"origin\": [2,-0.5,0.8], "        \
    "\"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 2, \"nv\": 2, \"normal\": [-1,0,0]}]}"
    double E[4], se[4];
    solve_grid(LEVEL_SCENE("\"surfaces\": [{\"type\": \"rect\", \"origin\": [1,-1,0], \"u\": [0,2,0], "
                           "\"v\": [0,0,2], \"reflectance\": 0}], "),
               E, se, 4);
    for (int i = 0; i < 4; ++i) CHECK_MSG(E[i] == 0.0, "point %d behind the wall: E = %g lx", i, E[i]);
    /* Without the wall the same points are lit: I cos / d^2 > 0. */
    solve_grid(LEVEL_SCENE(""), E, se, 4);
#undef LEVEL_SCENE
    /* Point 0 at (2.25, -0.25, 0.8): d^2 = 5.125, cos = 2.25 / sqrt(5.125). */
    CHECK_REL(E[0], 1000.0 * 2.25 / pow(5.125, 1.5), 1e-12);
}

/* An area emitter counted as fully visible from a point when nothing
 * crossed the pyramid from the point to its outline, shrunk by a tolerance:
 * the shrunk side planes cut away the pyramid's tip, and all of it for a
 * small emitter, so a table 5 cm above a floor point hid nothing. */
static void test_small_emitter_pyramid(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1,-1,0.05], \"u\": [2,0,0], \"v\": [0,2,0], "
        "\"reflectance\": 0}], \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", "
        "\"origin\": [-0.005,-0.005,3], \"u\": [0.01,0,0], \"v\": [0,-0.01,0]}, \"luminance_cd_m2\": 1e6}], "
        "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}, "
        "{\"p\": [0,0,0.1], \"n\": [0,0,1]}]}]}";
    double E[2], se[2];
    solve_grid(json, E, se, 2);
    /* Unoccluded, the 1 cm square at 3 m gives about L A / d^2 = 1e6 x 1e-4 / 9
     * = 11.1 lx. Under the table every sample is hidden: what is left is the
     * closed form minus the sampled hidden part, zero to within a few
     * standard errors (and far below 1 % of 11.1 lx). */
    CHECK_MSG(E[0] <= 4.0 * se[0] + 1e-9 && E[0] < 0.01 * 11.1, "under the table: E = %g lx (stderr %g)", E[0],
              se[0]);
    /* Above the table the emitter is in plain view: closed form, exact, and
     * within (size / d)^2 ~ 1e-5 of the point-source value L A / d^2. */
    CHECK_REL(E[1], 1e6 * 1e-4 / (2.9 * 2.9), 1e-4);
    CHECK(se[1] == 0.0);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK_MSG(f != NULL, "cannot write %s", path);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* Mesh files obey the bound on scene coordinates (1e12 m): a vertex at 1e20
 * was accepted, and Embree's single precision then lost every shadow near
 * the origin (a grid under a covering triangle was fully lit). Areas of
 * vertices at 1e150 overflowed into an "infinite area" message that named no
 * vertex. Now the message names the file, the vertex and the bound. */
static void test_mesh_file_magnitude(void)
{
    write_text(CANDELA_TEST_TMPDIR "/robust_far.obj", "v 0 0 0\nv 1e20 0 0\nv 0 1e20 0\nf 1 2 3\n");
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    const char *json = "{\"version\": 1, \"surfaces\": [{\"type\": \"mesh\", \"file\": \"robust_far.obj\", "
                       "\"reflectance\": 0}], " POINTS_GRID "}";
    cdl_status st = cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/robust.json", &scene, &err);
    CHECK(st == CDL_ERR_INPUT && scene == NULL);
    CHECK_MSG(strstr(err.message, "robust.json: surfaces[0].file: ") &&
                  strstr(err.message, "robust_far.obj: vertex 2 (from 1, in file order): expected coordinates of "
                                      "magnitude at most 1e+12 m, found [1e+20, 0, 0]"),
              "message: %s", err.message);
    cdl_scene_release(scene);
    /* At the bound itself the mesh loads. */
    write_text(CANDELA_TEST_TMPDIR "/robust_far.obj", "v 0 0 0\nv 1e12 0 0\nv 0 -1e12 0\nf 1 2 3\n");
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/robust.json", &scene, &err), &err);
    cdl_scene_release(scene);
}

/* The solve of a scene must fail with CDL_ERR_INPUT and a message holding both fragments. */
static void check_solve_refused(const char *json, const char *path, const char *fragment1, const char *fragment2)
{
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK_OK(cdl_scene_load_string(json, path, &scene, &err), &err);
    if (!scene) return;
    cdl_solution sol;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    so.threads = 1;
    cdl_status st = cdl_solve_scene_into(scene, &so, NULL, &sol, &err);
    CHECK_MSG(st == CDL_ERR_INPUT, "status %d: %s", (int)st, err.message);
    if (st == CDL_OK) cdl_solution_clear(&sol);
    CHECK_MSG(strstr(err.message, fragment1) && strstr(err.message, fragment2), "message: %s", err.message);
    cdl_scene_release(scene);
}

/* An environment image that is a folder read as "luminaires[0]: DIR: cannot
 * read as OpenEXR: Error reading from stream"; a missing one as "Unable to
 * open file". Now the JSON path ends in .file and the message says what the
 * path is. */
static void test_environment_file_messages(void)
{
    mkdir(CANDELA_TEST_TMPDIR "/robust_sky_folder.exr", 0755);
    check_solve_refused("{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"file\": "
                        "\"robust_sky_folder.exr\"}], " POINTS_GRID "}",
                        CANDELA_TEST_TMPDIR "/robust.json", "robust.json: luminaires[0].file: ",
                        "robust_sky_folder.exr: expected an OpenEXR image, found a directory or device");
    check_solve_refused("{\"version\": 1, \"luminaires\": [{\"type\": \"environment\", \"file\": "
                        "\"robust_no_such_sky.exr\"}], " POINTS_GRID "}",
                        CANDELA_TEST_TMPDIR "/robust.json", "robust.json: luminaires[0].file: ",
                        "robust_no_such_sky.exr: cannot open the OpenEXR image: No such file or directory");
}

/* A point light 1e-200 m above a grid point: I cos / d^2 overflows to
 * infinity, which the CSV writer then refused as an internal error (exit 3)
 * naming only the file. Now the solve refuses it as bad input naming the
 * grid, the point and the light. At 1e-150 m the value (1e302 lx) is finite
 * and kept: that is the inverse-square law, not an error. */
static void test_light_on_grid_point(void)
{
#define NEAR_LIGHT(z)                                                                                         \
    "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0," z "], \"intensity_cd\": 100}], " \
    POINTS_GRID "}"
    check_solve_refused(NEAR_LIGHT("1e-200"), "robust.json",
                        "robust.json: grids[0] (g) point 0 at [0, 0, 0]: expected a finite illuminance, found the "
                        "illuminance beyond the range of a double: ",
                        "luminaires[0] is too close to the point (or too bright)");
    /* E = 100 cd / (1e-150 m)^2 = 1e302 lx, to rounding. */
    CHECK_REL(solve_point(NEAR_LIGHT("1e-150")), 1e302, 1e-12);
#undef NEAR_LIGHT
}

/* A flux over a tiny emitter: flux / (pi area) or flux / (lumens per
 * candela of the beam) overflowed, and the emitter refused an "intensity"
 * or "luminance" of inf the user never wrote. Now the message names
 * flux_lm and what it was spread over. */
static void test_flux_overflow(void)
{
    check_solve_refused("{\"version\": 1, \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", "
                        "\"origin\": [0,0,2], \"u\": [1e-150,0,0], \"v\": [0,-1e-150,0]}, \"flux_lm\": 1e12}], "
                        POINTS_GRID "}",
                        "robust.json", "robust.json: luminaires[0].flux_lm: expected a flux that spreads over the shape's ",
                        "m^2 with a finite luminance (flux / (pi area)), found 1e+12 lm");
    check_solve_refused("{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0,0,3], "
                        "\"direction\": [0,0,-1], \"flux_lm\": 1e12, \"half_angle\": 1e-150}], " POINTS_GRID "}",
                        "robust.json", "robust.json: luminaires[0]: flux_lm: expected a flux this beam can carry with a "
                        "finite intensity (",
                        "lm per cd), found 1e+12 lm");
}

/* A polygon grid too fine to compute was refused with "grids[0].spacing:
 * ..." naming no scene file, and, with "auto" spacing, blamed a spacing the
 * user never wrote. */
static void test_polygon_grid_too_fine(void)
{
#define POLYGON_GRID(size, spacing)                                                                             \
    "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,2], \"intensity_cd\": 100}], "      \
    "\"grids\": [{\"name\": \"g\", \"type\": \"polygon\", \"vertices\": [[0,0,0],[" size ",0,0],[" size "," size ",0],[0," \
    size ",0]]" spacing "}]}"
    check_solve_refused(POLYGON_GRID("100", ", \"spacing\": 0.001"), "robust.json",
                        "robust.json: grids[0].spacing: expected a spacing giving at most 10000000 points, found "
                        "0.001 m",
                        "(about 1e+10 points over 10000 m^2)");
    check_solve_refused(POLYGON_GRID("1e12", ""), "robust.json",
                        "robust.json: grids[0].spacing: expected a spacing giving at most 10000000 points, found "
                        "\"auto\", the EN 12464-1 spacing capped at 10 m",
                        "points over 1e+24 m^2)");
#undef POLYGON_GRID
}

/* The plan's per-light "grids" objects are filled grid by grid through
 * pointers kept from their creation (looking each one up in the array cost
 * lights^2 x grids: seconds for a thousand of each, minutes beyond). Every
 * light must still name every grid, with its own strategy. */
static void test_plan_lights_by_grid(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [-1,-1,1], \"u\": [2,0,0], \"v\": [0,2,0], "
        "\"reflectance\": 0}], \"luminaires\": ["
        "{\"type\": \"point\", \"position\": [0,0,3], \"intensity_cd\": 10}, "
        "{\"type\": \"point\", \"position\": [5,5,3], \"intensity_cd\": 10}, "
        "{\"type\": \"point\", \"position\": [0,0,0.5], \"intensity_cd\": 10}], "
        "\"grids\": [{\"name\": \"under\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}, "
        "{\"name\": \"aside\", \"type\": \"points\", \"points\": [{\"p\": [5,5,0], \"n\": [0,0,1]}]}]}";
    cdl_scene *scene = load(json);
    if (!scene) return;
    cdl_solution sol;
    cdl_error err;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    so.threads = 1;
    CHECK_OK(cdl_solve_scene_into(scene, &so, NULL, &sol, &err), &err);
    const char *plan = sol.plan_json ? sol.plan_json : "";
    /* Light 0 above the table may be hidden from both grids (its box with
     * either holds the table); light 1 only from "under"; light 2, below the
     * table, from neither. */
#define SHADOWED "exact, one shadow ray per point: surfaces may come between this light and the grid"
#define CLEAR "exact, no shadow rays: no surface can come between this light and the grid"
#define LIGHT(k, under, aside) \
    "{\"light\":\"luminaires[" #k "]\",\"kind\":\"point\",\"grids\":{\"under\":\"" under "\",\"aside\":\"" aside "\"}}"
    CHECK_MSG(strstr(plan, "\"direct\":[" LIGHT(0, SHADOWED, SHADOWED) "," LIGHT(1, SHADOWED, CLEAR) ","
                           LIGHT(2, CLEAR, CLEAR) "]") != NULL,
              "plan: %s", plan);
#undef LIGHT
#undef CLEAR
#undef SHADOWED
    cdl_solution_clear(&sol);
    cdl_scene_release(scene);
}

/* A vector shorter than the smallest normal double (1e-320) normalised to
 * NaN (its reciprocal length overflows), so a grid "n": [1e-320, 0, 0] or a
 * rect grid of u, v = 1e-160 (u x v = 1e-320) wrote NaN normals, refused as
 * an internal error at the CSV writer. */
static void test_tiny_vectors(void)
{
    cdl_vec3 a = cdl_vec3_normalize(cdl_vec3_make(1e-320, 0, 0));
    CHECK(a.x == 1.0 && a.y == 0.0 && a.z == 0.0);
    /* Subnormal components keep about 1e-14 of relative precision here. */
    cdl_vec3 b = cdl_vec3_normalize(cdl_vec3_make(-3e-310, 4e-310, 0));
    CHECK_REL(b.x, -0.6, 1e-10);
    CHECK_REL(b.y, 0.8, 1e-10);
    cdl_vec3 z = cdl_vec3_normalize(cdl_vec3_make(0, 0, 0));
    CHECK(z.x == 0.0 && z.y == 0.0 && z.z == 0.0);
    double E[2], se[2];
    solve_grid("{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,2], \"intensity_cd\": 100}], "
               "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1e-320]}, "
               "{\"p\": [0,0,0], \"n\": [1e-320,0,0]}]}]}",
               E, se, 2);
    /* Facing the light: 100 cd / (2 m)^2; edge-on to it: 0. */
    CHECK_REL(E[0], 25.0, 1e-12);
    CHECK(E[1] == 0.0);
}

/* Perpendicular spans of 1e-200 m were refused as "v: expected a vector
 * not parallel to u, found one parallel to u" (|u| |v| underflowed and the
 * sine became 0 / 0); the real problem is an area below the double range. */
static void test_tiny_spans(void)
{
    check_refused("{\"version\": 1, \"surfaces\": [{\"type\": \"rect\", \"origin\": [0,0,1], \"u\": [1e-200,0,0], "
                  "\"v\": [0,1e-200,0], \"reflectance\": 0}], " POINTS_GRID "}",
                  "robust.json: surfaces[0]: expected u and v spanning an area a double can hold (|u x v| > 0), found "
                  "|u| = 1e-200 m and |v| = 1e-200 m, whose area underflows to 0");
    check_refused("{\"version\": 1, \"grids\": [{\"name\": \"g\", \"type\": \"rect\", \"origin\": [0,0,0], "
                  "\"u\": [0,0,1e-200], \"v\": [0,1e-200,0], \"nu\": 1, \"nv\": 1}]}",
                  "robust.json: grids[0]: expected u and v spanning an area a double can hold");
    /* Truly parallel spans keep their message. */
    check_refused("{\"version\": 1, \"grids\": [{\"name\": \"g\", \"type\": \"rect\", \"origin\": [0,0,0], "
                  "\"u\": [1,0,0], \"v\": [-3,0,0], \"nu\": 1, \"nv\": 1}]}",
                  "robust.json: grids[0].v: expected a vector not parallel to u, found one parallel to u");
}

/* A scene file is parsed whole into JSON nodes, about 21 times its size
 * in memory: the 1 GiB limit it shared with mesh files let a scene exhaust
 * the memory of most machines. Scenes stop at 256 MiB, said before reading
 * (a sparse file: no disk space used). */
static void test_scene_file_size(void)
{
    const char *path = CANDELA_TEST_TMPDIR "/robust_huge_scene.json";
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    CHECK(ftruncate(fileno(f), (off_t)300 << 20) == 0);
    fclose(f);
    cdl_scene *scene = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    CHECK(cdl_scene_load(path, &scene, &err) == CDL_ERR_INPUT && scene == NULL);
    CHECK_MSG(strstr(err.message, "robust_huge_scene.json: expected a scene file of at most 268435456 bytes, found "
                                  "314572800 bytes") != NULL,
              "message: %s", err.message);
    unlink(path);
}

int main(void)
{
    test_scene_file_size();
    test_tiny_spans();
    test_tiny_vectors();
    test_plan_lights_by_grid();
    test_polygon_grid_too_fine();
    test_flux_overflow();
    test_light_on_grid_point();
    test_environment_file_messages();
    test_flat_light_grid_box();
    test_small_emitter_pyramid();
    test_mesh_file_magnitude();
    test_sample_limits();
    test_narrow_spot();
    return check_finish();
}
