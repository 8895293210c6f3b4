/* Scene geometry: each surface type's triangles against closed-form areas,
 * their normals on the documented side, emitting shapes, area luminaires
 * as pieces, and bounds. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "solver/scene/scene_geometry.h"

#define DATA CANDELA_SOURCE_DIR "/tests/data/scene/"
#define GRIDS "\"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]"

/* Normals are compared as cosines with 1: normalising multiplies by 1/|n|,
 * which leaves the cosine within a few ulps of 1 (hence 1e-15 below, where
 * exact arithmetic would give exactly 1). */
typedef struct triangle_sums {
    double area;         /* sum of triangle areas */
    cdl_vec3 vector_area; /* sum of (b - a) x (c - a) / 2: area times normal for planar pieces */
    double min_dot;      /* smallest cosine between a triangle's normal and `expected` */
} triangle_sums;

static triangle_sums piece_sums(const cdl_scene_geometry *g, size_t id, cdl_vec3 expected)
{
    const double *xyz;
    const uint32_t *tri;
    size_t nv;
    size_t nt = cdl_scene_geometry_piece_triangles(g, id, &xyz, &nv, &tri);
    triangle_sums s = {0.0, {0, 0, 0}, 2.0};
    for (size_t t = 0; t < nt; ++t) {
        const double *a = &xyz[3 * tri[3 * t]], *b = &xyz[3 * tri[3 * t + 1]], *c = &xyz[3 * tri[3 * t + 2]];
        cdl_vec3 n = cdl_vec3_scale(cdl_vec3_cross(cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
                                                   cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2])),
                                    0.5);
        s.area += cdl_vec3_length(n);
        s.vector_area = cdl_vec3_add(s.vector_area, n);
        s.min_dot = fmin(s.min_dot, cdl_vec3_dot(cdl_vec3_normalize(n), expected));
    }
    return s;
}

static cdl_scene_geometry *build(const char *json, cdl_scene **scene)
{
    cdl_error err;
    *scene = NULL;
    cdl_scene_geometry *g = NULL;
    CHECK_OK(cdl_scene_load_string(json, DATA "geometry.json", scene, &err), &err);
    if (*scene) CHECK_OK(cdl_scene_geometry_build(*scene, &g, &err), &err);
    return g;
}

static void test_rects_polygons_meshes(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": ["
        /* 0: a 2 x 3 rect facing +z; 1: the same facing -z (v flipped) */
        "{\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [2,0,0], \"v\": [0,3,0], \"reflectance\": 0.25},"
        "{\"type\": \"rect\", \"origin\": [0,3,1], \"u\": [2,0,0], \"v\": [0,-3,0], \"reflectance\": 0.5, \"luminance_cd_m2\": 500},"
        /* 2: a 4 x 4 square with a 1 x 1 hole, counter-clockwise from +z: area 15 */
        "{\"type\": \"polygon\", \"vertices\": [[0,0,3],[4,0,3],[4,4,3],[0,4,3]],"
        " \"holes\": [[[1,1,3],[1,2,3],[2,2,3],[2,1,3]]], \"reflectance\": 0.7, \"two_sided\": false},"
        /* 3: the same outline clockwise from +z: faces -z */
        "{\"type\": \"polygon\", \"vertices\": [[0,0,5],[0,4,5],[4,4,5],[4,0,5]], \"reflectance\": 0.7},"
        /* 4: a vertical L-shaped wall in the plane x = 1, counter-clockwise seen from +x: area 2 x 3 - 1 x 1 = 5 */
        "{\"type\": \"polygon\", \"vertices\": [[1,0,0],[1,2,0],[1,2,2],[1,1,2],[1,1,3],[1,0,3]], \"reflectance\": 0.1},"
        /* 5: a tilted triangle inline; 6: the unit cube from a binary PLY file */
        "{\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,1],[0,1,0]], \"triangles\": [[0,1,2]], \"reflectance\": 0.3},"
        "{\"type\": \"mesh\", \"file\": \"cube_be.ply\", \"reflectance\": 0.5}"
        "], " GRIDS "}";
    cdl_scene *scene;
    cdl_scene_geometry *g = build(json, &scene);
    if (!g) {
        cdl_scene_release(scene);
        return;
    }
    CHECK(cdl_scene_geometry_piece_count(g) == 7);

    /* Rects: two triangles, area |u x v| = 6, normal u x v. */
    const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, 0);
    triangle_sums s = piece_sums(g, 0, cdl_vec3_make(0, 0, 1));
    CHECK(p->triangle_count == 2 && p->area == 6.0 && p->reflectance == 0.25 && p->two_sided == 1);
    CHECK(p->shape.kind == CDL_SHAPE_RECT && p->shape.u.x == 2.0 && p->shape.v.y == 3.0);
    CHECK(p->is_luminaire == 0 && p->source_index == 0 && p->box_face == -1 && p->luminance_cd_m2 == 0.0);
    /* Small integers: exact. */
    CHECK(s.area == 6.0);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    p = cdl_scene_geometry_piece(g, 1);
    s = piece_sums(g, 1, cdl_vec3_make(0, 0, -1));
    CHECK(s.area == 6.0);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    CHECK(p->luminance_cd_m2 == 500.0 && p->shape.kind == CDL_SHAPE_RECT && p->shape.v.y == -3.0);

    /* Polygons: CGAL's triangles cover area minus holes, all facing the front. */
    p = cdl_scene_geometry_piece(g, 2);
    s = piece_sums(g, 2, cdl_vec3_make(0, 0, 1));
    CHECK(p->triangle_count == 8 && p->shape.kind == CDL_SHAPE_TRIANGLES && p->shape.triangle_count == 8);
    CHECK(p->two_sided == 0);
    CHECK_REL(s.area, 15.0, 1e-15);       /* sums of exact small products */
    CHECK_REL(p->area, 15.0, 1e-15);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    s = piece_sums(g, 3, cdl_vec3_make(0, 0, -1));
    CHECK_REL(s.area, 16.0, 1e-15);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    p = cdl_scene_geometry_piece(g, 4);
    s = piece_sums(g, 4, cdl_vec3_make(1, 0, 0));
    CHECK_REL(s.area, 5.0, 1e-15);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    /* The triangles use the polygon's own vertices: every one on x = 1 exactly. */
    const double *xyz;
    const uint32_t *tri;
    size_t nv;
    cdl_scene_geometry_piece_triangles(g, 4, &xyz, &nv, &tri);
    int on_plane = nv == 6;
    for (size_t v = 0; v < nv; ++v) on_plane &= xyz[3 * v] == 1.0;
    CHECK(on_plane);

    /* Meshes: area of the tilted triangle |(1,0,1) x (0,1,0)| / 2 = sqrt(2) / 2. */
    p = cdl_scene_geometry_piece(g, 5);
    s = piece_sums(g, 5, cdl_vec3_normalize(cdl_vec3_make(-1, 0, 1)));
    CHECK_REL(p->area, sqrt(2.0) / 2.0, 1e-15);
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    p = cdl_scene_geometry_piece(g, 6);
    CHECK(p->triangle_count == 12 && p->area == 6.0 && p->shape.kind == CDL_SHAPE_TRIANGLES);
    CHECK(cdl_scene_geometry_triangle_count(g) == 2 + 2 + 8 + 2 + 4 + 1 + 12);

    /* Bounds: x in [0, 4], y in [0, 4], z in [0, 5]. */
    cdl_vec3 lo, hi;
    cdl_scene_geometry_bounds(g, &lo, &hi);
    CHECK(lo.x == 0 && lo.y == 0 && lo.z == 0 && hi.x == 4 && hi.y == 4 && hi.z == 5);
    CHECK_REL(cdl_scene_geometry_extent(g), sqrt(16.0 + 16.0 + 25.0), 1e-15);
    CHECK(cdl_scene_geometry_piece(g, 7) == NULL);
    cdl_scene_geometry_release(g);
    cdl_scene_release(scene);
}

/* A box's face normal must point away from (outward) or towards (inward) its centre. */
static void check_box(const cdl_scene_geometry *g, size_t first, size_t count, int inward, const double *areas)
{
    for (size_t i = first; i < first + count; ++i) {
        const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, i);
        cdl_vec3 centre = cdl_vec3_make(2, 2.5, 1.5);
        const double *xyz;
        const uint32_t *tri;
        size_t nv;
        size_t nt = cdl_scene_geometry_piece_triangles(g, i, &xyz, &nv, &tri);
        CHECK(nt == 2 && nv == 4);
        cdl_vec3 face = cdl_vec3_make(0.25 * (xyz[0] + xyz[3] + xyz[6] + xyz[9]), 0.25 * (xyz[1] + xyz[4] + xyz[7] + xyz[10]),
                                      0.25 * (xyz[2] + xyz[5] + xyz[8] + xyz[11]));
        cdl_vec3 out = cdl_vec3_normalize(cdl_vec3_sub(face, centre));
        /* Each face's centre lies on the axis of its outward normal. */
        cdl_vec3 axis = cdl_vec3_make(round(out.x), round(out.y), round(out.z));
        cdl_vec3 expected = inward ? cdl_vec3_neg(axis) : axis;
        triangle_sums s = piece_sums(g, i, expected);
        CHECK_MSG(fabs(s.min_dot - 1.0) <= 1e-15, "box face %d: normal off by cos %g", p->box_face, s.min_dot);
        CHECK(s.area == areas[p->box_face] && p->area == areas[p->box_face]);
        /* The analytic rect agrees: u x v along the front normal. */
        cdl_vec3 uxv = cdl_vec3_cross(p->shape.u, p->shape.v);
        CHECK(p->shape.kind == CDL_SHAPE_RECT);
        CHECK_ABS(cdl_vec3_dot(cdl_vec3_normalize(uxv), expected), 1.0, 1e-15);
        /* Face index matches its axis: -x, +x, -y, +y, -z, +z. */
        int k = axis.x != 0 ? 0 : axis.y != 0 ? 2 : 4;
        if (axis.x > 0 || axis.y > 0 || axis.z > 0) ++k;
        CHECK(p->box_face == k);
    }
}

static void test_boxes(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": ["
        "{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,5,3], \"reflectance\": 0.5},"
        "{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,5,3], \"inward\": true, \"open\": [\"ceiling\"],"
        " \"reflectance\": {\"floor\": 0.2, \"walls\": 0.6}, \"luminance_cd_m2\": 10},"
        "{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,5,3], \"inward\": true, \"open\": [\"-x\", \"+y\"],"
        " \"reflectance\": {\"+x\": 0.1, \"-y\": 0.2, \"-z\": 0.3, \"+z\": 0.4}}"
        "], " GRIDS "}";
    cdl_scene *scene;
    cdl_scene_geometry *g = build(json, &scene);
    if (!g) {
        cdl_scene_release(scene);
        return;
    }
    /* Face areas: x faces 5 x 3, y faces 4 x 3, z faces 4 x 5. */
    const double areas[6] = {15, 15, 12, 12, 20, 20};
    CHECK(cdl_scene_geometry_piece_count(g) == 6 + 5 + 4);
    check_box(g, 0, 6, 0, areas);
    check_box(g, 6, 5, 1, areas);
    check_box(g, 11, 4, 1, areas);
    for (size_t i = 6; i < 11; ++i) {
        const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, i);
        CHECK(p->source_index == 1 && p->box_face != CDL_BOX_POS_Z && p->luminance_cd_m2 == 10.0);
        CHECK(p->reflectance == (p->box_face == CDL_BOX_NEG_Z ? 0.2 : 0.6));
    }
    const double rho[6] = {-1, 0.1, 0.2, -1, 0.3, 0.4};
    for (size_t i = 11; i < 15; ++i) {
        const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, i);
        CHECK(p->box_face != CDL_BOX_NEG_X && p->box_face != CDL_BOX_POS_Y && p->reflectance == rho[p->box_face]);
    }
    /* Watertight: a ray from inside towards an edge of the closed box
     * (robust mode, shared corners) always hits; scan across the x = 4, y = 5 edge. */
    const cdl_ray_scene *rays = cdl_scene_geometry_rays(g);
    int all_hit = 1;
    for (int k = -50; k <= 50; ++k) {
        cdl_vec3 target = cdl_vec3_make(4.0 + k * 1e-7, 5.0 - k * 1e-7, 1.5);
        cdl_vec3 o = cdl_vec3_make(2, 2.5, 1.5);
        cdl_ray_hit hit;
        all_hit &= cdl_ray_scene_intersect(rays, o, cdl_vec3_normalize(cdl_vec3_sub(target, o)), 0.0, INFINITY, &hit);
    }
    CHECK(all_hit);
    cdl_scene_geometry_release(g);
    cdl_scene_release(scene);
}

static void test_disks_spheres_luminaires(void)
{
    const char *json =
        "{\"version\": 1, \"surfaces\": ["
        "{\"type\": \"disk\", \"center\": [1,2,3], \"normal\": [0,1,1], \"radius\": 0.5, \"reflectance\": 0.4,"
        " \"luminance_cd_m2\": 100},"
        "{\"type\": \"sphere\", \"center\": [5,0,0], \"radius\": 2, \"reflectance\": 0.5},"
        "{\"type\": \"sphere\", \"center\": [-5,0,0], \"radius\": 1, \"inward\": true, \"reflectance\": 0.5,"
        " \"luminance_cd_m2\": 7}"
        "], \"luminaires\": ["
        "{\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1},"
        "{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [1,1,2.99], \"u\": [0.6,0,0], \"v\": [0,-0.6,0]},"
        " \"flux_lm\": 1000, \"maintenance_factor\": 0.8},"
        "{\"type\": \"area\", \"shape\": {\"type\": \"disk\", \"center\": [0,0,3], \"normal\": [0,0,-1], \"radius\": 0.1},"
        " \"luminance_cd_m2\": 2000, \"reflectance\": 0.3},"
        "{\"type\": \"area\", \"shape\": {\"type\": \"polygon\", \"vertices\": [[0,0,4],[0,1,4],[1,1,4],[1,0,4]]},"
        " \"flux_lm\": 100}"
        "], " GRIDS "}";
    cdl_scene *scene;
    cdl_scene_geometry *g = build(json, &scene);
    if (!g) {
        cdl_scene_release(scene);
        return;
    }
    CHECK(cdl_scene_geometry_piece_count(g) == 6);

    /* Disk: the exact disk for emitters, a fan for rays. */
    const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, 0);
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0, 1, 1));
    CHECK(p->shape.kind == CDL_SHAPE_DISK && p->shape.radius == 0.5 && p->luminance_cd_m2 == 100.0);
    CHECK_ABS(cdl_vec3_dot(p->shape.normal, n), 1.0, 1e-15);
    CHECK_REL(p->area, CDL_PI * 0.25, 1e-15);
    size_t segments = p->triangle_count;
    triangle_sums s = piece_sums(g, 0, n);
    /* An inscribed regular N-gon has area (N/2) r^2 sin(2 pi / N). */
    CHECK_REL(s.area, 0.5 * segments * 0.25 * sin(CDL_TWO_PI / segments), 1e-12);
    CHECK_ABS(s.min_dot, 1.0, 1e-12);
    /* Chord error (sagitta) r (1 - cos(pi / N)) below 1e-4 r. */
    CHECK(1.0 - cos(CDL_PI / segments) < 1e-4);
    const double *xyz;
    const uint32_t *tri;
    size_t nv;
    cdl_scene_geometry_piece_triangles(g, 0, &xyz, &nv, &tri);
    double worst = 0.0;
    for (size_t v = 1; v < nv; ++v) {
        cdl_vec3 d = cdl_vec3_make(xyz[3 * v] - 1, xyz[3 * v + 1] - 2, xyz[3 * v + 2] - 3);
        worst = fmax(worst, fabs(cdl_vec3_length(d) - 0.5) + fabs(cdl_vec3_dot(d, n)));
    }
    CHECK_MSG(worst < 1e-15, "rim off the circle by %g", worst);

    /* Spheres: exact, no triangles. */
    p = cdl_scene_geometry_piece(g, 1);
    CHECK(p->triangle_count == 0 && p->shape.kind == CDL_SHAPE_SPHERE && p->shape.radius == 2.0 && !p->shape.inward);
    CHECK_REL(p->area, 16.0 * CDL_PI, 1e-15);
    p = cdl_scene_geometry_piece(g, 2);
    CHECK(p->shape.inward == 1 && p->luminance_cd_m2 == 7.0);
    const cdl_ray_scene *rays = cdl_scene_geometry_rays(g);
    cdl_ray_hit hit;
    /* From the sphere's centre outward: the hit is at t = r (float precision, 1e-6 relative). */
    CHECK(cdl_ray_scene_intersect(rays, cdl_vec3_make(5, 0, 0), cdl_vec3_normalize(cdl_vec3_make(1, 2, 3)), 0, INFINITY, &hit));
    CHECK(hit.geom_id == 1);
    CHECK_REL(hit.t, 2.0, 1e-6);

    /* Area luminaires come after the surfaces, in luminaire order. */
    p = cdl_scene_geometry_piece(g, 3);
    CHECK(p->is_luminaire == 1 && p->source_index == 1 && p->reflectance == 0.0 && p->shape.kind == CDL_SHAPE_RECT);
    /* Lambertian: flux = pi L A, times the maintenance factor. */
    CHECK_REL(p->luminance_cd_m2, 0.8 * 1000.0 / (CDL_PI * 0.36), 1e-14);
    CHECK_REL(p->area, 0.36, 1e-14);
    s = piece_sums(g, 3, cdl_vec3_make(0, 0, -1));
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    p = cdl_scene_geometry_piece(g, 4);
    CHECK(p->is_luminaire && p->source_index == 2 && p->luminance_cd_m2 == 2000.0 && p->reflectance == 0.3 &&
          p->shape.kind == CDL_SHAPE_DISK);
    s = piece_sums(g, 4, cdl_vec3_make(0, 0, -1));
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    p = cdl_scene_geometry_piece(g, 5);
    /* The polygon is clockwise seen from +z: it emits downwards, area 1. */
    CHECK(p->is_luminaire && p->source_index == 3 && p->shape.kind == CDL_SHAPE_TRIANGLES);
    CHECK_REL(p->luminance_cd_m2, 100.0 / CDL_PI, 1e-15);
    s = piece_sums(g, 5, cdl_vec3_make(0, 0, -1));
    CHECK_ABS(s.min_dot, 1.0, 1e-15);
    CHECK(s.area == 1.0);
    /* A luminaire blocks light: a ray up from below the polygon hits it. */
    CHECK(cdl_ray_scene_intersect(rays, cdl_vec3_make(0.5, 0.5, 3.5), cdl_vec3_make(0, 0, 1), 0, INFINITY, &hit));
    CHECK(hit.geom_id == 5);
    cdl_scene_geometry_release(g);
    cdl_scene_release(scene);
}

int main(void)
{
    test_rects_polygons_meshes();
    test_boxes();
    test_disks_spheres_luminaires();

    /* A shape whose area underflows is refused (its flux would divide by zero). */
    cdl_scene *scene = NULL;
    cdl_scene_geometry *g = NULL;
    cdl_error err;
    CHECK_OK(cdl_scene_load_string("{\"version\": 1, \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": "
                                   "\"disk\", \"center\": [0,0,0], \"normal\": [0,0,1], \"radius\": 1e-200},"
                                   " \"flux_lm\": 10}], " GRIDS "}",
                                   "tiny.json", &scene, &err),
             &err);
    if (scene) {
        g = NULL;
        cdl_error_clear(&err);
        CHECK(cdl_scene_geometry_build(scene, &g, &err) == CDL_ERR_INPUT && g == NULL);
        CHECK_MSG(strstr(err.message, "tiny.json: luminaires[0].shape: expected a surface of non-zero, finite area") != NULL,
                  "%s", err.message);
        cdl_scene_release(scene);
    }

    /* An empty scene has no pieces and zero extent. */
    g = build("{\"version\": 1, " GRIDS "}", &scene);
    if (g) {
        CHECK(cdl_scene_geometry_piece_count(g) == 0 && cdl_scene_geometry_extent(g) == 0.0);
        CHECK(!cdl_scene_geometry_ray_occluded(g, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1),
                                               cdl_vec3_make(0, 0, 1), INFINITY));
        cdl_scene_geometry_release(g);
    }
    cdl_scene_release(scene);
    return check_finish();
}
