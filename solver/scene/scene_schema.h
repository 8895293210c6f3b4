/* scene_schema.h - the scene format's JSON Schema (data/scene.schema.json, draft 2020-12), compiled in.
 *
 * The schema is the one description of the scene file a person or an
 * editor reads: every key with its unit ("x-unit", an annotation),
 * default and range. `candela help scene` prints its reference from it; a
 * test holds it to the loader's own key tables (cdl_scene_keys_collect) both
 * ways and validates every example scene against it. Editors validate and
 * complete a scene that names it in "$schema".
 */
#ifndef CANDELA_SOLVER_SCENE_SCHEMA_H
#define CANDELA_SOLVER_SCENE_SCHEMA_H

/* The schema's text, NUL-terminated (generated at build time by scripts/embed_text.cmake). */
extern const char cdl_scene_schema_text[];

#endif
