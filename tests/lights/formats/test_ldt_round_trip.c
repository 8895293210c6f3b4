/* EULUMDAT -> IES -> EULUMDAT gives back the file: on every EULUMDAT file
 * of the corpus, every header line (text as written without the quotes
 * some writers add, numbers as numbers; line 11, the file's own name, is
 * the name the third file is given) and every C angle, gamma angle and
 * cd/klm value (within 1e-8 of the largest: the writers print ten
 * significant digits). The fields IES has no place for travel as its
 * [_EULUMDAT_*] keywords; a gamma range LM-63 cannot end at (0..140) comes
 * back without the IES file's zero padding. And a file Candela wrote is a
 * fixed point: written again after the trip through IES, byte for byte.
 *
 * Needs CANDELA_PHOTOMETRIC_DIR; skipped (exit 77) when it is absent. */
// ctest-labels: corpus
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry_checks.h"

#define DIR_ CANDELA_PHOTOMETRIC_DIR

/* The file's lines, trimmed (CR, LF or CR LF ends), quotes around a whole line dropped. */
static char **split_lines(const char *text, size_t *count)
{
    size_t cap = 64, n = 0;
    char **lines = malloc(cap * sizeof *lines);
    const char *s = text;
    while (lines && *s) {
        size_t len = strcspn(s, "\r\n");
        const char *a = s, *b = s + len;
        while (a < b && (*a == ' ' || *a == '\t')) ++a;
        while (b > a && (b[-1] == ' ' || b[-1] == '\t')) --b;
        if (b - a >= 2 && *a == '"' && b[-1] == '"') ++a, --b;
        if (n == cap) lines = realloc(lines, (cap *= 2) * sizeof *lines);
        lines[n] = malloc((size_t)(b - a) + 1);
        memcpy(lines[n], a, (size_t)(b - a));
        lines[n][b - a] = '\0';
        ++n;
        s += len;
        if (*s == '\r' && s[1] == '\n') s += 2;
        else if (*s) ++s;
    }
    *count = n;
    return lines;
}

static void free_lines(char **l, size_t n)
{
    for (size_t i = 0; i < n; ++i) free(l[i]);
    free(l);
}

static int number(const char *s, double *x)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s", s);
    for (char *c = buf; *c; ++c)
        if (*c == ',') *c = '.'; /* a decimal comma */
    char *end = NULL;
    *x = strtod(buf, &end);
    return end != buf && *end == '\0';
}

/* Every number after the header, whatever the line breaks. */
static double *tail_numbers(char **l, size_t n, size_t from, size_t *count)
{
    double *x = malloc((n + 1) * 16 * sizeof *x);
    size_t k = 0;
    for (size_t i = from; i < n; ++i) {
        char *save = NULL, *copy = strdup(l[i]);
        for (char *t = strtok_r(copy, " \t", &save); t; t = strtok_r(NULL, " \t", &save))
            if (number(t, &x[k])) ++k;
        free(copy);
    }
    *count = k;
    return x;
}

static char *write_as(const cdl_photometry *p, int ldt, const char *name) { return pc_write(p, ldt, 2019, name); }

/* EULUMDAT -> IES -> EULUMDAT as text; NULL on failure. */
static char *round_trip(const cdl_photometry *p, const char *name)
{
    char *ies = write_as(p, 0, name);
    cdl_error err;
    cdl_photometry *q = ies ? pc_read_text("trip.ies", ies, strlen(ies), 0, &err) : NULL;
    CHECK_MSG(!ies || q, "%s: %s", name, err.message);
    char *ldt = q ? write_as(q, 1, name) : NULL;
    cdl_photometry_release(q);
    free(ies);
    return ldt;
}

static void compare(const char *file, const char *original, const char *back)
{
    size_t na, nb;
    char **a = split_lines(original, &na), **b = split_lines(back, &nb);
    double sets;
    size_t header = na > 26 && number(a[25], &sets) ? 26 + 6 * (size_t)sets + 10 : 0;
    CHECK_MSG(header > 0 && nb > header, "%s: header", file);
    for (size_t i = 0; header && i < header && i < nb; ++i) {
        if (i == 10) continue; /* line 11: the file's own name */
        double x, y;
        int same = strcmp(a[i], b[i]) == 0 ||
                   (number(a[i], &x) && number(b[i], &y) && fabs(x - y) <= 1e-9 * fmax(1.0, fabs(x))) ||
                   (a[i][0] == '\0' && number(b[i], &y) && y == 0.0); /* an empty number line reads as 0 */
        CHECK_MSG(same, "%s:%zu: '%s' came back as '%s'", file, i + 1, a[i], b[i]);
    }
    size_t ka, kb;
    double *x = tail_numbers(a, na, header, &ka), *y = tail_numbers(b, nb, header, &kb);
    /* the numbers the header asks for: extra values after a table are not the table */
    double mc, ng, isym;
    number(a[3], &mc);
    number(a[5], &ng);
    number(a[2], &isym);
    CHECK_MSG(kb <= ka, "%s: %zu numbers after the header, %zu before", file, kb, ka);
    double max = 0.0;
    for (size_t k = 0; k < kb; ++k) max = fmax(max, fabs(x[k]));
    size_t worst = 0;
    for (size_t k = 0; k < kb && k < ka; ++k)
        if (fabs(x[k] - y[k]) > fabs(x[worst] - y[worst])) worst = k;
    CHECK_MSG(kb == 0 || fabs(x[worst] - y[worst]) <= 1e-8 * max, "%s: value %zu was %.10g, came back %.10g", file,
              worst, x[worst], y[worst]);
    free(x);
    free(y);
    free_lines(a, na);
    free_lines(b, nb);
}

int main(void)
{
    DIR *d = opendir(DIR_);
    if (!d) {
        printf("SKIPPED: the photometric corpus folder %s is absent (this test needs ../shared/photometric)\n", DIR_);
        return 77;
    }
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strncmp(e->d_name, "ldt_", 4) != 0 || strstr(e->d_name, "MALFORMED")) continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", DIR_, e->d_name);
        cdl_error err;
        cdl_photometry *p = pc_read_file(path, 0, &err);
        CHECK_MSG(p != NULL, "%s: %s", e->d_name, err.message);
        if (!p) continue;
        ++files;
        FILE *f = fopen(path, "rb");
        char *original = calloc(1 << 21, 1);
        size_t len = f && original ? fread(original, 1, (1 << 21) - 1, f) : 0;
        if (f) fclose(f);
        original[len] = '\0';
        char *back = round_trip(p, e->d_name);
        if (back) compare(e->d_name, original, back);
        /* a file Candela wrote is a fixed point of the trip */
        char *canonical = write_as(p, 1, e->d_name);
        cdl_photometry *c = canonical ? pc_read_text(e->d_name, canonical, strlen(canonical), 0, &err) : NULL;
        char *again = c ? round_trip(c, e->d_name) : NULL;
        CHECK_MSG(canonical && again && strcmp(canonical, again) == 0, "%s: Candela's own file changed by the trip",
                  e->d_name);
        cdl_photometry_release(c);
        free(canonical);
        free(again);
        free(back);
        free(original);
        cdl_photometry_release(p);
    }
    closedir(d);
    CHECK_MSG(files >= 20, "only %d EULUMDAT files", files);
    return check_finish();
}
