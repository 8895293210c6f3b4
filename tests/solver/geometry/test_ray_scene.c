/* Embree: trace rays against triangles and an exact sphere. */
#include <math.h>

#include "check.h"
#include "solver/geometry/ray_scene.h"

/* Hits near a ray's ends are decided in double (ray_scene.c): a 1 km floor
 * (z = 0) and wall (x = 0), and a sphere of radius 1 at (200, 0, 50). Every
 * expected t is the line-plane (line-sphere) distance, exact to rounding. */
static void test_ends_in_double(void)
{
    cdl_error err;
    cdl_ray_scene *s = NULL;
    CHECK_OK(cdl_ray_scene_create(&s, &err), &err);
    if (!s) return;
    const double floor_xyz[] = {-500, -500, 0, 500, -500, 0, 500, 500, 0, -500, 500, 0};
    const double wall_xyz[] = {0, -500, 0, 0, 500, 0, 0, 500, 1000, 0, -500, 1000};
    const uint32_t quad[] = {0, 1, 2, 0, 2, 3};
    uint32_t floor_id, wall_id, sphere_id;
    CHECK_OK(cdl_ray_scene_add_triangles(s, floor_xyz, 4, quad, 2, &floor_id, &err), &err);
    CHECK_OK(cdl_ray_scene_add_triangles(s, wall_xyz, 4, quad, 2, &wall_id, &err), &err);
    CHECK_OK(cdl_ray_scene_add_sphere(s, cdl_vec3_make(200, 0, 50), 1.0, &sphere_id, &err), &err);
    CHECK_OK(cdl_ray_scene_commit(s, &err), &err);
    cdl_ray_hit hit;
    /* From the floor 0.1 mm off the wall's foot, towards the wall and up
     * 0.1 %: the wall at t = 1e-4 / |dx|, not the floor the ray starts on. */
    cdl_vec3 d = cdl_vec3_normalize(cdl_vec3_make(-1, 0, 1e-3));
    CHECK(cdl_ray_scene_intersect(s, cdl_vec3_make(1e-4, 0, 0), d, 0.0, INFINITY, &hit));
    CHECK(hit.geom_id == wall_id);
    CHECK_REL(hit.t, 1e-4 / -d.x, 1e-9);
    CHECK(cdl_ray_scene_occluded(s, cdl_vec3_make(1e-4, 0, 0), d, 0.0, INFINITY));
    /* Grazing away from the wall along the floor (1e-9 rad up): nothing. */
    cdl_vec3 graze = cdl_vec3_normalize(cdl_vec3_make(1, 0.3, 1e-9));
    CHECK(!cdl_ray_scene_occluded(s, cdl_vec3_make(0.3, 0.2, 0), graze, 0.0, INFINITY));
    CHECK(!cdl_ray_scene_intersect(s, cdl_vec3_make(0.3, 0.2, 0), graze, 0.0, INFINITY, &hit));
    /* A segment ending on the floor does not count it; one 1 um longer does. */
    CHECK(!cdl_ray_scene_occluded(s, cdl_vec3_make(0.3, 0.2, 5), cdl_vec3_make(0, 0, -1), 0.0, 5.0));
    CHECK(cdl_ray_scene_occluded(s, cdl_vec3_make(0.3, 0.2, 5), cdl_vec3_make(0, 0, -1), 0.0, 5.000001));
    /* From a point on the sphere, inwards along the diameter: the far side
     * at t = 2, not the start. */
    CHECK(cdl_ray_scene_intersect(s, cdl_vec3_make(201, 0, 50), cdl_vec3_make(-1, 0, 0), 0.0, INFINITY, &hit));
    CHECK(hit.geom_id == sphere_id);
    CHECK_REL(hit.t, 2.0, 1e-12);
    /* and outwards: nothing (the floor is below, the wall behind the sphere) */
    CHECK(!cdl_ray_scene_occluded(s, cdl_vec3_make(201, 0, 50), cdl_vec3_make(1, 0, 0), 0.0, INFINITY));
    cdl_ray_scene_release(s);
}

int main(void)
{
    cdl_error err;
    cdl_ray_scene *s = NULL;
    CHECK_OK(cdl_ray_scene_create(&s, &err), &err);
    if (!s) return check_finish();

    /* A unit square in the plane z = 2 (two triangles) and a sphere of
     * radius 0.5 centred at (5, 0, 0). */
    const double quad[] = {-0.5, -0.5, 2, 0.5, -0.5, 2, 0.5, 0.5, 2, -0.5, 0.5, 2};
    const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
    uint32_t quad_id = 99, sphere_id = 99;
    CHECK_OK(cdl_ray_scene_add_triangles(s, quad, 4, tris, 2, &quad_id, &err), &err);
    CHECK_OK(cdl_ray_scene_add_sphere(s, cdl_vec3_make(5, 0, 0), 0.5, &sphere_id, &err), &err);
    CHECK(quad_id != sphere_id);
    /* A bad index is refused with a message. */
    const uint32_t bad[] = {0, 1, 7};
    uint32_t bad_id;
    CHECK(cdl_ray_scene_add_triangles(s, quad, 4, bad, 1, &bad_id, &err) == CDL_ERR_INPUT);
    CHECK_OK(cdl_ray_scene_commit(s, &err), &err);
    CHECK(cdl_ray_scene_triangle_count(s) == 2);

    cdl_ray_hit hit;
    /* Straight up from the origin: hits the square at t = 2, normal along z. */
    CHECK(cdl_ray_scene_intersect(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), 0.0, INFINITY, &hit));
    CHECK_ABS(hit.t, 2.0, 1e-6);
    CHECK(hit.geom_id == quad_id);
    CHECK_ABS(fabs(hit.normal.z), 1.0, 1e-6);
    /* Occlusion respects the segment's extent. */
    CHECK(cdl_ray_scene_occluded(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), 0.0, 3.0));
    CHECK(!cdl_ray_scene_occluded(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 1), 0.0, 1.9));
    CHECK(!cdl_ray_scene_occluded(s, cdl_vec3_make(0.7, 0, 0), cdl_vec3_make(0, 0, 1), 0.0, 3.0));
    /* The sphere: from the origin along +x the first hit is at 4.5 (exact sphere). */
    CHECK(cdl_ray_scene_intersect(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(1, 0, 0), 0.0, INFINITY, &hit));
    CHECK(hit.geom_id == sphere_id);
    CHECK_ABS(hit.t, 4.5, 1e-5);
    /* Grazing the sphere's silhouette at 0.49 m from its axis still hits:
     * chord half-length sqrt(0.25 - 0.49^2) = 0.0995 -> t = 5 - 0.0995. */
    CHECK(cdl_ray_scene_intersect(s, cdl_vec3_make(0, 0.49, 0), cdl_vec3_make(1, 0, 0), 0.0, INFINITY, &hit));
    CHECK_ABS(hit.t, 5.0 - sqrt(0.25 - 0.49 * 0.49), 1e-4);
    CHECK(!cdl_ray_scene_intersect(s, cdl_vec3_make(0, 0.51, 0), cdl_vec3_make(1, 0, 0), 0.0, INFINITY, &hit));
    cdl_ray_scene_release(s);
    test_ends_in_double();
    return check_finish();
}
