/* The IES LM-63 reader: versions and tags, keywords, line ends, TILT,
 * horizontal ranges and the frame convention, types A/B, openings,
 * factors, and every kind of broken input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry_checks.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"

#define FIXTURES CANDELA_SOURCE_DIR "/tests/data/photometric/"

static cdl_photometry *read_fixture(const char *name, int strict, cdl_error *err)
{
    char path[1024];
    snprintf(path, sizeof path, "%s%s", FIXTURES, name);
    return pc_read_file(path, strict, err);
}

static cdl_photometry *read_text(const char *text, cdl_error *err)
{
    return pc_read_text("mem.ies", text, strlen(text), 0, err);
}

static double I(const cdl_photometry *p, double c, double g) { return cdl_photometry_intensity_c_gamma(p, c, g).cd; }

static void test_isotropic_fixture(void)
{
    cdl_error err;
    cdl_photometry *p = read_fixture("iso_1000cd.ies", 1, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (!p) return;
    /* a constant table integrates exactly: 4 pi I (round-off only) */
    CHECK_REL(cdl_photometry_flux(p).lm, 4000.0 * CDL_PI, 1e-12);
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    CHECK(m->format == CDL_PHOTOMETRY_FORMAT_IES && m->ies_version == 2002 && m->absolute);
    CHECK(m->file_horizontal_count == 1 && m->file_vertical_count == 19);
    CHECK(strcmp(cdl_photometry_keyword_value(p, "test"), "CANDELA-ISO-1") == 0);
    cdl_photometry_release(p);
}

static void test_1986(void)
{
    cdl_error err;
    cdl_photometry *p = read_fixture("ies_1986_one_per_line.ies", 1, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (!p) return;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    CHECK(m->ies_version == 1986 && m->version_tag[0] == '\0');
    /* label lines kept as free text */
    CHECK(m->keyword_count == 3 && m->keywords[0].key[0] == '\0' && strstr(m->keywords[0].value, "REPORT NUMBER"));
    /* "2.0" lamps of 500 lm, multiplier "2.0" applied to the table */
    CHECK(m->lamp_sets[0].count == 2);
    CHECK_REL(m->rated_lamp_flux_lm, 1000.0, 1e-15);
    CHECK_REL(I(p, 0.0, 0.0), 200.0, 1e-15);
    CHECK_REL(I(p, 90.0, 45.0), 120.0, 1e-15);
    /* 1986 negative width = round opening; units 1 = feet */
    CHECK(m->opening.shape == CDL_LUMINOUS_SHAPE_CIRCLE);
    CHECK_REL(m->opening.width_m, 0.1 * 0.3048, 1e-12);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_QUADRANT);
    cdl_photometry_release(p);
}

static void test_crlf_latin1_ctrlz(void)
{
    cdl_error err;
    cdl_photometry *p = read_fixture("ies_crlf_latin1_ctrlz.ies", 1, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (!p) return;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    CHECK(m->ies_version == 1995);
    CHECK(strcmp(cdl_photometry_keyword_value(p, "MANUFAC"), "Lumi\xe8re & Fils") == 0);
    CHECK(strcmp(cdl_photometry_keyword_value(p, "LUMINAIRE"), "first line\nsecond line") == 0);
    CHECK(strcmp(cdl_photometry_keyword_value(p, "_WATT"), "12") == 0);
    /* 1995: ballast factor x ballast-lamp photometric factor; the table keeps neither */
    CHECK_REL(cdl_photometry_output_factor(p), 0.9 * 0.95, 1e-15);
    CHECK_REL(I(p, 0.0, 0.0), 300.0, 1e-15);
    /* I falls linearly from 300 to 150 to 0 cd over gamma 0, 90, 180 degrees:
     * 2 pi [integral of the two linear pieces times sin] = 600 pi exactly */
    CHECK_REL(cdl_photometry_flux(p).lm, 600.0 * CDL_PI, 1e-12);
    CHECK(cdl_photometry_warning_count(p) == 0); /* bytes after Ctrl-Z are not data */
    cdl_photometry_release(p);
}

static void test_tilt(void)
{
    cdl_error err;
    cdl_photometry *p = read_fixture("ies_tilt_file.ies", 1, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        CHECK(m->tilt_kind == CDL_TILT_FILE && m->tilt_geometry == 3 && m->tilt_count == 4);
        CHECK(strcmp(m->tilt_file, "ies_tilt_file.tilt") == 0);
        CHECK_REL(cdl_photometry_tilt_factor(p, 45.0), 0.9, 1e-15);
        CHECK_REL(cdl_photometry_tilt_factor(p, 120.0), 0.7, 1e-15);
        /* the table is not tilted */
        CHECK_REL(I(p, 0.0, 0.0), 300.0, 1e-15);
        cdl_photometry_release(p);
    }
    p = read_fixture("ies_tilt_missing_file.ies", 0, &err);
    CHECK(!p && err.status == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "ies_tilt_missing_file.ies:3:") && strstr(err.message, "no_such_tilt_file.dat"),
              "%s", err.message);
    /* from memory without a path, or with external files disabled: refused, not opened */
    char path[1024];
    snprintf(path, sizeof path, "%sies_tilt_file.ies", FIXTURES);
    FILE *f = fopen(path, "rb");
    char buf[4096];
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f) fclose(f);
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    o.no_external_files = 1;
    p = NULL;
    CHECK(cdl_photometry_read_memory(buf, n, path, &o, &p, &err) == CDL_ERR_INPUT && !p);
    CHECK_MSG(strstr(err.message, "disabled"), "%s", err.message);
    /* TILT=INCLUDE: four records between the TILT line and record A, whatever the line breaks */
    p = read_text("IESNA:LM-63-2002\n[TEST] t\nTILT=INCLUDE\n1 4 0 45\n90 180 1.00 0.90\n0.80 1.00\n"
                  "1 -1 1 2 1 1 2 0 0 0 1 1 10 0 90 0 100 50\n",
                  &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        CHECK(cdl_photometry_get_metadata(p)->tilt_kind == CDL_TILT_INCLUDE);
        CHECK_REL(cdl_photometry_tilt_factor(p, 22.5), 0.95, 1e-15);
        CHECK_REL(cdl_photometry_tilt_factor(p, 135.0), 0.9, 1e-15);
        cdl_photometry_release(p);
    }
    p = read_text("IESNA:LM-63-2002\nTILT=INCLUDE\n4\n2\n0 90\n1 1\n1 -1 1 2 1 1 2 0 0 0 1 1 10 0 90 0 100 50\n", &err);
    CHECK(!p && strstr(err.message, "mem.ies:3: expected the tilt lamp-to-luminaire geometry"));
}

/* The same table with every kind of line end, and with the numbers wrapped
 * differently, reads the same. */
static void test_line_ends(void)
{
    const char *lf = "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 -1 1 3 2 1 2 0 0 0\n1 1 10\n0 45 90\n0 90\n"
                     "100 60 20\n80 50 10\n";
    char crlf[512], cr[512], mixed[512], wrapped[512];
    size_t k = 0, c = 0, m = 0, line = 0;
    for (const char *s = lf; *s; ++s) {
        if (*s == '\n') {
            crlf[k++] = '\r';
            crlf[k++] = '\n';
            cr[c++] = '\r';
            const char *ends[3] = {"\r\n", "\r", "\n"};
            for (const char *e = ends[line++ % 3]; *e; ++e) mixed[m++] = *e;
        } else {
            crlf[k++] = cr[c++] = mixed[m++] = *s;
        }
    }
    crlf[k] = cr[c] = mixed[m] = '\0';
    snprintf(wrapped, sizeof wrapped, "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 -1 1\n3\n2 1 2 0 0 0 1 1 10 0\n45\n90 0\t"
                                      "90,100 60\n20 80 50 10");
    const char *texts[5] = {lf, crlf, cr, mixed, wrapped};
    double ref = 0.0;
    for (int t = 0; t < 5; ++t) {
        cdl_error err;
        cdl_photometry *p = read_text(texts[t], &err);
        CHECK_MSG(p != NULL, "variant %d: %s", t, err.message);
        if (!p) continue;
        double f = cdl_photometry_flux(p).lm;
        if (t == 0) ref = f;
        CHECK_REL(f, ref, 0.0);
        CHECK_REL(I(p, 0.0, 45.0), 60.0, 0.0);
        CHECK(cdl_photometry_warning_count(p) == 0);
        cdl_photometry_release(p);
    }
    /* line numbers count CR LF, CR and LF line ends alike */
    cdl_error err;
    cdl_photometry *p = read_text("IESNA:LM-63-2002\r\r\n[TEST] x\rTILT=NONE\n1 -1 1 3 2 1 2 0 0 0\r\n1 1 10\n0 45 x\n", &err);
    CHECK(!p);
    CHECK_MSG(strstr(err.message, "mem.ies:7:") != NULL, "%s", err.message);
}

static int version_of(const char *tag, int *warned)
{
    char text[512];
    snprintf(text, sizeof text, "%s\n[TEST] x\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5\n", tag);
    cdl_error err;
    cdl_photometry *p = read_text(text, &err);
    if (!p) return -1;
    int v = cdl_photometry_get_metadata(p)->ies_version;
    *warned = pc_has_warning(p, "non-standard version tag");
    cdl_photometry_release(p);
    return v;
}

static void test_version_tags(void)
{
    int w;
    CHECK(version_of("IESNA91", &w) == 1991 && !w);
    CHECK(version_of("IESNA:LM-63-1995", &w) == 1995 && !w);
    CHECK(version_of(" IESNA:LM-63-1995", &w) == 1995 && !w);
    CHECK(version_of("IESNA:LM-63-2002", &w) == 2002 && !w);
    CHECK(version_of("IES:LM-63-2019", &w) == 2019 && !w);
    CHECK(version_of("IESNA95", &w) == 1995 && w);
    CHECK(version_of("IESNA94", &w) == 1995 && w);
    CHECK(version_of("IESNA:LM-63-2019", &w) == 2019 && w);
    /* no tag: 1986, line 1 is a label */
    CHECK(version_of("SOME LAB REPORT 12", &w) == 1986 && !w);
}

static cdl_photometry *with_record_b(const char *tag, const char *record_b)
{
    char text[512];
    snprintf(text, sizeof text, "%s\n[TEST] x\nTILT=NONE\n1 1000 1 2 1 1 2 0 0 0\n%s\n0 90\n0\n100 50\n", tag, record_b);
    cdl_error err;
    return read_text(text, &err);
}

static void test_record_b(void)
{
    /* 1995: second field is the ballast-lamp photometric factor, applied */
    cdl_photometry *p = with_record_b("IESNA:LM-63-1995", "0.9 0.95 40");
    if (p) {
        CHECK_REL(cdl_photometry_output_factor(p), 0.855, 1e-15);
        CHECK_REL(cdl_photometry_get_metadata(p)->input_watts, 40.0, 0.0);
        cdl_photometry_release(p);
    }
    /* 2002: "future use", ignored */
    p = with_record_b("IESNA:LM-63-2002", "0.9 0.5 40");
    if (p) {
        CHECK_REL(cdl_photometry_output_factor(p), 0.9, 1e-15);
        cdl_photometry_release(p);
    }
    /* 2019: file generation type 1.10000 is a code, never a multiplier */
    p = with_record_b("IES:LM-63-2019", "0.9 1.10000 40");
    CHECK(p != NULL);
    if (p) {
        CHECK_REL(cdl_photometry_output_factor(p), 0.9, 1e-15);
        CHECK_REL(cdl_photometry_get_metadata(p)->file_generation_type, 1.1, 1e-15);
        CHECK_REL(I(p, 0, 0), 100.0, 0.0);
        cdl_photometry_release(p);
    }
}

/* Horizontal ranges: the symmetry and the frame convention C = 360 - H. */
static cdl_photometry *horizontal(const char *angles, int n, cdl_error *err)
{
    /* row k holds 100 + 10 k at every vertical angle */
    char text[2048];
    int len = snprintf(text, sizeof text, "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 -1 1 2 %d 1 2 0 0 0\n1 1 10\n0 90\n%s\n",
                       n, angles);
    for (int k = 0; k < n; ++k) len += snprintf(text + len, sizeof text - (size_t)len, "%d %d\n", 100 + 10 * k, 100 + 10 * k);
    return read_text(text, err);
}

static void test_horizontal_ranges(void)
{
    cdl_error err;
    cdl_photometry_table t;
    cdl_photometry *p = horizontal("0", 1, &err);
    if (p) {
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL);
        CHECK_REL(I(p, 123.0, 30.0), 100.0, 0.0);
        cdl_photometry_release(p);
    }
    p = horizontal("0 45 90", 3, &err);
    if (p) {
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_QUADRANT);
        CHECK_REL(I(p, 135.0, 30.0), 110.0, 0.0);
        CHECK_REL(I(p, 270.0, 30.0), 120.0, 0.0);
        cdl_photometry_release(p);
    }
    p = horizontal("0 90 180", 3, &err);
    if (p) {
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180);
        CHECK_REL(I(p, 270.0, 30.0), 110.0, 0.0);
        CHECK_REL(I(p, 180.0, 30.0), 120.0, 0.0);
        cdl_photometry_release(p);
    }
    /* 90..270: rows H90 = 100, H180 = 110, H270 = 120. H90 is the frame's C270 (-y). */
    p = horizontal("90 180 270", 3, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270);
        CHECK_REL(I(p, 270.0, 30.0), 100.0, 0.0);
        CHECK_REL(I(p, 90.0, 30.0), 120.0, 0.0);
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0.0, -1.0, -1.0)).cd, 100.0, 1e-12);
        /* mirrored about the C90-C270 plane: C0 = C180 */
        CHECK_REL(I(p, 0.0, 30.0), 110.0, 0.0);
        cdl_photometry_release(p);
    }
    /* 0..360 full circle: H90 (row 1 = 110) is C270; H270 (row 3 = 130) is C90 */
    p = horizontal("0 90 180 270 360", 5, &err);
    if (p) {
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_NONE && t.horizontal_count == 4);
        CHECK_REL(I(p, 270.0, 30.0), 110.0, 0.0);
        CHECK_REL(I(p, 90.0, 30.0), 130.0, 0.0);
        CHECK(pc_has_warning(p, "mem.ies:12: the H = 0 and H = 360 rows differ")); /* rows 100 and 140, the last on line 12 */
        cdl_photometry_release(p);
    }
    /* 0..270 step 90 (no closing row): wraps 270 -> 360 = 0 without a warning */
    p = horizontal("0 90 180 270", 4, &err);
    if (p) {
        CHECK_REL(I(p, 45.0, 30.0), 0.5 * (100.0 + 130.0), 1e-12); /* between H0 and H315... C45 = H315 */
        CHECK(cdl_photometry_warning_count(p) == 0);
        cdl_photometry_release(p);
    }
    /* an irregular range leaves a gap: read, with a warning */
    p = horizontal("0 45 100", 3, &err);
    if (p) {
        CHECK(pc_has_warning(p, "mem.ies:7: expected horizontal angles 0, 0..90") &&
              pc_has_warning(p, "interpolated across"));
        cdl_photometry_release(p);
    }
    /* out of range */
    p = horizontal("0 90 400", 3, &err);
    CHECK(!p && strstr(err.message, "within [0, 360]"));
}

/* Type B: photometric zero at -z; H positive toward -y; V positive toward +x. */
static void test_type_b_and_a(void)
{
    const char *b = "IESNA:LM-63-2002\n[TEST] b\nTILT=NONE\n1 -1 1 3 3 2 2 0 0 0\n1 1 10\n-90 0 90\n-90 0 90\n"
                    "1 2 3\n4 5 6\n7 8 9\n";
    cdl_error err;
    cdl_photometry *p = read_text(b, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        /* row = H, column = V */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, 0, -1)).cd, 5.0, 1e-12);
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(1, 0, 0)).cd, 6.0, 1e-12);   /* V = 90 */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(-1, 0, 0)).cd, 4.0, 1e-12);  /* V = -90 */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, -1, 0)).cd, 8.0, 1e-9);   /* H = 90 */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, 1, 0)).cd, 2.0, 1e-9);    /* H = -90 */
        /* behind the floodlight (V beyond +-90): nothing measured */
        CHECK(cdl_photometry_intensity(p, cdl_vec3_make(0.1, 0, 1)).cd == 0.0);
        cdl_photometry_release(p);
    }
    const char *a = "IESNA:LM-63-2002\n[TEST] a\nTILT=NONE\n1 -1 1 3 3 3 2 0 0 0\n1 1 10\n-90 0 90\n-90 0 90\n"
                    "1 2 3\n4 5 6\n7 8 9\n";
    p = read_text(a, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, 0, -1)).cd, 5.0, 1e-12);
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(1, 0, 0)).cd, 6.0, 1e-9);    /* V = 90: the pole */
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, -1, 0)).cd, 8.0, 1e-9);   /* H = 90 */
        cdl_photometry_release(p);
    }
    /* laterally symmetric type B (H 0..90) */
    const char *half = "IESNA:LM-63-2002\n[TEST] b\nTILT=NONE\n1 -1 1 3 2 2 2 0 0 0\n1 1 10\n-90 0 90\n0 90\n"
                       "4 5 6\n7 8 9\n";
    p = read_text(half, &err);
    if (p) {
        cdl_photometry_table t;
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_LATERAL);
        CHECK_REL(cdl_photometry_intensity(p, cdl_vec3_make(0, 1, 0)).cd, 8.0, 1e-9); /* H = -90 mirrors H = 90 */
        cdl_photometry_release(p);
    }
}

static cdl_luminous_shape shape_of(const char *tag, const char *wlh, double *w, double *l, double *h)
{
    char text[512];
    snprintf(text, sizeof text, "%s\n[TEST] x\nTILT=NONE\n1 -1 1 2 1 1 2 %s\n1 1 10\n0 90\n0\n10 5\n", tag, wlh);
    cdl_error err;
    cdl_photometry *p = read_text(text, &err);
    if (!p) return (cdl_luminous_shape)-1;
    const cdl_luminous_opening *o = &cdl_photometry_get_metadata(p)->opening;
    cdl_luminous_shape s = o->shape;
    *w = o->width_m;
    *l = o->length_m;
    *h = o->height_m;
    cdl_photometry_release(p);
    return s;
}

static void test_openings(void)
{
    double w, l, h;
    const char *v95 = "IESNA:LM-63-1995", *v02 = "IESNA:LM-63-2002", *v19 = "IES:LM-63-2019";
    CHECK(shape_of(v95, "0 0 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_POINT);
    CHECK(shape_of(v95, "0.5 0.6 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_RECTANGLE && w == 0.5 && l == 0.6);
    CHECK(shape_of(v95, "0.5 0.6 0.1", &w, &l, &h) == CDL_LUMINOUS_SHAPE_BOX && h == 0.1);
    CHECK(shape_of(v95, "-0.3 0 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_CIRCLE && w == 0.3 && l == 0.3);
    CHECK(shape_of(v95, "-0.3 0 0.2", &w, &l, &h) == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER && h == 0.2);
    CHECK(shape_of(v95, "-0.12 0 -0.12", &w, &l, &h) == CDL_LUMINOUS_SHAPE_SPHERE && h == 0.12);
    CHECK(shape_of(v95, "-0.12 0.34 -0.56", &w, &l, &h) == CDL_LUMINOUS_SHAPE_ELLIPSOID);
    CHECK(shape_of(v95, "0 0.8 -0.1", &w, &l, &h) == CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG && w == 0.1);
    CHECK(shape_of(v02, "-0.56 -0.56 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_CIRCLE && w == 0.56);
    CHECK(shape_of(v02, "-0.56 -0.3 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_ELLIPSE);
    CHECK(shape_of(v02, "-0.56 -0.56 0.065", &w, &l, &h) == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER);
    CHECK(shape_of(v19, "-0.2 -0.2 -0.2", &w, &l, &h) == CDL_LUMINOUS_SHAPE_SPHERE);
    /* the same signs mean a horizontal cylinder in 2002/2019 but an ellipsoid in 1995 */
    CHECK(shape_of(v02, "-0.12 0.34 -0.56", &w, &l, &h) == CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG);
    CHECK(shape_of(v02, "0.3 -0.8 -0.3", &w, &l, &h) == CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS);
    CHECK(shape_of(v02, "-0.2 0 -0.2", &w, &l, &h) == CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE);
    /* a 2002 file with the 1995 disk code */
    CHECK(shape_of(v02, "-0.5 0 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_CIRCLE && l == 0.5);
    /* a code in no table */
    CHECK(shape_of(v02, "0 -0.63 0", &w, &l, &h) == CDL_LUMINOUS_SHAPE_UNKNOWN);
}

/* Broken files: exit status 1 material, with FILE:LINE, expected and found. */
static void test_errors(void)
{
    static const struct {
        const char *file;
        const char *where;
        const char *says;
    } cases[] = {
        {"bad_truncated.ies", "bad_truncated.ies:11:", "the file is truncated"},
        {"bad_count_mismatch.ies", "bad_count_mismatch.ies:8:", "holds 11 numbers after the ballast line where record A announces 14"},
        {"bad_not_a_number.ies", "bad_not_a_number.ies:9:", "found '1O'"},
        {"bad_angles_decreasing.ies", "bad_angles_decreasing.ies:7:", "increasing order, found 45 after 90"},
        {"bad_nan.ies", "bad_nan.ies:9:", "found 'nan'"},
        {"bad_infinite.ies", "bad_infinite.ies:10:", "finite number, found '1e999'"},
        {"bad_negative_candela.ies", "bad_negative_candela.ies:10:", "negative candela"},
        {"bad_type_4.ies", "bad_type_4.ies:5:", "unknown photometric type"},
        {"bad_no_tilt.ies", "bad_no_tilt.ies:7:", "expected a 'TILT=' line"},
        {"bad_vertical_range.ies", "bad_vertical_range.ies:7:", "within [0, 180] degrees, found -90"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        cdl_error err;
        cdl_photometry *p = read_fixture(cases[i].file, 0, &err);
        CHECK_MSG(!p && err.status == CDL_ERR_INPUT, "%s was read", cases[i].file);
        cdl_photometry_release(p);
        CHECK_MSG(strstr(err.message, cases[i].where) && strstr(err.message, "expected") &&
                      strstr(err.message, cases[i].says),
                  "%s: '%s'", cases[i].file, err.message);
    }
    /* the missing-ballast-line hint */
    cdl_error err;
    cdl_photometry *p = read_text("IES:LM-63-2019\n[TEST] x\nTILT=NONE\n1 -1 1 3 1 1 2 0 0 0\n0 45 90\n0\n10 5 1\n", &err);
    CHECK(!p && strstr(err.message, "mem.ies:5:") && strstr(err.message, "ballast line") &&
          strstr(err.message, "missing"));
    /* neither format: a name ending in .ies is read as IES (the error names
     * what IES lacks), any other name gets the error naming both formats */
    p = read_text("hello\nworld\n", &err);
    CHECK(!p && strstr(err.message, "mem.ies:") && strstr(err.message, "expected a 'TILT=' line"));
    p = pc_read_text("mem.txt", "hello\nworld\n", 12, 0, &err);
    CHECK(!p && strstr(err.message, "mem.txt:1: expected an IES LM-63 file") && strstr(err.message, "found neither"));
    p = read_text("", &err);
    CHECK(!p && err.status == CDL_ERR_INPUT);
    /* no such file */
    p = read_fixture("does_not_exist.ies", 0, &err);
    CHECK(!p && strstr(err.message, "does_not_exist.ies: cannot open"));
    /* a single vertical angle encloses no solid angle */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 1 1 1 2 0 0 0\n1 1 10\n0\n0\n10\n", &err);
    CHECK(!p && strstr(err.message, "mem.ies:3:") && strstr(err.message, ">= 2"));
    /* multiplier 0 */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 0 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5\n", &err);
    CHECK(!p && strstr(err.message, "candela multiplier"));
    /* type B with a single horizontal angle (a latitude): no solid angle, at record A */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 2 2 0 0 0\n1 1 10\n-90 0 90\n0\n10 5 1\n", &err);
    CHECK_MSG(!p && strstr(err.message, "mem.ies:3: expected the number of horizontal angles") &&
                  strstr(err.message, ">= 2 for type B data") && strstr(err.message, "found 1"),
              "%s", err.message);
    /* values each finite whose integral overflows: at the line of the first candela value */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n1e308 1e308 1e308\n", &err);
    CHECK_MSG(!p && strstr(err.message, "mem.ies:7: expected candela values whose flux is a finite number, found"),
              "%s", err.message);
    /* an absurd table size is refused before any allocation */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 900000000 900000000 1 2 0 0 0\n1 1 10\n0 90\n", &err);
    CHECK(!p && err.status == CDL_ERR_INPUT);
}

static void test_warnings_and_strict(void)
{
    cdl_error err;
    cdl_photometry *p = read_fixture("warn_seam.ies", 0, &err);
    /* named at the line where the H = 360 row starts */
    CHECK(p && pc_has_warning(p, "warn_seam.ies:13: the H = 0 and H = 360 rows differ: expected the H = 360 row"));
    if (p) CHECK_REL(I(p, 0.0, 0.0), 100.0, 0.0); /* the H = 0 row wins */
    cdl_photometry_release(p);
    p = read_fixture("warn_seam.ies", 1, &err);
    CHECK(!p && strstr(err.message, "H = 0 and H = 360") && strstr(err.message, "--strict"));
    p = read_fixture("warn_output_ratio.ies", 0, &err);
    CHECK(p && pc_has_warning(p, "warn_output_ratio.ies:5: output ratio above 1") &&
          pc_has_warning(p, "expected at most 100 %"));
    cdl_photometry_release(p);
    p = read_fixture("warn_output_ratio.ies", 1, &err);
    CHECK(!p && strstr(err.message, "output ratio above 1"));
    /* text after the table: read, with a warning */
    p = read_text("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5 ; end of data\n", &err);
    CHECK(p && pc_has_warning(p, "after the candela table"));
    cdl_photometry_release(p);
    /* a stated luminaire flux far from the table */
    p = read_text("IESNA:LM-63-2002\n[TEST] x\n\n[_ABSOLUTELUMENS] 5000\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n"
                  "10 5\n",
                  &err);
    /* named at the keyword's line (4: after a blank line) */
    CHECK(p && pc_has_warning(p, "mem.ies:4: the integrated flux") && pc_has_warning(p, "far from the luminaire flux"));
    if (p) CHECK(cdl_photometry_get_metadata(p)->keywords[1].line == 4);
    cdl_photometry_release(p);
}

int main(void)
{
    test_isotropic_fixture();
    test_1986();
    test_crlf_latin1_ctrlz();
    test_tilt();
    test_line_ends();
    test_version_tags();
    test_record_b();
    test_horizontal_ranges();
    test_type_b_and_a();
    test_openings();
    test_errors();
    test_warnings_and_strict();
    return check_finish();
}
