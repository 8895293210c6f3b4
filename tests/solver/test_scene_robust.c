/* Regression tests for scenes that are extreme but valid-looking (found by
 * fuzzing scene loading and solving, and by probing the command line): each
 * must be refused with a message naming the JSON path and what was
 * expected, or solved to finite, correct numbers. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/scene.h"
#include "solver/solve.h"

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

int main(void)
{
    test_sample_limits();
    return check_finish();
}
