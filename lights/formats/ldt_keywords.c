/* ldt_keywords.c - EULUMDAT fields carried through IES as keywords (ldt_keywords.h). */
#include "lights/formats/ldt_keywords.h"
#include "lights/photometry/photometry_metadata.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const field_keywords[] = {
    "_EULUMDAT_ITYP", "_EULUMDAT_ISYM", "_EULUMDAT_MC",     "_EULUMDAT_LUMINAIRE", "_EULUMDAT_LUMINOUS_HEIGHTS",
    "_EULUMDAT_DFF",  "_EULUMDAT_LORL", "_EULUMDAT_TILT",   "_EULUMDAT_COLOUR",    "_EULUMDAT_CRI",
    "_EULUMDAT_LAMPSET", "_EULUMDAT_DR", "_EULUMDAT_GAMMA", "_EULUMDAT_FILENAME", "_EULUMDAT_FLUX"};

int cdl_ldt_keyword_is_field(const char *key)
{
    for (size_t k = 0; k < sizeof field_keywords / sizeof *field_keywords; ++k)
        if (cdl_photometry_strcaseeq(key, field_keywords[k])) return 1;
    return 0;
}

/* Up to n numbers of a keyword's value; how many were read. */
static int numbers(const char *value, double *x, int n)
{
    int k = 0;
    const char *s = value;
    while (s && k < n) {
        char *end = NULL;
        double v = strtod(s, &end);
        if (end == s) break;
        x[k++] = v;
        s = end;
    }
    return k;
}

/* A further lamp set from "count | type | flux | colour | rendering | watts"; 0 when malformed. */
static int lamp_set(const char *value, cdl_photometry_lamp_set *set)
{
    const char *part[6];
    size_t len[6];
    const char *s = value;
    for (int k = 0; k < 6; ++k) {
        const char *bar = k < 5 ? strchr(s, '|') : s + strlen(s);
        if (!bar) return 0;
        part[k] = s;
        len[k] = (size_t)(bar - s);
        s = bar + (k < 5);
    }
    char number[64];
    double v[3];
    const int at[3] = {0, 2, 5};
    for (int k = 0; k < 3; ++k) {
        size_t n = len[at[k]] < sizeof number - 1 ? len[at[k]] : sizeof number - 1;
        memcpy(number, part[at[k]], n);
        number[n] = '\0';
        if (numbers(number, &v[k], 1) != 1) return 0;
    }
    memset(set, 0, sizeof *set);
    set->count = (int)v[0];
    set->flux_lm = v[1];
    set->watts = v[2];
    cdl_photometry_copy_text(set->type, sizeof set->type, part[1], len[1]);
    cdl_photometry_copy_text(set->colour, sizeof set->colour, part[3], len[3]);
    cdl_photometry_copy_text(set->cri, sizeof set->cri, part[4], len[4]);
    return 1;
}

static void from_keywords(const cdl_photometry *p, cdl_ldt_header *h)
{
    const cdl_photometry_metadata *m = &p->meta;
    double x[10];
    const char *v;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_ITYP")) && numbers(v, x, 1) == 1) h->ityp = (int)x[0];
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_ISYM")) && numbers(v, x, 1) == 1) h->isym = (int)x[0];
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_MC")) && numbers(v, x, 1) == 1) h->mc = (int)x[0];
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_LUMINAIRE")) && numbers(v, h->luminaire_mm, 3) == 3)
        h->has_luminaire = 1;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_LUMINOUS_HEIGHTS")) && numbers(v, h->heights_mm, 4) == 4)
        h->has_heights = 1;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_DFF"))) h->has_dff = numbers(v, &h->dff, 1) == 1;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_LORL"))) h->has_lorl = numbers(v, &h->lorl, 1) == 1;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_TILT")) && numbers(v, x, 1) == 1) h->tilt = x[0];
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_DR"))) h->has_ratios = numbers(v, h->ratios, 10) == 10;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_GAMMA"))) h->has_gamma = numbers(v, h->gamma_deg, 2) == 2;
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_COLOUR")))
        cdl_photometry_copy_text(h->colour, sizeof h->colour, v, strlen(v));
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_CRI"))) cdl_photometry_copy_text(h->cri, sizeof h->cri, v, strlen(v));
    if ((v = cdl_photometry_keyword_value(p, "_EULUMDAT_FLUX")) && numbers(v, x, 1) == 1 && x[0] > 0.0)
        h->absolute_flux = x[0];
    for (size_t i = 0; i < m->keyword_count; ++i)
        if (cdl_photometry_strcaseeq(m->keywords[i].key, "_EULUMDAT_LAMPSET") &&
            h->extra_sets < sizeof h->sets / sizeof *h->sets && lamp_set(m->keywords[i].value, &h->sets[h->extra_sets]))
            ++h->extra_sets;
}

void cdl_ldt_header_of(const cdl_photometry *p, cdl_ldt_header *h)
{
    memset(h, 0, sizeof *h);
    h->ityp = h->isym = h->mc = -1;
    const cdl_photometry_metadata *m = &p->meta;
    if (m->format != CDL_PHOTOMETRY_FORMAT_EULUMDAT) {
        from_keywords(p, h);
        return;
    }
    h->ityp = m->ldt_ityp;
    h->isym = m->ldt_isym;
    h->mc = (int)m->file_horizontal_count;
    h->has_luminaire = h->has_heights = h->has_dff = h->has_lorl = h->has_ratios = 1;
    memcpy(h->luminaire_mm, m->ldt_luminaire_mm, sizeof h->luminaire_mm);
    memcpy(h->heights_mm, m->ldt_luminous_height_mm, sizeof h->heights_mm);
    h->dff = m->ldt_dff_percent;
    h->lorl = m->ldt_lorl_percent;
    h->tilt = m->ldt_measurement_tilt_deg;
    memcpy(h->ratios, m->ldt_direct_ratios, sizeof h->ratios);
    snprintf(h->colour, sizeof h->colour, "%s", m->lamp_sets[0].colour);
    snprintf(h->cri, sizeof h->cri, "%s", m->lamp_sets[0].cri);
    for (size_t k = 1; k < m->lamp_set_count; ++k) h->sets[h->extra_sets++] = m->lamp_sets[k];
    if (m->absolute) h->absolute_flux = m->lamp_sets[0].flux_lm;
    h->has_gamma = 1;
    h->gamma_deg[0] = p->v[0];
    h->gamma_deg[1] = p->v[p->nv - 1];
}

/* "a b c" with ten significant digits each (the writers' precision). */
static void list(char *out, size_t size, const double *x, int n)
{
    size_t at = 0;
    out[0] = '\0';
    for (int k = 0; k < n && at < size; ++k) at += (size_t)snprintf(out + at, size - at, "%s%.10g", k ? " " : "", x[k]);
}

void cdl_ldt_header_keywords(const cdl_photometry *p, cdl_keyword_sink sink, void *context)
{
    const cdl_photometry_metadata *m = &p->meta;
    cdl_ldt_header h;
    cdl_ldt_header_of(p, &h);
    char value[512];
    snprintf(value, sizeof value, "%d", h.ityp);
    sink(context, "_EULUMDAT_ITYP", value);
    snprintf(value, sizeof value, "%d", h.isym);
    sink(context, "_EULUMDAT_ISYM", value);
    snprintf(value, sizeof value, "%d", h.mc);
    sink(context, "_EULUMDAT_MC", value);
    list(value, sizeof value, h.luminaire_mm, 3);
    sink(context, "_EULUMDAT_LUMINAIRE", value);
    list(value, sizeof value, h.heights_mm, 4);
    sink(context, "_EULUMDAT_LUMINOUS_HEIGHTS", value);
    list(value, sizeof value, &h.dff, 1);
    sink(context, "_EULUMDAT_DFF", value);
    list(value, sizeof value, &h.lorl, 1);
    sink(context, "_EULUMDAT_LORL", value);
    list(value, sizeof value, &h.tilt, 1);
    sink(context, "_EULUMDAT_TILT", value);
    if (h.colour[0]) sink(context, "_EULUMDAT_COLOUR", h.colour);
    if (h.cri[0]) sink(context, "_EULUMDAT_CRI", h.cri);
    for (size_t k = 0; k < h.extra_sets; ++k) {
        const cdl_photometry_lamp_set *s = &h.sets[k];
        snprintf(value, sizeof value, "%d | %s | %.10g | %s | %s | %.10g", s->count, s->type, s->flux_lm, s->colour,
                 s->cri, s->watts);
        sink(context, "_EULUMDAT_LAMPSET", value);
    }
    list(value, sizeof value, h.ratios, 10);
    sink(context, "_EULUMDAT_DR", value);
    /* LM-63's type C gamma runs from 0 or 90 to 90 or 180 (ies_write.c pads the rest) */
    int lm63_range = (h.gamma_deg[0] == 0.0 || h.gamma_deg[0] == 90.0) &&
                     (h.gamma_deg[1] == 90.0 || h.gamma_deg[1] == 180.0);
    if (!lm63_range) {
        list(value, sizeof value, h.gamma_deg, 2);
        sink(context, "_EULUMDAT_GAMMA", value);
    }
    if (m->ldt_file_name[0]) sink(context, "_EULUMDAT_FILENAME", m->ldt_file_name);
    if (h.absolute_flux > 0.0) {
        list(value, sizeof value, &h.absolute_flux, 1);
        sink(context, "_EULUMDAT_FLUX", value);
    }
}
