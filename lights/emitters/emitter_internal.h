/* emitter_internal.h - the per-kind table behind cdl_emitter (private to lights/).
 *
 * Each emitter kind lives in its own file (emitter_point.c, emitter_spot.c,
 * ...) and defines a struct whose first member is `cdl_emitter base`, plus
 * one constant table of operations. emitter.c dispatches through the table
 * and holds the validation helpers every constructor shares, so that every
 * kind reports bad parameters in the same words.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_EMITTER_INTERNAL_H
#define CANDELA_LIGHTS_EMITTERS_EMITTER_INTERNAL_H

#include "lights/emitters/emitter.h"

typedef struct cdl_emitter_ops {
    cdl_luminous_flux (*flux)(const cdl_emitter *e);
    cdl_luminous_intensity (*intensity)(const cdl_emitter *e, cdl_vec3 unit_dir);
    /* Delta emitters only (NULL otherwise). */
    int (*eval_delta)(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out);
    /* Non-delta emitters: returns 0 when there is no closed form. */
    int (*exact)(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E);
    /* Non-delta emitters only (NULL otherwise). */
    int (*sample)(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2, cdl_light_sample *out);
    cdl_luminance (*radiance)(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 unit_dir, double *pdf);
    /* Frees what the kind owns besides the block itself (may be NULL). */
    void (*destroy)(cdl_emitter *e);
    /* Positional delta emitters whose light is confined to a cone (may be NULL). */
    int (*cone)(const cdl_emitter *e, cdl_vec3 *position, cdl_vec3 *axis, double *cos_min);
    /* Delta emitters: eval_delta for many receivers (may be NULL: a loop over eval_delta). */
    void (*eval_delta_many)(const cdl_emitter *e, const cdl_vec3 *p, const cdl_vec3 *n, size_t count,
                            cdl_delta_light *out);
} cdl_emitter_ops;

struct cdl_emitter {
    cdl_emitter_kind kind;
    const cdl_emitter_ops *ops;
};

/* A zeroed block of `size` bytes whose leading cdl_emitter is filled in;
 * NULL (and an out-of-memory error) on failure. */
void *cdl_emitter_alloc(size_t size, cdl_emitter_kind kind, const cdl_emitter_ops *ops, cdl_error *err);

/* Validation shared by the constructors. `what` names the parameter, e.g.
 * "spot emitter: intensity". Each returns CDL_OK or CDL_ERR_INPUT with
 * "WHAT: expected ..., found ...". */
cdl_status cdl_emitter_check_position(cdl_vec3 v, const char *what, cdl_error *err);
/* A finite non-zero vector; *unit receives it normalised. */
cdl_status cdl_emitter_check_direction(cdl_vec3 v, const char *what, cdl_vec3 *unit, cdl_error *err);
/* A finite number >= 0 in `unit`. */
cdl_status cdl_emitter_check_nonnegative(double x, const char *what, const char *unit, cdl_error *err);
/* A finite number in [lo, hi] in `unit`. */
cdl_status cdl_emitter_check_range(double x, double lo, double hi, const char *what, const char *unit,
                                   cdl_error *err);

/* The delta-light record for a source at `position` whose intensity towards
 * the receiver at p is given by intensity_towards(emitter, direction from the
 * light to p); E = I cos / d^2 on the plane of n. Shared by point, spot and
 * goniometric emitters. Returns 0 when E = 0. */
typedef cdl_luminous_intensity (*cdl_emitter_intensity_fn)(const cdl_emitter *e, cdl_vec3 unit_dir);
int cdl_emitter_eval_positional(const cdl_emitter *e, cdl_vec3 position, cdl_emitter_intensity_fn intensity_towards,
                                cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out);

/* Columns of world_from_luminaire = Rz Ry Rx for rotations in degrees about
 * the fixed world x, y, z axes: the luminaire's x, y, z axes in world
 * (emitter_goniometric.c; shared with emitter_opening.c). */
void cdl_emitter_rotation_columns(const double rotation_deg[3], cdl_vec3 col[3]);

/* A goniometric luminaire spread over a shape (its flat opening,
 * emitter_opening.c, or luminous solid, emitter_solid.c): its struct
 * begins with this. Its flux and far-field intensity are those of `point`,
 * the same luminaire as a point, which it owns. */
typedef struct cdl_spread_emitter {
    cdl_emitter base;
    cdl_emitter *point;
} cdl_spread_emitter;

/* A zeroed spread emitter of `size` bytes (a struct beginning with a
 * cdl_spread_emitter) of kind CDL_EMITTER_GONIOMETRIC_OPENING, with the
 * point model of p made; NULL with *status and err set on failure. */
void *cdl_spread_emitter_create(size_t size, const cdl_emitter_ops *ops, const cdl_goniometric_params *p,
                                cdl_status *status, cdl_error *err);
/* The point model's flux and intensity: a spread emitter's, for its ops. */
cdl_luminous_flux cdl_spread_emitter_flux(const cdl_emitter *e);
cdl_luminous_intensity cdl_spread_emitter_intensity(const cdl_emitter *e, cdl_vec3 unit_dir);
/* Releases the point model (what a spread emitter's destroy must do). */
void cdl_spread_emitter_destroy(cdl_emitter *e);

/* A goniometric luminaire spread over the luminous solid of its photometry
 * (a box with luminous sides, vertical or horizontal (elliptic) cylinder,
 * sphere or ellipsoid of non-zero size; the caller checked):
 * emitter_solid.c, created through cdl_emitter_create_goniometric_opening. */
cdl_status cdl_emitter_create_goniometric_solid(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err);

/* 1 and *sphere = the sphere bounding a solid emitter; 0 for any other. */
int cdl_emitter_solid_bounding_sphere(const cdl_emitter *emitter, cdl_shape *sphere);

#endif
