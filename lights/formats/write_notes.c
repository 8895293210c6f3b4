/* write_notes.c - what a written format could not hold, one sentence each. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/formats/photometry_writer.h"

void cdl_photometry_notes_free(cdl_photometry_notes *notes)
{
    if (!notes) return;
    for (size_t i = 0; i < notes->count; ++i) free(notes->items[i]);
    free(notes->items);
    notes->items = NULL;
    notes->count = 0;
}

void cdl_photometry_note(cdl_photometry_notes *notes, const char *fmt, ...)
{
    if (!notes) return;
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    char **grown = realloc(notes->items, (notes->count + 1) * sizeof *grown);
    if (!grown) return;
    notes->items = grown;
    size_t len = strlen(buf);
    char *copy = malloc(len + 1);
    if (!copy) return;
    memcpy(copy, buf, len + 1);
    notes->items[notes->count++] = copy;
}
