/* daylight_coefficients.h - what each sky patch and each sun gives every
 * grid point: the daylight coefficients of an annual study (not public).
 *
 * A point's illuminance under any sky is linear in the sky's luminance:
 *     E = sum_k C_k L_k + sum_s D_s E_n,s
 * (Tregenza and Waters, "Daylight coefficients", Lighting Research and
 * Technology 15(2), 1983), L_k the luminance of sky patch k taken as
 * uniform over it (lights/environment/reinhart_patches.h, the ground patch
 * 0 included), E_n,s the direct normal illuminance of a sun s. Computed
 * once for a scene, the coefficients give every hour of a year as one
 * matrix product (daylight/annual.h).
 *
 * Sky patches, C_k (lx per cd/m^2):
 *  - direct: the projected solid angle of the part of patch k the point
 *    sees. Exact where the exact route can say what the point sees
 *    (solver/direct: the whole hemisphere, or the visible polygons past at
 *    most CDL_EXACT_ROUTE_MAX_OCCLUDERS planar occluders, no glass), each
 *    visible polygon cut by the patches in closed form
 *    (cdl_reinhart_add_polygon); where panes of glass are in the way, the
 *    same polygons seen through them (panes taken as clear), each patch's
 *    part then times the panes' mean transmittance over it, cosine-
 *    weighted, from GLASS_SAMPLES directions drawn over the polygons (T
 *    varies slowly with the angle of incidence: the ratio is close whatever
 *    the draw); elsewhere (curved or too many occluders) sampled with the
 *    paths' first rays (below), which pass panes with their transmittance;
 *  - interreflected: paths from the point (transport/surface_hit.h), the
 *    first direction stratified and cosine-weighted, each reflection
 *    Lambertian with the surface's reflectance and Russian roulette, as the
 *    path tracer's (transport/path.h); a path that leaves the scene after
 *    j >= 1 reflections adds pi x its throughput (the reflectances and the
 *    panes' transmittances on its way) to the patch it leaves through.
 * Suns, D_s (lx per lx of direct normal illuminance), interreflected only
 * (the direct sun of each hour is traced on its own: cdl_daylight_direct_sun):
 * at every reflection of every path, next-event estimation towards each
 * sun, max(0, n.s) times the panes' transmittance towards it (0 when
 * something opaque is in the way), times the path's throughput, as
 * DAYSIM's suns are lights of rtrace's.
 *
 * Stated error: each point's paths are sampled in two stages
 * (radiometry/estimate.h), so that the sampled part of E under a reference
 * sky (a uniform one of 1 cd/m^2 unless given: the CIE overcast for a
 * daylight factor) meets `target` relative to that sky's E at the point;
 * the stated relative error of that E is kept per point (sky_rel_stderr). The same paths
 * give the suns' coefficients; their summed value's relative error is
 * kept too (sun_rel_stderr). A patch's coefficient alone is far noisier
 * than their sum: what an hour's sky weighs is the sum.
 *
 * Random numbers are keyed by (seed, grid, point, path): results do not
 * depend on the number of threads.
 */
#ifndef CANDELA_SOLVER_DAYLIGHT_COEFFICIENTS_H
#define CANDELA_SOLVER_DAYLIGHT_COEFFICIENTS_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "lights/environment/reinhart_patches.h"
#include "solver/direct/direct.h"
#include "solver/grid/grid.h"
#include "solver/progress.h"
#include "solver/rank_group.h"
#include "solver/scene/scene_internal.h"

/* A scene's geometry and grids, built once for its coefficients and its
 * hourly suns. */
typedef struct cdl_daylight_scene {
    const cdl_scene *scene;               /* borrowed */
    cdl_scene_geometry *geometry;         /* owned */
    cdl_occluder_index *occluders;        /* owned; NULL when nothing can occlude */
    cdl_direct_context direct;            /* no lights: the exact route's visibility */
    cdl_grid *grids;                      /* scene->grid_count, owned */
} cdl_daylight_scene;

/* Build the scene's geometry, occluders and grids. The scene must hold no
 * luminaire and no emitting surface (the sky and the sun come from the
 * weather): CDL_ERR_INPUT naming the first found. */
cdl_status cdl_daylight_scene_build(const cdl_scene *scene, cdl_daylight_scene *out, cdl_error *err);
void cdl_daylight_scene_release(cdl_daylight_scene *ds);

typedef struct cdl_daylight_coefficient_options {
    const cdl_reinhart_patches *patches;  /* the sky's patches (with the ground) */
    const cdl_vec3 *suns;                 /* unit world directions towards the suns (interreflected) */
    size_t sun_count;
    double target;                        /* relative standard error of the sampled part under the reference sky */
    const double *reference_sky;          /* per patch, cd/m^2: the sky the error is held and stated for; NULL:
                                           * a uniform sky of 1 cd/m^2 */
    int collapse;                         /* 1: keep only each point's E under the reference sky (sky is points x
                                           * 1): a sky whose shape never changes needs no more */
    int keep_direct;                      /* 1: the direct part apart too (direct) */
    int direct_only;                      /* 1: no paths: the direct part alone, exact where the exact route is
                                           * (sampled points get 0 and exact[i] 0) */
    uint64_t seed;
    int threads;                          /* >= 1 */
    cdl_rank_group *ranks;                /* NULL: this process computes every point; else the points are
                                           * dealt among the ranks (rank_group.h, in the pool's chunks) and
                                           * rank 0 ends with every point's coefficients, the others with
                                           * their own points' rows only (cdl_rank_deal_row) */
    double max_paths;                     /* most paths a point */
    cdl_progress_sink progress;
} cdl_daylight_coefficient_options;

/* Points per route of the direct sky part. */
typedef struct cdl_daylight_routes {
    size_t exact;                         /* the whole hemisphere, or visible polygons */
    size_t through_glass;                 /* visible polygons through panes, weighed by their transmittance */
    size_t sampled[CDL_ROUTE_COUNT];      /* sampled, by the route's reason */
} cdl_daylight_routes;

typedef struct cdl_daylight_grid_coefficients {
    size_t points, patches, suns;
    float *sky;                           /* points x patches, row by row: lx per cd/m^2 (patches 1 when
                                           * collapsed: lx under the reference sky) */
    float *sun;                           /* points x suns: lx per lx of direct normal illuminance (NULL without suns) */
    double *sky_rel_stderr;               /* per point, under the reference sky (0 where E is 0) */
    double *sun_rel_stderr;               /* per point, of the suns' coefficients summed (NULL without suns) */
    float *direct;                        /* keep_direct: points x patches, the direct part (NULL otherwise) */
    unsigned char *exact;                 /* per point: 1 where the direct part took the exact route */
    cdl_daylight_routes routes;
    uint64_t paths, rays;
} cdl_daylight_grid_coefficients;

/* The coefficients of grid g. With ranks, a collective: the counts of
 * paths, rays and routes are every rank's summed; rank 0's arrays hold every
 * point's row, another rank's only its own points' (at
 * cdl_rank_deal_row of the deal cdl_daylight_coefficients_deal gives). */
cdl_status cdl_daylight_coefficients_compute(const cdl_daylight_scene *ds, size_t g,
                                             const cdl_daylight_coefficient_options *options,
                                             cdl_daylight_grid_coefficients *out, cdl_error *err);
void cdl_daylight_coefficients_release(cdl_daylight_grid_coefficients *c);

/* How the points of a grid of `points` are dealt among `ranks` (NULL: one process). */
cdl_rank_deal cdl_daylight_coefficients_deal(cdl_rank_group *ranks, size_t points);

/* The direct sun at each point of grid g per lx of direct normal
 * illuminance: max(0, n.s) times what the panes on the way let through (0
 * when something opaque is in the way), the sun a parallel beam along
 * unit `to_sun` (its disk's half-degree penumbra is left out). Thread-safe. */
void cdl_daylight_direct_sun(const cdl_daylight_scene *ds, size_t g, cdl_vec3 to_sun, float *out);

#endif
