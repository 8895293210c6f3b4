/* grow.c - doubling growth of arrays (grow.h). */
#include "base/grow.h"
#include "base/error_report.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

cdl_status cdl_grow(void *items, size_t *capacity, size_t needed, size_t item_size, size_t first, cdl_error *err)
{
    if (needed <= *capacity) return CDL_OK;
    size_t cap = *capacity ? *capacity : (first ? first : 1);
    while (cap < needed) {
        if (cap > SIZE_MAX / 2) return cdl_error_out_of_memory(err);
        cap *= 2;
    }
    if (cap > SIZE_MAX / item_size) return cdl_error_out_of_memory(err);
    void *old;
    memcpy(&old, items, sizeof old);
    void *grown = realloc(old, cap * item_size);
    if (!grown) return cdl_error_out_of_memory(err);
    memcpy(items, &grown, sizeof grown);
    *capacity = cap;
    return CDL_OK;
}
