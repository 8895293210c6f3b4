/* scene_help.h - `candela help scene` (scene_help.c). */
#ifndef CANDELA_TOOLS_SCENE_HELP_H
#define CANDELA_TOOLS_SCENE_HELP_H

#include <stdio.h>

/* The reference, from the compiled-in schema; 0, or 3 if it cannot be read. */
int cdl_scene_help_print(FILE *out);
/* The schema itself (data/scene.schema.json). */
int cdl_scene_help_print_schema(FILE *out);

#endif
