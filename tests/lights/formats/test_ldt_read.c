/* The EULUMDAT reader: symmetry indicators 0-4 expand to the same
 * distribution, cd/klm to candela, lamp sets, irregular C lists, partial
 * gamma ranges, absolute photometry, blank lines, CRLF, decimal commas,
 * broken files. */
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

typedef struct ldt_spec {
    int isym, mc;
    double dc;
    const double *c;        /* Mc angles, or NULL for k * dc */
    int ng;
    const double *g;
    int nsets;
    int lamps[3];
    double flux[3];
    double cfli, lorl, dff;
    const char *extra;      /* appended after the table */
} ldt_spec;

/* value at (C, gamma): a distribution with a known symmetry */
typedef double (*shape_fn)(double c, double g);

static int stored(int isym, double c)
{
    switch (isym) {
    case 1: return c == 0.0;
    case 2: return c <= 180.0;
    case 3: return c >= 90.0 && c <= 270.0;
    case 4: return c <= 90.0;
    default: return 1;
    }
}

static char *make_ldt(const ldt_spec *s, shape_fn f)
{
    size_t cap = 1 << 20, n = 0;
    char *t = malloc(cap);
#define OUT(...) n += (size_t)snprintf(t + n, cap - n, __VA_ARGS__)
    OUT("Candela tests\n1\n%d\n%d\n%g\n%d\n%g\nrep\n\"Quoted name\"\nnum\nfile.ldt\ndate\n", s->isym, s->mc, s->dc,
        s->ng, s->g[1] - s->g[0]);
    OUT("100\n0\n20\n90\n0\n0\n0\n0\n0\n%g\n%g\n%g\n0\n%d\n", s->dff, s->lorl, s->cfli, s->nsets);
    for (int k = 0; k < s->nsets; ++k) OUT("%d\nLamp %d\n%g\n3000\n80\n10\n", s->lamps[k], k + 1, s->flux[k]);
    for (int k = 0; k < 10; ++k) OUT("0.5\n");
    for (int i = 0; i < s->mc; ++i) OUT("%g\n", s->c ? s->c[i] : s->dc * i);
    for (int j = 0; j < s->ng; ++j) OUT("%g\n", s->g[j]);
    for (int i = 0; i < s->mc; ++i) {
        double c = s->c ? s->c[i] : s->dc * i;
        if (!stored(s->isym, c)) continue;
        for (int j = 0; j < s->ng; ++j) OUT("%.17g\n", f(c, s->g[j]));
        if (s->isym == 1) break;
    }
    if (s->extra) OUT("%s", s->extra);
#undef OUT
    return t;
}

static cdl_photometry *read_text(const char *text, cdl_error *err)
{
    return pc_read_text("mem.ldt", text, strlen(text), 0, err);
}

static const double g19[19] = {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160, 170, 180};

/* Quadrant-symmetric: depends on |sin C| and |cos C| only. */
static double quad(double c, double g)
{
    double r = c * CDL_DEG_TO_RAD;
    return 100.0 + 50.0 * fabs(cos(r)) + 20.0 * fabs(sin(r)) * (g / 180.0) + 30.0 * cos(0.5 * g * CDL_DEG_TO_RAD);
}

/* Symmetric about C90-C270 only: I(C) = I(180 - C). */
static double bilateral90(double c, double g) { return 200.0 + 80.0 * sin(c * CDL_DEG_TO_RAD) + g / 3.0; }

/* Symmetric about C0-C180 only: I(C) = I(360 - C). */
static double bilateral0(double c, double g) { return 200.0 + 80.0 * cos(c * CDL_DEG_TO_RAD) + g / 3.0; }

static double rotational(double c, double g) { return (void)c, 500.0 - 2.0 * g; }

/* Each Isym expands to the same distribution as the full table (Isym 0). */
static void test_symmetry_expansion(void)
{
    static const struct {
        int isym;
        shape_fn f;
        cdl_photometry_symmetry expect;
    } cases[] = {{1, rotational, CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL},
                 {2, bilateral0, CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180},
                 {3, bilateral90, CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270},
                 {4, quad, CDL_PHOTOMETRY_SYMMETRY_QUADRANT}};
    for (size_t k = 0; k < sizeof cases / sizeof *cases; ++k) {
        ldt_spec s = {0, 24, 15.0, NULL, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
        char *full_text = make_ldt(&s, cases[k].f);
        s.isym = cases[k].isym;
        char *sym_text = make_ldt(&s, cases[k].f);
        cdl_error err;
        cdl_photometry *full = read_text(full_text, &err), *sym = read_text(sym_text, &err);
        CHECK_MSG(full && sym, "Isym %d: %s", cases[k].isym, err.message);
        if (full && sym) {
            cdl_photometry_table t;
            cdl_photometry_get_table(sym, &t);
            CHECK(t.symmetry == cases[k].expect);
            /* the same numbers everywhere: only round-off (the text has 17 digits) */
            CHECK_MSG(pc_max_difference(full, sym) < 1e-9, "Isym %d differs by %g cd", cases[k].isym, pc_max_difference(full, sym));
            CHECK_REL(cdl_photometry_flux(sym).lm, cdl_photometry_flux(full).lm, 1e-12);
        }
        cdl_photometry_release(full);
        cdl_photometry_release(sym);
        free(full_text);
        free(sym_text);
    }
}

static double flat(double c, double g) { return (void)c, (void)g, 100.0; }

static void test_units_and_lamp_sets(void)
{
    /* 100 cd/klm x conversion factor 2 x 1500 lm / 1000 = 300 cd; set 2 (an
     * alternative, 4000 lm) does not count */
    ldt_spec s = {1, 1, 0.0, (const double[]){0.0}, 19, g19, 2, {3, 6}, {1500.0, 4000.0}, 2.0, 0.0, 0.0, NULL};
    char *text = make_ldt(&s, flat);
    cdl_error err;
    cdl_photometry *p = read_text(text, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 10.0, 20.0).cd, 300.0, 1e-15);
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        CHECK(m->lamp_set_count == 2 && m->lamp_sets[1].count == 6 && !m->absolute);
        CHECK_REL(m->rated_lamp_flux_lm, 1500.0, 0.0);
        CHECK(strcmp(m->ldt_luminaire_name, "Quoted name") == 0);
        CHECK(strcmp(m->lamp_sets[1].type, "Lamp 2") == 0);
        /* 300 cd everywhere: 4 pi 300 lm, LOR = 1200 pi / 1500 */
        cdl_photometry_summary sum;
        cdl_photometry_summary_compute(p, &sum);
        CHECK(sum.lor_known);
        CHECK_REL(sum.lor, 1200.0 * CDL_PI / 1500.0, 1e-12);
        cdl_photometry_release(p);
    }
    free(text);
    /* absolute photometry: negative lamp count, the flux is the luminaire's */
    s.lamps[0] = -1;
    s.cfli = 1.0;
    s.nsets = 1;
    text = make_ldt(&s, flat);
    p = read_text(text, &err);
    if (p) {
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        CHECK(m->absolute && m->rated_lamp_flux_lm == 0.0);
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 0.0, 0.0).cd, 150.0, 1e-15);
        cdl_photometry_summary sum;
        cdl_photometry_summary_compute(p, &sum);
        CHECK(!sum.lor_known && !sum.lamp_flux_known);
        cdl_photometry_release(p);
    }
    free(text);
}

static void test_irregular_and_partial(void)
{
    /* Isym 3 with an irregular C list (Dc = 0): the stored planes are found by angle */
    static const double c[10] = {0, 10, 30, 90, 100, 150, 180, 200, 270, 300};
    ldt_spec s = {3, 10, 0.0, c, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    char *text = make_ldt(&s, bilateral90);
    cdl_error err;
    cdl_photometry *p = read_text(text, &err);
    CHECK_MSG(p != NULL, "%s", err.message);
    if (p) {
        cdl_photometry_table t;
        cdl_photometry_get_table(p, &t);
        CHECK(t.horizontal_count == 6 && t.horizontal_deg[0] == 90.0 && t.horizontal_deg[5] == 270.0);
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 150.0, 40.0).cd, bilateral90(150.0, 40.0), 1e-12);
        /* mirrored: C30 takes C150 */
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 30.0, 40.0).cd, bilateral90(150.0, 40.0), 1e-12);
        cdl_photometry_release(p);
    }
    free(text);
    /* gamma 0..140: nothing beyond; the flux is the exact integral to 140:
     * 100 cd x 2 pi (1 - cos 140) */
    static const double g15[15] = {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140};
    ldt_spec s2 = {1, 1, 0.0, (const double[]){0.0}, 15, g15, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    text = make_ldt(&s2, flat);
    p = read_text(text, &err);
    if (p) {
        CHECK_REL(cdl_photometry_flux(p).lm, 2.0 * CDL_PI * 100.0 * (1.0 - cos(140.0 * CDL_DEG_TO_RAD)), 1e-12);
        CHECK(cdl_photometry_intensity_c_gamma(p, 0.0, 150.0).cd == 0.0);
        cdl_photometry_release(p);
    }
    free(text);
    /* Isym 0 with a single plane reads as rotational, with a warning; stray values after the table too */
    ldt_spec s3 = {0, 1, 0.0, (const double[]){0.0}, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, "\n\n0\n0\n0\n"};
    text = make_ldt(&s3, flat);
    p = read_text(text, &err);
    if (p) {
        cdl_photometry_table t;
        cdl_photometry_get_table(p, &t);
        CHECK(t.symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL);
        CHECK(pc_has_warning(p, "single C-plane"));
        CHECK(pc_has_warning(p, "3 values after the intensity table"));
        cdl_photometry_release(p);
    }
    free(text);
}

static void test_fixtures(void)
{
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    o.strict = 1;
    cdl_photometry *p = NULL;
    cdl_error err;
    /* CRLF, decimal commas, ten blank direct-ratio lines */
    CHECK_OK(cdl_photometry_read_file(FIXTURES "ldt_comma_blank_crlf.ldt", &o, &p, &err), &err);
    if (p) {
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 0.0, 0.0).cd, 300.5, 1e-15);
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 90.0, 30.0).cd, 150.5, 1e-15);
        CHECK_REL(cdl_photometry_intensity_c_gamma(p, 270.0, 30.0).cd, 150.5, 1e-15);
        CHECK(cdl_photometry_get_metadata(p)->ldt_direct_ratios[3] == 0.0);
        cdl_photometry_release(p);
    }
    static const struct {
        const char *file, *where, *says;
    } cases[] = {
        {"bad_truncated.ldt", "bad_truncated.ldt:63:", "the file is truncated"},
        {"bad_isym.ldt", "bad_isym.ldt:3:", "Isym 0, 1, 2, 3 or 4, found 7"},
        {"bad_negative.ldt", "bad_negative.ldt:52:", "negative intensity"},
        {"bad_shifted.ldt", "bad_shifted.ldt:24:", "every later field shifts"},
    };
    o.strict = 0;
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        char path[1024];
        snprintf(path, sizeof path, FIXTURES "%s", cases[i].file);
        p = NULL;
        CHECK(cdl_photometry_read_file(path, &o, &p, &err) == CDL_ERR_INPUT && !p);
        CHECK_MSG(strstr(err.message, cases[i].where) && strstr(err.message, "expected") &&
                      strstr(err.message, cases[i].says),
                  "%s: %s", cases[i].file, err.message);
    }
    /* the stated LORL disagrees: a warning, an error with --strict */
    CHECK_OK(cdl_photometry_read_file(FIXTURES "warn_lorl.ldt", &o, &p, &err), &err);
    if (p) {
        CHECK(pc_has_warning(p, "warn_lorl.ldt:23: stated light output ratio LORL 50 %"));
        cdl_photometry_release(p);
    }
    o.strict = 1;
    p = NULL;
    CHECK(cdl_photometry_read_file(FIXTURES "warn_lorl.ldt", &o, &p, &err) == CDL_ERR_INPUT && !p);
}

static double huge_value(double c, double g) { return (void)c, (void)g, 1e308; }

static void test_bad_angles(void)
{
    /* gamma not increasing */
    static const double gbad[4] = {0, 30, 30, 90};
    ldt_spec s = {1, 1, 0.0, (const double[]){0.0}, 4, gbad, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    char *text = make_ldt(&s, flat);
    cdl_error err;
    cdl_photometry *p = read_text(text, &err);
    CHECK(!p && strstr(err.message, "expected gamma angles in increasing order, found 30 after 30"));
    free(text);
    /* Isym 2 whose C list lacks C180 */
    static const double c[4] = {0, 45, 90, 135};
    ldt_spec s2 = {2, 4, 0.0, c, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    text = make_ldt(&s2, flat);
    p = read_text(text, &err);
    CHECK(!p && strstr(err.message, "Isym 2 stores the C-planes from C0 to C180"));
    free(text);
    /* finite intensities whose integral overflows: named at the first intensity's line
     * (26 header lines, 6 for the lamp set, 10 direct ratios, 1 C angle, 19 gamma angles) */
    ldt_spec s4 = {1, 1, 0.0, (const double[]){0.0}, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    text = make_ldt(&s4, huge_value);
    p = read_text(text, &err);
    CHECK_MSG(!p && strstr(err.message, "mem.ldt:63: expected candela values whose flux is a finite number"), "%s",
              err.message);
    free(text);
    /* lamp flux 0: intensities in cd/klm of nothing */
    ldt_spec s3 = {1, 1, 0.0, (const double[]){0.0}, 19, g19, 1, {1}, {0.0}, 1.0, 0.0, 0.0, NULL};
    text = make_ldt(&s3, flat);
    p = read_text(text, &err);
    CHECK(!p && strstr(err.message, "mem.ldt:29: expected the lamp flux of set 1 > 0"));
    free(text);
}

/* An EULUMDAT company line that reads like an IES tag (a converted file
 * whose [MANUFAC] was "IESNA:LM-63-2002"): still EULUMDAT (a fuzzer finding). */
static void test_company_like_a_tag(void)
{
    ldt_spec s = {1, 1, 0.0, (const double[]){0.0}, 19, g19, 1, {1}, {1000.0}, 1.0, 0.0, 0.0, NULL};
    char *text = make_ldt(&s, flat);
    const char *rest = strchr(text, '\n');
    char *tagged = malloc(strlen(text) + 32);
    sprintf(tagged, "IESNA:LM-63-2002%s", rest);
    cdl_error err;
    cdl_photometry *p = read_text(tagged, &err);
    CHECK_MSG(p && cdl_photometry_get_metadata(p)->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT, "%s", err.message);
    if (p) CHECK(strcmp(cdl_photometry_get_metadata(p)->ldt_company, "IESNA:LM-63-2002") == 0);
    cdl_photometry_release(p);
    free(tagged);
    free(text);
}

int main(void)
{
    test_company_like_a_tag();
    test_symmetry_expansion();
    test_units_and_lamp_sets();
    test_irregular_and_partial();
    test_fixtures();
    test_bad_angles();
    return check_finish();
}
