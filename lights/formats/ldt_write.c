/* ldt_write.c - EULUMDAT writer.
 *
 * Intensities in cd/klm of lamp set 1: cd/klm = cd x 1000 / Phi_ref, with
 * Phi_ref the rated lamp flux (relative photometry) or, for absolute
 * photometry, the integrated luminaire flux written with a negative lamp
 * count and LORL = 100 % (FORMAT_NOTES 3.1, as the BEGA files do). The
 * conversion factor is 1. EULUMDAT C-planes are the frame's planes; the
 * table is written with its most compact exact symmetry (Isym 1, 4, 2, 3
 * or 0). Type A/B data is resampled onto C-planes (EULUMDAT is type C only).
 * IES width/length map to the luminous length/width lines 16/17 as real
 * converters write them (FORMAT_NOTES 3.3). Lines end in CR LF.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/formats/photometry_writer.h"

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

/* The lamp flux an IES file's table is relative to: the rated flux, or
 * for absolute photometry the table's own (cd/klm of the luminaire). */
static double ballast_reference_flux(const cdl_photometry *p)
{
    double phi = p->meta.absolute ? p->flux_lm : p->meta.rated_lamp_flux_lm;
    return phi > 0.0 ? phi : p->flux_lm > 0.0 ? p->flux_lm : 1000.0;
}

static void ies_notes(const cdl_photometry *p, cdl_photometry_notes *lost)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->tilt_count > 0) cdl_photometry_note(lost, "TILT data (%zu angles) has no EULUMDAT field", m->tilt_count);
    double factor = cdl_photometry_output_factor(p);
    if (factor != 1.0)
        cdl_photometry_note(lost,
                            "ballast factor %g has no EULUMDAT field: folded into the lamp flux (line 29: %.6g lm x "
                            "%g = %.6g lm), so the luminaire gives the same light; the intensities stay per 1000 lm "
                            "of the rated lamps",
                            factor, ballast_reference_flux(p), factor, ballast_reference_flux(p) * factor);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version >= 2019 && m->file_generation_type != 0.0)
        cdl_photometry_note(lost, "the LM-63-2019 file generation type %.5f has no EULUMDAT field",
                            m->file_generation_type);
    size_t kept = 0;
    static const char *const mapped[] = {"TEST", "TESTLAB", "MANUFAC", "LUMCAT", "LUMINAIRE", "ISSUEDATE", "LAMP"};
    for (size_t i = 0; i < m->keyword_count; ++i) {
        int is_mapped = 0;
        for (size_t k = 0; k < sizeof mapped / sizeof *mapped; ++k)
            is_mapped |= cdl_photometry_strcaseeq(m->keywords[i].key, mapped[k]);
        if (!is_mapped) ++kept;
    }
    if (kept)
        cdl_photometry_note(lost, "%zu IES keyword lines other than [TEST] [TESTLAB] [MANUFAC] [LUMCAT] [LUMINAIRE] "
                                  "[ISSUEDATE] [LAMP] have no EULUMDAT field",
                            kept);
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
    cdl_photometry_note(lost, "direct ratios (lines 27-36) are not computed and are written as 0");
}

static int is_round(cdl_luminous_shape s)
{
    return s == CDL_LUMINOUS_SHAPE_CIRCLE || s == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER || s == CDL_LUMINOUS_SHAPE_SPHERE;
}

cdl_status cdl_photometry_format_ldt(const cdl_photometry *p, const cdl_photometry_write_options *options,
                                     char **text, size_t *length, cdl_photometry_notes *lost, cdl_error *err)
{
    *text = NULL;
    *length = 0;
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
    double *full = NULL;
    size_t nfull = 0;
    if (q->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL) {
        nfull = 24;
        full = malloc(nfull * sizeof *full);
        for (size_t i = 0; full && i < nfull; ++i) full[i] = 15.0 * (double)i;
    } else if (cdl_photometry_full_planes(q, &full, &nfull) != CDL_OK) {
        full = NULL;
    }
    if (!full) {
        cdl_photometry_release(q);
        return cdl_error_out_of_memory(err);
    }
    if (!from_ldt) ies_notes(p, lost);

    int isym = q->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL          ? 1
               : q->symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180  ? 2
               : q->symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270 ? 3
               : q->symmetry == CDL_PHOTOMETRY_SYMMETRY_QUADRANT           ? 4
                                                                            : 0;
    double flux = q->flux_lm;
    /* EULUMDAT input: keep its lamp set 1 as the reference, so the numbers
     * round-trip; IES input: the rated flux, or the luminaire's own flux */
    double phi_ref = from_ldt ? m->lamp_sets[0].flux_lm : m->absolute ? flux : m->rated_lamp_flux_lm;
    if (!(phi_ref > 0.0)) phi_ref = flux > 0.0 ? flux : 1000.0;
    double down = flux > 0.0 ? 100.0 * cdl_photometry_zone_flux(q, 0.0, 90.0).lm / flux : 0.0;

    cdl_text_buffer out = {0};
    /* lines 1-12 */
    text_line(&out, from_ldt ? m->ldt_company : keyword_or(p, "MANUFAC", ""), "company (line 1)", lost);
    int ityp = from_ldt && m->ldt_ityp >= 0 && m->ldt_ityp <= 3 ? m->ldt_ityp : (isym == 1 ? 1 : 3);
    cdl_text_buffer_printf(&out, "%d\r\n%d\r\n%zu\r\n", ityp, isym, nfull);
    number_line(&out, spacing(full, nfull, 360.0));
    cdl_text_buffer_printf(&out, "%zu\r\n", q->nv);
    number_line(&out, spacing(q->v, q->nv, 0.0));
    text_line(&out, from_ldt ? m->ldt_report : keyword_or(p, "TEST", ""), "report number (line 8)", lost);
    text_line(&out, from_ldt ? m->ldt_luminaire_name : keyword_or(p, "LUMINAIRE", ""), "luminaire name (line 9)", lost);
    text_line(&out, from_ldt ? m->ldt_luminaire_number : keyword_or(p, "LUMCAT", ""), "luminaire number (line 10)",
              lost);
    text_line(&out, options && options->file_name ? options->file_name : m->ldt_file_name, "file name (line 11)", lost);
    const char *date = from_ldt ? m->ldt_date_user
                                : keyword_or(p, "ISSUEDATE", keyword_or(p, "DATE", keyword_or(p, "TESTDATE", "")));
    /* The test lab has no EULUMDAT field: it goes with the date (line 12),
     * after CDL_LDT_TESTLAB_MARK, where the reader finds it again. */
    const char *lab = from_ldt ? "" : keyword_or(p, "TESTLAB", "");
    char date_lab[512];
    snprintf(date_lab, sizeof date_lab, "%s%s%s", date, lab[0] ? CDL_LDT_TESTLAB_MARK : "", lab);
    text_line(&out, date_lab, "date and user (line 12)", lost);
    /* lines 13-21: dimensions in mm */
    const cdl_luminous_opening *o = &m->opening;
    int circular = is_round(o->shape);
    double lum[2] = {o->width_m * 1000.0, circular ? 0.0 : o->length_m * 1000.0};
    double height = (o->shape == CDL_LUMINOUS_SHAPE_RECTANGLE || o->shape == CDL_LUMINOUS_SHAPE_CIRCLE ||
                     o->shape == CDL_LUMINOUS_SHAPE_POINT)
                        ? 0.0
                        : o->height_m * 1000.0;
    for (int k = 0; k < 3; ++k)
        number_line(&out, from_ldt ? m->ldt_luminaire_mm[k] : (k < 2 ? lum[k] : height));
    for (int k = 0; k < 2; ++k) number_line(&out, from_ldt ? m->ldt_luminous_mm[k] : lum[k]);
    for (int k = 0; k < 4; ++k) number_line(&out, from_ldt ? m->ldt_luminous_height_mm[k] : height);
    /* lines 22-25 */
    number_line(&out, from_ldt ? m->ldt_dff_percent : round(down * 100.0) / 100.0);
    double lorl = m->absolute ? 100.0 : 100.0 * flux / phi_ref;
    number_line(&out, from_ldt && m->ldt_lorl_percent > 0.0 ? m->ldt_lorl_percent : round(lorl * 100.0) / 100.0);
    cdl_text_buffer_printf(&out, "1\r\n");
    number_line(&out, from_ldt ? m->ldt_measurement_tilt_deg : 0.0);
    /* line 26 and the lamp sets */
    if (from_ldt) {
        cdl_text_buffer_printf(&out, "%zu\r\n", m->lamp_set_count);
        for (size_t k = 0; k < m->lamp_set_count; ++k) {
            const cdl_photometry_lamp_set *s = &m->lamp_sets[k];
            cdl_text_buffer_printf(&out, "%d\r\n", s->count);
            text_line(&out, s->type, "lamp type", lost);
            number_line(&out, s->flux_lm);
            text_line(&out, s->colour, "lamp colour", lost);
            text_line(&out, s->cri, "colour rendering", lost);
            number_line(&out, s->watts);
        }
        for (int k = 0; k < 10; ++k) number_line(&out, m->ldt_direct_ratios[k]);
    } else {
        const cdl_photometry_lamp_set *s = &m->lamp_sets[0];
        int lamps = s->count != 0 ? abs(s->count) : 1;
        cdl_text_buffer_printf(&out, "1\r\n%d\r\n", m->absolute ? -lamps : lamps);
        text_line(&out, s->type, "lamp type", lost);
        /* The ballast factor folded in: the same light from the same table (ies_notes). */
        number_line(&out, phi_ref * cdl_photometry_output_factor(p));
        cdl_text_buffer_printf(&out, "\r\n\r\n");
        number_line(&out, m->input_watts);
        for (int k = 0; k < 10; ++k) cdl_text_buffer_printf(&out, "0\r\n");
    }
    /* angles and intensities, one per line */
    for (size_t i = 0; i < nfull; ++i) number_line(&out, full[i]);
    for (size_t j = 0; j < q->nv; ++j) number_line(&out, q->v[j]);
    double scale = 1000.0 / phi_ref;
    for (size_t i = 0; i < q->nh; ++i)
        for (size_t j = 0; j < q->nv; ++j) number_line(&out, q->cd[i * q->nv + j] * scale);

    free(full);
    cdl_photometry_release(q);
    if (out.failed) {
        cdl_text_buffer_free(&out);
        return cdl_error_out_of_memory(err);
    }
    *text = out.data;
    *length = out.len;
    return CDL_OK;
}
