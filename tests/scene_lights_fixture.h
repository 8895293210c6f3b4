/* scene_lights_fixture.h - a scene from JSON text with its geometry and lights built, for tests.
 *
 * scene_lights_fixture_open loads `json` (named `path` in messages and for
 * relative files), builds its geometry and its lights, and returns the
 * first failure's status (err says what); scene_lights_fixture_close
 * releases whatever was built, after a failure too. */
#ifndef CANDELA_TESTS_SCENE_LIGHTS_FIXTURE_H
#define CANDELA_TESTS_SCENE_LIGHTS_FIXTURE_H

#include <string.h>

#include "solver/scene/scene.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

typedef struct scene_lights_fixture {
    cdl_scene *scene;
    cdl_scene_geometry *geometry;
    cdl_scene_lights lights;
} scene_lights_fixture;

static inline cdl_status scene_lights_fixture_open(scene_lights_fixture *f, const char *json, const char *path,
                                                   cdl_error *err)
{
    memset(f, 0, sizeof *f);
    cdl_status st = cdl_scene_load_string(json, path, &f->scene, err);
    if (st == CDL_OK) st = cdl_scene_geometry_build(f->scene, &f->geometry, err);
    if (st == CDL_OK) st = cdl_scene_lights_build(f->scene, f->geometry, &f->lights, err);
    return st;
}

static inline void scene_lights_fixture_close(scene_lights_fixture *f)
{
    cdl_scene_lights_release(&f->lights);
    cdl_scene_geometry_release(f->geometry);
    cdl_scene_release(f->scene);
    memset(f, 0, sizeof *f);
}

#endif
