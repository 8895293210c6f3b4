/* ies_read.c - IES LM-63 reader: 1986 (no tag), 1991, 1995, 2002, 2019 and
 * the variant tags of real files.
 *
 * Layout (FORMAT_NOTES section 1): line 1 version tag (none in 1986);
 * keyword or label lines up to the "TILT=" line; then, whatever the line
 * breaks, numbers read by count: the tilt records (TILT=INCLUDE), record A
 * (10 numbers: lamps, lumens per lamp, candela multiplier, number of
 * vertical and horizontal angles, photometric type, units, width, length,
 * height), record B (ballast factor, ballast-lamp factor / future use /
 * file-generation type, input watts), the vertical angles, the horizontal
 * angles, and one group of candela values per horizontal angle.
 *
 * Type C horizontal angles become frame planes C = (360 - H) mod 360 (see
 * photometry.h); the symmetry follows from the horizontal range.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/formats/photometry_io.h"
#include "lights/photometry/photometry_metadata.h"

typedef struct ies_reader {
    const char *source; /* name for messages */
    const char *name;   /* the path, or NULL (memory) */
    const cdl_photometry_read_options *options;
    cdl_photometry *p;
    cdl_error *err;
    cdl_photometry_scanner s;
    cdl_photometry_scanner table_start; /* after the ballast line */
    unsigned values_line;               /* line of the first candela value: where table-wide errors point */
    unsigned last_row_line;             /* line of the first value of the last horizontal angle's row */
    unsigned v_line, h_line;            /* lines of the last vertical and the last horizontal angle */
} ies_reader;

static cdl_status oom(ies_reader *r) { return cdl_error_out_of_memory(r->err); }

static int starts_nocase(const char *s, size_t len, const char *prefix)
{
    size_t n = strlen(prefix);
    if (len < n) return 0;
    for (size_t i = 0; i < n; ++i)
        if (toupper((unsigned char)s[i]) != toupper((unsigned char)prefix[i])) return 0;
    return 1;
}

static int equals_nocase(const char *s, size_t len, const char *word)
{
    return len == strlen(word) && starts_nocase(s, len, word);
}

/* ---- version tag ---------------------------------------------------------------- */

static const int known_versions[4] = {1991, 1995, 2002, 2019};

/* Version of a tag line (trimmed); *standard = 1 for the exact standard tags. */
static int version_of_tag(const char *t, size_t n, int *standard)
{
    *standard = 1;
    if (equals_nocase(t, n, "IESNA91")) return 1991;
    if (equals_nocase(t, n, "IESNA:LM-63-1995")) return 1995;
    if (equals_nocase(t, n, "IESNA:LM-63-2002")) return 2002;
    if (equals_nocase(t, n, "IES:LM-63-2019")) return 2019;
    *standard = 0;
    /* a year in the tag: the last run of 4 digits (19xx/20xx) or of 2 digits */
    int year = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!isdigit((unsigned char)t[i])) continue;
        size_t j = i;
        int v = 0;
        while (j < n && isdigit((unsigned char)t[j]) && j - i < 6) v = v * 10 + (t[j++] - '0');
        if (j - i == 4 && v >= 1980 && v <= 2099) year = v;
        else if (j - i == 2) year = v >= 80 ? 1900 + v : 2000 + v;
        i = j;
    }
    if (year == 0) return 2002;
    int best = known_versions[0];
    for (int k = 1; k < 4; ++k)
        if (abs(known_versions[k] - year) < abs(best - year)) best = known_versions[k];
    return best;
}

/* ---- header: tag, keywords, TILT line ----------------------------------------------- */

static int is_tilt_line(const char *t, size_t n, size_t *value_at)
{
    if (!starts_nocase(t, n, "TILT")) return 0;
    size_t k = 4;
    while (k < n && (t[k] == ' ' || t[k] == '\t')) ++k;
    if (k >= n || t[k] != '=') return 0;
    *value_at = k + 1;
    return 1;
}

static cdl_status read_keyword_line(ies_reader *r, const char *t, size_t n, int version)
{
    if (version >= 1991 && n > 0 && t[0] == '[') {
        const char *close = memchr(t, ']', n);
        if (close) {
            const char *key = t + 1;
            size_t key_len = (size_t)(close - key);
            const char *value = close + 1;
            size_t value_len = n - (size_t)(value - t);
            cdl_photometry_trim(&key, &key_len);
            cdl_photometry_trim(&value, &value_len);
            cdl_status st = equals_nocase(key, key_len, "MORE")
                                ? cdl_photometry_append_keyword(r->p, value, value_len)
                                : cdl_photometry_add_keyword(r->p, key, key_len, value, value_len);
            return st == CDL_OK ? CDL_OK : oom(r);
        }
    }
    /* 1986 label lines, and stray text in later versions: free text */
    return cdl_photometry_add_keyword(r->p, "", 0, t, n) == CDL_OK ? CDL_OK : oom(r);
}

/* Reads up to and including the TILT line; leaves the scanner after it. */
static cdl_status read_header(ies_reader *r, const char *data, size_t size, char *tilt, size_t tilt_size)
{
    cdl_photometry_metadata *m = &r->p->meta;
    size_t pos = 0;
    if (cdl_photometry_has_bom(data, size)) {
        pos = 3;
        if (cdl_photometry_add_warning(r->p, "byte-order-mark", 1,
                                       "%s:1: the file starts with a UTF-8 byte-order mark (LM-63 is plain text; "
                                       "some programs take it for part of the version tag): ignored",
                                       r->source) != CDL_OK)
            return oom(r);
    }
    const char *line;
    size_t len;
    unsigned number = 0;
    int version = 1986;
    while (cdl_photometry_next_line(data, size, &pos, &line, &len)) {
        ++number;
        cdl_photometry_trim(&line, &len);
        size_t value_at;
        if (number == 1 && (starts_nocase(line, len, "IESNA") || starts_nocase(line, len, "IES:"))) {
            int standard;
            version = version_of_tag(line, len, &standard);
            cdl_photometry_copy_text(m->version_tag, sizeof m->version_tag, line, len);
            if (!standard &&
                cdl_photometry_add_warning(r->p, "ies-version-tag", 1,
                                           "%s:1: expected a standard version tag (IESNA91, IESNA:LM-63-1995, "
                                           "IESNA:LM-63-2002 or IES:LM-63-2019), found the non-standard version tag "
                                           "'%s': read as LM-63-%d",
                                           r->source, m->version_tag, version) != CDL_OK)
                return oom(r);
            continue;
        }
        if (is_tilt_line(line, len, &value_at)) {
            const char *v = line + value_at;
            size_t vlen = len - value_at;
            cdl_photometry_trim(&v, &vlen);
            cdl_photometry_copy_text(tilt, tilt_size, v, vlen);
            m->ies_version = version;
            cdl_photometry_scanner_init(&r->s, data, size, pos, number + 1, 1);
            return CDL_OK;
        }
        if (len == 0) continue;
        size_t before = m->keyword_count;
        cdl_status st = read_keyword_line(r, line, len, version);
        if (st != CDL_OK) return st;
        if (m->keyword_count > before) m->keywords[m->keyword_count - 1].line = number;
    }
    return cdl_error_set(r->err, CDL_ERR_INPUT,
                         "%s:%u: expected a 'TILT=' line (TILT=NONE, TILT=INCLUDE or TILT=<file>) after the "
                         "header, found the end of the file",
                         r->source, number ? number : 1);
}

static cdl_status read_tilt(ies_reader *r, const char *tilt)
{
    cdl_photometry_metadata *m = &r->p->meta;
    if (cdl_photometry_strcaseeq(tilt, "NONE")) return CDL_OK;
    if (cdl_photometry_strcaseeq(tilt, "INCLUDE")) {
        m->tilt_kind = CDL_TILT_INCLUDE;
        return cdl_tilt_read_records(&r->s, r->source, r->p, r->err);
    }
    m->tilt_kind = CDL_TILT_FILE;
    snprintf(m->tilt_file, sizeof m->tilt_file, "%s", tilt);
    if (tilt[0] == '\0')
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected TILT=NONE, TILT=INCLUDE or TILT=<file>, found 'TILT='",
                             r->source, r->s.line - 1);
    if (!r->name || r->options->no_external_files)
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: TILT=%s names a separate tilt file, and reading other files is disabled here",
                             r->source, r->s.line - 1, tilt);
    if (m->ies_version >= 2019 &&
        cdl_photometry_add_warning(r->p, "ies-tilt-file-2019", r->s.line - 1, "%s:%u: LM-63-2019 no longer allows TILT=<file>; '%s' read anyway",
                                   r->source, r->s.line - 1, tilt) != CDL_OK)
        return oom(r);
    cdl_error first;
    cdl_error_clear(&first);
    cdl_status st = cdl_tilt_read_file(r->name, tilt, r->p, &first);
    if (st == CDL_OK) return CDL_OK;
    /* a non-standard "TILT=FILE name" (seen in test fixtures) */
    if (starts_nocase(tilt, strlen(tilt), "FILE") && (tilt[4] == ' ' || tilt[4] == '\t')) {
        const char *rest = tilt + 5;
        while (*rest == ' ' || *rest == '\t') ++rest;
        if (*rest && cdl_tilt_read_file(r->name, rest, r->p, r->err) == CDL_OK)
            return cdl_photometry_add_warning(r->p, "ies-tilt-syntax", r->s.line - 1, "%s:%u: non-standard 'TILT=%s' read as TILT=%s", r->source,
                                              r->s.line - 1, tilt, rest) == CDL_OK
                       ? CDL_OK
                       : oom(r);
    }
    *r->err = first;
    return cdl_error_prefix(r->err, "%s:%u: TILT=%s: ", r->source, r->s.line - 1, tilt);
}

/* ---- records A and B ------------------------------------------------------------------- */

typedef struct ies_header {
    long lamps, nv, nh, type, units;
    double lumens, multiplier, width, length, height;
    double ballast, factor2, watts;
    unsigned line_a[10], line_b[3];
} ies_header;

static cdl_status read_records(ies_reader *r, ies_header *h)
{
    static const char *const names_a[10] = {
        "the number of lamps (record A, field 1)",      "the lumens per lamp (record A, field 2)",
        "the candela multiplier (record A, field 3)",   "the number of vertical angles (record A, field 4)",
        "the number of horizontal angles (record A, field 5)", "the photometric type (record A, field 6)",
        "the units type (record A, field 7)",           "the luminous width (record A, field 8)",
        "the luminous length (record A, field 9)",      "the luminous height (record A, field 10)"};
    double a[10];
    for (int k = 0; k < 10; ++k) {
        cdl_status st = cdl_photometry_expect_number(&r->s, r->source, names_a[k], &a[k], &h->line_a[k], r->err);
        if (st != CDL_OK) return st;
    }
    const char *src = r->source;
    /* whole-number fields (1986 files may write them as "3.0") */
    const int integer_fields[5] = {0, 3, 4, 5, 6};
    for (int i = 0; i < 5; ++i) {
        int k = integer_fields[i];
        if (a[k] != floor(a[k]) || fabs(a[k]) > 1e9)
            return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s as a whole number, found %g", src,
                                 h->line_a[k], names_a[k], a[k]);
    }
    h->lamps = (long)a[0];
    h->lumens = a[1];
    h->multiplier = a[2];
    h->nv = (long)a[3];
    h->nh = (long)a[4];
    h->type = (long)a[5];
    h->units = (long)a[6];
    h->width = a[7];
    h->length = a[8];
    h->height = a[9];
    if (h->lamps < 0)
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s >= 1, found %ld", src, h->line_a[0],
                             names_a[0], h->lamps);
    if (!(h->multiplier > 0.0))
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s > 0, found %g", src, h->line_a[2], names_a[2],
                             h->multiplier);
    if (h->nv < 2)
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: expected %s >= 2 (one angle encloses no solid angle), found %ld", src,
                             h->line_a[3], names_a[3], h->nv);
    if (h->nh < 1)
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s >= 1, found %ld", src, h->line_a[4],
                             names_a[4], h->nh);
    if (h->type < 1 || h->type > 3)
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: expected %s 1 (type C), 2 (type B) or 3 (type A), found %ld: unknown "
                             "photometric type",
                             src, h->line_a[5], names_a[5], h->type);
    /* types A/B: H is a latitude (B) or a longitude (A) of a two-angle grid; one H encloses no solid angle */
    if (h->type != 1 && h->nh < 2)
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: expected %s >= 2 for type %c data (one angle encloses no solid angle), found %ld",
                             src, h->line_a[4], names_a[4], h->type == 2 ? 'B' : 'A', h->nh);

    static const char *const names_b[3][3] = {
        {"the ballast factor (record B, field 1)", "the ballast-lamp photometric factor (record B, field 2)",
         "the input watts (record B, field 3)"},
        {"the ballast factor (record B, field 1)", "the future-use field (record B, field 2)",
         "the input watts (record B, field 3)"},
        {"the ballast factor (record B, field 1)", "the file generation type (record B, field 2)",
         "the input watts (record B, field 3)"}};
    int era = r->p->meta.ies_version <= 1995 ? 0 : r->p->meta.ies_version < 2019 ? 1 : 2;
    /* where record A ends, to count what follows for the missing-record hint below */
    cdl_photometry_scanner after_a = r->s;
    double b[3];
    for (int k = 0; k < 3; ++k) {
        cdl_status st = cdl_photometry_expect_number(&r->s, src, names_b[era][k], &b[k], &h->line_b[k], r->err);
        if (st != CDL_OK) return st;
    }
    h->ballast = b[0];
    h->factor2 = b[1];
    h->watts = b[2];
    if (!(h->ballast > 0.0)) {
        double need = 3.0 + (double)h->nv + (double)h->nh + (double)h->nv * (double)h->nh;
        const char *hint = (double)cdl_photometry_count_numbers(&after_a, 1) + 3.0 == need
                               ? "; the file holds exactly 3 numbers fewer than its header needs: the ballast "
                                 "line (ballast factor, second factor, input watts) looks missing"
                               : "";
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s > 0, found %g%s", src, h->line_b[0],
                             names_b[era][0], h->ballast, hint);
    }
    return CDL_OK;
}

/* ---- angles and values ------------------------------------------------------------------ */

static double numbers_needed(const ies_header *h) { return (double)h->nv + (double)h->nh + (double)h->nv * (double)h->nh; }

/* The data ended (at `line`) after `have` of the numbers that follow the ballast line. */
static cdl_status truncated(ies_reader *r, const ies_header *h, size_t have, unsigned line)
{
    return cdl_error_set(r->err, CDL_ERR_INPUT,
                         "%s:%u: expected %.0f numbers after the ballast line (%ld vertical angles, %ld horizontal "
                         "angles, %ld x %ld candela values), found %zu: the file is truncated",
                         r->source, line, numbers_needed(h), h->nv, h->nh, h->nv, h->nh, have);
}

/* For an angle error: when the file holds a different number of values
 * than record A announces, say so (the counts, not the angles, are wrong). */
static void count_hint(const ies_reader *r, const ies_header *h, char *out, size_t size)
{
    size_t have = cdl_photometry_count_numbers(&r->table_start, 1);
    out[0] = '\0';
    if ((double)have != numbers_needed(h))
        snprintf(out, size, "; the file holds %zu numbers after the ballast line where record A announces %.0f (%ld "
                            "vertical angles, %ld horizontal angles, %ld x %ld values): check those counts",
                 have, numbers_needed(h), h->nv, h->nh, h->nv, h->nh);
}

static cdl_status read_angles(ies_reader *r, const ies_header *h, size_t done, const char *kind, long n, double lo,
                              double hi, double *x, unsigned *last_line)
{
    char what[96];
    for (long i = 0; i < n; ++i) {
        cdl_token_kind k = cdl_photometry_take_number(&r->s, &x[i]);
        unsigned line = r->s.tok_line;
        *last_line = line;
        if (k == CDL_TOKEN_END) return truncated(r, h, done + (size_t)i, r->s.line);
        if (k != CDL_TOKEN_NUMBER || x[i] < lo || x[i] > hi || (i > 0 && !(x[i] > x[i - 1])))
            snprintf(what, sizeof what, "%s angle %ld of %ld", kind, i + 1, n);
        if (k != CDL_TOKEN_NUMBER) return cdl_photometry_token_error(&r->s, k, r->source, what, r->err);
        char hint[256];
        if (x[i] < lo || x[i] > hi) {
            count_hint(r, h, hint, sizeof hint);
            return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s within [%g, %g] degrees, found %g%s",
                                 r->source, line, what, lo, hi, x[i], hint);
        }
        if (i > 0 && !(x[i] > x[i - 1])) {
            count_hint(r, h, hint, sizeof hint);
            return cdl_error_set(r->err, CDL_ERR_INPUT,
                                 "%s:%u: expected %s angles in increasing order, found %g after %g%s", r->source, line,
                                 kind, x[i], x[i - 1], hint);
        }
    }
    return CDL_OK;
}

static cdl_status read_values(ies_reader *r, const ies_header *h, const double *v, const double *hz, double *cd)
{
    char what[128];
    for (long i = 0; i < h->nh; ++i)
        for (long j = 0; j < h->nv; ++j) {
            double x;
            cdl_token_kind k = cdl_photometry_take_number(&r->s, &x);
            unsigned line = r->s.tok_line;
            if (i == 0 && j == 0) r->values_line = line;
            if (i == h->nh - 1 && j == 0) r->last_row_line = line;
            if (k == CDL_TOKEN_NUMBER && x >= 0.0 && isfinite(x * h->multiplier)) {
                cd[i * h->nv + j] = x * h->multiplier;
                continue;
            }
            if (k == CDL_TOKEN_END)
                return truncated(r, h, (size_t)(h->nv + h->nh) + (size_t)(i * h->nv + j), r->s.line);
            snprintf(what, sizeof what, "the candela value at horizontal angle %g, vertical angle %g", hz[i], v[j]);
            if (k != CDL_TOKEN_NUMBER) return cdl_photometry_token_error(&r->s, k, r->source, what, r->err);
            if (x < 0.0)
                return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s >= 0, found %g (negative candela)",
                                     r->source, line, what, x);
            double y = x * h->multiplier;
            if (!isfinite(y))
                return cdl_error_set(r->err, CDL_ERR_INPUT,
                                     "%s:%u: expected %s times the multiplier %g to be finite, found %g", r->source,
                                     line, what, h->multiplier, x);
            cd[i * h->nv + j] = y;
        }
    return CDL_OK;
}

/* After the table: more numbers or text are ignored with a warning. */
static cdl_status check_trailing(ies_reader *r)
{
    const char *tok;
    size_t len;
    unsigned line;
    cdl_photometry_scanner probe = r->s;
    if (!cdl_photometry_scan(&probe, &tok, &len, &line)) return CDL_OK;
    size_t numbers = cdl_photometry_count_numbers(&r->s, 1);
    char q[40];
    cdl_photometry_quote(q, sizeof q, tok, len);
    cdl_status st = cdl_photometry_add_warning(r->p, "trailing-values", line, "%s:%u: %zu number%s and other text after the candela table "
                                                     "ignored (starting with %s)",
                                               r->source, line, numbers, numbers == 1 ? "" : "s", q);
    return st == CDL_OK ? CDL_OK : oom(r);
}

/* ---- type C horizontal angles to frame planes --------------------------------------------- */

static cdl_status build_type_c(ies_reader *r, const ies_header *h, const double *v, const double *hz, double *cd)
{
    size_t nh = (size_t)h->nh, nv = (size_t)h->nv;
    double first = hz[0], last = hz[nh - 1];
    cdl_photometry_symmetry sym;
    if (nh == 1) sym = CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    else if (first == 0.0 && last == 90.0) sym = CDL_PHOTOMETRY_SYMMETRY_QUADRANT;
    else if (first == 0.0 && last == 180.0) sym = CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180;
    else if (first == 90.0 && last == 270.0) sym = CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270;
    else sym = CDL_PHOTOMETRY_SYMMETRY_NONE;

    double *c = malloc(nh * sizeof *c), *table = malloc(nh * nv * sizeof *table);
    if (!c || !table) {
        free(c);
        free(table);
        return oom(r);
    }
    size_t out_n = 0;
    cdl_status st = CDL_OK;
    switch (sym) {
    case CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL:
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT:
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180:
        /* mirror-symmetric about C0-C180: C = 360 - H holds the same values as C = H */
        for (size_t i = 0; i < nh; ++i) c[i] = sym == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL ? 0.0 : hz[i];
        memcpy(table, cd, nh * nv * sizeof *table);
        out_n = nh;
        break;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270:
        for (size_t i = 0; i < nh; ++i) {
            c[i] = 360.0 - hz[nh - 1 - i];
            memcpy(table + i * nv, cd + (nh - 1 - i) * nv, nv * sizeof *table);
        }
        out_n = nh;
        break;
    default: {
        size_t n = nh;
        if (first == 0.0 && last == 360.0) {
            /* H = 360 is H = 0 again: keep the 0 row, warn when they differ */
            const double *r0 = cd, *r1 = cd + (nh - 1) * nv;
            double worst = 0.0;
            size_t at = 0;
            for (size_t j = 0; j < nv; ++j)
                if (fabs(r0[j] - r1[j]) > worst) {
                    worst = fabs(r0[j] - r1[j]);
                    at = j;
                }
            if (worst > 0.0 &&
                cdl_photometry_add_warning(r->p, "seam-differs", r->last_row_line,
                                           "%s:%u: the H = 0 and H = 360 rows differ: expected the H = 360 row to "
                                           "repeat the H = 0 row, found a largest difference of %g cd at V = %g "
                                           "(%g vs %g); the H = 0 row is used",
                                           r->source, r->last_row_line, worst, v[at], r0[at], r1[at]) != CDL_OK)
                st = oom(r);
            --n;
        } else if (n > 1) {
            double gap = first + 360.0 - last, step = 0.0;
            for (size_t i = 1; i < n; ++i) step = fmax(step, hz[i] - hz[i - 1]);
            if (gap > step + 1e-9 &&
                cdl_photometry_add_warning(r->p, "ies-horizontal-range", r->h_line,
                                           "%s:%u: expected horizontal angles 0, 0..90, 0..180, 90..270 or a full "
                                           "circle, found horizontal angles %g..%g: the %g degree gap to %g "
                                           "is interpolated across",
                                           r->source, r->h_line, first, last, gap, first + 360.0) != CDL_OK)
                st = oom(r);
        }
        /* C = (360 - H) mod 360, in increasing C: H = 0 first, then the rest reversed */
        size_t k = 0;
        if (hz[0] == 0.0) {
            c[k] = 0.0;
            memcpy(table, cd, nv * sizeof *table);
            ++k;
        }
        for (size_t i = n; i-- > (hz[0] == 0.0 ? 1u : 0u);) {
            c[k] = 360.0 - hz[i];
            memcpy(table + k * nv, cd + i * nv, nv * sizeof *table);
            ++k;
        }
        out_n = k;
        if (out_n == 1) sym = CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
        break;
    }
    }
    if (st == CDL_OK) {
        st = cdl_photometry_set_table(r->p, CDL_PHOTOMETRIC_TYPE_C, sym, c, out_n, v, nv, table, r->err);
        if (st != CDL_OK) cdl_error_prefix(r->err, "%s:%u: ", r->source, r->values_line);
    }
    free(c);
    free(table);
    return st;
}

/* ---- metadata ------------------------------------------------------------------------- */

static cdl_status fill_metadata(ies_reader *r, const ies_header *h)
{
    cdl_photometry_metadata *m = &r->p->meta;
    m->format = CDL_PHOTOMETRY_FORMAT_IES;
    m->file_horizontal_count = (size_t)h->nh;
    m->file_vertical_count = (size_t)h->nv;
    m->candela_multiplier = h->multiplier;
    m->ballast_factor = h->ballast;
    m->input_watts = h->watts > 0.0 ? h->watts : 0.0;
    if (h->watts < 0.0 &&
        cdl_photometry_add_warning(r->p, "ies-input-watts", h->line_b[2], "%s:%u: expected input watts >= 0 (0 when unknown), found %g; read as unknown",
                                   r->source, h->line_b[2], h->watts) != CDL_OK)
        return oom(r);
    r->p->lamp_flux_line = h->line_a[1];
    r->p->ballast_line = h->line_b[0];
    r->p->generation_line = h->line_b[1];
    if (m->ies_version <= 1995) {
        if (h->factor2 > 0.0) {
            m->ballast_lamp_factor = h->factor2;
        } else if (cdl_photometry_add_warning(r->p, "ies-ballast-lamp-factor", h->line_b[1], "%s:%u: ballast-lamp photometric factor %g is not positive; 1 is "
                                                    "used",
                                              r->source, h->line_b[1], h->factor2) != CDL_OK) {
            return oom(r);
        }
    } else if (m->ies_version >= 2019) {
        m->file_generation_type = h->factor2;
    }
    int relative = h->lumens > 0.0;
    if (!relative && h->lumens != -1.0 &&
        cdl_photometry_add_warning(r->p, "ies-lumens-per-lamp", h->line_a[1], "%s:%u: expected lumens per lamp > 0 or -1 (absolute photometry), found %g; "
                                         "read as absolute photometry",
                                   r->source, h->line_a[1], h->lumens) != CDL_OK)
        return oom(r);
    if (relative && h->lamps == 0 &&
        cdl_photometry_add_warning(r->p, "ies-lamp-count", h->line_a[0], "%s:%u: the number of lamps is 0, so the rated lamp flux is unknown",
                                   r->source, h->line_a[0]) != CDL_OK)
        return oom(r);
    m->absolute = !(relative && h->lamps > 0);
    m->rated_lamp_flux_lm = m->absolute ? 0.0 : (double)h->lamps * h->lumens;
    m->lamp_set_count = 1;
    cdl_photometry_lamp_set *set = &m->lamp_sets[0];
    set->count = (int)(h->lamps > 1000000 ? 1000000 : h->lamps);
    set->flux_lm = m->rated_lamp_flux_lm;
    set->watts = m->input_watts;
    const char *lamp = cdl_photometry_keyword_value(r->p, "LAMP");
    if (!lamp || !*lamp) lamp = cdl_photometry_keyword_value(r->p, "LAMPCAT");
    if (lamp) cdl_photometry_copy_text(set->type, sizeof set->type, lamp, strlen(lamp));
    int units = (int)h->units;
    if (units != 1 && units != 2) {
        if (cdl_photometry_add_warning(r->p, "ies-units-type", h->line_a[6], "%s:%u: expected the units type 1 (feet) or 2 (metres), found %ld; the "
                                             "opening is read in metres",
                                       r->source, h->line_a[6], h->units) != CDL_OK)
            return oom(r);
        units = 2;
    }
    cdl_photometry_opening_from_ies(m->ies_version, h->width, h->length, h->height, units, &m->opening);
    return CDL_OK;
}

/* ---- the reader ------------------------------------------------------------------------ */

cdl_status cdl_ies_read(const char *data, size_t size, const char *name, const cdl_photometry_read_options *options,
                        cdl_photometry *p, cdl_error *err)
{
    ies_reader r;
    memset(&r, 0, sizeof r);
    r.source = name ? name : "<memory>";
    r.name = name;
    r.options = options;
    r.p = p;
    r.err = err;
    char tilt[256];
    cdl_status st = read_header(&r, data, size, tilt, sizeof tilt);
    if (st != CDL_OK) return st;
    if ((st = read_tilt(&r, tilt)) != CDL_OK) return st;
    ies_header h;
    if ((st = read_records(&r, &h)) != CDL_OK) return st;

    /* All remaining numbers must be there: say "truncated" rather than
     * failing on whichever value happens to be missing. */
    double need = (double)h.nv + (double)h.nh + (double)h.nv * (double)h.nh;
    if (need > 2e7)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected a table of at most 2e7 values, found %ld x %ld",
                             r.source, h.line_a[4], h.nv, h.nh);
    /* A number takes at least two bytes (a digit and a separator): a header
     * asking for more than the rest of the file can hold is refused before
     * anything is allocated (a hostile header cannot make us allocate more
     * than a few times the file's size). */
    if (need > 0.5 * (double)(size - r.s.pos) + 1.0) {
        size_t have;
        unsigned end_line;
        cdl_photometry_numbers_then_end(&r.s, &have, &end_line);
        return truncated(&r, &h, have, end_line);
    }
    r.table_start = r.s;

    double lo_v, hi_v, lo_h, hi_h;
    switch (h.type) {
    case 1: lo_v = 0.0; hi_v = 180.0; lo_h = 0.0; hi_h = 360.0; break;
    case 2: lo_v = -180.0; hi_v = 180.0; lo_h = -90.0; hi_h = 90.0; break;
    default: lo_v = -90.0; hi_v = 90.0; lo_h = -180.0; hi_h = 180.0; break;
    }
    size_t nv = (size_t)h.nv, nh = (size_t)h.nh;
    double *v = malloc(nv * sizeof *v), *hz = malloc(nh * sizeof *hz), *cd = malloc(nv * nh * sizeof *cd);
    if (!v || !hz || !cd) st = oom(&r);
    const char *vname = h.type == 1 ? "vertical (type C)" : h.type == 2 ? "vertical (type B)" : "vertical (type A)";
    const char *hname = h.type == 1 ? "horizontal (type C)" : h.type == 2 ? "horizontal (type B)" : "horizontal (type A)";
    if (st == CDL_OK) st = read_angles(&r, &h, 0, vname, h.nv, lo_v, hi_v, v, &r.v_line);
    if (st == CDL_OK) st = read_angles(&r, &h, (size_t)h.nv, hname, h.nh, lo_h, hi_h, hz, &r.h_line);
    if (st == CDL_OK) st = read_values(&r, &h, v, hz, cd);
    if (st == CDL_OK) st = check_trailing(&r);
    if (st == CDL_OK) st = fill_metadata(&r, &h);
    if (st == CDL_OK && h.type == 1) {
        if ((v[0] != 0.0 && v[0] != 90.0) || (v[nv - 1] != 90.0 && v[nv - 1] != 180.0))
            if (cdl_photometry_add_warning(p, "ies-vertical-range", r.v_line,
                                           "%s:%u: expected vertical angles from 0 or 90 to 90 or 180 (LM-63), found "
                                           "vertical angles %g..%g; the intensity outside is taken as zero",
                                           r.source, r.v_line, v[0], v[nv - 1]) != CDL_OK)
                st = oom(&r);
        if (st == CDL_OK) st = build_type_c(&r, &h, v, hz, cd);
    } else if (st == CDL_OK) {
        int ok_h = (hz[0] == -90.0 || hz[0] == 0.0) && hz[nh - 1] == 90.0;
        int ok_v = (v[0] == -90.0 || v[0] == 0.0) && v[nv - 1] == 90.0;
        if ((!ok_h || !ok_v) &&
            cdl_photometry_add_warning(p, "ies-ab-range", r.h_line,
                                       "%s:%u: expected type %c angles from -90 or 0 to 90 for both H and V (LM-63), "
                                       "found H %g..%g, V %g..%g; the intensity outside is taken as zero",
                                       r.source, r.h_line, h.type == 2 ? 'B' : 'A', hz[0], hz[nh - 1], v[0],
                                       v[nv - 1]) != CDL_OK)
            st = oom(&r);
        if (st == CDL_OK) {
            st = cdl_photometry_set_table(p, h.type == 2 ? CDL_PHOTOMETRIC_TYPE_B : CDL_PHOTOMETRIC_TYPE_A,
                                          CDL_PHOTOMETRY_SYMMETRY_INFER, hz, nh, v, nv, cd, err);
            if (st != CDL_OK) cdl_error_prefix(err, "%s:%u: ", r.source, r.values_line);
        }
    }
    free(v);
    free(hz);
    free(cd);
    return st;
}
