/* text_buffer.c - a growing text the writers print into. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/formats/text_buffer.h"

void cdl_text_buffer_printf(cdl_text_buffer *t, const char *fmt, ...)
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

void cdl_text_buffer_number(cdl_text_buffer *t, double x)
{
    /* Ten significant digits survive a candela value's trip through both
     * formats with room to spare; %g drops trailing zeros. -0 prints as 0. */
    if (x == 0.0) x = 0.0;
    cdl_text_buffer_printf(t, "%.10g", x);
}

void cdl_text_buffer_exact(cdl_text_buffer *t, double x)
{
    if (x == 0.0) x = 0.0;
    char buf[40];
    for (int digits = 10; digits <= 17; ++digits) {
        snprintf(buf, sizeof buf, "%.*g", digits, x);
        if (strtod(buf, NULL) == x) break;
    }
    cdl_text_buffer_printf(t, "%s", buf);
}

void cdl_text_buffer_free(cdl_text_buffer *t)
{
    free(t->data);
    t->data = NULL;
    t->len = t->cap = 0;
}
