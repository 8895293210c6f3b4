/* photometry_lexer.c - lines, tokens and locale-independent numbers. */
#include "base/error_report.h"
#include "lights/formats/photometry_lexer.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#define CTRL_Z 0x1A

size_t cdl_photometry_text_length(const char *data, size_t size)
{
    const char *z = memchr(data, CTRL_Z, size);
    return z ? (size_t)(z - data) : size;
}

int cdl_photometry_has_bom(const char *data, size_t size)
{
    return size >= 3 && (unsigned char)data[0] == 0xEF && (unsigned char)data[1] == 0xBB &&
           (unsigned char)data[2] == 0xBF;
}

int cdl_photometry_next_line(const char *data, size_t size, size_t *pos, const char **line, size_t *len)
{
    size_t p = *pos;
    if (p >= size) return 0;
    size_t start = p;
    while (p < size && data[p] != '\n' && data[p] != '\r') ++p;
    *line = data + start;
    *len = p - start;
    if (p < size) p += (data[p] == '\r' && p + 1 < size && data[p + 1] == '\n') ? 2 : 1;
    *pos = p;
    return 1;
}

static int is_blank(unsigned char c) { return c <= ' ' || c == 0x7F; }

void cdl_photometry_trim(const char **s, size_t *len)
{
    const char *p = *s;
    size_t n = *len;
    while (n > 0 && is_blank((unsigned char)*p)) {
        ++p;
        --n;
    }
    while (n > 0 && is_blank((unsigned char)p[n - 1])) --n;
    *s = p;
    *len = n;
}

void cdl_photometry_scanner_init(cdl_photometry_scanner *s, const char *data, size_t size, size_t pos,
                                 unsigned line, int comma_is_separator)
{
    s->data = data;
    s->size = size;
    s->pos = pos;
    s->line = line;
    s->comma_is_separator = comma_is_separator;
    s->tok = NULL;
    s->tok_len = 0;
    s->tok_line = line;
}

static int is_separator(const cdl_photometry_scanner *s, unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == '\0' ||
           (c == ',' && s->comma_is_separator);
}

int cdl_photometry_scan(cdl_photometry_scanner *s, const char **tok, size_t *len, unsigned *line)
{
    const char *d = s->data;
    size_t p = s->pos, n = s->size;
    while (p < n && is_separator(s, (unsigned char)d[p])) {
        if (d[p] == '\n') ++s->line;
        else if (d[p] == '\r' && !(p + 1 < n && d[p + 1] == '\n')) ++s->line; /* lone CR */
        ++p;
    }
    if (p >= n) {
        s->pos = n;
        return 0;
    }
    size_t start = p;
    while (p < n && !is_separator(s, (unsigned char)d[p])) ++p;
    *tok = d + start;
    *len = p - start;
    *line = s->line;
    s->pos = p;
    return 1;
}

/* 10^k for k = 0..22: exactly representable in a double. */
static const double exact_pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

int cdl_photometry_parse_number(const char *t, size_t n, int decimal_comma, double *value)
{
    size_t i = 0;
    int negative = 0;
    if (i < n && (t[i] == '+' || t[i] == '-')) negative = t[i++] == '-';
    uint64_t mantissa = 0;
    int digits = 0, significant = 0;
    long exponent = 0;
    int point = 0;
    for (; i < n; ++i) {
        char c = t[i];
        if (c >= '0' && c <= '9') {
            ++digits;
            if (mantissa == 0 && c == '0') {
                if (point) --exponent; /* leading zeros after the point scale down */
                continue;
            }
            if (significant < 19) {
                mantissa = mantissa * 10u + (uint64_t)(c - '0');
                ++significant;
                if (point) --exponent;
            } else if (!point) {
                ++exponent; /* digits beyond 19 before the point only scale up */
            }
        } else if ((c == '.' || (c == ',' && decimal_comma)) && !point) {
            point = 1;
        } else {
            break;
        }
    }
    if (digits == 0) return 0;
    if (i < n && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        int eneg = 0;
        if (i < n && (t[i] == '+' || t[i] == '-')) eneg = t[i++] == '-';
        long e = 0;
        int edigits = 0;
        for (; i < n && t[i] >= '0' && t[i] <= '9'; ++i, ++edigits)
            if (e < 100000) e = e * 10 + (t[i] - '0');
        if (edigits == 0) return 0;
        exponent += eneg ? -e : e;
    }
    if (i != n) return 0;
    double v;
    if (mantissa == 0) {
        v = 0.0;
    } else if (mantissa < ((uint64_t)1 << 53) && exponent >= -22 && exponent <= 22) {
        /* Both operands exact: one correctly rounded operation (Clinger's fast path). */
        v = exponent >= 0 ? (double)mantissa * exact_pow10[exponent] : (double)mantissa / exact_pow10[-exponent];
    } else if (exponent > 400) {
        v = INFINITY;
    } else if (exponent < -400) {
        v = 0.0;
    } else {
        v = (double)((long double)mantissa * powl(10.0L, (long double)exponent));
    }
    *value = negative ? -v : v;
    return 1;
}

size_t cdl_photometry_count_numbers(const cdl_photometry_scanner *s, int all)
{
    cdl_photometry_scanner c = *s;
    const char *tok;
    size_t len, count = 0;
    unsigned line;
    double v;
    while (cdl_photometry_scan(&c, &tok, &len, &line)) {
        if (cdl_photometry_parse_number(tok, len, !c.comma_is_separator, &v)) ++count;
        else if (!all) break;
    }
    return count;
}

int cdl_photometry_numbers_then_end(const cdl_photometry_scanner *s, size_t *count, unsigned *end_line)
{
    cdl_photometry_scanner c = *s;
    const char *tok;
    size_t len;
    unsigned line;
    double v;
    *count = 0;
    while (cdl_photometry_scan(&c, &tok, &len, &line)) {
        if (!cdl_photometry_parse_number(tok, len, !c.comma_is_separator, &v)) {
            *end_line = line;
            return 0;
        }
        ++*count;
    }
    *end_line = c.line;
    return 1;
}

void cdl_photometry_quote(char *out, size_t out_size, const char *tok, size_t len)
{
    if (out_size < 8) {
        if (out_size) out[0] = '\0';
        return;
    }
    size_t limit = out_size - 6 < 24 ? out_size - 6 : 24, k = 0;
    out[k++] = '\'';
    for (size_t i = 0; i < len && i < limit; ++i) {
        unsigned char c = (unsigned char)tok[i];
        out[k++] = (c >= 0x20 && c < 0x7F) ? (char)c : '?';
    }
    if (len > limit) {
        out[k++] = '.';
        out[k++] = '.';
    }
    out[k++] = '\'';
    out[k] = '\0';
}

cdl_token_kind cdl_photometry_take_number(cdl_photometry_scanner *s, double *value)
{
    if (!cdl_photometry_scan(s, &s->tok, &s->tok_len, &s->tok_line)) {
        s->tok = NULL;
        s->tok_len = 0;
        s->tok_line = s->line;
        return CDL_TOKEN_END;
    }
    if (!cdl_photometry_parse_number(s->tok, s->tok_len, !s->comma_is_separator, value)) return CDL_TOKEN_TEXT;
    return isfinite(*value) ? CDL_TOKEN_NUMBER : CDL_TOKEN_OUT_OF_RANGE;
}

cdl_status cdl_photometry_token_error(const cdl_photometry_scanner *s, cdl_token_kind kind, const char *source,
                                      const char *what, cdl_error *err)
{
    char q[40];
    cdl_photometry_quote(q, sizeof q, s->tok ? s->tok : "", s->tok_len);
    switch (kind) {
    case CDL_TOKEN_END:
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s, found the end of the file (truncated?)", source,
                             s->tok_line, what);
    case CDL_TOKEN_TEXT:
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s (a number), found %s", source, s->tok_line, what,
                             q);
    case CDL_TOKEN_OUT_OF_RANGE:
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s as a finite number, found %s (out of range)",
                             source, s->tok_line, what, q);
    default:
        return CDL_OK;
    }
}

cdl_status cdl_photometry_expect_number(cdl_photometry_scanner *s, const char *source, const char *what,
                                        double *value, unsigned *line, cdl_error *err)
{
    cdl_token_kind k = cdl_photometry_take_number(s, value);
    if (line) *line = s->tok_line;
    return k == CDL_TOKEN_NUMBER ? CDL_OK : cdl_photometry_token_error(s, k, source, what, err);
}

cdl_status cdl_photometry_expect_integer(cdl_photometry_scanner *s, const char *source, const char *what, long lo,
                                         long hi, long *value, unsigned *line, cdl_error *err)
{
    double v;
    unsigned at;
    cdl_status st = cdl_photometry_expect_number(s, source, what, &v, &at, err);
    if (line) *line = at;
    if (st != CDL_OK) return st;
    if (v != floor(v) || v < (double)lo || v > (double)hi)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s (a whole number from %ld to %ld), found %g",
                             source, at, what, lo, hi, v);
    *value = (long)v;
    return CDL_OK;
}
