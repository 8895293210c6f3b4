/* direct_ratios.c - the direct ratios of EULUMDAT lines 27-36: for a room
 * index k, the share of the luminaires' flux that falls directly on the
 * work plane (CIE 52 and LiTG "direct ratio", used with the room's
 * reflections to find the utilance of the lumen method).
 *
 * CIE 52's own tabulated method (flux codes times coefficients per
 * spacing-to-height ratio) was not available to us; what is implemented is
 * its definition, computed exactly for a stated room:
 *  - a square room of side a and the luminaires' plane h above the work
 *    plane, so that k = a b / (h (a + b)) = a / (2 h);
 *  - luminaires in a regular array at spacing s = h (a spacing-to-height
 *    ratio of 1), each in the middle of its own s x s cell: taken as
 *    spread evenly over the ceiling inset by s / 2 from the walls (the
 *    array's continuum limit, so that the ratio varies smoothly with k);
 *  - DR(k) = (1 / Phi) integral over the lower hemisphere of I(w) T_k(w) dw,
 *    Phi the luminaire's total flux and T_k(w) the share of luminaire
 *    positions from which direction w lands on the work plane. A luminaire
 *    at x in [m, a - m] (m = s / 2) sends w to x + d, d = h tan(gamma) cos C
 *    (and likewise in y), inside [0, a] for a share
 *        S(d) = max(0, min(a - m, a - |d|) - m) / (a - 2 m)
 *    of the positions, so T_k = S(h tan(gamma) cos C) S(h tan(gamma) sin C).
 * DR = (Phi_down / Phi) x (the share of Phi_down landing on the plane):
 * the first factor exact, the second a ratio of two sums over the same
 * quadrature nodes (sphere_quadrature.h, cut at the table's own angles).
 * For a Lambertian luminaire DR is the configuration factor from the inset
 * square of luminaires to the work plane (tests/lights/photometry check it
 * against that closed form). Real files' stated ratios come from other
 * arrangements and differ from these by up to about 0.1.
 */
#include <math.h>

#include "base/error_report.h"
#include "lights/photometry/sphere_quadrature.h"
#include "radiometry/constants.h"

static const double room_index[CDL_DIRECT_RATIO_COUNT] = {0.60, 0.80, 1.00, 1.25, 1.50,
                                                          2.00, 2.50, 3.00, 4.00, 5.00};

/* Spacing of the luminaires over the height h of their plane above the work plane. */
#define SPACING_TO_HEIGHT 1.0

/* Quadrature: 0.5 degree steps of gamma (2 Gauss nodes each), C every degree. */
#define DR_GAMMA_STEP_DEG 0.5
#define DR_C_NODES 360

double cdl_direct_ratio_room_index(int k)
{
    return k >= 0 && k < CDL_DIRECT_RATIO_COUNT ? room_index[k] : 0.0;
}

/* The share of luminaire positions in [m, a - m] from which a displacement d stays in [0, a]. */
static double share(double d, double a, double m)
{
    d = fabs(d);
    return fmax(0.0, fmin(a - m, a - d) - m) / (a - 2.0 * m);
}

cdl_status cdl_photometry_direct_ratios(const cdl_photometry *p, double ratio[CDL_DIRECT_RATIO_COUNT],
                                        cdl_error *err)
{
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT; ++k) ratio[k] = 0.0;
    double flux = p->flux_lm; /* the table's own integral: the ratio has no unit */
    if (!(flux > 0.0)) return CDL_OK;
    cdl_sphere_quadrature q;
    if (!cdl_sphere_quadrature_sample(p, 0.0, 90.0, DR_GAMMA_STEP_DEG, DR_C_NODES, &q))
        return cdl_error_out_of_memory(err);
    /* DR is the downward share of the flux (exact, photometry_flux.c) times
     * the share of that downward flux which reaches the work plane, the
     * latter a ratio of two sums over the same nodes: so DR never exceeds
     * the downward share and grows with k whatever the quadrature's error. */
    double down = cdl_sphere_quadrature_flux(&q);
    double down_share = fmin(1.0, cdl_photometry_zone_flux(p, 0.0, 90.0).lm / flux);
    const double h = 1.0, m = 0.5 * SPACING_TO_HEIGHT * h;
    for (int k = 0; k < CDL_DIRECT_RATIO_COUNT && down > 0.0 && down_share > 0.0; ++k) {
        double a = 2.0 * room_index[k] * h, sum = 0.0;
        for (size_t i = 0; i < q.ng; ++i) {
            double t = h * tan(q.gamma_deg[i] * CDL_DEG_TO_RAD), ring = 0.0;
            for (size_t j = 0; j < q.nc; ++j) {
                double c = q.c_deg[j] * CDL_DEG_TO_RAD;
                double T = share(t * cos(c), a, m) * share(t * sin(c), a, m);
                if (T > 0.0) ring += q.cd[i * q.nc + j] * q.c_weight[j] * T;
            }
            sum += ring * q.weight[i];
        }
        ratio[k] = down_share * fmin(1.0, sum / down);
    }
    cdl_sphere_quadrature_free(&q);
    return CDL_OK;
}
