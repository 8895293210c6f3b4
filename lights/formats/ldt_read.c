/* ldt_read.c - EULUMDAT reader.
 *
 * Line-oriented header (FORMAT_NOTES section 2): lines 1-25 fixed, line 26
 * the number n of lamp sets, 6 lines per set, 10 direct ratios; then, read
 * by tokens whatever the line breaks, Mc C angles, Ng gamma angles and the
 * stored planes' intensities in cd/klm. Stored planes by Isym: 0 all Mc;
 * 1 one; 2 C0..C180; 3 C90..C270; 4 C0..C90 - selected by angle, so
 * irregular C lists (Dc = 0) work. Absolute candela:
 *     I = (cd/klm) x conversion factor x Phi(set 1) / 1000,
 * set 1 being the measured equipment (further sets are alternatives).
 * EULUMDAT C-planes are the frame's C-planes unchanged (photometry.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/formats/ldt_full_table.h"
#include "lights/formats/photometry_io.h"
#include "lights/photometry/photometry_metadata.h"

typedef struct ldt_reader {
    const char *source;
    cdl_photometry *p;
    cdl_error *err;
    const char *data;
    size_t size, pos; /* pos: start of the next unread line */
    unsigned line;    /* number of the last line read */
} ldt_reader;

static cdl_status oom(ldt_reader *r) { return cdl_error_out_of_memory(r->err); }

/* The next line, trimmed; an absent line (end of data) is an error naming `what`. */
static cdl_status next_line(ldt_reader *r, const char *what, const char **t, size_t *n)
{
    if (!cdl_photometry_next_line(r->data, r->size, &r->pos, t, n))
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s, found the end of the file (truncated?)",
                             r->source, r->line + 1, what);
    ++r->line;
    cdl_photometry_trim(t, n);
    return CDL_OK;
}

static cdl_status text_field(ldt_reader *r, const char *what, char *dst, size_t dst_size)
{
    const char *t;
    size_t n;
    cdl_status st = next_line(r, what, &t, &n);
    if (st != CDL_OK) return st;
    /* some writers quote text fields */
    if (n >= 2 && t[0] == '"' && t[n - 1] == '"') {
        ++t;
        n -= 2;
    }
    cdl_photometry_copy_text(dst, dst_size, t, n);
    return CDL_OK;
}

/* A numeric line. An empty line reads as `empty_value` when allowed (real
 * files leave direct ratios or heights blank), else it is an error. */
static cdl_status number_field(ldt_reader *r, const char *what, int allow_empty, double empty_value, double *value)
{
    const char *t;
    size_t n;
    cdl_status st = next_line(r, what, &t, &n);
    if (st != CDL_OK) return st;
    if (n == 0) {
        if (allow_empty) {
            *value = empty_value;
            return CDL_OK;
        }
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s (a number), found an empty line", r->source,
                             r->line, what);
    }
    /* a number followed by text on the same line (e.g. "100 %") keeps the number */
    size_t k = 0;
    while (k < n && t[k] != ' ' && t[k] != '\t') ++k;
    char q[40];
    if (!cdl_photometry_parse_number(t, k, 1, value) || !isfinite(*value)) {
        cdl_photometry_quote(q, sizeof q, t, n);
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s (a number), found %s", r->source, r->line,
                             what, q);
    }
    return CDL_OK;
}

static cdl_status integer_field(ldt_reader *r, const char *what, long lo, long hi, long *value)
{
    double v;
    cdl_status st = number_field(r, what, 0, 0.0, &v);
    if (st != CDL_OK) return st;
    if (v != floor(v) || v < (double)lo || v > (double)hi)
        return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s (a whole number from %ld to %ld), found %g",
                             r->source, r->line, what, lo, hi, v);
    *value = (long)v;
    return CDL_OK;
}

typedef struct ldt_header {
    long ityp, isym, mc, ng, nsets;
    double dc, dg, cfli;
    unsigned isym_line, mc_line;
} ldt_header;

static cdl_status read_header(ldt_reader *r, ldt_header *h)
{
    cdl_photometry_metadata *m = &r->p->meta;
    cdl_status st;
#define TRY(call)                                                                                                      \
    do {                                                                                                               \
        if ((st = (call)) != CDL_OK) return st;                                                                        \
    } while (0)
    TRY(text_field(r, "the company name (line 1)", m->ldt_company, sizeof m->ldt_company));
    TRY(integer_field(r, "the type indicator Ityp (line 2)", -1000000, 1000000, &h->ityp));
    TRY(integer_field(r, "the symmetry indicator Isym (line 3)", -1000000, 1000000, &h->isym));
    h->isym_line = r->line;
    if (h->isym < 0 || h->isym > 4)
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: expected the symmetry indicator Isym 0, 1, 2, 3 or 4, found %ld", r->source,
                             r->line, h->isym);
    TRY(integer_field(r, "the number of C-planes Mc (line 4)", 1, 100000, &h->mc));
    h->mc_line = r->line;
    TRY(number_field(r, "the C-plane spacing Dc (line 5)", 1, 0.0, &h->dc));
    TRY(integer_field(r, "the number of gamma angles Ng (line 6)", 2, 100000, &h->ng));
    TRY(number_field(r, "the gamma spacing Dg (line 7)", 1, 0.0, &h->dg));
    TRY(text_field(r, "the measurement report number (line 8)", m->ldt_report, sizeof m->ldt_report));
    TRY(text_field(r, "the luminaire name (line 9)", m->ldt_luminaire_name, sizeof m->ldt_luminaire_name));
    TRY(text_field(r, "the luminaire number (line 10)", m->ldt_luminaire_number, sizeof m->ldt_luminaire_number));
    TRY(text_field(r, "the file name (line 11)", m->ldt_file_name, sizeof m->ldt_file_name));
    TRY(text_field(r, "the date and user (line 12)", m->ldt_date_user, sizeof m->ldt_date_user));
    /* A test lab written by Candela from an IES [TESTLAB] (ldt_write.c). */
    char *lab = strstr(m->ldt_date_user, CDL_LDT_TESTLAB_MARK);
    if (lab) {
        const char *name = lab + strlen(CDL_LDT_TESTLAB_MARK);
        if (cdl_photometry_add_keyword(r->p, "TESTLAB", 7, name, strlen(name)) != CDL_OK) return oom(r);
        *lab = '\0';
    }
    static const char *const dims[3] = {"the luminaire length or diameter in mm (line 13)",
                                        "the luminaire width in mm (line 14)", "the luminaire height in mm (line 15)"};
    for (int k = 0; k < 3; ++k) TRY(number_field(r, dims[k], 1, 0.0, &m->ldt_luminaire_mm[k]));
    TRY(number_field(r, "the luminous area length or diameter in mm (line 16)", 1, 0.0, &m->ldt_luminous_mm[0]));
    TRY(number_field(r, "the luminous area width in mm (line 17)", 1, 0.0, &m->ldt_luminous_mm[1]));
    static const char *const heights[4] = {
        "the luminous height in the C0 plane in mm (line 18)", "the luminous height in the C90 plane in mm (line 19)",
        "the luminous height in the C180 plane in mm (line 20)", "the luminous height in the C270 plane in mm (line 21)"};
    for (int k = 0; k < 4; ++k) TRY(number_field(r, heights[k], 1, 0.0, &m->ldt_luminous_height_mm[k]));
    TRY(number_field(r, "the downward flux fraction DFF in % (line 22)", 1, 0.0, &m->ldt_dff_percent));
    TRY(number_field(r, "the light output ratio LORL in % (line 23)", 1, 0.0, &m->ldt_lorl_percent));
    TRY(number_field(r, "the intensity conversion factor (line 24)", 1, 1.0, &h->cfli));
    unsigned cfli_line = r->line;
    TRY(number_field(r, "the measurement tilt in degrees (line 25)", 1, 0.0, &m->ldt_measurement_tilt_deg));
    TRY(integer_field(r, "the number of lamp sets n (line 26)", 1, CDL_PHOTOMETRY_MAX_LAMP_SETS, &h->nsets));
    if (!(h->cfli > 0.0))
        return cdl_error_set(r->err, CDL_ERR_INPUT,
                             "%s:%u: expected the intensity conversion factor > 0, found %g (if a header line is "
                             "missing or extra, every later field shifts)",
                             r->source, cfli_line, h->cfli);
    m->lamp_set_count = (size_t)h->nsets;
    char what[96];
    for (long k = 0; k < h->nsets; ++k) {
        cdl_photometry_lamp_set *s = &m->lamp_sets[k];
        double count;
        snprintf(what, sizeof what, "the number of lamps of set %ld (line %u)", k + 1, r->line + 1);
        TRY(number_field(r, what, 0, 0.0, &count));
        if (count != floor(count) || fabs(count) > 1e6)
            return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s as a whole number, found %g", r->source,
                                 r->line, what, count);
        s->count = (int)count;
        snprintf(what, sizeof what, "the lamp type of set %ld (line %u)", k + 1, r->line + 1);
        TRY(text_field(r, what, s->type, sizeof s->type));
        snprintf(what, sizeof what, "the total lamp flux in lm of set %ld (line %u)", k + 1, r->line + 1);
        TRY(number_field(r, what, k > 0, 0.0, &s->flux_lm));
        snprintf(what, sizeof what, "the colour appearance of set %ld (line %u)", k + 1, r->line + 1);
        TRY(text_field(r, what, s->colour, sizeof s->colour));
        snprintf(what, sizeof what, "the colour rendering of set %ld (line %u)", k + 1, r->line + 1);
        TRY(text_field(r, what, s->cri, sizeof s->cri));
        snprintf(what, sizeof what, "the wattage of set %ld (line %u)", k + 1, r->line + 1);
        TRY(number_field(r, what, 1, 0.0, &s->watts));
    }
    for (int k = 0; k < 10; ++k) {
        snprintf(what, sizeof what, "direct ratio %d (line %u)", k + 1, r->line + 1);
        TRY(number_field(r, what, 1, 0.0, &m->ldt_direct_ratios[k]));
    }
#undef TRY
    return CDL_OK;
}

static cdl_status read_angles(ldt_reader *r, cdl_photometry_scanner *s, const char *kind, long n, double hi,
                              double *x, unsigned *first_line)
{
    char what[96];
    for (long i = 0; i < n; ++i) {
        cdl_token_kind k = cdl_photometry_take_number(s, &x[i]);
        unsigned line = s->tok_line;
        if (i == 0) *first_line = line;
        if (k != CDL_TOKEN_NUMBER || x[i] < 0.0 || x[i] > hi || (i > 0 && !(x[i] > x[i - 1])))
            snprintf(what, sizeof what, "%s angle %ld of %ld", kind, i + 1, n);
        if (k != CDL_TOKEN_NUMBER) return cdl_photometry_token_error(s, k, r->source, what, r->err);
        if (x[i] < 0.0 || x[i] > hi)
            return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s within [0, %g] degrees, found %g",
                                 r->source, line, what, hi, x[i]);
        if (i > 0 && !(x[i] > x[i - 1]))
            return cdl_error_set(r->err, CDL_ERR_INPUT,
                                 "%s:%u: expected %s angles in increasing order, found %g after %g (a header line "
                                 "missing or extra shifts every later field)",
                                 r->source, line, kind, x[i], x[i - 1]);
    }
    return CDL_OK;
}

static void fill_opening(cdl_photometry_metadata *m)
{
    cdl_luminous_opening *o = &m->opening;
    memset(o, 0, sizeof *o);
    double h = 0.0;
    for (int k = 0; k < 4; ++k) h += m->ldt_luminous_height_mm[k] / 4.0;
    double a = fabs(m->ldt_luminous_mm[0]) / 1000.0, b = fabs(m->ldt_luminous_mm[1]) / 1000.0;
    o->height_m = fabs(h) / 1000.0;
    /* IES width = LDT luminous length, IES length = LDT luminous width, as
     * real converters write them (FORMAT_NOTES 3.3) */
    if (a == 0.0 && b == 0.0) {
        o->shape = CDL_LUMINOUS_SHAPE_POINT;
    } else if (b == 0.0) {
        o->shape = o->height_m > 0.0 ? CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER : CDL_LUMINOUS_SHAPE_CIRCLE;
        o->width_m = o->length_m = a;
    } else {
        o->shape = o->height_m > 0.0 ? CDL_LUMINOUS_SHAPE_BOX : CDL_LUMINOUS_SHAPE_RECTANGLE;
        o->width_m = a;
        o->length_m = b;
        /* sides luminous to different heights: each its own (a round
         * luminous area's side has no C0 or C90 face: its mean stands) */
        const double *h4 = m->ldt_luminous_height_mm;
        if (o->shape == CDL_LUMINOUS_SHAPE_BOX && (h4[0] != h4[1] || h4[0] != h4[2] || h4[0] != h4[3]))
            for (int k = 0; k < 4; ++k) o->side_height_m[k] = fabs(h4[k]) / 1000.0;
    }
}

/* np x ng intensities in cd/klm, times `scale` to candela, into cd;
 * *first_line: the line of the first. */
static cdl_status read_intensities(ldt_reader *r, cdl_photometry_scanner *s, const double *planes, size_t np,
                                   const double *g, size_t ng, double scale, double *cd, unsigned *first_line)
{
    char what[96];
    for (size_t i = 0; i < np; ++i)
        for (size_t j = 0; j < ng; ++j) {
            double x;
            cdl_token_kind k = cdl_photometry_take_number(s, &x);
            unsigned line = s->tok_line;
            if (i == 0 && j == 0) *first_line = line;
            if (k == CDL_TOKEN_NUMBER && x >= 0.0 && isfinite(x * scale)) {
                cd[i * ng + j] = x * scale;
                continue;
            }
            snprintf(what, sizeof what, "the intensity at C%g, gamma %g", planes[i], g[j]);
            if (k != CDL_TOKEN_NUMBER) return cdl_photometry_token_error(s, k, r->source, what, r->err);
            if (x < 0.0)
                return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s >= 0, found %g (negative intensity)",
                                     r->source, line, what, x);
            return cdl_error_set(r->err, CDL_ERR_INPUT, "%s:%u: expected %s to give a finite candela value, found %g",
                                 r->source, line, what, x);
        }
    return CDL_OK;
}

/* Isym 1..4 followed by exactly the values of the planes it leaves out:
 * the file holds all its Mc planes, in C order from C0 (ldt_full_table.c).
 * When it does, *t becomes what to use (the planes Isym names, or the full
 * table where the data contradict Isym) and *used is 1, with a warning. */
static cdl_status full_table(ldt_reader *r, cdl_photometry_scanner *s, const ldt_header *h, const double *c,
                             const double *g, double scale, cdl_ldt_table *t, int *used)
{
    size_t mc = (size_t)h->mc, ng = t->ng;
    if (mc >= 2 && c[mc - 1] == 360.0) --mc; /* C360 is C0 again */
    if (mc <= t->np || cdl_photometry_count_numbers(s, 1) != (mc - t->np) * ng) return CDL_OK;
    cdl_ldt_table all = {malloc(mc * sizeof *all.planes), malloc(mc * ng * sizeof *all.cd), mc, ng,
                         CDL_PHOTOMETRY_SYMMETRY_NONE};
    if (!all.planes || !all.cd) {
        free(all.planes);
        free(all.cd);
        return oom(r);
    }
    memcpy(all.planes, c, mc * sizeof *c);
    memcpy(all.cd, t->cd, t->np * ng * sizeof *t->cd);
    cdl_photometry_scanner probe = *s;
    int numbers = 1;
    for (size_t k = t->np * ng; k < mc * ng && numbers; ++k) {
        double x;
        numbers = cdl_photometry_take_number(&probe, &x) == CDL_TOKEN_NUMBER && x >= 0.0 && isfinite(x * scale);
        all.cd[k] = x * scale;
    }
    cdl_ldt_table use;
    double worst = 0.0;
    size_t at_plane = 0, at_gamma = 0;
    int agree = numbers ? cdl_ldt_check_full_table(&all, h->isym, g, &use, &worst, &at_plane, &at_gamma) : -2;
    cdl_status st = agree == -1 ? oom(r) : CDL_OK;
    if (agree == 1) {
        st = cdl_photometry_add_warning(r->p, "ldt-full-table", h->mc_line,
                                        "%s:%u: the file holds all %zu C-planes although Isym %ld stores %zu: they are "
                                        "the mirror images Isym %ld says (within 1 %% of the peak), and its planes are "
                                        "used",
                                        r->source, h->mc_line, mc, h->isym, t->np, h->isym) == CDL_OK
                 ? CDL_OK
                 : oom(r);
        free(all.planes);
        free(all.cd);
        all = use;
    } else if (agree == 0) {
        st = cdl_photometry_add_warning(r->p, "ldt-symmetry-indicator", h->isym_line,
                                        "%s:%u: the symmetry indicator Isym %ld is contradicted by the data: the file "
                                        "holds all %zu C-planes, and at C%g, gamma %g it has %.4g cd/klm where the "
                                        "symmetry gives %.4g more or less; read as the full table (Isym 0)",
                                        r->source, h->isym_line, h->isym, mc, all.planes[at_plane], g[at_gamma],
                                        all.cd[at_plane * ng + at_gamma] / scale, worst / scale) == CDL_OK
                 ? CDL_OK
                 : oom(r);
    }
    if (agree < 0 || st != CDL_OK) {
        free(all.planes);
        free(all.cd);
        return st;
    }
    free(t->planes);
    free(t->cd);
    *t = all;
    *s = probe;
    *used = 1;
    return CDL_OK;
}

cdl_status cdl_ldt_read(const char *data, size_t size, const char *name, const cdl_photometry_read_options *options,
                        cdl_photometry *p, cdl_error *err)
{
    (void)options;
    ldt_reader r;
    memset(&r, 0, sizeof r);
    r.source = name ? name : "<memory>";
    r.p = p;
    r.err = err;
    r.data = data;
    r.size = size;
    cdl_photometry_metadata *m = &p->meta;
    m->format = CDL_PHOTOMETRY_FORMAT_EULUMDAT;
    /* A UTF-8 byte-order mark is not part of the company name (line 1). */
    if (cdl_photometry_has_bom(data, size)) {
        r.pos = 3;
        if (cdl_photometry_add_warning(p, "byte-order-mark", 1,
                                       "%s:1: the file starts with a UTF-8 byte-order mark (EULUMDAT is plain "
                                       "text; some programs take it for part of the company name): ignored",
                                       r.source) != CDL_OK)
            return oom(&r);
    }
    ldt_header h;
    cdl_status st = read_header(&r, &h);
    if (st != CDL_OK) return st;
    m->ldt_ityp = (int)h.ityp;
    m->ldt_isym = (int)h.isym;
    m->candela_multiplier = h.cfli;
    m->file_horizontal_count = (size_t)h.mc;
    m->file_vertical_count = (size_t)h.ng;
    if ((h.ityp < 0 || h.ityp > 3) &&
        cdl_photometry_add_warning(p, "ldt-ityp", 2, "%s:2: expected the type indicator Ityp 0..3, found %ld", r.source, h.ityp) != CDL_OK)
        return oom(&r);

    const cdl_photometry_lamp_set *set1 = &m->lamp_sets[0];
    m->absolute = set1->count < 0;
    m->rated_lamp_flux_lm = m->absolute ? 0.0 : set1->flux_lm;
    m->input_watts = set1->watts;
    /* fixed lines of the header (FORMAT_NOTES section 2) */
    p->lamp_flux_line = 29;
    p->lorl_line = 23;
    p->dff_line = 22;
    if (!(set1->flux_lm > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:29: expected the lamp flux of set 1 > 0 (intensities are in cd/klm of it), found %g",
                             r.source, set1->flux_lm);

    cdl_photometry_scanner s;
    cdl_photometry_scanner_init(&s, data, size, r.pos, r.line + 1, 0);
    size_t have;
    unsigned end_line;
    int ends = cdl_photometry_numbers_then_end(&s, &have, &end_line);
    /* When the stored plane count follows from the header alone (Isym 0
     * and 1, or an equidistant C list), a short file is reported as
     * truncated before any angle is examined. */
    long np_header = h.isym == 0 ? h.mc : h.isym == 1 ? 1 : h.dc > 0.0 ? (h.isym == 4 ? h.mc / 4 + 1 : h.mc / 2 + 1) : 0;
    size_t need_all = (size_t)(h.mc + h.ng) + (size_t)np_header * (size_t)h.ng;
    if (have < need_all && ends)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:%u: expected %zu numbers after the direct ratios (%ld C angles, %ld gamma angles, "
                             "%ld x %ld intensities for Isym %ld), found %zu: the file is truncated",
                             r.source, end_line, need_all, h.mc, h.ng, np_header, h.ng, h.isym, have);
    size_t mc = (size_t)h.mc, ng = (size_t)h.ng;
    double *c = malloc(mc * sizeof *c), *g = malloc(ng * sizeof *g);
    double *planes = malloc(mc * sizeof *planes), *cd = NULL;
    size_t np = 0;
    if (!c || !g || !planes) st = oom(&r);
    unsigned c_line = 0, g_line = 0;
    if (st == CDL_OK) st = read_angles(&r, &s, "C", h.mc, 360.0, c, &c_line);
    if (st == CDL_OK) st = read_angles(&r, &s, "gamma", h.ng, 180.0, g, &g_line);
    if (st == CDL_OK && c[0] != 0.0 &&
        cdl_photometry_add_warning(p, "ldt-c-start", c_line, "%s:%u: expected the C-plane list to start at 0, found %g", r.source, c_line,
                                   c[0]) != CDL_OK)
        st = oom(&r);
    if (st == CDL_OK) {
        if (h.isym == 1) {
            planes[np++] = 0.0;
        } else {
            for (size_t i = 0; i < mc; ++i)
                if (cdl_ldt_stored_plane(h.isym, c[i])) planes[np++] = c[i];
        }
        if (h.isym == 0 && np >= 2 && c[mc - 1] == 360.0) --np; /* C360 is C0 again */
        static const double lo[5] = {0, 0, 0, 90, 0}, hi[5] = {0, 0, 180, 270, 90};
        if (h.isym >= 2 && (np < 2 || planes[0] != lo[h.isym] || planes[np - 1] != hi[h.isym]))
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s:%u: Isym %ld stores the C-planes from C%g to C%g, but the C list (Mc = %ld) does "
                               "not contain both",
                               r.source, h.isym_line, h.isym, lo[h.isym], hi[h.isym], h.mc);
    }
    if (st == CDL_OK) {
        size_t need = np * ng;
        ends = cdl_photometry_numbers_then_end(&s, &have, &end_line);
        if (have < need && ends)
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s:%u: expected %zu intensities (%zu C-planes x %zu gamma angles for Isym %ld), found "
                               "%zu: the file is truncated",
                               r.source, end_line, need, np, ng, h.isym, have);
    }
    /* A number takes at least two bytes: a table larger than the rest of the
     * file can hold is refused before it is allocated. */
    if (st == CDL_OK && (double)np * (double)ng > 0.5 * (double)(size - s.pos) + 1.0)
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s:%u: expected %zu intensities (%zu C-planes x %zu gamma angles for Isym %ld), but the "
                           "rest of the file is too short to hold them",
                           r.source, s.line, np * ng, np, ng, h.isym);
    if (st == CDL_OK && !(cd = malloc(np * ng * sizeof *cd))) st = oom(&r);
    double scale = h.cfli * set1->flux_lm / 1000.0;
    unsigned values_line = s.line; /* line of the first intensity: where table-wide errors point */
    if (st == CDL_OK) st = read_intensities(&r, &s, planes, np, g, ng, scale, cd, &values_line);
    cdl_ldt_table table = {planes, cd, np, ng, CDL_PHOTOMETRY_SYMMETRY_INFER};
    int full = 0;
    if (st == CDL_OK && h.isym != 0) st = full_table(&r, &s, &h, c, g, scale, &table, &full);
    planes = table.planes;
    cd = table.cd;
    np = table.np;
    if (st == CDL_OK && !full) {
        size_t extra = cdl_photometry_count_numbers(&s, 1);
        const char *tok;
        size_t len;
        unsigned line;
        cdl_photometry_scanner probe = s;
        if (cdl_photometry_scan(&probe, &tok, &len, &line) &&
            cdl_photometry_add_warning(p, "trailing-values", line, "%s:%u: %zu value%s after the intensity table ignored", r.source, line,
                                       extra, extra == 1 ? "" : "s") != CDL_OK)
            st = oom(&r);
    }
    if (st == CDL_OK) {
        cdl_photometry_symmetry sym = cdl_ldt_symmetry(h.isym);
        if (h.isym == 0 && np == 1) sym = CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
        if (full) sym = table.symmetry; /* what the full table it holds showed */
        if (h.isym == 0 && np == 1 && !full &&
            cdl_photometry_add_warning(p, "ldt-isym0-one-plane", h.mc_line, "%s:%u: Isym 0 with a single C-plane, read as rotationally symmetric",
                                       r.source, h.mc_line) != CDL_OK)
            st = oom(&r);
        if (st == CDL_OK) {
            if (sym == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL) planes[0] = 0.0;
            st = cdl_photometry_set_table(p, CDL_PHOTOMETRIC_TYPE_C, sym, planes, np, g, ng, cd, err);
            if (st != CDL_OK) cdl_error_prefix(err, "%s:%u: ", r.source, values_line);
        }
    }
    if (st == CDL_OK) fill_opening(m);
    free(c);
    free(g);
    free(planes);
    free(cd);
    return st;
}
