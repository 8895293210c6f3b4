/* scene_inputs.h - what a solve's results depend on, hashed part by part.
 *
 * `candela report` must never print a solve beside a scene that changed
 * after it (a maintenance factor of 0.5 beside an Em computed with 0.8).
 * The solve records these hashes in summary.json ("inputs"); the report
 * computes them again from the scene as it is now and refuses a folder
 * whose scene differs, naming each part that changed.
 *
 * The parts are the scene's description and the files it names:
 *  - each key of each entry of the top-level lists ("surfaces",
 *    "luminaires", "grids", "observers"): entry "luminaires[0]", key
 *    "maintenance_factor";
 *  - each key of the other top-level objects (entry "solver", key "seed"),
 *    and each other top-level value as a whole (entry "version", key "");
 *  - the content of each file an entry names (a photometric file's bytes
 *    with the TILT table it brings, a mesh file's, an environment image's):
 *    entry "luminaires[0]", key "file content" (an area luminaire's mesh:
 *    "shape.file content").
 * Left out, as no result depends on them: "$schema", the scene's "name"
 * and "project" (what the report prints on its cover), the "requirements"
 * of grids and observers (the report checks them; a surface's
 * requirements have it mapped, so they count), and the solver's "threads"
 * (results do not depend on the thread count).
 *
 * A value is hashed by what it is, not by how it is written: whitespace,
 * the order of an object's keys and the spelling of a number (0.8, 0.80,
 * 8e-1) do not count; a quantity written in another unit ("2 kcd" for
 * 2000) does. Hashes are content_hash.h's (FNV-1a, 64 bits, the same on
 * every machine); an object's members are combined by a sum of their
 * hashes, which does not depend on their order.
 *
 * Ownership: a cdl_scene_inputs owns its parts (cdl_scene_inputs_release);
 * a part's `file` is borrowed from the scene it was collected from.
 * Errors: memory; a file that cannot be read (CDL_ERR_INPUT naming it and
 * the JSON path that names it); summary.json's "inputs" malformed.
 */
#ifndef CANDELA_SOLVER_SCENE_SCENE_INPUTS_H
#define CANDELA_SOLVER_SCENE_SCENE_INPUTS_H

#include <cjson/cJSON.h>
#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

typedef struct cdl_scene_input_part {
    char *entry;              /* "luminaires[0]", "solver", "version" */
    char *key;                /* "maintenance_factor", "file content"; "" for a top-level value */
    uint64_t hash;
    const char *file;         /* a file's content: its path (the scene's), else NULL */
} cdl_scene_input_part;

typedef struct cdl_scene_inputs {
    cdl_scene_input_part *parts;
    size_t count, capacity;
} cdl_scene_inputs;

/* The parts of a scene document (its parsed JSON): what the loader keeps
 * in the scene. */
cdl_status cdl_scene_inputs_from_document(const cJSON *root, cdl_scene_inputs *out, cdl_error *err);

struct cdl_scene;
/* The scene's description parts and the content of every file it names,
 * read now, into *out (the caller's to release). */
cdl_status cdl_scene_inputs_collect(const struct cdl_scene *scene, cdl_scene_inputs *out, cdl_error *err);

/* One hash of all the parts (independent of their order). */
uint64_t cdl_scene_inputs_hash(const cdl_scene_inputs *inputs);

/* {"hash": "16 hex digits", "parts": {ENTRY: {KEY: "16 hex digits"}}}, or
 * NULL when out of memory. */
cJSON *cdl_scene_inputs_to_json(const cdl_scene_inputs *inputs);

/* Read what cdl_scene_inputs_to_json wrote; `where` names it in messages
 * ("out/summary.json: inputs"). CDL_ERR_INPUT when it is not that. */
cdl_status cdl_scene_inputs_from_json(const cJSON *json, const char *where, cdl_scene_inputs *out, cdl_error *err);

/* What differs from `then` to `now`, as a list for a message into out:
 * "luminaires[0].maintenance_factor, surfaces[0].reflectance changed;
 * luminaires[7] added" (entries added or removed whole are named once, a
 * file's content with its path; at most 8 items, then "and N more").
 * Returns the number of differences (0: the same parts). */
size_t cdl_scene_inputs_describe_changes(const cdl_scene_inputs *then, const cdl_scene_inputs *now, char *out,
                                         size_t size);

void cdl_scene_inputs_release(cdl_scene_inputs *inputs);

#endif
