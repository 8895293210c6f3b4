/* photometry_check.c - consistency between a file's header and its table.
 *
 * Each finding is a warning (an error with --strict):
 *  - output ratio above 1: the table holds more flux than the rated lamps;
 *  - EULUMDAT: the stated light output ratio LORL disagrees with the table
 *    (equivalently the integrated flux is far from lamp flux x LORL);
 *  - EULUMDAT: the stated downward flux fraction DFF disagrees;
 *  - IES absolute photometry: the integrated flux is far from a luminaire
 *    flux stated in a keyword ([_ABSOLUTELUMENS], [_TOTALLUMINAIRELUMENS]).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lights/photometry_io.h"

/* A stated downward fraction may differ from the table's by rounding of
 * the table and of DFF itself; real files agree within 1 point. */
#define DFF_TOLERANCE_POINTS 2.0

/* An output ratio up to 1 % above 1 is integration round-off in real LED
 * files whose lamp flux is the luminaire flux (LORL 100 %); beyond that the
 * table holds more light than the lamps. */
#define LOR_TOLERANCE 0.01

static const char *const luminaire_flux_keywords[] = {"_ABSOLUTELUMENS", "_TOTALLUMINAIRELUMENS", "_LUMINAIRELUMENS"};

/* "FILE:LINE" of the header value a warning is about, or "FILE" when the line is unknown. */
static const char *where(char *buf, size_t size, const char *name, unsigned line)
{
    if (line) snprintf(buf, size, "%s:%u", name, line);
    else snprintf(buf, size, "%s", name);
    return buf;
}

cdl_status cdl_photometry_check_consistency(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    double flux = p->flux_lm;
    cdl_status st = CDL_OK;
    char at[1100];
    if (!m->absolute && m->rated_lamp_flux_lm > 0.0) {
        double lor = flux / m->rated_lamp_flux_lm;
        if (lor > 1.0 + LOR_TOLERANCE)
            st = cdl_photometry_add_warning(
                p,
                "%s: output ratio above 1: the table integrates to %.6g lm, %.1f %% of the rated lamp flux %.6g lm "
                "(expected at most 100 %%)%s",
                where(at, sizeof at, name, p->lamp_flux_line), flux, 100.0 * lor, m->rated_lamp_flux_lm,
                lor > 1.5 ? "; is the number of lamps or the lumens per lamp wrong?" : "");
    }
    if (st == CDL_OK && m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT && m->ldt_lorl_percent > 0.0) {
        /* cd/klm tables integrate to LORL: Phi / Phi_lamp = LORL / 100 */
        double lamp = m->lamp_sets[0].flux_lm;
        double stated = lamp * m->ldt_lorl_percent / 100.0;
        if (stated > 0.0 && fabs(flux - stated) > CDL_PHOTOMETRY_FLUX_TOLERANCE * stated)
            st = cdl_photometry_add_warning(p,
                                            "%s: stated light output ratio LORL %.4g %% disagrees with the table, "
                                            "which integrates to %.4g %% of the lamp flux (expected lamp flux x LORL "
                                            "= %.6g lm within %.0f %%, found %.6g lm)",
                                            where(at, sizeof at, name, p->lorl_line), m->ldt_lorl_percent,
                                            100.0 * flux / lamp, stated, 100.0 * CDL_PHOTOMETRY_FLUX_TOLERANCE, flux);
    }
    if (st == CDL_OK && m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT && flux > 0.0) {
        double down = 100.0 * cdl_photometry_zone_flux(p, 0.0, 90.0).lm / flux;
        if (fabs(down - m->ldt_dff_percent) > DFF_TOLERANCE_POINTS)
            st = cdl_photometry_add_warning(p,
                                            "%s: stated downward flux fraction DFF %.4g %% disagrees with the table "
                                            "(expected the table's %.4g %% within %.0f points)",
                                            where(at, sizeof at, name, p->dff_line), m->ldt_dff_percent, down,
                                            DFF_TOLERANCE_POINTS);
    }
    if (st == CDL_OK && m->format == CDL_PHOTOMETRY_FORMAT_IES && m->absolute) {
        for (size_t k = 0; k < sizeof luminaire_flux_keywords / sizeof *luminaire_flux_keywords; ++k) {
            const char *v = NULL;
            unsigned line = 0;
            for (size_t i = 0; i < m->keyword_count && !v; ++i)
                if (cdl_photometry_strcaseeq(m->keywords[i].key, luminaire_flux_keywords[k])) {
                    v = m->keywords[i].value;
                    line = m->keywords[i].line;
                }
            if (!v) continue;
            double stated;
            const char *t = v;
            size_t n = 0;
            while (t[n] && t[n] != ' ' && t[n] != '\t' && t[n] != '\n') ++n;
            if (!cdl_photometry_parse_number(t, n, 0, &stated) || !(stated > 0.0) || !isfinite(stated)) continue;
            if (fabs(flux - stated) > CDL_PHOTOMETRY_FLUX_TOLERANCE * stated)
                st = cdl_photometry_add_warning(p,
                                                "%s: the integrated flux %.6g lm is far from the luminaire flux %g "
                                                "lm stated in [%s] (%+.1f %%; expected within %.0f %%)",
                                                where(at, sizeof at, name, line), flux, stated,
                                                luminaire_flux_keywords[k], 100.0 * (flux - stated) / stated,
                                                100.0 * CDL_PHOTOMETRY_FLUX_TOLERANCE);
            break;
        }
    }
    return st;
}
