/* tilt_read.c - LM-63 tilt data: TILT=INCLUDE records or a TILT=<file>.
 *
 * Four records (LM-63-2002 section "TILT"): lamp-to-luminaire geometry
 * (1 vertical, 2 horizontal and stays horizontal, 3 horizontal and tilts
 * with the luminaire), the number of tilt angles N, N angles in degrees,
 * N multiplying factors. The factors never change the candela table.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/formats/photometry_io.h"

/* Tilt tables are short (a handful of angles); this bounds a hostile count. */
#define MAX_TILT_ANGLES 100000L

cdl_status cdl_tilt_read_records(cdl_photometry_scanner *s, const char *source, cdl_photometry *p, cdl_error *err)
{
    long geometry, n;
    unsigned line;
    cdl_status st = cdl_photometry_expect_integer(s, source, "the tilt lamp-to-luminaire geometry", 1, 3, &geometry,
                                                  &line, err);
    if (st != CDL_OK) return st;
    st = cdl_photometry_expect_integer(s, source, "the number of tilt angles", 1, MAX_TILT_ANGLES, &n, &line, err);
    if (st != CDL_OK) return st;
    double *angles = malloc((size_t)n * sizeof *angles), *factors = malloc((size_t)n * sizeof *factors);
    if (!angles || !factors) {
        free(angles);
        free(factors);
        return cdl_error_out_of_memory(err);
    }
    char what[96];
    for (long i = 0; i < n && st == CDL_OK; ++i) {
        snprintf(what, sizeof what, "tilt angle %ld of %ld", i + 1, n);
        st = cdl_photometry_expect_number(s, source, what, &angles[i], &line, err);
        if (st == CDL_OK && (angles[i] < -180.0 || angles[i] > 180.0))
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s within [-180, 180] degrees, found %g", source,
                               line, what, angles[i]);
        if (st == CDL_OK && i > 0 && !(angles[i] > angles[i - 1]))
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected tilt angles in increasing order, found %g after %g",
                               source, line, angles[i], angles[i - 1]);
    }
    for (long i = 0; i < n && st == CDL_OK; ++i) {
        snprintf(what, sizeof what, "tilt multiplying factor %ld of %ld", i + 1, n);
        st = cdl_photometry_expect_number(s, source, what, &factors[i], &line, err);
        if (st == CDL_OK && factors[i] < 0.0)
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%u: expected %s >= 0, found %g", source, line, what, factors[i]);
    }
    if (st == CDL_OK) st = cdl_photometry_set_tilt(p, (int)geometry, angles, factors, (size_t)n, err);
    free(angles);
    free(factors);
    return st;
}

cdl_status cdl_tilt_read_file(const char *ies_name, const char *file, cdl_photometry *p, cdl_error *err)
{
    /* resolve next to the IES file unless absolute */
    char path[4096];
    const char *slash = ies_name ? strrchr(ies_name, '/') : NULL;
    if (file[0] == '/' || !slash) snprintf(path, sizeof path, "%s", file);
    else snprintf(path, sizeof path, "%.*s/%s", (int)(slash - ies_name), ies_name, file);
    char *data = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "tilt file", CDL_PHOTOMETRY_MAX_FILE_BYTES, &data, &size, err);
    if (st != CDL_OK) return st;
    cdl_photometry_scanner s;
    cdl_photometry_scanner_init(&s, data, cdl_photometry_text_length(data, size), 0, 1, 1);
    st = cdl_tilt_read_records(&s, path, p, err);
    free(data);
    return st;
}
