/* strings.c - owned copies of strings and joined paths (strings.h). */
#include "base/strings.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *cdl_string_copy(const char *s)
{
    return cdl_string_copy_n(s, strlen(s));
}

char *cdl_string_copy_n(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (c) {
        memcpy(c, s, n);
        c[n] = '\0';
    }
    return c;
}

char *cdl_path_join(const char *dir, const char *name, const char *ext)
{
    size_t n = strlen(dir) + strlen(name) + strlen(ext) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s%s", dir, name, ext);
    return p;
}
