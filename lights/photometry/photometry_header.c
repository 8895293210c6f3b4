/* photometry_header.c - what a photometric file says besides its table, through the public accessors. */
#include "lights/photometry/photometry_internal.h"

cdl_photometry_format cdl_photometry_get_format(const cdl_photometry *p)
{
    return p->meta.format;
}

int cdl_photometry_ies_version(const cdl_photometry *p)
{
    return p->meta.ies_version;
}

double cdl_photometry_input_watts(const cdl_photometry *p)
{
    return p->meta.input_watts;
}

double cdl_photometry_ballast_factor(const cdl_photometry *p)
{
    return p->meta.ballast_factor;
}

int cdl_photometry_is_absolute(const cdl_photometry *p)
{
    return p->meta.absolute;
}

int cdl_photometry_is_radiometric(const cdl_photometry *p)
{
    return p->meta.radiometric;
}

const cdl_luminous_opening *cdl_photometry_opening(const cdl_photometry *p)
{
    return &p->meta.opening;
}

size_t cdl_photometry_lamp_set_count(const cdl_photometry *p)
{
    return p->meta.lamp_set_count;
}

int cdl_photometry_get_lamp_set(const cdl_photometry *p, size_t index, cdl_photometry_lamp_set *out)
{
    if (index >= p->meta.lamp_set_count) return 0;
    *out = p->meta.lamp_sets[index];
    return 1;
}

size_t cdl_photometry_keyword_count(const cdl_photometry *p)
{
    return p->meta.keyword_count;
}

const char *cdl_photometry_keyword_name(const cdl_photometry *p, size_t index)
{
    return index < p->meta.keyword_count ? p->meta.keywords[index].key : NULL;
}

const char *cdl_photometry_keyword_text(const cdl_photometry *p, size_t index)
{
    return index < p->meta.keyword_count ? p->meta.keywords[index].value : NULL;
}

const char *cdl_photometry_get_text(const cdl_photometry *p, cdl_photometry_text which)
{
    const cdl_photometry_metadata *m = &p->meta;
    int ldt = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT;
    const char *text = NULL;
    switch (which) {
    case CDL_PHOTOMETRY_MANUFACTURER: text = ldt ? m->ldt_company : cdl_photometry_keyword_value(p, "MANUFAC"); break;
    case CDL_PHOTOMETRY_LUMINAIRE: text = ldt ? m->ldt_luminaire_name : cdl_photometry_keyword_value(p, "LUMINAIRE"); break;
    case CDL_PHOTOMETRY_CATALOGUE: text = ldt ? m->ldt_luminaire_number : cdl_photometry_keyword_value(p, "LUMCAT"); break;
    case CDL_PHOTOMETRY_LAMP:
        if (ldt) text = m->lamp_set_count ? m->lamp_sets[0].type : NULL;
        else if (!(text = cdl_photometry_keyword_value(p, "LAMP"))) text = cdl_photometry_keyword_value(p, "LAMPCAT");
        break;
    }
    return text ? text : "";
}
