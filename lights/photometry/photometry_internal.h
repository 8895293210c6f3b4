/* photometry_internal.h - the cdl_photometry object, shared by the modules
 * of lights/ that build and query it (model, readers, writers). Not part of
 * the public API: nothing outside lights/photometry*.c, ies_*.c, ldt_*.c and
 * tilt_*.c includes it. */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_INTERNAL_H
#define CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_INTERNAL_H

#include <stddef.h>

#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"

/* Symmetry value meaning "infer it from the horizontal range". */
#define CDL_PHOTOMETRY_SYMMETRY_INFER ((cdl_photometry_symmetry)-1)

/* Number of 10-degree zones from nadir to zenith. */
#define CDL_PHOTOMETRY_ZONES 18

/* One warning: code (static), line, message (owned). */
typedef struct cdl_photometry_warning_item {
    const char *code;
    unsigned line;
    char *message;
} cdl_photometry_warning_item;

struct cdl_photometry {
    cdl_photometric_type type;
    cdl_photometry_symmetry symmetry;
    size_t nh, nv;       /* outer (horizontal) and inner (vertical) counts */
    double *h;           /* type C: frame C planes; A/B: H */
    double *v;           /* type C: gamma; A/B: V */
    double *cd;          /* cd[i * nv + j] */
    int h_mirror, v_mirror;          /* A/B: the list runs 0..90 and is mirrored */
    int h_uniform, v_uniform;        /* equal steps: O(1) cell lookup */
    double h_inv_step, v_inv_step;
    double max_cd;
    size_t max_i, max_j;
    double flux_lm;                  /* cached exact total */
    cdl_photometry_metadata meta;
    double *tilt_angles, *tilt_factors; /* owned; meta.tilt_* point here */
    cdl_photometry_warning_item *warnings;
    size_t warning_count, warning_capacity;
    /* Lines of the file the header-versus-table warnings point at (0: not read from a file). */
    unsigned lamp_flux_line;      /* IES record A field 2 (lumens per lamp); EULUMDAT line 29 (set 1 flux) */
    unsigned lorl_line, dff_line; /* EULUMDAT lines 23 and 22 */
    unsigned ballast_line;        /* IES record B field 1 (field 2 follows on the same line in real files) */
    unsigned generation_line;     /* IES record B field 2 */
};

/* A zeroed object with neutral metadata (factors 1). NULL when out of memory. */
cdl_photometry *cdl_photometry_alloc(void);

/* Validate and install the table (copied), infer or check the symmetry,
 * and precompute lookups, maximum and flux. On failure the message names
 * `what` (e.g. "table") and the offending value. */
cdl_status cdl_photometry_set_table(cdl_photometry *p, cdl_photometric_type type, cdl_photometry_symmetry symmetry,
                                    const double *h, size_t nh, const double *v, size_t nv, const double *cd,
                                    cdl_error *err);

/* Install tilt data (copied). */
cdl_status cdl_photometry_set_tilt(cdl_photometry *p, int geometry, const double *angles, const double *factors,
                                   size_t count, cdl_error *err);

/* Append a warning: its stable code (a string literal from the list in
 * docs/photometry-warnings.md), the line of the file it points at (0: the
 * file as a whole) and its message (printf-style, naming the file).
 * Returns CDL_OK or an out-of-memory status. */
cdl_status cdl_photometry_add_warning(cdl_photometry *p, const char *code, unsigned line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Append a keyword (copies key and value). */
cdl_status cdl_photometry_add_keyword(cdl_photometry *p, const char *key, size_t key_len, const char *value,
                                      size_t value_len);

/* Append text to the last keyword's value after a '\n' ([MORE]). */
cdl_status cdl_photometry_append_keyword(cdl_photometry *p, const char *value, size_t value_len);

/* Copy all metadata, keywords, tilt data and warnings of `src` into `dst`
 * (which has none yet); the table is not copied. */
cdl_status cdl_photometry_copy_metadata(cdl_photometry *dst, const cdl_photometry *src);

/* Reduce a frame C (any value) into the stored range of a type C table. */
double cdl_photometry_reduce_c(cdl_photometry_symmetry symmetry, double c_deg);

/* Bilinear value at table coordinates (h, v), after symmetry reduction;
 * zero outside the ranges. */
double cdl_photometry_eval_hv(const cdl_photometry *p, double h_deg, double v_deg);

/* Table coordinates (h, v) of a frame direction (any length > 0). Returns 0
 * for the zero or a non-finite vector. */
int cdl_photometry_direction_to_hv(cdl_photometric_type type, cdl_vec3 d, double *h_deg, double *v_deg);

/* Flux in the 18 zones of 10 degrees of frame gamma: exact for type C,
 * a quadrature for types A/B (see photometry_flux.c). */
void cdl_photometry_zones(const cdl_photometry *p, double zone[CDL_PHOTOMETRY_ZONES]);

/* Exact flux of the table (no caching); used once at set-up. */
double cdl_photometry_compute_flux(const cdl_photometry *p);

/* Every plane of a type C table's full circle, in [0, 360), ascending
 * (the stored sector and its mirror images). malloc'd. */
cdl_status cdl_photometry_full_planes(const cdl_photometry *p, double **c, size_t *count);

/* Copy a string of given length into a fixed buffer, trimmed of surrounding
 * blanks, always NUL-terminated. */
void cdl_photometry_copy_text(char *dst, size_t dst_size, const char *src, size_t len);

/* Where an IES file's [TESTLAB] goes in EULUMDAT, which has no field for
 * it: after the date on line 12 ("2026-01-01, test lab: Lab name"); the
 * EULUMDAT reader splits it back off into a TESTLAB keyword. */
#define CDL_LDT_TESTLAB_MARK ", test lab: "

/* Set meta.radiometric from the keywords (photometry_units.c). */
void cdl_photometry_detect_units(cdl_photometry *p);

/* Case-insensitive ASCII comparison of NUL-terminated strings. */
int cdl_photometry_strcaseeq(const char *a, const char *b);

/* Checks across header and table (LOR, stated flux, DFF) that become
 * warnings, then the header's own fields (cdl_photometry_check_fields). */
cdl_status cdl_photometry_check_consistency(cdl_photometry *p, const char *name);

/* Checks of header fields against the standards and each other
 * (photometry_check_fields.c): LM-63-2019's required keywords and
 * file-generation codes, the ballast factor's range, EULUMDAT's text
 * lengths, dimensions, measurement tilt, direct ratios and indicators. */
cdl_status cdl_photometry_check_fields(cdl_photometry *p, const char *name);

/* "FILE:LINE" (or "FILE" when line is 0) into buf; returns buf. */
const char *cdl_photometry_where(char *buf, size_t size, const char *name, unsigned line);

/* The unit of the table's values and of its integral, as printed: "cd" and
 * "lm", or for a radiometric file "W/sr" and "W" with the file's prefix
 * ("mW/sr" and "mW"). Static strings. */
const char *cdl_photometry_intensity_unit(const cdl_photometry *p);
const char *cdl_photometry_flux_unit(const cdl_photometry *p);

/* Relative flux differences above this are reported (3 %: real files
 * reproduce their stated LORL within 0.35 points, the worst real one by 2.1 %). */
#define CDL_PHOTOMETRY_FLUX_TOLERANCE 0.03

#endif
