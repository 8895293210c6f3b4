/* solve_fixture.h - solving a scene given as JSON text, for the end-to-end
 * solver tests. Include after check.h. */
#ifndef CANDELA_TESTS_SOLVE_FIXTURE_H
#define CANDELA_TESTS_SOLVE_FIXTURE_H

#include <stdio.h>

#include "solver/solve.h"

/* Load and solve `json` (relative paths resolve in CANDELA_TEST_TMPDIR) on
 * `threads` threads; returns 0 on failure (a failed check, the message
 * printed, nothing left to release). */
static int solve_json(const char *json, cdl_scene **scene, cdl_solution *sol, int threads)
{
    cdl_error err;
    cdl_error_clear(&err);
    *scene = NULL;
    if (cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/inline.json", scene, &err) != CDL_OK) {
        fprintf(stderr, "scene load failed: %s\n", err.message);
        CHECK(0);
        return 0;
    }
    cdl_solve_options o = CDL_SOLVE_OPTIONS_DEFAULT;
    o.threads = threads;
    if (cdl_solve_scene(*scene, &o, sol, &err) != CDL_OK) {
        fprintf(stderr, "solve failed: %s\n", err.message);
        CHECK(0);
        cdl_scene_release(*scene);
        *scene = NULL;
        return 0;
    }
    return 1;
}

#endif
