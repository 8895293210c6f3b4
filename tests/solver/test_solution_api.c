/* The public handles of a solve (solve.h, solution.h, scene.h), as a
 * program using the installed library sees them: a 1000 cd point light
 * 2 m above a 3 x 1 rect grid, so every value has a closed form
 * E = I cos(theta) / d^2. Checked: the accessors against those values, the
 * grid summary against its own points, the structs that begin with their
 * size (an older, shorter struct is filled only as far as it reaches), and
 * the options that override the scene's settings (and their refusal when
 * out of range). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/solve.h"

static const char *const scene_json =
    "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 2], \"intensity_cd\": 1000}],"
    " \"grids\": [{\"name\": \"strip\", \"type\": \"rect\", \"origin\": [-1.5, -0.5, 0], \"u\": [3, 0, 0],"
    " \"v\": [0, 1, 0], \"nu\": 3, \"nv\": 1}, {\"name\": \"probe\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0],"
    " \"n\": [0, 0, 1]}]}], \"solver\": {\"method\": \"pathtrace\", \"quality\": \"draft\", \"seed\": 7}}";

/* E at (x, 0, 0) facing up under the light: I h / d^3 with h = 2. */
static double closed_form(double x)
{
    double d = sqrt(x * x + 4.0);
    return 1000.0 * 2.0 / (d * d * d);
}

static void test_accessors(const cdl_scene *scene)
{
    cdl_error err;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = 1;
    cdl_solution *sol = NULL;
    CHECK_OK(cdl_solve_scene(scene, &o, &sol, &err), &err);
    if (!sol) return;
    CHECK(cdl_solution_grid_count(sol) == 2);
    CHECK(strcmp(cdl_solution_grid_name(sol, 0), "strip") == 0 && strcmp(cdl_solution_grid_name(sol, 1), "probe") == 0);
    CHECK(cdl_solution_grid_name(sol, 2) == NULL && cdl_solution_grid_points(sol, 2) == NULL &&
          cdl_solution_grid_point_count(sol, 2) == 0);
    CHECK(cdl_solution_grid_point_count(sol, 0) == 3);
    const cdl_vec3 *p = cdl_solution_grid_points(sol, 0);
    const cdl_vec3 *n = cdl_solution_grid_normals(sol, 0);
    const double *E = cdl_solution_grid_values(sol, 0, CDL_GRID_E);
    const double *Ed = cdl_solution_grid_values(sol, 0, CDL_GRID_E_DIRECT);
    const double *Ei = cdl_solution_grid_values(sol, 0, CDL_GRID_E_INDIRECT);
    const double *se = cdl_solution_grid_values(sol, 0, CDL_GRID_E_STDERR);
    const double *w = cdl_solution_grid_weights(sol, 0);
    CHECK(p && n && E && Ed && Ei && se && w);
    /* outputs the grid did not ask for */
    CHECK(cdl_solution_grid_values(sol, 0, CDL_GRID_AO) == NULL && cdl_solution_grid_values(sol, 0, CDL_GRID_EZ) == NULL &&
          cdl_solution_grid_values(sol, 0, CDL_GRID_L) == NULL);
    for (size_t i = 0; p && E && i < 3; ++i) {
        /* cell centres x = -1, 0, 1; nothing reflects: exact, no error */
        CHECK_REL(p[i].x, -1.0 + (double)i, 1e-15);
        CHECK(n[i].z == 1.0 && Ei[i] == 0.0 && se[i] == 0.0);
        CHECK_REL(E[i], closed_form(p[i].x), 1e-12);
        CHECK(Ed[i] == E[i]);
        CHECK_REL(w[i], 1.0, 1e-15);
    }
    cdl_grid_summary sum = CDL_GRID_SUMMARY_INIT;
    cdl_solution_grid_summary(sol, 0, &sum);
    CHECK(sum.count == 3);
    CHECK_REL(sum.area_m2, 3.0, 1e-15);
    CHECK_REL(sum.E_avg_lx, (closed_form(-1) + closed_form(0) + closed_form(1)) / 3.0, 1e-12);
    CHECK_REL(sum.E_min_lx, closed_form(1), 1e-12);
    CHECK_REL(sum.E_max_lx, closed_form(0), 1e-12);
    CHECK_REL(sum.U0, sum.E_min_lx / sum.E_avg_lx, 1e-12);
    /* An older program's shorter struct: filled up to its size, no further. */
    struct {
        cdl_grid_summary s;
        double guard;
    } old;
    memset(&old, 0x5a, sizeof old);
    old.s.size = offsetof(cdl_grid_summary, E_min_lx);
    cdl_solution_grid_summary(sol, 0, &old.s);
    CHECK(old.s.count == 3 && old.s.E_avg_lx == sum.E_avg_lx);
    double poison;
    memset(&poison, 0x5a, sizeof poison);
    CHECK(memcmp(&old.s.E_min_lx, &poison, sizeof poison) == 0 && memcmp(&old.guard, &poison, sizeof poison) == 0);

    cdl_solution_info info = CDL_SOLUTION_INFO_INIT;
    cdl_solution_get_info(sol, &info);
    /* nothing reflects: pathtrace asked, direct light is the whole answer */
    CHECK(info.method == CDL_METHOD_PATHTRACE && info.quality == CDL_QUALITY_DRAFT && info.seed == 7);
    CHECK(info.target_error == 0.02 && info.threads == 1 && info.rays == 0);
    CHECK(info.luminaires_without_watts == 1 && info.installed_w == 0.0);
    const char *plan = cdl_solution_plan_json(sol);
    CHECK(plan && plan[0] == '{' && strstr(plan, "\"interreflection\""));
    CHECK(cdl_solution_warning_count(sol) == 0 && cdl_solution_warning(sol, 0) == NULL);
    cdl_solution_release(sol);
}

static void test_overrides(const cdl_scene *scene)
{
    cdl_error err;
    /* the scene asks for draft; the options for high, then a target of their own */
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.quality = CDL_QUALITY_HIGH;
    o.method = CDL_METHOD_DIRECT;
    cdl_solution *sol = NULL;
    CHECK_OK(cdl_solve_scene(scene, &o, &sol, &err), &err);
    if (sol) {
        cdl_solution_info info = CDL_SOLUTION_INFO_INIT;
        cdl_solution_get_info(sol, &info);
        CHECK(info.quality == CDL_QUALITY_HIGH && info.target_error == 0.001 && info.method == CDL_METHOD_DIRECT);
        cdl_solution_release(sol);
    }
    o.target_error = 0.003;
    CHECK_OK(cdl_solve_scene(scene, &o, &sol, &err), &err);
    if (sol) {
        cdl_solution_info info = CDL_SOLUTION_INFO_INIT;
        cdl_solution_get_info(sol, &info);
        CHECK(info.target_error == 0.003);
        cdl_solution_release(sol);
    }
    /* out of range: usage errors, no solution */
    const struct {
        int method, quality;
        double target;
        const char *fragment;
    } bad[] = {{7, -1, 0.0, "expected a method"}, {-1, 9, 0.0, "expected a quality"}, {-1, -1, 0.9, "target error"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        cdl_solve_options b = CDL_SOLVE_OPTIONS_INIT;
        b.method = bad[k].method;
        b.quality = bad[k].quality;
        b.target_error = bad[k].target;
        sol = (cdl_solution *)&b; /* must be set to NULL on failure */
        cdl_status st = cdl_solve_scene(scene, &b, &sol, &err);
        CHECK_MSG(st == CDL_ERR_USAGE && sol == NULL && strstr(err.message, bad[k].fragment), "case %zu: %d %s", k,
                  (int)st, err.message);
    }
    /* An older program's options (only size, threads, progress): the rest take their defaults. */
    cdl_solve_options older = CDL_SOLVE_OPTIONS_INIT;
    older.size = offsetof(cdl_solve_options, cache_path);
    older.cache_path = "/nonexistent/folder/cache"; /* beyond its size: never read */
    older.method = 99;
    CHECK_OK(cdl_solve_scene(scene, &older, &sol, &err), &err);
    cdl_solution_release(sol);
}

int main(void)
{
    cdl_error err;
    cdl_scene *scene = NULL;
    CHECK_OK(cdl_scene_load_string(scene_json, "api.json", &scene, &err), &err);
    if (!scene) return check_finish();
    CHECK(strcmp(cdl_scene_path(scene), "api.json") == 0);
    CHECK(cdl_scene_grid_count(scene) == 2 && strcmp(cdl_scene_grid_name(scene, 1), "probe") == 0 &&
          cdl_scene_grid_name(scene, 2) == NULL);
    CHECK(cdl_scene_luminaire_count(scene) == 1 && cdl_scene_surface_count(scene) == 0);
    CHECK(cdl_scene_method(scene) == CDL_METHOD_PATHTRACE && cdl_scene_quality(scene) == CDL_QUALITY_DRAFT);
    CHECK(cdl_scene_target_error(scene) == 0.02 && cdl_scene_seed(scene) == 7);
    test_accessors(scene);
    test_overrides(scene);
    cdl_scene_release(scene);
    return check_finish();
}
