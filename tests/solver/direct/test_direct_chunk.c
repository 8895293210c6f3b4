/* The solver computes points in chunks (lights evaluated light by light,
 * shadow rays traced together); that must give exactly the bits of the
 * simple point-by-point form, for every kind of light and strategy. */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "base/rng.h"
#include "solver/direct/direct.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

static const char *scene_json =
    "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [6, 5, 3], \"inward\": true,"
    " \"reflectance\": 0}, {\"type\": \"sphere\", \"center\": [3, 2.5, 1.4], \"radius\": 0.35, \"reflectance\": 0},"
    " {\"type\": \"rect\", \"origin\": [1, 1, 1.1], \"u\": [1.5, 0, 0], \"v\": [0, 0.8, 0], \"reflectance\": 0}],"
    " \"luminaires\": [{\"type\": \"spot\", \"position\": [2, 2, 2.9], \"direction\": [0.2, 0.1, -1],"
    " \"intensity_cd\": 3000, \"half_angle\": 35, \"falloff_start\": 25},"
    " {\"type\": \"point\", \"position\": [4.5, 3.5, 2.5], \"intensity_cd\": 400},"
    " {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/downlight.ies\", \"position\": [3, 2.5, 2.95]},"
    " {\"type\": \"goniometric\", \"file\": \"" CANDELA_SOURCE_DIR "/data/office/linear.ies\", \"position\": [1.5, 3.5, 2.4],"
    " \"rotation\": [0, 0, 30]},"
    " {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [4, 1, 2.99], \"u\": [0, 0.6, 0], \"v\": [0.6, 0, 0]},"
    " \"luminance_cd_m2\": 2500}],"
    " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0], \"u\": [6, 0, 0], \"v\": [0, 5, 0],"
    " \"nu\": 30, \"nv\": 25}], \"solver\": {\"method\": \"direct\", \"quality\": \"draft\"}}";

int main(void)
{
    cdl_error err;
    cdl_scene *scene = NULL;
    CHECK_OK(cdl_scene_load_string(scene_json, CANDELA_TEST_TMPDIR "/chunk.json", &scene, &err), &err);
    if (!scene) return check_finish();
    cdl_scene_geometry *geometry = NULL;
    CHECK_OK(cdl_scene_geometry_build(scene, &geometry, &err), &err);
    cdl_scene_lights lights;
    CHECK_OK(cdl_scene_lights_build(scene, geometry, &lights, &err), &err);
    cdl_grid grid;
    CHECK_OK(cdl_grid_build(&scene->grids[0], &grid, &err), &err);

    /* The occluder index as solve.c builds it is not needed: with occluders
     * NULL every extended light is tested per point and sampled where the
     * sphere or the plate may hide it, which exercises the sampling path. */
    cdl_direct_context ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.geometry = geometry;
    ctx.rays = cdl_scene_geometry_rays(geometry);
    cdl_scene_geometry_ray_offsets(geometry, &ctx.offsets);
    ctx.lights = lights.lights;
    ctx.light_count = lights.count;
    ctx.samples = 16;
    ctx.ao_samples = 16;
    ctx.seed = 7;
    cdl_light_strategy strategies[16];
    for (size_t l = 0; l < lights.count; ++l)
        strategies[l] = cdl_emitter_is_delta(lights.lights[l].emitter) ? CDL_STRATEGY_DELTA_SHADOWED
                                                                        : CDL_STRATEGY_SAMPLED;

    cdl_direct_scratch scratch;
    memset(&scratch, 0, sizeof scratch);
    cdl_direct_sample_stats s1 = {0}, s2 = {0};
    size_t mismatches = 0, lit = 0;
    for (size_t start = 0; start < grid.count; start += 13) { /* an odd chunk size on purpose */
        size_t count = grid.count - start < 13 ? grid.count - start : 13;
        uint64_t streams[13];
        double E[13], var[13];
        for (size_t i = 0; i < count; ++i) streams[i] = cdl_rng_stream_id(0, start + i, 1);
        CHECK_OK(cdl_direct_illuminance_chunk(&ctx, strategies, NULL, 0, streams, grid.points + start,
                                              grid.normals + start, count, E, var, &s1, &scratch, &err),
                 &err);
        for (size_t i = 0; i < count; ++i) {
            double e, v;
            cdl_direct_illuminance(&ctx, strategies, NULL, 0, streams[i], grid.points[start + i],
                                   grid.normals[start + i], &e, &v, &s2);
            if (memcmp(&e, &E[i], sizeof e) != 0 || memcmp(&v, &var[i], sizeof v) != 0) mismatches++;
            lit += e > 0.0;
        }
    }
    CHECK_MSG(mismatches == 0, "%zu of %zu points differ between the chunked and the simple form", mismatches,
              grid.count);
    CHECK(s1.rays == s2.rays && s1.rays > 0);
    CHECK(lit > grid.count / 2);
    /* Too many points for one chunk is refused, not overrun. */
    uint64_t many_streams[CDL_DIRECT_CHUNK_MAX + 1] = {0};
    double many_E[CDL_DIRECT_CHUNK_MAX + 1], many_var[CDL_DIRECT_CHUNK_MAX + 1];
    CHECK(cdl_direct_illuminance_chunk(&ctx, strategies, NULL, 0, many_streams, grid.points, grid.normals,
                                       CDL_DIRECT_CHUNK_MAX + 1, many_E, many_var, &s1, &scratch, &err) ==
          CDL_ERR_INTERNAL);

    cdl_direct_scratch_release(&scratch);
    cdl_grid_release(&grid);
    cdl_scene_lights_release(&lights);
    cdl_scene_geometry_release(geometry);
    cdl_scene_release(scene);
    return check_finish();
}
