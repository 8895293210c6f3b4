/* photometry_read.c - reading a photometric file: load, detect the format
 * from the content, parse, check consistency, apply --strict. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
#include "lights/formats/photometry_io.h"

static int starts_with_nocase(const char *s, size_t len, const char *prefix)
{
    size_t n = strlen(prefix);
    if (len < n) return 0;
    for (size_t i = 0; i < n; ++i)
        if (toupper((unsigned char)s[i]) != prefix[i]) return 0;
    return 1;
}

/* IES: line 1 is a version tag. EULUMDAT: lines 2, 3, 4 and 6 are numbers
 * (Ityp, Isym, Mc, Ng) and lines 5 and 7 numbers or empty (Dc, Dg) - checked
 * before looking for a TILT= line, since EULUMDAT text fields may contain
 * anything. IES 1986: no tag, but a "TILT=" line ends the label lines. */
typedef enum { FORMAT_UNKNOWN, FORMAT_IES, FORMAT_LDT } detected_format;

static detected_format detect(const char *data, size_t size)
{
    size_t pos = 0;
    const char *line;
    size_t len;
    int ldt_lines = 0, tilt = 0, tag = 0;
    /* skip a UTF-8 byte-order mark */
    if (cdl_photometry_has_bom(data, size)) pos = 3;
    for (unsigned n = 1; n <= 2000 && cdl_photometry_next_line(data, size, &pos, &line, &len); ++n) {
        cdl_photometry_trim(&line, &len);
        if (n == 1) tag = starts_with_nocase(line, len, "IESNA") || starts_with_nocase(line, len, "IES:");
        if (!tilt && starts_with_nocase(line, len, "TILT")) {
            size_t k = 4;
            while (k < len && (line[k] == ' ' || line[k] == '\t')) ++k;
            tilt = k < len && line[k] == '=';
        }
        if (n >= 2 && n <= 7) {
            double v;
            int optional = n == 5 || n == 7;
            if ((len == 0 && optional) || (len > 0 && cdl_photometry_parse_number(line, len, 1, &v))) ++ldt_lines;
        }
    }
    /* an EULUMDAT company line may read like an IES tag; an IES file never
     * has six numeric lines right after its tag (keywords or TILT= come first) */
    if (ldt_lines == 6) return FORMAT_LDT;
    return tag || tilt ? FORMAT_IES : FORMAT_UNKNOWN;
}

static detected_format format_from_extension(const char *name)
{
    const char *dot = strrchr(name, '.');
    if (!dot || strchr(dot, '/')) return FORMAT_UNKNOWN;
    size_t len = strlen(dot);
    if (starts_with_nocase(dot, len, ".LDT") && len == 4) return FORMAT_LDT;
    if (starts_with_nocase(dot, len, ".IES") && len == 4) return FORMAT_IES;
    return FORMAT_UNKNOWN;
}

cdl_status cdl_photometry_read_memory(const void *bytes, size_t size, const char *name,
                                      const cdl_photometry_read_options *options, cdl_photometry **out,
                                      cdl_error *err)
{
    *out = NULL;
    cdl_photometry_read_options given = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_sized_struct_read(&given, sizeof given, options);
    options = &given;
    const char *source = name ? name : "<memory>";
    const char *data = bytes;
    size = cdl_photometry_text_length(data, size);
    detected_format format = detect(data, size);
    /* Content that fits neither format: a file named .ldt or .ies is read
     * as that format anyway, so the error names the line that is wrong. */
    if (format == FORMAT_UNKNOWN && name) format = format_from_extension(name);
    if (format == FORMAT_UNKNOWN)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:1: expected an IES LM-63 file (a version tag such as 'IESNA:LM-63-2002' or a "
                             "'TILT=' line) or an EULUMDAT file (numbers on lines 2 to 7), found neither",
                             source);
    cdl_photometry *p = cdl_photometry_alloc();
    if (!p) return cdl_error_out_of_memory(err);
    cdl_status st = format == FORMAT_IES ? cdl_ies_read(data, size, name, options, p, err)
                                         : cdl_ldt_read(data, size, name, options, p, err);
    if (st == CDL_OK) cdl_photometry_detect_units(p);
    if (st == CDL_OK && cdl_photometry_check_consistency(p, source) != CDL_OK) st = cdl_error_out_of_memory(err);
    if (st == CDL_OK && options->strict && p->warning_count > 0)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s [%s] (an error with --strict)", p->warnings[0].message,
                           p->warnings[0].code);
    if (st != CDL_OK) {
        cdl_photometry_release(p);
        return st;
    }
    *out = p;
    return CDL_OK;
}

cdl_status cdl_photometry_read_file(const char *path, const cdl_photometry_read_options *options,
                                    cdl_photometry **out, cdl_error *err)
{
    *out = NULL;
    char *data = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "photometric file", CDL_PHOTOMETRY_MAX_FILE_BYTES, &data, &size, err);
    if (st != CDL_OK) return st;
    st = cdl_photometry_read_memory(data, size, path, options, out, err);
    free(data);
    return st;
}
