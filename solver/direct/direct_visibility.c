/* direct_visibility.c - is a shadow ray blocked, is a whole emitter in view? */
#include "solver/direct/direct_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "radiometry/frame.h"

/* Geometric tolerance of region tests around p: a surface must reach ten
 * double rounding bounds (cdl_ray_offsets_epsilon: 1e-11 of the scene's
 * coordinates, never a fraction of its size) into the region to count as an
 * occluder, so surfaces that only touch it (the floor under a grid point,
 * the ceiling around a recessed emitter) do not, and a wall 0.1 mm from a
 * point in a 1 km scene does. */
double cdl_direct_region_tolerance(const cdl_direct_context *ctx, cdl_vec3 p)
{
    return 10.0 * cdl_ray_offsets_epsilon(&ctx->offsets, p);
}

void cdl_direct_record_ray(cdl_ray_log *log, cdl_vec3 o, cdl_vec3 dir, double t_near, double t_far, uint32_t exclude)
{
    if (log->count == log->capacity) {
        size_t cap = log->capacity ? 2 * log->capacity : 4096;
        cdl_ray_record *r = realloc(log->rays, cap * sizeof *r);
        if (!r) {
            log->overflow = 1;
            return;
        }
        log->rays = r;
        log->capacity = cap;
    }
    cdl_ray_record rec = {o, dir, t_near, t_far, exclude};
    log->rays[log->count++] = rec;
}

int cdl_direct_shadow_segment(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                              uint32_t exclude, cdl_ray_segment *ray, cdl_direct_sample_stats *stats)
{
    if (!ctx->geometry) return 0;
    if (!cdl_ray_offsets_shadow_ray(&ctx->offsets, p, n, dir, distance, &ray->origin, &ray->t_near, &ray->t_far))
        return 0;
    ray->dir = dir;
    ray->exclude = exclude;
    stats->rays++;
    if (ctx->log) cdl_direct_record_ray(ctx->log, ray->origin, dir, ray->t_near, ray->t_far, exclude);
    return 1;
}

/* The fraction of light along one such segment: through the panes
 * crossed, 0 past anything opaque (scene_geometry.h). */
static double segment_fraction(const cdl_direct_context *ctx, const cdl_ray_segment *r)
{
    if (cdl_scene_geometry_has_glass(ctx->geometry))
        return cdl_scene_geometry_transmission_except(ctx->geometry, r->origin, r->dir, r->t_far, r->exclude);
    return cdl_ray_scene_occluded_except(ctx->rays, r->origin, r->dir, r->t_near, r->t_far, r->exclude) ? 0.0 : 1.0;
}

/* Is the segment from p towards the light blocked? The surface p lies on
 * and the one the light's sample lies on never count (scene_geometry.h). */
int cdl_direct_shadowed(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                        uint32_t exclude, cdl_direct_sample_stats *stats)
{
    cdl_ray_segment r;
    if (!cdl_direct_shadow_segment(ctx, p, n, dir, distance, exclude, &r, stats)) return 0;
    return cdl_ray_scene_occluded_except(ctx->rays, r.origin, r.dir, r.t_near, r.t_far, r.exclude);
}

double cdl_direct_transmission(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                               uint32_t exclude, cdl_direct_sample_stats *stats)
{
    cdl_ray_segment r;
    if (!cdl_direct_shadow_segment(ctx, p, n, dir, distance, exclude, &r, stats)) return 1.0;
    return segment_fraction(ctx, &r);
}

void cdl_direct_transmit_many(const cdl_direct_context *ctx, const cdl_ray_segment *rays, size_t count,
                              unsigned char *blocked, double *fraction)
{
    if (count == 0) return;
    if (cdl_scene_geometry_has_glass(ctx->geometry)) {
        for (size_t k = 0; k < count; ++k) fraction[k] = segment_fraction(ctx, &rays[k]);
        return;
    }
    cdl_ray_scene_occluded_many(ctx->rays, rays, count, blocked);
    for (size_t k = 0; k < count; ++k) fraction[k] = blocked[k] ? 0.0 : 1.0;
}

/* Move planes first .. first + count - 1 of a region outward by tol, so
 * that the index's shrink by tol leaves them where they were. */
static void unshrink_planes(cdl_convex_region *region, int first, int count, double tol)
{
    for (int i = first; i < first + count && i < region->plane_count; ++i) region->planes[i].offset += tol;
}

/* Is the region between p and the whole of the light clear of surfaces?
 * The index shrinks every plane by tol, so that the surface p lies on and
 * the one the emitter is set into do not count. The side planes of a
 * pyramid meet at p, though: shrunk, they cut away everything within about
 * tol x distance / emitter size of p, and all of a pyramid thinner than
 * 2 tol (a small emitter), so a table just above a floor point went unseen.
 * The sides are therefore kept where they are; only the caps (the plane
 * of p, the plane of the emitter) shrink. */
int cdl_direct_light_region(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n,
                            cdl_convex_region *region, double *tol_out)
{
    region->plane_count = 0;
    double tol = cdl_direct_region_tolerance(ctx, p);
    *tol_out = tol;
    if (light->is_sun_disk) {
        /* The cone towards the sun, in the square pyramid about it whose
         * sides touch the cone (half-angle widened by a hundredth): each
         * side {x : m.(x - p) <= 0}, m = u cos a - s sin a, u = +-e1, +-e2. */
        cdl_frame f = cdl_frame_from_normal(light->sun_dir);
        double a = 1.01 * light->sun_half_angle, ca = cos(a), sa = sin(a);
        const cdl_vec3 u[4] = {f.s, f.t, cdl_vec3_neg(f.s), cdl_vec3_neg(f.t)};
        for (int k = 0; k < 4; ++k) {
            cdl_vec3 m = cdl_vec3_sub(cdl_vec3_scale(u[k], ca), cdl_vec3_scale(light->sun_dir, sa));
            cdl_region_add(region, m, cdl_vec3_dot(m, p));
        }
        unshrink_planes(region, 0, 4, tol);
        cdl_region_add(region, cdl_vec3_neg(n), -cdl_vec3_dot(n, p));
    } else if (light->is_environment) {
        /* The open half-space above the receiving plane (and above the
         * horizon for an upper-hemisphere sky): {x : -n.x <= -n.p}. */
        cdl_region_add(region, cdl_vec3_neg(n), -cdl_vec3_dot(n, p));
        if (light->upper_only) cdl_region_add(region, cdl_vec3_neg(light->up), -cdl_vec3_dot(light->up, p));
    } else if (light->outline_is_sphere) {
        cdl_region_sphere_view(region, p, light->sphere_center, light->sphere_radius);
        if (region->plane_count == CDL_REGION_SPHERE_SIDES + 1) unshrink_planes(region, 0, CDL_REGION_SPHERE_SIDES, tol);
        cdl_region_add(region, cdl_vec3_neg(n), -cdl_vec3_dot(n, p));
    } else {
        if (!cdl_region_pyramid(region, p, light->outline, light->outline_count)) return 0;
        unshrink_planes(region, 1, light->outline_count, tol);
        cdl_region_add(region, cdl_vec3_neg(n), -cdl_vec3_dot(n, p));
    }
    return 1;
}

int cdl_direct_light_fully_visible(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n)
{
    cdl_convex_region region;
    double tol;
    if (!cdl_direct_light_region(ctx, light, p, n, &region, &tol)) return 0;
    return !cdl_occluder_index_intersects(ctx->occluders, &region, tol, cdl_scene_light_own_piece(light));
}

int cdl_direct_sphere_in_view(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 center, double radius,
                              uint32_t owner)
{
    if (!ctx->geometry || !ctx->occluders) return 1;
    /* as for a light bounded by a sphere (cdl_direct_light_region) */
    cdl_scene_light sphere;
    memset(&sphere, 0, sizeof sphere);
    sphere.outline_is_sphere = 1;
    sphere.sphere_center = center;
    sphere.sphere_radius = radius;
    sphere.owner = owner;
    return cdl_direct_light_fully_visible(ctx, &sphere, p, n);
}

int cdl_direct_polygon_in_view(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, const cdl_vec3 *polygon,
                               int count, uint32_t owner)
{
    if (!ctx->geometry || !ctx->occluders) return 1;
    if (count < 3 || count > CDL_SCENE_LIGHT_OUTLINE_MAX) return 0;
    /* as for a flat light with this outline (cdl_direct_light_region) */
    cdl_vec3 outline[CDL_SCENE_LIGHT_OUTLINE_MAX];
    memcpy(outline, polygon, (size_t)count * sizeof *outline);
    cdl_scene_light flat;
    memset(&flat, 0, sizeof flat);
    flat.outline = outline;
    flat.outline_count = count;
    flat.owner = owner;
    return cdl_direct_light_fully_visible(ctx, &flat, p, n);
}

int cdl_direct_ray_blocked(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                           uint32_t owner)
{
    if (!ctx->geometry) return 0;
    cdl_direct_sample_stats stats;
    memset(&stats, 0, sizeof stats);
    return cdl_direct_shadowed(ctx, p, n, dir, distance, owner, &stats);
}
