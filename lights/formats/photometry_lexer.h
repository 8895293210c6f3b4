/* photometry_lexer.h - bytes to lines, tokens and numbers for the IES and
 * EULUMDAT readers.
 *
 * Text is treated as bytes (Latin-1 or anything else passes through); line
 * ends may be CR LF, LF or a lone CR, mixed; a Ctrl-Z (0x1A) ends the data,
 * as on MS-DOS. Numbers are parsed by our own grammar, independent of the C
 * locale:  [+-] digits [. digits] [(e|E) [+-] digits]  with at least one
 * digit before the exponent, e.g. "-.09", "5000.", "1.0E+03". EULUMDAT
 * readers may also accept a decimal comma ("12,5").
 */
#ifndef CANDELA_LIGHTS_FORMATS_PHOTOMETRY_LEXER_H
#define CANDELA_LIGHTS_FORMATS_PHOTOMETRY_LEXER_H

#include <stddef.h>

#include "base/error.h"

/* The data up to (not including) the first Ctrl-Z. */
size_t cdl_photometry_text_length(const char *data, size_t size);

/* 1 when the data start with a UTF-8 byte-order mark (EF BB BF). */
int cdl_photometry_has_bom(const char *data, size_t size);

/* Next line starting at *pos (< size): sets its span (without the line
 * end) and advances *pos past the line end. Returns 0 at the end of data. */
int cdl_photometry_next_line(const char *data, size_t size, size_t *pos, const char **line, size_t *len);

/* Span without leading and trailing blanks (space, tab, other control bytes). */
void cdl_photometry_trim(const char **s, size_t *len);

/* Walks whitespace-separated tokens and counts lines (1-based). */
typedef struct cdl_photometry_scanner {
    const char *data;
    size_t pos, size;
    unsigned line;
    int comma_is_separator; /* IES: ',' separates numbers; EULUMDAT: it may be a decimal comma */
    const char *tok;        /* the last token taken, for messages */
    size_t tok_len;
    unsigned tok_line;
} cdl_photometry_scanner;

void cdl_photometry_scanner_init(cdl_photometry_scanner *s, const char *data, size_t size, size_t pos,
                                 unsigned line, int comma_is_separator);

/* Next token; returns 0 at the end of the data. *line is the token's line. */
int cdl_photometry_scan(cdl_photometry_scanner *s, const char **tok, size_t *len, unsigned *line);

/* Parse a whole token as a number. Returns 1 on success (the value may be
 * +-inf when it overflows), 0 when the token is not a number. */
int cdl_photometry_parse_number(const char *tok, size_t len, int decimal_comma, double *value);

/* How many of the remaining tokens are numbers: `all` counts every number
 * to the end (skipping text), otherwise counting stops at the first token
 * that is not a number. The scanner is not moved. */
size_t cdl_photometry_count_numbers(const cdl_photometry_scanner *s, int all);

/* Counts the numbers ahead (stopping at the first token that is not one)
 * and says whether the data ends right after them (1) or text follows (0);
 * *end_line is the line where the count stopped. The scanner is not moved. */
int cdl_photometry_numbers_then_end(const cdl_photometry_scanner *s, size_t *count, unsigned *end_line);

/* Quote a token for a message: at most 24 bytes, non-printable bytes as '?'. */
void cdl_photometry_quote(char *out, size_t out_size, const char *tok, size_t len);

typedef enum cdl_token_kind {
    CDL_TOKEN_NUMBER = 0,   /* a finite number */
    CDL_TOKEN_END,          /* no more data */
    CDL_TOKEN_TEXT,         /* a token that is not a number */
    CDL_TOKEN_OUT_OF_RANGE  /* a number too large for a double */
} cdl_token_kind;

/* The fast path for tables: the next token as a number, no message. The
 * token stays in s->tok for cdl_photometry_token_error. */
cdl_token_kind cdl_photometry_take_number(cdl_photometry_scanner *s, double *value);

/* The message for a failed take: "SOURCE:LINE: expected WHAT, found ...". */
cdl_status cdl_photometry_token_error(const cdl_photometry_scanner *s, cdl_token_kind kind, const char *source,
                                      const char *what, cdl_error *err);

/* The next token as a number. On failure the message reads
 * "SOURCE:LINE: expected WHAT, found 'TOKEN'" (or "found the end of the
 * file"). Infinite values (overflow) are refused. *line gets the token's line. */
cdl_status cdl_photometry_expect_number(cdl_photometry_scanner *s, const char *source, const char *what,
                                        double *value, unsigned *line, cdl_error *err);

/* Same for a whole number within [lo, hi] (LM-63-1986 writes integers as
 * "3.0", which is accepted). */
cdl_status cdl_photometry_expect_integer(cdl_photometry_scanner *s, const char *source, const char *what, long lo,
                                         long hi, long *value, unsigned *line, cdl_error *err);

#endif
