/* The checks of header fields a photometric lab's checker makes
 * (lights/photometry/photometry_check_fields.c, docs/photometry-warnings.md):
 * each fires, with its code and line, on a file that breaks it and on no
 * other, and is silent on the same file made right. The real corpus files
 * that keep these rules stay silent (test_photometry_corpus.c's table). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "lights/photometry_checks.h"
#include "lights/photometry/photometry_metadata.h"

/* An EULUMDAT file: rotationally symmetric, 250/200/100/0 cd/klm at gamma
 * 0/30/60/90 of 1000 lm, all downward (DFF 100), LORL left 0 (not
 * stated), sizes and the rest as the fields say. */
typedef struct ldt_fields {
    const char *company, *name;
    int ityp, isym;
    double luminaire[3], luminous[2], heights[4];
    double tilt;
    double dr[10];
    double c90[4]; /* the C90 plane when Isym 4 (C0 is 250 200 100 0) */
    int all_planes;      /* 1: the file holds C0, C90, C180 and C270, whatever Isym says */
    double planes[4][4]; /* their values then */
} ldt_fields;

static ldt_fields good_ldt(void)
{
    ldt_fields f = {"Maker", "Luminaire", 1, 1, {600, 600, 80}, {580, 580}, {0, 0, 0, 0}, 0.0,
                    {0.3, 0.4, 0.5, 0.55, 0.6, 0.7, 0.75, 0.8, 0.85, 0.9}, {250, 200, 100, 0}, 0, {{0}}};
    return f;
}

static size_t ldt_text(const ldt_fields *f, char *out, size_t size)
{
    size_t n = 0;
#define PUT(...) n += (size_t)snprintf(out + n, n < size ? size - n : 0, __VA_ARGS__)
    PUT("%s\r\n%d\r\n%d\r\n4\r\n90\r\n4\r\n30\r\nR-1\r\n%s\r\nNo. 1\r\nf.ldt\r\n2026-01-01\r\n", f->company, f->ityp,
        f->isym, f->name);
    for (int k = 0; k < 3; ++k) PUT("%g\r\n", f->luminaire[k]);
    for (int k = 0; k < 2; ++k) PUT("%g\r\n", f->luminous[k]);
    for (int k = 0; k < 4; ++k) PUT("%g\r\n", f->heights[k]);
    PUT("100\r\n0\r\n1\r\n%g\r\n1\r\n1\r\nLED\r\n1000\r\n3000\r\n80\r\n10\r\n", f->tilt);
    for (int k = 0; k < 10; ++k) PUT("%g\r\n", f->dr[k]);
    PUT("0\r\n90\r\n180\r\n270\r\n0\r\n30\r\n60\r\n90\r\n");
    if (f->all_planes) {
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 4; ++k) PUT("%g\r\n", f->planes[i][k]);
        return n;
    }
    PUT("250\r\n200\r\n100\r\n0\r\n");
    if (f->isym == 4)
        for (int k = 0; k < 4; ++k) PUT("%g\r\n", f->c90[k]);
#undef PUT
    return n;
}

/* An LM-63 file, rotationally symmetric, absolute photometry. */
typedef struct ies_fields {
    int version;              /* 2002 or 2019 */
    const char *keywords;     /* lines before TILT */
    double ballast, second;   /* record B fields 1 and 2 */
    int bom;
} ies_fields;

static ies_fields good_ies(void)
{
    ies_fields f = {2019, "[TEST] R-1\r\n[TESTLAB] Lab\r\n[ISSUEDATE] 2026-01-01\r\n[MANUFAC] Maker\r\n", 1.0, 1.1,
                    0};
    return f;
}

static size_t ies_text(const ies_fields *f, char *out, size_t size)
{
    return (size_t)snprintf(out, size,
                            "%s%s\r\n%sTILT=NONE\r\n1 -1 1 4 1 1 2 0 0 0\r\n%g %.5f 1000\r\n0 30 60 90\r\n0\r\n"
                            "250 200 100 0\r\n",
                            f->bom ? "\xEF\xBB\xBF" : "", f->version == 2019 ? "IES:LM-63-2019" : "IESNA:LM-63-2002",
                            f->keywords, f->ballast, f->second);
}

/* Read the text and check: no warning (code NULL), or exactly one, with
 * this code and line, whose message holds `needle`. */
static void expect(const char *what, const char *text, size_t len, const char *code, unsigned line,
                   const char *needle)
{
    cdl_error err;
    cdl_photometry *p = pc_read_text(what, text, len, 0, &err);
    CHECK_MSG(p != NULL, "%s: %s", what, err.message);
    if (!p) return;
    size_t n = cdl_photometry_warning_count(p);
    if (!code) {
        CHECK_MSG(n == 0, "%s: expected no warning, found %zu: [%s] %s", what, n,
                  n ? cdl_photometry_warning_code(p, 0) : "", n ? cdl_photometry_warning(p, 0) : "");
    } else {
        CHECK_MSG(n == 1 && strcmp(cdl_photometry_warning_code(p, 0), code) == 0 &&
                      cdl_photometry_warning_line(p, 0) == line && strstr(cdl_photometry_warning(p, 0), needle),
                  "%s: expected [%s] at line %u with '%s', found %zu: [%s] line %u %s", what, code, line, needle, n,
                  n ? cdl_photometry_warning_code(p, 0) : "", n ? cdl_photometry_warning_line(p, 0) : 0,
                  n ? cdl_photometry_warning(p, 0) : "");
        /* and --strict refuses the file, naming the code */
        cdl_photometry *s = pc_read_text(what, text, len, 1, &err);
        CHECK_MSG(!s && strstr(err.message, code), "%s: --strict", what);
        cdl_photometry_release(s);
    }
    cdl_photometry_release(p);
}

static char buf[8192];

static void ldt_case(const char *what, const ldt_fields *f, const char *code, unsigned line, const char *needle)
{
    expect(what, buf, ldt_text(f, buf, sizeof buf), code, line, needle);
}

static void ies_case(const char *what, const ies_fields *f, const char *code, unsigned line, const char *needle)
{
    expect(what, buf, ies_text(f, buf, sizeof buf), code, line, needle);
}

static void test_ies(void)
{
    ies_fields f = good_ies();
    ies_case("a good LM-63-2019 file", &f, NULL, 0, NULL);
    f.keywords = "[TEST] R-1\r\n[ISSUEDATE] 2026-01-01\r\n[MANUFAC] Maker\r\n";
    ies_case("2019 without [TESTLAB]", &f, "ies-required-keyword", 0, "found no [TESTLAB]");
    f.keywords = "[TEST] R-1\r\n[TESTLAB] Lab\r\n[MANUFAC] Maker\r\n";
    ies_case("2019 without [ISSUEDATE]", &f, "ies-required-keyword", 0, "found no [ISSUEDATE]");
    f.version = 2002;
    ies_case("2002 without [ISSUEDATE] (not held to it)", &f, NULL, 0, NULL);
    f = good_ies();
    /* every one of the ten codes is silent; others are not */
    const double codes[10] = {1.0, 1.00001, 1.0001, 1.001, 1.01, 1.011, 1.1, 1.101, 1.11, 1.111};
    for (int k = 0; k < 10; ++k) {
        f.second = codes[k];
        ies_case("a standard file generation type", &f, NULL, 0, NULL);
    }
    /* record B, line 8: the generation type (field 2) and the ballast factor (field 1) */
    static const struct {
        const char *what;
        double ballast, second;
        const char *code, *needle;
    } record_b[] = {
        {"file generation type 1.2", 1.0, 1.2, "ies-file-generation-type", "found 1.2"},
        {"a ballast factor written as the generation type", 1.0, 0.88, "ies-file-generation-type", "found 0.88"},
        {"ballast factor 1.3 (the range's end)", 1.3, 1.1, NULL, NULL},
        {"ballast factor 88 (a percentage)", 88.0, 1.1, "ballast-factor-range", "found 88"},
        {"ballast factor 0.45", 0.45, 1.1, "ballast-factor-range", "found 0.45"},
    };
    for (size_t k = 0; k < sizeof record_b / sizeof *record_b; ++k) {
        f = good_ies();
        f.ballast = record_b[k].ballast;
        f.second = record_b[k].second;
        ies_case(record_b[k].what, &f, record_b[k].code, record_b[k].code ? 8 : 0, record_b[k].needle);
    }
    f = good_ies();
    f.bom = 1;
    ies_case("a byte-order mark", &f, "byte-order-mark", 1, "byte-order mark");
}

static void test_ldt(void)
{
    ldt_fields f = good_ldt();
    ldt_case("a good EULUMDAT file", &f, NULL, 0, NULL);
    char long_name[120];
    memset(long_name, 'x', 79);
    long_name[79] = '\0';
    f.name = long_name;
    ldt_case("a 79-character luminaire name", &f, "ldt-text-length", 9, "luminaire name (line 9)");
    long_name[78] = '\0';
    ldt_case("a 78-character luminaire name", &f, NULL, 0, NULL);
    f = good_ldt();
    f.company = long_name;
    long_name[78] = 'x';
    ldt_case("a 79-character company", &f, "ldt-text-length", 1, "company (line 1)");

    f = good_ldt();
    f.luminous[0] = 700.0;
    ldt_case("luminous length 700 over a 600 mm luminaire", &f, "ldt-luminous-larger", 16, "length 700 mm");
    f.luminous[0] = 605.0; /* within rounding: 1 % of 600 mm */
    ldt_case("luminous length 605 over 600 mm", &f, NULL, 0, NULL);
    f = good_ldt();
    f.luminous[1] = 650.0;
    ldt_case("luminous width 650 over 600 mm", &f, "ldt-luminous-larger", 17, "width 650 mm");
    f = good_ldt();
    f.heights[2] = 120.0;
    ldt_case("luminous height 120 over an 80 mm luminaire", &f, "ldt-luminous-larger", 20, "C180 plane");
    f = good_ldt();
    f.luminaire[1] = 0.0; /* a round luminaire of 600 mm */
    f.luminous[1] = 0.0;
    f.luminous[0] = 640.0;
    ldt_case("a 640 mm luminous disk in a 600 mm round luminaire", &f, "ldt-luminous-larger", 16, "diameter 640 mm");

    f = good_ldt();
    f.tilt = 95.0;
    ldt_case("measurement tilt 95", &f, "ldt-measurement-tilt", 25, "found 95");
    f.tilt = -90.0;
    ldt_case("measurement tilt -90", &f, NULL, 0, NULL);

    f = good_ldt();
    f.dr[9] = 1.2;
    ldt_case("a direct ratio of 1.2", &f, "ldt-direct-ratios", 42, "found 1.2 for room index 5");
    f = good_ldt();
    f.dr[4] = 0.54;
    ldt_case("direct ratios falling at k = 1.5", &f, "ldt-direct-ratios", 37, "found 0.54 for room index 1.5");
    for (int k = 0; k < 10; ++k) f.dr[k] = 0.0;
    ldt_case("direct ratios not given (all 0)", &f, NULL, 0, NULL);
    for (int k = 0; k < 10; ++k) f.dr[k] = 0.5;
    ldt_case("direct ratios all equal (rounded flat)", &f, NULL, 0, NULL);

    f = good_ldt();
    f.ityp = 2;
    ldt_case("Isym 1 said of a linear luminaire", &f, "ldt-symmetry-indicator", 3, "Ityp 2 (line 2: a linear");
    f = good_ldt();
    f.isym = 4;
    ldt_case("Ityp 1 over Isym 4 data whose planes agree", &f, NULL, 0, NULL);
    f.c90[1] = 150.0;
    ldt_case("Ityp 1 over Isym 4 data whose planes differ by 20 %", &f, "ldt-symmetry-indicator", 2,
             "the C90 plane differs from the C0 plane by 50 cd at gamma 30");
    f.ityp = 3;
    ldt_case("the same data as Ityp 3", &f, NULL, 0, NULL);

    /* Isym 3 (symmetric to C90-C270) over a file that holds all four planes
     * from C0: C0 and C180 mirror each other, so the data agree; the stored
     * planes are the file's C90, C180 and C270, whose values come from the
     * full table (the second plane the file writes is C90's). */
    f = good_ldt();
    f.ityp = 3;
    f.isym = 3;
    f.all_planes = 1;
    const double agree[4][4] = {{250, 200, 100, 0}, {300, 220, 90, 0}, {250, 200, 100, 0}, {280, 210, 95, 0}};
    memcpy(f.planes, agree, sizeof agree);
    ldt_case("Isym 3 over all four planes, symmetric", &f, "ldt-full-table", 4, "holds all 4 C-planes although Isym 3 stores 3");
    cdl_error err;
    cdl_photometry *p = pc_read_text("full", buf, ldt_text(&f, buf, sizeof buf), 0, &err);
    /* 1000 lm, cd/klm x 1: C90 at gamma 0 is 300 cd, C270 280 cd */
    CHECK(p && cdl_photometry_intensity_c_gamma(p, 90.0, 0.0).cd == 300.0 &&
          cdl_photometry_intensity_c_gamma(p, 270.0, 0.0).cd == 280.0);
    cdl_photometry_release(p);
    /* the same planes under Isym 2 (symmetric to C0-C180): C90 and C270 differ by 20 cd/klm at nadir */
    f.isym = 2;
    ldt_case("Isym 2 over all four planes that are not", &f, "ldt-symmetry-indicator", 3,
             "Isym 2 is contradicted by the data: the file holds all 4 C-planes, and at C270, gamma 0 it has 280 "
             "cd/klm where the symmetry gives 20 more or less; read as the full table");
    p = pc_read_text("full", buf, ldt_text(&f, buf, sizeof buf), 0, &err);
    cdl_photometry_table t;
    if (p) cdl_photometry_get_table(p, &t);
    CHECK(p && t.symmetry == CDL_PHOTOMETRY_SYMMETRY_NONE && t.horizontal_count == 4 &&
          cdl_photometry_intensity_c_gamma(p, 270.0, 0.0).cd == 280.0);
    cdl_photometry_release(p);

    /* a byte-order mark: warned, and not kept in the company name */
    f = good_ldt();
    size_t n = ldt_text(&f, buf + 3, sizeof buf - 3);
    memcpy(buf, "\xEF\xBB\xBF", 3);
    expect("an EULUMDAT byte-order mark", buf, n + 3, "byte-order-mark", 1, "byte-order mark");
    p = pc_read_text("bom", buf, n + 3, 0, &err);
    CHECK(p && strcmp(cdl_photometry_get_metadata(p)->ldt_company, "Maker") == 0);
    cdl_photometry_release(p);
}

int main(void)
{
    test_ies();
    test_ldt();
    return check_finish();
}
