/* strings.h - owned copies of strings and file paths joined from parts.
 *
 * The one home of the copies every layer makes (a name kept past the
 * caller's buffer, a path under an output folder), so that each is written
 * once. Not public. Each returns malloc'ed memory the caller frees, or NULL
 * when out of memory; thread-safe.
 */
#ifndef CANDELA_BASE_STRINGS_H
#define CANDELA_BASE_STRINGS_H

#include <stddef.h>

/* A copy of the NUL-terminated s. */
char *cdl_string_copy(const char *s);

/* A copy of the first n bytes of s, NUL-terminated. */
char *cdl_string_copy_n(const char *s, size_t n);

/* "DIR/NAMEEXT" (ext may be ""). */
char *cdl_path_join(const char *dir, const char *name, const char *ext);

#endif
