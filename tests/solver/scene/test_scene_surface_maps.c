/* "surface_maps" and surfaces' "requirements" as the loader reads them:
 * which surfaces are mapped, their map names, the requirements kept. */
#include <string.h>

#include "check.h"
#include "solver/scene/scene_internal.h"

#define GRIDS "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]"
#define RECT "\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0.5"
#define SURFACES                                                                                                  \
    "\"surfaces\": [{" RECT ", \"name\": \"floor\"}, {\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,3,2.5], " \
    "\"inward\": true, \"reflectance\": 0.5}, {" RECT ", \"name\": \"wall\", \"requirements\": {\"Em_lx\": 50, "   \
    "\"U0\": 0.1}}, {" RECT ", \"name\": \"Ceiling.1\"}]"

static cdl_scene *load(const char *json)
{
    cdl_error err;
    cdl_scene *s = NULL;
    CHECK_OK(cdl_scene_load_string(json, "maps.json", &s, &err), &err);
    return s;
}

static int mapped(const cdl_scene *s, const char *expected)
{
    /* expected: one character per surface, '1' mapped, '0' not. */
    for (size_t k = 0; k < s->surface_count; ++k)
        if (s->surfaces[k].mapped != (expected[k] == '1')) return 0;
    return 1;
}

int main(void)
{
    /* Default: none, but the wall with requirements. */
    cdl_scene *s = load("{\"version\": 1, " SURFACES ", " GRIDS "}");
    if (s) {
        CHECK(s->settings.surface_maps == CDL_SURFACE_MAPS_NONE);
        CHECK(mapped(s, "0010"));
        CHECK(s->surfaces[2].required_Em_lx == 50.0 && s->surfaces[2].required_U0 == 0.1);
        CHECK(s->surfaces[0].required_Em_lx == 0.0 && s->surfaces[0].map_name == NULL);
        CHECK(!strcmp(s->surfaces[2].map_name, "wall"));
    }
    cdl_scene_release(s);

    /* All: the unnamed box is "surface_1". */
    s = load("{\"version\": 1, " SURFACES ", " GRIDS ", \"solver\": {\"surface_maps\": \"all\"}}");
    if (s) {
        CHECK(s->settings.surface_maps == CDL_SURFACE_MAPS_ALL);
        CHECK(mapped(s, "1111"));
        CHECK(!strcmp(s->surfaces[0].map_name, "floor") && !strcmp(s->surfaces[1].map_name, "surface_1") &&
              !strcmp(s->surfaces[3].map_name, "Ceiling.1"));
    }
    cdl_scene_release(s);

    /* Listed: those named, and the wall for its requirements. */
    s = load("{\"version\": 1, " SURFACES ", " GRIDS ", \"solver\": {\"surface_maps\": [\"Ceiling.1\"]}}");
    if (s) {
        CHECK(s->settings.surface_maps == CDL_SURFACE_MAPS_LISTED);
        CHECK(mapped(s, "0011"));
    }
    cdl_scene_release(s);

    /* "none" explicitly; an empty list maps nothing either. */
    s = load("{\"version\": 1, " SURFACES ", " GRIDS ", \"solver\": {\"surface_maps\": []}}");
    if (s) CHECK(s->settings.surface_maps == CDL_SURFACE_MAPS_LISTED && mapped(s, "0010"));
    cdl_scene_release(s);
    s = load("{\"version\": 1, " SURFACES ", " GRIDS ", \"solver\": {\"surface_maps\": \"none\"}}");
    if (s) CHECK(s->settings.surface_maps == CDL_SURFACE_MAPS_NONE && mapped(s, "0010"));
    cdl_scene_release(s);
    return check_finish();
}
