/* direct.h - direct illuminance at calculation points, exact where it can be.
 *
 * For each light and each grid a plan decides what the light needs:
 *   delta lights (point, spot, goniometric, directional): the exact
 *     I cos(theta) / d^2 (or E cos for directional) plus one shadow ray, and no
 *     shadow ray at all when no surface can lie between the light and the
 *     grid (nothing intersects the box around both);
 *   area emitters and environments: the closed-form illuminance (contour
 *     integral, disk and sphere formulas, pi L x visible fraction, for an
 *     image the exact sum over pixels of L x projected solid angle)
 *     when no surface intersects the region between the receiver and the
 *     emitter (tested exactly per point, see occluder_index.h); where at
 *     most CDL_EXACT_ROUTE_MAX_OCCLUDERS planar triangles are in the way, L
 *     times the projected solid angle of the visible polygon (exact,
 *     direct_exact_route.c); otherwise the
 *     closed form minus a Monte-Carlo estimate of the hidden part
 *     (E = E_exact - <f (1 - V)>, a control variate that is exact when
 *     nothing is hidden), with its standard error; an image's hidden part
 *     drawn by luminance x each pixel's projected solid angle on the
 *     receiver's hemisphere (lights/environment/environment_sampler.h).
 * Random numbers are keyed by (seed, grid, point, light, sample): results do
 * not depend on threads or on the order points are computed in.
 */
#ifndef CANDELA_SOLVER_DIRECT_H
#define CANDELA_SOLVER_DIRECT_H

#include <stddef.h>
#include <stdint.h>

#include "lights/emitters/emitter.h"
#include "base/rng.h"
#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/direct/sky_portals.h"
#include "solver/geometry/occluder_index.h"
#include "solver/geometry/ray_scene.h"
#include "solver/rank_group.h"
#include "solver/scene/scene_geometry.h"
#include "solver/scene/scene_lights.h"

/* How a light's contribution is obtained (per light, per grid). */
typedef enum cdl_light_strategy {
    CDL_STRATEGY_DELTA_EXACT,         /* delta light, nothing can occlude: no rays */
    CDL_STRATEGY_DELTA_SHADOWED,      /* delta light, one shadow ray per point */
    CDL_STRATEGY_EXTENDED_EXACT,      /* closed form, nothing can occlude for any point */
    CDL_STRATEGY_EXTENDED_TESTED,     /* closed form where the per-point region is clear, else sampled */
    CDL_STRATEGY_SAMPLED              /* always sampled (non-planar emitter that surfaces may hide) */
} cdl_light_strategy;

/* What the strategy models, and after a colon why (summary.json's plan). */
const char *cdl_light_strategy_name(cdl_light_strategy strategy);

/* The same in the words of the light it is for (a luminaire spread over
 * its opening has its own; NULL: the general words). */
const char *cdl_light_strategy_describe(cdl_light_strategy strategy, const cdl_scene_light *light);

/* Shadow rays as cast, for benchmarks that replay them (single-threaded use). */
typedef cdl_ray_segment cdl_ray_record; /* exclude: the light's own piece, which the ray passes */

typedef struct cdl_ray_log {
    cdl_ray_record *rays;
    size_t count, capacity;
    int overflow;                     /* 1 if a ray could not be recorded (out of memory) */
} cdl_ray_log;

typedef struct cdl_direct_context {
    const cdl_scene_geometry *geometry;  /* rays and their epsilons; NULL: nothing can occlude */
    cdl_ray_offsets offsets;          /* the geometry's ray offsets (when geometry != NULL) */
    const cdl_ray_scene *rays;        /* the geometry's rays; NULL when there is no geometry */
    const cdl_occluder_index *occluders; /* NULL when the scene has no geometry */
    const cdl_scene_light *lights;
    size_t light_count;
    double target;                    /* relative standard error of a point's direct E (sampled terms) */
    int samples;                      /* > 0: exactly this many samples (rounded up to 2 k^2) per partly
                                       * hidden extended light; 0: sample to the target */
    int ao_samples;                   /* per point for ambient occlusion (rounded up to a square) */
    uint64_t seed;
    cdl_ray_log *log;                 /* NULL, or records every shadow ray (one thread only) */
    int no_exact_route;               /* 1: partly hidden lights are always sampled, never solved as
                                       * visible polygons (tests of the sampler, benchmarks); default 0 */
    const cdl_sky_portals *portals;   /* NULL, or the panes the sky comes in through: path vertices sample
                                       * skies through them too (sky_portals.h) */
} cdl_direct_context;

/* Decide each light's strategy for a set of receiver points (a grid). */
void cdl_direct_plan_grid(const cdl_direct_context *ctx, const cdl_vec3 *points, size_t count,
                          cdl_light_strategy *strategies);

/* The route a partly hidden area emitter or uniform sky took at a point
 * (direct_exact_route.c): in full view (closed form), the visible polygon
 * past few planar occluders (exact), or sampled, and why. */
typedef enum cdl_direct_route {
    CDL_ROUTE_FULL_VIEW,              /* nothing in the way: the closed form */
    CDL_ROUTE_VISIBLE_POLYGON,        /* exact: the visible polygon past planar occluders */
    CDL_ROUTE_SKY_REGION,             /* an image or overcast sky sampled within its visible polygon */
    CDL_ROUTE_SKY_SUN,                /* as SKY_REGION, the sky's brightest pixels (a sun) exact over it */
    CDL_ROUTE_TOO_MANY,               /* sampled: more than CDL_EXACT_ROUTE_MAX_OCCLUDERS occluders */
    CDL_ROUTE_CURVED_OCCLUDER,        /* sampled: a sphere or a disk may be in the way */
    CDL_ROUTE_CURVED_EMITTER,         /* sampled: a disk, sphere or non-planar emitter */
    CDL_ROUTE_TOO_COMPLEX,            /* sampled: the visible part had too many pieces */
    CDL_ROUTE_SKY_PEAK,               /* sampled: a sky far brighter in too many pixels over the visible part */
    CDL_ROUTE_DISABLED,               /* sampled: the context asked for it (no_exact_route) */
    CDL_ROUTE_GLASS,                  /* sampled: seen through glass, whose transmittance varies with the angle */
    CDL_ROUTE_COUNT
} cdl_direct_route;

/* Whether any part of an extended light with a closed form reaches p
 * (normal n) past the surfaces, as the exact route sees it: 1 when it
 * finds a visible part that gives light, 0 when it finds none, -1 when it
 * cannot tell (too many or curved occluders: the caller probes with
 * samples). A window's worth of sky that a few samples would miss counts. */
int cdl_direct_light_seen(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy strategy,
                          cdl_vec3 p, cdl_vec3 n);

/* The sky a point sees, for callers that integrate their own functions of
 * direction over it (daylight coefficients, solver/daylight/): every
 * direction on the side of n that leaves the scene, whatever the horizon,
 * as convex spherical polygons, each handed to `piece` as `count` unit
 * world directions from p (count <= CDL_VISIBLE_MAX_VERTICES; either
 * orientation; edges the shorter great-circle arcs). Returns
 * CDL_ROUTE_FULL_VIEW when nothing can hide any of it (no piece is handed
 * over: the whole hemisphere of n is seen), CDL_ROUTE_VISIBLE_POLYGON when
 * the pieces were handed over (exactly what is seen past the surfaces,
 * geometry/visible_polygon.h), or the route's reason why it cannot say
 * (glass, curved or too many occluders, too many pieces: the caller
 * samples; some pieces may have been handed over before it found out).
 * Thread-safe. */
typedef void (*cdl_sky_piece_fn)(void *user, const cdl_vec3 *dirs, int count);
cdl_direct_route cdl_direct_visible_sky(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_sky_piece_fn piece,
                                        void *user);

/* The same with panes of glass taken as clear: the pieces are what p sees
 * through them and past everything else, and *through_glass says whether
 * any pane was among the occluders (the caller then weighs the pieces with
 * the panes' transmittance itself: cdl_scene_geometry_transmission). */
cdl_direct_route cdl_direct_visible_sky_through_glass(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n,
                                                      cdl_sky_piece_fn piece, void *user, int *through_glass);

/* Most occluders between a point and a light for the exact route. */
#define CDL_EXACT_ROUTE_MAX_OCCLUDERS 64

/* Points per route of one light (over a grid). */
typedef struct cdl_direct_route_tally {
    uint64_t points[CDL_ROUTE_COUNT];
    uint32_t most_occluders;          /* most occluders past which a point took the exact route */
    uint64_t capped;                  /* sampled points whose stage the cap of samples held below its plan */
} cdl_direct_route_tally;

typedef struct cdl_direct_sample_stats {
    uint64_t rays;
    uint64_t exact_evaluations;       /* closed forms used */
    uint64_t sampled_evaluations;     /* Monte-Carlo estimates used */
    cdl_direct_route_tally *routes;   /* NULL, or one per light of the context: points per route */
} cdl_direct_sample_stats;

/* Add b's counts (rays, evaluations, routes of `light_count` lights when
 * both have them) to a. */
void cdl_direct_stats_add(cdl_direct_sample_stats *a, const cdl_direct_sample_stats *b, size_t light_count);

/* s's counts (and its routes of `light_count` lights, when it has them)
 * added up over the ranks of `group` (a collective; nothing without one):
 * afterwards every rank holds the whole solve's. */
cdl_status cdl_direct_stats_share(cdl_rank_group *group, cdl_direct_sample_stats *s, size_t light_count,
                                  cdl_error *err);

/* For integrators beyond direct light (glare at an eye), the two visibility
 * questions the direct solver asks, with its tolerances: is the region
 * between p and the sphere (center, radius) - the cone from p around it,
 * cut by p's plane of normal n - clear of every surface but those of
 * geometry piece `owner` (UINT32_MAX: none excluded)? 1 when it is, or when
 * the scene has no geometry. And is the segment from p along unit `dir`
 * over `distance` blocked by anything but piece `owner` (the shadow ray
 * direct light casts)? Both thread-safe. */
int cdl_direct_sphere_in_view(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 center, double radius,
                              uint32_t owner);
/* The same for the pyramid from p to a convex planar polygon of up to
 * CDL_SCENE_LIGHT_OUTLINE_MAX corners (the region a flat emitter's light
 * crosses). */
int cdl_direct_polygon_in_view(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, const cdl_vec3 *polygon,
                               int count, uint32_t owner);
int cdl_direct_ray_blocked(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_vec3 dir, double distance,
                           uint32_t owner);

/* What a light's tally says, for the plan: "exact: visible polygon past up
 * to 3 occluders at 192 points", "sampled at 40 points: more than 64
 * occluders", ...; empty when the light took no per-point route. */
void cdl_direct_route_describe(const cdl_direct_route_tally *tally, char *out, size_t size);

/* Lights that can reach any point of a ball (centre, radius): the indices
 * of all lights except those whose emission cone misses the ball. Writes
 * at most ctx->light_count indices into `active`; returns their number. */
size_t cdl_direct_select_lights(const cdl_direct_context *ctx, cdl_vec3 center, double radius, uint32_t *active);

/* Direct illuminance (lux) at p on the plane with unit normal n, with the
 * variance of its estimate (0 when exact), from the lights listed in
 * `active` (NULL: all lights). `stream` identifies the point (grid and
 * index) for the random numbers. */
void cdl_direct_illuminance(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                            const uint32_t *active, size_t active_count, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                            double *E, double *variance, cdl_direct_sample_stats *stats);

/* An unbiased estimate of the direct illuminance (lux) at any point p with
 * unit normal n, lying on a surface or not: a path vertex, a gather ray's
 * hit. Cheap: delta lights exactly with one shadow ray (none without
 * geometry); every other light with one sample (random numbers from `key`,
 * index = the light's number): the closed form minus the sample's hidden
 * part where the light has a closed form (exact when the sample is not
 * hidden), else the sample itself. The estimate of a single call may be
 * negative (a hidden sample can exceed the closed form); its mean is exact.
 * *unoccluded (may be NULL) receives what the lights would give with
 * nothing in the way (closed forms, or the sample's unshadowed value). */
double cdl_direct_estimate_point(const cdl_direct_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n,
                                 double *unoccluded, cdl_direct_sample_stats *stats);

/* The same estimate with one light drawn instead of a sample of every
 * light, for path vertices: one light drawn with probability in proportion
 * to a delta light's exact value or an extended light's far-field guess
 * I cos / d^2 (a share drawn evenly among the extended ones, whose guess
 * may miss light near them), its light e V or f V (one sample, no closed
 * form) divided by the probability of drawing it. Skies and the sun, and
 * with closed_apart every light with a cheap closed form (a Lambertian
 * panel, an emitting surface: E_0 - f (1 - V), exact unless hidden), take
 * their own sample as in cdl_direct_estimate_point and are not drawn.
 * Unbiased like cdl_direct_estimate_point, for one shadow ray (and one per
 * light taken apart) instead of one per light; noisier where lights are
 * partly hidden, exactly 0 where all are (but for closed forms taken
 * apart). Random numbers from `key`: index = the light's number for its
 * sample, light_count for the draw. */
double cdl_direct_estimate_one_light(const cdl_direct_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n,
                                     int closed_apart, double *unoccluded, cdl_direct_sample_stats *stats);

/* Most points cdl_direct_illuminance_chunk takes at once. */
#define CDL_DIRECT_CHUNK_MAX 64

/* Scratch space for cdl_direct_illuminance_chunk, one per thread. */
typedef struct cdl_direct_scratch {
    double *contribution;             /* points x active lights */
    cdl_ray_record *rays;             /* pending shadow rays */
    uint32_t *ray_slot;               /* their slot in `contribution` */
    unsigned char *ray_blocked;       /* their answers (scratch of cdl_direct_transmit_many) */
    double *ray_fraction;             /* the light that passes along each */
    size_t capacity;                  /* slots */
    uint32_t *ext_light;              /* the chunk's extended lights */
    size_t *ext_slot;                 /* their place among the active lights */
    double *ext_value;                /* a point's values of them */
    size_t light_capacity;
} cdl_direct_scratch;

void cdl_direct_scratch_release(cdl_direct_scratch *scratch);

/* cdl_direct_illuminance for `count` (<= CDL_DIRECT_CHUNK_MAX) points at
 * once, with the same result bit for bit: every light's contribution to
 * every point is found first (light by light),
 * the delta lights' shadow rays are then traced one after another (as a
 * plain loop of occlusion queries would), and each point's sum is formed in
 * light order. streams[i] identifies point i for the random numbers. */
cdl_status cdl_direct_illuminance_chunk(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                                        const uint32_t *active, size_t active_count, const uint64_t *streams,
                                        const cdl_vec3 *points, const cdl_vec3 *normals, size_t count, double *E,
                                        double *variance, cdl_direct_sample_stats *stats,
                                        cdl_direct_scratch *scratch, cdl_error *err);

/* ---- vertical illuminance (direct_vertical.c) ----------------------------- */

/* A facing direction needs a horizontal part of the normal at least this long. */
#define CDL_DIRECT_FACING_MIN 1e-6

/* One light's cylindrical E_z = E_n sin(theta) / pi and semicylindrical
 * E_sz = E_n sin(theta) (1 + cos alpha) / pi, in lux, from its illuminance
 * E_normal on the plane facing it and the unit direction towards it
 * (theta from the vertical +z; alpha between its horizontal part and the
 * unit horizontal `facing`). */
void cdl_vertical_illuminance_from_light(double E_normal, cdl_vec3 to_light, cdl_vec3 facing, double *Ez,
                                         double *Esz);

/* The horizontal direction a semicylinder at a point of normal n faces:
 * n's horizontal part, made unit. 0 when n is (within
 * CDL_DIRECT_FACING_MIN) vertical and so faces no horizontal direction. */
int cdl_direct_facing_direction(cdl_vec3 n, cdl_vec3 *facing);

/* Cylindrical and semicylindrical illuminance (lux) at p from the delta
 * lights among `active` (NULL: all), each shadowed as for E (n: the
 * point's normal, for its rays). on_surface: p lies on a surface, which
 * hides every light behind n. Lights of other strategies are skipped (the
 * caller samples them: transport/vertical_sampled.h). Either output may
 * be NULL. */
void cdl_direct_vertical_point(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                               const uint32_t *active, size_t active_count, cdl_vec3 p, cdl_vec3 n, cdl_vec3 facing,
                               int on_surface, double *Ez, double *Esz, cdl_direct_sample_stats *stats);

/* Cosine-weighted unoccluded fraction of the hemisphere about n at p, and
 * in *stderr_out (may be NULL) its standard error: the spread of a
 * fraction seen in `open` of N rays under a uniform prior (0 only where
 * the scene has no geometry). */
double cdl_direct_ambient_occlusion(const cdl_direct_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                                    double *stderr_out, cdl_direct_sample_stats *stats);

#endif
