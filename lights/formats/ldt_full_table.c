/* ldt_full_table.c - an EULUMDAT file of Isym 1 to 4 that holds every one
 * of its Mc planes anyway (some writers store the full table whatever the
 * indicator): the planes the indicator leaves out show whether it is
 * right. Where they are the mirror images it promises (within 1 % of the
 * peak), the planes it names are used, taken from the full table (which
 * starts at C0 in the file, whatever the indicator); where they are not,
 * the data contradict the indicator, and the full table is read as it is
 * (Isym 0), with a warning. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lights/formats/ldt_full_table.h"

/* Planes of a full table agree with a symmetry within 1 % of the peak:
 * the rounding and measurement noise real files leave between mirror planes. */
#define MIRROR_TOLERANCE 0.01

int cdl_ldt_stored_plane(long isym, double c)
{
    switch (isym) {
    case 1: return c == 0.0;
    case 2: return c >= 0.0 && c <= 180.0;
    case 3: return c >= 90.0 && c <= 270.0;
    case 4: return c >= 0.0 && c <= 90.0;
    default: return 1;
    }
}

cdl_photometry_symmetry cdl_ldt_symmetry(long isym)
{
    return isym == 1   ? CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL
           : isym == 2 ? CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180
           : isym == 3 ? CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270
           : isym == 4 ? CDL_PHOTOMETRY_SYMMETRY_QUADRANT
                       : CDL_PHOTOMETRY_SYMMETRY_NONE;
}

/* The sector's planes of the full table `t` into `out`; returns 0 when out of memory. */
static int sector(const cdl_ldt_table *full, long isym, cdl_ldt_table *out)
{
    out->planes = malloc(full->np * sizeof *out->planes);
    out->cd = malloc(full->np * full->ng * sizeof *out->cd);
    out->np = 0;
    out->ng = full->ng;
    if (!out->planes || !out->cd) return 0;
    for (size_t i = 0; i < full->np; ++i) {
        if (!cdl_ldt_stored_plane(isym, full->planes[i])) continue;
        out->planes[out->np] = full->planes[i];
        memcpy(out->cd + out->np * full->ng, full->cd + i * full->ng, full->ng * sizeof *out->cd);
        ++out->np;
    }
    out->symmetry = cdl_ldt_symmetry(isym);
    return out->np > 0;
}

int cdl_ldt_check_full_table(const cdl_ldt_table *full, long isym, const double *gamma, cdl_ldt_table *use,
                             double *worst, size_t *at_plane, size_t *at_gamma)
{
    memset(use, 0, sizeof *use);
    *worst = 0.0;
    cdl_ldt_table part;
    memset(&part, 0, sizeof part);
    cdl_photometry *promised = cdl_photometry_alloc();
    int ok = promised && sector(full, isym, &part) &&
             cdl_photometry_set_table(promised, CDL_PHOTOMETRIC_TYPE_C, part.symmetry, part.planes, part.np, gamma,
                                      part.ng, part.cd, NULL) == CDL_OK;
    double peak = 0.0;
    for (size_t k = 0; k < full->np * full->ng; ++k) peak = fmax(peak, full->cd[k]);
    for (size_t i = 0; ok && i < full->np; ++i)
        for (size_t j = 0; j < full->ng; ++j) {
            double d = fabs(cdl_photometry_intensity_c_gamma(promised, full->planes[i], gamma[j]).cd -
                            full->cd[i * full->ng + j]);
            if (d > *worst) {
                *worst = d;
                *at_plane = i;
                *at_gamma = j;
            }
        }
    cdl_photometry_release(promised);
    if (!ok) {
        free(part.planes);
        free(part.cd);
        return -1;
    }
    if (*worst <= MIRROR_TOLERANCE * peak) {
        *use = part;
        return 1;
    }
    free(part.planes);
    free(part.cd);
    return 0;
}
