/* scene_internal.h - the scene as C data, behind the public handle of scene.h (not public).
 *
 * cdl_scene_load reads the JSON scene ("version": 1), checks every key and
 * value, resolves relative paths against the scene file's folder, and
 * returns plain data. It reads external files whose content is part of the
 * scene description (OBJ/OFF/PLY meshes, so their errors carry the JSON
 * path); it does not read photometric files or environment images (the
 * solver opens those and prefixes the JSON path to their errors).
 *
 * Errors: CDL_ERR_INPUT, message "SCENE.json: luminaires[2].position:
 * expected ..., found ..." (JSON syntax errors give line and column).
 * Unknown keys are errors: a typo must not silently change a result.
 *
 * Units: metres, degrees, cd, lm, lx, cd/m^2 as the field names say.
 * Ownership: a scene from cdl_scene_load or cdl_scene_load_string belongs
 * to the caller, who frees it with cdl_scene_release (NULL is fine); every
 * string and array in it belongs to the scene. Thread safety: the library
 * keeps no global state and never modifies a loaded scene (every other
 * call takes it const), so scenes may be loaded, read and solved on
 * several threads at once; release one only when no call uses it.
 */
#ifndef CANDELA_SOLVER_SCENE_SCENE_INTERNAL_H
#define CANDELA_SOLVER_SCENE_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/geometry/ring3.h"
#include "solver/scene/scene.h"
#include "solver/scene/scene_inputs.h"

#define CDL_JSON_PATH_SIZE 96

/* ---- surfaces ----------------------------------------------------------- */

typedef enum cdl_surface_kind {
    CDL_SURFACE_RECT,
    CDL_SURFACE_POLYGON,
    CDL_SURFACE_BOX,
    CDL_SURFACE_DISK,
    CDL_SURFACE_SPHERE,
    CDL_SURFACE_MESH
} cdl_surface_kind;

/* Box faces, in the order of the names -x, +x, -y, +y, -z, +z. With the
 * floor/walls/ceiling naming, floor = -z, ceiling = +z, walls = the other four. */
enum { CDL_BOX_NEG_X, CDL_BOX_POS_X, CDL_BOX_NEG_Y, CDL_BOX_POS_Y, CDL_BOX_NEG_Z, CDL_BOX_POS_Z, CDL_BOX_FACES };

typedef struct cdl_surface_spec {
    char json_path[CDL_JSON_PATH_SIZE]; /* "surfaces[3]" */
    char *name;                         /* NULL when not given */
    cdl_surface_kind kind;
    /* rect: origin + s u + t v, normal u x v */
    cdl_vec3 origin, u, v;
    /* polygon: outer ring and holes, coplanar; normal from the outer ring's
     * orientation (counter-clockwise seen from the front) */
    cdl_ring3 outer;
    cdl_ring3 *holes;
    size_t hole_count;
    /* box */
    cdl_vec3 box_min, box_max;
    int inward;                          /* box, sphere: front side faces inside */
    double face_reflectance[CDL_BOX_FACES];
    int face_open[CDL_BOX_FACES];        /* 1: face left out */
    /* disk (center, normal, radius) and sphere (center, radius) */
    cdl_vec3 center, normal;
    double radius;
    /* mesh: from `file` (resolved path kept for messages) or inline */
    char *file;
    double *mesh_vertices;               /* xyz */
    size_t mesh_vertex_count;
    uint32_t *mesh_triangles;            /* counter-clockwise from the front */
    size_t mesh_triangle_count;
    /* material */
    double reflectance;                  /* diffuse, [0, 1]; box: see face_reflectance */
    int two_sided;                       /* default 1 */
    double luminance_cd_m2;              /* > 0: the front side emits (Lambertian) */
    /* surface map: its front side's illuminance on a mesh that follows the
     * light (OUTDIR/surfaces/NAME.csv). mapped when "solver":
     * {"surface_maps"} is "all" or names it, or when it has requirements;
     * map_name is then the NAME of its files: its name, or "surface_K" (K
     * its index in "surfaces") when it has none. */
    int mapped;
    char *map_name;
    /* "requirements" (EN 12464-1:2021 4.3 for walls and ceilings: say Em
     * 50 lx, U0 0.10), which `candela report` checks; 0 when not given */
    double required_Em_lx;
    double required_U0;
    double transmittance;                /* > 0: a thin pane of glass of this normal transmittance
                                          * (radiometry/glass.h); its reflectance 0 */
} cdl_surface_spec;

/* ---- luminaires --------------------------------------------------------- */

typedef enum cdl_luminaire_kind {
    CDL_LUMINAIRE_POINT,
    CDL_LUMINAIRE_SPOT,
    CDL_LUMINAIRE_GONIOMETRIC,
    CDL_LUMINAIRE_AREA,
    CDL_LUMINAIRE_DIRECTIONAL,
    CDL_LUMINAIRE_ENVIRONMENT
} cdl_luminaire_kind;

/* When a goniometric luminaire is spread over its luminous opening (an
 * extended emitter, cdl_emitter_create_goniometric_opening) instead of a
 * point: AUTO at calculation points where the point model's error could
 * exceed CDL_NEAR_FIELD_SHARE of the solve's target (the bound of
 * lights/emitters/near_field_bound.h; nearer than CDL_NEAR_FIELD_DISTANCES
 * times the opening's largest dimension in any case), ALWAYS everywhere,
 * NEVER nowhere. A file whose opening is not spread
 * (cdl_luminous_opening_is_spread: flat, horizontal or vertical, or a
 * luminous solid of LM-63 Table 1 (box with luminous sides, vertical or
 * horizontal (elliptic) cylinder, sphere, ellipsoid) of non-zero size)
 * stays a point; under ALWAYS the plan and a warning say so. */
typedef enum cdl_near_field_mode { CDL_NEAR_FIELD_AUTO = 0, CDL_NEAR_FIELD_ALWAYS, CDL_NEAR_FIELD_NEVER } cdl_near_field_mode;

/* The sky of an environment luminaire ("sky"). */
typedef enum cdl_scene_sky {
    CDL_SCENE_SKY_UNIFORM,               /* "uniform" (default), or an image "file" */
    CDL_SCENE_SKY_CIE_OVERCAST,          /* "cie_overcast": L_z (1 + 2 cos theta) / 3 */
    CDL_SCENE_SKY_CIE,                   /* "cie": a CIE standard general sky, cie_type 1..15 */
    CDL_SCENE_SKY_PEREZ                  /* "perez": the Perez all-weather sky from weather data */
} cdl_scene_sky;

/* Where the sun is and what a "cie" or "perez" sky needs besides
 * (scene_daylight.c reads it; the loader turns "sun" or "site" + "time"
 * into the world direction `sun`). */
typedef struct cdl_daylight_spec {
    int has_sun;                         /* "sun" or "site" + "time" given */
    cdl_vec3 sun;                        /* unit world direction towards the sun */
    double sun_altitude_deg, sun_azimuth_deg; /* apparent altitude; azimuth eastward from north */
    cdl_vec3 north;                      /* "north", made perpendicular to up (default +y) */
    int from_site;                       /* 1: the sun by the SPA from "site" and "time" */
    double latitude_deg, longitude_deg, elevation_m, pressure_mbar, temperature_c, delta_t_s; /* "site" */
    char time[64];                       /* "time" as given (ISO 8601 with its UTC offset) */
    int day_of_year;                     /* 1..366: from "time", or "day_of_year" */
    int cie_type;                        /* "cie": 1..15 */
    int scale_to_horizontal;             /* "cie": 1 with diffuse_horizontal_illuminance_lx (else zenith) */
    int radiometric;                     /* "perez": 1 with irradiances in W/m^2, 0 with illuminances in lx */
    double diffuse_horizontal;           /* lx (or W/m^2 for "perez" with irradiances) */
    double direct_normal;                /* lx (or W/m^2): the sun's; 0: no sun disk */
    double dew_point_c;                  /* "perez": default 11 */
} cdl_daylight_spec;

typedef struct cdl_luminaire_spec {
    char json_path[CDL_JSON_PATH_SIZE];  /* "luminaires[2]": the entry it comes from */
    char *name;                          /* NULL when not given */
    cdl_luminaire_kind kind;
    /* One entry may place a luminaire many times ("array" or "positions"):
     * each placement is its own spec, in order, sharing the entry's
     * json_path; copy is its number within the entry, copy_count their
     * number (1 for a single luminaire). */
    size_t entry;                        /* index of the entry in "luminaires" */
    size_t copy, copy_count;
    int array_index[2];                  /* "array": [i, j] of this copy; else [copy, 0] */
    /* "aim" (spot, goniometric): the point the spot axis or the photometric
     * nadir points at, turned by spin_deg about that axis; the loader has
     * already turned it into `direction` (spot) or rotation_deg
     * (goniometric) for this copy's position. */
    int has_aim;
    cdl_vec3 aim;
    double spin_deg;
    cdl_vec3 position;                   /* point, spot, goniometric */
    cdl_vec3 direction;                  /* spot axis; directional: direction of travel */
    /* exactly one of intensity_cd / flux_lm for point and spot; for
     * goniometric, flux_lm optionally rescales the file */
    int has_intensity, has_flux;
    double intensity_cd, flux_lm;
    /* spot */
    int has_exponent;                    /* cos^n profile instead of smoothstep */
    double exponent, half_angle_deg, falloff_start_deg; /* falloff_start defaults to half_angle */
    /* goniometric */
    char *file;                          /* resolved path (also environment image) */
    double rotation_deg[3];
    double multiplier;                   /* default 1 */
    cdl_near_field_mode near_field;      /* spread over the file's luminous opening: default AUTO */
    /* "body": the solid the luminaire occupies (lights/photometry/luminaire_body.h) blocks every other
     * light and reflects: 1 (the default, or true, or an object), 0 with "body": false */
    int body;
    int has_body_reflectance;            /* "body": {"reflectance": R} given */
    double body_reflectance;             /* [0, 1]; unset: 0.5 for a housing, 0 for an opening alone */
    /* all: default 1 */
    double maintenance_factor;
    /* area: a surface-like shape (rect, disk, polygon or mesh, same keys as
     * surfaces; its json_path is "luminaires[k].shape") and luminance or flux */
    cdl_surface_spec shape;
    int has_luminance;
    double luminance_cd_m2;
    double reflectance;                  /* area: default 0 */
    /* directional */
    double illuminance_lx;
    double angular_diameter_deg;         /* 0: parallel; > 0: a disk (the sun: 0.533) */
    /* environment: uniform luminance_cd_m2 (has_luminance) or image file */
    double scale;                        /* default 1 */
    cdl_vec3 up;                         /* default (0, 0, 1) */
    int upper_hemisphere_only;           /* "hemisphere": "upper" */
    int sky_overcast;                    /* "sky": "cie_overcast" (luminance_cd_m2 holds its zenith's) */
    cdl_scene_sky sky;                   /* "sky" (luminance_cd_m2 holds a "cie" sky's zenith luminance) */
    cdl_daylight_spec daylight;          /* "cie" and "perez" skies */
} cdl_luminaire_spec;

/* ---- grids -------------------------------------------------------------- */

/* Largest number of points a grid may have (the scene loader refuses more;
 * polygon grids check their estimated count before meshing). */
#define CDL_GRID_MAX_POINTS 10000000

/* Most luminaires one scene may place (entries times their copies). */
#define CDL_SCENE_MAX_LUMINAIRES 1000000

typedef enum cdl_grid_kind { CDL_GRID_RECT, CDL_GRID_POLYGON, CDL_GRID_POINTS } cdl_grid_kind;

typedef struct cdl_grid_spec {
    char json_path[CDL_JSON_PATH_SIZE];  /* "grids[0]" */
    char *name;                          /* required, unique, safe as a file name */
    cdl_grid_kind kind;
    /* rect */
    cdl_vec3 origin, u, v;
    int nu, nv;
    int has_normal;
    cdl_vec3 normal;                     /* rect/polygon: default u x v / from the ring */
    /* polygon (holes allowed, as for surfaces) */
    cdl_ring3 outer;
    cdl_ring3 *holes;
    size_t hole_count;
    double spacing;                      /* metres; <= 0 means "auto" (EN 12464-1) */
    /* points */
    cdl_vec3 *points, *normals;
    size_t point_count;
    /* outputs (each an extra CSV column, EXR channel and summary statistic) */
    int want_ao;                         /* "ao": ambient occlusion */
    int want_cylindrical;                /* "cylindrical": mean vertical illuminance E_z (EN 12464-1) */
    int want_semicylindrical;            /* "semicylindrical": towards the point's normal, horizontal part */
    int want_luminance;                  /* "luminance": rho E / pi of the surface the grid lies on */
    int want_daylight_factor;            /* "daylight_factor": 100 E / E_h under the CIE overcast sky */
    /* "requirements" (EN 12464-1 for a task area), which `candela report`
     * checks: maintained illuminance in lux and uniformity Emin / Em;
     * 0 when not given. */
    double required_Em_lx;
    double required_U0;
} cdl_grid_spec;

/* ---- solver settings ---------------------------------------------------- */


/* `bounces` value meaning "auto": reflections are followed (Russian
 * roulette) until what is left out is below a tenth of the target. */
#define CDL_BOUNCES_AUTO (-1)

/* Which surfaces are mapped ("surface_maps"): none (the default), all, or
 * those listed by name (cdl_surface_spec.mapped says which). */
typedef enum cdl_surface_maps { CDL_SURFACE_MAPS_NONE, CDL_SURFACE_MAPS_ALL, CDL_SURFACE_MAPS_LISTED } cdl_surface_maps;

typedef struct cdl_solver_settings {
    cdl_method method;                   /* default auto */
    cdl_quality quality;                 /* default normal */
    double target_error;                 /* relative standard error of E per point; 0 = the quality's */
    int bounces;                         /* CDL_BOUNCES_AUTO (default) or the most reflections followed */
    uint64_t seed;                       /* default 1 */
    int threads;                         /* 0 = all cores (default) */
    int direct_samples;                  /* 0 = adaptive to the target: samples per partly hidden emitter */
    int ao_samples;                      /* 0 = from quality */
    cdl_surface_maps surface_maps;       /* default none; surfaces with requirements are mapped regardless */
} cdl_solver_settings;

/* The target the settings ask for: target_error when given, else the
 * quality's. */
double cdl_solver_settings_target(const cdl_solver_settings *settings);

/* Bounds of an explicit target_error: tighter than 1e-5 would ask for
 * billions of samples per point; looser than 0.5 is no estimate at all. */
#define CDL_TARGET_ERROR_MIN 1e-5
#define CDL_TARGET_ERROR_MAX 0.5

/* Most samples per point the scene may ask for (direct_samples, ao_samples):
 * 2^24, 4096 times the "reference" quality's AO count and far beyond any
 * converged result (seconds per point and light); the stratified square
 * k x k of samples then stays far inside an int. */
#define CDL_SCENE_MAX_SAMPLES 16777216


/* ---- observers (glare) ---------------------------------------------------- */

/* Most observers one scene may place (entries, their copies and the points
 * of observer grids). */
#define CDL_SCENE_MAX_OBSERVERS 100000

/* An observer rated for discomfort glare (CIE 117:1995 UGR): an eye and a
 * horizontal line of sight. An entry of "observers" places one (at "eye"),
 * or many ("array" in its own frame: rows along the line of sight and to
 * its left; or "positions"); a grid of "type": "observers" places one at
 * each cell centre of a rect, as a rect grid places points, all looking
 * along its "view". Each placement is its own spec, in order. */
typedef struct cdl_observer_spec {
    char json_path[CDL_JSON_PATH_SIZE];  /* "observers[1]", or "grids[2]" for an observer grid */
    char *name;                          /* the entry's name; with copies "NAME[k]" (k from 0 in order) */
    size_t entry;                        /* the entry's index in "observers" (or in "grids") */
    size_t copy, copy_count;
    int array_index[2];                  /* "array": [i, j]; an observer grid: [i, j] of the cell; else [k, 0] */
    int from_grid;                       /* 1: a point of an observer grid */
    cdl_vec3 eye;                        /* metres */
    cdl_vec3 view;                       /* the line of sight: unit and horizontal (z = 0); the loader refuses
                                          * a view more than 1 degree from horizontal */
    double required_ugr;                 /* "requirements": {"UGR_L": x}, EN 12464-1's limit; 0 when none */
} cdl_observer_spec;

/* The most a line of sight may rise or fall from the horizontal, in
 * degrees: CIE 117's position index is for a horizontal line of sight. */
#define CDL_OBSERVER_TILT_MAX_DEG 1.0

/* ---- what the report says about the scene ---------------------------------- */

/* "project": who and what the results are for, printed on the cover of
 * `candela report` (which may take them from a file instead, field by
 * field). Free text; none of it changes a result. NULL when not given. */
typedef struct cdl_scene_project {
    char *project, *client, *designer, *date, *notes;
} cdl_scene_project;

/* A project file: the object a scene's "project" holds, alone
 * ({"project": "...", "client": "..."}); messages name the file and the
 * key. The caller frees *out with cdl_scene_project_free. */
cdl_status cdl_scene_project_load(const char *path, cdl_scene_project *out, cdl_error *err);
void cdl_scene_project_free(cdl_scene_project *project);

/* ---- the scene ------------------------------------------------------------ */

struct cdl_scene {
    char *path;                          /* the scene file as given */
    char *base_dir;                      /* folder relative paths resolve against */
    cdl_surface_spec *surfaces;
    size_t surface_count;
    cdl_luminaire_spec *luminaires;
    size_t luminaire_count;
    cdl_grid_spec *grids;                /* illuminance grids (observer grids are in observers) */
    size_t grid_count;
    cdl_observer_spec *observers;        /* "observers" and the points of observer grids, in order */
    size_t observer_count;
    cdl_solver_settings settings;
    char *name;                          /* "name": the scene's name for reports; NULL when not given */
    cdl_scene_project project;           /* "project" */
    cdl_scene_inputs inputs;             /* the description's parts, hashed (scene_inputs.h) */
};


/* The keys the loader accepts, per kind of object ("scene", "luminaire
 * spot", "surface box", "shape rect", "grid polygon", "solver", "array",
 * "grid point"): the very tables it checks scenes against, so that a test
 * can hold data/scene.schema.json to them both ways. Filled into a
 * caller-owned cdl_scene_keys (no global state); reentrant. */
#define CDL_SCENE_KEY_SETS_MAX 32
#define CDL_SCENE_KEYS_PER_SET 24
typedef struct cdl_scene_key_set {
    const char *object;
    const char *const *keys;             /* NULL-terminated */
} cdl_scene_key_set;

typedef struct cdl_scene_keys {
    cdl_scene_key_set sets[CDL_SCENE_KEY_SETS_MAX];
    size_t count;
    /* room for the names and key lists assembled from the loader's tables */
    char names[CDL_SCENE_KEY_SETS_MAX][32];
    const char *lists[CDL_SCENE_KEY_SETS_MAX][CDL_SCENE_KEYS_PER_SET];
} cdl_scene_keys;
/* The loader's key sets, assembled into caller-owned storage (no static
 * table). Thread-safe; no errors. */
void cdl_scene_keys_collect(cdl_scene_keys *out);

/* A label for messages and the plan: the JSON path, the name when given,
 * and for one copy of many its number ("luminaires[2] (row A, 3 of 12)"). */
void cdl_luminaire_spec_label(const cdl_luminaire_spec *spec, char *out, size_t size);

#endif
