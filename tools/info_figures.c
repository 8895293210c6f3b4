/* info_figures.c - the figures `candela info` prints, computed once for the text and the JSON. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "info_output.h"
#include "lights/photometry/photometry_metadata.h"

int cdl_info_figures_compute(const cdl_photometry *p, int classify, cdl_info_figures *f)
{
    memset(f, 0, sizeof *f);
    cdl_photometry_summary_compute(p, &f->s);
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    f->scale = f->s.output_factor * (m->radiometric ? m->radiometric_scale : 1.0);
    if (!classify) return 1;
    cdl_error err;
    cdl_error_clear(&err);
    if (cdl_photometry_direct_ratios(p, f->direct_ratio, &err) != CDL_OK) return 0;
    cdl_photometry_cie_flux_code(p, f->flux_code);
    cdl_status st = cdl_photometry_bug_rating(p, &f->bug, &err);
    if (st == CDL_ERR_INTERNAL) return 0;
    f->bug_known = st == CDL_OK;
    f->classified = 1;
    return 1;
}

const char *cdl_info_type_letter(cdl_photometric_type t)
{
    return t == CDL_PHOTOMETRIC_TYPE_A ? "A" : t == CDL_PHOTOMETRIC_TYPE_B ? "B" : "C";
}

void cdl_info_version_text(const cdl_photometry_metadata *m, char *buf, size_t size)
{
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES) snprintf(buf, size, "LM-63-%d", m->ies_version);
    else if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) snprintf(buf, size, "EULUMDAT");
    else snprintf(buf, size, "table");
}

char *cdl_info_utf8(const char *s)
{
    size_t n = strlen(s);
    int valid = 1;
    for (size_t i = 0; i < n && valid;) {
        unsigned char c = (unsigned char)s[i];
        size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (len == 0 || i + len > n) valid = 0;
        for (size_t k = 1; valid && k < len; ++k)
            if (((unsigned char)s[i + k] >> 6) != 2) valid = 0;
        i += len ? len : 1;
    }
    char *out = malloc(2 * n + 1);
    if (!out) return NULL;
    if (valid) {
        memcpy(out, s, n + 1);
        return out;
    }
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x80) {
            out[k++] = (char)c;
        } else {
            out[k++] = (char)(0xC0 | (c >> 6));
            out[k++] = (char)(0x80 | (c & 0x3F));
        }
    }
    out[k] = '\0';
    return out;
}
