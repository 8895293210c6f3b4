/* photometry.h - one photometric model for IES LM-63 and EULUMDAT data.
 *
 * A cdl_photometry holds a luminaire's measured intensity distribution in
 * absolute candela (the file's candela multiplier / conversion factor and,
 * for relative EULUMDAT data, the lamp flux already applied), its angle grid
 * and symmetry, lamp data, luminous opening, keywords, and tilt data.
 *
 * Coordinate convention (the "photometric frame"), used by every function
 * that takes a direction: right-handed, nadir (gamma = 0, type C) along -z,
 * the C = 0 half-plane containing +x, C = 90 containing +y, so that
 *     direction = (sin g cos C, sin g sin C, -cos g).
 * Types A and B are mapped onto this frame as documented in photometry.c.
 *
 * Application factors are NOT in the table: ballast factor, tilt factor,
 * maintenance factor and scene multipliers are applied by the emitter at
 * render time (see cdl_photometry_output_factor and cdl_photometry_tilt_factor).
 *
 * Thread-safety: a finished cdl_photometry is immutable; every query is
 * thread-safe.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_H
#define CANDELA_LIGHTS_PHOTOMETRY_H

#include <stddef.h>

#include "radiometry/error.h"
#include "radiometry/units.h"
#include "radiometry/vec3.h"

typedef enum cdl_photometric_type {
    CDL_PHOTOMETRIC_TYPE_C = 1, /* polar axis vertical (LM-63 code 1, EULUMDAT) */
    CDL_PHOTOMETRIC_TYPE_B = 2, /* polar axis horizontal, floodlights (code 2) */
    CDL_PHOTOMETRIC_TYPE_A = 3  /* automotive (code 3) */
} cdl_photometric_type;

typedef struct cdl_photometry cdl_photometry;

typedef struct cdl_photometry_read_options {
    int strict;              /* 1: warnings become errors */
} cdl_photometry_read_options;
#define CDL_PHOTOMETRY_READ_OPTIONS_DEFAULT {0}

/* Read an IES (any LM-63 version) or EULUMDAT file; the format is detected
 * from the content, not the extension. Errors: CDL_ERR_INPUT with
 * "FILE:LINE: expected ..., found ...". */
cdl_status cdl_photometry_read_file(const char *path, const cdl_photometry_read_options *options,
                                    cdl_photometry **out, cdl_error *err);

/* Build a type C table from arrays (used by tests and by programs that make
 * distributions): planes c_deg[nc] (ascending, within [0, 360]), angles
 * gamma_deg[ng] (ascending, within [0, 180]), candela[nc * ng] with plane
 * index outermost. Symmetry is inferred from the C range exactly as for IES
 * horizontal angles (single plane: rotational; 0..90: quadrant; 0..180:
 * bilateral; 90..270: bilateral about 90-270; otherwise full). */
cdl_status cdl_photometry_create_type_c(const double *c_deg, size_t nc, const double *gamma_deg, size_t ng,
                                        const double *candela, cdl_photometry **out, cdl_error *err);

void cdl_photometry_release(cdl_photometry *photometry);

/* I(direction) in candela, direction in the photometric frame (need not be
 * unit length), interpolated linearly in C and in gamma (bilinear), with
 * symmetry expansion and wrap-around; zero outside the measured gamma range. */
cdl_luminous_intensity cdl_photometry_intensity(const cdl_photometry *photometry, cdl_vec3 direction);

/* Same, by angles in degrees (type C meaning: C azimuth, gamma from nadir). */
cdl_luminous_intensity cdl_photometry_intensity_c_gamma(const cdl_photometry *photometry, double c_deg,
                                                        double gamma_deg);

/* Total flux: the exact integral of the interpolated distribution over the sphere. */
cdl_luminous_flux cdl_photometry_flux(const cdl_photometry *photometry);

/* Largest tabulated intensity. */
cdl_luminous_intensity cdl_photometry_max_intensity(const cdl_photometry *photometry);

/* Render-time output factor from the file: the ballast factor (LM-63
 * record B field 1; 1 for EULUMDAT) times, for LM-63-1995 and older, the
 * ballast-lamp photometric factor. Never the LM-63-2019 file-generation code. */
double cdl_photometry_output_factor(const cdl_photometry *photometry);

/* Tilt multiplier at an installed tilt angle in degrees (linear
 * interpolation in the file's TILT table, clamped at its ends); 1 when the
 * file has TILT=NONE. */
double cdl_photometry_tilt_factor(const cdl_photometry *photometry, double tilt_deg);

#endif
