/* photometry_io.h - the readers' and writers' shared internals (not public). */
#ifndef CANDELA_LIGHTS_FORMATS_PHOTOMETRY_IO_H
#define CANDELA_LIGHTS_FORMATS_PHOTOMETRY_IO_H

#include <stddef.h>

#include "lights/photometry/photometry_internal.h"
#include "lights/formats/photometry_lexer.h"
#include "base/file_bytes.h"

/* Largest photometric or tilt file read: real files are below 2 MB. */
#define CDL_PHOTOMETRY_MAX_FILE_BYTES ((size_t)256 * 1024 * 1024)

/* The parsers fill an allocated object `p`; `name` names the input in messages. */
cdl_status cdl_ies_read(const char *data, size_t size, const char *name, const cdl_photometry_read_options *options,
                        cdl_photometry *p, cdl_error *err);
cdl_status cdl_ldt_read(const char *data, size_t size, const char *name, const cdl_photometry_read_options *options,
                        cdl_photometry *p, cdl_error *err);

/* The four TILT records (geometry, count, angles, factors) from a scanner. */
cdl_status cdl_tilt_read_records(cdl_photometry_scanner *s, const char *source, cdl_photometry *p, cdl_error *err);

/* TILT=<file>: open `file` relative to the folder of `ies_name` and read its records. */
cdl_status cdl_tilt_read_file(const char *ies_name, const char *file, cdl_photometry *p, cdl_error *err);

/* Luminous opening from an IES width/length/height triple (file units) and back. */
void cdl_photometry_opening_from_ies(int version, double w, double l, double h, int units_type,
                                     cdl_luminous_opening *opening);
/* LM-63-2002/2019 signed codes in metres. */
void cdl_photometry_opening_to_ies(const cdl_luminous_opening *opening, double out[3]);

#endif
