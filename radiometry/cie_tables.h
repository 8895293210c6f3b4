/* cie_tables.h - the CIE photopic V(lambda) and scotopic V'(lambda) functions.
 *
 *   V(lambda)   CIE 1924 / 1931 2-degree photopic, 360-830 nm, 1 nm steps
 *   V'(lambda)  CIE 1951 scotopic, 380-780 nm, 5 nm steps (zero outside)
 * Between tabulated wavelengths the functions are linear; outside their
 * range they are zero. Sources: V(lambda) as CIE 018:2019 and ISO/CIE
 * 11664-1:2019 tabulate the 1931 observer's y-bar (the 1 nm values of the
 * CVRL database); V'(lambda) the CIE 1951 defining table (Wyszecki and
 * Stiles, Color Science, 2nd ed., table I(4.3.2)).
 *
 * Units: wavelengths in nanometres; efficiencies dimensionless.
 * Ownership: the tables are static and read-only, never freed. Thread
 * safety: thread-safe. Errors: none; outside a table's range the value is 0.
 */
#ifndef CANDELA_RADIOMETRY_CIE_TABLES_H
#define CANDELA_RADIOMETRY_CIE_TABLES_H

#include <stddef.h>

#include "radiometry/units.h"

typedef enum cdl_vision {
    CDL_VISION_PHOTOPIC = 0, /* cone vision, V(lambda), Km = 683 lm/W */
    CDL_VISION_SCOTOPIC = 1  /* rod vision, V'(lambda), K'm = 1700 lm/W */
} cdl_vision;

/* A regularly sampled table: values[i] at first_nm + i * step_nm. */
typedef struct cdl_cie_table {
    double first_nm;
    double step_nm;
    size_t count;
    const double *values;
} cdl_cie_table;

/* The table of a vision (V'(lambda) for CDL_VISION_SCOTOPIC, V(lambda)
 * otherwise): static storage, never NULL. */
const cdl_cie_table *cdl_cie_luminous_efficiency_table(cdl_vision vision);

/* The table's piecewise-linear value at lambda_nm (0 outside its range). */
double cdl_cie_table_value(const cdl_cie_table *table, double lambda_nm);

/* V(lambda) or V'(lambda), dimensionless, peak 1. */
double cdl_cie_luminous_efficiency(cdl_vision vision, cdl_wavelength wavelength);

#endif
