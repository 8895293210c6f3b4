/* sized_struct.c - structs that begin with their own size (sized_struct.h). */
#include "base/sized_struct.h"

#include <string.h>

/* The bytes after the size field that both structs have. */
static size_t shared_tail(const void *caller, size_t ours_size)
{
    size_t theirs;
    memcpy(&theirs, caller, sizeof theirs);
    size_t n = theirs < ours_size ? theirs : ours_size;
    return n > sizeof theirs ? n - sizeof theirs : 0;
}

void cdl_sized_struct_read(void *ours, size_t ours_size, const void *given)
{
    if (!given) return;
    size_t n = shared_tail(given, ours_size);
    memcpy((char *)ours + sizeof(size_t), (const char *)given + sizeof(size_t), n);
}

void cdl_sized_struct_fill(void *given, const void *ours, size_t ours_size)
{
    size_t n = shared_tail(given, ours_size);
    memcpy((char *)given + sizeof(size_t), (const char *)ours + sizeof(size_t), n);
}
