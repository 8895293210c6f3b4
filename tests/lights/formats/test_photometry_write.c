/* The IES and EULUMDAT writers: layout, the most compact exact symmetry,
 * the frame convention, gamma padding, factors and tilt, absolute
 * photometry, atomic files, remapping, and round trips of made tables. */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "lights/photometry_checks.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"

#define FIXTURES CANDELA_SOURCE_DIR "/tests/data/photometric/"
#define TMP CANDELA_TEST_TMPDIR "/photometry_write"

typedef double (*shape_fn)(double c, double g);

/* A full-circle type C table (C every 22.5 deg) of a function. */
static cdl_photometry *full_table(shape_fn f, double last_gamma)
{
    double c[16], g[19], cd[16 * 19];
    size_t ng = 0;
    for (double x = 0.0; x <= last_gamma + 1e-9; x += 10.0) g[ng++] = x;
    for (int i = 0; i < 16; ++i) {
        c[i] = 22.5 * i;
        for (size_t j = 0; j < ng; ++j) cd[i * ng + j] = f(c[i], g[j]);
    }
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create_type_c(c, 16, g, ng, cd, &p, &err), &err);
    return p;
}

static double quad(double c, double g)
{
    return 100.0 + 50.0 * fabs(cos(c * CDL_DEG_TO_RAD)) + g;
}
static double rot(double c, double g) { return (void)c, 300.0 - g; }
static double bil90(double c, double g) { return 200.0 + 80.0 * sin(c * CDL_DEG_TO_RAD) + g; }
static double bil0(double c, double g) { return 200.0 + 80.0 * cos(c * CDL_DEG_TO_RAD) + g; }
static double asym(double c, double g) { return 200.0 + 80.0 * sin(c * CDL_DEG_TO_RAD) + 30.0 * cos(c * CDL_DEG_TO_RAD) + g; }

static char *format(const cdl_photometry *p, int ldt, int version, cdl_photometry_notes *notes)
{
    cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    o.ies_version = version;
    o.file_name = "out.ldt";
    char *text = NULL;
    size_t len = 0;
    cdl_error err;
    cdl_status st = ldt ? cdl_photometry_format_ldt(p, &o, &text, &len, notes, &err)
                        : cdl_photometry_format_ies(p, &o, &text, &len, notes, &err);
    CHECK_MSG(st == CDL_OK, "%s", err.message);
    CHECK(!text || strlen(text) == len);
    return text;
}

static cdl_photometry *reread(const char *text)
{
    cdl_error err;
    if (!text) return NULL;
    cdl_photometry *p = pc_read_text("written", text, strlen(text), 0, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    return p;
}

/* The n-th line (1-based) of a text, without its line end. */
static void nth_line(const char *text, int n, char *out, size_t size)
{
    const char *s = text;
    for (int k = 1; k < n && s; ++k) {
        s = strchr(s, '\n');
        if (s) ++s;
    }
    out[0] = '\0';
    if (!s) return;
    size_t len = strcspn(s, "\r\n");
    if (len >= size) len = size - 1;
    memcpy(out, s, len);
    out[len] = '\0';
}

static int line_after(const char *text, const char *marker, int offset, char *out, size_t size)
{
    const char *s = strstr(text, marker);
    if (!s) return 0;
    for (int k = 0; k < offset && s; ++k) {
        s = strchr(s, '\n');
        if (s) ++s;
    }
    if (!s) return 0;
    size_t len = strcspn(s, "\r\n");
    if (len >= size) len = size - 1;
    memcpy(out, s, len);
    out[len] = '\0';
    return 1;
}

/* Each symmetry class is found in a full table, written compactly, and read back exactly. */
static void test_compact_symmetry(void)
{
    static const struct {
        shape_fn f;
        const char *ies_h;    /* the horizontal-angle line */
        int isym;
        size_t nh;
    } cases[] = {{rot, "0", 1, 1},
                 {quad, "0 22.5 45 67.5 90", 4, 5},
                 {bil0, "0 22.5 45 67.5 90 112.5 135 157.5 180", 2, 9},
                 {bil90, "90 112.5 135 157.5 180 202.5 225 247.5 270", 3, 9},
                 {asym, "0 22.5 45 67.5 90 112.5 135 157.5 180 202.5", 0, 17}};
    for (size_t k = 0; k < sizeof cases / sizeof *cases; ++k) {
        cdl_photometry *p = full_table(cases[k].f, 180.0);
        if (!p) continue;
        char *ies = format(p, 0, 2019, NULL), *ldt = format(p, 1, 0, NULL);
        char line[512];
        /* the horizontal angles follow the 19 vertical ones (two lines of ten and nine) */
        CHECK(ies && line_after(ies, "TILT=NONE", 5, line, sizeof line));
        CHECK_MSG(ies && strncmp(line, cases[k].ies_h, strlen(cases[k].ies_h)) == 0, "case %zu: H line '%s'", k, line);
        nth_line(ldt, 3, line, sizeof line);
        CHECK_MSG(atoi(line) == cases[k].isym, "case %zu: Isym %s", k, line);
        cdl_photometry *a = reread(ies), *b = reread(ldt);
        if (a && b) {
            const cdl_photometry_metadata *m = cdl_photometry_get_metadata(a);
            CHECK(m->file_horizontal_count == cases[k].nh);
            /* written with ten significant digits (EULUMDAT: the cd/klm value and the
             * reference flux): below 1e-9 of the largest value */
            double tol = 1e-9 * cdl_photometry_max_intensity(p).cd;
            CHECK(pc_max_difference(p, a) < tol);
            CHECK(pc_max_difference(p, b) < tol);
            CHECK_REL(cdl_photometry_flux(a).lm, cdl_photometry_flux(p).lm, 1e-9);
            CHECK_REL(cdl_photometry_flux(b).lm, cdl_photometry_flux(p).lm, 1e-9);
        }
        cdl_photometry_release(a);
        cdl_photometry_release(b);
        free(ies);
        free(ldt);
        cdl_photometry_release(p);
    }
}

static void test_ies_layout(void)
{
    cdl_photometry *p = full_table(asym, 180.0);
    if (!p) return;
    char *v19 = format(p, 0, 2019, NULL), *v02 = format(p, 0, 2002, NULL);
    char line[512];
    if (v19 && v02) {
        CHECK(strncmp(v19, "IES:LM-63-2019\r\n", 16) == 0);
        CHECK(strncmp(v02, "IESNA:LM-63-2002\r\n", 18) == 0);
        CHECK(strstr(v19, "\r\n[TEST] ") && strstr(v19, "\r\n[TESTLAB] ") && strstr(v19, "\r\n[ISSUEDATE] ") &&
              strstr(v19, "\r\n[MANUFAC] ") && strstr(v19, "\r\n[FILEGENINFO] "));
        CHECK(!strstr(v02, "[FILEGENINFO]"));
        /* record B: 2019 file generation type "undefined", 2002 "future use" 1 */
        CHECK(line_after(v19, "TILT=NONE", 2, line, sizeof line) && strcmp(line, "1 1.00001 0") == 0);
        CHECK(line_after(v02, "TILT=NONE", 2, line, sizeof line) && strcmp(line, "1 1.00000 0") == 0);
        /* record A: absolute, multiplier 1, 17 horizontal angles with the closing 360, metres */
        CHECK_MSG(line_after(v19, "TILT=NONE", 1, line, sizeof line) && strcmp(line, "1 -1 1 19 17 1 2 0 0 0") == 0,
                  "%s", line);
        /* the frame convention: the H = 90 row holds frame C = 270 (100 + ...: sin 270 = -1) */
        cdl_photometry *a = reread(v19);
        if (a) {
            CHECK_REL(cdl_photometry_intensity_c_gamma(a, 270.0, 0.0).cd, asym(270.0, 0.0), 1e-12);
            cdl_photometry_release(a);
        }
        /* every line ends in CR LF and no line is longer than 256 bytes (LM-63-2002) */
        size_t longest = 0, lf = 0, crlf = 0;
        for (const char *s = v02; *s;) {
            size_t n = strcspn(s, "\n");
            longest = n > longest ? n : longest;
            if (s[n] == '\n') {
                ++lf;
                crlf += n > 0 && s[n - 1] == '\r';
                s += n + 1;
            } else {
                s += n;
            }
        }
        CHECK(longest < 256 && lf == crlf && lf > 10);
    }
    free(v19);
    free(v02);
    cdl_photometry_release(p);
}

/* EULUMDAT allows gamma 0..140; LM-63 type C does not: padded with zeros. */
static void test_gamma_padding(void)
{
    cdl_photometry *p = full_table(quad, 140.0);
    if (!p) return;
    cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
    char *ies = format(p, 0, 2019, &notes);
    int noted = 0;
    for (size_t i = 0; i < notes.count; ++i) noted |= strstr(notes.items[i], "padded") != NULL;
    CHECK(noted);
    cdl_photometry *a = reread(ies);
    if (a) {
        cdl_photometry_table t;
        cdl_photometry_get_table(a, &t);
        CHECK(t.vertical_count == 17 && t.vertical_deg[15] == 140.001 && t.vertical_deg[16] == 180.0);
        /* the 0.001 degree ramp from I(140) to 0 adds I(140) x 2 pi sin(140) x 0.001 deg / 2
         * = 290 cd x pi x 0.643 x 1.75e-5 rad = 0.010 lm, 4.3e-6 of this table's 2364 lm */
        CHECK_REL(cdl_photometry_flux(a).lm, cdl_photometry_flux(p).lm, 5e-6);
        cdl_photometry_release(a);
    }
    cdl_photometry_notes_free(&notes);
    free(ies);
    cdl_photometry_release(p);
}

static void test_factors_tilt_absolute(void)
{
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *p = NULL;
    cdl_error err;
    /* 1995 with ballast factor 0.9 and ballast-lamp factor 0.95: folded into 0.855 */
    CHECK_OK(cdl_photometry_read_file(FIXTURES "ies_crlf_latin1_ctrlz.ies", &o, &p, &err), &err);
    if (p) {
        cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
        char *ies = format(p, 0, 2019, &notes);
        cdl_photometry *a = reread(ies);
        if (a) {
            CHECK_REL(cdl_photometry_output_factor(a), 0.855, 1e-12);
            CHECK(strstr(cdl_photometry_keyword_value(a, "MANUFAC"), "Lumi\xe8re"));
            CHECK(strcmp(cdl_photometry_keyword_value(a, "LUMINAIRE"), "first line\nsecond line") == 0);
            cdl_photometry_release(a);
        }
        int folded = 0;
        for (size_t i = 0; i < notes.count; ++i) folded |= strstr(notes.items[i], "folded") != NULL;
        CHECK(folded);
        cdl_photometry_notes_free(&notes);
        free(ies);
        /* absolute photometry in EULUMDAT: a negative lamp count and the integrated flux */
        char *ldt = format(p, 1, 0, &notes);
        char line[128];
        nth_line(ldt, 27, line, sizeof line);
        CHECK(atoi(line) == -1);
        /* the ballast factor 0.855 folded into the lamp flux (EULUMDAT has no field for it) */
        nth_line(ldt, 29, line, sizeof line);
        CHECK_REL(atof(line), 600.0 * CDL_PI * 0.855, 1e-9);
        nth_line(ldt, 23, line, sizeof line);
        CHECK_REL(atof(line), 100.0, 0.0);
        int ballast_noted = 0;
        for (size_t i = 0; i < notes.count; ++i)
            ballast_noted |= strstr(notes.items[i], "ballast factor 0.855 has no EULUMDAT field: folded into the lamp "
                                                    "flux") != NULL;
        CHECK(ballast_noted);
        cdl_photometry_notes_free(&notes);
        cdl_photometry *b = reread(ldt);
        if (b) {
            /* the same light: the table's flux times the ballast factor, now in the table */
            CHECK_REL(cdl_photometry_flux(b).lm, 600.0 * CDL_PI * 0.855, 1e-9);
            CHECK(cdl_photometry_output_factor(b) == 1.0);
            CHECK(cdl_photometry_get_metadata(b)->absolute);
            cdl_photometry_release(b);
        }
        free(ldt);
        cdl_photometry_release(p);
    }
    /* TILT=<file> is written inline; EULUMDAT cannot hold it */
    CHECK_OK(cdl_photometry_read_file(FIXTURES "ies_tilt_file.ies", &o, &p, &err), &err);
    if (p) {
        cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
        char *ies = format(p, 0, 2019, &notes);
        CHECK(ies && strstr(ies, "TILT=INCLUDE\r\n3\r\n4\r\n0 30 60 90\r\n1 0.95 0.85 0.7\r\n"));
        cdl_photometry *a = reread(ies);
        if (a) {
            CHECK_REL(cdl_photometry_tilt_factor(a, 45.0), 0.9, 1e-15);
            cdl_photometry_release(a);
        }
        free(ies);
        cdl_photometry_notes_free(&notes);
        char *ldt = format(p, 1, 0, &notes);
        int tilt_noted = 0;
        for (size_t i = 0; i < notes.count; ++i) tilt_noted |= strstr(notes.items[i], "TILT") != NULL;
        CHECK(tilt_noted);
        cdl_photometry_notes_free(&notes);
        free(ldt);
        cdl_photometry_release(p);
    }
}

/* C' = -C moves frame C90 data to C270; offsets rotate; symmetry follows. */
static void test_remap(void)
{
    cdl_photometry *p = full_table(asym, 180.0), *q = NULL, *r = NULL;
    cdl_error err;
    if (!p) return;
    CHECK_OK(cdl_photometry_remap_c(p, -1, 0.0, &q, &err), &err);
    if (q) {
        CHECK_REL(cdl_photometry_intensity_c_gamma(q, 270.0, 50.0).cd, asym(90.0, 50.0), 1e-12);
        CHECK_REL(cdl_photometry_intensity_c_gamma(q, 22.5, 50.0).cd, asym(337.5, 50.0), 1e-12);
        CHECK_REL(cdl_photometry_flux(q).lm, cdl_photometry_flux(p).lm, 1e-12);
    }
    cdl_photometry_release(q);
    /* bilateral about C0-C180, turned by 90 degrees, becomes bilateral about C90-C270 */
    cdl_photometry *b = full_table(quad, 180.0);
    double c[9], g[2] = {0.0, 180.0}, cd[18];
    for (int i = 0; i < 9; ++i) {
        c[i] = 22.5 * i;
        cd[2 * i] = cd[2 * i + 1] = 100.0 + c[i];
    }
    cdl_photometry *bil = NULL;
    CHECK_OK(cdl_photometry_create_type_c(c, 9, g, 2, cd, &bil, &err), &err);
    if (bil) {
        CHECK_OK(cdl_photometry_remap_c(bil, 1, 90.0, &r, &err), &err);
        if (r) {
            cdl_photometry_table t;
            cdl_photometry_get_table(r, &t);
            CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270);
            CHECK_REL(cdl_photometry_intensity_c_gamma(r, 90.0, 0.0).cd, 100.0, 1e-12);
        }
        cdl_photometry_release(r);
    }
    cdl_photometry_release(bil);
    cdl_photometry_release(b);
    cdl_photometry_release(p);
}

/* Type B has no EULUMDAT form: resampled, the flux change reported. */
static void test_type_b_to_ldt(void)
{
    static double hv[37], cd[37 * 37];
    for (int i = 0; i < 37; ++i) hv[i] = -90.0 + 5.0 * i;
    for (int i = 0; i < 37; ++i)
        for (int j = 0; j < 37; ++j) cd[i * 37 + j] = 1000.0 * cos(hv[i] * CDL_DEG_TO_RAD) * cos(hv[j] * CDL_DEG_TO_RAD);
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create(CDL_PHOTOMETRIC_TYPE_B, hv, 37, hv, 37, cd, &p, &err), &err);
    if (!p) return;
    cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
    char *ldt = format(p, 1, 0, &notes);
    CHECK(notes.count > 0 && strstr(notes.items[0], "resampled"));
    cdl_photometry *b = reread(ldt);
    if (b) {
        /* cos(alpha) sampled at 5 deg in (H, V) and again at 2.5 x 1 deg in (C, gamma): both
         * interpolants lie within h^2/8 ~ 1e-3 of cos, so the fluxes agree to 2e-3 */
        CHECK_REL(cdl_photometry_flux(b).lm, cdl_photometry_flux(p).lm, 2e-3);
        CHECK_REL(cdl_photometry_intensity(b, cdl_vec3_make(0, 0, -1)).cd, 1000.0, 1e-9);
        cdl_photometry_release(b);
    }
    cdl_photometry_notes_free(&notes);
    free(ldt);
    cdl_photometry_release(p);
}

static int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.') ++n;
    closedir(d);
    return n;
}

static void test_write_file(void)
{
    mkdir(CANDELA_TEST_TMPDIR, 0777);
    mkdir(TMP, 0777);
    cdl_photometry *p = full_table(quad, 180.0);
    if (!p) return;
    cdl_error err;
    remove(TMP "/out.ldt");
    CHECK_OK(cdl_photometry_write_file(p, TMP "/out.ldt", CDL_PHOTOMETRY_FORMAT_EULUMDAT, NULL, NULL, &err), &err);
    CHECK_OK(cdl_photometry_write_file(p, TMP "/out.ldt", CDL_PHOTOMETRY_FORMAT_EULUMDAT, NULL, NULL, &err), &err);
    /* replaced in place, no temporary left behind */
    CHECK(count_entries(TMP) == 1);
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *q = NULL;
    CHECK_OK(cdl_photometry_read_file(TMP "/out.ldt", &o, &q, &err), &err);
    if (q) {
        CHECK(strcmp(cdl_photometry_get_metadata(q)->ldt_file_name, "out.ldt") == 0);
        cdl_photometry_release(q);
    }
    /* a folder that does not exist: an error naming the file, nothing written */
    CHECK(cdl_photometry_write_file(p, TMP "/missing/out.ies", CDL_PHOTOMETRY_FORMAT_IES, NULL, NULL, &err) ==
          CDL_ERR_INPUT);
    CHECK(strstr(err.message, "missing/out.ies") != NULL);
    CHECK(count_entries(TMP) == 1);
    cdl_photometry_release(p);
}

/* EULUMDAT's four luminous heights (lines 18-21) that differ have no IES
 * field: written as their mean, and the note says so. A fixture given the
 * heights 100, 200, 100, 200 mm: LM-63's one height is 150 mm. */
static void test_side_heights(void)
{
    FILE *f = fopen(FIXTURES "warn_lorl.ldt", "rb");
    CHECK(f != NULL);
    if (!f) return;
    char text[4096], out[4096];
    size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[len] = '\0';
    /* replace lines 18-21 */
    size_t at = 0, o = 0;
    int line = 1;
    while (at < len) {
        size_t end = at;
        while (end < len && text[end] != '\n') end++;
        if (line >= 18 && line <= 21) o += (size_t)snprintf(out + o, sizeof out - o, "%d\n", line % 2 ? 200 : 100);
        else o += (size_t)snprintf(out + o, sizeof out - o, "%.*s\n", (int)(end - at), text + at);
        at = end + 1;
        line++;
    }
    cdl_error err;
    cdl_photometry *p = pc_read_text("heights.ldt", out, o, 0, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (!p) return;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    CHECK(m->ldt_luminous_height_mm[0] == 100.0 && m->ldt_luminous_height_mm[1] == 200.0);
    CHECK_REL(m->opening.height_m, 0.15, 1e-12);
    cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
    char *ies = format(p, 0, 2019, &notes);
    int noted = 0;
    for (size_t i = 0; i < notes.count; ++i)
        noted |= strstr(notes.items[i], "luminous heights per side (C0 100, C90 200, C180 100, C270 200 mm") != NULL;
    CHECK(noted);
    cdl_photometry *a = reread(ies);
    if (a) {
        CHECK_REL(cdl_photometry_get_metadata(a)->opening.height_m, 0.15, 1e-9);
        cdl_photometry_release(a);
    }
    cdl_photometry_notes_free(&notes);
    free(ies);
    cdl_photometry_release(p);
}

int main(void)
{
    test_compact_symmetry();
    test_ies_layout();
    test_gamma_padding();
    test_factors_tilt_absolute();
    test_remap();
    test_type_b_to_ldt();
    test_write_file();
    test_side_heights();
    return check_finish();
}
