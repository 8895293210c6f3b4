/* ldt_full_table.h - an EULUMDAT file of Isym 1..4 that holds all its Mc
 * planes: do the extra planes agree with the indicator (ldt_full_table.c)?
 * Not public. */
#ifndef CANDELA_LIGHTS_FORMATS_LDT_FULL_TABLE_H
#define CANDELA_LIGHTS_FORMATS_LDT_FULL_TABLE_H

#include <stddef.h>

#include "lights/photometry/photometry_internal.h"

/* Does Isym store the plane C? 1 the C0 plane, 2 C in [0, 180], 3 [90, 270], 4 [0, 90], 0 all. */
int cdl_ldt_stored_plane(long isym, double c);

/* The table symmetry an Isym stands for (none for 0 and anything else). */
cdl_photometry_symmetry cdl_ldt_symmetry(long isym);

/* Planes (ascending C), ng values each, plane outermost. */
typedef struct cdl_ldt_table {
    double *planes, *cd;
    size_t np, ng;
    cdl_photometry_symmetry symmetry;
} cdl_ldt_table;

/* 1: the full table agrees with Isym's symmetry; *use holds the planes
 * Isym names (malloc'd, the caller frees). 0: the data contradict it;
 * *worst is the largest difference in cd, at full->planes[*at_plane],
 * gamma[*at_gamma]. -1: out of memory. */
int cdl_ldt_check_full_table(const cdl_ldt_table *full, long isym, const double *gamma, cdl_ldt_table *use,
                             double *worst, size_t *at_plane, size_t *at_gamma);

#endif
