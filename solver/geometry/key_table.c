/* key_table.c - open addressing, linear probing (key_table.h). */
#include "solver/geometry/key_table.h"
#include "base/error_report.h"

#include <stdlib.h>

/* SplitMix64's finaliser (Steele, Lea and Flood, "Fast splittable
 * pseudorandom number generators", OOPSLA 2014): every key bit reaches
 * every hash bit, so vertex pairs that differ in a few low bits spread. */
static uint64_t mix(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

static size_t slot_of(const cdl_key_table_slot *slots, size_t capacity, uint64_t key)
{
    size_t mask = capacity - 1, i = (size_t)mix(key) & mask;
    while (slots[i].value != CDL_KEY_TABLE_NONE && slots[i].key != key) i = (i + 1) & mask;
    return i;
}

size_t cdl_key_table_find(const cdl_key_table *table, uint64_t key)
{
    if (table->capacity == 0) return CDL_KEY_TABLE_NONE;
    return table->slots[slot_of(table->slots, table->capacity, key)].value;
}

static cdl_status grow(cdl_key_table *table, cdl_error *err)
{
    size_t capacity = table->capacity ? 2 * table->capacity : 64;
    cdl_key_table_slot *slots = malloc(capacity * sizeof *slots);
    if (!slots) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < capacity; ++i) slots[i].value = CDL_KEY_TABLE_NONE;
    for (size_t i = 0; i < table->capacity; ++i) {
        if (table->slots[i].value == CDL_KEY_TABLE_NONE) continue;
        slots[slot_of(slots, capacity, table->slots[i].key)] = table->slots[i];
    }
    free(table->slots);
    table->slots = slots;
    table->capacity = capacity;
    return CDL_OK;
}

cdl_status cdl_key_table_put(cdl_key_table *table, uint64_t key, size_t value, cdl_error *err)
{
    if (2 * (table->count + 1) > table->capacity && grow(table, err) != CDL_OK) return CDL_ERR_INTERNAL;
    size_t i = slot_of(table->slots, table->capacity, key);
    if (table->slots[i].value == CDL_KEY_TABLE_NONE) ++table->count;
    table->slots[i].key = key;
    table->slots[i].value = value;
    return CDL_OK;
}

void cdl_key_table_release(cdl_key_table *table)
{
    free(table->slots);
    table->slots = NULL;
    table->capacity = table->count = 0;
}
