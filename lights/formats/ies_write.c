/* ies_write.c - IES LM-63-2019 (default) and LM-63-2002 writer.
 *
 * Lines end in CR LF (the standard's rule); keyword lines are kept below
 * 256 bytes (the 2002 limit) by continuing long values with [MORE]. The
 * candela multiplier is 1 and the units are metres. Type C frame planes
 * become horizontal angles H = (360 - C) mod 360 (photometry.h); the table
 * is written with its most compact exact symmetry, and a full circle gets
 * its closing H = 360 row. LM-63 needs the vertical angles of type C data
 * to start at 0 or 90 and end at 90 or 180: a partial gamma range is padded
 * with zero intensity, which leaves the interpolated distribution (zero
 * outside the measured range) unchanged but for a 0.001 degree ramp.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
#include "lights/formats/ldt_keywords.h"
#include "lights/formats/photometry_io.h"
#include "lights/formats/photometry_writer.h"
#include "lights/photometry/photometry_metadata.h"

#define PER_LINE 10
#define KEYWORD_CHUNK 200
#define PAD_STEP_DEG 0.001

typedef struct ies_table {
    size_t nh, nv;
    double *h, *v, *cd;
} ies_table;

static void table_free(ies_table *t)
{
    free(t->h);
    free(t->v);
    free(t->cd);
}

static int row_is_zero(const double *cd, size_t nh, size_t nv, size_t j)
{
    for (size_t i = 0; i < nh; ++i)
        if (cd[i * nv + j] != 0.0) return 0;
    return 1;
}

/* The file's horizontal angles and rows for a type C table (already compact). */
static cdl_status type_c_rows(const cdl_photometry *q, ies_table *t, cdl_error *err)
{
    size_t n = q->nh, nv = q->nv;
    int closing = q->symmetry == CDL_PHOTOMETRY_SYMMETRY_NONE && n > 1 && q->h[0] == 0.0;
    size_t nh = n + (closing ? 1 : 0);
    t->h = malloc(nh * sizeof *t->h);
    double *rows = malloc(nh * nv * sizeof *rows);
    if (!t->h || !rows) {
        free(rows);
        return cdl_error_out_of_memory(err);
    }
    /* row k of the file holds frame plane C = (360 - H) mod 360 */
    for (size_t k = 0; k < nh; ++k) {
        size_t src;
        switch (q->symmetry) {
        case CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL:
        case CDL_PHOTOMETRY_SYMMETRY_QUADRANT:
        case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180:
            /* mirror-symmetric about C0-C180: H = C */
            src = k;
            t->h[k] = q->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL ? 0.0 : q->h[k];
            break;
        case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270:
            src = n - 1 - k;
            t->h[k] = 360.0 - q->h[src];
            break;
        default:
            if (closing) {
                /* H = 0 is C = 0; then H = 360 - C for C descending; H = 360 closes with C = 0 */
                src = (k == 0 || k == n) ? 0 : n - k;
                t->h[k] = k == n ? 360.0 : (k == 0 ? 0.0 : 360.0 - q->h[src]);
            } else {
                src = n - 1 - k;
                t->h[k] = 360.0 - q->h[src];
            }
            break;
        }
        memcpy(rows + k * nv, q->cd + src * nv, nv * sizeof *rows);
    }
    t->nh = nh;
    t->cd = rows;
    return CDL_OK;
}

/* LM-63 vertical range for type C: first 0 or 90, last 90 or 180; pad with zeros. */
static cdl_status pad_gamma(ies_table *t, const double *g, size_t ng, cdl_photometry_notes *lost, cdl_error *err)
{
    double first = g[0], last = g[ng - 1];
    double lo = first == 0.0 || first == 90.0 ? first : (first < 90.0 ? 0.0 : 90.0);
    double hi = last == 90.0 || last == 180.0 ? last : (last < 90.0 ? 90.0 : 180.0);
    int front = lo != first, back = hi != last;
    int front_ramp = front && !row_is_zero(t->cd, t->nh, ng, 0) && first - lo > 2.0 * PAD_STEP_DEG;
    int back_ramp = back && !row_is_zero(t->cd, t->nh, ng, ng - 1) && hi - last > 2.0 * PAD_STEP_DEG;
    size_t pre = (size_t)front + (size_t)front_ramp, post = (size_t)back + (size_t)back_ramp;
    size_t nv = ng + pre + post;
    double *v = malloc(nv * sizeof *v), *cd = calloc(t->nh * nv, sizeof *cd);
    if (!v || !cd) {
        free(v);
        free(cd);
        return cdl_error_out_of_memory(err);
    }
    size_t k = 0;
    if (front) v[k++] = lo;
    if (front_ramp) v[k++] = first - PAD_STEP_DEG;
    memcpy(v + k, g, ng * sizeof *v);
    k += ng;
    if (back_ramp) v[k++] = last + PAD_STEP_DEG;
    if (back) v[k++] = hi;
    for (size_t i = 0; i < t->nh; ++i) memcpy(cd + i * nv + pre, t->cd + i * ng, ng * sizeof *cd);
    if ((front || back) && lost)
        cdl_photometry_note(lost, "gamma angles %g..%g padded with zero intensity to %g..%g (LM-63 needs type C "
                                  "vertical angles from 0 or 90 to 90 or 180)",
                            first, last, lo, hi);
    free(t->cd);
    t->cd = cd;
    t->v = v;
    t->nv = nv;
    return CDL_OK;
}

/* ---- keywords ------------------------------------------------------------------ */

static void keyword(cdl_text_buffer *out, const char *key, const char *value)
{
    /* split at line breaks and every KEYWORD_CHUNK bytes: [KEY] first, [MORE] after */
    const char *v = value ? value : "";
    int first = 1;
    do {
        size_t n = strcspn(v, "\r\n");
        if (n > KEYWORD_CHUNK) n = KEYWORD_CHUNK;
        cdl_text_buffer_printf(out, "[%s] %.*s\r\n", first ? key : "MORE", (int)n, v);
        first = 0;
        v += n;
        if (*v == '\r' && v[1] == '\n') v += 2;
        else if (*v == '\r' || *v == '\n') ++v;
    } while (*v);
}

static void keyword_sink(void *context, const char *key, const char *value) { keyword(context, key, value); }

static int is_one_of(const char *key, const char *const *set, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (cdl_photometry_strcaseeq(key, set[i])) return 1;
    return 0;
}

static void write_keywords(cdl_text_buffer *out, const cdl_photometry *p, int version, cdl_photometry_notes *lost)
{
    const cdl_photometry_metadata *m = &p->meta;
    static const char *const required[4] = {"TEST", "TESTLAB", "ISSUEDATE", "MANUFAC"};
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) {
        keyword(out, "TEST", m->ldt_report);
        const char *lab = cdl_photometry_keyword_value(p, "TESTLAB"); /* split off line 12 by the reader */
        keyword(out, "TESTLAB", lab ? lab : "");
        keyword(out, "ISSUEDATE", m->ldt_date_user);
        keyword(out, "MANUFAC", m->ldt_company);
        if (m->ldt_luminaire_number[0]) keyword(out, "LUMCAT", m->ldt_luminaire_number);
        if (m->ldt_luminaire_name[0]) keyword(out, "LUMINAIRE", m->ldt_luminaire_name);
        if (m->lamp_sets[0].type[0]) keyword(out, "LAMP", m->lamp_sets[0].type);
        /* every other field as a user keyword the EULUMDAT writer reads back (ldt_keywords.h) */
        cdl_ldt_header_keywords(p, keyword_sink, out);
        const double *h = m->ldt_luminous_height_mm;
        if (h[0] != h[1] || h[0] != h[2] || h[0] != h[3])
            cdl_photometry_note(lost, "EULUMDAT luminous heights per side (C0 %g, C90 %g, C180 %g, C270 %g mm, lines "
                                      "18-21) written as their mean, IES's one height ([_EULUMDAT_LUMINOUS_HEIGHTS] "
                                      "keeps each for EULUMDAT)",
                                h[0], h[1], h[2], h[3]);
        if (m->candela_multiplier != 1.0)
            cdl_photometry_note(lost, "the EULUMDAT conversion factor %g (line 24) is applied to the intensities "
                                      "(LM-63 multiplier 1): the light is the same, the cd/klm values scale by it",
                                m->candela_multiplier);
    } else {
        /* LM-63-2002 and -2019 both require these four, in this order */
        for (int r = 0; r < 4; ++r) {
            const char *v = cdl_photometry_keyword_value(p, required[r]);
            keyword(out, required[r], v ? v : "");
        }
        int seen_required[4] = {0, 0, 0, 0};
        for (size_t i = 0; i < m->keyword_count; ++i) {
            const cdl_photometry_keyword *k = &m->keywords[i];
            int skip = 0;
            for (int r = 0; r < 4; ++r)
                if (cdl_photometry_strcaseeq(k->key, required[r]) && !seen_required[r]) {
                    seen_required[r] = 1; /* written above */
                    skip = 1;
                }
            if (skip) continue;
            if (version < 2019 && cdl_photometry_strcaseeq(k->key, "FILEGENINFO")) {
                keyword(out, "OTHER", k->value);
                continue;
            }
            keyword(out, k->key[0] ? k->key : "OTHER", k->value);
        }
    }
    static const char *const geninfo[1] = {"FILEGENINFO"};
    int has_geninfo = 0;
    for (size_t i = 0; i < m->keyword_count; ++i) has_geninfo |= is_one_of(m->keywords[i].key, geninfo, 1);
    if (version >= 2019 && (!has_geninfo || m->format != CDL_PHOTOMETRY_FORMAT_IES)) {
        char info[160];
        if (m->format == CDL_PHOTOMETRY_FORMAT_IES)
            snprintf(info, sizeof info, "Converted by Candela %s from IES LM-63-%d", CANDELA_VERSION, m->ies_version);
        else if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT)
            snprintf(info, sizeof info, "Converted by Candela %s from EULUMDAT", CANDELA_VERSION);
        else
            snprintf(info, sizeof info, "Written by Candela %s from a computed table", CANDELA_VERSION);
        keyword(out, "FILEGENINFO", info);
    }
}

static void numbers(cdl_text_buffer *out, const double *x, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        cdl_text_buffer_number(out, x[i]);
        cdl_text_buffer_printf(out, "%s", (i + 1) % PER_LINE == 0 || i + 1 == n ? "\r\n" : " ");
    }
}

cdl_status cdl_photometry_format_ies(const cdl_photometry *p, const cdl_photometry_write_options *options,
                                     char **text, size_t *length, cdl_photometry_notes *lost, cdl_error *err)
{
    *text = NULL;
    *length = 0;
    cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    cdl_sized_struct_read(&o, sizeof o, options);
    options = &o;
    int version = options->ies_version ? options->ies_version : 2019;
    if (version != 2019 && version != 2002)
        return cdl_error_set(err, CDL_ERR_USAGE, "IES output is LM-63-2019 or LM-63-2002, not %d", version);
    const cdl_photometry_metadata *m = &p->meta;
    cdl_photometry *compact = NULL;
    ies_table t;
    memset(&t, 0, sizeof t);
    cdl_status st = CDL_OK;
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) {
        st = cdl_photometry_remap_c(p, 1, 0.0, &compact, err);
        if (st == CDL_OK) st = type_c_rows(compact, &t, err);
        if (st == CDL_OK) st = pad_gamma(&t, compact->v, compact->nv, lost, err);
    } else {
        t.nh = p->nh;
        t.nv = p->nv;
        t.h = malloc(t.nh * sizeof *t.h);
        t.v = malloc(t.nv * sizeof *t.v);
        t.cd = malloc(t.nh * t.nv * sizeof *t.cd);
        if (!t.h || !t.v || !t.cd) st = cdl_error_out_of_memory(err);
        else {
            memcpy(t.h, p->h, t.nh * sizeof *t.h);
            memcpy(t.v, p->v, t.nv * sizeof *t.v);
            memcpy(t.cd, p->cd, t.nh * t.nv * sizeof *t.cd);
        }
    }
    if (st != CDL_OK) {
        table_free(&t);
        cdl_photometry_release(compact);
        return st;
    }

    cdl_text_buffer out = {0};
    cdl_text_buffer_printf(&out, "%s\r\n", version >= 2019 ? "IES:LM-63-2019" : "IESNA:LM-63-2002");
    write_keywords(&out, p, version, lost);

    if (m->tilt_count > 0) {
        if (m->tilt_kind == CDL_TILT_FILE)
            cdl_photometry_note(lost, "TILT=%s written inline as TILT=INCLUDE", m->tilt_file);
        cdl_text_buffer_printf(&out, "TILT=INCLUDE\r\n%d\r\n%zu\r\n", m->tilt_geometry, m->tilt_count);
        numbers(&out, m->tilt_angles_deg, m->tilt_count);
        numbers(&out, m->tilt_factors, m->tilt_count);
    } else {
        cdl_text_buffer_printf(&out, "TILT=NONE\r\n");
    }

    /* record A */
    const cdl_photometry_lamp_set *set = &m->lamp_sets[0];
    int lamps = set->count != 0 ? abs(set->count) : 1;
    double lumens = m->absolute ? -1.0 : m->rated_lamp_flux_lm / lamps;
    double opening[3];
    cdl_photometry_opening_to_ies(&m->opening, opening);
    cdl_text_buffer_printf(&out, "%d ", lamps);
    /* lamps x lumens is the reference flux: printed so that it comes back exactly */
    cdl_text_buffer_exact(&out, lumens);
    cdl_text_buffer_printf(&out, " 1 %zu %zu %d 2 ", t.nv, t.nh, (int)p->type);
    for (int k = 0; k < 3; ++k) {
        cdl_text_buffer_number(&out, opening[k]);
        cdl_text_buffer_printf(&out, "%s", k < 2 ? " " : "\r\n");
    }
    /* record B */
    double ballast = m->ballast_factor;
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version <= 1995 && m->ballast_lamp_factor != 1.0) {
        ballast *= m->ballast_lamp_factor;
        cdl_photometry_note(lost, "the LM-63-%d ballast-lamp photometric factor %g is folded into the ballast factor "
                                  "(%g x %g)",
                            m->ies_version, m->ballast_lamp_factor, m->ballast_factor, m->ballast_lamp_factor);
    }
    double second = 1.0;
    if (version >= 2019) {
        int has_code = m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version >= 2019 &&
                       m->file_generation_type >= 1.0 && m->file_generation_type < 2.0;
        /* 1.00001: "undefined" - provenance not stated by a converted file */
        second = has_code ? m->file_generation_type : 1.00001;
    } else if (m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version >= 2019) {
        cdl_photometry_note(lost, "the LM-63-2019 file generation type %.5f has no LM-63-2002 field",
                            m->file_generation_type);
    }
    cdl_text_buffer_number(&out, ballast);
    cdl_text_buffer_printf(&out, " %.5f ", second);
    cdl_text_buffer_number(&out, m->input_watts);
    cdl_text_buffer_printf(&out, "\r\n");

    numbers(&out, t.v, t.nv);
    numbers(&out, t.h, t.nh);
    for (size_t i = 0; i < t.nh; ++i) numbers(&out, t.cd + i * t.nv, t.nv);

    table_free(&t);
    cdl_photometry_release(compact);
    if (out.failed) {
        cdl_text_buffer_free(&out);
        return cdl_error_out_of_memory(err);
    }
    *text = out.data;
    *length = out.len;
    return CDL_OK;
}
