/* key_table.h - a hash table from 64-bit keys to indices: the edges of a
 * mesh (an unordered pair of vertex numbers), a vertex's copy per region.
 *
 * Open addressing with linear probing over a power-of-two array kept at
 * most half full; keys are never removed (meshes that refine only grow).
 * Lookups cost O(1) on average whatever the key pattern: keys are mixed by
 * a 64-bit finaliser (SplitMix64's) before use. Iteration order is never
 * exposed, so results cannot depend on it.
 *
 * Ownership: the table owns its array (cdl_key_table_release); a
 * zero-initialised table is empty and valid. Thread safety: none per table.
 */
#ifndef CANDELA_SOLVER_GEOMETRY_KEY_TABLE_H
#define CANDELA_SOLVER_GEOMETRY_KEY_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

#define CDL_KEY_TABLE_NONE SIZE_MAX

typedef struct cdl_key_table_slot {
    uint64_t key;
    size_t value;             /* CDL_KEY_TABLE_NONE: the slot is empty */
} cdl_key_table_slot;

typedef struct cdl_key_table {
    cdl_key_table_slot *slots;
    size_t capacity;          /* 0 or a power of two */
    size_t count;
} cdl_key_table;

/* The key of the unordered pair {a, b}. */
static inline uint64_t cdl_key_pair(uint32_t a, uint32_t b)
{
    return a < b ? ((uint64_t)a << 32) | b : ((uint64_t)b << 32) | a;
}

/* The key of the ordered pair (a, b). */
static inline uint64_t cdl_key_ordered(uint32_t a, uint32_t b)
{
    return ((uint64_t)a << 32) | b;
}

/* The value stored under key, or CDL_KEY_TABLE_NONE. */
size_t cdl_key_table_find(const cdl_key_table *table, uint64_t key);

/* Store value (not CDL_KEY_TABLE_NONE) under key, replacing any value
 * there. Errors: memory. */
cdl_status cdl_key_table_put(cdl_key_table *table, uint64_t key, size_t value, cdl_error *err);

void cdl_key_table_release(cdl_key_table *table);

#endif
