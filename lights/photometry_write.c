/* photometry_write.c - what the writers share: a growable text buffer, the
 * notes of what a format cannot hold, and atomic file output. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "lights/photometry_writer.h"
#include "radiometry/atomic_file.h"

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

void cdl_text_printf(cdl_text *t, const char *fmt, ...)
{
    if (t->failed) return;
    for (;;) {
        size_t room = t->cap - t->len;
        va_list ap;
        va_start(ap, fmt);
        int n = t->data ? vsnprintf(t->data + t->len, room, fmt, ap) : -2;
        va_end(ap);
        if (n >= 0 && (size_t)n < room) {
            t->len += (size_t)n;
            return;
        }
        if (n == -1) {
            t->failed = 1;
            return;
        }
        size_t need = t->len + (n > 0 ? (size_t)n : 0) + 1;
        size_t cap = t->cap ? t->cap : 4096;
        while (cap < need) cap *= 2;
        char *d = realloc(t->data, cap);
        if (!d) {
            t->failed = 1;
            return;
        }
        t->data = d;
        t->cap = cap;
    }
}

void cdl_text_number(cdl_text *t, double x)
{
    /* Ten significant digits survive a candela value's trip through both
     * formats with room to spare; %g drops trailing zeros. -0 prints as 0. */
    if (x == 0.0) x = 0.0;
    cdl_text_printf(t, "%.10g", x);
}

void cdl_text_free(cdl_text *t)
{
    free(t->data);
    t->data = NULL;
    t->len = t->cap = 0;
}

cdl_status cdl_photometry_write_file(const cdl_photometry *p, const char *path, cdl_photometry_format format,
                                     const cdl_photometry_write_options *options, cdl_photometry_notes *lost,
                                     cdl_error *err)
{
    cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_DEFAULT;
    if (options) o = *options;
    if (!o.file_name) {
        const char *slash = strrchr(path, '/');
        o.file_name = slash ? slash + 1 : path;
    }
    char *text = NULL;
    size_t len = 0;
    cdl_status st;
    if (format == CDL_PHOTOMETRY_FORMAT_IES) st = cdl_photometry_format_ies(p, &o, &text, &len, lost, err);
    else if (format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) st = cdl_photometry_format_ldt(p, &o, &text, &len, lost, err);
    else st = cdl_error_set(err, CDL_ERR_USAGE, "%s: can write IES or EULUMDAT only", path);
    if (st != CDL_OK) return st;

    /* No half-written output (radiometry/atomic_file.h). A file that cannot
     * be created there (a missing or read-only folder) is the user's path
     * to fix: bad input; failing writes and syncs stay internal failures. */
    st = cdl_atomic_file_write_all(path, text, len, err);
    free(text);
    return st;
}
