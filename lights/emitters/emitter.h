/* emitter.h - every light source behind one interface.
 *
 *   kind          parameters                                  closed-form flux
 *   point         position, I (cd)                            4 pi I
 *   spot          position, axis, I0, half angle, falloff     2 pi I0 [(1-cos a_f) + smoothstep part]
 *                 start (smoothstep) or exponent n (cos^n)    2 pi I0 / (n + 1)
 *   goniometric   position, rotation, photometry, factors     factor x photometric flux
 *   (opening)     the same, spread over the file's opening     the same
 *   area          Lambertian, one-sided shape, L (cd/m^2)     pi L A
 *   directional   direction of travel, E normal to the beam   E per m^2 of beam section
 *   (sun disk)    the same from a disk of angular diameter     the same
 *   environment   uniform L, CIE overcast (L at   see cdl_emitter_flux
 *                 the zenith) or lat-long image,
 *                 up, hemisphere
 *
 * All inputs are photometric (cd, cd/m^2, lx, lm). Positions in metres,
 * world frame (right-handed, z up). An emitter is immutable once created;
 * all queries are thread-safe.
 *
 * The solver asks three kinds of question:
 *  - delta emitters (point, spot, goniometric, directional): the exact
 *    unshadowed illuminance at a point and where to aim the one shadow ray;
 *  - area and environment emitters: the exact unoccluded illuminance
 *    (closed form), used when nothing hides the emitter;
 *  - all non-delta emitters: importance samples with their pdf, used when
 *    the emitter is partly hidden.
 *
 * Photometric amounts given as flux (a scene's `flux_lm`) are converted by
 * the caller, once, with the closed-form flux, which is linear in the
 * intensity or luminance: create the emitter with 1 cd (1 cd/m^2), read
 * cdl_emitter_flux, and scale: I0 = Phi / flux_at_1cd (spot), L = Phi /
 * flux_at_1nit (area; = Phi / (pi A)), I = Phi / (4 pi) (point,
 * cdl_isotropic_intensity_from_flux). Goniometric emitters take flux_lm.
 *
 * Each kind's parameters are documented at its struct below (meaning,
 * unit, default, range), with the physics it uses.
 * Constructors validate every parameter and fail with CDL_ERR_INPUT and
 * "<kind> emitter: <parameter>: expected ..., found ..." (the caller
 * prefixes the scene file and JSON path).
 *
 * Ownership: an emitter from cdl_emitter_create_* belongs to the caller,
 * who frees it with cdl_emitter_release (NULL is fine). Parameters are
 * copied, except the photometry of a goniometric emitter, which is
 * borrowed and must outlive it. Thread safety: an emitter is immutable
 * once created; every query may run on any number of threads at once.
 * Errors: the constructors fail with CDL_ERR_INPUT (message above) or
 * CDL_ERR_INTERNAL (memory), leaving *out NULL; the queries do not fail.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_EMITTER_H
#define CANDELA_LIGHTS_EMITTERS_EMITTER_H

#include <stddef.h>
#include <stdint.h>

#include "lights/photometry/photometry.h"
#include "base/error.h"
#include "radiometry/units.h"
#include "radiometry/vec3.h"

typedef enum cdl_emitter_kind {
    CDL_EMITTER_POINT,
    CDL_EMITTER_SPOT,
    CDL_EMITTER_GONIOMETRIC,
    CDL_EMITTER_AREA,
    CDL_EMITTER_DIRECTIONAL,
    CDL_EMITTER_ENVIRONMENT,
    CDL_EMITTER_GONIOMETRIC_OPENING        /* a goniometric luminaire spread over its luminous opening */
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

/* Goniometric: I(w) = I_table(luminaire_from_world w) x k with
 * k = s x output factor x tilt factor x multiplier x maintenance factor,
 * s = flux_lm / Phi_table when flux_lm > 0 (the table is rescaled to that
 * luminaire flux first; every application factor then acts on it), else 1.
 * world_from_luminaire = Rz Ry Rx, right-handed about the fixed world axes;
 * the tilt factor is taken at the installed tilt (angle between the turned
 * nadir and world -z). */
typedef struct cdl_goniometric_params {
    cdl_vec3 position;
    double rotation_deg[3];                /* about world x, then y, then z (fixed axes) */
    const cdl_photometry *photometry;      /* borrowed: must outlive the emitter */
    double multiplier;                     /* scene multiplier, > 0 (default 1) */
    double maintenance_factor;             /* > 0, (0, 1] typically (default 1) */
    double flux_lm;                        /* > 0: rescale the table to this flux; <= 0: keep */
    int apply_output_factor;               /* 1: apply cdl_photometry_output_factor (default 1) */
} cdl_goniometric_params;
#define CDL_GONIOMETRIC_PARAMS_DEFAULT {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, NULL, 1.0, 1.0, 0.0, 1}

/* Shapes of area emitters. Triangles are counter-clockwise seen from the
 * emitting side; rect and disk emit along their normal (u x v for rect);
 * a sphere emits outward, or inward with `inward`. Degenerate triangles
 * (zero area) are skipped; the total area must be > 0. */
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

/* Parallel light, or (angular_diameter_deg > 0) light from a distant disk
 * of that angular diameter and uniform luminance, `illuminance` normal to
 * its axis: the sun, 0.533 degrees (emitter_directional.c). A disk is not
 * a delta emitter: it has an exact illuminance, samples and radiance. */
typedef struct cdl_directional_params {
    cdl_vec3 direction;                    /* direction the light travels (the disk's axis) */
    cdl_illuminance illuminance;           /* measured normal to the beam */
    double angular_diameter_deg;           /* 0 (default): parallel; else in (0, 10] */
} cdl_directional_params;

/* The luminance of an environment without an image (image == NULL). */
typedef enum cdl_sky_model {
    CDL_SKY_UNIFORM,                       /* `luminance` in every direction */
    CDL_SKY_CIE_OVERCAST,                  /* the CIE standard overcast sky (Moon and Spencer 1942, adopted by
                                            * the CIE in 1955; CIE 110-1994): L(theta) = L_z (1 + 2 cos theta)
                                            * / 3, theta from `up`, L_z = `luminance`; nothing below the
                                            * horizon */
    CDL_SKY_CIE_GENERAL,                   /* the CIE standard general sky of type `cie_type` (1..15; ISO
                                            * 15469:2004 / CIE S 011/E:2003): L = L_z phi(Z) f(chi) / (phi(0)
                                            * f(Z_s)), Z from `up`, chi from `sun`; nothing below the horizon */
    CDL_SKY_PEREZ                          /* the Perez all-weather sky (Perez, Seals and Michalsky 1993) of
                                            * coefficients `perez` (cdl_perez_sky_compute), the same form
                                            * without the CIE's offset in f, negative values taken as 0 */
} cdl_sky_model;

typedef struct cdl_environment_params {
    cdl_vec3 up;                           /* zenith, any length > 0 (default +z) */
    int upper_hemisphere_only;             /* 1: no light from below the horizon of `up` (a CIE overcast sky
                                            * has none either way) */
    /* image == NULL: a sky model of `luminance` (cd/m^2, >= 0) */
    cdl_luminance luminance;
    /* lat-long image (copied): luminance in cd/m^2 per pixel BEFORE `scale`
     * (the file's Y, or 0.2126 R + 0.7152 G + 0.0722 B), row-major, top row
     * first, every value finite and >= 0. Column u in [0,1) looks towards
     * azimuth phi = pi + 2 pi u (counter-clockwise from +x seen from above;
     * left edge -x, centre +x); row v in [0,1) towards polar angle pi v from
     * `up`. For an `up` other than +z, azimuth 0 is world +x made
     * perpendicular to `up` (world +y if `up` is within 2.6 deg of the x axis). */
    const float *image;
    int width, height;
    double scale;                          /* multiplies the image, > 0 (default 1) */
    cdl_sky_model sky;                     /* image == NULL: the model (default CDL_SKY_UNIFORM) */
    /* CDL_SKY_CIE_GENERAL and CDL_SKY_PEREZ: */
    int cie_type;                          /* 1..15 */
    double perez[5];                       /* a, b, c, d, e of the Perez sky (b < 0) */
    cdl_vec3 sun;                          /* towards the sun, any length > 0; above the horizon unless the
                                            * sky's indicatrix is constant (CIE types 1, 3, 5) */
    int scale_to_horizontal;               /* 1: scale so that the unobstructed horizontal illuminance is
                                            * `horizontal` (`luminance` unused); 0: `luminance` is L_z */
    cdl_illuminance horizontal;            /* >= 0 */
} cdl_environment_params;
#define CDL_ENVIRONMENT_PARAMS_DEFAULT                                                                        \
    {{0.0, 0.0, 1.0}, 0, {0.0}, NULL, 0, 0, 1.0, CDL_SKY_UNIFORM, 0, {0.0, 0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, \
     0, {0.0}}

/* 1 when a CIE standard general sky type (1..15) brightens towards the sun
 * (its indicatrix is not constant: every type but 1, 3 and 5), so that the
 * sun's place matters. */
int cdl_sky_cie_type_uses_sun(int type);

/* Create an emitter of each kind from its parameters (validated, copied;
 * see the ownership note above for the photometry). */
cdl_status cdl_emitter_create_point(const cdl_point_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_spot(const cdl_spot_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_goniometric(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_area(const cdl_area_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_directional(const cdl_directional_params *p, cdl_emitter **out, cdl_error *err);
cdl_status cdl_emitter_create_environment(const cdl_environment_params *p, cdl_emitter **out, cdl_error *err);
void cdl_emitter_release(cdl_emitter *emitter);

/* Near field: the goniometric luminaire of `p` spread over the luminous
 * opening of its photometry (metadata.opening; cdl_luminous_opening_is_spread
 * must hold), an extended emitter. A flat opening (a rectangle, circle or
 * ellipse of non-zero size in the luminaire's x-y plane, or LM-63-2019's
 * vertical circle or ellipse in its y-z plane): each element dA of the opening emits I(w) dA / A towards w, so
 * the opening's luminance is I(w) / (A |cos theta_o|): downward light
 * (gamma < 90) from its lower face, upward light from its upper face; the
 * flux and the far-field intensity are the point emitter's. Exact
 * unoccluded illuminance (cdl_emitter_exact_illuminance): in closed form
 * where the table is I0 cos(gamma) below the horizontal and dark above
 * (within 1e-6 I0 at every sample) on a rectangle or circle (a Lambertian
 * area emitter of luminance I0 / A); otherwise an adaptive Gauss-Legendre
 * cubature of the opening converged to its tolerance, 1e-5 relative unless
 * set (cdl_emitter_opening_set_tolerance; it fails, and the
 * caller samples, where 4096 cells do not reach that: a receiver in the
 * opening's plane). Samples (cdl_emitter_sample) with their exact pdf for
 * every opening, for shadows. A luminous solid of LM-63 Table 1 (a box
 * with luminous sides, vertical cylinder, vertical elliptic cylinder,
 * sphere, ellipsoid, horizontal cylinder along or across, of non-zero
 * size): every face point seen from w has the luminance I(w) / A_proj(w)
 * (cdl_luminous_opening_projected_area), so the solid's intensity is I(w)
 * and its flux the file's. Exact illuminance for a sphere the receiver
 * sees whole (a cubature of its cone converged to 1e-5; it declines where
 * the receiver's horizon cuts the sphere or the panels do not converge),
 * none for the other solids (cdl_emitter_has_exact_illuminance is 0);
 * samples uniform in the solid angle of the solid's bounding box (a box:
 * the box itself) or of its bounding sphere, whichever subtends less,
 * with their exact pdf. */
cdl_status cdl_emitter_create_goniometric_opening(const cdl_goniometric_params *p, cdl_emitter **out,
                                                  cdl_error *err);

/* The point model a goniometric luminaire spread over its opening or solid
 * carries (its far field: the file's I(w) from the luminaire's centre),
 * borrowed; NULL for any other emitter. */
const cdl_emitter *cdl_emitter_far_field(const cdl_emitter *emitter);

/* The lower (nadir-facing) face of a goniometric opening emitter in world
 * coordinates: a CDL_SHAPE_RECT or CDL_SHAPE_DISK, an ellipse as its
 * bounding rectangle (which contains it); a luminous solid's bounding
 * sphere (a CDL_SHAPE_SPHERE). Returns 0 (and sets nothing) for
 * other kinds. What a solver needs to bound where the light comes from. */
int cdl_emitter_opening_face(const cdl_emitter *emitter, cdl_shape *face);

/* The relative tolerance of a flat goniometric opening emitter's cubature
 * (its exact and partial illuminance; 1e-5 when created), clamped to
 * [1e-7, 1e-3]. A solver sets it from its target error before the emitter
 * is used by several threads. Returns 0 (and changes nothing) for other
 * emitters or a tolerance that is not positive. */
int cdl_emitter_opening_set_tolerance(cdl_emitter *emitter, double relative);

/* The rectangle bounding a flat goniometric opening emitter (the
 * rectangle itself, or the one around a circle or ellipse), its four
 * corners in world coordinates in order round it. Returns 0 (and sets
 * nothing) for luminous solids and other kinds. */
int cdl_emitter_opening_bounding_rectangle(const cdl_emitter *emitter, cdl_vec3 corner[4]);

/* Illuminance at p on the plane of n (unit) from the part of a flat
 * goniometric opening emitter that lies within the given convex polygons
 * (world points in the opening's plane, `counts[k]` corners for polygon k,
 * the polygons one after another in `points`, not overlapping): the
 * opening's integral E = (1 / A) int I(w_x) cos(theta_r) / r_x^2 dA_x
 * restricted to them, the polygons clipped to the opening (a circle's or
 * ellipse's arcs exactly) and integrated by the adaptive cubature to its
 * tolerance (cdl_emitter_opening_set_tolerance), as the whole opening's. What a solver gives the part of an
 * opening a point sees past planar occluders: with the whole opening as
 * the one polygon it is the unoccluded E. CDL_ERR_USAGE for other
 * emitters; CDL_ERR_INTERNAL (the caller samples instead) where the
 * cubature does not converge within its budget or the parts have too
 * many corners. */
cdl_status cdl_emitter_opening_partial_illuminance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n,
                                                   const cdl_vec3 *points, const int *counts, size_t polygons,
                                                   cdl_illuminance *E, cdl_error *err);

/* 1 when a goniometric opening emitter's exact illuminance is Lambert's
 * closed form (a Lambertian table on a rectangle or circle: microseconds);
 * 0 when it is the adaptive cubature (tenths of a millisecond, more within
 * a few centimetres of the opening) and for other kinds. Lets a solver
 * that needs many unshadowed values cheaply (next-event estimation)
 * sample such an emitter instead. */
int cdl_emitter_opening_is_lambertian(const cdl_emitter *emitter);

/* 1 for a directional emitter with a disk (angular_diameter_deg > 0):
 * *to_light the unit direction of its axis towards it, *half_angle_rad
 * half its angular diameter. 0 (and nothing set) for any other. */
int cdl_emitter_directional_disk(const cdl_emitter *emitter, cdl_vec3 *to_light, double *half_angle_rad);

/* The kind the emitter was created as. */
cdl_emitter_kind cdl_emitter_get_kind(const cdl_emitter *emitter);
/* 1 for point, spot, goniometric, directional: light from one direction. */
int cdl_emitter_is_delta(const cdl_emitter *emitter);

/* Closed-form total flux. Point/spot/goniometric/area: all light emitted.
 * Directional: flux through 1 m^2 normal to the beam (= E).
 * Environment: flux incident on the face of a 1 m^2 disk facing `up` with
 * nothing around it: pi L for a uniform sky (full or upper hemisphere);
 * for a CIE overcast sky 7 pi L_z / 9; for an image, the exact sum over
 * pixels of L times their cosine-weighted solid angle above the horizon. */
cdl_luminous_flux cdl_emitter_flux(const cdl_emitter *emitter);

/* Luminous intensity emitted toward world direction `dir` (any length > 0).
 * Point, spot, goniometric: their distribution. Area: int L max(0, m.w) dA
 * over the shape, self-occlusion ignored (so its integral over the sphere
 * is the flux). Directional and environment: 0 (no finite intensity). */
cdl_luminous_intensity cdl_emitter_intensity(const cdl_emitter *emitter, cdl_vec3 dir);

/* The installed tilt of a goniometric emitter in degrees (angle between its
 * turned nadir and world -z), the angle its TILT factor was taken at; 0 for
 * other kinds. */
double cdl_emitter_goniometric_tilt_deg(const cdl_emitter *emitter);

/* ---- delta emitters ------------------------------------------------------ */

typedef struct cdl_delta_light {
    cdl_vec3 to_light;        /* unit vector from the receiver towards the light */
    double distance;          /* metres; INFINITY for directional */
    cdl_illuminance E;        /* unshadowed illuminance on the plane of n */
} cdl_delta_light;

/* Illuminance at p on the plane with unit normal n (hemisphere n faces),
 * without shadowing: E = I cos(theta) / d^2 (directional: E_n cos(theta)),
 * with full relative precision for d from 1e-4 to 1e5 m and any I. Returns
 * 0 when E = 0 (behind, outside the beam, p at the light) and for
 * non-delta emitters. */
int cdl_emitter_eval_delta(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out);

/* cdl_emitter_eval_delta for count receivers (p[i], n[i]) at once, the
 * same values; out[i].E is 0 where no light arrives. One dispatch per
 * call: the direct solver's hot loop. */
void cdl_emitter_eval_delta_many(const cdl_emitter *emitter, const cdl_vec3 *p, const cdl_vec3 *n, size_t count,
                                 cdl_delta_light *out);

/* The cone outside which a positional delta emitter sends no light: from
 * *position, only directions w (unit) with dot(w, *axis) > *cos_min carry
 * light. A spot: its axis and half angle (hemisphere for cos^n); a
 * goniometric luminaire: its rotated nadir and the largest gamma with
 * non-zero interpolated intensity (type C tables). Returns 0 when there is
 * no such cone (point lights, uplights, types A/B, directional and extended
 * emitters): light may go anywhere. Lets a solver skip, in one test, points
 * a luminaire cannot reach. */
int cdl_emitter_emission_cone(const cdl_emitter *emitter, cdl_vec3 *position, cdl_vec3 *axis, double *cos_min);

/* ---- extended emitters (area, environment) -------------------------------- */

/* Exact illuminance at p on the plane with unit normal n from the whole
 * emitter as if nothing occluded it, parts below the plane excluded.
 * Area emitters: contour integral (Lambert) over the shape clipped to the
 * hemisphere (far from a small polygon, a converged cubature of the same
 * integral, which does not cancel); disk and sphere in closed form; inside
 * an inward sphere pi L. A non-convex mesh's self-occlusion is ignored (the
 * caller's visibility test must treat the emitter's own triangles as
 * occluders). Uniform environment: pi L (full sphere) or pi L (1 + cos
 * beta) / 2 (upper hemisphere, beta between n and up). CIE overcast sky:
 * (L_z / 3) [pi (1 + cos beta) / 2 + (4 / 3)((pi - beta) cos beta +
 * sin beta)]. Image environment: the exact sum over pixels of
 * L times the pixel's projected solid angle on n's hemisphere (pixels the
 * horizon crosses clipped exactly), one pass over the pixels; it depends on
 * n only, so callers may cache it by normal. Delta emitters: the E of
 * cdl_emitter_eval_delta. `err` may be NULL. */
cdl_status cdl_emitter_exact_illuminance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E,
                                         cdl_error *err);

/* Bounds on an environment's luminance over a convex spherical polygon of
 * directions: unit world vertex directions dirs[0 .. count), edges the
 * shorter great-circle arcs, either orientation. *lo <= L(w) <= *hi for
 * every direction w in it (conservative: pixels just outside the region
 * may count; lights/environment/environment_bounds.h). Returns 0 (and sets nothing)
 * for an emitter that is not an environment. Thread-safe. */
int cdl_emitter_luminance_bounds(const cdl_emitter *emitter, const cdl_vec3 *dirs, int count, cdl_luminance *lo,
                                 cdl_luminance *hi);

/* 1 when cdl_emitter_exact_illuminance has a closed form for this emitter
 * (every kind). */
int cdl_emitter_has_exact_illuminance(const cdl_emitter *emitter);

typedef struct cdl_light_sample {
    cdl_vec3 to_light;        /* unit vector from p towards the sampled point */
    double distance;          /* to the sampled point; INFINITY for environment */
    cdl_luminance L;          /* luminance arriving along -to_light */
    double pdf;               /* with respect to solid angle at p; > 0 */
} cdl_light_sample;

/* Importance-sample a direction towards the emitter from p (n: unit
 * receiver normal). u1, u2 in [0, 1); stratified pairs give stratified
 * samples. Returns 0 if the sample carries no light (behind the receiver's
 * plane, the back of the emitter, a dark pixel) and for delta emitters.
 * The mean of L cos / pdf over samples (counting the 0s) is, without
 * shadowing, exactly cdl_emitter_exact_illuminance: area samples are points
 * on the emitter chosen whether or not another part of the same emitter
 * hides them, so a shadow ray to each sample gives the shadowed E.
 * Samplers: rects uniform in
 * solid angle when they subtend >= 1e-3 sr, else by area; meshes of up to
 * 64 triangles by solid angle (facing triangles only), larger ones by
 * area; disks cos-weighted about n when they fill half the receiver's
 * cosine-weighted hemisphere, else by area; spheres uniform in their cone
 * (outside) or cos-weighted about n (inside an inward sphere); uniform and
 * CIE overcast skies cos-weighted about n; image sky by pixel luminance x solid angle (a
 * sampler for one receiver normal, by luminance x projected solid angle,
 * is lights/environment/environment_sampler.h). */
int cdl_emitter_sample(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, double u1, double u2,
                       cdl_light_sample *out);

/* Luminance arriving at p from world direction `to_light` (any length > 0)
 * and, in *pdf (may be NULL), the solid-angle density with which
 * cdl_emitter_sample(emitter, p, n, ...) produces that direction (for MIS);
 * L = 0 if no light arrives that way. Area emitters: the nearest point of
 * the emitter along the ray, L = 0 on its back; the pdf is that point's.
 * The receiver normal n is needed because some samplers depend on it
 * (uniform skies, disks close to p and inward spheres sample cos-weighted
 * about n).
 * Delta emitters: L = 0, pdf = 0. */
cdl_luminance cdl_emitter_radiance(const cdl_emitter *emitter, cdl_vec3 p, cdl_vec3 n, cdl_vec3 to_light,
                                   double *pdf);

#endif
