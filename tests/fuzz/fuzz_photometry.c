/* fuzz_photometry - libFuzzer harness over both photometric readers and the
 * writers' round trip.
 *
 * Any input: read it (format detected from the content; TILT=<file> is
 * refused so the fuzzer never opens files). If it reads, summarise it, write
 * it as IES (2019 and 2002) and EULUMDAT, and read every output back: a
 * writer must never produce a file its own reader rejects, and a type C
 * table must keep its light (flux x output factor) and its units (a table
 * in W/sr is refused by EULUMDAT). The direct ratios lie between 0 and the
 * downward share and grow with the room index; the BUG rating is 0..5. A
 * violated invariant aborts (a finding), as do crashes, hangs and
 * sanitizer reports. */
#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"

static void require(int ok, const char *what, const char *detail)
{
    if (!ok) {
        fprintf(stderr, "fuzz_photometry: invariant broken: %s (%s)\n", what, detail ? detail : "");
        abort();
    }
}

/* The table's integral in its own unit: lumens, or watts for a file in W/sr. */
static double table_flux(const cdl_photometry *p)
{
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    return s.radiometric ? s.radiant_flux.W : s.flux.lm;
}

static void round_trip(const cdl_photometry *p, int ldt, int version)
{
    cdl_photometry_write_options wo = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    wo.ies_version = version;
    char *text = NULL;
    size_t len = 0;
    cdl_error err;
    cdl_photometry_notes notes = CDL_PHOTOMETRY_NOTES_INIT;
    cdl_status st = ldt ? cdl_photometry_format_ldt(p, &wo, &text, &len, &notes, &err)
                        : cdl_photometry_format_ies(p, &wo, &text, &len, &notes, &err);
    cdl_photometry_notes_free(&notes);
    if (st == CDL_ERR_INTERNAL) return; /* out of memory under the fuzzer's limit */
    if (ldt && cdl_photometry_get_metadata(p)->radiometric) {
        /* EULUMDAT holds cd/klm only: a table in W/sr is refused, never written as light */
        require(st == CDL_ERR_INPUT && !text, "a radiometric table is refused by EULUMDAT", NULL);
        return;
    }
    require(st == CDL_OK, "a read table can be written", err.message);
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    ro.no_external_files = 1;
    cdl_photometry *q = NULL;
    st = cdl_photometry_read_memory(text, len, "written", &ro, &q, &err);
    require(st == CDL_OK, "the writer's output reads back", err.message);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    /* The light kept is the flux times the output factor: a target with no
     * ballast-factor field (EULUMDAT) folds the factor into its table. */
    require(cdl_photometry_get_metadata(q)->radiometric == cdl_photometry_get_metadata(p)->radiometric,
            "the units kept", NULL);
    double a = table_flux(p) * cdl_photometry_output_factor(p);
    double b = table_flux(q) * cdl_photometry_output_factor(q);
    require(isfinite(b) && b >= 0.0, "finite flux after the round trip", NULL);
    /* Type C data is written, not resampled: ten significant digits, and a
     * partial gamma range padded for LM-63 gains at most two 0.001 degree
     * ramps, each adding less than 2 pi I_max x (0.001 deg) / 2. */
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    double ramps = 2.0 * M_PI * cdl_photometry_max_intensity(p).cd * (m->radiometric ? m->radiometric_scale : 1.0) *
                   0.001 * M_PI / 180.0 * cdl_photometry_output_factor(p);
    if (t.type == CDL_PHOTOMETRIC_TYPE_C) require(fabs(b - a) <= 1e-6 * a + ramps, "light kept", NULL);
    cdl_photometry_release(q);
    free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    ro.no_external_files = 1;
    cdl_photometry *p = NULL;
    cdl_error err;
    if (cdl_photometry_read_memory(data, size, "fuzz/input", &ro, &p, &err) != CDL_OK) {
        require(err.message[0] != '\0', "a rejection has a message", NULL);
        return 0;
    }
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    double flux = s.radiometric ? s.radiant_flux.W : s.flux.lm;
    require(isfinite(flux) && flux >= 0.0, "finite flux", NULL);
    require(!s.radiometric || isnan(s.flux.lm), "no lumens from a file in W/sr", NULL);
    require(isfinite(s.downward_fraction), "finite downward fraction", NULL);
    (void)cdl_photometry_intensity(p, cdl_vec3_make(0.3, -0.2, -0.9));
    /* direct ratios: shares of the flux, growing with the room index, never above the downward share */
    double dr[CDL_DIRECT_RATIO_COUNT];
    if (cdl_photometry_direct_ratios(p, dr, &err) == CDL_OK)
        for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k)
            require(isfinite(dr[k]) && dr[k] >= -1e-12 && dr[k] <= s.downward_fraction + 1e-9 &&
                        (k == 0 || dr[k] >= dr[k - 1] - 1e-12),
                    "direct ratios within 0 and the downward share, growing", NULL);
    /* the CIE flux code's cones: shares of the downward flux, growing, never above it */
    double code[5];
    cdl_photometry_cie_flux_code(p, code);
    for (int k = 0; k < 3; ++k)
        require(isfinite(code[k]) && code[k] >= -1e-9 && code[k] <= 100.0 + 1e-9 && (k == 0 || code[k] >= code[k - 1] - 1e-9),
                "flux code cones within 0 and 100 %, growing", NULL);
    cdl_bug_rating bug;
    if (!s.radiometric && cdl_photometry_bug_rating(p, &bug, &err) == CDL_OK) {
        require(bug.b >= 0 && bug.b <= 5 && bug.u >= 0 && bug.u <= 5 && bug.g >= 0 && bug.g <= 5, "BUG 0..5", NULL);
        for (int z = 0; z < CDL_BUG_ZONES; ++z) require(isfinite(bug.zone_lm[z]) && bug.zone_lm[z] >= 0.0, "zone lumens", NULL);
    }
    round_trip(p, 0, 2019);
    round_trip(p, 0, 2002);
    round_trip(p, 1, 0);
    cdl_photometry_release(p);
    return 0;
}
