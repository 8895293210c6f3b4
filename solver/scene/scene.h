/* scene.h - a scene from a file or a JSON string: load it, ask what it holds, release it.
 *
 * A cdl_scene is an opaque handle on a scene file in the format of
 * Candela's scene reference (`candela help scene`; the JSON Schema is
 * installed as share/candela/scene.schema.json): "version": 1, surfaces,
 * luminaires, grids and solver settings. cdl_scene_load reads the file,
 * checks every key and value (unknown keys are errors: a typo must not
 * silently change a result), resolves relative paths against the scene
 * file's folder, and reads the meshes the scene names; photometric files
 * and environment images are read when the scene is solved (solve.h), and
 * their errors then carry the JSON path that names them.
 *
 * Errors: CDL_ERR_INPUT with a message "SCENE.json: luminaires[2].position:
 * expected ..., found ..." (JSON syntax errors give line and column);
 * CDL_ERR_INTERNAL for memory.
 *
 * Units: metres, degrees, cd, lm, lx, cd/m^2 as the scene's keys say.
 * Ownership: a scene from cdl_scene_load or cdl_scene_load_string belongs
 * to the caller, who frees it with cdl_scene_release (NULL is fine); the
 * strings its accessors return belong to it and live as long as it does.
 * Thread safety: a loaded scene is never modified (every other call takes
 * it const), so scenes may be loaded, read and solved on several threads at
 * once; release one only when no call uses it.
 */
#ifndef CANDELA_SOLVER_SCENE_SCENE_H
#define CANDELA_SOLVER_SCENE_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

typedef struct cdl_scene cdl_scene;

/* How interreflected light is computed ("solver": {"method"}): AUTO picks
 * per grid (direct light alone when nothing reflects), DIRECT leaves it
 * out, ICACHE by an irradiance cache, PATHTRACE by paths from every point
 * (the unbiased reference). */
typedef enum cdl_method { CDL_METHOD_AUTO, CDL_METHOD_DIRECT, CDL_METHOD_ICACHE, CDL_METHOD_PATHTRACE } cdl_method;

/* The accuracy asked ("solver": {"quality"}): a target relative standard
 * error of E per point (cdl_quality_target_error). */
typedef enum cdl_quality { CDL_QUALITY_DRAFT, CDL_QUALITY_NORMAL, CDL_QUALITY_HIGH, CDL_QUALITY_REFERENCE } cdl_quality;

/* The target relative standard error of a quality: draft 0.02, normal
 * 0.005, high 0.001, reference 0.0002 (normal's for a value outside the
 * enum). Thread-safe; never fails. */
double cdl_quality_target_error(cdl_quality quality);

/* Short stable names, as in the scene file ("auto", "direct", "icache",
 * "pathtrace"; "draft", "normal", "high", "reference"); static storage, "unknown"
 * for a value outside the enum. Thread-safe. */
const char *cdl_method_name(cdl_method method);
const char *cdl_quality_name(cdl_quality quality);

/* Load the scene file at `path` (relative paths in it resolve against its
 * folder). On success *out is the caller's; on failure it is NULL and err
 * says where. */
cdl_status cdl_scene_load(const char *path, cdl_scene **out, cdl_error *err);

/* The same from a JSON text; `path` names it in messages, and relative
 * paths in it resolve against path's folder (the current folder when path
 * has none). */
cdl_status cdl_scene_load_string(const char *json, const char *path, cdl_scene **out, cdl_error *err);

/* Free a scene (NULL is fine). */
void cdl_scene_release(cdl_scene *scene);

/* The scene file as given to the loader. */
const char *cdl_scene_path(const cdl_scene *scene);

/* The grids, in the scene's order: their count and each one's name (NULL
 * for an index beyond the count). */
size_t cdl_scene_grid_count(const cdl_scene *scene);
const char *cdl_scene_grid_name(const cdl_scene *scene, size_t index);

/* Luminaires placed (each copy of an "array" or "positions" counts) and
 * surfaces listed. */
size_t cdl_scene_luminaire_count(const cdl_scene *scene);
size_t cdl_scene_surface_count(const cdl_scene *scene);

/* The solver settings the scene asks for: method, quality, the target
 * relative standard error (its "target_error", else its quality's), and the
 * seed of its random numbers. */
cdl_method cdl_scene_method(const cdl_scene *scene);
cdl_quality cdl_scene_quality(const cdl_scene *scene);
double cdl_scene_target_error(const cdl_scene *scene);
uint64_t cdl_scene_seed(const cdl_scene *scene);

#endif
