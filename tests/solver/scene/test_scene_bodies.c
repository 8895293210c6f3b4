/* Luminaire bodies as geometry (solver/scene/scene_bodies.h): each shape of
 * opening placed and turned with its luminaire, against closed forms -
 * areas (a box's 2 (LW + LH + WH), a 224-sided prism's sides and caps),
 * every vertex on the surface it stands for, every triangle facing out
 * (a flat body: away from its opening) - plus one body per array copy,
 * none with "body": false, the reflectances, and a ray through a body
 * blocked unless that body is left out. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "radiometry/constants.h"
#include "solver/scene/scene_geometry.h"

static char folder[512];

/* LM-63-2002 with the opening "W L H", one plane, 100 cd down. */
static void write_ies(const char *name, const char *opening)
{
    char path[700], text[400];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    snprintf(text, sizeof text,
             "IESNA:LM-63-2002\n[TEST] body\nTILT=NONE\n1 -1 1 3 1 1 2 %s\n1 1 0\n0 90 180\n0\n100 0 0\n", opening);
    CHECK(fixture_write_file(path, text));
}

typedef struct mesh_check {
    double area;
    double worst_out;     /* smallest cosine of a triangle's normal with its outward direction */
} mesh_check;

/* Area and facing of a piece's triangles; outward: from `centre` to the
 * triangle's centroid (a solid) or along `front` (a flat body). */
static mesh_check check_mesh(const cdl_scene_geometry *g, uint32_t id, cdl_vec3 centre, const cdl_vec3 *front)
{
    const double *xyz;
    const uint32_t *tri;
    size_t nv, nt = cdl_scene_geometry_piece_triangles(g, id, &xyz, &nv, &tri);
    mesh_check m = {0.0, 2.0};
    for (size_t t = 0; t < nt; ++t) {
        cdl_vec3 v[3];
        for (int k = 0; k < 3; ++k) v[k] = cdl_vec3_make(xyz[3 * tri[3 * t + k]], xyz[3 * tri[3 * t + k] + 1], xyz[3 * tri[3 * t + k] + 2]);
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_sub(v[1], v[0]), cdl_vec3_sub(v[2], v[0]));
        m.area += 0.5 * cdl_vec3_length(n);
        cdl_vec3 out = front ? *front
                             : cdl_vec3_sub(cdl_vec3_scale(cdl_vec3_add(cdl_vec3_add(v[0], v[1]), v[2]), 1.0 / 3.0), centre);
        m.worst_out = fmin(m.worst_out, cdl_vec3_dot(cdl_vec3_normalize(n), cdl_vec3_normalize(out)));
    }
    return m;
}

int main(void)
{
    CHECK(fixture_folder("scene_bodies", folder, sizeof folder));
    write_ies("rect.ies", "0.3 1.2 0");    /* flat rectangle: L 1.2 along x, W 0.3 along y */
    write_ies("box.ies", "0.2 0.6 0.1");   /* luminous box */
    write_ies("cyl.ies", "-0.4 -0.4 0.5"); /* vertical cylinder, diameter 0.4, 0.5 tall */
    write_ies("ball.ies", "-0.3 -0.3 -0.3");
    write_ies("egg.ies", "-0.2 -0.6 -0.4"); /* ellipsoid: semi-axes 0.3 (x), 0.1 (y), 0.2 (z) */
    write_ies("point.ies", "0 0 0");
    char json[8000];
    snprintf(json, sizeof json,
             "{\"version\": 1, \"luminaires\": ["
             "{\"type\": \"goniometric\", \"file\": \"%s/rect.ies\", \"position\": [0, 0, 3], \"rotation\": [0, 0, 90]},"
             "{\"type\": \"goniometric\", \"file\": \"%s/box.ies\", \"position\": [2, 0, 3], \"rotation\": [30, 0, 0],"
             " \"body\": {\"reflectance\": 0.6}},"
             "{\"type\": \"goniometric\", \"file\": \"%s/cyl.ies\", \"position\": [4, 0, 3]},"
             "{\"type\": \"goniometric\", \"file\": \"%s/ball.ies\", \"position\": [6, 0, 3]},"
             "{\"type\": \"goniometric\", \"file\": \"%s/egg.ies\", \"position\": [8, 0, 3]},"
             "{\"type\": \"goniometric\", \"file\": \"%s/point.ies\", \"position\": [10, 0, 3]},"
             "{\"type\": \"goniometric\", \"file\": \"%s/rect.ies\", \"position\": [0, 5, 3], \"body\": false},"
             "{\"type\": \"goniometric\", \"file\": \"%s/box.ies\", \"position\": [0, 8, 3],"
             " \"array\": {\"counts\": [3, 1], \"spacing\": [1, 1]}}],"
             " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0, 0, 0], \"n\": [0, 0, 1]}]}]}",
             folder, folder, folder, folder, folder, folder, folder, folder);
    cdl_scene *scene = NULL;
    cdl_scene_geometry *g = NULL;
    cdl_error err;
    CHECK_OK(cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/bodies.json", &scene, &err), &err);
    if (scene) CHECK_OK(cdl_scene_geometry_build(scene, &g, &err), &err);
    if (!g) {
        cdl_scene_release(scene);
        return check_finish();
    }
    /* 5 bodies, none for the point and for "body": false, 3 for the array */
    CHECK(cdl_scene_geometry_piece_count(g) == 8);
    CHECK(cdl_scene_geometry_luminaire_body(g, 5) == UINT32_MAX && cdl_scene_geometry_luminaire_body(g, 6) == UINT32_MAX);
    for (size_t k = 7; k < 10; ++k) CHECK(cdl_scene_geometry_luminaire_body(g, k) != UINT32_MAX);

    /* the rectangle, turned 90 degrees about z: 1.2 along y, 0.3 along x,
     * facing up (away from its opening), reflectance 0 (the opening alone) */
    uint32_t id = cdl_scene_geometry_luminaire_body(g, 0);
    const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, id);
    cdl_vec3 up = cdl_vec3_make(0, 0, 1);
    mesh_check m = check_mesh(g, id, cdl_vec3_make(0, 0, 3), &up);
    /* sums of products of the file's sizes: rounding only */
    CHECK_REL(m.area, 0.36, 1e-12);
    CHECK(m.worst_out > 1.0 - 1e-12);
    CHECK(p->is_body && p->is_luminaire && p->source_index == 0 && p->reflectance == 0.0 && !p->curved &&
          !p->two_sided);
    const double *xyz;
    const uint32_t *tri;
    size_t nv;
    cdl_scene_geometry_piece_triangles(g, id, &xyz, &nv, &tri);
    for (size_t v = 0; v < nv; ++v)
        CHECK_MSG(fabs(fabs(xyz[3 * v]) - 0.15) < 1e-12 && fabs(fabs(xyz[3 * v + 1]) - 0.6) < 1e-12 &&
                      xyz[3 * v + 2] == 3.0,
                  "rectangle corner (%g, %g, %g)", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);

    /* the luminous box, tilted 30 degrees: 2 (LW + LH + WH), outward, its reflectance */
    id = cdl_scene_geometry_luminaire_body(g, 1);
    m = check_mesh(g, id, cdl_vec3_make(2, 0, 3), NULL);
    CHECK_REL(m.area, 2.0 * (0.6 * 0.2 + 0.6 * 0.1 + 0.2 * 0.1), 1e-12);
    CHECK(m.worst_out > 0.0);
    CHECK(cdl_scene_geometry_piece(g, id)->reflectance == 0.6 && !cdl_scene_geometry_piece(g, id)->curved);

    /* the cylinder: a 224-sided prism, sides N 2 r sin(pi / N) h, caps
     * 2 (N / 2) r^2 sin(2 pi / N); every rim vertex at r from the axis */
    id = cdl_scene_geometry_luminaire_body(g, 2);
    m = check_mesh(g, id, cdl_vec3_make(4, 0, 3), NULL);
    const double N = 224.0, r = 0.2, h = 0.5;
    CHECK_REL(m.area, N * 2.0 * r * sin(CDL_PI / N) * h + N * r * r * sin(CDL_TWO_PI / N), 1e-12);
    CHECK(m.worst_out > 0.0 && cdl_scene_geometry_piece(g, id)->curved);
    cdl_scene_geometry_piece_triangles(g, id, &xyz, &nv, &tri);
    int off = 0;
    for (size_t v = 0; v < nv; ++v) {
        double rho = hypot(xyz[3 * v] - 4.0, xyz[3 * v + 1]), z = xyz[3 * v + 2] - 3.0;
        if (!(fabs(fabs(z) - 0.5 * h) < 1e-12 && (rho < 1e-12 || fabs(rho - r) < 1e-12))) off++;
    }
    CHECK_MSG(off == 0, "%d cylinder vertices off its rims", off);

    /* the sphere stays exact; the ellipsoid's vertices lie on it, facing out */
    p = cdl_scene_geometry_piece(g, cdl_scene_geometry_luminaire_body(g, 3));
    CHECK(p->shape.kind == CDL_SHAPE_SPHERE && p->shape.radius == 0.15 && p->curved);
    id = cdl_scene_geometry_luminaire_body(g, 4);
    m = check_mesh(g, id, cdl_vec3_make(8, 0, 3), NULL);
    CHECK(m.worst_out > 0.0);
    cdl_scene_geometry_piece_triangles(g, id, &xyz, &nv, &tri);
    double worst = 0.0;
    for (size_t v = 0; v < nv; ++v) {
        double x = (xyz[3 * v] - 8.0) / 0.3, y = xyz[3 * v + 1] / 0.1, z = (xyz[3 * v + 2] - 3.0) / 0.2;
        worst = fmax(worst, fabs(x * x + y * y + z * z - 1.0));
    }
    CHECK_MSG(worst < 1e-12, "ellipsoid vertices off by %g", worst);

    /* a ray through the cylinder is blocked by it, and not when it is left out */
    const cdl_ray_scene *rays = cdl_scene_geometry_rays(g);
    cdl_vec3 from = cdl_vec3_make(4, -1, 3), dir = cdl_vec3_make(0, 1, 0);
    id = cdl_scene_geometry_luminaire_body(g, 2);
    CHECK(cdl_ray_scene_occluded(rays, from, dir, 0.0, 2.0));
    CHECK(!cdl_ray_scene_occluded_except(rays, from, dir, 0.0, 2.0, id));
    CHECK(cdl_ray_scene_occluded_except(rays, from, dir, 0.0, 2.0, cdl_scene_geometry_luminaire_body(g, 1)));

    cdl_scene_geometry_release(g);
    cdl_scene_release(scene);
    return check_finish();
}
