/* apidoc.c - libcandela's public headers read as an API.
 *
 * The public headers are those candela/candela.h includes (ROOT is the
 * folder they are relative to: the source tree, or include/candela of an
 * installed prefix). From them this program makes:
 *
 *   cdl_apidoc symbols --root ROOT UMBRELLA [--version-script OUT]
 *       the functions the headers declare (not the static inline ones),
 *       one a line, or as the linker version script of libcandela.so;
 *   cdl_apidoc html --root ROOT --out DIR UMBRELLA
 *       the API reference: DIR/index.html (the umbrella's text, the list of
 *       headers, an index of every name) and a page per header, each
 *       declaration with the comment written above it, names linked;
 *   cdl_apidoc check --root ROOT UMBRELLA
 *       every declared function has a comment, and every header's opening
 *       comment speaks of thread safety: exit 1 naming what lacks one;
 *   cdl_apidoc types --root ROOT UMBRELLA < PREPROCESSED
 *       from the preprocessor's output of the umbrella (cc -E), every type
 *       the public headers define, macros expanded, one a line, spacing
 *       normalised and sorted: what the ABI fingerprint is taken of.
 *
 * The reader knows the shapes these headers use, not all of C: comments,
 * preprocessor lines, declarations ending in ';', static inline functions
 * (body skipped), typedefs, struct and enum definitions, extern "C"
 * blocks, and top-level macro invocations that define types
 * (CDL_DEFINE_QUANTITY in units.h). A comment directly above a
 * declaration (no blank line between) documents it; a comment followed by
 * a blank line is a note of its own; a header's first comment describes
 * the header.
 */
#define _XOPEN_SOURCE 700 /* realpath */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct text {
    char *s;
    size_t len, cap;
} text;

static void die(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("cdl_apidoc: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(2);
}

static void text_add(text *t, const char *s, size_t n)
{
    if (t->len + n + 1 > t->cap) {
        size_t cap = t->cap ? t->cap : 256;
        while (t->len + n + 1 > cap) cap *= 2;
        t->s = realloc(t->s, cap);
        if (t->s == NULL) die("out of memory");
        t->cap = cap;
    }
    memcpy(t->s + t->len, s, n);
    t->len += n;
    t->s[t->len] = '\0';
}

static void text_put(text *t, const char *s) { text_add(t, s, strlen(s)); }
static void text_char(text *t, char c) { text_add(t, &c, 1); }

/* The string built so far (never NULL), leaving t empty. */
static char *text_take(text *t)
{
    char *s = t->s ? t->s : strdup("");
    if (s == NULL) die("out of memory");
    t->s = NULL;
    t->len = t->cap = 0;
    return s;
}

static char *copy_span(const char *s, size_t n)
{
    text t = {0};
    text_add(&t, s, n);
    return text_take(&t);
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) die("%s: %s", path, strerror(errno));
    text t = {0};
    char chunk[65536];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) text_add(&t, chunk, n);
    if (ferror(f)) die("%s: read error", path);
    fclose(f);
    return text_take(&t);
}

static int is_ident_char(int c) { return isalnum(c) || c == '_'; }

/* ---- the model of a header ---------------------------------------------- */

typedef enum item_kind {
    ITEM_FUNCTION, /* declared, defined in the library: exported */
    ITEM_INLINE,   /* static inline, defined in the header */
    ITEM_TYPE,     /* typedef, struct, enum; or a macro invocation that defines a type */
    ITEM_MACRO,    /* #define */
    ITEM_DATA,     /* an extern object: exported */
    ITEM_NOTE      /* a comment standing alone */
} item_kind;

typedef struct item {
    item_kind kind;
    char *name;    /* NULL for notes */
    char *doc;     /* the comment above it, or NULL */
    char *code;    /* the declaration as written (an inline function without its body) */
    int line, end_line;
    const char *file; /* the file it came from (types mode: the line markers') */
} item;

typedef struct header {
    char *name;     /* as included: "radiometry/units.h"; the umbrella "candela/candela.h" */
    char *path;
    char *overview; /* the first comment */
    item *items;
    size_t count, cap;
} header;

static void header_add(header *h, item it)
{
    if (h->count == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 32;
        h->items = realloc(h->items, h->cap * sizeof *h->items);
        if (h->items == NULL) die("out of memory");
    }
    h->items[h->count++] = it;
}

/* A comment's text without its delimiters and the leading " * " of its lines. */
static char *comment_text(const char *s, size_t n)
{
    int block = n >= 2 && s[1] == '*';
    const char *p = s + 2, *end = block ? s + n - 2 : s + n;
    text t = {0};
    int first = 1;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        const char *stop = eol ? eol : end;
        const char *q = p;
        if (!first) {
            while (q < stop && (*q == ' ' || *q == '\t')) ++q;
            if (q < stop && *q == '*') ++q;
        }
        if (q < stop && *q == ' ') ++q;
        const char *r = stop;
        while (r > q && (r[-1] == ' ' || r[-1] == '\t')) --r;
        if (!(first && r == q)) {
            text_add(&t, q, (size_t)(r - q));
            text_char(&t, '\n');
        }
        first = 0;
        p = eol ? eol + 1 : end;
    }
    while (t.len > 0 && t.s[t.len - 1] == '\n') t.s[--t.len] = '\0';
    return text_take(&t);
}

/* The end of the comment starting at s (past its closing delimiter). */
static const char *comment_end(const char *s)
{
    if (s[1] == '/') {
        const char *e = strchr(s, '\n');
        return e ? e : s + strlen(s);
    }
    const char *e = strstr(s + 2, "*/");
    return e ? e + 2 : s + strlen(s);
}

static int count_lines(const char *s, const char *e)
{
    int n = 0;
    for (; s < e; ++s) n += *s == '\n';
    return n;
}

/* The identifier ending right before position `end` of s (skipping blanks), copied. */
static char *ident_before(const char *s, const char *end)
{
    while (end > s && isspace((unsigned char)end[-1])) --end;
    const char *b = end;
    while (b > s && is_ident_char((unsigned char)b[-1])) --b;
    return b < end ? copy_span(b, (size_t)(end - b)) : NULL;
}

/* The first identifier at or after p, copied. */
static char *ident_after(const char *p)
{
    while (*p && !is_ident_char((unsigned char)*p)) ++p;
    const char *b = p;
    while (is_ident_char((unsigned char)*p)) ++p;
    return p > b ? copy_span(b, (size_t)(p - b)) : NULL;
}

/* The code with its comments removed (for classifying and naming). */
static char *strip_comments(const char *s)
{
    text t = {0};
    while (*s) {
        if (s[0] == '/' && (s[1] == '*' || s[1] == '/')) {
            s = comment_end(s);
            text_char(&t, ' ');
            continue;
        }
        text_char(&t, *s++);
    }
    return text_take(&t);
}

static int starts_with_word(const char *s, const char *word)
{
    size_t n = strlen(word);
    return strncmp(s, word, n) == 0 && !is_ident_char((unsigned char)s[n]);
}

/* NAME( ... ) with NAME in capitals: a macro invocation at file scope. */
static int is_macro_use(const char *code)
{
    const char *p = code;
    while (isspace((unsigned char)*p)) ++p;
    if (!(isupper((unsigned char)*p) || *p == '_')) return 0;
    while (isupper((unsigned char)*p) || isdigit((unsigned char)*p) || *p == '_') ++p;
    while (*p == ' ' || *p == '\t') ++p;
    if (*p != '(') return 0;
    const char *e = code + strlen(code);
    while (e > p && isspace((unsigned char)e[-1])) --e;
    return e > p && e[-1] == ')';
}

/* Kind and name of a declaration (`code` without comments). */
static void classify(const char *code, int has_body, item *it)
{
    const char *p = code;
    while (isspace((unsigned char)*p)) ++p;
    const char *paren = strchr(p, '(');
    if (starts_with_word(p, "typedef")) {
        const char *fp = strstr(p, "(*");
        it->kind = ITEM_TYPE;
        if (fp) {
            it->name = ident_after(fp + 2);
        } else {
            const char *end = p + strlen(p);
            while (end > p && (isspace((unsigned char)end[-1]) || end[-1] == ';')) --end;
            while (end > p && end[-1] == ']') { /* typedef T name[N]; */
                while (end > p && end[-1] != '[') --end;
                if (end > p) --end;
            }
            it->name = ident_before(p, end);
        }
    } else if (starts_with_word(p, "struct") || starts_with_word(p, "enum") || starts_with_word(p, "union")) {
        it->kind = ITEM_TYPE;
        const char *q = p;
        while (is_ident_char((unsigned char)*q)) ++q;
        while (isspace((unsigned char)*q)) ++q;
        it->name = ident_after(q); /* the tag, or else the first enumerator */
    } else if (is_macro_use(p)) {
        it->kind = ITEM_TYPE; /* CDL_DEFINE_QUANTITY(type, field, constructor) */
        it->name = ident_after(paren + 1);
    } else if (starts_with_word(p, "static")) {
        it->kind = ITEM_INLINE;
        it->name = paren ? ident_before(p, paren) : NULL;
    } else if (paren) {
        it->kind = has_body ? ITEM_INLINE : ITEM_FUNCTION;
        it->name = ident_before(p, paren);
    } else {
        it->kind = ITEM_DATA;
        const char *end = p + strlen(p);
        while (end > p && (isspace((unsigned char)end[-1]) || end[-1] == ';')) --end;
        it->name = ident_before(p, end);
    }
}

/* Reads a header's text into items. With `markers` (preprocessed input)
 * "# N FILE" lines set the file items come from; `file` starts as path. */
static void parse_header(header *h, const char *src, int markers)
{
    const char *p = src;
    int line = 1;
    text doc = {0};
    int doc_pending = 0, doc_last_line = 0, seen_code = 0, last_item_line = -1;
    const char *file = h->path;

#define FLUSH_NOTE()                                                                 \
    do {                                                                             \
        if (doc_pending) {                                                           \
            item note = {ITEM_NOTE, NULL, text_take(&doc), NULL, doc_last_line, doc_last_line, file}; \
            header_add(h, note);                                                     \
            doc_pending = 0;                                                         \
        }                                                                            \
    } while (0)

    while (*p) {
        if (*p == '\n') { ++line; ++p; continue; }
        if (isspace((unsigned char)*p)) { ++p; continue; }

        if (p[0] == '/' && (p[1] == '*' || p[1] == '/')) {
            const char *e = comment_end(p);
            int first_line = line;
            char *body = comment_text(p, (size_t)(e - p));
            line += count_lines(p, e);
            if (!seen_code && h->overview == NULL && !doc_pending && !markers) {
                h->overview = body;
            } else if (first_line == last_item_line && h->count > 0 && h->items[h->count - 1].code) {
                /* a comment after a declaration on its line belongs to it */
                item *last = &h->items[h->count - 1];
                text t = {0};
                text_put(&t, last->code);
                text_put(&t, " ");
                text_add(&t, p, (size_t)(e - p));
                free(last->code);
                last->code = text_take(&t);
                free(body);
            } else {
                if (doc_pending && first_line > doc_last_line + 1) FLUSH_NOTE();
                if (doc_pending) text_char(&doc, '\n');
                text_put(&doc, body);
                free(body);
                doc_pending = 1;
                doc_last_line = line;
            }
            p = e;
            continue;
        }

        if (*p == '#') {
            const char *b = p;
            while (*p && !(*p == '\n' && p[-1] != '\\')) ++p;
            char *directive = copy_span(b, (size_t)(p - b));
            const char *d = directive + 1;
            while (*d == ' ' || *d == '\t') ++d;
            if (markers && isdigit((unsigned char)*d)) {
                /* # N "file" flags: the next line is line N of file */
                line = atoi(d) - 1;
                const char *q = strchr(d, '"');
                if (q) {
                    const char *r = strchr(q + 1, '"');
                    if (r) file = copy_span(q + 1, (size_t)(r - q - 1)); /* kept for the items' lifetime */
                }
                free(directive);
                continue;
            }
            line += count_lines(b, p);
            if (starts_with_word(d, "define")) {
                char *name = ident_after(d + 6);
                size_t n = strlen(name);
                /* the include guard is not part of the API */
                int guard = n > 2 && strcmp(name + n - 2, "_H") == 0 && strncmp(name, "CANDELA_", 8) == 0;
                if (guard) {
                    free(name);
                    free(directive);
                } else {
                    if (doc_pending && line - count_lines(b, p) > doc_last_line + 1) FLUSH_NOTE();
                    item it = {ITEM_MACRO, name, doc_pending ? text_take(&doc) : NULL, directive, line, line, file};
                    doc_pending = 0;
                    header_add(h, it);
                    last_item_line = line;
                }
            } else {
                FLUSH_NOTE();
                free(directive);
            }
            seen_code = 1;
            continue;
        }

        seen_code = 1;
        /* extern "C" { and its closing brace */
        if (starts_with_word(p, "extern") && strncmp(p + 6 + strspn(p + 6, " \t"), "\"C\"", 3) == 0) {
            const char *brace = strchr(p, '{');
            if (brace == NULL) break;
            p = brace + 1;
            continue;
        }
        if (*p == '}') { ++p; continue; }

        if (doc_pending && line > doc_last_line + 1) FLUSH_NOTE();
        int first_line = line;
        text code = {0};
        int parens = 0, braces = 0, has_body = 0;
        while (*p) {
            char c = *p;
            if (markers && c == '#' && (p == src || p[-1] == '\n')) {
                /* a line marker inside a declaration (after a long comment): where its next line is from */
                const char *d = p + 1 + strspn(p + 1, " \t");
                line = atoi(d) - 1;
                p += strcspn(p, "\n");
                continue;
            }
            if (c == '/' && (p[1] == '*' || p[1] == '/')) {
                const char *e = comment_end(p);
                text_add(&code, p, (size_t)(e - p));
                line += count_lines(p, e);
                p = e;
                continue;
            }
            if (c == '"' || c == '\'') {
                const char *q = p + 1;
                while (*q && *q != c) q += (*q == '\\' && q[1]) ? 2 : 1;
                if (*q) ++q;
                text_add(&code, p, (size_t)(q - p));
                p = q;
                continue;
            }
            if (c == '{' && braces == 0 && parens == 0) {
                size_t k = code.len;
                while (k > 0 && isspace((unsigned char)code.s[k - 1])) --k;
                if (k > 0 && code.s[k - 1] == ')') { /* a function body: skip it */
                    int depth = 0;
                    do {
                        if (*p == '{') ++depth;
                        else if (*p == '}') --depth;
                        else if (*p == '\n') ++line;
                        ++p;
                    } while (*p && depth > 0);
                    code.len = k;
                    code.s[k] = '\0';
                    has_body = 1;
                    break;
                }
            }
            if (c == '(') ++parens;
            else if (c == ')') --parens;
            else if (c == '{') ++braces;
            else if (c == '}') --braces;
            if (c == '\n' && parens == 0 && braces == 0 && is_macro_use(code.s ? code.s : "")) break;
            text_char(&code, c);
            ++p;
            if (c == '\n') ++line;
            if (c == ';' && parens == 0 && braces == 0) break;
        }
        char *raw = text_take(&code);
        char *bare = strip_comments(raw);
        item it = {ITEM_DATA, NULL, doc_pending ? text_take(&doc) : NULL, raw, first_line, first_line, file};
        doc_pending = 0;
        classify(bare, has_body, &it);
        free(bare);
        if (it.name == NULL) {
            char *shown = copy_span(raw, strcspn(raw, "\n"));
            die("%s:%d: cannot tell what this declares: %s", h->path, first_line, shown);
        }
        it.end_line = line;
        header_add(h, it);
        last_item_line = line;
    }
    FLUSH_NOTE();
#undef FLUSH_NOTE
    if (h->overview == NULL) h->overview = strdup("");
}

/* ---- the public headers --------------------------------------------------- */

typedef struct api {
    header *headers; /* [0] the umbrella, then the headers it includes, in its order */
    size_t count;
} api;

static char *join_path(const char *dir, const char *name)
{
    text t = {0};
    text_put(&t, dir);
    if (t.len && t.s[t.len - 1] != '/') text_char(&t, '/');
    text_put(&t, name);
    return text_take(&t);
}

/* The umbrella's #include "..." lines, resolved against root, each parsed. */
static void api_load(api *a, const char *root, const char *umbrella)
{
    char *src = read_file(umbrella);
    size_t cap = 32;
    a->headers = calloc(cap, sizeof *a->headers);
    if (a->headers == NULL) die("out of memory");
    a->headers[0].name = strdup("candela/candela.h");
    a->headers[0].path = strdup(umbrella);
    a->count = 1;
    for (const char *p = src; *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : p + strlen(p)) {
        if (strncmp(p, "#include \"", 10) != 0) continue;
        const char *b = p + 10, *e = strchr(b, '"');
        if (e == NULL) continue;
        if (a->count == cap) die("more than %zu public headers", cap);
        header *h = &a->headers[a->count++];
        h->name = copy_span(b, (size_t)(e - b));
        h->path = join_path(root, h->name);
    }
    for (size_t i = 0; i < a->count; ++i) {
        char *text_of = i == 0 ? src : read_file(a->headers[i].path);
        parse_header(&a->headers[i], text_of, 0);
    }
}

static int compare_strings(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* ---- symbols ---------------------------------------------------------------- */

static int run_symbols(const api *a, const char *script)
{
    size_t n = 0;
    for (size_t i = 0; i < a->count; ++i) n += a->headers[i].count;
    char **names = malloc((n ? n : 1) * sizeof *names);
    if (names == NULL) die("out of memory");
    n = 0;
    for (size_t i = 0; i < a->count; ++i)
        for (size_t j = 0; j < a->headers[i].count; ++j) {
            const item *it = &a->headers[i].items[j];
            if (it->kind == ITEM_FUNCTION || it->kind == ITEM_DATA) names[n++] = it->name;
        }
    qsort(names, n, sizeof *names, compare_strings);
    FILE *out = stdout;
    char *tmp = NULL;
    if (script) {
        text t = {0};
        text_put(&t, script);
        text_put(&t, ".tmp");
        tmp = text_take(&t);
        out = fopen(tmp, "w");
        if (out == NULL) die("%s: %s", tmp, strerror(errno));
        fprintf(out, "/* libcandela.so exports: the functions of the public headers (made by cdl_apidoc). */\n{\n"
                     "  global:\n");
    }
    for (size_t i = 0; i < n; ++i) {
        if (i > 0 && strcmp(names[i], names[i - 1]) == 0) continue;
        fprintf(out, script ? "    %s;\n" : "%s\n", names[i]);
    }
    if (script) {
        fprintf(out, "  local:\n    *;\n};\n");
        if (fclose(out) != 0 || rename(tmp, script) != 0) die("%s: %s", script, strerror(errno));
    }
    free(names);
    return 0;
}

/* ---- check -------------------------------------------------------------------- */

static int run_check(const api *a)
{
    int problems = 0;
    for (size_t i = 0; i < a->count; ++i) {
        const header *h = &a->headers[i];
        if (strstr(h->overview, "hread") == NULL) {
            fprintf(stderr, "%s: its opening comment does not say what is thread-safe\n", h->name);
            ++problems;
        }
        for (size_t j = 0; j < h->count; ++j) {
            const item *it = &h->items[j];
            if (it->kind == ITEM_FUNCTION && (it->doc == NULL || it->doc[0] == '\0')) {
                /* a group of declarations shares the comment above the first */
                int grouped = j > 0 && h->items[j - 1].kind == ITEM_FUNCTION && h->items[j - 1].end_line + 1 >= it->line;
                if (!grouped) {
                    fprintf(stderr, "%s:%d: %s has no comment\n", h->name, it->line, it->name);
                    ++problems;
                }
            }
        }
    }
    if (problems) fprintf(stderr, "cdl_apidoc check: %d problem(s)\n", problems);
    return problems ? 1 : 0;
}

/* ---- types (the ABI fingerprint) ---------------------------------------------- */

/* Tokens joined by one space only where two identifier characters meet. */
static char *normalise(const char *s)
{
    text t = {0};
    int pending_space = 0;
    for (; *s; ++s) {
        if (isspace((unsigned char)*s)) {
            pending_space = 1;
            continue;
        }
        if (pending_space && t.len && is_ident_char((unsigned char)t.s[t.len - 1]) && is_ident_char((unsigned char)*s))
            text_char(&t, ' ');
        pending_space = 0;
        text_char(&t, *s);
    }
    return text_take(&t);
}

static int run_types(const api *a)
{
    char real[PATH_MAX];
    char **public_files = malloc(a->count * sizeof *public_files);
    if (public_files == NULL) die("out of memory");
    for (size_t i = 0; i < a->count; ++i) {
        if (realpath(a->headers[i].path, real) == NULL) die("%s: %s", a->headers[i].path, strerror(errno));
        public_files[i] = strdup(real);
    }
    text in = {0};
    char chunk[65536];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, stdin)) > 0) text_add(&in, chunk, n);
    char *src = text_take(&in);
    header all = {0};
    all.path = "<stdin>";
    parse_header(&all, src, 1);
    char **lines = malloc((all.count ? all.count : 1) * sizeof *lines);
    if (lines == NULL) die("out of memory");
    size_t count = 0;
    for (size_t j = 0; j < all.count; ++j) {
        const item *it = &all.items[j];
        if (it->kind != ITEM_TYPE) continue;
        if (realpath(it->file, real) == NULL) continue;
        int is_public = 0;
        for (size_t i = 0; i < a->count; ++i) is_public |= strcmp(real, public_files[i]) == 0;
        if (is_public) lines[count++] = normalise(it->code);
    }
    qsort(lines, count, sizeof *lines, compare_strings);
    for (size_t i = 0; i < count; ++i)
        if (i == 0 || strcmp(lines[i], lines[i - 1]) != 0) printf("%s\n", lines[i]);
    return count ? 0 : 1;
}

/* ---- html ------------------------------------------------------------------------ */

typedef struct anchor {
    const char *name;
    const char *page;
} anchor;

static int compare_anchors(const void *a, const void *b)
{
    return strcmp(((const anchor *)a)->name, ((const anchor *)b)->name);
}

static char *page_of(const header *h, int umbrella)
{
    if (umbrella) return strdup("index.html");
    text t = {0};
    for (const char *s = h->name; *s; ++s) text_char(&t, *s == '/' ? '_' : *s);
    if (t.len > 2 && strcmp(t.s + t.len - 2, ".h") == 0) t.len -= 2;
    t.s[t.len] = '\0';
    text_put(&t, ".html");
    return text_take(&t);
}

/* Escapes s, linking every identifier that names a public declaration
 * (except `self`, the item being shown). */
static void put_linked(FILE *out, const char *s, const anchor *anchors, size_t n, const char *self)
{
    while (*s) {
        if (is_ident_char((unsigned char)*s) && !isdigit((unsigned char)*s)) {
            const char *b = s;
            while (is_ident_char((unsigned char)*s)) ++s;
            char word[256];
            size_t len = (size_t)(s - b) < sizeof word - 1 ? (size_t)(s - b) : sizeof word - 1;
            memcpy(word, b, len);
            word[len] = '\0';
            anchor key = {word, NULL};
            const anchor *hit = n ? bsearch(&key, anchors, n, sizeof *anchors, compare_anchors) : NULL;
            if (hit && !(self && strcmp(self, word) == 0))
                fprintf(out, "<a href=\"%s#%s\">%s</a>", hit->page, word, word);
            else
                fwrite(b, 1, (size_t)(s - b), out);
            continue;
        }
        switch (*s) {
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '&': fputs("&amp;", out); break;
        default: fputc(*s, out);
        }
        ++s;
    }
}

static void put_escaped(FILE *out, const char *s)
{
    put_linked(out, s, NULL, 0, NULL);
}

static const char *const page_style =
    "body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 1em;color:#222}"
    "pre{white-space:pre-wrap;font-size:0.9em}"
    "pre.code{background:#f4f4f4;border-left:3px solid #c90;padding:0.5em;margin-bottom:0.2em}"
    "pre.doc{margin-top:0;padding-left:1em}"
    "pre.note{color:#555;border-top:1px solid #ddd;padding-top:0.5em}"
    "a{color:#06c;text-decoration:none}a:hover{text-decoration:underline}"
    ".kind{color:#888;font-size:0.8em}"
    "ul.index{columns:3;font-size:0.85em;list-style:none;padding:0}";

static FILE *open_page(const char *dir, const char *page, const char *title)
{
    char *path = join_path(dir, page);
    FILE *out = fopen(path, "w");
    if (out == NULL) die("%s: %s", path, strerror(errno));
    free(path);
    fprintf(out, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>");
    put_escaped(out, title);
    fprintf(out, "</title><style>%s</style></head><body>\n", page_style);
    return out;
}

static const char *kind_name(item_kind k)
{
    switch (k) {
    case ITEM_FUNCTION: return "function";
    case ITEM_INLINE: return "inline function";
    case ITEM_TYPE: return "type";
    case ITEM_MACRO: return "macro";
    case ITEM_DATA: return "object";
    default: return "";
    }
}

static void put_items(FILE *out, const header *h, const anchor *anchors, size_t n)
{
    for (size_t j = 0; j < h->count; ++j) {
        const item *it = &h->items[j];
        if (it->kind == ITEM_NOTE) {
            fputs("<pre class=\"note\">", out);
            put_linked(out, it->doc, anchors, n, NULL);
            fputs("</pre>\n", out);
            continue;
        }
        fprintf(out, "<div id=\"%s\"><span class=\"kind\">%s</span><pre class=\"code\">", it->name, kind_name(it->kind));
        put_linked(out, it->code, anchors, n, it->name);
        fputs("</pre>", out);
        if (it->doc) {
            fputs("<pre class=\"doc\">", out);
            put_linked(out, it->doc, anchors, n, it->name);
            fputs("</pre>", out);
        }
        fputs("</div>\n", out);
    }
}

/* mkdir -p */
static void make_folders(const char *dir)
{
    char *path = strdup(dir);
    if (path == NULL) die("out of memory");
    for (char *p = path + 1;; ++p) {
        if (*p != '/' && *p != '\0') continue;
        char c = *p;
        *p = '\0';
        if (mkdir(path, 0777) != 0 && errno != EEXIST) die("%s: %s", path, strerror(errno));
        *p = c;
        if (c == '\0') break;
    }
    free(path);
}

static int run_html(const api *a, const char *dir)
{
    make_folders(dir);
    size_t n = 0;
    for (size_t i = 0; i < a->count; ++i) n += a->headers[i].count;
    anchor *anchors = malloc((n ? n : 1) * sizeof *anchors);
    char **pages = calloc(a->count, sizeof *pages);
    if (anchors == NULL || pages == NULL) die("out of memory");
    n = 0;
    for (size_t i = 0; i < a->count; ++i) {
        pages[i] = page_of(&a->headers[i], i == 0);
        for (size_t j = 0; j < a->headers[i].count; ++j)
            if (a->headers[i].items[j].name) anchors[n++] = (anchor){a->headers[i].items[j].name, pages[i]};
    }
    qsort(anchors, n, sizeof *anchors, compare_anchors);

    FILE *index = open_page(dir, pages[0], "libcandela API reference");
    fputs("<h1>libcandela API reference</h1>\n<h2>candela/candela.h</h2>\n<pre>", index);
    put_linked(index, a->headers[0].overview, anchors, n, NULL);
    fputs("</pre>\n<h2>Headers</h2>\n<ul>\n", index);
    for (size_t i = 1; i < a->count; ++i) {
        const char *ov = a->headers[i].overview;
        const char *dash = strstr(ov, " - ");
        size_t len = strcspn(dash ? dash + 3 : ov, "\n");
        fprintf(index, "<li><a href=\"%s\">%s</a> ", pages[i], a->headers[i].name);
        char *summary = copy_span(dash ? dash + 3 : ov, len);
        put_escaped(index, summary);
        free(summary);
        fputs("</li>\n", index);
    }
    fputs("</ul>\n<h2>Declared in candela/candela.h</h2>\n", index);
    put_items(index, &a->headers[0], anchors, n);
    fputs("<h2>Index</h2>\n<ul class=\"index\">\n", index);
    for (size_t k = 0; k < n; ++k)
        if (k == 0 || strcmp(anchors[k].name, anchors[k - 1].name) != 0)
            fprintf(index, "<li><a href=\"%s#%s\">%s</a></li>\n", anchors[k].page, anchors[k].name, anchors[k].name);
    fputs("</ul>\n</body></html>\n", index);
    if (fclose(index) != 0) die("%s: write error", dir);

    for (size_t i = 1; i < a->count; ++i) {
        const header *h = &a->headers[i];
        FILE *out = open_page(dir, pages[i], h->name);
        fputs("<p><a href=\"index.html\">libcandela API reference</a></p>\n<h1>", out);
        put_escaped(out, h->name);
        fputs("</h1>\n<pre>", out);
        put_linked(out, h->overview, anchors, n, NULL);
        fputs("</pre>\n", out);
        put_items(out, h, anchors, n);
        fputs("</body></html>\n", out);
        if (fclose(out) != 0) die("%s: write error", pages[i]);
    }
    return 0;
}

/* ---- main ---------------------------------------------------------------------------- */

static void usage(void)
{
    fprintf(stderr, "usage: cdl_apidoc symbols --root ROOT UMBRELLA [--version-script OUT]\n"
                    "       cdl_apidoc html --root ROOT --out DIR UMBRELLA\n"
                    "       cdl_apidoc check --root ROOT UMBRELLA\n"
                    "       cdl_apidoc types --root ROOT UMBRELLA < PREPROCESSED\n");
    exit(2);
}

int main(int argc, char **argv)
{
    if (argc < 2) usage();
    const char *mode = argv[1], *root = NULL, *umbrella = NULL, *out = NULL, *script = NULL;
    for (int i = 2; i < argc; ++i) {
        if (strcmp(argv[i], "--root") == 0 && i + 1 < argc) root = argv[++i];
        else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) out = argv[++i];
        else if (strcmp(argv[i], "--version-script") == 0 && i + 1 < argc) script = argv[++i];
        else if (argv[i][0] != '-' && umbrella == NULL) umbrella = argv[i];
        else usage();
    }
    if (root == NULL || umbrella == NULL) usage();
    api a = {0};
    api_load(&a, root, umbrella);
    if (strcmp(mode, "symbols") == 0) return run_symbols(&a, script);
    if (strcmp(mode, "check") == 0) return run_check(&a);
    if (strcmp(mode, "types") == 0) return run_types(&a);
    if (strcmp(mode, "html") == 0 && out) return run_html(&a, out);
    usage();
    return 2;
}
