/* photometry_check_fields.c - a header's fields against the standards
 * and against each other (what a photometric lab's checker looks at).
 *
 * Each finding is a warning with a stable code (docs/photometry-warnings.md):
 *  - ies-required-keyword: an LM-63-2019 file without [TEST], [TESTLAB],
 *    [ISSUEDATE] or [MANUFAC], which that edition requires;
 *  - ies-file-generation-type: an LM-63-2019 file-generation type that is
 *    none of the standard's ten codes;
 *  - ballast-factor-range: a ballast factor outside 0.5..1.3;
 *  - ldt-text-length: EULUMDAT text lines 1, 8, 9, 10 or 12 longer than the
 *    format's 78 characters;
 *  - ldt-luminous-larger: a luminous area (lines 16-21) larger than the
 *    luminaire (lines 13-15);
 *  - ldt-measurement-tilt: a measurement tilt (line 25) outside -90..90;
 *  - ldt-direct-ratios: direct ratios (lines 27-36) above 1 or falling as
 *    the room index grows;
 *  - ldt-symmetry-indicator: a type indicator Ityp that the symmetry
 *    indicator Isym or the data contradict.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lights/photometry/photometry_internal.h"

/* The LM-63-2019 file generation types (record B field 2, section 5.9 of
 * the standard as FORMAT_NOTES 1.5 transcribes it): 1.abcde with flags
 * a accredited lab, b interpolated angles, c lumen-scaled, d computer
 * simulation, e undefined; these ten combinations are the standard's. */
static const double generation_types[] = {1.00001, 1.00010, 1.00000, 1.00100, 1.01000,
                                          1.01100, 1.10000, 1.10100, 1.11000, 1.11100};

/* Ballast factors of real ballasts: fluorescent and HID ballasts are rated
 * from about 0.7 (reduced-output) to 1.2 (high-output) of the reference
 * ballast's light (IES Lighting Handbook, 10th ed., ch. 7), LED drivers 1.
 * Outside 0.5..1.3 the field more likely holds something else (a
 * percentage, a multiplier or a dimming level). */
#define BALLAST_FACTOR_MIN 0.5
#define BALLAST_FACTOR_MAX 1.3

/* EULUMDAT text lines 1 and 8-12 hold at most 78 characters (Stockmar
 * 1990; the AGi32 and Helios32 transcriptions of the format). Line 11,
 * the file name, is listed at 8 (a DOS name): real files ignore that
 * limit, and it is not checked. */
#define LDT_TEXT_MAX 78

/* A luminous dimension may exceed the luminaire's by rounding: both are
 * whole millimetres, often rounded to 5 or 10 mm. 1 % of the luminaire or
 * 1 mm, whichever is larger, is taken as rounding. */
#define LDT_DIMENSION_SLACK 0.01

static cdl_status check_required_keywords(cdl_photometry *p, const char *name)
{
    static const char *const required[4] = {"TEST", "TESTLAB", "ISSUEDATE", "MANUFAC"};
    if (p->meta.format != CDL_PHOTOMETRY_FORMAT_IES || p->meta.ies_version < 2019) return CDL_OK;
    char missing[64] = "";
    int count = 0;
    for (int k = 0; k < 4; ++k) {
        if (cdl_photometry_keyword_value(p, required[k])) continue;
        snprintf(missing + strlen(missing), sizeof missing - strlen(missing), "%s[%s]", count ? ", " : "",
                 required[k]);
        ++count;
    }
    if (!count) return CDL_OK;
    return cdl_photometry_add_warning(p, "ies-required-keyword", 0,
                                      "%s: expected the keywords LM-63-2019 requires ([TEST], [TESTLAB], "
                                      "[ISSUEDATE], [MANUFAC]), found no %s",
                                      name, missing);
}

static cdl_status check_generation_type(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    if (m->format != CDL_PHOTOMETRY_FORMAT_IES || m->ies_version < 2019) return CDL_OK;
    /* written with five decimals: a code is matched to half the last digit */
    for (size_t k = 0; k < sizeof generation_types / sizeof *generation_types; ++k)
        if (fabs(m->file_generation_type - generation_types[k]) < 5e-6) return CDL_OK;
    char at[1100];
    return cdl_photometry_add_warning(p, "ies-file-generation-type", p->generation_line,
                                      "%s: expected a file generation type of LM-63-2019 (1.00000, 1.00001, "
                                      "1.00010, 1.00100, 1.01000, 1.01100, 1.10000, 1.10100, 1.11000 or 1.11100), "
                                      "found %.6g (it is a code, not a factor: it changes no intensity)",
                                      cdl_photometry_where(at, sizeof at, name, p->generation_line),
                                      m->file_generation_type);
}

static cdl_status check_ballast_factor(cdl_photometry *p, const char *name)
{
    double bf = p->meta.ballast_factor;
    if (p->meta.format != CDL_PHOTOMETRY_FORMAT_IES || (bf >= BALLAST_FACTOR_MIN && bf <= BALLAST_FACTOR_MAX))
        return CDL_OK;
    char at[1100];
    return cdl_photometry_add_warning(p, "ballast-factor-range", p->ballast_line,
                                      "%s: expected a ballast factor between %g and %g (real ballasts give 0.7 to "
                                      "1.2 of the reference ballast's light), found %g: every flux and intensity "
                                      "of the luminaire is multiplied by it",
                                      cdl_photometry_where(at, sizeof at, name, p->ballast_line), BALLAST_FACTOR_MIN,
                                      BALLAST_FACTOR_MAX, bf);
}

static cdl_status check_text_lengths(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    const struct {
        const char *text, *what;
        unsigned line;
    } fields[] = {{m->ldt_company, "company", 1},         {m->ldt_report, "report number", 8},
                  {m->ldt_luminaire_name, "luminaire name", 9}, {m->ldt_luminaire_number, "luminaire number", 10},
                  {m->ldt_date_user, "date and user", 12}};
    cdl_status st = CDL_OK;
    for (size_t k = 0; k < sizeof fields / sizeof *fields && st == CDL_OK; ++k) {
        size_t n = strlen(fields[k].text);
        if (n <= LDT_TEXT_MAX) continue;
        char at[1100];
        st = cdl_photometry_add_warning(p, "ldt-text-length", fields[k].line,
                                        "%s: expected the %s (line %u) in at most %d characters (EULUMDAT), found "
                                        "%s%zu",
                                        cdl_photometry_where(at, sizeof at, name, fields[k].line), fields[k].what,
                                        fields[k].line, LDT_TEXT_MAX, n + 1 >= sizeof m->ldt_company ? "at least " : "",
                                        n);
    }
    return st;
}

/* Does a luminous dimension exceed the luminaire's beyond rounding? */
static int exceeds(double luminous, double luminaire)
{
    return luminaire > 0.0 && luminous > luminaire + fmax(1.0, LDT_DIMENSION_SLACK * luminaire);
}

static cdl_status check_dimensions(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    const double *lum = m->ldt_luminaire_mm, *area = m->ldt_luminous_mm, *h = m->ldt_luminous_height_mm;
    char what[160] = "";
    unsigned line = 0;
    /* a width of 0 means round: the length is then a diameter */
    double across = lum[1] > 0.0 ? lum[1] : lum[0];
    double area_across = area[1] > 0.0 ? area[1] : area[0];
    if (exceeds(area[0], lum[0])) {
        snprintf(what, sizeof what, "luminous %s %g mm (line 16) exceeds the luminaire's %g mm (line 13)",
                 area[1] > 0.0 ? "length" : "diameter", area[0], lum[0]);
        line = 16;
    } else if (exceeds(area_across, across)) {
        snprintf(what, sizeof what, "luminous %s %g mm (line %d) exceeds the luminaire's %s %g mm (line %d)",
                 area[1] > 0.0 ? "width" : "diameter", area_across, area[1] > 0.0 ? 17 : 16,
                 lum[1] > 0.0 ? "width" : "diameter", across, lum[1] > 0.0 ? 14 : 13);
        line = area[1] > 0.0 ? 17 : 16;
    } else {
        for (int k = 0; k < 4 && !line; ++k)
            if (exceeds(h[k], lum[2])) {
                snprintf(what, sizeof what, "luminous height %g mm in the C%d plane (line %d) exceeds the "
                         "luminaire's height %g mm (line 15)", h[k], 90 * k, 18 + k, lum[2]);
                line = (unsigned)(18 + k);
            }
    }
    if (!line) return CDL_OK;
    char at[1100];
    return cdl_photometry_add_warning(p, "ldt-luminous-larger", line,
                                      "%s: expected a luminous area no larger than the luminaire, found that the %s",
                                      cdl_photometry_where(at, sizeof at, name, line), what);
}

static cdl_status check_measurement_tilt(cdl_photometry *p, const char *name)
{
    double t = p->meta.ldt_measurement_tilt_deg;
    if (t >= -90.0 && t <= 90.0) return CDL_OK;
    char at[1100];
    return cdl_photometry_add_warning(p, "ldt-measurement-tilt", 25,
                                      "%s: expected the tilt of the luminaire during measurement within -90..90 "
                                      "degrees, found %g",
                                      cdl_photometry_where(at, sizeof at, name, 25), t);
}

/* Direct ratios are fractions of the luminaire's flux reaching the work
 * plane directly; a larger room (a larger room index) catches more of it,
 * so they grow with the index and never exceed 1. Rounding cannot make a
 * growing sequence fall. All zero: not given. */
static cdl_status check_direct_ratios(cdl_photometry *p, const char *name)
{
    const cdl_photometry_metadata *m = &p->meta;
    static const double k_index[10] = {0.6, 0.8, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0};
    const double *dr = m->ldt_direct_ratios;
    unsigned first = 26 + 6 * (unsigned)m->lamp_set_count + 1; /* line of the ratio for k = 0.6 */
    char at[1100];
    for (int k = 0; k < 10; ++k)
        if (dr[k] > 1.0 || dr[k] < 0.0)
            return cdl_photometry_add_warning(p, "ldt-direct-ratios", first + (unsigned)k,
                                              "%s: expected a direct ratio between 0 and 1 (a fraction of the "
                                              "luminaire's flux), found %g for room index %g",
                                              cdl_photometry_where(at, sizeof at, name, first + (unsigned)k), dr[k],
                                              k_index[k]);
    for (int k = 1; k < 10; ++k)
        if (dr[k] < dr[k - 1])
            return cdl_photometry_add_warning(p, "ldt-direct-ratios", first + (unsigned)k,
                                              "%s: expected direct ratios that grow with the room index, found %g "
                                              "for room index %g after %g for %g",
                                              cdl_photometry_where(at, sizeof at, name, first + (unsigned)k), dr[k],
                                              k_index[k], dr[k - 1], k_index[k - 1]);
    return CDL_OK;
}

/* Planes of a rotationally symmetric luminaire agree: within 1 % of the
 * peak, what measurement noise and rounding leave between planes. */
#define ROTATIONAL_TOLERANCE 0.01

/* The largest difference between a stored plane and the first, in cd. */
static double plane_spread(const cdl_photometry *p, size_t *plane, size_t *angle)
{
    double worst = 0.0;
    for (size_t i = 1; i < p->nh; ++i)
        for (size_t j = 0; j < p->nv; ++j) {
            double d = fabs(p->cd[i * p->nv + j] - p->cd[j]);
            if (d > worst) {
                worst = d;
                *plane = i;
                *angle = j;
            }
        }
    return worst;
}

/* The type indicator against the symmetry indicator and the data: Ityp 1
 * (a point source symmetric about the vertical axis) whose stored planes
 * differ, or Isym 1 (symmetric about the vertical axis) said of a linear
 * luminaire (Ityp 2), one without symmetry (Ityp 0) or one with another
 * symmetry (Ityp 3). */
static cdl_status check_indicators(cdl_photometry *p, const char *name)
{
    int ityp = p->meta.ldt_ityp, isym = p->meta.ldt_isym;
    static const char *const ityp_names[4] = {"a point source without symmetry",
                                              "a point source symmetric about the vertical axis",
                                              "a linear luminaire", "a point source with another symmetry"};
    char at[1100];
    if (ityp < 0 || ityp > 3) return CDL_OK; /* ldt-ityp says so */
    if (isym == 1 && ityp != 1)
        return cdl_photometry_add_warning(p, "ldt-symmetry-indicator", 3,
                                          "%s: the symmetry indicator Isym 1 (line 3: symmetry about the vertical "
                                          "axis) contradicts the type indicator Ityp %d (line 2: %s)",
                                          cdl_photometry_where(at, sizeof at, name, 3), ityp, ityp_names[ityp]);
    size_t plane = 0, angle = 0;
    double spread = ityp == 1 && p->nh > 1 ? plane_spread(p, &plane, &angle) : 0.0;
    if (!(spread > ROTATIONAL_TOLERANCE * p->max_cd)) return CDL_OK;
    return cdl_photometry_add_warning(p, "ldt-symmetry-indicator", 2,
                                      "%s: the type indicator Ityp 1 (a point source symmetric about the vertical "
                                      "axis) is contradicted by the data: the C%g plane differs from the C%g plane "
                                      "by %.3g cd at gamma %g (%.1f %% of the peak; expected within %.0f %%)",
                                      cdl_photometry_where(at, sizeof at, name, 2), p->h[plane], p->h[0], spread,
                                      p->v[angle], 100.0 * spread / p->max_cd, 100.0 * ROTATIONAL_TOLERANCE);
}

cdl_status cdl_photometry_check_fields(cdl_photometry *p, const char *name)
{
    cdl_status st = check_required_keywords(p, name);
    if (st == CDL_OK) st = check_generation_type(p, name);
    if (st == CDL_OK) st = check_ballast_factor(p, name);
    if (p->meta.format != CDL_PHOTOMETRY_FORMAT_EULUMDAT) return st;
    if (st == CDL_OK) st = check_text_lengths(p, name);
    if (st == CDL_OK) st = check_dimensions(p, name);
    if (st == CDL_OK) st = check_measurement_tilt(p, name);
    if (st == CDL_OK) st = check_direct_ratios(p, name);
    if (st == CDL_OK) st = check_indicators(p, name);
    return st;
}
