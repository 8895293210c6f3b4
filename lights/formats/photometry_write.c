/* photometry_write.c - a photometric file written in the format asked, atomically. */
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/error_report.h"
#include "base/sized_struct.h"
#include "lights/photometry/photometry_internal.h"

cdl_status cdl_photometry_write_file(const cdl_photometry *p, const char *path, cdl_photometry_format format,
                                     const cdl_photometry_write_options *options, cdl_photometry_notes *lost,
                                     cdl_error *err)
{
    cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    cdl_sized_struct_read(&o, sizeof o, options);
    if (!o.file_name) {
        const char *slash = strrchr(path, '/');
        o.file_name = slash ? slash + 1 : path;
    }
    char *text = NULL;
    size_t len = 0;
    cdl_status st;
    if (format == CDL_PHOTOMETRY_FORMAT_IES) st = cdl_photometry_format_ies(p, &o, &text, &len, lost, err);
    else if (format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) st = cdl_photometry_format_ldt(p, &o, &text, &len, lost, err);
    else st = cdl_error_set(err, CDL_ERR_USAGE, "%s: can write IES or EULUMDAT only", path);
    if (st != CDL_OK) return st;

    /* No half-written output (base/atomic_file.h). A file that cannot
     * be created there (a missing or read-only folder) is the user's path
     * to fix: bad input; failing writes and syncs stay internal failures. */
    st = cdl_atomic_file_write_all(path, text, len, err);
    free(text);
    return st;
}
