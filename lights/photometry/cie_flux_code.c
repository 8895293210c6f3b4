/* cie_flux_code.c - the CIE flux code (CIE 52:1982, as the EULUMDAT tools
 * and GLDF print it): five percentages N1..N5 of a distribution,
 *   N1, N2, N3: the downward flux within the cones about nadir of half
 *       angle 41.4, 60 and 75.5 degrees (solid angles pi/2, pi and 3 pi/2:
 *       cos = 3/4, 1/2, 1/4), as a share of the whole downward flux;
 *   N4: the downward flux as a share of the lamp flux (DLOR);
 *   N5: the whole flux as a share of the lamp flux (LOR).
 * Without a lamp flux (absolute photometry) the luminaire's flux stands in
 * for it (LOR 100 %). The code is printed rounded to whole percents.
 */
#include <math.h>

#include "lights/photometry/photometry_internal.h"
#include "radiometry/constants.h"

void cdl_photometry_cie_flux_code(const cdl_photometry *p, double n[5])
{
    for (int k = 0; k < 5; ++k) n[k] = 0.0;
    double total = p->flux_lm; /* the table's integral; every N is a ratio of two */
    double down = cdl_photometry_zone_flux(p, 0.0, 90.0).lm;
    const cdl_photometry_metadata *m = &p->meta;
    double lamp = !m->absolute && m->rated_lamp_flux_lm > 0.0 ? m->rated_lamp_flux_lm : total;
    static const double cone_cos[3] = {0.75, 0.5, 0.25};
    double half[3];
    cdl_luminous_flux cone[3];
    for (int k = 0; k < 3; ++k) half[k] = acos(cone_cos[k]) * CDL_RAD_TO_DEG;
    cdl_photometry_cone_fluxes(p, half, 3, cone);
    for (int k = 0; k < 3 && down > 0.0; ++k) n[k] = 100.0 * cone[k].lm / down;
    if (lamp > 0.0) {
        n[3] = 100.0 * down / lamp;
        n[4] = 100.0 * total / lamp;
    }
}
