/* grow.h - room for one more item in a growing array.
 *
 *   if (cdl_grow(&items, &capacity, count + 1, sizeof *items, 64, err) != CDL_OK) return CDL_ERR_INTERNAL;
 *   items[count++] = item;
 *
 * The capacity doubles (from `first` when zero) until it holds `needed`
 * items, so n appends cost O(n) copies in all. On failure the array and
 * its capacity are unchanged (still the caller's to free) and err says
 * "out of memory". Thread safety: touches only its arguments.
 */
#ifndef CANDELA_BASE_GROW_H
#define CANDELA_BASE_GROW_H

#include <stddef.h>

#include "base/error.h"

/* *items (a void * to an array of item_size-byte items, possibly NULL)
 * holds at least `needed` items afterwards. */
cdl_status cdl_grow(void *items, size_t *capacity, size_t needed, size_t item_size, size_t first, cdl_error *err);

#endif
