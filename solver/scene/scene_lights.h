/* scene_lights.h - the scene's luminaires and emitting surfaces as emitters.
 *
 * Every luminaire of the scene becomes one emitter; every emitting surface
 * piece (a surface with luminance_cd_m2, each box face separately) becomes an
 * area emitter on its geometry. Photometric files and environment images
 * are read here; their errors are prefixed with the scene file and JSON path.
 * Conversions done once, at creation:
 *   point   flux_lm -> I = Phi / (4 pi)
 *   spot    flux_lm -> I0 = Phi / (flux of the same spot at 1 cd)
 *   area    flux_lm -> L = Phi / (pi A)
 *   all     x maintenance_factor (goniometric: also multiplier, file factors)
 */
#ifndef CANDELA_SOLVER_SCENE_LIGHTS_H
#define CANDELA_SOLVER_SCENE_LIGHTS_H

#include <stddef.h>

#include "lights/emitters/emitter.h"
#include "lights/emitters/intensity_map.h"
#include "lights/photometry/photometry.h"
#include "radiometry/bounds.h"
#include "solver/geometry/occluder_index.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_geometry.h"

#define CDL_SCENE_LIGHT_OUTLINE_MAX (CDL_REGION_MAX_PLANES - 2)

/* A light as placed in the scene: its emitter and what the solvers need to
 * know of where its light can go (bounds, outline, emission cone). */
typedef struct cdl_scene_light {
    const cdl_emitter *emitter;
    char label[160];                  /* "luminaires[3]" or "surfaces[2]" (+ face) for the plan */
    size_t luminaire;                 /* its index in scene->luminaires; SIZE_MAX for an emitting surface */
    uint32_t owner;                   /* geometry piece id of its own surface, UINT32_MAX if none */
    int has_body;                     /* its luminaire has a body (scene_bodies.h): piece `body` */
    uint32_t body;                    /* geometry piece id of that body */
    int has_closed_form;              /* area or environment (uniform, overcast or image) */
    int is_environment;
    int is_image;                     /* environment: a lat-long image (not one luminance everywhere) */
    int sky_varies;                   /* environment: a sky model whose luminance varies (CIE overcast, CIE
                                       * general, Perez) */
    int is_sun_disk;                  /* a directional light from a disk (the sun): extended, exact past
                                       * planar occluders (direct_exact_route.c) */
    cdl_vec3 sun_dir;                 /* sun disk: unit, towards it */
    double sun_half_angle;            /* sun disk: radians */
    int upper_only;                   /* environment: sky above the horizon of `up` only */
    cdl_vec3 up;
    /* A convex outline bounding the emitter (area emitters), for the
     * per-point visibility region; outline_count = 0 when there is none.
     * Kept out of line so that the records the per-point loop walks stay small. */
    cdl_vec3 *outline;                /* up to CDL_SCENE_LIGHT_OUTLINE_MAX points, owned by whoever built the light */
    int outline_count;
    int outline_is_sphere;            /* use center/radius instead */
    cdl_vec3 sphere_center;
    double sphere_radius;
    cdl_bounds3 bounds;               /* world bounds of the emitter (delta: its position); */
    int bounded;                      /* 0 (and bounds empty) for directional and environment */
    /* Emission cone (cdl_emitter_emission_cone): no light outside the
     * directions within cone_angle of cone_axis from cone_position. */
    int has_cone;
    cdl_vec3 cone_position, cone_axis;
    double cone_angle;                /* radians */
    double cone_cos, cone_sin;        /* cos and sin of cone_angle */
    double cone_cos2;                 /* cos^2 of cone_angle */
    /* Near field (a goniometric luminaire with near_field "auto"): the
     * luminaire is two lights, its opening (near_part 1) at points nearer
     * than near_radius to near_center, its point model (near_part -1) at
     * the others; near_part 0 lights every point. */
    int near_part;
    cdl_vec3 near_center;
    double near_radius;               /* where the point model's error bound falls to CDL_NEAR_FIELD_SHARE of the
                                       * target, at least CDL_NEAR_FIELD_DISTANCES x the opening's largest dimension */
    double near_model_error;          /* that bound at near_radius (relative) */
    int costly_exact;                 /* its exact E is a cubature (an opening of a non-Lambertian table, a
                                       * CIE general or Perez sky) */
    char *model;                      /* NULL, or what the light was made from in words (a daylight sky and
                                       * its sun: scene_sky.h), for the plan; owned like the outline */
    int near_field_unspread;          /* near_field "always" on a file whose opening is not spread: a point */
    const char *sealed_by;            /* NULL, or the JSON path of the closed box that keeps its light from
                                       * every point of the solve (solver/solve_sealed.h): left out */
    /* A bounded extended light's intensity as seen from afar, on a coarse
     * map over the sphere (lights/emitters/intensity_map.h), and the point
     * it is taken from (a spread luminaire's photometric centre, else the
     * centre of its bounds): the far-field guess that weighs it in the
     * one-light draw. NULL for the other lights; owned like the outline. */
    cdl_intensity_map *guess_map;
    cdl_vec3 guess_origin;
} cdl_scene_light;

/* The piece a light's own shadow rays and occluder tests pass through:
 * its own surface (an area emitter, whose samples lie on it) or its body
 * (a luminaire's light leaves through its opening, never blocked by its
 * own housing); UINT32_MAX when it has neither. */
static inline uint32_t cdl_scene_light_own_piece(const cdl_scene_light *light)
{
    return light->owner != UINT32_MAX ? light->owner : light->has_body ? light->body : UINT32_MAX;
}

/* Does the light reach p at all as far as its near-field split goes (and
 * is it in the solve at all: not sealed out)? */
static inline int cdl_scene_light_applies(const cdl_scene_light *light, cdl_vec3 p)
{
    if (light->sealed_by) return 0;
    if (!light->near_part) return 1;
    cdl_vec3 d = cdl_vec3_sub(p, light->near_center);
    int near = cdl_vec3_dot(d, d) < light->near_radius * light->near_radius;
    return light->near_part > 0 ? near : !near;
}

typedef struct cdl_scene_lights {
    cdl_scene_light *lights;       /* one per emitter, in scene order: luminaires, then emitting surfaces */
    const char **kinds;             /* "point", "area", ... per light */
    cdl_emitter **emitters;
    size_t count;
    cdl_photometry **photometries;  /* owned, one per goniometric entry (its copies share it) */
    size_t photometry_count;
    /* Per photometry, its opening's near-field bound (near_field_bound.h),
     * measured once in the luminaire's own frame when a copy first needs it. */
    struct cdl_near_field_bound *near_bounds;
    unsigned char *near_bound_known;
    /* Per luminaire of the scene (scene->luminaires[k]): its photometry, borrowed; NULL unless goniometric. */
    const cdl_photometry **luminaire_photometry;
    int has_environment;
} cdl_scene_lights;

cdl_status cdl_scene_lights_build(const cdl_scene *scene, const cdl_scene_geometry *geometry, cdl_scene_lights *out,
                                  cdl_error *err);
void cdl_scene_lights_release(cdl_scene_lights *lights);

#endif
