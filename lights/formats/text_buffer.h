/* text_buffer.h - a growing text the photometric writers print into (not public). */
#ifndef CANDELA_LIGHTS_FORMATS_TEXT_BUFFER_H
#define CANDELA_LIGHTS_FORMATS_TEXT_BUFFER_H

#include <stddef.h>

/* A growing text; after a failed allocation every call is a no-op and
 * `failed` stays set. */
typedef struct cdl_text_buffer {
    char *data;
    size_t len, cap;
    int failed;
} cdl_text_buffer;

void cdl_text_buffer_printf(cdl_text_buffer *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A number with up to 10 significant digits, no trailing zeros. */
void cdl_text_buffer_number(cdl_text_buffer *t, double x);
/* The shortest form, of 10 to 17 significant digits, that reads back as x
 * exactly (for a value another is derived from: lumens per lamp). */
void cdl_text_buffer_exact(cdl_text_buffer *t, double x);
void cdl_text_buffer_free(cdl_text_buffer *t);

#endif
