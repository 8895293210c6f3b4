/* The public shared solve, cdl_solve_scene_ranks, on three threads standing
 * in for three ranks (thread_ranks.h: no MPI, so the sanitizers see it
 * all). Each scene is solved by one process (cdl_solve_scene) and by the
 * three ranks, with the same options: rank 0's solution must have the same
 * bits at every point (E, its parts, its stated error, the outputs asked
 * for), the others none. Scenes: the integrating sphere by the irradiance
 * cache, whose interreflected part is also checked against its closed form
 * (a source of flux Phi in a sphere of area A and reflectance rho gives
 * every point of the wall rho Phi / (A (1 - rho)) by interreflection;
 * e.g. Ohno, OSA Handbook of Optics, "Integrating sphere"), each point
 * within 4 of its stated errors (the stated error is calibrated: 95 %
 * within 2, and 4 leaves a fixed seed's 60 points no chance to fail by
 * noise: about 4e-3 in all); a room by paths with ambient occlusion and
 * cylindrical illuminance, two threads a rank. Failures: a photometric
 * file rank 2 cannot read fails every rank with its message, agreed;
 * options out of range fail every rank alike. */
#include <math.h>
#include <string.h>

#include "base/error_report.h"
#include "check.h"
#include "radiometry/constants.h"
#include "solver/solution_internal.h"
#include "solver/solve.h"

#define RANKS 3
#include "solver/thread_ranks.h"

typedef struct shared_solve {
    const char *json[RANKS];     /* each rank's scene */
    cdl_solve_options options;
    cdl_solution *out[RANKS];
    cdl_status got[RANKS];
    int agreed[RANKS];
    char message[RANKS][CDL_ERROR_MESSAGE_SIZE];
} shared_solve;

static void solve_body(const cdl_ranks *ranks, void *user)
{
    shared_solve *s = user;
    int r = ranks->rank;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    s->got[r] = cdl_scene_load_string(s->json[r], CANDELA_TEST_TMPDIR "/ranks.json", &scene, &err);
    s->got[r] = cdl_ranks_agree(ranks, s->got[r], &err);
    if (s->got[r] == CDL_OK) s->got[r] = cdl_solve_scene_ranks(scene, &s->options, ranks, &s->out[r], &s->agreed[r], &err);
    snprintf(s->message[r], sizeof s->message[r], "%s", err.message);
    cdl_scene_release(scene);
}

static int same_doubles(const double *a, const double *b, size_t n)
{
    if (!a || !b) return a == b;
    return memcmp(a, b, n * sizeof *a) == 0;
}

/* The ranks' rank 0 solution has the bits of one process's. */
static void check_same(const cdl_solution *one, const cdl_solution *shared, const char *what)
{
    CHECK_MSG(one->grid_count == shared->grid_count, "%s: grids", what);
    for (size_t g = 0; g < one->grid_count && g < shared->grid_count; ++g) {
        const cdl_grid_solution *a = &one->grids[g], *b = &shared->grids[g];
        size_t n = a->grid.count;
        CHECK_MSG(n == b->grid.count, "%s: grid %zu points", what, g);
        if (n != b->grid.count) continue;
        CHECK_MSG(same_doubles(a->E, b->E, n), "%s: grid %zu E", what, g);
        CHECK_MSG(same_doubles(a->E_direct, b->E_direct, n), "%s: grid %zu E_direct", what, g);
        CHECK_MSG(same_doubles(a->E_indirect, b->E_indirect, n), "%s: grid %zu E_indirect", what, g);
        CHECK_MSG(same_doubles(a->E_stderr, b->E_stderr, n), "%s: grid %zu E_stderr", what, g);
        CHECK_MSG(same_doubles(a->ao, b->ao, n) && same_doubles(a->ao_stderr, b->ao_stderr, n), "%s: grid %zu AO",
                  what, g);
        CHECK_MSG(same_doubles(a->Ez, b->Ez, n) && same_doubles(a->Ez_stderr, b->Ez_stderr, n), "%s: grid %zu Ez",
                  what, g);
    }
    CHECK_MSG(one->rays == shared->rays && one->records == shared->records, "%s: rays %llu/%llu, records %llu/%llu",
              what, (unsigned long long)one->rays, (unsigned long long)shared->rays,
              (unsigned long long)one->records, (unsigned long long)shared->records);
    CHECK_MSG(strcmp(one->plan_json, shared->plan_json) == 0, "%s: the plan differs", what);
    cdl_solution_info info = CDL_SOLUTION_INFO_INIT;
    cdl_solution_get_info(shared, &info);
    CHECK_MSG(info.ranks == RANKS && shared->rank_count == RANKS, "%s: %d ranks said", what, info.ranks);
}

/* Solve `json` alone and on the ranks; returns rank 0's solution (NULL on
 * failure), *one the process's. */
static cdl_solution *solve_both(const char *json, int threads, cdl_solution **one, const char *what)
{
    shared_solve s;
    memset(&s, 0, sizeof s);
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = threads;
    s.options = o;
    for (int r = 0; r < RANKS; ++r) s.json[r] = json;
    cdl_error err;
    cdl_scene *scene = NULL;
    *one = NULL;
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/ranks.json", &scene, &err), &err);
    if (scene) CHECK_OK(cdl_solve_scene(scene, &o, one, &err), &err);
    cdl_scene_release(scene);
    thread_world world = {0};
    run_ranks(&world, solve_body, &s);
    for (int r = 0; r < RANKS; ++r) {
        CHECK_MSG(s.got[r] == CDL_OK, "%s: rank %d: %s", what, r, s.message[r]);
        CHECK_MSG((r == 0) == (s.out[r] != NULL), "%s: rank %d holds a solution: %d", what, r, s.out[r] != NULL);
        if (r > 0) cdl_solution_release(s.out[r]);
    }
    if (*one && s.out[0]) check_same(*one, s.out[0], what);
    return s.out[0];
}

/* 60 points on the wall of a sphere of radius 1 (a Fibonacci lattice),
 * 0.999 m from the centre, facing it. */
static void sphere_points(char *out, size_t size, int n)
{
    size_t used = 0;
    for (int i = 0; i < n; ++i) {
        double z = 1.0 - 2.0 * (i + 0.5) / n, r = sqrt(1.0 - z * z), ph = i * CDL_PI * (3.0 - sqrt(5.0));
        double x = r * cos(ph), y = r * sin(ph), R = 0.999;
        used += (size_t)snprintf(out + used, size - used, "%s{\"p\": [%.9f, %.9f, %.9f], \"n\": [%.9f, %.9f, %.9f]}",
                                 i ? ", " : "", R * x, R * y, R * z, -x, -y, -z);
    }
}

static void test_sphere(void)
{
    static char points[16384], json[20000];
    sphere_points(points, sizeof points, 60);
    const double rho = 0.5, flux = 1000.0;
    snprintf(json, sizeof json,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
             "\"inward\": true, \"reflectance\": %g}], \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 0], "
             "\"flux_lm\": %g}], \"grids\": [{\"name\": \"wall\", \"type\": \"points\", \"points\": [%s]}], "
             "\"solver\": {\"method\": \"icache\", \"target_error\": 0.01, \"seed\": 4}}",
             rho, flux, points);
    cdl_solution *one = NULL, *shared = solve_both(json, 1, &one, "sphere by the cache");
    if (shared) {
        /* the integrating sphere: rho Phi / (A (1 - rho)), A = 4 pi r^2 */
        double exact = rho * flux / (4.0 * CDL_PI * (1.0 - rho));
        const cdl_grid_solution *g = &shared->grids[0];
        size_t within = 0;
        for (size_t i = 0; i < g->grid.count; ++i) within += fabs(g->E_indirect[i] - exact) <= 4.0 * g->E_stderr[i];
        CHECK_MSG(within == g->grid.count, "sphere: %zu of %zu points within 4 stated errors of %g lx", within,
                  g->grid.count, exact);
        CHECK(shared->records > 0);
    }
    cdl_solution_release(one);
    cdl_solution_release(shared);
}

static const char *room =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [4, 3, 2.8], \"inward\": true, "
    "\"reflectance\": {\"floor\": 0.2, \"walls\": 0.5, \"ceiling\": 0.7}}],"
    " \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1.7, 1.8, 2.78], "
    "\"u\": [0.6, 0, 0], \"v\": [0, -0.6, 0]}, \"luminance_cd_m2\": 3000}, {\"type\": \"point\", "
    "\"position\": [3, 1, 2.5], \"intensity_cd\": 300}],"
    " \"grids\": [{\"name\": \"workplane\", \"type\": \"rect\", \"origin\": [0.3, 0.3, 0.8], \"u\": [3.4, 0, 0], "
    "\"v\": [0, 2.4, 0], \"nu\": 9, \"nv\": 7, \"outputs\": [\"ao\", \"cylindrical\"]}, {\"name\": \"probe\", "
    "\"type\": \"points\", \"points\": [{\"p\": [2, 1.5, 1.2], \"n\": [0, 0, 1]}]}],"
    " \"solver\": {\"method\": \"pathtrace\", \"quality\": \"draft\", \"seed\": 9}}";

static void test_room(void)
{
    cdl_solution *one = NULL, *shared = solve_both(room, 2, &one, "room by paths");
    cdl_solution_release(one);
    cdl_solution_release(shared);
}

static void test_failures(void)
{
    /* rank 2's scene names a file that is not there */
    static const char *gonio =
        "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"%s\", \"position\": [0, 0, 3]}],"
        " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}]}]}";
    static char seen[1024], unseen[1024];
    snprintf(seen, sizeof seen, gonio, CANDELA_SOURCE_DIR "/data/office/downlight.ies");
    snprintf(unseen, sizeof unseen, gonio, CANDELA_SOURCE_DIR "/data/office/no_such_file.ies");
    shared_solve s;
    memset(&s, 0, sizeof s);
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = 1;
    s.options = o;
    s.json[0] = s.json[1] = seen;
    s.json[2] = unseen;
    thread_world world = {0};
    run_ranks(&world, solve_body, &s);
    for (int r = 0; r < RANKS; ++r) {
        CHECK(s.got[r] == CDL_ERR_INPUT && s.agreed[r] && !s.out[r]);
        CHECK_MSG(strncmp(s.message[r], "rank 2 of 3: ", 13) == 0 && strstr(s.message[r], "no_such_file.ies"),
                  "rank %d: '%s'", r, s.message[r]);
    }
    /* the same options out of range on every rank: every rank's error, no rank named */
    memset(&s, 0, sizeof s);
    o.target_error = 7.0;
    s.options = o;
    s.json[0] = s.json[1] = s.json[2] = seen;
    run_ranks(&world, solve_body, &s);
    for (int r = 0; r < RANKS; ++r)
        CHECK_MSG(s.got[r] == CDL_ERR_USAGE && s.agreed[r] && strncmp(s.message[r], "solve options:", 14) == 0,
                  "rank %d: '%s'", r, s.message[r]);
}

int main(void)
{
    test_sphere();
    test_room();
    test_failures();
    return check_finish();
}
