/* photometry_units.c - files whose table is in radiometric units (W/sr), not candela.
 *
 * LM-63 tables are candela, but UV and infrared makers write radiant
 * intensity and say so in a keyword: [_INTENSITYUNITS] mW/sr, or any
 * keyword whose name contains "UNIT" whose value names watts per
 * steradian ("W/sr", "mW/sr", "uW/sr" or "µW/sr", in any case); or in
 * words, a keyword whose value names them beside "intensit", "candela" or
 * "expressed" ("Intensity values in this file are expressed in mW/sr",
 * "candela-> mW/sr"). Such a
 * table's integral is radiant flux in W (times the prefix), not lumens;
 * nothing turns it into light without a spectrum or an efficacy, so
 * `candela info` reports watts and a scene refuses it.
 */
#include <ctype.h>
#include <string.h>

#include "lights/photometry/photometry_internal.h"

/* Does `value` name watts per steradian? *scale: the prefix as a factor to W/sr. */
static int names_w_per_sr(const char *value, double *scale)
{
    static const struct {
        const char *unit;
        double scale;
    } units[] = {{"mW/sr", 1e-3}, {"uW/sr", 1e-6}, {"\xC2\xB5W/sr", 1e-6}, {"W/sr", 1.0}};
    for (const char *s = value; *s; ++s)
        for (size_t u = 0; u < sizeof units / sizeof units[0]; ++u) {
            size_t n = strlen(units[u].unit);
            size_t k = 0;
            while (k < n && s[k] && tolower((unsigned char)s[k]) == tolower((unsigned char)units[u].unit[k])) ++k;
            if (k == n) {
                *scale = units[u].scale;
                return 1;
            }
        }
    return 0;
}

/* Does `text` contain `word` (ASCII, case-insensitive)? */
static int contains(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *s = text; *s; ++s) {
        size_t k = 0;
        while (k < n && s[k] && tolower((unsigned char)s[k]) == tolower((unsigned char)word[k])) ++k;
        if (k == n) return 1;
    }
    return 0;
}

/* A keyword saying the table is in W/sr: by its name (pass 0), or in words (pass 1). */
static int says_radiometric(const cdl_photometry_keyword *k, int pass, double *scale)
{
    if (!names_w_per_sr(k->value, scale)) return 0;
    if (pass == 0) return contains(k->key, "UNIT");
    return contains(k->value, "intensit") || contains(k->value, "candela") || contains(k->value, "expressed");
}

void cdl_photometry_detect_units(cdl_photometry *p)
{
    cdl_photometry_metadata *m = &p->meta;
    m->radiometric = 0;
    m->radiometric_scale = 1.0;
    m->units_keyword[0] = '\0';
    for (int pass = 0; pass < 2; ++pass)
        for (size_t i = 0; i < m->keyword_count; ++i) {
            double scale = 1.0;
            if (!says_radiometric(&m->keywords[i], pass, &scale)) continue;
            m->radiometric = 1;
            m->radiometric_scale = scale;
            cdl_photometry_copy_text(m->units_keyword, sizeof m->units_keyword, m->keywords[i].key,
                                     strlen(m->keywords[i].key));
            return;
        }
}

const char *cdl_photometry_intensity_unit(const cdl_photometry *p)
{
    if (!p->meta.radiometric) return "cd";
    double k = p->meta.radiometric_scale;
    return k == 1e-3 ? "mW/sr" : k == 1e-6 ? "uW/sr" : "W/sr";
}

const char *cdl_photometry_flux_unit(const cdl_photometry *p)
{
    if (!p->meta.radiometric) return "lm";
    double k = p->meta.radiometric_scale;
    return k == 1e-3 ? "mW" : k == 1e-6 ? "uW" : "W";
}
