/* mesh_file.c - small readers for OBJ, OFF and PLY triangle meshes.
 *
 * The whole file is read into memory and parsed line by line (binary PLY:
 * value by value with explicit byte order), so every message can say
 * where the problem is. Formats:
 *   OBJ: Wavefront "Object Files (.obj)", Appendix B1 of the Advanced
 *        Visualizer manual (polygonal subset).
 *   OFF: Geomview "OFF" file format documentation.
 *   PLY: G. Turk, "The PLY Polygon File Format" (1994).
 */
#include "solver/scene/mesh_file.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/file_bytes.h"
#include "solver/scene/scene_file.h"

/* ---- growing arrays ------------------------------------------------------ */

typedef struct mesh_builder {
    cdl_mesh_data mesh;
    size_t vertex_capacity, triangle_capacity;
    uint32_t *face;             /* indices of the face being read */
    size_t face_count, face_capacity;
} mesh_builder;

static int push_vertex(mesh_builder *b, double x, double y, double z)
{
    if (b->mesh.vertex_count == b->vertex_capacity) {
        size_t cap = b->vertex_capacity ? 2 * b->vertex_capacity : 64;
        double *v = realloc(b->mesh.vertices, cap * 3 * sizeof *v);
        if (!v) return 0;
        b->mesh.vertices = v;
        b->vertex_capacity = cap;
    }
    double *v = &b->mesh.vertices[3 * b->mesh.vertex_count++];
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return 1;
}

static int push_face_index(mesh_builder *b, uint32_t index)
{
    if (b->face_count == b->face_capacity) {
        size_t cap = b->face_capacity ? 2 * b->face_capacity : 16;
        uint32_t *f = realloc(b->face, cap * sizeof *f);
        if (!f) return 0;
        b->face = f;
        b->face_capacity = cap;
    }
    b->face[b->face_count++] = index;
    return 1;
}

/* Fan-triangulate the current face (v0, vi, vi+1) and start a new one. */
static int emit_face(mesh_builder *b)
{
    size_t n = b->face_count;
    b->face_count = 0;
    if (b->mesh.triangle_count + (n - 2) > b->triangle_capacity) {
        size_t cap = b->triangle_capacity ? 2 * b->triangle_capacity : 64;
        while (cap < b->mesh.triangle_count + (n - 2)) cap *= 2;
        uint32_t *t = realloc(b->mesh.triangles, cap * 3 * sizeof *t);
        if (!t) return 0;
        b->mesh.triangles = t;
        b->triangle_capacity = cap;
    }
    for (size_t i = 1; i + 1 < n; ++i) {
        uint32_t *t = &b->mesh.triangles[3 * b->mesh.triangle_count++];
        t[0] = b->face[0];
        t[1] = b->face[i];
        t[2] = b->face[i + 1];
    }
    return 1;
}

static void builder_free(mesh_builder *b)
{
    cdl_mesh_data_release(&b->mesh);
    free(b->face);
    b->face = NULL;
}

/* Drop triangles of zero area and hand the mesh over. */
static cdl_status builder_finish(mesh_builder *b, const char *name, cdl_mesh_data *out, cdl_error *err)
{
    size_t kept = 0;
    for (size_t t = 0; t < b->mesh.triangle_count; ++t) {
        const uint32_t *i = &b->mesh.triangles[3 * t];
        const double *p = &b->mesh.vertices[3 * i[0]], *q = &b->mesh.vertices[3 * i[1]], *r = &b->mesh.vertices[3 * i[2]];
        double e1[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, e2[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
        if (cx == 0.0 && cy == 0.0 && cz == 0.0) continue;
        memmove(&b->mesh.triangles[3 * kept], i, 3 * sizeof *i);
        ++kept;
    }
    b->mesh.triangle_count = kept;
    if (kept == 0) {
        builder_free(b);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected at least one triangle of non-zero area, found none",
                             name);
    }
    free(b->face);
    b->face = NULL;
    *out = b->mesh;
    memset(&b->mesh, 0, sizeof b->mesh);
    return CDL_OK;
}

/* ---- lines, tokens, numbers --------------------------------------------- */

typedef struct text_cursor {
    const char *p, *end;
    size_t line;            /* number of the line last returned, 1-based */
} text_cursor;

/* Next line without its terminator (\n or \r\n); 0 at the end of the data. */
static int next_line(text_cursor *c, const char **start, const char **stop)
{
    if (c->p >= c->end) return 0;
    const char *s = c->p, *e = memchr(s, '\n', (size_t)(c->end - s));
    c->p = e ? e + 1 : c->end;
    if (!e) e = c->end;
    if (e > s && e[-1] == '\r') --e;
    *start = s;
    *stop = e;
    ++c->line;
    return 1;
}

/* Cut a line at a '#' comment. */
static const char *strip_comment(const char *s, const char *e)
{
    if (e <= s) return e;
    const char *hash = memchr(s, '#', (size_t)(e - s));
    return hash ? hash : e;
}

static int next_token(const char **p, const char *end, const char **tok, size_t *len)
{
    const char *s = *p;
    while (s < end && isspace((unsigned char)*s)) ++s;
    if (s >= end) {
        *p = s;
        return 0;
    }
    const char *t = s;
    while (t < end && !isspace((unsigned char)*t)) ++t;
    *tok = s;
    *len = (size_t)(t - s);
    *p = t;
    return 1;
}

static int token_is(const char *tok, size_t len, const char *word)
{
    return strlen(word) == len && memcmp(tok, word, len) == 0;
}

/* "\"abc\"" or "the end of the line" for messages. */
static void quote_token(const char *tok, size_t len, char *out, size_t size)
{
    if (!tok) {
        snprintf(out, size, "the end of the line");
        return;
    }
    int shown = len > 40 ? 40 : (int)len;
    snprintf(out, size, "\"%.*s\"%s", shown, tok, len > 40 ? "..." : "");
}

static int parse_double(const char *tok, size_t len, double *out)
{
    char buf[80];
    if (len == 0 || len >= sizeof buf) return 0;
    memcpy(buf, tok, len);
    buf[len] = '\0';
    char *endp;
    errno = 0;
    double v = strtod(buf, &endp);
    if (endp != buf + len || !isfinite(v)) return 0;
    *out = v;
    return 1;
}

static int parse_long(const char *tok, size_t len, long long *out)
{
    char buf[32];
    if (len == 0 || len >= sizeof buf) return 0;
    memcpy(buf, tok, len);
    buf[len] = '\0';
    char *endp;
    errno = 0;
    long long v = strtoll(buf, &endp, 10);
    if (endp != buf + len || errno == ERANGE) return 0;
    *out = v;
    return 1;
}

static cdl_status fail_at(cdl_error *err, const char *name, size_t line, const char *expected, const char *fmt, ...)
    CDL_PRINTF(5, 6);
static cdl_status fail_at(cdl_error *err, const char *name, size_t line, const char *expected, const char *fmt, ...)
{
    char found[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(found, sizeof found, fmt, ap);
    va_end(ap);
    return cdl_error_set(err, CDL_ERR_INPUT, "%s:%zu: expected %s, found %s", name, line, expected, found);
}

static cdl_status fail_token(cdl_error *err, const char *name, size_t line, const char *expected, const char *tok,
                             size_t len)
{
    char q[64];
    quote_token(tok, len, q, sizeof q);
    return fail_at(err, name, line, expected, "%s", q);
}

/* ---- OBJ ------------------------------------------------------------------ */

static const char *const obj_ignored[] = {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p", NULL};

/* One "f" entry: "i", "i/t", "i//n" or "i/t/n"; the vertex index is the part
 * before the first slash. */
static int obj_vertex_ref(const char *tok, size_t len, long long *index)
{
    size_t k = 0;
    while (k < len && tok[k] != '/') ++k;
    if (!parse_long(tok, k, index)) return 0;
    for (size_t i = k; i < len; ++i)
        if (tok[i] != '/' && tok[i] != '-' && !isdigit((unsigned char)tok[i])) return 0;
    return 1;
}

static cdl_status parse_obj(const char *data, size_t size, const char *name, cdl_mesh_data *out, cdl_error *err)
{
    mesh_builder b = {0};
    text_cursor c = {data, data + size, 0};
    const char *s, *e, *tok;
    size_t len;
    /* Positive indices may point forward; the largest is checked at the end. */
    long long max_index = 0;
    size_t max_index_line = 0;
    while (next_line(&c, &s, &e)) {
        e = strip_comment(s, e);
        const char *p = s;
        if (!next_token(&p, e, &tok, &len)) continue;
        if (token_is(tok, len, "v")) {
            double x[7];
            int k = 0;
            const char *t2;
            size_t l2;
            while (next_token(&p, e, &t2, &l2)) {
                if (k == 7 || !parse_double(t2, l2, &x[k]))
                    return builder_free(&b), fail_token(err, name, c.line, "a finite number", t2, l2);
                ++k;
            }
            if (k != 3 && k != 4 && k != 6)
                return builder_free(&b), fail_at(err, name, c.line, "a vertex \"v x y z\" (optionally w, or r g b)",
                                                  "%d numbers", k);
            if (k == 4) {
                if (x[3] == 0.0) return builder_free(&b), fail_at(err, name, c.line, "a non-zero w", "w = 0");
                for (int i = 0; i < 3; ++i) x[i] /= x[3];
            }
            if (b.mesh.vertex_count >= UINT32_MAX)
                return builder_free(&b), fail_at(err, name, c.line, "at most 4294967295 vertices", "more");
            if (!push_vertex(&b, x[0], x[1], x[2])) return builder_free(&b), cdl_error_out_of_memory(err);
        } else if (token_is(tok, len, "f") || token_is(tok, len, "fo")) {
            const char *t2;
            size_t l2;
            while (next_token(&p, e, &t2, &l2)) {
                long long idx;
                if (!obj_vertex_ref(t2, l2, &idx) || idx == 0)
                    return builder_free(&b),
                           fail_token(err, name, c.line, "a vertex reference i, i/t, i//n or i/t/n with i != 0", t2, l2);
                if (idx < 0) {
                    idx += (long long)b.mesh.vertex_count;
                    if (idx < 0)
                        return builder_free(&b), fail_token(err, name, c.line,
                                                            "a relative index within the vertices read so far", t2, l2);
                } else {
                    if (idx > max_index) {
                        max_index = idx;
                        max_index_line = c.line;
                    }
                    if (idx > (long long)UINT32_MAX)
                        return builder_free(&b), fail_token(err, name, c.line, "an index below 2^32", t2, l2);
                    idx -= 1;
                }
                if (!push_face_index(&b, (uint32_t)idx)) return builder_free(&b), cdl_error_out_of_memory(err);
            }
            if (b.face_count < 3)
                return builder_free(&b), fail_at(err, name, c.line, "a face of at least 3 vertices", "%zu",
                                                  b.face_count);
            if (!emit_face(&b)) return builder_free(&b), cdl_error_out_of_memory(err);
        } else {
            int known = 0;
            for (size_t i = 0; obj_ignored[i]; ++i) known |= token_is(tok, len, obj_ignored[i]);
            if (!known)
                return builder_free(&b),
                       fail_token(err, name, c.line,
                                  "a statement of polygonal geometry (v, f, vt, vn, vp, g, o, s, usemtl, mtllib, l, p)",
                                  tok, len);
        }
    }
    if (max_index > (long long)b.mesh.vertex_count) {
        /* The message first: freeing the builder zeroes its vertex count. */
        cdl_status st = fail_at(err, name, max_index_line, "vertex indices up to the number of vertices",
                                "index %lld of %zu vertices", max_index, b.mesh.vertex_count);
        builder_free(&b);
        return st;
    }
    return builder_finish(&b, name, out, err);
}

/* ---- OFF ------------------------------------------------------------------ */

/* Next line with content (comments removed); 0 at the end. */
static int next_content_line(text_cursor *c, const char **s, const char **e)
{
    while (next_line(c, s, e)) {
        *e = strip_comment(*s, *e);
        const char *p = *s, *tok;
        size_t len;
        if (next_token(&p, *e, &tok, &len)) return 1;
    }
    return 0;
}

static cdl_status parse_off(const char *data, size_t size, const char *name, cdl_mesh_data *out, cdl_error *err)
{
    mesh_builder b = {0};
    text_cursor c = {data, data + size, 0};
    const char *s, *e, *p, *tok = NULL;
    size_t len = 0;
    if (!next_content_line(&c, &s, &e))
        return fail_at(err, name, c.line ? c.line : 1, "the header \"OFF\"", "an empty file");
    p = s;
    next_token(&p, e, &tok, &len);
    if (!token_is(tok, len, "OFF") && !token_is(tok, len, "COFF") && !token_is(tok, len, "NOFF") &&
        !token_is(tok, len, "CNOFF"))
        return fail_token(err, name, c.line, "the header \"OFF\" (or COFF, NOFF, CNOFF)", tok, len);
    /* Counts follow on the header line or on the next line with content. */
    if (!next_token(&p, e, &tok, &len)) {
        if (!next_content_line(&c, &s, &e)) return fail_at(err, name, c.line, "the counts \"V F E\"", "the end of the file");
        p = s;
        next_token(&p, e, &tok, &len);
    }
    long long counts[2];
    for (int i = 0; i < 2; ++i) {
        if (i == 1 && !next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
        if (!tok || !parse_long(tok, len, &counts[i]) || counts[i] < 0 || counts[i] > (long long)UINT32_MAX)
            return fail_token(err, name, c.line, i == 0 ? "a vertex count V >= 0" : "a face count F >= 0", tok, len);
    }
    for (long long v = 0; v < counts[0]; ++v) {
        if (!next_content_line(&c, &s, &e))
            return builder_free(&b), fail_at(err, name, c.line, "a vertex line \"x y z\"", "the end of the file (%lld of %lld vertices)", v, counts[0]);
        double x[3];
        p = s;
        for (int k = 0; k < 3; ++k) {
            if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            if (!tok || !parse_double(tok, len, &x[k]))
                return builder_free(&b), fail_token(err, name, c.line, "a finite coordinate", tok, len);
        }
        if (!push_vertex(&b, x[0], x[1], x[2])) return builder_free(&b), cdl_error_out_of_memory(err);
    }
    for (long long f = 0; f < counts[1]; ++f) {
        if (!next_content_line(&c, &s, &e))
            return builder_free(&b), fail_at(err, name, c.line, "a face line \"n i0 ... i(n-1)\"", "the end of the file (%lld of %lld faces)", f, counts[1]);
        p = s;
        long long n, idx;
        next_token(&p, e, &tok, &len);
        if (!parse_long(tok, len, &n) || n < 3)
            return builder_free(&b), fail_token(err, name, c.line, "a vertex count n >= 3 for the face", tok, len);
        for (long long k = 0; k < n; ++k) {
            if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            if (!tok || !parse_long(tok, len, &idx) || idx < 0 || idx >= counts[0]) {
                char expected[64];
                snprintf(expected, sizeof expected, "a vertex index in [0, %lld]", counts[0] - 1);
                return builder_free(&b), fail_token(err, name, c.line, expected, tok, len);
            }
            if (!push_face_index(&b, (uint32_t)idx)) return builder_free(&b), cdl_error_out_of_memory(err);
        }
        if (!emit_face(&b)) return builder_free(&b), cdl_error_out_of_memory(err);
    }
    if (next_content_line(&c, &s, &e)) {
        p = s;
        next_token(&p, e, &tok, &len);
        return builder_free(&b), fail_token(err, name, c.line, "the end of the file after the faces", tok, len);
    }
    return builder_finish(&b, name, out, err);
}

/* ---- PLY ------------------------------------------------------------------ */

typedef enum ply_kind { PLY_SINT, PLY_UINT, PLY_FLOAT } ply_kind;

typedef struct ply_type {
    const char *name;
    int size;
    ply_kind kind;
} ply_type;

static const ply_type ply_types[] = {
    {"char", 1, PLY_SINT},   {"int8", 1, PLY_SINT},    {"uchar", 1, PLY_UINT},   {"uint8", 1, PLY_UINT},
    {"short", 2, PLY_SINT},  {"int16", 2, PLY_SINT},   {"ushort", 2, PLY_UINT},  {"uint16", 2, PLY_UINT},
    {"int", 4, PLY_SINT},    {"int32", 4, PLY_SINT},   {"uint", 4, PLY_UINT},    {"uint32", 4, PLY_UINT},
    {"float", 4, PLY_FLOAT}, {"float32", 4, PLY_FLOAT}, {"double", 8, PLY_FLOAT}, {"float64", 8, PLY_FLOAT},
};

enum { PLY_ROLE_NONE, PLY_ROLE_X, PLY_ROLE_Y, PLY_ROLE_Z, PLY_ROLE_INDICES };

typedef struct ply_property {
    const ply_type *type;        /* scalar type, or the list's item type */
    const ply_type *count_type;  /* NULL for scalars */
    int role;
} ply_property;

typedef struct ply_element {
    char name[32];
    size_t count;
    ply_property *props;
    size_t prop_count;
} ply_element;

typedef enum ply_format { PLY_ASCII, PLY_LITTLE, PLY_BIG } ply_format;

typedef struct ply_reader {
    ply_format format;
    const char *name;
    cdl_error *err;
    /* binary */
    const unsigned char *p, *end;
    /* ascii: the current line's remaining text */
    text_cursor text;
    const char *lp, *le;
    /* for messages */
    const char *element;
    size_t element_index;
} ply_reader;

static const ply_type *ply_find_type(const char *tok, size_t len)
{
    for (size_t i = 0; i < sizeof ply_types / sizeof ply_types[0]; ++i)
        if (token_is(tok, len, ply_types[i].name)) return &ply_types[i];
    return NULL;
}

static cdl_status ply_fail(ply_reader *r, const char *expected, const char *fmt, ...) CDL_PRINTF(3, 4);
static cdl_status ply_fail(ply_reader *r, const char *expected, const char *fmt, ...)
{
    char found[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(found, sizeof found, fmt, ap);
    va_end(ap);
    if (r->format == PLY_ASCII)
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%zu: %s %zu: expected %s, found %s", r->name, r->text.line,
                             r->element, r->element_index, expected, found);
    return cdl_error_set(r->err, CDL_ERR_INPUT, "%s: %s %zu: expected %s, found %s", r->name, r->element,
                         r->element_index, expected, found);
}

/* One value of type t, as a double (integers of up to 32 bits are exact). */
static int ply_read_value(ply_reader *r, const ply_type *t, double *out)
{
    if (r->format == PLY_ASCII) {
        const char *tok;
        size_t len;
        if (!next_token(&r->lp, r->le, &tok, &len)) {
            ply_fail(r, "another value", "the end of the line");
            return 0;
        }
        if (!parse_double(tok, len, out) || (t->kind != PLY_FLOAT && *out != floor(*out))) {
            char q[64];
            quote_token(tok, len, q, sizeof q);
            ply_fail(r, t->kind == PLY_FLOAT ? "a finite number" : "an integer", "%s", q);
            return 0;
        }
        return 1;
    }
    if ((size_t)(r->end - r->p) < (size_t)t->size) {
        ply_fail(r, "more data", "the end of the file");
        return 0;
    }
    uint64_t bits = 0;
    for (int i = 0; i < t->size; ++i) {
        int shift = r->format == PLY_LITTLE ? 8 * i : 8 * (t->size - 1 - i);
        bits |= (uint64_t)r->p[i] << shift;
    }
    r->p += t->size;
    if (t->kind == PLY_FLOAT) {
        if (t->size == 4) {
            uint32_t b32 = (uint32_t)bits;
            float f;
            memcpy(&f, &b32, sizeof f);
            *out = f;
        } else {
            memcpy(out, &bits, sizeof *out);
        }
        if (!isfinite(*out)) {
            ply_fail(r, "a finite number", "%g", *out);
            return 0;
        }
    } else if (t->kind == PLY_SINT) {
        int bitsz = 8 * t->size;
        int64_t v = (int64_t)(bits << (64 - bitsz)) >> (64 - bitsz);
        *out = (double)v;
    } else {
        *out = (double)bits;
    }
    return 1;
}

static cdl_status ply_parse_header(text_cursor *c, const char *name, ply_format *format, ply_element **elements,
                                   size_t *element_count, cdl_error *err)
{
    const char *s, *e, *p, *tok;
    size_t len;
    if (!next_line(c, &s, &e) || !token_is(s, (size_t)(e - s), "ply"))
        return fail_at(err, name, 1, "the magic line \"ply\"", "something else");
    int have_format = 0;
    for (;;) {
        if (!next_line(c, &s, &e)) return fail_at(err, name, c->line, "\"end_header\"", "the end of the file");
        p = s;
        if (!next_token(&p, e, &tok, &len)) continue;
        if (token_is(tok, len, "end_header")) break;
        if (token_is(tok, len, "comment") || token_is(tok, len, "obj_info")) continue;
        if (token_is(tok, len, "format")) {
            if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            if (tok && token_is(tok, len, "ascii")) *format = PLY_ASCII;
            else if (tok && token_is(tok, len, "binary_little_endian")) *format = PLY_LITTLE;
            else if (tok && token_is(tok, len, "binary_big_endian")) *format = PLY_BIG;
            else return fail_token(err, name, c->line, "ascii, binary_little_endian or binary_big_endian", tok, len);
            if (!next_token(&p, e, &tok, &len) || !token_is(tok, len, "1.0"))
                return fail_at(err, name, c->line, "format version 1.0", "another version");
            have_format = 1;
        } else if (token_is(tok, len, "element")) {
            ply_element *grown = realloc(*elements, (*element_count + 1) * sizeof *grown);
            if (!grown) return cdl_error_out_of_memory(err);
            *elements = grown;
            ply_element *el = &grown[(*element_count)++];
            memset(el, 0, sizeof *el);
            long long count;
            if (!next_token(&p, e, &tok, &len) || len >= sizeof el->name)
                return fail_at(err, name, c->line, "an element name (under 32 characters)", "none");
            memcpy(el->name, tok, len);
            if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            if (!tok || !parse_long(tok, len, &count) || count < 0)
                return fail_token(err, name, c->line, "an element count >= 0", tok, len);
            el->count = (size_t)count;
        } else if (token_is(tok, len, "property")) {
            if (*element_count == 0) return fail_at(err, name, c->line, "an element before its properties", "a property");
            ply_element *el = &(*elements)[*element_count - 1];
            ply_property prop = {NULL, NULL, PLY_ROLE_NONE};
            if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            if (tok && token_is(tok, len, "list")) {
                if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
                prop.count_type = tok ? ply_find_type(tok, len) : NULL;
                if (!prop.count_type || prop.count_type->kind == PLY_FLOAT)
                    return fail_token(err, name, c->line, "an integer type for the list count", tok, len);
                if (!next_token(&p, e, &tok, &len)) tok = NULL, len = 0;
            }
            prop.type = tok ? ply_find_type(tok, len) : NULL;
            if (!prop.type)
                return fail_token(err, name, c->line, "a PLY type (char, uchar, short, ushort, int, uint, float, double)",
                                  tok, len);
            if (!next_token(&p, e, &tok, &len)) return fail_at(err, name, c->line, "a property name", "none");
            int is_vertex = strcmp(el->name, "vertex") == 0, is_face = strcmp(el->name, "face") == 0;
            if (is_vertex && !prop.count_type) {
                if (token_is(tok, len, "x")) prop.role = PLY_ROLE_X;
                if (token_is(tok, len, "y")) prop.role = PLY_ROLE_Y;
                if (token_is(tok, len, "z")) prop.role = PLY_ROLE_Z;
            }
            if (is_face && prop.count_type && (token_is(tok, len, "vertex_indices") || token_is(tok, len, "vertex_index"))) {
                if (prop.type->kind == PLY_FLOAT)
                    return fail_at(err, name, c->line, "an integer type for vertex indices", "a floating-point type");
                prop.role = PLY_ROLE_INDICES;
            }
            ply_property *grown = realloc(el->props, (el->prop_count + 1) * sizeof *grown);
            if (!grown) return cdl_error_out_of_memory(err);
            el->props = grown;
            el->props[el->prop_count++] = prop;
        } else {
            return fail_token(err, name, c->line, "a header line (format, element, property, comment, end_header)", tok,
                              len);
        }
    }
    if (!have_format) return fail_at(err, name, c->line, "a \"format\" line in the header", "none");
    return CDL_OK;
}

static cdl_status ply_check_roles(const ply_element *els, size_t n, const char *name, size_t *vertex_count,
                                  cdl_error *err)
{
    int have_vertex = 0, have_face = 0;
    for (size_t i = 0; i < n; ++i) {
        int roles = 0;
        for (size_t k = 0; k < els[i].prop_count; ++k) roles |= 1 << els[i].props[k].role;
        if (strcmp(els[i].name, "vertex") == 0) {
            int need = (1 << PLY_ROLE_X) | (1 << PLY_ROLE_Y) | (1 << PLY_ROLE_Z);
            if ((roles & need) != need)
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: header: expected scalar properties x, y and z in element vertex, found %s",
                                     name, "some missing");
            if (els[i].count > UINT32_MAX)
                return cdl_error_set(err, CDL_ERR_INPUT, "%s: header: expected at most 4294967295 vertices, found %zu",
                                     name, els[i].count);
            *vertex_count = els[i].count;
            have_vertex = 1;
        }
        if (strcmp(els[i].name, "face") == 0) {
            if (!(roles & (1 << PLY_ROLE_INDICES)))
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: header: expected a list property vertex_indices in element face, found none",
                                     name);
            have_face = 1;
        }
    }
    if (!have_vertex || !have_face)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: header: expected elements vertex and face, found %s", name,
                             have_vertex ? "no face element" : "no vertex element");
    return CDL_OK;
}

/* Read one instance of an element, storing vertex coordinates or face indices. */
static cdl_status ply_read_instance(ply_reader *r, const ply_element *el, size_t vertex_count, mesh_builder *b)
{
    double xyz[3] = {0, 0, 0};
    int is_vertex = strcmp(el->name, "vertex") == 0;
    for (size_t k = 0; k < el->prop_count; ++k) {
        const ply_property *prop = &el->props[k];
        double v;
        if (!prop->count_type) {
            if (!ply_read_value(r, prop->type, &v)) return CDL_ERR_INPUT;
            if (prop->role >= PLY_ROLE_X && prop->role <= PLY_ROLE_Z) xyz[prop->role - PLY_ROLE_X] = v;
            continue;
        }
        double count;
        if (!ply_read_value(r, prop->count_type, &count)) return CDL_ERR_INPUT;
        if (count < 0) return ply_fail(r, "a list length >= 0", "%.0f", count);
        if (r->format != PLY_ASCII && count * prop->type->size > (double)(r->end - r->p))
            return ply_fail(r, "a list that fits in the file", "a list of %.0f items", count);
        if (prop->role == PLY_ROLE_INDICES && count < 3)
            return ply_fail(r, "a face of at least 3 vertices", "%.0f", count);
        for (double i = 0; i < count; ++i) {
            if (!ply_read_value(r, prop->type, &v)) return CDL_ERR_INPUT;
            if (prop->role != PLY_ROLE_INDICES) continue;
            if (v < 0 || v >= (double)vertex_count) {
                char expected[64];
                snprintf(expected, sizeof expected, "vertex indices in [0, %zu]", vertex_count - 1);
                return ply_fail(r, expected, "%.0f", v);
            }
            if (!push_face_index(b, (uint32_t)v)) return cdl_error_out_of_memory(r->err);
        }
        if (prop->role == PLY_ROLE_INDICES && !emit_face(b)) return cdl_error_out_of_memory(r->err);
    }
    if (is_vertex && !push_vertex(b, xyz[0], xyz[1], xyz[2])) return cdl_error_out_of_memory(r->err);
    if (r->format == PLY_ASCII) {
        const char *tok;
        size_t len;
        if (next_token(&r->lp, r->le, &tok, &len)) {
            char q[64];
            quote_token(tok, len, q, sizeof q);
            return ply_fail(r, "the end of the line", "%s", q);
        }
    }
    return CDL_OK;
}

static cdl_status parse_ply(const char *data, size_t size, const char *name, cdl_mesh_data *out, cdl_error *err)
{
    text_cursor c = {data, data + size, 0};
    ply_format format = PLY_ASCII;
    ply_element *els = NULL;
    size_t n = 0, vertex_count = 0;
    mesh_builder b = {0};
    cdl_status st = ply_parse_header(&c, name, &format, &els, &n, err);
    if (st == CDL_OK) st = ply_check_roles(els, n, name, &vertex_count, err);
    ply_reader r = {format, name, err, (const unsigned char *)c.p, (const unsigned char *)c.end, c, NULL, NULL, "", 0};
    for (size_t i = 0; i < n && st == CDL_OK; ++i) {
        r.element = els[i].name;
        for (size_t k = 0; k < els[i].count && st == CDL_OK; ++k) {
            r.element_index = k;
            if (format == PLY_ASCII) {
                const char *s, *e, *tok;
                size_t len;
                int found = 0;
                while (!found && next_line(&r.text, &s, &e)) {
                    const char *p = s;
                    found = next_token(&p, e, &tok, &len);
                }
                if (!found) {
                    st = ply_fail(&r, "another line of data", "the end of the file");
                    break;
                }
                r.lp = s;
                r.le = e;
            }
            st = ply_read_instance(&r, &els[i], vertex_count, &b);
        }
    }
    for (size_t i = 0; i < n; ++i) free(els[i].props);
    free(els);
    if (st != CDL_OK) {
        builder_free(&b);
        return st;
    }
    return builder_finish(&b, name, out, err);
}

/* ---- entry points ---------------------------------------------------------- */

int cdl_mesh_file_format_from_name(const char *path, cdl_mesh_format *format)
{
    const char *dot = strrchr(path, '.');
    if (!dot || strchr(dot, '/')) return 0;
    char ext[8] = {0};
    for (size_t i = 0; i < sizeof ext - 1 && dot[1 + i]; ++i) ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    if (strlen(dot + 1) != strlen(ext)) return 0;
    if (strcmp(ext, "obj") == 0) *format = CDL_MESH_OBJ;
    else if (strcmp(ext, "off") == 0) *format = CDL_MESH_OFF;
    else if (strcmp(ext, "ply") == 0) *format = CDL_MESH_PLY;
    else return 0;
    return 1;
}

cdl_status cdl_mesh_file_parse(const char *data, size_t size, cdl_mesh_format format, const char *name,
                               cdl_mesh_data *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    switch (format) {
    case CDL_MESH_OBJ: return parse_obj(data, size, name, out, err);
    case CDL_MESH_OFF: return parse_off(data, size, name, out, err);
    case CDL_MESH_PLY: return parse_ply(data, size, name, out, err);
    }
    return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: unknown mesh format", name);
}

cdl_status cdl_mesh_file_read(const char *path, cdl_mesh_data *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_mesh_format format;
    if (!cdl_mesh_file_format_from_name(path, &format))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a mesh file ending in .obj, .off or .ply, found %s",
                             path, strrchr(path, '.') ? strrchr(path, '.') : "no extension");
    char *data = NULL;
    size_t size = 0;
    cdl_status read = cdl_file_read_bytes(path, "mesh file", CDL_SCENE_MAX_FILE_BYTES, &data, &size, err);
    if (read != CDL_OK) return read;
    cdl_status st = cdl_mesh_file_parse(data, size, format, path, out, err);
    free(data);
    return st;
}

void cdl_mesh_data_release(cdl_mesh_data *mesh)
{
    if (!mesh) return;
    free(mesh->vertices);
    free(mesh->triangles);
    memset(mesh, 0, sizeof *mesh);
}
