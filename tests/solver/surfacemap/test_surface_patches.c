/* The scene's mapped surfaces as patches (surface_patches.h): one per rect,
 * polygon, disk, sphere and mesh, one per closed box face; box corners and
 * disk rims the very points the ray scene has; coarsest edges by EN
 * 12464-1's spacing; and meshed whole, every vertex on its surface. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene_geometry.h"
#include "solver/surfacemap/surface_patches.h"

static const char *scene_json =
    "{\"version\": 1, \"surfaces\": ["
    "{\"name\": \"desk\", \"type\": \"rect\", \"origin\": [1,1,0.75], \"u\": [1.2,0,0], \"v\": [0,0.8,0], "
    "\"reflectance\": 0.4},"
    "{\"name\": \"room\", \"type\": \"box\", \"min\": [0,0,0], \"max\": [6,5,2.8], \"inward\": true, "
    "\"reflectance\": 0.5, \"open\": [\"+x\"]},"
    "{\"name\": \"lamp\", \"type\": \"disk\", \"center\": [3,2.5,2.79], \"normal\": [0,0,-1], \"radius\": 0.3, "
    "\"reflectance\": 0.8},"
    "{\"type\": \"sphere\", \"center\": [4,4,0.5], \"radius\": 0.5, \"reflectance\": 0.5},"
    "{\"name\": \"ramp\", \"type\": \"mesh\", \"vertices\": [[4,1,0],[5,1,0],[5,2,0.5],[4,2,0.5]], "
    "\"triangles\": [[0,1,2],[0,2,3]], \"reflectance\": 0.3},"
    "{\"name\": \"shelf\", \"type\": \"polygon\", \"vertices\": [[0.5,4,1],[2,4,1],[2,4.5,1],[0.5,4.5,1]], "
    "\"reflectance\": 0.3},"
    "{\"name\": \"hidden\", \"type\": \"rect\", \"origin\": [0,0,3], \"u\": [1,0,0], \"v\": [0,1,0], "
    "\"reflectance\": 0.3}],"
    "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [1,1,1], \"n\": [0,0,1]}]}],"
    "\"solver\": {\"surface_maps\": [\"desk\", \"room\", \"lamp\", \"ramp\", \"shelf\"], \"method\": \"direct\"}}";

static cdl_status constant(void *user, const cdl_field_probe *probes, size_t count, double *value, double *sigma,
                           double *noise, double *aux, cdl_error *err)
{
    (void)aux;
    (void)noise;
    (void)user, (void)probes, (void)err;
    for (size_t i = 0; i < count; ++i) value[i] = 100.0, sigma[i] = 0.0;
    return CDL_OK;
}

static int same_point(cdl_vec3 a, const double *b)
{
    return a.x == b[0] && a.y == b[1] && a.z == b[2];
}

int main(void)
{
    cdl_error err;
    cdl_scene *scene = NULL;
    CHECK_OK(cdl_scene_load_string(scene_json, "patches.json", &scene, &err), &err);
    if (!scene) return check_finish();
    /* Mapped: the five named in surface_maps (not the sphere nor "hidden"). */
    cdl_surface_patches p;
    CHECK_OK(cdl_surface_patches_build(scene, &p, &err), &err);
    CHECK(p.map_count == 5 && p.count == 1 + 5 + 1 + 1 + 1);
    const size_t expected_surface[5] = {0, 1, 2, 4, 5};
    for (size_t k = 0; k < 5 && k < p.map_count; ++k) CHECK(p.scene_surface[k] == expected_surface[k]);

    /* The box's five closed faces: the ray scene's quads, corner for corner. */
    cdl_scene_geometry *g = NULL;
    CHECK_OK(cdl_scene_geometry_build(scene, &g, &err), &err);
    size_t matched = 0;
    for (size_t piece = 0; g && piece < cdl_scene_geometry_piece_count(g); ++piece) {
        const cdl_geometry_piece *gp = cdl_scene_geometry_piece(g, piece);
        if (gp->is_luminaire || gp->source_index != 1) continue;
        const double *xyz;
        size_t nv;
        const uint32_t *tri;
        cdl_scene_geometry_piece_triangles(g, piece, &xyz, &nv, &tri);
        for (size_t q = 1; q <= 5; ++q) {
            int all = nv == 4;
            for (int c = 0; all && c < 4; ++c) all = same_point(p.patches[q].outer.points[c], &xyz[3 * c]);
            matched += all;
        }
    }
    CHECK(matched == 5);
    /* The disk: 0.3 m, coarsest edge 0.2 x 5^log10(0.6) = 0.16 m; 32 sides
     * give chords of 2 x 0.3 sin(pi / 32) = 0.059 m; each corner a rim
     * vertex of the fan. */
    const cdl_patch *disk = &p.patches[6];
    CHECK_REL(disk->max_edge, 0.2 * pow(5.0, log10(0.6)), 1e-12);
    CHECK(disk->outer.count == 32 && cdl_surface_patches_disk_sides(0.3, 0.16) == 32);
    CHECK(cdl_surface_patches_disk_sides(1.0, 0.1) == 112 && cdl_surface_patches_disk_sides(10.0, 0.1) == 224);
    size_t on_rim = 0;
    for (size_t k = 0; k < disk->outer.count; ++k)
        on_rim += cdl_vec3_distance(disk->outer.points[k],
                                    cdl_disk_rim_point(scene->surfaces[2].center, scene->surfaces[2].normal, 0.3,
                                                       (uint32_t)(7 * k))) == 0.0;
    CHECK(on_rim == 32);
    /* Coarsest edges: the desk's longest side 1.2 m, the room's faces 6 or 5 m. */
    CHECK_REL(p.patches[0].max_edge, cdl_grid_auto_spacing(1.2), 1e-15);
    CHECK_REL(p.patches[1].max_edge, cdl_grid_auto_spacing(5.0), 1e-15);  /* -x: 5 x 2.8 */
    CHECK(p.patches[7].kind == CDL_PATCH_TRIANGLES && p.patches[8].kind == CDL_PATCH_POLYGON);

    /* Meshed, under an even field: five maps at their coarsest, each the
     * area of its surface (the room without its open +x face: floor and
     * ceiling 30 m^2 each, the y walls 16.8 each, the -x wall 14). */
    cdl_surface_mesh maps[5];
    cdl_surface_mesh_stats stats;
    cdl_surface_mesh_request q = {p.patches, p.count, p.map_count,
                                  {.rel_tol = 0.005, .floor_fraction = 0.5, .min_edge = 0.01, .join_tolerance = 1e-9,
                                   .feature_angle_deg = 40.0, .max_vertices = 100000},
                                  constant, NULL};
    CHECK_OK(cdl_surface_mesh_build(&q, maps, &stats, &err), &err);
    CHECK(stats.rounds == 0);
    CHECK_REL(maps[0].area, 1.2 * 0.8, 1e-12);
    CHECK_REL(maps[1].area, 2 * 30.0 + 2 * 6 * 2.8 + 5 * 2.8, 1e-12);
    /* The disk's 32-gon: (32 / 2) r^2 sin(2 pi / 32). */
    CHECK_REL(maps[2].area, 16.0 * 0.09 * sin(2.0 * 3.14159265358979323846 / 32.0), 1e-12);
    CHECK_REL(maps[3].area, sqrt(1.25), 1e-12);
    CHECK_REL(maps[4].area, 1.5 * 0.5, 1e-12);
    /* The ramp's vertices on its plane z = (y - 1) / 2, normals along (0, -1, 2) / sqrt 5. */
    double off = 0.0, normal_error = 0.0;
    for (size_t v = 0; v < maps[3].vertex_count; ++v) {
        const double *x = &maps[3].xyz[3 * v], *n = &maps[3].normal[3 * v];
        off = fmax(off, fabs(x[2] - (x[1] - 1.0) / 2.0));
        normal_error = fmax(normal_error, fabs(n[1] + 1.0 / sqrt(5.0)) + fabs(n[2] - 2.0 / sqrt(5.0)) + fabs(n[0]));
    }
    CHECK(off < 1e-12 && normal_error < 1e-12);
    for (int k = 0; k < 5; ++k) cdl_surface_mesh_release(&maps[k]);
    cdl_scene_geometry_release(g);
    cdl_surface_patches_release(&p);
    cdl_scene_release(scene);
    return check_finish();
}
