/* Observers in the scene (glare): single eyes, arrays laid out along the
 * line of sight and to its left, positions, observer grids at cell
 * centres, names, requirements, and the refusals with their JSON paths. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/scene/scene_internal.h"

#define GRID "{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}"

static cdl_scene *load(const char *json, cdl_error *err)
{
    cdl_scene *s = NULL;
    if (cdl_scene_load_string(json, "office.json", &s, err) != CDL_OK) return NULL;
    return s;
}

static void check_refused(const char *json, const char *fragment)
{
    cdl_error err;
    cdl_scene *s = load(json, &err);
    CHECK_MSG(s == NULL && err.status == CDL_ERR_INPUT, "accepted: %s", json);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "\n  message  %s\n  expected %s", err.message, fragment);
    cdl_scene_release(s);
}

static void test_single_and_array(void)
{
    cdl_error err;
    cdl_scene *s = load("{\"version\": 1, \"observers\": ["
                        "{\"name\": \"desk\", \"eye\": [1, 2, 1.2], \"view\": [0, 3, 0], \"requirements\": {\"UGR_L\": 19}},"
                        "{\"name\": \"row\", \"eye\": [0, 0, 1.2], \"view\": [1, 1, 0.02],"
                        " \"array\": {\"counts\": [2, 3], \"spacing\": [2, 0.5]}},"
                        "{\"name\": \"two\", \"positions\": [[5, 5, 1.7], [6, 5, 1.7]], \"view\": [-1, 0, 0]}]}",
                        &err);
    CHECK_MSG(s != NULL, "%s", err.message);
    if (!s) return;
    /* no grids: observers alone are a scene */
    CHECK(s->grid_count == 0);
    CHECK(s->observer_count == 1 + 6 + 2);
    const cdl_observer_spec *o = s->observers;
    CHECK(strcmp(o[0].name, "desk") == 0 && strcmp(o[0].json_path, "observers[0]") == 0);
    CHECK(o[0].eye.x == 1.0 && o[0].eye.y == 2.0 && o[0].eye.z == 1.2);
    /* the view is kept as a unit horizontal vector */
    CHECK(o[0].view.x == 0.0 && o[0].view.y == 1.0 && o[0].view.z == 0.0);
    CHECK(o[0].required_ugr == 19.0 && o[0].copy_count == 1 && !o[0].from_grid);
    /* 0.02 up in 1.41: 0.81 degrees, accepted and levelled */
    double r = sqrt(0.5);
    CHECK_ABS(o[1].view.x, r, 1e-15);
    CHECK_ABS(o[1].view.y, r, 1e-15);
    CHECK(o[1].view.z == 0.0 && o[1].required_ugr == 0.0);
    /* rows along the line of sight (2 m) and to its left (0.5 m), i fastest */
    CHECK(strcmp(o[1].name, "row[0]") == 0 && strcmp(o[6].name, "row[5]") == 0);
    CHECK(o[2].array_index[0] == 1 && o[2].array_index[1] == 0);
    CHECK_ABS(o[2].eye.x, 2.0 * r, 1e-12); /* eye + 2 m along (r, r, 0) */
    CHECK_ABS(o[2].eye.y, 2.0 * r, 1e-12);
    CHECK_ABS(o[3].eye.x, -0.5 * r, 1e-12); /* + 0.5 m to the left: z x view = (-r, r, 0) */
    CHECK_ABS(o[3].eye.y, 0.5 * r, 1e-12);
    CHECK(o[3].eye.z == 1.2 && o[6].copy == 5 && o[6].copy_count == 6 && o[6].entry == 1);
    CHECK(strcmp(o[7].name, "two[0]") == 0 && o[8].eye.x == 6.0 && o[8].view.x == -1.0);
    cdl_scene_release(s);
}

static void test_observer_grid(void)
{
    cdl_error err;
    cdl_scene *s = load("{\"version\": 1, \"grids\": [" GRID ", {\"name\": \"map\", \"type\": \"observers\","
                        " \"origin\": [0, 0, 1.2], \"u\": [4, 0, 0], \"v\": [0, 2, 0], \"nu\": 2, \"nv\": 2,"
                        " \"view\": [1, 0, 0], \"requirements\": {\"UGR_L\": 22}}]}",
                        &err);
    CHECK_MSG(s != NULL, "%s", err.message);
    if (!s) return;
    /* the observer grid is no calculation grid */
    CHECK(s->grid_count == 1 && strcmp(s->grids[0].name, "g") == 0);
    CHECK(s->observer_count == 4);
    const cdl_observer_spec *o = s->observers;
    /* cell centres, u fastest, as a rect grid's points */
    CHECK(o[0].eye.x == 1.0 && o[0].eye.y == 0.5 && o[1].eye.x == 3.0 && o[2].eye.y == 1.5);
    CHECK(strcmp(o[3].name, "map[3]") == 0 && strcmp(o[3].json_path, "grids[1]") == 0);
    CHECK(o[3].from_grid && o[3].entry == 1 && o[3].array_index[0] == 1 && o[3].array_index[1] == 1);
    CHECK(o[0].required_ugr == 22.0 && o[0].view.x == 1.0);
    cdl_scene_release(s);
}

static void test_refusals(void)
{
    /* a view more than 1 degree from horizontal, a view of zero length */
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1.2], \"view\": [1, 0, 0.03]}]}",
                  "office.json: observers[0].view: expected a horizontal line of sight (within 1 degree");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1.2], \"view\": [1, 0, 0.03]}]}",
                  "1.72 degrees above the horizontal");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1.2], \"view\": [0, 0, 0]}]}",
                  "office.json: observers[0].view: expected a non-zero vector of 3 numbers, found the zero vector");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1.2]}]}",
                  "observers[0].view: expected a non-zero vector of 3 numbers, found nothing");
    /* where, and which name */
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"view\": [1,0,0]}]}",
                  "observers[0].eye: expected an array of 3 numbers, found nothing");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1], \"positions\": [[0,0,1]], "
                  "\"view\": [1,0,0]}]}",
                  "observers[0].eye: expected either \"eye\" or \"positions\", found both");
    check_refused("{\"version\": 1, \"observers\": [{\"eye\": [0,0,1], \"view\": [1,0,0]}]}",
                  "observers[0].name: expected an observer name usable as a file name");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1], \"view\": [1,0,0]}, "
                  "{\"name\": \"A\", \"eye\": [0,0,1], \"view\": [1,0,0]}]}",
                  "observers[1].name: expected an observer name not used before (ignoring case), found \"A\", "
                  "already the name of observers[0]");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"m\", \"eye\": [0,0,1], \"view\": [1,0,0]}], "
                  "\"grids\": [{\"name\": \"M\", \"type\": \"observers\", \"origin\": [0,0,1], \"u\": [1,0,0], "
                  "\"v\": [0,1,0], \"nu\": 1, \"nv\": 1, \"view\": [1,0,0]}]}",
                  "grids[0].name: expected a name not used by an observer (ignoring case)");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1], \"view\": [1,0,0], "
                  "\"look\": 1}]}",
                  "observers[0].look: expected a key of an observer");
    /* requirements */
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1], \"view\": [1,0,0], "
                  "\"requirements\": {\"UGR_L\": -1}}]}",
                  "observers[0].requirements.UGR_L: expected a number > 0");
    check_refused("{\"version\": 1, \"observers\": [{\"name\": \"a\", \"eye\": [0,0,1], \"view\": [1,0,0], "
                  "\"requirements\": {\"Em_lx\": 500}}]}",
                  "observers[0].requirements.Em_lx: expected a key of requirements {\"UGR_L\": limit}");
    /* an observer grid as a rect grid is checked, and its view */
    check_refused("{\"version\": 1, \"grids\": [{\"name\": \"map\", \"type\": \"observers\", \"origin\": [0,0,1], "
                  "\"u\": [1,0,0], \"v\": [2,0,0], \"nu\": 1, \"nv\": 1, \"view\": [1,0,0]}]}",
                  "grids[0].v: expected a vector not parallel to u");
    check_refused("{\"version\": 1, \"grids\": [{\"name\": \"map\", \"type\": \"observers\", \"origin\": [0,0,1], "
                  "\"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 1, \"nv\": 1, \"view\": [0,0,-1]}]}",
                  "grids[0].view: expected a horizontal line of sight");
    check_refused("{\"version\": 1, \"grids\": [{\"name\": \"map\", \"type\": \"observers\", \"origin\": [0,0,1], "
                  "\"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 1, \"nv\": 1, \"view\": [1,0,0], \"outputs\": [\"ao\"]}]}",
                  "grids[0].outputs: expected a key of an observer grid");
    /* neither grids nor observers */
    check_refused("{\"version\": 1, \"observers\": []}", "grids: expected a list of at least one calculation grid");
}

int main(void)
{
    test_single_and_array();
    test_observer_grid();
    test_refusals();
    return check_finish();
}
