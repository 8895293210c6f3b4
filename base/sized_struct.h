/* sized_struct.h - structs that begin with their own size, as OpenEXR Core's do (not public).
 *
 * A public options or result struct starts with `size_t size`, which the
 * caller sets to sizeof the struct it was compiled with (the INIT macros
 * do). When the library adds fields at the end, a program built against the
 * older, shorter struct keeps working: the library reads only the fields
 * the caller's size covers (the rest keep their defaults) and writes only
 * those it has room for. Thread-safe; no errors.
 */
#ifndef CANDELA_BASE_SIZED_STRUCT_H
#define CANDELA_BASE_SIZED_STRUCT_H

#include <stddef.h>

/* Options: copy over *ours (the library's struct of ours_size bytes,
 * holding the defaults) the fields of *given that its size field covers;
 * ours keeps its own size. given may be NULL (the defaults stay). */
void cdl_sized_struct_read(void *ours, size_t ours_size, const void *given);

/* Results: copy into *given (the caller's struct, its size field set) the
 * fields of *ours (ours_size bytes) that it has room for. */
void cdl_sized_struct_fill(void *given, const void *ours, size_t ours_size);

#endif
