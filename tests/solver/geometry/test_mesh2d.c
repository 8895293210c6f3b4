/* CGAL through the C shim: triangulate polygons with holes. */
#include <math.h>

#include "check.h"
#include "solver/geometry/mesh2d.h"

static double max_edge_length(const cdl_mesh2d *m)
{
    double longest = 0.0;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            const double *a = &m->xy[2 * m->triangles[3 * t + k]];
            const double *b = &m->xy[2 * m->triangles[3 * t + (k + 1) % 3]];
            longest = fmax(longest, hypot(a[0] - b[0], a[1] - b[1]));
        }
    return longest;
}

static int all_counter_clockwise(const cdl_mesh2d *m)
{
    for (size_t t = 0; t < m->triangle_count; ++t) {
        const double *a = &m->xy[2 * m->triangles[3 * t]];
        const double *b = &m->xy[2 * m->triangles[3 * t + 1]];
        const double *c = &m->xy[2 * m->triangles[3 * t + 2]];
        if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0.0) return 0;
    }
    return 1;
}

int main(void)
{
    cdl_error err;
    /* 4 x 4 square with a 1 x 1 square hole (given clockwise): area 15. */
    const double outer[] = {0, 0, 4, 0, 4, 4, 0, 4};
    const double hole[] = {1, 1, 1, 2, 2, 2, 2, 1};
    cdl_ring2d out_ring = {outer, 4};
    cdl_ring2d hole_ring = {hole, 4};
    cdl_mesh2d m;
    CHECK_OK(cdl_mesh2d_triangulate(out_ring, &hole_ring, 1, 0.0, &m, &err), &err);
    CHECK_REL(m.area, 15.0, 1e-14);
    CHECK(m.vertex_count == 8);      /* no Steiner points without refinement */
    CHECK(m.triangle_count == 8);    /* V - 2 + 2 * holes */
    CHECK(all_counter_clockwise(&m));
    cdl_mesh2d_release(&m);

    /* Refined: no edge longer than the bound, area unchanged. The EN 12464-1
     * spacing for a 10 m room is p = 0.2 * 5^log10(10) = 1 m. */
    const double room[] = {0, 0, 10, 0, 10, 8, 6, 8, 6, 5, 0, 5};
    const double column[] = {2, 2, 2.6, 2, 2.6, 2.6, 2, 2.6};
    cdl_ring2d room_ring = {room, 6}, column_ring = {column, 4};
    CHECK_OK(cdl_mesh2d_triangulate(room_ring, &column_ring, 1, 1.0, &m, &err), &err);
    CHECK_REL(m.area, 10.0 * 5.0 + 4.0 * 3.0 - 0.36, 1e-12);
    CHECK_MSG(max_edge_length(&m) <= 1.0 + 1e-12, "longest edge %g", max_edge_length(&m));
    CHECK(m.triangle_count > 60);
    CHECK(all_counter_clockwise(&m));
    cdl_mesh2d_release(&m);

    /* Degenerate input is an error, not a crash. */
    const double line[] = {0, 0, 1, 1, 2, 2};
    cdl_ring2d line_ring = {line, 3};
    CHECK(cdl_mesh2d_triangulate(line_ring, NULL, 0, 0.0, &m, &err) == CDL_ERR_INPUT);
    cdl_ring2d two = {line, 2};
    CHECK(cdl_mesh2d_triangulate(two, NULL, 0, 0.0, &m, &err) == CDL_ERR_INPUT);
    return check_finish();
}
