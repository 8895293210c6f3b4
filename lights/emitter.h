/* emitter.h - every light source behind one interface.
 *
 *   kind          parameters                                  closed-form flux
 *   point         position, I (cd)                            4 pi I
 *   spot          position, axis, I0, half angle, falloff     2 pi I0 [(1-cos a_f) + smoothstep part]
 *                 start (smoothstep) or exponent n (cos^n)    2 pi I0 / (n + 1)
 *   goniometric   position, rotation, photometry, factors     factor x photometric flux
 *   area          Lambertian, one-sided shape, L (cd/m^2)     pi L A
 *   directional   direction of travel, E normal to the beam   E per m^2 of beam section
 *   environment   uniform L or lat-long image, up, hemisphere see cdl_emitter_flux
 *
 * All inputs are photometric (cd, cd/m^2, lx, lm). Positions in metres,
 * world frame (right-handed, z up). An emitter is immutable once created;
 * all queries are thread-safe.
 *
 * The solver asks three kinds of question:
 *  - delta emitters (point, spot, goniometric, directional): the exact
 *    unshadowed illuminance at a point and where to aim the one shadow ray;
 *  - area and uniform environment emitters: the exact unoccluded
 *    illuminance (closed form), used when nothing hides the emitter;
 *  - all non-delta emitters: importance samples with their pdf, used when
 *    the emitter is partly hidden.
 */
#ifndef CANDELA_LIGHTS_EMITTER_H
#define CANDELA_LIGHTS_EMITTER_H

#include <stddef.h>
#include <stdint.h>

#include "lights/photometry.h"
#include "radiometry/error.h"
#include "radiometry/units.h"
#include "radiometry/vec3.h"

typedef enum cdl_emitter_kind {
    CDL_EMITTER_POINT,
    CDL_EMITTER_SPOT,
    CDL_EMITTER_GONIOMETRIC,
    CDL_EMITTER_AREA,
    CDL_EMITTER_DIRECTIONAL,
    CDL_EMITTER_ENVIRONMENT
} cdl_emitter_kind;

typedef struct cdl_emitter cdl_emitter;

/* ---- constructors -------------------------------------------------------- */

typedef struct cdl_point_params {
    cdl_vec3 position;
    cdl_luminous_intensity intensity;      /* >= 0 */
} cdl_point_params;

typedef struct cdl_spot_params {
    cdl_vec3 position;
    cdl_vec3 direction;                    /* beam axis, any length > 0 */
    cdl_luminous_intensity intensity;      /* on the axis, >= 0 */
    int use_exponent;                      /* 0: smoothstep profile, 1: cos^n */
    double half_angle_deg;                 /* smoothstep: (0, 180], no light beyond */
    double falloff_start_deg;              /* smoothstep: [0, half_angle]; = half_angle is a hard edge */
    double exponent;                       /* cos^n: n >= 0, zero behind the spot */
} cdl_spot_params;

typedef struct cdl_goniometric_params {
    cdl_vec3 position;
    double rotation_deg[3];                /* about world x, then y, then z (fixed axes) */
    const cdl_photometry *photometry;      /* borrowed: must outlive the emitter */
    double multiplier;                     /* scene multiplier, >= 0 (default 1) */
    double maintenance_factor;             /* (0, 1] typically (default 1) */
    double flux_lm;                        /* > 0: rescale the table to this flux; <= 0: keep */
    int apply_output_factor;               /* 1: apply cdl_photometry_output_factor (default 1) */
} cdl_goniometric_params;

/* Shapes of area emitters. Triangles are counter-clockwise seen from the
 * emitting side; rect and disk emit along their normal (u x v for rect). */
typedef enum cdl_shape_kind {
    CDL_SHAPE_TRIANGLES,
    CDL_SHAPE_RECT,
    CDL_SHAPE_DISK,
    CDL_SHAPE_SPHERE
} cdl_shape_kind;

typedef struct cdl_shape {
    cdl_shape_kind kind;
    /* CDL_SHAPE_TRIANGLES (borrowed during creation, copied) */
    const double *vertices;                /* xyz, vertex_count x 3 */
    size_t vertex_count;
    const uint32_t *triangles;             /* triangle_count x 3 */
    size_t triangle_count;
    /* CDL_SHAPE_RECT: origin + s u + t v */
    cdl_vec3 origin, u, v;
    /* CDL_SHAPE_DISK and CDL_SHAPE_SPHERE */
    cdl_vec3 center, normal;
    double radius;
    int inward;                            /* sphere: 1 emits towards its centre */
} cdl_shape;

typedef struct cdl_area_params {
    cdl_shape shape;
    cdl_luminance luminance;               /* Lambertian, one-sided, >= 0 */
} cdl_area_params;

typedef struct cdl_directional_params {
    cdl_vec3 direction;                    /* direction the light travels */
    cdl_illuminance illuminance;           /* measured normal to the beam */
} cdl_directional_params;

typedef struct cdl_environment_params {
    cdl_vec3 up;                           /* zenith */
    int upper_hemisphere_only;             /* 1: no light from below the horizon of `up` */
    /* uniform: image == NULL */
    cdl_luminance luminance;
    /* lat-long image (copied): luminance in cd/m^2 per pixel, row-major, top
     * row first. Column u in [0,1) looks towards azimuth phi = pi + 2 pi u
     * (counter-clockwise from +x seen from above; left edge -x, centre +x);
     * row v in [0,1) towards polar angle pi v from `up`. */
    const float *image;
    int width, height;
    double scale;                          /* multiplies the image (default 1) */
} cdl_environment_params;

cdl_status cdl_emitter_create_point(const cdl_point_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_spot(const cdl_spot_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_goniometric(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_area(const cdl_area_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_directional(const cdl_directional_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_environment(const cdl_environment_params *p, cdl_emitter **out, cdl_error *err);
void cdl_emitter_release(cdl_emitter *emitter);

cdl_emitter_kind cdl_emitter_get_kind(const cdl_emitter *emitter);
/* 1 for point, spot, goniometric, directional: light from one direction. */
int cdl_emitter_is_delta(const cdl_emitter *emitter);

/* Closed-form total flux. Point/spot/goniometric/area: all light emitted.
 * Directional: flux through 1 m^2 normal to the beam (= E).
 * Environment: flux incident on the upper face of a horizontal 1 m^2 disk
 * with nothing around it (uniform full sphere: pi L; see emitter docs). */
cdl_luminous_flux cdl_emitter_flux(const cdl_emitter *emitter);

/* Luminous intensity emitted toward world direction `dir` (delta emitters
 * except directional; area emitters: the total of L cos over the shape). */
cdl_luminous_intensity cdl_emitter_intensity(const cdl_emitter *emitter, cdl_vec3 dir);

/* ---- delta emitters ------------------------------------------------------ */

typedef struct cdl_delta_light {
    cdl_vec3 to_light;        /* unit vector from the receiver towards the light */
    double distance;          /* metres; INFINITY for directional */
    cdl_illuminance E;        /* unshadowed illuminance on the plane of n */
} cdl_delta_light;

/* Illuminance at p on the plane with unit normal n (hemisphere n faces),
 * without shadowing. Returns 0 when E = 0 (behind, outside the beam). */
int cdl_emitter_eval_delta(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out);

/* ---- extended emitters (area, environment) -------------------------------- */

/* Exact illuminance at p on the plane with unit normal n from the whole
 * emitter as if nothing occluded it, parts below the plane excluded.
 * Area emitters: contour integral (Lambert) over the shape clipped to the
 * hemisphere; disk and sphere in closed form. Uniform environment:
 * pi L x (visible fraction). Returns CDL_ERR_USAGE for image environments
 * (no closed form). */
cdl_status cdl_emitter_exact_illuminance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E,
                                         cdl_error *err);

/* 1 when cdl_emitter_exact_illuminance has a closed form for this emitter
 * (every kind except the image environment). */
int cdl_emitter_has_exact_illuminance(const cdl_emitter *emitter);

typedef struct cdl_light_sample {
    cdl_vec3 to_light;        /* unit vector from p towards the sampled point */
    double distance;          /* to the sampled point; INFINITY for environment */
    cdl_luminance L;          /* luminance arriving along -to_light */
    double pdf;               /* with respect to solid angle at p; > 0 */
} cdl_light_sample;

/* Importance-sample a direction towards the emitter from p (n: receiver
 * normal, used to skip the back hemisphere where possible). Returns 0 if the
 * sample carries no light. The estimator of E is L cos / pdf averaged. */
int cdl_emitter_sample(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, double u1, double u2,
                       cdl_light_sample *out);

/* Luminance arriving at p from world direction `to_light` (any length > 0)
 * and, in *pdf (may be NULL), the solid-angle density with which
 * cdl_emitter_sample(emitter, p, n, ...) produces that direction (for MIS);
 * L = 0 if no light arrives that way. Area emitters: the nearest point of
 * the emitter along the ray, L = 0 on its back; the pdf is that point's.
 * The receiver normal n is needed because some samplers depend on it
 * (uniform environment and inward spheres sample cos-weighted about n).
 * Delta emitters: L = 0, pdf = 0. */
cdl_luminance cdl_emitter_radiance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_vec3 to_light,
                                   double *pdf);

#endif
