/* Placing luminaires: "name", "aim" with "spin", "array" and "positions"
 * read into one spec per luminaire placed, agreeing with "rotation" and
 * "direction"; and the refusals of contradictory placements. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/scene/scene_internal.h"

/* world_from_luminaire = Rz(c) Ry(b) Rx(a) applied to v (DESIGN.md:
 * rotation about fixed x, then y, then z), written out independently of
 * the loader's. */
static cdl_vec3 rotate(const double deg[3], cdl_vec3 v)
{
    double a = deg[0] * CDL_DEG_TO_RAD, b = deg[1] * CDL_DEG_TO_RAD, c = deg[2] * CDL_DEG_TO_RAD;
    cdl_vec3 x = cdl_vec3_make(v.x, cos(a) * v.y - sin(a) * v.z, sin(a) * v.y + cos(a) * v.z);
    cdl_vec3 y = cdl_vec3_make(cos(b) * x.x + sin(b) * x.z, x.y, -sin(b) * x.x + cos(b) * x.z);
    return cdl_vec3_make(cos(c) * y.x - sin(c) * y.y, sin(c) * y.x + cos(c) * y.y, y.z);
}

static cdl_scene *load(const char *json)
{
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *s = NULL;
    if (cdl_scene_load_string(json, CANDELA_SOURCE_DIR "/data/office/inline.json", &s, &err) != CDL_OK)
        fprintf(stderr, "load failed: %s\n", err.message);
    CHECK(s != NULL);
    return s;
}

#define GRID "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]"

/* Rounding in the rotation's construction and its Euler angles: a few
 * ulps of 1 per step, far below 1e-12. */
#define ROT_TOL 1e-12

static void test_aim_matches_rotation(void)
{
    /* Aimed 30 degrees from -z towards +x: DESIGN.md's rotation [0, -30, 0]. */
    char json[1024];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "
             "\"position\": [2, 2, 3], \"aim\": [%.17g, 2, 0], \"name\": \"tilted\"}], " GRID "}",
             2.0 + 3.0 * tan(30.0 * CDL_DEG_TO_RAD));
    cdl_scene *s = load(json);
    if (!s) return;
    const cdl_luminaire_spec *l = &s->luminaires[0];
    CHECK_ABS(l->rotation_deg[0], 0.0, ROT_TOL);
    CHECK_ABS(l->rotation_deg[1], -30.0, ROT_TOL);
    CHECK_ABS(l->rotation_deg[2], 0.0, ROT_TOL);
    CHECK(l->has_aim && strcmp(l->name, "tilted") == 0);
    char label[160];
    cdl_luminaire_spec_label(l, label, sizeof label);
    CHECK(strcmp(label, "luminaires[0] (tilted)") == 0);
    cdl_scene_release(s);

    /* Straight down with a spin of 90 degrees: C0 turned to +y, i.e. rotation [0, 0, 90]. */
    s = load("{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "
             "\"position\": [0, 0, 3], \"aim\": [0, 0, 0], \"spin\": 90}], " GRID "}");
    if (!s) return;
    cdl_vec3 c0 = rotate(s->luminaires[0].rotation_deg, cdl_vec3_make(1, 0, 0));
    cdl_vec3 nadir = rotate(s->luminaires[0].rotation_deg, cdl_vec3_make(0, 0, -1));
    CHECK_ABS(c0.x, 0.0, ROT_TOL);
    CHECK_ABS(c0.y, 1.0, ROT_TOL);
    CHECK_ABS(nadir.z, -1.0, ROT_TOL);
    cdl_scene_release(s);

    /* A spot aimed: its direction is the unit vector to the aim point. */
    s = load("{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [1, 2, 3], \"aim\": [4, 6, 3], "
             "\"intensity_cd\": 10, \"half_angle\": 20}], " GRID "}");
    if (!s) return;
    CHECK_ABS(s->luminaires[0].direction.x, 0.6, ROT_TOL);
    CHECK_ABS(s->luminaires[0].direction.y, 0.8, ROT_TOL);
    CHECK_ABS(s->luminaires[0].direction.z, 0.0, ROT_TOL);
    cdl_scene_release(s);
}

/* The copy's turned nadir points from its position at `aim`. */
static void check_nadir_at(const cdl_luminaire_spec *l, cdl_vec3 aim, size_t k)
{
    cdl_vec3 want = cdl_vec3_normalize(cdl_vec3_sub(aim, l->position));
    cdl_vec3 nadir = rotate(l->rotation_deg, cdl_vec3_make(0, 0, -1));
    CHECK_MSG(cdl_vec3_length(cdl_vec3_sub(nadir, want)) < ROT_TOL, "copy %zu nadir off by %g", k,
              cdl_vec3_length(cdl_vec3_sub(nadir, want)));
}

/* Floodlights on poles all aimed at one point: every copy's nadir points
 * at it, whatever its position (including straight above and level with it). */
static void test_positions_aimed(void)
{
    cdl_scene *s = load(
        "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "
        "\"name\": \"mast\", \"positions\": [[0, 0, 10], [20, 0, 12], [20, 15, 8], [-3, 40, 9], [5, 5, 30], "
        "[15, 7, 0.5]], \"aim\": [5, 5, 0.5], \"spin\": 15}], " GRID "}");
    if (!s) return;
    CHECK(s->luminaire_count == 6);
    for (size_t k = 0; k < s->luminaire_count && k < 6; ++k) {
        const cdl_luminaire_spec *l = &s->luminaires[k];
        check_nadir_at(l, cdl_vec3_make(5, 5, 0.5), k);
        CHECK(strcmp(l->json_path, "luminaires[0]") == 0 && l->entry == 0 && l->copy == k && l->copy_count == 6);
    }
    char label[160];
    cdl_luminaire_spec_label(&s->luminaires[2], label, sizeof label);
    CHECK_MSG(strcmp(label, "luminaires[0] (mast, 3 of 6)") == 0, "%s", label);
    cdl_scene_release(s);
}

/* An array in the luminaire's own frame: turned by rotation [0, 0, 90],
 * its rows run along +y (C0) and -x (C90). */
static void test_array(void)
{
    cdl_scene *s = load(
        "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0, 0, 3], \"intensity_cd\": 1}, "
        "{\"type\": \"goniometric\", \"file\": \"downlight.ies\", \"position\": [1, 1, 2.8], "
        "\"rotation\": [0, 0, 90], \"array\": {\"counts\": [4, 3], \"spacing\": [1.5, 1.2]}}, "
        "{\"type\": \"point\", \"position\": [0, 0, 3], \"intensity_cd\": 1, \"array\": {\"counts\": [2, 1], "
        "\"spacing\": [0.5, 9]}}], " GRID "}");
    if (!s) return;
    CHECK(s->luminaire_count == 1 + 12 + 2);
    if (s->luminaire_count != 15) {
        cdl_scene_release(s);
        return;
    }
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const cdl_luminaire_spec *l = &s->luminaires[1 + j * 4 + i];
            /* position + i 1.5 Rz90(x) + j 1.2 Rz90(y) = (1 - 1.2 j, 1 + 1.5 i, 2.8) */
            CHECK_ABS(l->position.x, 1.0 - 1.2 * j, 1e-12);
            CHECK_ABS(l->position.y, 1.0 + 1.5 * i, 1e-12);
            CHECK(l->position.z == 2.8);
            CHECK(l->array_index[0] == i && l->array_index[1] == j && l->entry == 1);
            CHECK(l->rotation_deg[2] == 90.0);
            CHECK(l->file && strstr(l->file, "downlight.ies"));
        }
    /* A point light's frame is the world's. */
    CHECK(s->luminaires[14].position.x == 0.5 && s->luminaires[14].position.y == 0.0);
    CHECK(s->luminaires[13].entry == 2 && s->luminaires[0].copy_count == 1);
    cdl_scene_release(s);
}

/* The trap: rotation [0, 0, 90] with counts [3, 4] laid rows along
 * the turned C0/C90 axes, 9 of 12 luminaires outside a 6 x 8 m room. With
 * "axes": "world" the rows run along world x and y, where the plan shows
 * them, whatever the luminaires' rotation; each copy keeps the rotation. */
static void test_array_world_axes(void)
{
    cdl_scene *s = load(
        "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "
        "\"position\": [1, 1, 2.8], \"rotation\": [0, 0, 90], \"array\": {\"counts\": [3, 4], \"spacing\": [2, 2], "
        "\"axes\": \"world\"}}], " GRID "}");
    if (!s) return;
    CHECK(s->luminaire_count == 12);
    int inside = 0;
    for (size_t k = 0; k < s->luminaire_count && k < 12; ++k) {
        const cdl_luminaire_spec *l = &s->luminaires[k];
        int i = (int)(k % 3), j = (int)(k / 3);
        CHECK_ABS(l->position.x, 1.0 + 2.0 * i, 1e-12);
        CHECK_ABS(l->position.y, 1.0 + 2.0 * j, 1e-12);
        CHECK(l->rotation_deg[2] == 90.0);
        inside += l->position.x > 0.0 && l->position.x < 6.0 && l->position.y > 0.0 && l->position.y < 8.0;
    }
    CHECK_MSG(inside == 12, "%d of 12 luminaires inside the 6 x 8 m room", inside);
    cdl_scene_release(s);
}

/* Floodlights on masts, each aimed at its own point of a pitch: with
 * "positions", "aim" takes as many points. */
static void test_positions_each_aimed(void)
{
    cdl_scene *s = load(
        "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "
        "\"positions\": [[0, 0, 20], [0, 0, 20], [50, 30, 18]], \"aim\": [[10, 5, 0], [30, 25, 0], [40, 10, 0]]}], "
        GRID "}");
    if (!s) return;
    static const double aims[3][3] = {{10, 5, 0}, {30, 25, 0}, {40, 10, 0}};
    CHECK(s->luminaire_count == 3);
    for (size_t k = 0; k < s->luminaire_count && k < 3; ++k)
        check_nadir_at(&s->luminaires[k], cdl_vec3_make(aims[k][0], aims[k][1], aims[k][2]), k);
    cdl_scene_release(s);
}

/* A room with a window wall left open and its reflectances by floor,
 * walls and ceiling: the natural mix of namings. */
static void test_window_room(void)
{
    cdl_scene *s = load("{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,5,3], "
                        "\"inward\": true, \"open\": [\"-y\"], "
                        "\"reflectance\": {\"floor\": 0.2, \"walls\": 0.5, \"ceiling\": 0.7}}], " GRID "}");
    if (!s) return;
    const cdl_surface_spec *b = &s->surfaces[0];
    CHECK(b->face_open[CDL_BOX_NEG_Y] && !b->face_open[CDL_BOX_POS_Y] && !b->face_open[CDL_BOX_NEG_Z]);
    CHECK(b->face_reflectance[CDL_BOX_NEG_Z] == 0.2 && b->face_reflectance[CDL_BOX_POS_Z] == 0.7);
    CHECK(b->face_reflectance[CDL_BOX_NEG_X] == 0.5 && b->face_reflectance[CDL_BOX_POS_Y] == 0.5);
    cdl_scene_release(s);
}

static void expect_error(const char *json, const char *fragment)
{
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *s = NULL;
    cdl_status st = cdl_scene_load_string(json, CANDELA_SOURCE_DIR "/data/office/inline.json", &s, &err);
    CHECK_MSG(st == CDL_ERR_INPUT && strstr(err.message, fragment), "status %d, message: %s\n  expected: %s", (int)st,
              err.message, fragment);
    cdl_scene_release(s);
}

#define GONIO "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"downlight.ies\", "

static void test_errors(void)
{
    expect_error(GONIO "\"position\": [0,0,3], \"aim\": [0,0,0], \"rotation\": [0,0,0]}], " GRID "}",
                 "luminaires[0].aim: expected either \"aim\" or \"rotation\", found both");
    expect_error(GONIO "\"position\": [0,0,3], \"spin\": 10}], " GRID "}",
                 "luminaires[0].spin: expected \"spin\" only with \"aim\"");
    expect_error(GONIO "\"position\": [0,0,3], \"aim\": [0,0,3]}], " GRID "}",
                 "luminaires[0].aim: expected a point away from the luminaire");
    expect_error(GONIO "\"positions\": [[0,0,3], [1,1,1]], \"aim\": [1,1,1]}], " GRID "}",
                 "luminaires[0].aim: expected a point away from the luminaire");
    expect_error(GONIO "\"position\": [0,0,3], \"positions\": [[0,0,3]]}], " GRID "}",
                 "luminaires[0].positions: expected either \"position\" or \"positions\", found both");
    expect_error(GONIO "\"position\": [0,0,3], \"array\": {\"counts\": [2, 2], \"spacing\": [1, 1]}, "
                       "\"positions\": [[0,0,3]]}], " GRID "}",
                 "luminaires[0].positions: expected either \"array\" or \"positions\", found both");
    expect_error(GONIO "\"position\": [0,0,3], \"array\": {\"counts\": [0, 2], \"spacing\": [1, 1]}}], " GRID "}",
                 "luminaires[0].array.counts[0]: expected");
    expect_error(GONIO "\"position\": [0,0,3], \"array\": {\"counts\": [2, 2]}}], " GRID "}",
                 "luminaires[0].array.spacing: expected two distances [dx, dy] in metres, found nothing");
    expect_error(GONIO "\"position\": [0,0,3], \"array\": {\"counts\": [2, 2], \"spacing\": [1, 1], \"gap\": 1}}], "
                       GRID "}",
                 "luminaires[0].array.gap: expected a key of a luminaire array");
    expect_error(GONIO "\"positions\": []}], " GRID "}",
                 "luminaires[0].positions: expected a non-empty list of positions");
    expect_error("{\"version\": 1, \"luminaires\": [{\"type\": \"directional\", \"direction\": [0,0,-1], "
                 "\"illuminance_lx\": 1, \"array\": {\"counts\": [2, 2], \"spacing\": [1, 1]}}], " GRID "}",
                 "luminaires[0].array: expected a key of a directional luminaire");
    expect_error("{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,3], "
                 "\"intensity_cd\": 1, \"aim\": [0,0,0]}], " GRID "}",
                 "luminaires[0].aim: expected a key of a point luminaire");
    expect_error("{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0,0,3], "
                 "\"intensity_cd\": 1, \"half_angle\": 20}], " GRID "}",
                 "luminaires[0].direction: expected a non-zero vector of 3 numbers, found nothing");
    expect_error("{\"$schema\": 3, \"version\": 1, " GRID "}", "$schema: expected the address of the scene's JSON Schema");
    expect_error(GONIO "\"position\": [0,0,3], \"array\": {\"counts\": [2, 2], \"spacing\": [1, 1], \"axes\": \"plan\"}}], "
                       GRID "}",
                 "luminaires[0].array.axes: expected \"luminaire\"");
    expect_error(GONIO "\"positions\": [[0,0,3], [1,1,3]], \"aim\": [[0,0,0]]}], " GRID "}",
                 "luminaires[0].aim: expected one aim point per entry of \"positions\", found 1 aim points for 2 positions");
    expect_error(GONIO "\"position\": [0,0,3], \"aim\": [[0,0,0]]}], " GRID "}",
                 "luminaires[0].aim: expected one aim point [x, y, z] (a list of them goes with \"positions\"");
}

int main(void)
{
    test_aim_matches_rotation();
    test_positions_aimed();
    test_array();
    test_array_world_axes();
    test_positions_each_aimed();
    test_window_room();
    test_errors();
    return check_finish();
}
