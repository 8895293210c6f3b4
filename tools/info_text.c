/* info_text.c - `candela info` as text: the summary of one file, and one line per file of a batch. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "info_output.h"
#include "lights/emitters/near_field_bound.h"
#include "solver/scene/scene.h"
#include "lights/photometry/photometry_metadata.h"

#define LABEL "%-16s"

static void print_angle(const char *label, const double a[2], int about_peak)
{
    printf(LABEL, label);
    for (int k = 0; k < 2; ++k) {
        if (a[k] >= 0.0) printf("%.1f deg", a[k]);
        else printf("not defined");
        if (about_peak) printf("%s", k == 0 ? " (vertical plane through the peak), " : " (across it)\n");
        else printf("%s", k == 0 ? " (C0-C180), " : " (C90-C270)\n");
    }
}

static void print_header(const char *path, const cdl_photometry *p)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    char version[32];
    cdl_info_version_text(m, version, sizeof version);
    printf(LABEL "%s\n", "file", path);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES)
        printf(LABEL "IES %s%s%s%s\n", "format", version, m->version_tag[0] ? " (tag '" : " (no version tag)",
               m->version_tag, m->version_tag[0] ? "')" : "");
    else
        printf(LABEL "EULUMDAT (Isym %d, Ityp %d)\n", "format", m->ldt_isym, m->ldt_ityp);
    const char *name = cdl_photometry_get_text(p, CDL_PHOTOMETRY_LUMINAIRE);
    const char *maker = cdl_photometry_get_text(p, CDL_PHOTOMETRY_MANUFACTURER);
    if (maker && *maker) printf(LABEL "%s\n", "manufacturer", maker);
    if (name && *name) printf(LABEL "%.*s\n", "luminaire", (int)strcspn(name, "\n"), name);
    printf(LABEL "type %s, symmetry %s, %zu x %zu angles in the file (%zu planes stored)\n", "photometry",
           cdl_info_type_letter(t.type), cdl_photometry_symmetry_name(t.symmetry), m->file_horizontal_count,
           m->file_vertical_count, t.horizontal_count);
}

/* Lamps, flux, LOR, power, efficacy and the output factor. */
static void print_flux(const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_photometry_summary *s = &f->s;
    double k = s->output_factor;
    int lamps = m->lamp_sets[0].count ? abs(m->lamp_sets[0].count) : 1;
    if (s->lamp_flux_known && !s->radiometric)
        printf(LABEL "%d x %.6g lm = %.6g lm rated (relative photometry)\n", "lamps", m->lamp_sets[0].count,
               s->lamp_flux.lm / lamps, s->lamp_flux.lm);
    else if (s->lamp_flux_known)
        printf(LABEL "%d lamp%s, %.6g W rated (relative photometry)\n", "lamps", lamps, lamps == 1 ? "" : "s",
               m->rated_lamp_flux_lm * m->radiometric_scale);
    else
        printf(LABEL "absolute photometry (no lamp reference)\n", "lamps");
    char factor[96] = "";
    if (k != 1.0) snprintf(factor, sizeof factor, " with the output factor %g", k);
    if (s->radiometric) {
        double u = m->radiometric_scale;
        printf(LABEL "%.6g W radiant%s (integrated; the table is radiant intensity in %s, as [%s] says: no lumens)",
               "flux", s->radiant_flux.W * k, factor, u == 1e-3 ? "mW/sr" : u == 1e-6 ? "uW/sr" : "W/sr",
               m->units_keyword);
        if (k != 1.0) printf(", %.6g W as tabulated", s->radiant_flux.W);
    } else {
        printf(LABEL "%.6g lm%s (integrated)", "flux", s->luminaire_flux.lm, factor);
        if (k != 1.0) printf(", %.6g lm as tabulated", s->flux.lm);
    }
    printf(", downward %.1f %%, upward %.1f %%\n", 100.0 * s->downward_fraction, 100.0 * s->upward_fraction);
    if (s->lor_known) printf(LABEL "%.1f %%\n", "LOR", 100.0 * s->lor);
    if (m->input_watts > 0.0) printf(LABEL "%.6g W\n", "input power", m->input_watts);
    if (s->efficacy_known) printf(LABEL "%.1f lm/W%s\n", "efficacy", s->efficacy.lm_W, k != 1.0 ? factor : "");
    if (k != 1.0) {
        printf(LABEL "%.4g: the ballast factor %g", "output factor", k, m->ballast_factor);
        if (k != m->ballast_factor) printf(" x the ballast-lamp factor %g", m->ballast_lamp_factor);
        printf(", applied to every flux and intensity shown, as in a scene (EULUMDAT, which has no field for it, "
               "carries it in its lamp flux)\n");
    }
}

static void print_peak(const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_photometry_summary *s = &f->s;
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    if (s->radiometric)
        printf(LABEL "%.6g W/sr at C %.4g, gamma %.4g", "max intensity", s->max_radiant_intensity.W_sr * s->output_factor,
               s->max_c_deg, s->max_gamma_deg);
    else
        printf(LABEL "%.6g cd at C %.4g, gamma %.4g", "max intensity", s->luminaire_max_intensity.cd, s->max_c_deg,
               s->max_gamma_deg);
    if (s->output_factor != 1.0 && !s->radiometric) printf(" (%.6g cd as tabulated)", s->max_intensity.cd);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES && t.type == CDL_PHOTOMETRIC_TYPE_C)
        printf(" (IES H %.4g, V %.4g)", fmod(360.0 - s->max_c_deg, 360.0), s->max_gamma_deg);
    else if (t.type != CDL_PHOTOMETRIC_TYPE_C)
        printf(" (type %s H %.4g, V %.4g)", cdl_info_type_letter(t.type), s->max_h_deg, s->max_v_deg);
    printf("\n");
    print_angle("beam angle", s->beam_angle_deg, s->spread_about_peak);
    print_angle("field angle", s->field_angle_deg, s->spread_about_peak);
    if (s->spread_about_peak)
        printf(LABEL "peak at C %.4g, gamma %.4g (its maximum lies off nadir: angles about it)\n", "beam axis",
               s->spread_axis_c_deg, s->spread_axis_gamma_deg);
}

/* The opening named as the file names it: EULUMDAT's luminous length (line
 * 16) lies along C90-C270 and its width (line 17) along C0-C180; IES's
 * width, length, height, the length along C0-C180. */
static void print_opening(const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_luminous_opening *o = &m->opening;
    printf(LABEL "%s", "opening", cdl_luminous_shape_name(o->shape));
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT && o->shape != CDL_LUMINOUS_SHAPE_POINT) {
        const double *a = m->ldt_luminous_mm;
        if (a[1] > 0.0) printf(", length %g mm (along C90-C270) x width %g mm (along C0-C180)", fabs(a[0]), fabs(a[1]));
        else printf(", diameter %g mm", fabs(a[0]));
        if (o->height_m > 0.0) printf(", luminous height %.4g mm", 1000.0 * o->height_m);
        printf(" (EULUMDAT lines 16-21)");
    } else if (o->shape != CDL_LUMINOUS_SHAPE_POINT) {
        printf(", %.4g x %.4g x %.4g m (width x length x height; the length along C0-C180)", o->width_m, o->length_m,
               o->height_m);
    }
    const double *sh = o->side_height_m;
    if (o->shape == CDL_LUMINOUS_SHAPE_BOX && (sh[0] > 0.0 || sh[1] > 0.0 || sh[2] > 0.0 || sh[3] > 0.0))
        printf(", sides luminous to %.4g (C0), %.4g (C90), %.4g (C180), %.4g (C270) m, the height their mean", sh[0],
               sh[1], sh[2], sh[3]);
    printf("\n");
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) {
        const double *l = m->ldt_luminaire_mm;
        if (l[1] > 0.0) printf(LABEL "length %g x width %g x height %g mm (EULUMDAT lines 13-15)\n", "luminaire", l[0],
                               l[1], l[2]);
        else printf(LABEL "diameter %g x height %g mm (EULUMDAT lines 13-15)\n", "luminaire", l[0], l[2]);
    }
    double targets[4] = {cdl_quality_target_error(CDL_QUALITY_DRAFT), cdl_quality_target_error(CDL_QUALITY_NORMAL),
                         cdl_quality_target_error(CDL_QUALITY_HIGH), cdl_quality_target_error(CDL_QUALITY_REFERENCE)};
    double d[4];
    if (cdl_luminous_opening_is_spread(o) && cdl_near_field_switch_distances(p, targets, 4, d, NULL) == CDL_OK)
        printf(LABEL "spread over its opening within %.3g m at draft, %.3g at normal, %.3g at high, %.3g at "
                     "reference (where a point model would err by more than %g of the target; never within %g x "
                     "its largest dimension %.3g m)\n",
               "near field", d[0], d[1], d[2], d[3], CDL_NEAR_FIELD_SHARE, CDL_NEAR_FIELD_DISTANCES,
               cdl_luminous_opening_largest_m(o));
    cdl_luminance nadir, max, c0, c90;
    cdl_photometry_opening_luminance(p, 0.0, 0.0, &nadir, &max);
    cdl_photometry_opening_luminance(p, 0.0, 65.0, &c0, &max);
    cdl_photometry_opening_luminance(p, 90.0, 65.0, &c90, &max);
    if (nadir.cd_m2 > 0.0 || c0.cd_m2 > 0.0 || c90.cd_m2 > 0.0)
        printf(LABEL "%.4g %s at nadir; %.4g (C0) and %.4g (C90) at gamma 65 (average over the opening)\n",
               f->s.radiometric ? "radiance" : "luminance", nadir.cd_m2 * f->scale,
               f->s.radiometric ? "W/m2/sr" : "cd/m2", c0.cd_m2 * f->scale, c90.cd_m2 * f->scale);
    if (m->tilt_count > 0)
        printf(LABEL "%zu angles, geometry %d (factors %.4g..%.4g)\n", "tilt", m->tilt_count, m->tilt_geometry,
               m->tilt_factors[0], m->tilt_factors[m->tilt_count - 1]);
}

static void print_zones(const cdl_info_figures *f)
{
    const cdl_photometry_summary *s = &f->s;
    printf(LABEL, s->radiometric ? "zones (W)" : "zones (lm)");
    for (int k = 0; k < 18; ++k) {
        double v = s->radiometric ? s->radiant_zone_flux[k].W * s->output_factor
                                  : s->zone_flux[k].lm * s->output_factor;
        printf("%s%d-%d: %.4g", k == 0 ? "" : k % 6 == 0 ? "\n                " : ", ", 10 * k, 10 * k + 10, v);
    }
    printf("\n");
}

/* Direct ratios (computed, and as stated by an EULUMDAT file), CIE flux code, BUG rating. */
static void print_classification(const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    printf(LABEL "%.0f %.0f %.0f %.0f %.0f (N1-N3: %% of the downward flux within 41.4, 60, 75.5 deg of nadir; "
           "N4, N5: downward and total flux in %% of the lamp flux)\n",
           "CIE flux code", f->flux_code[0], f->flux_code[1], f->flux_code[2], f->flux_code[3], f->flux_code[4]);
    printf(LABEL, "direct ratios");
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k)
        printf("%s%.2f: %.3f", k ? ", " : "k ", cdl_direct_ratio_room_index(k), f->direct_ratio[k]);
    printf("\n" LABEL "(computed: share of the flux on the work plane, square room, luminaires at a spacing equal "
           "to their height above it)\n", "");
    int stated = 0;
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k) stated |= m->ldt_direct_ratios[k] != 0.0;
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT && stated) {
        printf(LABEL "stated (EULUMDAT lines 27-36): ", "");
        for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k) printf("%s%.3g", k ? ", " : "", m->ldt_direct_ratios[k]);
        printf("\n");
    }
    if (!f->bug_known) {
        printf(LABEL "not defined (the rating counts lumens; the table is radiant intensity)\n", "BUG rating");
        return;
    }
    printf(LABEL "B%d U%d G%d (IES TM-15-11; front towards C0, IES H0)\n" LABEL "lumens", "BUG rating", f->bug.b,
           f->bug.u, f->bug.g, "");
    for (int z = 0; z < CDL_BUG_ZONES; ++z) printf("%s%s %.4g", z ? ", " : " ", cdl_bug_zone_name(z), f->bug.zone_lm[z]);
    printf("\n");
}

void cdl_info_print_text(const char *path, const cdl_photometry *p, const cdl_info_figures *f)
{
    print_header(path, p);
    print_flux(p, f);
    print_peak(p, f);
    print_opening(p, f);
    print_zones(f);
    if (f->classified) print_classification(p, f);
    size_t nw = cdl_photometry_warning_count(p);
    if (nw == 0) printf(LABEL "none\n", "warnings");
    for (size_t i = 0; i < nw; ++i)
        printf(LABEL "[%s] %s\n", i == 0 ? "warnings" : "", cdl_photometry_warning_code(p, i),
               cdl_photometry_warning(p, i));
}

void cdl_info_print_line(const char *path, const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_photometry_summary *s = &f->s;
    char version[32], flux[64], efficacy[48] = "", beam[96];
    cdl_info_version_text(m, version, sizeof version);
    if (s->radiometric) snprintf(flux, sizeof flux, "%.5g W radiant", s->radiant_flux.W * s->output_factor);
    else snprintf(flux, sizeof flux, "%.5g lm", s->luminaire_flux.lm);
    if (s->efficacy_known) snprintf(efficacy, sizeof efficacy, ", %.4g lm/W", s->efficacy.lm_W);
    char a[2][24];
    for (int k = 0; k < 2; ++k)
        if (s->beam_angle_deg[k] >= 0.0) snprintf(a[k], sizeof a[k], "%.3g", s->beam_angle_deg[k]);
        else snprintf(a[k], sizeof a[k], "-");
    snprintf(beam, sizeof beam, "beam %s/%s deg%s", a[0], a[1], s->spread_about_peak ? " about the peak" : "");
    size_t nw = cdl_photometry_warning_count(p);
    printf("ok    %s: %s, %s%s, %s, %zu warning%s\n", path, version, flux, efficacy, beam, nw, nw == 1 ? "" : "s");
}
