/* direct_internal.h - what the files of direct/ share (private to direct/). */
#ifndef CANDELA_SOLVER_DIRECT_INTERNAL_H
#define CANDELA_SOLVER_DIRECT_INTERNAL_H

#include "solver/direct/direct.h"
#include "solver/direct/sky_region.h"

/* Most samples per light and point when sampling to a target, pilots and
 * stage together (an explicit direct_samples may ask for more). 2^18
 * shadow rays take about 30 ms. */
#define CDL_DIRECT_MAX_SAMPLES 262144.0

/* Geometric tolerance of region tests around p (direct_visibility.c). */
double cdl_direct_region_tolerance(const cdl_direct_context *ctx, cdl_vec3 p);

/* Append a shadow ray to a benchmark's log. */
void cdl_direct_record_ray(cdl_ray_log *log, cdl_vec3 o, cdl_vec3 dir, double t_near, double t_far, uint32_t exclude);

/* The fraction of light that reaches p (normal n) along -dir from
 * `distance` away: 1 or 0 without glass (the segment clear or blocked),
 * the product of the panes' transmittances at their angles with it
 * (scene_geometry.h). `exclude`: the light's own piece, which never blocks
 * its light (cdl_scene_light_own_piece; UINT32_MAX: none). Counts the ray
 * in stats. */
double cdl_direct_transmission(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                               uint32_t exclude, cdl_direct_sample_stats *stats);

/* The shadow ray cdl_direct_transmission traces for the same arguments,
 * to trace later with others (cdl_direct_transmit_many): 0 when it traces
 * none (no geometry, or nothing between p and the light: the fraction is
 * 1). Logged and counted in stats as cdl_direct_transmission does. */
int cdl_direct_shadow_segment(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                              uint32_t exclude, cdl_ray_segment *ray, cdl_direct_sample_stats *stats);

/* The fractions of light along `count` such segments, each to the bit what
 * cdl_direct_transmission gives: without glass traced as Embree packets
 * (cdl_ray_scene_occluded_many; `blocked` is scratch for count answers),
 * through glass one after another. */
void cdl_direct_transmit_many(const cdl_direct_context *ctx, const cdl_ray_segment *rays, size_t count,
                              unsigned char *blocked, double *fraction);

/* Is the segment from p (normal n) along unit dir over `distance` blocked
 * (by anything but piece `exclude`, glass included)? Counts the ray in stats. */
int cdl_direct_shadowed(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                        uint32_t exclude, cdl_direct_sample_stats *stats);

/* The region between p (normal n) and the whole of the light, as the
 * occluder index is asked about it with tolerance *tol: the half-space
 * above p's plane for a sky, the pyramid to the emitter's outline (or the
 * sphere's view) cut by that plane otherwise. 0 if there is none. */
int cdl_direct_light_region(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n,
                            cdl_convex_region *region, double *tol);

/* Is the region between p and the whole of the light clear of surfaces? */
int cdl_direct_light_fully_visible(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_vec3 p,
                                   cdl_vec3 n);

/* A light with a closed form that something may hide, at p
 * (direct_exact_route.c): 0 when the light is in full view (strategy
 * EXTENDED_TESTED and the region clear: its closed form stands); 1 when few
 * planar occluders hide part of it and *E is the exact illuminance of its
 * visible part; 2 for an image or overcast sky whose visible part is known
 * but not of one luminance: *region is that part, to integrate over (the
 * caller releases it); -1 when it must be sampled. `unoccluded` is the
 * light's E with nothing in the way. Counts the route in stats. */
int cdl_direct_exact_term(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy st,
                          cdl_vec3 p, cdl_vec3 n, double unoccluded, double *E, cdl_sky_region **region,
                          cdl_direct_sample_stats *stats);

/* The extended lights (area emitters, skies) of one point (direct_extended.c):
 * lights[0 .. count) are their indices, in light order; `known` is the
 * point's direct illuminance from its other (exact) lights. Each light's
 * illuminance goes to contribution[j], the variance of their sum to
 * *variance. Sampled until the point's target holds (ctx->target), or with
 * ctx->samples samples a light when that is set. */
void cdl_direct_extended_point(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                               const uint32_t *lights, size_t count, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                               double known, double *contribution, double *variance, cdl_direct_sample_stats *stats);

#endif
