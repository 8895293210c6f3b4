/* surface_mesh_fixture.h - what the surface-mesh tests measure on a mesh:
 * its angles, edges, areas, interpolant, and where its vertices lie. */
#ifndef CANDELA_TESTS_SURFACE_MESH_FIXTURE_H
#define CANDELA_TESTS_SURFACE_MESH_FIXTURE_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "radiometry/constants.h"
#include "radiometry/vec3.h"
#include "solver/geometry/surface_mesh.h"

static inline cdl_vec3 fx_vertex(const cdl_surface_mesh *m, uint32_t v)
{
    return cdl_vec3_make(m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2]);
}

static inline cdl_vec3 fx_normal(const cdl_surface_mesh *m, uint32_t v)
{
    return cdl_vec3_make(m->normal[3 * v], m->normal[3 * v + 1], m->normal[3 * v + 2]);
}

/* The angle at a of triangle abc, in degrees. */
static inline double fx_angle_deg(cdl_vec3 a, cdl_vec3 b, cdl_vec3 c)
{
    cdl_vec3 u = cdl_vec3_sub(b, a), v = cdl_vec3_sub(c, a);
    return atan2(cdl_vec3_length(cdl_vec3_cross(u, v)), cdl_vec3_dot(u, v)) * CDL_RAD_TO_DEG;
}

static inline double fx_triangle_min_angle_deg(const cdl_surface_mesh *m, size_t t)
{
    const uint32_t *v = &m->triangles[3 * t];
    cdl_vec3 p[3] = {fx_vertex(m, v[0]), fx_vertex(m, v[1]), fx_vertex(m, v[2])};
    double least = 180.0;
    for (int k = 0; k < 3; ++k) least = fmin(least, fx_angle_deg(p[k], p[(k + 1) % 3], p[(k + 2) % 3]));
    return least;
}

static inline double fx_min_angle_deg(const cdl_surface_mesh *m)
{
    double least = 180.0;
    for (size_t t = 0; t < m->triangle_count; ++t) least = fmin(least, fx_triangle_min_angle_deg(m, t));
    return least;
}

static inline double fx_max_edge(const cdl_surface_mesh *m)
{
    double longest = 0.0;
    for (size_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k)
            longest = fmax(longest, cdl_vec3_distance(fx_vertex(m, m->triangles[3 * t + k]),
                                                      fx_vertex(m, m->triangles[3 * t + (k + 1) % 3])));
    return longest;
}

/* Twice the vector area of a triangle: its normal times twice its area. */
static inline cdl_vec3 fx_area_vector(const cdl_surface_mesh *m, size_t t)
{
    const uint32_t *v = &m->triangles[3 * t];
    cdl_vec3 a = fx_vertex(m, v[0]);
    return cdl_vec3_cross(cdl_vec3_sub(fx_vertex(m, v[1]), a), cdl_vec3_sub(fx_vertex(m, v[2]), a));
}

/* The integral of the linear interpolant over the mesh. */
static inline double fx_integral(const cdl_surface_mesh *m)
{
    double sum = 0.0;
    for (size_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *v = &m->triangles[3 * t];
        sum += 0.5 * cdl_vec3_length(fx_area_vector(m, t)) * (m->value[v[0]] + m->value[v[1]] + m->value[v[2]]) / 3.0;
    }
    return sum;
}

/* A point of triangle t by barycentric weights (1 - s - u, s, u), and the
 * interpolant there. */
static inline cdl_vec3 fx_point(const cdl_surface_mesh *m, size_t t, double s, double u, double *interpolated)
{
    const uint32_t *v = &m->triangles[3 * t];
    double w[3] = {1.0 - s - u, s, u};
    cdl_vec3 p = cdl_vec3_make(0, 0, 0);
    *interpolated = 0.0;
    for (int k = 0; k < 3; ++k) {
        p = cdl_vec3_madd(p, w[k], fx_vertex(m, v[k]));
        *interpolated += w[k] * m->value[v[k]];
    }
    return p;
}

/* A small deterministic generator for sample positions (a 64-bit LCG,
 * Knuth's MMIX constants), uniform in [0, 1). */
static inline double fx_uniform(uint64_t *state)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*state >> 11) * 0x1p-53;
}

#endif
