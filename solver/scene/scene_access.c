/* scene_access.c - what a loaded scene holds, asked through its public handle (scene.h). */
#include "solver/scene/scene_internal.h"

size_t cdl_scene_grid_count(const cdl_scene *scene)
{
    return scene->grid_count;
}

const char *cdl_scene_path(const cdl_scene *scene)
{
    return scene->path;
}

const char *cdl_scene_grid_name(const cdl_scene *scene, size_t index)
{
    return index < scene->grid_count ? scene->grids[index].name : NULL;
}

size_t cdl_scene_luminaire_count(const cdl_scene *scene)
{
    return scene->luminaire_count;
}

size_t cdl_scene_surface_count(const cdl_scene *scene)
{
    return scene->surface_count;
}

cdl_method cdl_scene_method(const cdl_scene *scene)
{
    return scene->settings.method;
}

cdl_quality cdl_scene_quality(const cdl_scene *scene)
{
    return scene->settings.quality;
}

double cdl_scene_target_error(const cdl_scene *scene)
{
    return cdl_solver_settings_target(&scene->settings);
}

uint64_t cdl_scene_seed(const cdl_scene *scene)
{
    return scene->settings.seed;
}
