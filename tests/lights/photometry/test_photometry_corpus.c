/* The real files in ../shared/photometric: every file read or rejected as
 * its notes say, lab flux, converter pairs (which fix the C <-> H
 * convention), and round trips through both formats.
 *
 * Needs CANDELA_PHOTOMETRIC_DIR; says so and reports itself skipped (exit 77) when it is absent. */
// ctest-labels: corpus
// ctest-timeout: 600
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry_checks.h"
#include "lights/photometry/photometry_metadata.h"

#define DIR_ CANDELA_PHOTOMETRIC_DIR

typedef struct expectation {
    const char *file;
    const char *error;      /* substring of the error, or NULL: the file reads */
    const char *warning1;   /* substrings of the warnings (NULL: none expected) */
    const char *warning2;
} expectation;

/* From SOURCES.md's notes column and what each file holds. A file read
 * with no expected warning must have none. */
static const expectation expected[] = {
    {"ies_1986_reportheader_b.ies", NULL, "output ratio above 1", NULL}, /* 3340 lm from 3150 lm lamps */
    {"ies_1991_IESNA91_axial.ies", NULL, NULL, NULL},
    {"ies_1991_IESNA91_soft.ies", NULL, NULL, NULL},
    {"ies_1995_conv_inconsistent_lumens.ies", NULL, "output ratio above 1: the table integrates to 6150.48 lm", NULL},
    {"ies_1995_leadingspace_tag.ies", NULL, NULL, NULL},
    {"ies_1995_mult127_bilateral.ies", NULL, NULL, NULL},
    {"ies_1995_mult_eq_lumens.ies", NULL, NULL, NULL},
    {"ies_1995_quad_91x37.ies", NULL, NULL, NULL},
    {"ies_2002_tabs_bilateral.ies", NULL, NULL, NULL},
    /* radiometric table, a lumen keyword read in its unit */
    {"ies_CRonly_big.ies", NULL, "radiant flux 121.138 mW is far from the luminaire flux 91.6 mW stated in [_TOTALLUMINAIRELUMENS]", NULL},
    {"ies_archive_full_mult0667.ies", NULL, NULL, NULL},
    {"ies_dlip_1995_ellipsoid.ies", NULL, NULL, NULL},
    {"ies_dlip_1995_relative_mult.ies", NULL, "output ratio above 1", NULL},
    {"ies_dlip_1995_sphere.ies", NULL, NULL, NULL},
    {"ies_erco_1986_quad.ies", NULL, NULL, NULL},
    {"ies_erco_1995_uplight.IES", NULL, NULL, NULL},
    {"ies_eurs_absolute_led.ies", NULL, NULL, NULL},
    {"ies_eurs_tilt_include.ies", NULL, "output ratio above 1", "efficacy 322.7 lm/W is above what LED lamps reach"},
    /* synthetic: 3227 lm from 1000 lm, from 10 W of "LED Integrated" */
    {"ies_floodlight_2002_ratio_gt1.ies", NULL, "output ratio above 1", NULL},
    /* at the line of the last vertical angle */
    {"ies_gldf_H90-270_circle2002.ies", NULL,
     "circle2002.ies:15: expected vertical angles from 0 or 90 to 90 or 180 (LM-63), found vertical angles 0..140", NULL},
    {"ies_guv_lumenizer_seam.ies", NULL, "H = 0 and H = 360 rows differ", NULL},
    {"ies_guv_nukit_lantern.ies", NULL, NULL, NULL},
    {"ies_guv_ushio_b1_LF.ies", NULL, NULL, NULL},
    {"ies_indoor_full360_nolab.IES", NULL, NULL, NULL},
    {"ies_interlab_1995_1p3MB.ies", NULL, NULL, NULL},
    {"ies_italo_road_2002_88k.IES", NULL, NULL, NULL},
    {"ies_itl_indoor_quad.IES", NULL, NULL, NULL},
    {"ies_lightlab_uv_2002.ies", NULL, NULL, NULL},
    {"ies_lithonia_AF10_bf088.ies", NULL, NULL, NULL},
    {"ies_lithonia_AV_ASY_full360.ies", NULL, NULL, NULL},
    {"ies_lithonia_ELM2_typeB_abs.ies", NULL, NULL, NULL},
    {"ies_lithonia_LF6N_axial_2lamps.ies", NULL, NULL, NULL},
    {"ies_lithonia_OFL2_65F_typeB.ies", NULL, NULL, NULL},
    {"ies_lithonia_OFL_213F_typeB.ies", NULL, NULL, NULL},
    {"ies_lithonia_PMO_H90-270.ies", NULL, NULL, NULL},
    {"ies_lithonia_RV8_oddshape.ies", NULL, NULL, NULL},
    {"ies_luxcore_ASA_15M.ies", NULL, NULL, NULL},
    {"ies_luxera_MALFORMED_comments.ies", "ballast line (ballast factor, second factor, input watts) looks missing",
     NULL, NULL},
    {"ies_luxera_MALFORMED_tilt_file_simple.ies", "ballast line (ballast factor, second factor, input watts) looks missing",
     NULL, NULL},
    {"ies_maxwell_1995_full.IES", NULL, NULL, NULL},
    {"ies_phpy_2019_filegen.ies", NULL, NULL, NULL},
    {"ies_phpy_2019_tilt_include.ies", NULL, NULL, NULL},
    {"ies_phpy_2019_typeB_full.ies", NULL, NULL, NULL},
    {"ies_rab_flood_typeB_half.IES", NULL, NULL, NULL},
    {"ies_rab_indoor_bilateral_latin1.IES", NULL, NULL, NULL},
    {"ies_rab_roadway_bilateral.IES", NULL, NULL, NULL},
    {"ies_rab_roadway_quad.IES", NULL, NULL, NULL},
    {"ies_radiance_IESNA95_tag.ies", NULL, "non-standard version tag 'IESNA95'", NULL},
    {"ies_ruco_2002_circle.ies", NULL, NULL, NULL},
    {"ldt_avad_Isym4.ldt", NULL, NULL, NULL},
    {"ldt_bega_Isym1_absolute.ldt", NULL, NULL, NULL},
    /* Ityp 1 (rotationally symmetric) over Isym 3 data whose C90 and C270 planes differ */
    {"ldt_dlip_Isym3_synthetic.ldt", NULL, "stated light output ratio LORL 100 %",
     "Ityp 1 (a point source symmetric about the vertical axis) is contradicted by the data"},
    {"ldt_dlip_MALFORMED_truncated.ldt", "expected 949 numbers", NULL, NULL},
    {"ldt_dlip_three_lamp_sets.ldt", NULL, "stated light output ratio LORL 100 %", NULL},
    {"ldt_eurs_wiki_batwing_badLORL.ldt", NULL, "output ratio above 1", "stated light output ratio LORL 85 %"},
    {"ldt_gldf_two_lamp_sets_CRLF.ldt", NULL, NULL, NULL},
    {"ldt_ledvance_1200W_SYM10_Ng91.ldt", NULL, NULL, NULL},
    {"ldt_ledvance_600W_SYM30_CRLF.ldt", NULL, NULL, NULL},
    {"ldt_luxpy_Isym3.ldt", NULL, NULL, NULL},
    {"ldt_luxpy_Isym4_Mc144.ldt", NULL, NULL, NULL},
    {"ldt_min_example_Mc4.ldt", NULL, "stated downward flux fraction DFF 90 %", NULL},
    {"ldt_philips_projector_Isym2_Mc72.ldt", NULL, NULL, NULL},
    {"ldt_road_Isym3_Mc52.ldt", NULL, NULL, NULL},
    {"ldt_ruco_Isym1.ldt", NULL, NULL, NULL},
    {"ldt_vb_sample_isym0.ldt", NULL, NULL, NULL},
    {"ldt_zumtobel_ARCOS3_Isym1.LDT", NULL, NULL, NULL},
    {"ldt_zumtobel_LINETIK_Isym3_indirect.LDT", NULL, NULL, NULL},
    {"ldt_zumtobel_MIREL_Isym4.LDT", NULL, NULL, NULL},
    {"ldt_zumtobel_PERLUCE_Isym0_lor92.ldt", NULL, NULL, NULL},
    {"ldt_zumtobel_PERLUCE_Isym4.LDT", NULL, NULL, NULL},
    {"ldt_zumtobel_TECTON_Isym0.LDT", NULL, NULL, NULL},
    {"ldt_zumtobel_floor_uplight.ldt", NULL, NULL, NULL},
};
#define NEXPECTED (sizeof expected / sizeof *expected)

static cdl_photometry *load(const char *name, cdl_error *err)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", DIR_, name);
    return pc_read_file(path, 0, err);
}

/* Not photometric data: the notes, and the tilt file another file names. */
static int is_data_file(const char *name)
{
    size_t n = strlen(name);
    if (name[0] == '.' || strcmp(name, "tilt.dat") == 0) return 0;
    return !(n > 3 && strcmp(name + n - 3, ".md") == 0) && !(n > 4 && strcmp(name + n - 4, ".csv") == 0);
}

static void test_every_file(void)
{
    DIR *d = opendir(DIR_);
    if (!d) return;
    struct dirent *e;
    int seen[NEXPECTED] = {0};
    while ((e = readdir(d))) {
        if (!is_data_file(e->d_name)) continue;
        size_t k = 0;
        while (k < NEXPECTED && strcmp(expected[k].file, e->d_name) != 0) ++k;
        CHECK_MSG(k < NEXPECTED, "%s is in the corpus but not in this test's table: decide what it should do", e->d_name);
        if (k == NEXPECTED) continue;
        seen[k] = 1;
        const expectation *x = &expected[k];
        cdl_error err;
        cdl_photometry *p = load(x->file, &err);
        if (x->error) {
            CHECK_MSG(!p && err.status == CDL_ERR_INPUT, "%s was read but must be rejected", x->file);
            /* a clear message: FILE:LINE: expected ..., found ... */
            char where[256];
            snprintf(where, sizeof where, "%s:", x->file);
            CHECK_MSG(strstr(err.message, where) && strstr(err.message, "expected") && strstr(err.message, "found") &&
                          strstr(err.message, x->error),
                      "%s: '%s'", x->file, err.message);
        } else {
            CHECK_MSG(p != NULL, "%s: %s", x->file, err.message);
            if (!p) continue;
            size_t want = (x->warning1 != NULL) + (x->warning2 != NULL);
            CHECK_MSG(cdl_photometry_warning_count(p) == want, "%s: %zu warnings, expected %zu (first: %s)", x->file,
                      cdl_photometry_warning_count(p), want,
                      cdl_photometry_warning_count(p) ? cdl_photometry_warning(p, 0) : "-");
            if (x->warning1) CHECK_MSG(pc_has_warning(p, x->warning1), "%s: no warning '%s'", x->file, x->warning1);
            if (x->warning2) CHECK_MSG(pc_has_warning(p, x->warning2), "%s: no warning '%s'", x->file, x->warning2);
            /* --strict turns exactly these files into errors */
            cdl_photometry *strict = NULL;
            char path[2048];
            snprintf(path, sizeof path, "%s/%s", DIR_, x->file);
            strict = pc_read_file(path, 1, &err);
            CHECK_MSG((strict == NULL) == (want > 0), "%s: --strict", x->file);
            cdl_photometry_release(strict);
            /* every figure of the summary is finite: luminous ones, or radiant ones for a file in W/sr */
            cdl_photometry_summary s;
            cdl_photometry_summary_compute(p, &s);
            double flux = s.radiometric ? s.radiant_flux.W : s.flux.lm;
            double peak = s.radiometric ? s.max_radiant_intensity.W_sr : s.max_intensity.cd;
            CHECK_MSG(isfinite(flux) && flux > 0.0 && isfinite(s.downward_fraction) && isfinite(peak) &&
                          isfinite(s.beam_angle_deg[0]) && isfinite(s.lor),
                      "%s: summary", x->file);
            /* every warning has a code and, when it names a line, the message names it too */
            for (size_t w = 0; w < cdl_photometry_warning_count(p); ++w) {
                const char *code = cdl_photometry_warning_code(p, w);
                char at[64];
                snprintf(at, sizeof at, ":%u:", cdl_photometry_warning_line(p, w));
                CHECK_MSG(code && code[0], "%s: warning %zu has no code", x->file, w);
                CHECK_MSG(cdl_photometry_warning_line(p, w) == 0 || strstr(cdl_photometry_warning(p, w), at),
                          "%s: warning %zu: line %u not in '%s'", x->file, w, cdl_photometry_warning_line(p, w),
                          cdl_photometry_warning(p, w));
            }
            cdl_photometry_release(p);
        }
    }
    closedir(d);
    for (size_t k = 0; k < NEXPECTED; ++k) CHECK_MSG(seen[k], "%s is missing from the corpus", expected[k].file);
}

/* Reference flux from a lab program, recorded by the source repository
 * (SOURCES.md): the exact integral must agree within 0.5 %. */
static void test_lab_flux(void)
{
    static const struct {
        const char *file;
        double lm;
    } lab[] = {{"ies_rab_roadway_quad.IES", 9217.18},
               {"ies_rab_roadway_bilateral.IES", 5834.2},
               {"ies_rab_indoor_bilateral_latin1.IES", 5821.76},
               {"ies_itl_indoor_quad.IES", 753.8},
               {"ies_indoor_full360_nolab.IES", 9230.16}};
    for (size_t k = 0; k < sizeof lab / sizeof *lab; ++k) {
        cdl_error err;
        cdl_photometry *p = load(lab[k].file, &err);
        CHECK_MSG(p != NULL, "%s", err.message);
        if (!p) continue;
        CHECK_REL(cdl_photometry_flux(p).lm, lab[k].lm, 0.005);
        cdl_photometry_release(p);
    }
    /* The type B floodlight against its [_ABSOLUTELUMENS] 10601: with H the
     * lateral angle (dOmega = cos H dH dV) it integrates to 10698 lm
     * (+0.9 %); the swapped reading of H and V would give 11311 lm (+6.7 %). */
    cdl_error err;
    cdl_photometry *p = load("ies_rab_flood_typeB_half.IES", &err);
    if (p) {
        CHECK_REL(cdl_photometry_flux(p).lm, 10601.0, 0.015);
        cdl_photometry_release(p);
    }
}

/* Pairs written by real converters hold the same light: read on their own,
 * they agree everywhere in the frame. The H90-270 / Isym 3 pair shows the
 * handedness: the IES H90 plane is the EULUMDAT C270 plane (C = 360 - H). */
static void test_pairs(void)
{
    static const struct {
        const char *ies, *ldt;
        double tolerance; /* of the maximum: the files print 4-5 significant digits */
    } pairs[] = {{"ies_gldf_H90-270_circle2002.ies", "ldt_gldf_two_lamp_sets_CRLF.ldt", 1e-4},
                 {"ies_ruco_2002_circle.ies", "ldt_ruco_Isym1.ldt", 1e-4},
                 {"ies_1995_mult_eq_lumens.ies", "ldt_avad_Isym4.ldt", 1e-4},
                 {"ies_1995_quad_91x37.ies", "ldt_luxpy_Isym4_Mc144.ldt", 1e-4}};
    for (size_t k = 0; k < sizeof pairs / sizeof *pairs; ++k) {
        cdl_error err;
        cdl_photometry *a = load(pairs[k].ies, &err), *b = load(pairs[k].ldt, &err);
        CHECK_MSG(a && b, "%s", err.message);
        if (a && b) {
            double max = cdl_photometry_max_intensity(a).cd;
            double diff = pc_max_difference(a, b);
            CHECK_MSG(diff <= pairs[k].tolerance * max, "%s vs %s: %g cd of %g", pairs[k].ies, pairs[k].ldt, diff, max);
            CHECK_REL(cdl_photometry_flux(a).lm, cdl_photometry_flux(b).lm, 1e-4);
            if (k == 0) {
                /* the other convention (H = C) puts the asymmetric half on the wrong side */
                cdl_photometry *mirrored = NULL;
                CHECK_OK(cdl_photometry_remap_c(b, -1, 0.0, &mirrored, &err), &err);
                if (mirrored) CHECK(pc_max_difference(a, mirrored) > 0.05 * max);
                cdl_photometry_release(mirrored);
            }
        }
        cdl_photometry_release(a);
        cdl_photometry_release(b);
    }
}

static char *write_as(const cdl_photometry *p, int ldt, int version) { return pc_write(p, ldt, version, NULL); }

/* The table's integral in its own unit: lumens, or watts for a radiometric file. */
static double table_flux(const cdl_photometry *p)
{
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    return s.radiometric ? s.radiant_flux.W : s.flux.lm;
}

/* IES -> EULUMDAT -> IES and EULUMDAT -> IES -> EULUMDAT: every stored
 * intensity survives (the writers print ten significant digits, far more
 * than any file prints, so 1e-8 of the maximum is within the printed
 * precision) and the flux within 0.1 %. Type A/B data cannot enter
 * EULUMDAT without resampling (reported by the writer): for those the IES
 * legs are exact and the EULUMDAT leg keeps the flux within 0.5 %.
 * Radiometric files (W/sr) are refused by EULUMDAT and stay radiometric
 * through IES. */
static void test_round_trips(void)
{
    for (size_t k = 0; k < NEXPECTED; ++k) {
        if (expected[k].error) continue;
        cdl_error err;
        cdl_photometry *p = load(expected[k].file, &err);
        if (!p) continue;
        int is_ldt = strncmp(expected[k].file, "ldt_", 4) == 0;
        cdl_photometry_table t;
        cdl_photometry_get_table(p, &t);
        double max = cdl_photometry_max_intensity(p).cd, flux = table_flux(p);
        int radiometric = cdl_photometry_get_metadata(p)->radiometric;
        for (int version = 2002; version <= 2019; version += 17) {
            /* EULUMDAT has no radiometric units: refused, never written as cd/klm */
            char *ldt = NULL;
            size_t ldt_len;
            cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
            if (radiometric)
                CHECK_MSG(cdl_photometry_format_ldt(p, &o, &ldt, &ldt_len, NULL, &err) == CDL_ERR_INPUT && !ldt &&
                              strstr(err.message, "mW/sr"),
                          "%s: written to EULUMDAT", expected[k].file);
            char *first = radiometric ? NULL : write_as(p, !is_ldt, version);
            cdl_photometry *q = first ? pc_read_text("first", first, strlen(first), 0, &err) : NULL;
            char *second = q ? write_as(q, is_ldt, version) : NULL;
            cdl_photometry *r = second ? pc_read_text("second", second, strlen(second), 0, &err) : NULL;
            CHECK_MSG(r != NULL || radiometric, "%s: %s", expected[k].file, err.message);
            if (r) {
                /* A ballast factor EULUMDAT cannot hold is folded into its
                 * lamp flux: the light (flux x output factor) is kept, the
                 * table scaled by the factor. */
                double kp = cdl_photometry_output_factor(p), kr = cdl_photometry_output_factor(r);
                if (t.type == CDL_PHOTOMETRIC_TYPE_C) {
                    if (kp == kr)
                        CHECK_MSG(pc_node_difference(p, r) <= 1e-8 * max, "%s: stored values moved by %g cd",
                                  expected[k].file, pc_node_difference(p, r));
                    CHECK_REL(table_flux(r) * kr, flux * kp, 1e-3);
                } else {
                    CHECK_REL(table_flux(r) * kr, flux * kp, 5e-3);
                }
            }
            cdl_photometry_release(q);
            cdl_photometry_release(r);
            free(first);
            free(second);
            /* the same-format trip is exact for every type */
            char *same = write_as(p, is_ldt, version);
            cdl_photometry *s = same ? pc_read_text("same", same, strlen(same), 0, &err) : NULL;
            CHECK_MSG(s != NULL, "%s: %s", expected[k].file, err.message);
            if (s) {
                CHECK_MSG(pc_node_difference(p, s) <= 1e-8 * max, "%s: same-format trip", expected[k].file);
                /* IES to IES keeps [_INTENSITYUNITS]: still radiometric, the same watts */
                CHECK_MSG(cdl_photometry_get_metadata(s)->radiometric == radiometric, "%s: units", expected[k].file);
                CHECK_REL(table_flux(s), flux, 1e-6);
            }
            cdl_photometry_release(s);
            free(same);
            if (is_ldt) break; /* the IES version matters only when IES is written first */
        }
        cdl_photometry_release(p);
    }
}

/* The UV files say, in a keyword or in words, that their tables are in
 * mW/sr: read as radiometric, their "flux" as radiant flux in W; every
 * other file of the corpus is photometric. */
static void test_radiometric_units(void)
{
    static const char *const radiometric[] = {"ies_CRonly_big.ies", "ies_guv_lumenizer_seam.ies", "ies_guv_nukit_lantern.ies",
                                              "ies_guv_ushio_b1_LF.ies", "ies_lightlab_uv_2002.ies"};
    for (size_t k = 0; k < NEXPECTED; ++k) {
        cdl_error err;
        cdl_photometry *p = load(expected[k].file, &err);
        if (!p) continue;
        int want = 0;
        for (size_t r = 0; r < sizeof radiometric / sizeof *radiometric; ++r)
            want |= strcmp(expected[k].file, radiometric[r]) == 0;
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        CHECK_MSG(m->radiometric == want, "%s: radiometric %d, expected %d", expected[k].file, m->radiometric, want);
        if (want) {
            CHECK(m->radiometric_scale == 1e-3);
            cdl_photometry_summary s;
            cdl_photometry_summary_compute(p, &s);
            /* The same table built as candela (cdl_photometry_create_type_c) integrates to
             * lumens; read from a file in mW/sr, that integral is milliwatts, and no lumens. */
            cdl_photometry_table t;
            cdl_photometry_get_table(p, &t);
            cdl_photometry *as_cd = NULL;
            CHECK_OK(cdl_photometry_create_type_c(t.horizontal_deg, t.horizontal_count, t.vertical_deg,
                                                  t.vertical_count, t.candela, &as_cd, &err),
                     &err);
            double mw = as_cd ? cdl_photometry_flux(as_cd).lm : NAN;
            cdl_photometry_release(as_cd);
            /* the same sum over the same table: equal to rounding */
            CHECK_REL(s.radiant_flux.W, mw * 1e-3, 1e-12);
            CHECK(s.radiometric && isnan(s.flux.lm) && isnan(s.zone_flux[0].lm) && !s.efficacy_known);
            /* the 18 zones share the whole radiant flux (sums of the same exact integrals: 1e-12) */
            double zones = 0.0;
            for (int z = 0; z < 18; ++z) zones += s.radiant_zone_flux[z].W;
            CHECK_REL(zones, s.radiant_flux.W, 1e-12);
            /* the typed API: watts, and an error for lumens */
            cdl_radiant_flux w = cdl_watts(0.0);
            cdl_luminous_flux lm = cdl_lumens(-1.0);
            CHECK_OK(cdl_photometry_radiant_flux(p, &w, &err), &err);
            CHECK_REL(w.W, s.radiant_flux.W, 0.0);
            CHECK(cdl_photometry_luminous_flux(p, &lm, &err) == CDL_ERR_INPUT && lm.lm == -1.0 &&
                  strstr(err.message, "mW/sr") && isnan(cdl_photometry_flux(p).lm));
        } else {
            cdl_radiant_flux w = cdl_watts(-1.0);
            cdl_luminous_flux lm;
            CHECK(cdl_photometry_radiant_flux(p, &w, &err) == CDL_ERR_INPUT && w.W == -1.0);
            CHECK(cdl_photometry_luminous_flux(p, &lm, &err) == CDL_OK && lm.lm == cdl_photometry_flux(p).lm);
        }
        cdl_photometry_release(p);
    }
}

int main(void)
{
    DIR *d = opendir(DIR_);
    if (!d) {
        /* Exit status 77 makes ctest report the test as skipped, with this reason. */
        fprintf(stderr,
                "SKIPPED: the photometric corpus folder %s is absent; this test needs the real files of "
                "../shared/photometric (set CANDELA_PHOTOMETRIC_DIR when configuring).\n",
                DIR_);
        return 77;
    }
    closedir(d);
    test_every_file();
    test_lab_flux();
    test_pairs();
    test_round_trips();
    test_radiometric_units();
    return check_finish();
}
