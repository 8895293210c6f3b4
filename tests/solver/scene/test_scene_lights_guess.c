/* The far-field guesses the one-light draw weighs lights by
 * (solver/scene/scene_lights.h, guess_map and guess_origin): every bounded
 * extended light has one, taken from the right place and the right
 * emitter, and no delta light has one.
 *  - a luminaire spread over its opening (near field "auto": the point
 *    model beyond, the opening nearer; and "always"): the map of its point
 *    model, turned as the luminaire is, from its photometric centre;
 *  - an area luminaire: the map of its own intensity (int L cos dA), from
 *    the centre of its bounds;
 *  - points, spots and the point-model parts: none.
 * At every node the map holds the emitter's intensity to a float's
 * rounding, so a map of the wrong emitter, frame or turn fails here. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "scene_lights_fixture.h"
#include "lights/emitters/intensity_map.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_lights.h"

static const char *scene_json =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": true,"
    " \"reflectance\": 0.5}],"
    " \"luminaires\": ["
    "  {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/downlight.ies\","
    "   \"position\": [1.5, 1.5, 2.95], \"near_field\": \"auto\"},"
    "  {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/linear.ies\","
    "   \"position\": [4, 2.5, 2.2], \"rotation\": [10, -20, 35], \"near_field\": \"always\"},"
    "  {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0.3, 3.7, 2.79], \"u\": [0, 0.6, 0],"
    "   \"v\": [0.6, 0, 0]}, \"flux_lm\": 3000},"
    "  {\"type\": \"point\", \"position\": [5, 4, 2.5], \"intensity_cd\": 400},"
    "  {\"type\": \"spot\", \"position\": [2, 4, 2.9], \"direction\": [0, 0, -1], \"intensity_cd\": 900,"
    "   \"half_angle\": 30}],"
    " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [1, 1, 0], \"n\": [0, 0, 1]}]}],"
    " \"solver\": {\"method\": \"direct\"}}";

/* The largest difference between the map's nodes and the emitter's intensity there, cd. */
static double node_difference(const cdl_intensity_map *m, const cdl_emitter *e)
{
    double worst = 0.0;
    int res = cdl_intensity_map_resolution(m);
    for (int j = 0; j < res; ++j)
        for (int i = 0; i < res; ++i) {
            double exact = cdl_emitter_intensity(e, cdl_intensity_map_node_direction(m, i, j)).cd;
            worst = fmax(worst, fabs(cdl_intensity_map_node(m, i, j).cd - exact));
        }
    return worst;
}

int main(void)
{
    cdl_error err;
    cdl_error_clear(&err);
    scene_lights_fixture f;
    CHECK_OK(scene_lights_fixture_open(&f, scene_json, CANDELA_TEST_TMPDIR "/lights_guess.json", &err), &err);
    const cdl_scene *scene = f.scene;
    const cdl_scene_lights lights = f.lights;
    int openings = 0, areas = 0, deltas = 0;
    for (size_t i = 0; i < lights.count; ++i) {
        const cdl_scene_light *l = &lights.lights[i];
        const char *kind = lights.kinds[i];
        if (cdl_emitter_is_delta(l->emitter)) {
            /* points, spots, the downlight's point model beyond its near field */
            ++deltas;
            CHECK_MSG(l->guess_map == NULL, "%s (%s) has a map", l->label, kind);
            continue;
        }
        CHECK_MSG(l->guess_map != NULL, "%s (%s) has no map", l->label, kind);
        if (!l->guess_map) continue;
        const cdl_emitter *far = cdl_emitter_far_field(l->emitter);
        if (far) {
            ++openings;
            cdl_vec3 c = scene->luminaires[l->luminaire].position;
            CHECK(l->guess_origin.x == c.x && l->guess_origin.y == c.y && l->guess_origin.z == c.z);
            /* 1e-6 of the tables' peaks (1000 and 800 cd, scaled): a float's rounding */
            CHECK_MSG(node_difference(l->guess_map, far) <= 1e-6 * 1000.0, "%s: nodes off by %.3g cd", l->label,
                      node_difference(l->guess_map, far));
        } else {
            ++areas;
            cdl_vec3 c = cdl_bounds3_centre(l->bounds);
            CHECK(l->guess_origin.x == c.x && l->guess_origin.y == c.y && l->guess_origin.z == c.z);
            /* the panel's peak intensity L A = 3000 / pi cd: a float's rounding of it */
            CHECK_MSG(node_difference(l->guess_map, l->emitter) <= 1e-6 * 3000.0, "%s: nodes off by %.3g cd",
                      l->label, node_difference(l->guess_map, l->emitter));
        }
    }
    /* the downlight (auto: its opening), the linear luminaire (always), the panel; the point, the spot
     * and the downlight's point model */
    CHECK_MSG(openings == 2 && areas == 1 && deltas == 3, "%d openings, %d areas, %d delta lights", openings, areas,
              deltas);
    scene_lights_fixture_close(&f);
    return check_finish();
}
