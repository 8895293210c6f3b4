/* The public accessors of a photometric file's header (photometry.h), as a
 * program sees them through the installed headers only: an IES file and an
 * EULUMDAT file written here with known fields, read back field by field;
 * the summary filled only as far as an older, shorter struct reaches. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "lights/photometry/photometry.h"

static const char ies[] = "IESNA:LM-63-2002\n[TEST] header\n[MANUFAC] Acme Lighting\n[LUMINAIRE] Slot 1200\n"
                          "[LUMCAT] AC-1200\n[LAMP] LED 4000 K\nTILT=NONE\n2 1500 1 3 1 1 2 -0.15 -0.15 0\n"
                          "0.9 1 42\n0 45 90\n0\n1000 700 0\n";

static cdl_photometry *read_text(const char *text, const char *name)
{
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_read_memory(text, strlen(text), name, &o, &p, &err), &err);
    return p;
}

static void test_ies(void)
{
    cdl_photometry *p = read_text(ies, "header.ies");
    if (!p) return;
    CHECK(cdl_photometry_get_format(p) == CDL_PHOTOMETRY_FORMAT_IES && cdl_photometry_ies_version(p) == 2002);
    CHECK(cdl_photometry_input_watts(p) == 42.0 && cdl_photometry_ballast_factor(p) == 0.9);
    CHECK(!cdl_photometry_is_absolute(p) && !cdl_photometry_is_radiometric(p));
    const cdl_luminous_opening *o = cdl_photometry_opening(p);
    CHECK(o && o->shape == CDL_LUMINOUS_SHAPE_CIRCLE && fabs(o->width_m - 0.15) < 1e-12);
    CHECK(cdl_photometry_lamp_set_count(p) == 1);
    cdl_photometry_lamp_set set;
    CHECK(cdl_photometry_get_lamp_set(p, 0, &set) && set.count == 2 && set.flux_lm == 3000.0);
    CHECK(!cdl_photometry_get_lamp_set(p, 1, &set));
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_MANUFACTURER), "Acme Lighting") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_LUMINAIRE), "Slot 1200") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_CATALOGUE), "AC-1200") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_LAMP), "LED 4000 K") == 0);
    size_t n = cdl_photometry_keyword_count(p);
    int found = 0;
    for (size_t i = 0; i < n; ++i)
        found += strcmp(cdl_photometry_keyword_name(p, i), "LUMCAT") == 0 &&
                 strcmp(cdl_photometry_keyword_text(p, i), "AC-1200") == 0;
    CHECK(n >= 5 && found == 1 && cdl_photometry_keyword_name(p, n) == NULL);

    /* The summary: the table's flux, and an older program's shorter struct
     * filled only up to its size. */
    cdl_photometry_summary all = CDL_PHOTOMETRY_SUMMARY_INIT;
    cdl_photometry_summarize(p, &all);
    CHECK(all.size == sizeof all && all.flux.lm > 0.0 && all.max_intensity.cd == 1000.0);
    struct {
        cdl_photometry_summary s;
        double guard;
    } old;
    memset(&old, 0x5a, sizeof old);
    old.s.size = offsetof(cdl_photometry_summary, downward_flux);
    cdl_photometry_summarize(p, &old.s);
    CHECK(old.s.flux.lm == all.flux.lm);
    double poison;
    memset(&poison, 0x5a, sizeof poison);
    CHECK(memcmp(&old.s.downward_flux, &poison, sizeof poison) == 0 && memcmp(&old.guard, &poison, sizeof poison) == 0);
    cdl_photometry_release(p);
}

/* The EULUMDAT fields behind the same accessors: company (line 1),
 * luminaire name and number (lines 9 and 10), the lamp set's type. */
static void test_ldt(void)
{
    const char *lines[] = {"Acme GmbH", "1", "1", "1", "0", "3", "45", "report 7", "Round one", "AR-1",
                           "round.ldt", "2026-11-26", "300", "0", "80", "200", "0", "0", "0", "0", "0", "100",
                           "100", "1", "0", "1", "1", "LED module", "1000", "4000", "80", "12",
                           "0.5", "0.6", "0.7", "0.8", "0.85", "0.9", "0.92", "0.94", "0.96", "0.97",
                           "0", "0", "45", "90", "300", "200", "0"};
    char text[2048];
    size_t at = 0;
    for (size_t i = 0; i < sizeof lines / sizeof *lines; ++i)
        at += (size_t)snprintf(text + at, sizeof text - at, "%s\r\n", lines[i]);
    cdl_photometry *p = read_text(text, "round.ldt");
    if (!p) return;
    CHECK(cdl_photometry_get_format(p) == CDL_PHOTOMETRY_FORMAT_EULUMDAT && cdl_photometry_ies_version(p) == 0);
    CHECK(cdl_photometry_input_watts(p) == 12.0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_MANUFACTURER), "Acme GmbH") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_LUMINAIRE), "Round one") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_CATALOGUE), "AR-1") == 0);
    CHECK(strcmp(cdl_photometry_get_text(p, CDL_PHOTOMETRY_LAMP), "LED module") == 0);
    cdl_photometry_release(p);
}

int main(void)
{
    test_ies();
    test_ldt();
    return check_finish();
}
