/* Scene loading: DESIGN.md's example scene read key by key, the documented
 * defaults, and relative paths resolved against the scene file's folder
 * wherever the program runs. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/scene/scene_internal.h"

#define DATA CANDELA_SOURCE_DIR "/tests/data/scene/"

static int vec_eq(cdl_vec3 a, double x, double y, double z)
{
    return a.x == x && a.y == y && a.z == z;
}

static void check_design_example(const cdl_scene *s, const char *base)
{
    char expect[1024];
    CHECK(s->surface_count == 8);
    CHECK(s->luminaire_count == 8);
    CHECK(s->grid_count == 3);
    if (s->surface_count != 8 || s->luminaire_count != 8 || s->grid_count != 3) return;

    /* surfaces[0]: the room box. */
    const cdl_surface_spec *box = &s->surfaces[0];
    CHECK(box->kind == CDL_SURFACE_BOX);
    CHECK(strcmp(box->name, "room") == 0);
    CHECK(strcmp(box->json_path, "surfaces[0]") == 0);
    CHECK(vec_eq(box->box_min, 0, 0, 0) && vec_eq(box->box_max, 4, 4, 3));
    CHECK(box->inward == 1);
    CHECK(box->face_reflectance[CDL_BOX_NEG_Z] == 0.2);
    CHECK(box->face_reflectance[CDL_BOX_POS_Z] == 0.7);
    CHECK(box->face_reflectance[CDL_BOX_NEG_X] == 0.5 && box->face_reflectance[CDL_BOX_POS_X] == 0.5 &&
          box->face_reflectance[CDL_BOX_NEG_Y] == 0.5 && box->face_reflectance[CDL_BOX_POS_Y] == 0.5);
    for (int f = 0; f < CDL_BOX_FACES; ++f) CHECK(box->face_open[f] == 0);
    CHECK(box->two_sided == 1);

    const cdl_surface_spec *table = &s->surfaces[1];
    CHECK(table->kind == CDL_SURFACE_RECT && vec_eq(table->origin, 1, 1, 0.75) && vec_eq(table->u, 1, 0, 0) &&
          vec_eq(table->v, 0, 0.8, 0) && table->reflectance == 0.4);

    const cdl_surface_spec *column = &s->surfaces[2];
    snprintf(expect, sizeof expect, "%s/cube.obj", base);
    CHECK(column->kind == CDL_SURFACE_MESH);
    CHECK_MSG(column->file && strcmp(column->file, expect) == 0, "file %s, expected %s", column->file, expect);
    CHECK(column->mesh_vertex_count == 8 && column->mesh_triangle_count == 12);

    const cdl_surface_spec *inline_mesh = &s->surfaces[3];
    CHECK(inline_mesh->kind == CDL_SURFACE_MESH && inline_mesh->file == NULL);
    CHECK(inline_mesh->mesh_vertex_count == 3 && inline_mesh->mesh_triangle_count == 1);
    CHECK(inline_mesh->mesh_vertices[3] == 1.0 && inline_mesh->mesh_triangles[2] == 2);
    CHECK(inline_mesh->name == NULL && inline_mesh->reflectance == 0.3);

    const cdl_surface_spec *poly = &s->surfaces[4];
    CHECK(poly->kind == CDL_SURFACE_POLYGON && poly->outer.count == 4 && poly->hole_count == 1 &&
          poly->holes[0].count == 4 && vec_eq(poly->holes[0].points[2], 2, 2, 3));

    const cdl_surface_spec *disk = &s->surfaces[5];
    CHECK(disk->kind == CDL_SURFACE_DISK && vec_eq(disk->normal, 0, 0, 1) && disk->radius == 1 &&
          disk->reflectance == 0);
    const cdl_surface_spec *sphere = &s->surfaces[6];
    CHECK(sphere->kind == CDL_SURFACE_SPHERE && sphere->inward == 1 && sphere->radius == 1);
    const cdl_surface_spec *lamp = &s->surfaces[7];
    CHECK(lamp->luminance_cd_m2 == 500 && lamp->reflectance == 0.8 && vec_eq(lamp->v, 0, -1, 0));
    CHECK(table->luminance_cd_m2 == 0);

    /* luminaires */
    const cdl_luminaire_spec *l = s->luminaires;
    snprintf(expect, sizeof expect, "%s/downlight.ies", base);
    CHECK(l[0].kind == CDL_LUMINAIRE_GONIOMETRIC && l[0].file && strcmp(l[0].file, expect) == 0);
    CHECK(vec_eq(l[0].position, 2, 2, 2.95) && l[0].multiplier == 1.0 && l[0].maintenance_factor == 0.8);
    CHECK(l[0].rotation_deg[0] == 0 && l[0].rotation_deg[1] == 0 && l[0].rotation_deg[2] == 0 && !l[0].has_flux);
    CHECK(l[1].kind == CDL_LUMINAIRE_POINT && l[1].has_intensity && !l[1].has_flux && l[1].intensity_cd == 1000);
    CHECK(l[1].maintenance_factor == 1.0);
    CHECK(l[2].kind == CDL_LUMINAIRE_SPOT && !l[2].has_exponent && l[2].half_angle_deg == 30 &&
          l[2].falloff_start_deg == 25 && vec_eq(l[2].direction, 0, 0, -1) && l[2].intensity_cd == 5000);
    CHECK(l[3].kind == CDL_LUMINAIRE_SPOT && l[3].has_exponent && l[3].exponent == 3 && l[3].intensity_cd == 400);
    CHECK(l[4].kind == CDL_LUMINAIRE_AREA && l[4].has_luminance && l[4].luminance_cd_m2 == 2000 &&
          l[4].reflectance == 0.0 && l[4].shape.kind == CDL_SURFACE_RECT && vec_eq(l[4].shape.u, 0.6, 0, 0));
    CHECK(strcmp(l[4].shape.json_path, "luminaires[4].shape") == 0);
    /* Directions are stored as unit vectors. */
    double len = sqrt(0.3 * 0.3 + 0.2 * 0.2 + 1.0);
    CHECK(l[5].kind == CDL_LUMINAIRE_DIRECTIONAL && l[5].illuminance_lx == 80000);
    CHECK_ABS(l[5].direction.x, 0.3 / len, 1e-15);
    CHECK_ABS(l[5].direction.z, -1.0 / len, 1e-15);
    CHECK(l[6].kind == CDL_LUMINAIRE_ENVIRONMENT && l[6].has_luminance && l[6].luminance_cd_m2 == 5000 &&
          l[6].upper_hemisphere_only == 1 && l[6].file == NULL);
    snprintf(expect, sizeof expect, "%s/sky.exr", base);
    CHECK(l[7].kind == CDL_LUMINAIRE_ENVIRONMENT && !l[7].has_luminance && l[7].file &&
          strcmp(l[7].file, expect) == 0 && l[7].scale == 1.0 && l[7].upper_hemisphere_only == 0 &&
          vec_eq(l[7].up, 0, 0, 1));

    /* grids */
    const cdl_grid_spec *g = s->grids;
    CHECK(g[0].kind == CDL_GRID_RECT && strcmp(g[0].name, "workplane") == 0 && g[0].nu == 9 && g[0].nv == 9 &&
          g[0].want_ao == 1 && !g[0].has_normal && vec_eq(g[0].u, 3.2, 0, 0));
    CHECK(g[1].kind == CDL_GRID_POLYGON && strcmp(g[1].name, "desk") == 0 && g[1].outer.count == 5 &&
          g[1].spacing == 0.0 && g[1].want_ao == 0 && g[1].hole_count == 0);
    CHECK(g[2].kind == CDL_GRID_POINTS && g[2].point_count == 1 && vec_eq(g[2].points[0], 2, 2, 0.8) &&
          vec_eq(g[2].normals[0], 0, 0, 1));
    CHECK(strcmp(g[2].json_path, "grids[2]") == 0);

    /* solver */
    CHECK(s->settings.method == CDL_METHOD_AUTO && s->settings.quality == CDL_QUALITY_NORMAL &&
          s->settings.bounces == CDL_BOUNCES_AUTO && s->settings.seed == 1 && s->settings.threads == 0 &&
          s->settings.direct_samples == 0 && s->settings.ao_samples == 0 && s->settings.target_error == 0.005);
    /* The quality presets are target relative standard errors (DESIGN.md). */
    CHECK(cdl_solver_settings_target(&s->settings) == 0.005);
    const double presets[4] = {0.02, 0.005, 0.001, 0.0002};
    for (int q = 0; q < 4; ++q) CHECK(cdl_quality_target_error((cdl_quality)q) == presets[q]);
}

static void check_defaults(void)
{
    const char *json =
        "{\"version\": 1,\n"
        " \"surfaces\": [{\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0.5,"
        "                 \"two_sided\": false},\n"
        "               {\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,2,3], \"reflectance\": 0.25,"
        "                \"open\": [\"+z\", \"-x\"]},\n"
        "               {\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,2,3], \"open\": [\"walls\"],"
        "                \"reflectance\": {\"floor\": 0.1, \"ceiling\": 0.9}}],\n"
        " \"luminaires\": [{\"type\": \"spot\", \"position\": [0,0,3], \"direction\": [0,0,-2], \"flux_lm\": 1000,"
        "                   \"half_angle\": 40},\n"
        "                 {\"type\": \"environment\", \"luminance_cd_m2\": 100},\n"
        "                 {\"type\": \"area\", \"shape\": {\"type\": \"disk\", \"center\": [0,0,3],"
        "                  \"normal\": [0,0,-1], \"radius\": 0.2}, \"flux_lm\": 500, \"reflectance\": 0.6},\n"
        "                 {\"type\": \"goniometric\", \"file\": \"/abs/lum.ldt\", \"position\": [1,1,1],"
        "                  \"flux_lm\": 1200, \"multiplier\": 2}],\n"
        " \"grids\": [{\"name\": \"floor\", \"type\": \"polygon\","
        "             \"vertices\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,0]], \"spacing\": 0.25,"
        "             \"normal\": [0,0,2]}],\n"
        " \"solver\": {\"method\": \"pathtrace\", \"quality\": \"high\", \"seed\": 9007199254740992,"
        "            \"direct_samples\": 64, \"ao_samples\": 32, \"threads\": 2, \"bounces\": 0}}";
    cdl_error err;
    cdl_scene *s = NULL;
    CHECK_OK(cdl_scene_load_string(json, "defaults.json", &s, &err), &err);
    if (!s) return;
    CHECK(strcmp(s->base_dir, ".") == 0);
    CHECK(s->surfaces[0].two_sided == 0 && s->surfaces[1].two_sided == 1);
    CHECK(s->surfaces[1].inward == 0);
    CHECK(s->surfaces[1].face_open[CDL_BOX_POS_Z] && s->surfaces[1].face_open[CDL_BOX_NEG_X] &&
          !s->surfaces[1].face_open[CDL_BOX_NEG_Z]);
    CHECK(s->surfaces[1].face_reflectance[CDL_BOX_POS_Y] == 0.25);
    /* Open walls need no reflectance. */
    CHECK(s->surfaces[2].face_open[CDL_BOX_NEG_X] && s->surfaces[2].face_open[CDL_BOX_POS_Y] &&
          s->surfaces[2].face_reflectance[CDL_BOX_POS_Z] == 0.9);
    const cdl_luminaire_spec *spot = &s->luminaires[0];
    CHECK(spot->has_flux && !spot->has_intensity && spot->flux_lm == 1000);
    CHECK(spot->falloff_start_deg == 40.0 && spot->half_angle_deg == 40.0);
    CHECK(vec_eq(spot->direction, 0, 0, -1));
    const cdl_luminaire_spec *env = &s->luminaires[1];
    CHECK(env->upper_hemisphere_only == 0 && vec_eq(env->up, 0, 0, 1) && env->scale == 1.0);
    const cdl_luminaire_spec *area = &s->luminaires[2];
    CHECK(area->has_flux && !area->has_luminance && area->flux_lm == 500 && area->reflectance == 0.6 &&
          area->shape.kind == CDL_SURFACE_DISK && area->shape.radius == 0.2);
    const cdl_luminaire_spec *gonio = &s->luminaires[3];
    CHECK(strcmp(gonio->file, "/abs/lum.ldt") == 0 && gonio->has_flux && gonio->flux_lm == 1200 &&
          gonio->multiplier == 2.0);
    /* A ring written closed drops its repeated last point. */
    CHECK(s->grids[0].outer.count == 4 && s->grids[0].spacing == 0.25);
    CHECK(s->grids[0].has_normal && vec_eq(s->grids[0].normal, 0, 0, 1));
    CHECK(s->settings.method == CDL_METHOD_PATHTRACE && s->settings.quality == CDL_QUALITY_HIGH);
    CHECK(s->settings.seed == 9007199254740992ull && s->settings.direct_samples == 64 &&
          s->settings.ao_samples == 32 && s->settings.threads == 2 && s->settings.bounces == 0);
    CHECK(strcmp(cdl_method_name(s->settings.method), "pathtrace") == 0);
    CHECK(cdl_solver_settings_target(&s->settings) == 0.001); /* "high" */
    CHECK(strcmp(cdl_quality_name(CDL_QUALITY_DRAFT), "draft") == 0);
    cdl_scene_release(s);

    /* target_error overrides the quality; bounces "auto". */
    {
        const char *t = "{\"version\": 1, \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": "
                        "[{\"p\": [0,0,0], \"n\": [0,0,1]}]}], \"solver\": {\"quality\": \"draft\", "
                        "\"target_error\": 0.003, \"bounces\": \"auto\"}}";
        cdl_scene *ts = NULL;
        CHECK_OK(cdl_scene_load_string(t, "target.json", &ts, &err), &err);
        if (ts) {
            CHECK(ts->settings.target_error == 0.003 && cdl_solver_settings_target(&ts->settings) == 0.003);
            CHECK(ts->settings.bounces == CDL_BOUNCES_AUTO && ts->settings.quality == CDL_QUALITY_DRAFT);
            cdl_scene_release(ts);
        }
    }

    /* A UTF-8 byte-order mark is read past; minimal scene: only a grid. */
    const char *minimal = "\xEF\xBB\xBF{\"version\": 1, \"grids\": [{\"name\": \"p\", \"type\": \"points\","
                          " \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}";
    CHECK_OK(cdl_scene_load_string(minimal, "dir/sub/minimal.json", &s, &err), &err);
    if (s) {
        CHECK(s->surface_count == 0 && s->luminaire_count == 0 && s->grid_count == 1);
        CHECK(strcmp(s->base_dir, "dir/sub") == 0 && strcmp(s->path, "dir/sub/minimal.json") == 0);
        CHECK(s->settings.method == CDL_METHOD_AUTO && s->settings.bounces == CDL_BOUNCES_AUTO && s->settings.seed == 1);
        cdl_scene_release(s);
    }
}

/* Photometric values may be typed with their unit; each becomes the value in
 * the unit the key names, the same as writing the number there. */
static void check_quantities_with_units(void)
{
    const char *json =
        "{\"version\": 1,\n"
        " \"surfaces\": [{\"type\": \"rect\", \"origin\": [0,0,3], \"u\": [1,0,0], \"v\": [0,-1,0],"
        "                 \"reflectance\": 0.5, \"luminance_cd_m2\": \"2 nit\"}],\n"
        " \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,3], \"intensity_cd\": \"1.2 kcd\"},\n"
        "                 {\"type\": \"point\", \"position\": [0,0,3], \"flux_lm\": \"3000 lm\"},\n"
        "                 {\"type\": \"spot\", \"position\": [0,0,3], \"direction\": [0,0,-1],"
        "                  \"flux_lm\": \"2.5 klm\", \"exponent\": 1},\n"
        "                 {\"type\": \"directional\", \"direction\": [0,0,-1], \"illuminance_lx\": \"46.45 fc\"},\n"
        "                 {\"type\": \"environment\", \"luminance_cd_m2\": \"1200 cd/m2\"},\n"
        "                 {\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1,1,2.99],"
        "                  \"u\": [0.6,0,0], \"v\": [0,0.6,0]}, \"luminance_cd_m2\": \"10 fL\"},\n"
        "                 {\"type\": \"goniometric\", \"file\": \"/abs/lum.ldt\", \"position\": [1,1,1],"
        "                  \"flux_lm\": \"1200lm\"}],\n"
        " \"grids\": [{\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}";
    cdl_error err;
    cdl_scene *s = NULL;
    CHECK_OK(cdl_scene_load_string(json, "units.json", &s, &err), &err);
    if (!s) return;
    CHECK(s->surfaces[0].luminance_cd_m2 == 2.0);
    CHECK(s->luminaires[0].has_intensity && s->luminaires[0].intensity_cd == 1200.0);
    CHECK(s->luminaires[1].has_flux && s->luminaires[1].flux_lm == 3000.0);
    CHECK(s->luminaires[2].has_flux && s->luminaires[2].flux_lm == 2500.0);
    /* 1 fc = 1 lm/ft^2 with the international foot of 0.3048 m. */
    CHECK_REL(s->luminaires[3].illuminance_lx, 46.45 / (0.3048 * 0.3048), 1e-15);
    CHECK(s->luminaires[4].has_luminance && s->luminaires[4].luminance_cd_m2 == 1200.0);
    /* 1 fL = (1/pi) cd/ft^2. */
    CHECK_REL(s->luminaires[5].luminance_cd_m2, 10.0 / (CDL_PI * 0.3048 * 0.3048), 1e-15);
    CHECK(s->luminaires[6].has_flux && s->luminaires[6].flux_lm == 1200.0);
    cdl_scene_release(s);
}

int main(void)
{
    cdl_error err;
    cdl_scene *s = NULL;
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';

    /* Absolute path: files resolve to the scene's folder. */
    CHECK_OK(cdl_scene_load(DATA "design_example.json", &s, &err), &err);
    if (s) {
        CHECK(strcmp(s->base_dir, CANDELA_SOURCE_DIR "/tests/data/scene") == 0);
        check_design_example(s, CANDELA_SOURCE_DIR "/tests/data/scene");
        cdl_scene_release(s);
    }

    /* Relative path from another working directory: the mesh file is still
     * found (it is read at load time) and paths are relative to the scene. */
    CHECK(chdir(CANDELA_SOURCE_DIR "/tests") == 0);
    CHECK_OK(cdl_scene_load("data/scene/design_example.json", &s, &err), &err);
    if (s) {
        check_design_example(s, "data/scene");
        cdl_scene_release(s);
    }
    CHECK(chdir(CANDELA_SOURCE_DIR "/tests/data/scene") == 0);
    CHECK_OK(cdl_scene_load("design_example.json", &s, &err), &err);
    if (s) {
        CHECK(strcmp(s->surfaces[2].file, "cube.obj") == 0);
        cdl_scene_release(s);
    }
    /* From the build tree, where there is no cube.obj: same result. */
    CHECK(chdir(CANDELA_TEST_TMPDIR) == 0);
    CHECK_OK(cdl_scene_load(DATA "design_example.json", &s, &err), &err);
    if (s) {
        CHECK(s->surfaces[2].mesh_triangle_count == 12);
        cdl_scene_release(s);
    }
    /* The same text loaded as if it lived elsewhere looks for its mesh there. */
    FILE *fp = fopen(DATA "design_example.json", "rb");
    char text[8192];
    size_t n = fp ? fread(text, 1, sizeof text - 1, fp) : 0;
    if (fp) fclose(fp);
    text[n] = '\0';
    cdl_error_clear(&err);
    CHECK(cdl_scene_load_string(text, "/nonexistent/folder/office.json", &s, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "office.json: surfaces[2].file: /nonexistent/folder/cube.obj: cannot open") != NULL,
              "%s", err.message);
    if (cwd[0]) CHECK(chdir(cwd) == 0);

    check_defaults();
    check_quantities_with_units();
    return check_finish();
}
