/* grid_surface.c - the surface a grid lies on, and its reflectance at each point.
 *
 * A grid asking for "luminance" must lie on a surface: at each point some
 * surface passes through it (within a few of Embree's float resolutions)
 * with its plane across the point's normal (normals parallel within 1e-6
 * in cosine, about 0.08 degrees), and the side the normal faces reflects:
 * a two-sided surface, or a one-sided one whose front faces that way. The
 * first such surface found gives the point's reflectance (for a box, its
 * face's).
 *
 * The same probe, taking a surface whichever side reflects, says which
 * points lie on a surface at all: there the surface hides the half-space
 * behind the point's normal, which matters to the outputs that look all
 * round (cylindrical and semicylindrical illuminance).
 */
#include "solver/grid/grid.h"

#include <math.h>

#include "solver/geometry/occluder_index.h"
#include "solver/scene/scene_geometry.h"

#define PARALLEL_COS (1.0 - 1e-6)
#define RESOLUTIONS 4.0

typedef struct surface_probe {
    const cdl_scene_geometry *geometry;
    cdl_vec3 p, n;
    double tol;
    int any_side;      /* 1: any surface through p across n, whichever side reflects */
    int found;
    double rho;
} surface_probe;

/* Does p lie in the triangle abc (in its plane), with slack tol? */
static int in_triangle(cdl_vec3 p, cdl_vec3 a, cdl_vec3 b, cdl_vec3 c, cdl_vec3 normal, double tol)
{
    cdl_vec3 v[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
        cdl_vec3 e = cdl_vec3_sub(v[(k + 1) % 3], v[k]);
        cdl_vec3 inward = cdl_vec3_cross(normal, e);
        double len = cdl_vec3_length(inward);
        if (!(len > 0.0)) return 0;
        if (cdl_vec3_dot(inward, cdl_vec3_sub(p, v[k])) / len < -tol) return 0;
    }
    return 1;
}

static void visit_surface(void *user, const double *prim, int is_sphere, uint32_t owner)
{
    surface_probe *s = user;
    if (s->found) return;
    cdl_vec3 front;
    double dist;
    if (is_sphere) {
        cdl_vec3 d = cdl_vec3_sub(s->p, cdl_vec3_make(prim[0], prim[1], prim[2]));
        double len = cdl_vec3_length(d);
        if (!(len > 0.0)) return;
        front = cdl_vec3_scale(d, 1.0 / len);
        dist = len - prim[3];
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(s->geometry, owner);
        if (piece && piece->shape.inward) front = cdl_vec3_neg(front);
    } else {
        cdl_vec3 a = cdl_vec3_make(prim[0], prim[1], prim[2]);
        cdl_vec3 b = cdl_vec3_make(prim[3], prim[4], prim[5]), c = cdl_vec3_make(prim[6], prim[7], prim[8]);
        front = cdl_vec3_normalize(cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
        dist = cdl_vec3_dot(front, cdl_vec3_sub(s->p, a));
        if (fabs(dist) <= s->tol && !in_triangle(s->p, a, b, c, front, s->tol)) return;
    }
    double along = cdl_vec3_dot(front, s->n);
    if (!(fabs(dist) <= s->tol) || !(fabs(along) >= PARALLEL_COS)) return;
    const cdl_geometry_piece *piece = cdl_scene_geometry_piece(s->geometry, owner);
    if (!piece || (!s->any_side && !piece->two_sided && along < 0.0)) return;
    s->found = 1;
    s->rho = piece->reflectance;
}

/* The first surface through point i of the grid across its normal. */
static surface_probe probe_point(const cdl_grid *grid, size_t i, const cdl_scene_geometry *geometry,
                                 const cdl_occluder_index *occluders, int any_side)
{
    cdl_vec3 p = grid->points[i];
    surface_probe s = {geometry, p, grid->normals[i], 0.0, any_side, 0, 0.0};
    if (geometry && occluders) {
        s.tol = RESOLUTIONS * cdl_scene_geometry_resolution(geometry, p);
        cdl_vec3 h = cdl_vec3_make(s.tol, s.tol, s.tol);
        cdl_occluder_index_visit_box(occluders, cdl_vec3_sub(p, h), cdl_vec3_add(p, h), visit_surface, &s);
    }
    return s;
}

cdl_status cdl_grid_surface_reflectance(const cdl_grid *grid, const cdl_scene_geometry *geometry,
                                        const cdl_occluder_index *occluders, double *rho, size_t *missing)
{
    *missing = SIZE_MAX;
    for (size_t i = 0; i < grid->count; ++i) {
        surface_probe s = probe_point(grid, i, geometry, occluders, 0);
        if (!s.found) {
            *missing = i;
            return CDL_ERR_INPUT;
        }
        rho[i] = s.rho;
    }
    return CDL_OK;
}

size_t cdl_grid_surface_mask(const cdl_grid *grid, const cdl_scene_geometry *geometry,
                             const cdl_occluder_index *occluders, unsigned char *on_surface)
{
    size_t count = 0;
    for (size_t i = 0; i < grid->count; ++i) {
        on_surface[i] = (unsigned char)probe_point(grid, i, geometry, occluders, 1).found;
        count += on_surface[i];
    }
    return count;
}
