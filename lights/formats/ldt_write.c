/* ldt_write.c - EULUMDAT writer.
 *
 * Intensities in cd/klm of lamp set 1: cd/klm = cd x 1000 / Phi_ref, with
 * Phi_ref the rated lamp flux (relative photometry) or, for absolute
 * photometry, the luminaire flux written with a negative lamp count: an
 * EULUMDAT file's own (line 29, through IES as [_EULUMDAT_FLUX]), else the
 * table's integral with LORL = 100 % (FORMAT_NOTES 3.1, as the BEGA files
 * do). The conversion factor is 1. EULUMDAT C-planes are the frame's
 * planes. The symmetry indicator is the source's (an EULUMDAT file's, or
 * an IES file's [_EULUMDAT_ISYM]) when the table has that symmetry, else
 * the most compact one that represents the table exactly (Isym 1, 4, 2, 3
 * or 0). Type A/B data is resampled onto C-planes (EULUMDAT is type C
 * only). IES width/length map to the luminous length/width lines 16/17 as
 * real converters write them (FORMAT_NOTES 3.3). The fields IES has no
 * place for come back from its [_EULUMDAT_*] keywords (ldt_keywords.h), so
 * that EULUMDAT -> IES -> EULUMDAT gives back the file; where an IES file
 * has none, the downward flux fraction, light output ratio and direct
 * ratios are computed from the table. A radiometric table is refused:
 * EULUMDAT holds cd/klm only. Lines end in CR LF.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
#include "lights/formats/ldt_full_table.h"
#include "lights/formats/ldt_keywords.h"
#include "lights/formats/photometry_writer.h"
#include "lights/photometry/photometry_metadata.h"

/* EULUMDAT text fields are at most 78 characters (line 1 and 8-12). */
#define TEXT_MAX 78

static void text_line(cdl_text_buffer *out, const char *s, const char *what, cdl_photometry_notes *lost)
{
    size_t n = strcspn(s ? s : "", "\r\n");
    if (n > TEXT_MAX) {
        cdl_photometry_note(lost, "%s cut to %d characters", what, TEXT_MAX);
        n = TEXT_MAX;
    }
    cdl_text_buffer_printf(out, "%.*s\r\n", (int)n, s ? s : "");
}

static void number_line(cdl_text_buffer *out, double x)
{
    cdl_text_buffer_number(out, x);
    cdl_text_buffer_printf(out, "\r\n");
}

static const char *keyword_or(const cdl_photometry *p, const char *key, const char *fallback)
{
    const char *v = cdl_photometry_keyword_value(p, key);
    return v && *v ? v : fallback;
}

/* Equal spacing that closes the circle (Dc) or covers gamma (Dg), else 0. */
static double spacing(const double *x, size_t n, double period)
{
    if (n < 2) return 0.0;
    double step = x[1] - x[0];
    for (size_t i = 1; i < n; ++i)
        if (fabs(x[i] - x[i - 1] - step) > 1e-9) return 0.0;
    if (period > 0.0 && fabs(step * (double)n - period) > 1e-9) return 0.0;
    return step;
}

/* The reference flux of an IES file's table, before its ballast factor:
 * the rated flux, or for absolute photometry the EULUMDAT file's it came
 * from or the table's own. */
static double ies_reference_flux(const cdl_photometry *p, const cdl_ldt_header *h, double table_flux)
{
    double phi = p->meta.absolute ? (h->absolute_flux > 0.0 ? h->absolute_flux : table_flux) : p->meta.rated_lamp_flux_lm;
    return phi > 0.0 ? phi : table_flux > 0.0 ? table_flux : 1000.0;
}

/* What an IES file holds that EULUMDAT has no field for, named. */
static void ies_notes(const cdl_photometry *p, double phi_ref, cdl_photometry_notes *lost)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->tilt_count > 0) cdl_photometry_note(lost, "TILT data (%zu angles) has no EULUMDAT field", m->tilt_count);
    double factor = cdl_photometry_output_factor(p);
    if (factor != 1.0)
        cdl_photometry_note(lost,
                            "ballast factor %g has no EULUMDAT field: folded into the lamp flux (line 29: %.6g lm x "
                            "%g = %.6g lm), so the luminaire gives the same light; the intensities stay per 1000 lm "
                            "of the rated lamps",
                            factor, phi_ref, factor, phi_ref * factor);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version >= 2019 && m->file_generation_type != 0.0)
        cdl_photometry_note(lost, "the LM-63-2019 file generation type %.5f has no EULUMDAT field",
                            m->file_generation_type);
    static const char *const mapped[] = {"TEST", "TESTLAB", "MANUFAC", "LUMCAT", "LUMINAIRE", "ISSUEDATE", "LAMP"};
    char names[400] = "";
    size_t count = 0, at = 0;
    for (size_t i = 0; i < m->keyword_count; ++i) {
        const char *key = m->keywords[i].key;
        int kept = cdl_ldt_keyword_is_field(key);
        for (size_t k = 0; k < sizeof mapped / sizeof *mapped; ++k) kept |= cdl_photometry_strcaseeq(key, mapped[k]);
        if (kept) continue;
        /* each name once, in the file's order */
        int seen = 0;
        for (size_t j = 0; j < i && !seen; ++j) seen = cdl_photometry_strcaseeq(m->keywords[j].key, key);
        ++count;
        if (!seen && at < sizeof names)
            at += (size_t)snprintf(names + at, sizeof names - at, "%s%s%s%s", at ? ", " : "", key[0] ? "[" : "",
                                   key[0] ? key : "free text lines", key[0] ? "]" : "");
    }
    if (count)
        cdl_photometry_note(lost, "%zu IES keyword%s with no EULUMDAT field: %s", count, count == 1 ? "" : "s",
                            names);
    switch (m->opening.shape) {
    case CDL_LUMINOUS_SHAPE_POINT:
    case CDL_LUMINOUS_SHAPE_RECTANGLE:
    case CDL_LUMINOUS_SHAPE_BOX:
    case CDL_LUMINOUS_SHAPE_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER:
        break;
    default:
        cdl_photometry_note(lost, "luminous opening '%s' written as its bounding %s",
                            cdl_luminous_shape_name(m->opening.shape), "rectangle or circle");
    }
}

/* No intensity at gamma index j in any stored plane. */
static int zero_row(const cdl_photometry *q, size_t j)
{
    for (size_t i = 0; i < q->nh; ++i)
        if (q->cd[i * q->nv + j] != 0.0) return 0;
    return 1;
}

static int is_round(cdl_luminous_shape s)
{
    return s == CDL_LUMINOUS_SHAPE_CIRCLE || s == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER || s == CDL_LUMINOUS_SHAPE_SPHERE;
}

/* What is written of the table: the symmetry indicator, the C-planes
 * listed (Mc), and those whose intensities are stored. */
typedef struct ldt_layout {
    int isym;
    double *full, *stored;
    size_t nfull, nstored;
} ldt_layout;

/* Can a table of symmetry s be written under the indicator isym? */
static int fits(cdl_photometry_symmetry s, int isym)
{
    switch (isym) {
    case 0: return 1;
    case 1: return s == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    case 2:
        return s == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL || s == CDL_PHOTOMETRY_SYMMETRY_QUADRANT ||
               s == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180;
    case 3:
        return s == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL || s == CDL_PHOTOMETRY_SYMMETRY_QUADRANT ||
               s == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270;
    case 4: return s == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL || s == CDL_PHOTOMETRY_SYMMETRY_QUADRANT;
    default: return 0;
    }
}

static int compact_isym(cdl_photometry_symmetry s)
{
    return s == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL          ? 1
           : s == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180  ? 2
           : s == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270 ? 3
           : s == CDL_PHOTOMETRY_SYMMETRY_QUADRANT           ? 4
                                                              : 0;
}

static int plan_layout(const cdl_photometry *q, const cdl_ldt_header *h, ldt_layout *l)
{
    memset(l, 0, sizeof *l);
    l->isym = h->isym >= 0 && fits(q->symmetry, h->isym) ? h->isym : compact_isym(q->symmetry);
    if (q->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL) {
        /* one plane: list the source's Mc planes (24 when unknown), equally spaced */
        l->nfull = h->mc > 0 ? (size_t)h->mc : 24;
        l->full = malloc(l->nfull * sizeof *l->full);
        for (size_t i = 0; l->full && i < l->nfull; ++i) l->full[i] = 360.0 * (double)i / (double)l->nfull;
    } else if (cdl_photometry_full_planes(q, &l->full, &l->nfull) != CDL_OK) {
        l->full = NULL;
    }
    l->stored = l->full ? malloc(l->nfull * sizeof *l->stored) : NULL;
    if (!l->stored) return 0;
    for (size_t i = 0; i < l->nfull; ++i)
        if (cdl_ldt_stored_plane(l->isym, l->full[i])) l->stored[l->nstored++] = l->full[i];
    return 1;
}

/* Lines 1-12: company, indicators, grid, the text fields. */
static void write_identity(cdl_text_buffer *out, const cdl_photometry *p, const ldt_layout *l,
                           const cdl_ldt_header *h, const double *gamma, size_t ng,
                           const cdl_photometry_write_options *options,
                           cdl_photometry_notes *lost)
{
    const cdl_photometry_metadata *m = &p->meta;
    int from_ldt = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT;
    text_line(out, from_ldt ? m->ldt_company : keyword_or(p, "MANUFAC", ""), "company (line 1)", lost);
    int ityp = h->ityp >= 0 && h->ityp <= 3 ? h->ityp : (l->isym == 1 ? 1 : 3);
    cdl_text_buffer_printf(out, "%d\r\n%d\r\n%zu\r\n", ityp, l->isym, l->nfull);
    number_line(out, spacing(l->full, l->nfull, 360.0));
    cdl_text_buffer_printf(out, "%zu\r\n", ng);
    number_line(out, spacing(gamma, ng, 0.0));
    text_line(out, from_ldt ? m->ldt_report : keyword_or(p, "TEST", ""), "report number (line 8)", lost);
    text_line(out, from_ldt ? m->ldt_luminaire_name : keyword_or(p, "LUMINAIRE", ""), "luminaire name (line 9)", lost);
    text_line(out, from_ldt ? m->ldt_luminaire_number : keyword_or(p, "LUMCAT", ""), "luminaire number (line 10)", lost);
    text_line(out, options && options->file_name ? options->file_name : m->ldt_file_name, "file name (line 11)", lost);
    const char *date = from_ldt ? m->ldt_date_user
                                : keyword_or(p, "ISSUEDATE", keyword_or(p, "DATE", keyword_or(p, "TESTDATE", "")));
    /* The test lab has no EULUMDAT field: it goes with the date (line 12),
     * after CDL_LDT_TESTLAB_MARK, where the reader finds it again. */
    const char *lab = from_ldt ? "" : keyword_or(p, "TESTLAB", "");
    char date_lab[512];
    snprintf(date_lab, sizeof date_lab, "%s%s%s", date, lab[0] ? CDL_LDT_TESTLAB_MARK : "", lab);
    text_line(out, date_lab, "date and user (line 12)", lost);
}

/* Lines 13-21: the luminaire's and the luminous area's sizes in mm. */
static void write_sizes(cdl_text_buffer *out, const cdl_photometry *p, const cdl_ldt_header *h)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) {
        for (int k = 0; k < 3; ++k) number_line(out, m->ldt_luminaire_mm[k]);
        for (int k = 0; k < 2; ++k) number_line(out, m->ldt_luminous_mm[k]);
        for (int k = 0; k < 4; ++k) number_line(out, m->ldt_luminous_height_mm[k]);
        return;
    }
    const cdl_luminous_opening *o = &m->opening;
    double lum[2] = {o->width_m * 1000.0, is_round(o->shape) ? 0.0 : o->length_m * 1000.0};
    double height = (o->shape == CDL_LUMINOUS_SHAPE_RECTANGLE || o->shape == CDL_LUMINOUS_SHAPE_CIRCLE ||
                     o->shape == CDL_LUMINOUS_SHAPE_POINT)
                        ? 0.0
                        : o->height_m * 1000.0;
    for (int k = 0; k < 3; ++k) number_line(out, h->has_luminaire ? h->luminaire_mm[k] : (k < 2 ? lum[k] : height));
    for (int k = 0; k < 2; ++k) number_line(out, lum[k]);
    for (int k = 0; k < 4; ++k) number_line(out, h->has_heights ? h->heights_mm[k] : height);
}

/* Line 26 on: the lamp sets (set 1 with the ballast factor folded into its flux). */
static void write_lamps(cdl_text_buffer *out, const cdl_photometry *p, const cdl_ldt_header *h, double phi_ref,
                        cdl_photometry_notes *lost)
{
    const cdl_photometry_metadata *m = &p->meta;
    const cdl_photometry_lamp_set *s = &m->lamp_sets[0];
    int lamps = s->count != 0 ? abs(s->count) : 1;
    cdl_text_buffer_printf(out, "%zu\r\n%d\r\n", 1 + h->extra_sets, m->absolute ? -lamps : lamps);
    text_line(out, s->type, "lamp type", lost);
    /* The ballast factor folded in: the same light from the same table (ies_notes). */
    number_line(out, phi_ref * cdl_photometry_output_factor(p));
    text_line(out, h->colour, "lamp colour", lost);
    text_line(out, h->cri, "colour rendering", lost);
    number_line(out, m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? s->watts : m->input_watts);
    for (size_t k = 0; k < h->extra_sets; ++k) {
        const cdl_photometry_lamp_set *e = &h->sets[k];
        cdl_text_buffer_printf(out, "%d\r\n", e->count);
        text_line(out, e->type, "lamp type", lost);
        number_line(out, e->flux_lm);
        text_line(out, e->colour, "lamp colour", lost);
        text_line(out, e->cri, "colour rendering", lost);
        number_line(out, e->watts);
    }
}

cdl_status cdl_photometry_format_ldt(const cdl_photometry *p, const cdl_photometry_write_options *options,
                                     char **text, size_t *length, cdl_photometry_notes *lost, cdl_error *err)
{
    *text = NULL;
    *length = 0;
    cdl_photometry_write_options given = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    cdl_sized_struct_read(&given, sizeof given, options);
    options = &given;
    const cdl_photometry_metadata *m = &p->meta;
    /* EULUMDAT's intensities are cd/klm and nothing in it can say otherwise:
     * a W/sr table written there would be read as light by every program. */
    if (m->radiometric)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a photometric table (EULUMDAT holds cd/klm only), found radiant intensity in "
                             "%s ([%s]): a radiometric file is kept in IES, which says its unit",
                             cdl_photometry_intensity_unit(p), m->units_keyword);
    int from_ldt = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT;
    cdl_photometry *q = NULL;
    cdl_status st;
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) {
        st = cdl_photometry_remap_c(p, 1, 0.0, &q, err);
    } else {
        st = cdl_photometry_resample_type_c(p, CDL_RESAMPLE_DC_DEG, CDL_RESAMPLE_DG_DEG, &q, err);
        if (st == CDL_OK)
            cdl_photometry_note(lost,
                                "type %c data resampled onto C-planes every %g deg and gamma every %g deg (EULUMDAT "
                                "is type C only): flux %.6g lm becomes %.6g lm (%+.3f %%)",
                                p->type == CDL_PHOTOMETRIC_TYPE_B ? 'B' : 'A', CDL_RESAMPLE_DC_DEG,
                                CDL_RESAMPLE_DG_DEG, p->flux_lm, q->flux_lm,
                                p->flux_lm > 0.0 ? 100.0 * (q->flux_lm - p->flux_lm) / p->flux_lm : 0.0);
    }
    if (st != CDL_OK) return st;
    cdl_ldt_header h;
    cdl_ldt_header_of(p, &h);
    ldt_layout l;
    double ratios[CDL_DIRECT_RATIO_COUNT];
    if (!plan_layout(q, &h, &l) ||
        (!h.has_ratios && cdl_photometry_direct_ratios(q, ratios, err) != CDL_OK)) {
        free(l.full);
        free(l.stored);
        cdl_photometry_release(q);
        return cdl_error_out_of_memory(err);
    }
    /* gamma back to the source's range where IES padded it with zero intensity */
    size_t g0 = 0, g1 = q->nv;
    while (h.has_gamma && g0 + 2 < g1 && q->v[g0] < h.gamma_deg[0] && zero_row(q, g0)) ++g0;
    while (h.has_gamma && g1 > g0 + 2 && q->v[g1 - 1] > h.gamma_deg[1] && zero_row(q, g1 - 1)) --g1;
    double flux = q->flux_lm;
    /* EULUMDAT input: keep its lamp set 1 as the reference, so the numbers round-trip */
    double phi_ref = from_ldt ? m->lamp_sets[0].flux_lm : ies_reference_flux(p, &h, flux);
    if (!from_ldt) ies_notes(p, phi_ref, lost);

    cdl_text_buffer out = {0};
    write_identity(&out, p, &l, &h, q->v + g0, g1 - g0, options, lost);
    write_sizes(&out, p, &h);
    /* lines 22-25: stated DFF and LORL where the source states them, else the table's */
    double down = flux > 0.0 ? 100.0 * cdl_photometry_zone_flux(q, 0.0, 90.0).lm / flux : 0.0;
    number_line(&out, h.has_dff ? h.dff : round(down * 100.0) / 100.0);
    double lorl = 100.0 * flux / phi_ref;
    number_line(&out, h.has_lorl && h.lorl > 0.0 ? h.lorl : round(lorl * 100.0) / 100.0);
    cdl_text_buffer_printf(&out, "1\r\n");
    number_line(&out, h.tilt);
    write_lamps(&out, p, &h, phi_ref, lost);
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k)
        number_line(&out, h.has_ratios ? h.ratios[k] : round(ratios[k] * 1e4) / 1e4);
    /* angles and intensities, one per line; each stored value is the table's at that node */
    for (size_t i = 0; i < l.nfull; ++i) number_line(&out, l.full[i]);
    for (size_t j = g0; j < g1; ++j) number_line(&out, q->v[j]);
    double scale = 1000.0 / phi_ref;
    for (size_t i = 0; i < l.nstored; ++i)
        for (size_t j = g0; j < g1; ++j)
            number_line(&out, cdl_photometry_intensity_c_gamma(q, l.stored[i], q->v[j]).cd * scale);

    free(l.full);
    free(l.stored);
    cdl_photometry_release(q);
    if (out.failed) {
        cdl_text_buffer_free(&out);
        return cdl_error_out_of_memory(err);
    }
    *text = out.data;
    *length = out.len;
    return CDL_OK;
}
