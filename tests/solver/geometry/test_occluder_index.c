/* The occluder index: exact "is anything inside this convex region?" answers. */
#include <math.h>
#include <stdint.h>

#include "check.h"
#include "solver/geometry/occluder_index.h"

/* A 4 x 4 m floor at z = 0 (owner 0), a 0.5 x 0.5 m plate at z = 1.5 over
 * (1..1.5, 1..1.5) (owner 1), a ceiling at z = 3 (owner 2), a sphere of radius
 * 0.2 at (3, 3, 1) (owner 3). */
static const double V[] = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0,
                           1, 1, 1.5, 1.5, 1, 1.5, 1.5, 1.5, 1.5, 1, 1.5, 1.5,
                           0, 0, 3, 4, 0, 3, 4, 4, 3, 0, 4, 3};
static const uint32_t T[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11};
static const uint32_t TO[] = {0, 0, 1, 1, 2, 2};
static const double SC[] = {3, 3, 1};
static const double SR[] = {0.2};
static const uint32_t SO[] = {3};

int main(void)
{
    cdl_error err;
    cdl_occluder_index *ix = NULL;
    cdl_occluder_input in = {V, T, TO, 6, SC, SR, SO, 1};
    CHECK_OK(cdl_occluder_index_build(&in, &ix, &err), &err);
    if (!ix) return check_finish();
    CHECK(cdl_occluder_index_primitive_count(ix) == 7);
    const double tol = 1e-6;
    cdl_convex_region r;

    /* A box between floor and ceiling away from the plate and sphere: empty,
     * even though its faces touch the floor and the ceiling planes. */
    cdl_region_box(&r, cdl_vec3_make(2, 0.2, 0.0), cdl_vec3_make(2.5, 0.8, 3.0));
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));
    /* Extending it below the floor catches the floor. */
    cdl_region_box(&r, cdl_vec3_make(2, 0.2, -0.1), cdl_vec3_make(2.5, 0.8, 3.0));
    CHECK(cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));
    /* ... unless the floor's owner is excluded. */
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, 0));
    /* A box around the plate's edge. */
    cdl_region_box(&r, cdl_vec3_make(1.4, 1.4, 1.0), cdl_vec3_make(2.0, 2.0, 2.0));
    CHECK(cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));

    /* Pyramid from a floor point to a ceiling panel: blocked by the plate
     * when the point is under it, clear when beside it. */
    const cdl_vec3 panel[4] = {{1, 1, 3}, {1.5, 1, 3}, {1.5, 1.5, 3}, {1, 1.5, 3}};
    CHECK(cdl_region_pyramid(&r, cdl_vec3_make(1.25, 1.25, 0.0), panel, 4));
    CHECK(cdl_occluder_index_intersects(ix, &r, tol, 2));
    CHECK(cdl_region_pyramid(&r, cdl_vec3_make(3.5, 0.5, 0.0), panel, 4));
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, 2));
    /* The ceiling the panel is set into touches the pyramid's base: not an occluder. */
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));
    /* A point in the panel's plane gives no usable pyramid. */
    CHECK(!cdl_region_pyramid(&r, cdl_vec3_make(3, 3, 3), panel, 4));

    /* Near miss: from (0.2, 0.2, 0) the pyramid to the panel spans
     * x, y in [0.2 + 0.5 (1 - 0.2), 0.2 + 0.5 (1.5 - 0.2)] = [0.6, 0.85] at
     * z = 1.5, beside the plate (1 .. 1.5): clear. */
    CHECK(cdl_region_pyramid(&r, cdl_vec3_make(0.2, 0.2, 0.0), panel, 4));
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, 2));
    /* From (0.6, 0.6, 0) it spans [0.8, 1.05] there: it clips the plate's corner. */
    CHECK(cdl_region_pyramid(&r, cdl_vec3_make(0.6, 0.6, 0.0), panel, 4));
    CHECK(cdl_occluder_index_intersects(ix, &r, tol, 2));

    /* The sphere: a box around it, and one beside it. */
    cdl_region_box(&r, cdl_vec3_make(2.9, 2.9, 0.9), cdl_vec3_make(3.1, 3.1, 1.1));
    CHECK(cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));
    cdl_region_box(&r, cdl_vec3_make(3.3, 3.3, 0.5), cdl_vec3_make(3.9, 3.9, 2.5));
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));

    /* The view region of a sphere contains the segment to its near point and
     * excludes points beyond the sphere's centre plane. */
    cdl_region_sphere_view(&r, cdl_vec3_make(0, 0, 0), cdl_vec3_make(10, 0, 0), 1.0);
    int inside = 1;
    for (int p = 0; p < r.plane_count; ++p) {
        const cdl_halfspace *h = &r.planes[p];
        /* (9, 0, 0): the sphere's near point; (5, 0.4, 0): on the way to the
         * tangent point (10 cos^2 a, 10 cos a sin a, 0) ~ (9.9, 0.99, 0). */
        if (h->normal.x * 9.0 > h->offset + 1e-12) inside = 0;
        if (h->normal.x * 5.0 + h->normal.y * 0.4 > h->offset + 1e-12) inside = 0;
    }
    CHECK(inside);
    int beyond_excluded = 0;
    for (int p = 0; p < r.plane_count; ++p)
        if (r.planes[p].normal.x * 10.5 > r.planes[p].offset) beyond_excluded = 1;
    CHECK(beyond_excluded);

    cdl_occluder_index_release(ix);

    /* An empty index intersects nothing. */
    cdl_occluder_input none = {NULL, NULL, NULL, 0, NULL, NULL, NULL, 0};
    CHECK_OK(cdl_occluder_index_build(&none, &ix, &err), &err);
    cdl_region_box(&r, cdl_vec3_make(-1e9, -1e9, -1e9), cdl_vec3_make(1e9, 1e9, 1e9));
    CHECK(!cdl_occluder_index_intersects(ix, &r, tol, UINT32_MAX));
    cdl_occluder_index_release(ix);
    return check_finish();
}
