/* OBJ, OFF and PLY readers: the same unit cube in every format and
 * encoding, and broken files whose messages must name the file and line
 * (or, for binary PLY, the element). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/scene/mesh_file.h"

#define DATA CANDELA_SOURCE_DIR "/tests/data/scene/"

/* Closed-form checks of a unit cube [0,1]^3: surface area 6, and volume 1 by
 * the divergence theorem, V = sum over triangles of a . (b x c) / 6, which
 * is +1 only if every triangle is counter-clockwise seen from outside. */
static void check_unit_cube(const cdl_mesh_data *m, const char *what)
{
    CHECK_MSG(m->vertex_count == 8, "%s: %zu vertices", what, m->vertex_count);
    CHECK_MSG(m->triangle_count == 12, "%s: %zu triangles", what, m->triangle_count);
    double area = 0.0, volume = 0.0;
    int outward = 1;
    for (size_t t = 0; t < m->triangle_count; ++t) {
        const double *a = &m->vertices[3 * m->triangles[3 * t]], *b = &m->vertices[3 * m->triangles[3 * t + 1]],
                     *c = &m->vertices[3 * m->triangles[3 * t + 2]];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double bxc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
        volume += a[0] * bxc[0] + a[1] * bxc[1] + a[2] * bxc[2]; /* 6 V */
        /* The normal points away from the cube's centre. */
        double centroid[3] = {(a[0] + b[0] + c[0]) / 3 - 0.5, (a[1] + b[1] + c[1]) / 3 - 0.5, (a[2] + b[2] + c[2]) / 3 - 0.5};
        if (n[0] * centroid[0] + n[1] * centroid[1] + n[2] * centroid[2] <= 0.0) outward = 0;
    }
    /* Coordinates are small integers: sums are exact in double. */
    CHECK_MSG(area == 6.0, "%s: area %.17g", what, area);
    CHECK_MSG(volume == 6.0, "%s: volume %.17g", what, volume / 6.0);
    CHECK_MSG(outward, "%s: a triangle faces inward", what);
}

static void check_file(const char *path)
{
    cdl_error err;
    cdl_mesh_data m;
    CHECK_OK(cdl_mesh_file_read(path, &m, &err), &err);
    check_unit_cube(&m, path);
    cdl_mesh_data_release(&m);
}

/* Parsing `text` must fail with a message containing `fragment`. */
static void check_broken(cdl_mesh_format format, const char *text, size_t size, const char *fragment)
{
    cdl_error err;
    cdl_mesh_data m;
    cdl_error_clear(&err);
    cdl_status st = cdl_mesh_file_parse(text, size ? size : strlen(text), format, "bad.mesh", &m, &err);
    CHECK_MSG(st == CDL_ERR_INPUT, "status %d for %s", (int)st, fragment);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "message \"%s\" lacks \"%s\"", err.message, fragment);
    CHECK(m.vertices == NULL && m.triangles == NULL);
}

int main(void)
{
    check_file(DATA "cube.obj");
    check_file(DATA "cube.off");
    check_file(DATA "cube_ascii.ply");
    check_file(DATA "cube_le.ply");
    check_file(DATA "cube_be.ply");

    cdl_mesh_format f;
    CHECK(cdl_mesh_file_format_from_name("a/b/Column.OBJ", &f) && f == CDL_MESH_OBJ);
    CHECK(cdl_mesh_file_format_from_name("x.ply", &f) && f == CDL_MESH_PLY);
    CHECK(!cdl_mesh_file_format_from_name("x.stl", &f));
    CHECK(!cdl_mesh_file_format_from_name("dir.obj/file", &f));

    cdl_error err;
    cdl_mesh_data m;
    /* Homogeneous w divides; a polygon of 5 vertices becomes 3 triangles. */
    const char *pentagon = "v 0 0 0 2\nv 2 0 0 2\nv 2 2 0 2\nv 1 3 0 2\nv 0 2 0 2\nf 1 2 3 4 5\n";
    CHECK_OK(cdl_mesh_file_parse(pentagon, strlen(pentagon), CDL_MESH_OBJ, "p.obj", &m, &err), &err);
    CHECK(m.triangle_count == 3);
    CHECK(m.vertices[3 * 3 + 1] == 1.5);
    cdl_mesh_data_release(&m);
    /* Zero-area triangles are dropped, others kept. */
    const char *degenerate = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\nf 1 2 4\n";
    CHECK_OK(cdl_mesh_file_parse(degenerate, strlen(degenerate), CDL_MESH_OBJ, "d.obj", &m, &err), &err);
    CHECK(m.triangle_count == 1);
    cdl_mesh_data_release(&m);

    /* Broken OBJ files: the message names file and line. */
    check_broken(CDL_MESH_OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 0, "bad.mesh:4: expected vertex indices up to the number of vertices, found index 4 of 3 vertices");
    check_broken(CDL_MESH_OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", 0, "bad.mesh:4: expected a vertex reference");
    check_broken(CDL_MESH_OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 0, "bad.mesh:4: expected a relative index");
    check_broken(CDL_MESH_OBJ, "# c\nv 0 zero 0\n", 0, "bad.mesh:2: expected a finite number, found \"zero\"");
    check_broken(CDL_MESH_OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 0, "bad.mesh:4: expected a face of at least 3");
    check_broken(CDL_MESH_OBJ, "v 0 0\n", 0, "bad.mesh:1: expected a vertex");
    check_broken(CDL_MESH_OBJ, "v 0 0 0 0\n", 0, "bad.mesh:1: expected a non-zero w");
    check_broken(CDL_MESH_OBJ, "v 0 0 0\ncstype bspline\ncurv 0 1 1 2\n", 0, "bad.mesh:2: expected a statement");
    check_broken(CDL_MESH_OBJ, "v 1e999 0 0\n", 0, "bad.mesh:1: expected a finite number");
    check_broken(CDL_MESH_OBJ, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", 0, "expected at least one triangle of non-zero area");
    check_broken(CDL_MESH_OBJ, "", 0, "expected at least one triangle");

    /* Broken OFF files. */
    check_broken(CDL_MESH_OFF, "PLY\n3 1 0\n", 0, "bad.mesh:1: expected the header \"OFF\"");
    check_broken(CDL_MESH_OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n", 0, "bad.mesh:4: expected a vertex line");
    check_broken(CDL_MESH_OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 0,
                 "bad.mesh:6: expected a vertex index in [0, 2], found \"3\"");
    check_broken(CDL_MESH_OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 0, "bad.mesh:6: expected a vertex count n >= 3");
    check_broken(CDL_MESH_OFF, "OFF\n# comment\n3 x 0\n", 0, "bad.mesh:3: expected a face count");
    check_broken(CDL_MESH_OFF, "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nextra\n", 0,
                 "bad.mesh:6: expected the end of the file");
    /* Counts on the header line are accepted. */
    const char *inline_counts = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n";
    CHECK_OK(cdl_mesh_file_parse(inline_counts, strlen(inline_counts), CDL_MESH_OFF, "ok.off", &m, &err), &err);
    CHECK(m.triangle_count == 1);
    cdl_mesh_data_release(&m);

    /* Broken PLY files. */
    const char *ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    char text[1024];
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n", ply_head);
    check_broken(CDL_MESH_PLY, text, 0, "bad.mesh:12: vertex 2: expected a finite number, found \"one\"");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", ply_head);
    check_broken(CDL_MESH_PLY, text, 0, "bad.mesh:13: face 0: expected vertex indices in [0, 2], found 5");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n", ply_head);
    check_broken(CDL_MESH_PLY, text, 0, "face 0: expected another line of data");
    snprintf(text, sizeof text, "%s0 0 0 7\n", ply_head);
    check_broken(CDL_MESH_PLY, text, 0, "bad.mesh:10: vertex 0: expected the end of the line, found \"7\"");
    check_broken(CDL_MESH_PLY, "ply\nformat binary_middle_endian 1.0\nend_header\n", 0,
                 "bad.mesh:2: expected ascii, binary_little_endian or binary_big_endian");
    check_broken(CDL_MESH_PLY, "solid x\n", 0, "bad.mesh:1: expected the magic line \"ply\"");
    check_broken(CDL_MESH_PLY,
                 "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
                 0, "expected scalar properties x, y and z");
    check_broken(CDL_MESH_PLY, "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", 0,
                 "bad.mesh:4: expected a PLY type");
    /* A binary file cut short names the element and its index. */
    const char *bin_head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
    size_t head_len = strlen(bin_head);
    memcpy(text, bin_head, head_len);
    memset(text + head_len, 0, 36);        /* three vertices at the origin */
    text[head_len + 36] = 3;               /* face 0: 3 indices (12 bytes) */
    memset(text + head_len + 37, 0, 12);
    text[head_len + 49] = 3;               /* face 1: count, then only 2 bytes */
    check_broken(CDL_MESH_PLY, text, head_len + 52, "bad.mesh: face 1: expected a list that fits in the file");
    /* Big-endian index beyond the vertices. */
    const char *be_head = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    head_len = strlen(be_head);
    memcpy(text, be_head, head_len);
    memset(text + head_len, 0, 36 + 13);
    text[head_len + 36] = 3;
    text[head_len + 37 + 11] = 9;          /* third index = 9, big endian */
    check_broken(CDL_MESH_PLY, text, head_len + 49, "bad.mesh: face 0: expected vertex indices in [0, 2], found 9");

    /* Files that cannot be read. */
    cdl_error_clear(&err);
    CHECK(cdl_mesh_file_read(DATA "no_such_file.obj", &m, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "no_such_file.obj: cannot open") != NULL);
    CHECK(cdl_mesh_file_read(DATA "design_example.json", &m, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "expected a mesh file ending in .obj, .off or .ply") != NULL);
    return check_finish();
}
