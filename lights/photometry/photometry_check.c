/* photometry_check.c - consistency between a file's header and its table.
 *
 * Each finding is a warning (an error with --strict):
 *  - output ratio above 1: the table holds more flux than the rated lamps;
 *  - EULUMDAT: the stated light output ratio LORL disagrees with the table
 *    (equivalently the integrated flux is far from lamp flux x LORL);
 *  - EULUMDAT: the stated downward flux fraction DFF disagrees;
 *  - IES absolute photometry: the integrated flux is far from a luminaire
 *    flux stated in a keyword ([_ABSOLUTELUMENS], [_TOTALLUMINAIRELUMENS]);
 *  - and where the candela multiplier explains such a mismatch (the table
 *    without it would agree), the warning says so with that flux;
 *  - efficacy (flux x output factor / input watts) above 683 lm/W, the
 *    luminous efficacy of monochromatic 555 nm radiation (CIE S 017:2020,
 *    17-21-053: K_m = 683 lm/W), which no light can exceed; or above what
 *    the lamp type the file names can reach (lamp_efficacy_limits).
 * Files in radiometric units (W/sr) have no lumens and skip the efficacy checks.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/photometry/photometry_internal.h"
#include "radiometry/constants.h"

/* A stated downward fraction may differ from the table's by rounding of
 * the table and of DFF itself; real files agree within 1 point. */
#define DFF_TOLERANCE_POINTS 2.0

/* An output ratio up to 1 % above 1 is integration round-off in real LED
 * files whose lamp flux is the luminaire flux (LORL 100 %); beyond that the
 * table holds more light than the lamps. */
#define LOR_TOLERANCE 0.01

/* Upper ends of lamp efficacy by lamp type, lamp lumens per lamp watt (a
 * luminaire's efficacy is lower still): rounded up from the ranges of the
 * IES Lighting Handbook, 10th ed. (2011), ch. 7, and for LEDs the 303
 * lm/W laboratory record for a white LED (Cree, 2014). Matched as words
 * in the lamp description, case-insensitively, first match wins. */
static const struct {
    const char *word;
    double max_lm_per_w;
    const char *type;
} lamp_efficacy_limits[] = {
    {"LED", 310.0, "LED"},
    {"halogen", 35.0, "halogen"},
    {"incandescent", 25.0, "incandescent"},
    {"low pressure sodium", 210.0, "low-pressure sodium"},
    {"LPS", 210.0, "low-pressure sodium"},
    {"SOX", 210.0, "low-pressure sodium"},
    {"high pressure sodium", 160.0, "high-pressure sodium"},
    {"HPS", 160.0, "high-pressure sodium"},
    {"SON", 160.0, "high-pressure sodium"},
    {"metal halide", 150.0, "metal halide"},
    {"HQI", 150.0, "metal halide"},
    {"CDM", 150.0, "metal halide"},
    {"mercury", 65.0, "mercury vapour"},
    {"fluorescent", 120.0, "fluorescent"},
    {"T5", 120.0, "fluorescent"},
    {"T8", 120.0, "fluorescent"},
    {"CFL", 120.0, "fluorescent"},
};

/* Does `word` stand as a word in `text` (case-insensitive; not inside a longer word)? */
static int has_word(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *s = text; *s; ++s) {
        size_t k = 0;
        while (k < n && s[k] && tolower((unsigned char)s[k]) == tolower((unsigned char)word[k])) ++k;
        if (k != n) continue;
        int before = s == text || !isalnum((unsigned char)s[-1]);
        int after = !isalnum((unsigned char)s[n]);
        if (before && after) return 1;
    }
    return 0;
}

/* The file's lamp description: EULUMDAT lamp set 1's type, IES [LAMP]. */
static const char *lamp_text(const cdl_photometry *p)
{
    if (p->meta.lamp_set_count > 0 && p->meta.lamp_sets[0].type[0]) return p->meta.lamp_sets[0].type;
    for (size_t i = 0; i < p->meta.keyword_count; ++i)
        if (cdl_photometry_strcaseeq(p->meta.keywords[i].key, "LAMP")) return p->meta.keywords[i].value;
    return NULL;
}

/* Efficacy above physics, or above the named lamp type. */
static cdl_status check_efficacy(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->radiometric || !(m->input_watts > 0.0) || !(p->flux_lm > 0.0)) return CDL_OK;
    double efficacy = p->flux_lm * cdl_photometry_output_factor(p) / m->input_watts;
    if (efficacy > CDL_KM_PHOTOPIC_LM_PER_W)
        return cdl_photometry_add_warning(p, "efficacy-above-683", 0,
                                          "%s: efficacy %.4g lm/W (%.6g lm from %.6g W) is above %g lm/W, the "
                                          "efficacy of monochromatic 555 nm light, which no light source can "
                                          "exceed: are the input watts or the lumens wrong?",
                                          name, efficacy, p->flux_lm * cdl_photometry_output_factor(p),
                                          m->input_watts, CDL_KM_PHOTOPIC_LM_PER_W);
    const char *lamp = lamp_text(p);
    for (size_t k = 0; lamp && k < sizeof lamp_efficacy_limits / sizeof lamp_efficacy_limits[0]; ++k) {
        if (!has_word(lamp, lamp_efficacy_limits[k].word)) continue;
        if (efficacy > lamp_efficacy_limits[k].max_lm_per_w)
            return cdl_photometry_add_warning(p, "efficacy-above-lamp", 0,
                                              "%s: efficacy %.4g lm/W is above what %s lamps reach (at most about "
                                              "%.0f lm/W; the lamp is \"%.60s\"): are the input watts or the "
                                              "lumens wrong?",
                                              name, efficacy, lamp_efficacy_limits[k].type,
                                              lamp_efficacy_limits[k].max_lm_per_w, lamp);
        break;
    }
    return CDL_OK;
}

/* When the table's flux disagrees with what the header expects and the
 * table without its candela multiplier would agree: say so. */
static void multiplier_note(const cdl_photometry *p, double expected, double tolerance, char *out, size_t size)
{
    double k = p->meta.candela_multiplier;
    out[0] = '\0';
    if (!(k > 0.0) || k == 1.0 || !(expected > 0.0)) return;
    double without = p->flux_lm / k;
    if (fabs(without - expected) <= tolerance * expected)
        snprintf(out, size, "; the table integrates to %.6g %s without the %g multiplier, which agrees: is the "
                 "multiplier applied twice, or meant for other units?", without, cdl_photometry_flux_unit(p), k);
}

static const char *const luminaire_flux_keywords[] = {"_ABSOLUTELUMENS", "_TOTALLUMINAIRELUMENS", "_LUMINAIRELUMENS"};

const char *cdl_photometry_where(char *buf, size_t size, const char *name, unsigned line)
{
    if (line) snprintf(buf, size, "%s:%u", name, line);
    else snprintf(buf, size, "%s", name);
    return buf;
}

/* Output ratio above 1: the table holds more flux than the rated lamps. */
static cdl_status check_output_ratio(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->absolute || !(m->rated_lamp_flux_lm > 0.0)) return CDL_OK;
    double flux = p->flux_lm, lor = flux / m->rated_lamp_flux_lm;
    const char *unit = cdl_photometry_flux_unit(p);
    char note[200] = "", at[1100];
    /* Without the multiplier the table would hold at most the lamps' flux. */
    if (m->candela_multiplier > 1.0 && flux / m->candela_multiplier <= m->rated_lamp_flux_lm * (1.0 + LOR_TOLERANCE))
        snprintf(note, sizeof note, "; the table integrates to %.6g %s without the %g multiplier, within the "
                 "lamps' flux: is the multiplier meant for other units?", flux / m->candela_multiplier, unit,
                 m->candela_multiplier);
    if (!(lor > 1.0 + LOR_TOLERANCE)) return CDL_OK;
    return cdl_photometry_add_warning(
        p, "lor-above-1", p->lamp_flux_line,
        "%s: output ratio above 1: the table integrates to %.6g %s, %.1f %% of the rated lamp flux %.6g %s "
        "(expected at most 100 %%)%s",
        cdl_photometry_where(at, sizeof at, name, p->lamp_flux_line), flux, unit, 100.0 * lor,
        m->rated_lamp_flux_lm, unit, note[0] ? note : lor > 1.5 ? "; is the number of lamps or the lumens per lamp wrong?" : "");
}

/* EULUMDAT's stated LORL and DFF against the table. */
static cdl_status check_ldt_ratios(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    double flux = p->flux_lm;
    const char *unit = cdl_photometry_flux_unit(p);
    char at[1100];
    cdl_status st = CDL_OK;
    if (m->format != CDL_PHOTOMETRY_FORMAT_EULUMDAT) return CDL_OK;
    if (m->ldt_lorl_percent > 0.0) {
        /* cd/klm tables integrate to LORL: Phi / Phi_lamp = LORL / 100 */
        double lamp = m->lamp_sets[0].flux_lm;
        double stated = lamp * m->ldt_lorl_percent / 100.0;
        if (stated > 0.0 && fabs(flux - stated) > CDL_PHOTOMETRY_FLUX_TOLERANCE * stated)
            st = cdl_photometry_add_warning(p, "ldt-lorl-mismatch", p->lorl_line,
                                            "%s: stated light output ratio LORL %.4g %% disagrees with the table, "
                                            "which integrates to %.4g %% of the lamp flux (expected lamp flux x LORL "
                                            "= %.6g %s within %.0f %%, found %.6g %s)",
                                            cdl_photometry_where(at, sizeof at, name, p->lorl_line),
                                            m->ldt_lorl_percent, 100.0 * flux / lamp, stated, unit,
                                            100.0 * CDL_PHOTOMETRY_FLUX_TOLERANCE, flux, unit);
    }
    if (st == CDL_OK && flux > 0.0) {
        double down = 100.0 * cdl_photometry_zone_flux(p, 0.0, 90.0).lm / flux;
        if (fabs(down - m->ldt_dff_percent) > DFF_TOLERANCE_POINTS)
            st = cdl_photometry_add_warning(p, "ldt-dff-mismatch", p->dff_line,
                                            "%s: stated downward flux fraction DFF %.4g %% disagrees with the table "
                                            "(expected the table's %.4g %% within %.0f points)",
                                            cdl_photometry_where(at, sizeof at, name, p->dff_line),
                                            m->ldt_dff_percent, down, DFF_TOLERANCE_POINTS);
    }
    return st;
}

/* The first number of a keyword's value, or 0 when it does not start with one. */
static int leading_number(const char *v, double *x)
{
    size_t n = 0;
    while (v[n] && v[n] != ' ' && v[n] != '\t' && v[n] != '\n') ++n;
    char number[64];
    if (n == 0 || n >= sizeof number) return 0;
    memcpy(number, v, n);
    number[n] = '\0';
    char *end = NULL;
    *x = strtod(number, &end);
    return end == number + n && *x > 0.0 && isfinite(*x);
}

/* IES absolute photometry: the integral against a luminaire flux stated in
 * a keyword. A radiometric file's "lumens" keyword holds its table's unit
 * (UV makers write "Lumens-> mW"): compared, and named, in that unit. */
static cdl_status check_stated_flux(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->format != CDL_PHOTOMETRY_FORMAT_IES || !m->absolute) return CDL_OK;
    const char *unit = cdl_photometry_flux_unit(p);
    for (size_t k = 0; k < sizeof luminaire_flux_keywords / sizeof *luminaire_flux_keywords; ++k) {
        const cdl_photometry_keyword *kw = NULL;
        for (size_t i = 0; i < m->keyword_count && !kw; ++i)
            if (cdl_photometry_strcaseeq(m->keywords[i].key, luminaire_flux_keywords[k])) kw = &m->keywords[i];
        double stated;
        if (!kw || !leading_number(kw->value, &stated)) continue;
        double flux = p->flux_lm;
        if (fabs(flux - stated) <= CDL_PHOTOMETRY_FLUX_TOLERANCE * stated) return CDL_OK;
        char note[200], at[1100], read_as[160] = "";
        multiplier_note(p, stated, CDL_PHOTOMETRY_FLUX_TOLERANCE, note, sizeof note);
        if (m->radiometric)
            snprintf(read_as, sizeof read_as, " (a lumen keyword, read in %s: the table is radiant intensity in "
                     "%s, and a radiometric file has no lumens)", unit, cdl_photometry_intensity_unit(p));
        return cdl_photometry_add_warning(p, "stated-flux-mismatch", kw->line,
                                          "%s: the integrated %s %.6g %s is far from the luminaire flux %g %s "
                                          "stated in [%s]%s (%+.1f %%; expected within %.0f %%)%s",
                                          cdl_photometry_where(at, sizeof at, name, kw->line),
                                          m->radiometric ? "radiant flux" : "flux", flux, unit, stated, unit,
                                          luminaire_flux_keywords[k], read_as, 100.0 * (flux - stated) / stated,
                                          100.0 * CDL_PHOTOMETRY_FLUX_TOLERANCE, note);
    }
    return CDL_OK;
}

cdl_status cdl_photometry_check_consistency(cdl_photometry *p, const char *name)
{
    cdl_status st = check_output_ratio(p, name);
    if (st == CDL_OK) st = check_ldt_ratios(p, name);
    if (st == CDL_OK) st = check_stated_flux(p, name);
    if (st == CDL_OK) st = check_efficacy(p, name);
    if (st == CDL_OK) st = cdl_photometry_check_fields(p, name);
    return st;
}
