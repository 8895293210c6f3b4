/* scene_parse.h - shared by the scene loader's files (scene_json.c,
 * scene_surface.c, scene_load.c); not a public interface.
 *
 * Every reader takes the parse context, the JSON node and the node's JSON
 * path ("luminaires[2].position") and on failure fills the context's error
 * with "SCENE.json: PATH: expected WHAT, found WHAT" and returns
 * CDL_ERR_INPUT. A NULL node means the key is absent: optional readers then
 * keep their default, required ones report the missing key.
 */
#ifndef CANDELA_SOLVER_SCENE_PARSE_H
#define CANDELA_SOLVER_SCENE_PARSE_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "base/error_report.h"
#include "radiometry/quantity.h"
#include "radiometry/vec3.h"
#include "solver/scene/scene_internal.h"

/* Longer than CDL_JSON_PATH_SIZE: messages keep the whole path even where a
 * spec's json_path field is truncated. */
#define CDL_SCENE_PATH_MAX 256

typedef struct cdl_scene_parse {
    const char *file;       /* scene file as given, for messages */
    const char *base_dir;   /* folder that relative paths resolve against */
    cdl_error *err;
} cdl_scene_parse;

/* ---- paths and messages -------------------------------------------------- */

/* A spec's json_path field (CDL_JSON_PATH_SIZE bytes), truncated if need be. */
void cdl_scene_json_copy_path(char *json_path, const char *path);
/* out = "parent.key" (or "key" when parent is empty). */
void cdl_scene_json_path_key(char *out, const char *parent, const char *key);
/* out = "parent[index]" */
void cdl_scene_json_path_index(char *out, const char *parent, size_t index);
/* "a string", "an array of 2 items", "the number 1.5", "nothing (the key is missing)". */
void cdl_scene_json_describe(const cJSON *node, char *out, size_t size);
/* "FILE: PATH: expected EXPECTED, found <description of node>". */
cdl_status cdl_scene_json_fail(const cdl_scene_parse *ctx, const char *path, const char *expected, const cJSON *found);
/* "FILE: PATH: expected EXPECTED, found <formatted>". */
cdl_status cdl_scene_json_failf(const cdl_scene_parse *ctx, const char *path, const char *expected, const char *fmt, ...)
    CDL_PRINTF(4, 5);

/* ---- structure ----------------------------------------------------------- */

/* `node` must be an object whose keys are all in `allowed` (NULL-terminated),
 * each at most once. `what` names the object in messages ("a rect surface"). */
cdl_status cdl_scene_json_check_object(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                       const char *what, const char *const *allowed);
/* The member `key` of an object, or NULL. */
const cJSON *cdl_scene_json_member(const cJSON *object, const char *key);
/* The member `key` of an object, or NULL; key_path receives "path.key". */
const cJSON *cdl_scene_json_field(const cJSON *object, const char *path, const char *key, char *key_path);
/* An array (of any length when min_count is 0). */
cdl_status cdl_scene_json_check_array(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const char *expected, size_t min_count);

/* ---- values -------------------------------------------------------------- */

/* Largest magnitude of any number in a scene (coordinates in metres,
 * photometric values): far beyond any real scene (the sun's luminance is
 * 1.6e9 cd/m^2), small enough that squares and products stay finite and
 * coordinates fit Embree's single precision. */
#define CDL_SCENE_MAX_MAGNITUDE 1e12

typedef enum cdl_scene_range {
    CDL_RANGE_ANY,          /* any finite number */
    CDL_RANGE_NONNEGATIVE,  /* >= 0 */
    CDL_RANGE_POSITIVE,     /* > 0 */
    CDL_RANGE_UNIT,         /* [0, 1] */
    CDL_RANGE_UNIT_OPEN0    /* (0, 1] */
} cdl_scene_range;

/* A finite number in `range`. Absent: *out keeps its value unless required. */
cdl_status cdl_scene_json_read_number(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      cdl_scene_range range, int required, double *out);
/* A finite number in `range`, given either as a JSON number in the unit the
 * key names (the dimension's base unit: "intensity_cd": 1200) or as text with
 * a unit of `dimension` ("intensity_cd": "1.2 kcd", "illuminance_lx":
 * "46.45 fc"), converted to the base unit by cdl_quantity_parse. A unit of
 * another dimension or an unknown unit is an error naming the path. */
cdl_status cdl_scene_json_read_quantity(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                        cdl_dimension dimension, cdl_scene_range range, int required, double *out);
/* An integer in [lo, hi]. */
cdl_status cdl_scene_json_read_integer(const cdl_scene_parse *ctx, const cJSON *node, const char *path, double lo,
                                       double hi, int required, double *out);
cdl_status cdl_scene_json_read_bool(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                    int *out);
/* A string equal to one of `choices` (NULL-terminated); *out = its index. */
cdl_status cdl_scene_json_read_choice(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const char *const *choices, int required, int *out);
/* A non-empty string, copied (caller frees). */
cdl_status cdl_scene_json_read_string(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                      char **out);
/* An array of 3 finite numbers. nonzero: the vector must have a length > 0. */
cdl_status cdl_scene_json_read_vec3(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int nonzero,
                                    int required, cdl_vec3 *out);
/* A list of at least 3 points (a closing copy of the first point is dropped). */
cdl_status cdl_scene_json_read_ring(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_ring3 *out);
/* A file name, resolved against the scene's folder (caller frees). */
cdl_status cdl_scene_json_read_path(const cdl_scene_parse *ctx, const cJSON *node, const char *path, int required,
                                    char **out);

/* "requirements": {"Em_lx": 500, "U0": 0.6} (grids and surfaces), EN
 * 12464-1's maintained illuminance (> 0) and uniformity Emin / Em (in
 * (0, 1]); at least one. Absent: both stay as they are. */
extern const char *const cdl_scene_requirements_keys[];
cdl_status cdl_scene_json_read_requirements(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                            double *Em_lx, double *U0);

/* ---- polygons and surfaces (scene_surface.c) ------------------------------ */

/* Reads "vertices" and "holes" of `object` into outer/holes and checks the
 * polygon (planar, not degenerate, simple, holes inside). */
cdl_status cdl_scene_json_read_polygon(const cdl_scene_parse *ctx, const cJSON *object, const char *path,
                                       cdl_ring3 *outer, cdl_ring3 **holes, size_t *hole_count);

/* "origin", "u", "v" of a parallelogram (rect surfaces and grids): u and v
 * non-zero and not parallel. */
cdl_status cdl_scene_json_read_span(const cdl_scene_parse *ctx, const cJSON *object, const char *path,
                                    cdl_vec3 *origin, cdl_vec3 *u, cdl_vec3 *v);

typedef enum cdl_scene_shape_use {
    CDL_SHAPE_USE_SURFACE,   /* an entry of "surfaces": material keys allowed */
    CDL_SHAPE_USE_LUMINAIRE  /* an area luminaire's "shape": geometry only, rect/disk/polygon/mesh */
} cdl_scene_shape_use;

cdl_status cdl_scene_json_read_surface(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                       cdl_scene_shape_use use, cdl_surface_spec *out);
void cdl_scene_surface_spec_free(cdl_surface_spec *spec);
/* The surface and shape kinds' keys as the loader checks them, into
 * keys->sets from index `first` on (cdl_scene_keys_collect); returns how
 * many were added. */
size_t cdl_scene_surface_key_sets(cdl_scene_keys *keys, size_t first);

/* ---- daylight skies (scene_daylight.c) ------------------------------------------ */

/* The keys of a "sun" and of a "site" object. */
extern const char *const cdl_scene_sun_keys[];
extern const char *const cdl_scene_site_keys[];

/* An environment with "sky": "cie" or "perez" (out->sky set): its up,
 * north, the sky's inputs and its sun ("sun", or "site" and "time" by the
 * SPA), into out->daylight. */
cdl_status cdl_scene_json_read_daylight(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                        cdl_luminaire_spec *out);

/* ---- names (scene_json.c) ---------------------------------------------------------- */

/* A name usable as a file name: 1 to 64 letters, digits, '.', '_', '-', not
 * starting with '.' or '-' (grids, observers, surface maps). */
int cdl_scene_name_ok(const char *name);

/* ---- the scene's name and project (scene_project.c) ------------------------------------ */

extern const char *const cdl_scene_project_keys[];
/* The top-level "name" and "project" of `root` into the scene. */
cdl_status cdl_scene_json_read_about(const cdl_scene_parse *ctx, const cJSON *root, cdl_scene *scene);

/* ---- observers (scene_observers.c) --------------------------------------------------- */

extern const char *const cdl_scene_observer_keys[];
extern const char *const cdl_scene_observer_grid_keys[];
extern const char *const cdl_scene_observer_requirements_keys[];

/* One entry of "observers" (index `entry`), appended to scene->observers,
 * one spec per placement. */
cdl_status cdl_scene_json_read_observer_entry(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                              size_t entry, cdl_scene *scene);
/* A grid of "type": "observers" (index `entry` in "grids"), its points
 * appended to scene->observers. */
cdl_status cdl_scene_json_read_observer_grid(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                             size_t entry, cdl_scene *scene);

/* ---- placing luminaires (scene_placement.c) ------------------------------------ */

/* The keys of an "array" object. */
extern const char *const cdl_scene_array_keys[];

/* "aim" and "spin" of a spot or goniometric luminaire (refusing "aim" with
 * "direction" or "rotation", and "spin" without "aim"). */
cdl_status cdl_scene_json_read_aim(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                   cdl_luminaire_spec *out);

/* Where an entry places its luminaires: one at proto->position, an
 * "array" laid out in the entry's own frame, or the "positions" listed. */
typedef struct cdl_luminaire_copies {
    cdl_vec3 *positions;
    int (*index)[2];              /* [i, j] in the array, or [k, 0] */
    cdl_vec3 *aims;               /* with "positions" and a list of aim points: each copy's; else NULL */
    size_t count;
} cdl_luminaire_copies;
cdl_status cdl_scene_json_read_copies(const cdl_scene_parse *ctx, const cJSON *node, const char *path,
                                      const cdl_luminaire_spec *proto, cdl_luminaire_copies *out);
void cdl_scene_luminaire_copies_free(cdl_luminaire_copies *copies);

/* Turn an aimed copy (has_aim) towards its aim point from its position:
 * the spot's direction or the goniometric rotation. Refuses an aim point
 * at the luminaire. */
cdl_status cdl_scene_place_copy(const cdl_scene_parse *ctx, const char *path, cdl_luminaire_spec *spec);
void cdl_scene_rings_free(cdl_ring3 *outer, cdl_ring3 *holes, size_t hole_count);

#endif
