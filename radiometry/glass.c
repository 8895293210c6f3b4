/* glass.c - a thin pane's transmittance by angle of incidence (glass.h). */
#include "radiometry/glass.h"

#include <math.h>

#include "base/error_report.h"

/* r0, one face's reflectance at normal incidence */
static double normal_reflectance(void)
{
    double q = (CDL_GLASS_INDEX - 1.0) / (CDL_GLASS_INDEX + 1.0);
    return q * q;
}

double cdl_glass_max_transmittance(void)
{
    double r0 = normal_reflectance();
    return (1.0 - r0) / (1.0 + r0);
}

cdl_status cdl_glass_from_transmittance(double Tn, cdl_glass *out, cdl_error *err)
{
    double top = cdl_glass_max_transmittance();
    if (!(isfinite(Tn) && Tn > 0.0 && Tn <= top))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a normal transmittance in (0, %.4f] (a pane of index %.2f without absorption "
                             "transmits %.4f), found %g",
                             top, CDL_GLASS_INDEX, top, Tn);
    double r0 = normal_reflectance(), q = (1.0 - r0) * (1.0 - r0);
    /* the positive root of r0^2 T_n a^2 + q a - T_n = 0, written so that it
     * does not cancel: a = 2 T_n / (q + sqrt(q^2 + 4 r0^2 T_n^2)) */
    double a = 2.0 * Tn / (q + sqrt(q * q + 4.0 * r0 * r0 * Tn * Tn));
    out->normal_transmittance = Tn;
    out->internal = fmin(1.0, a);
    return CDL_OK;
}

double cdl_glass_transmittance(const cdl_glass *g, double cos_theta)
{
    double c = fmin(1.0, fabs(cos_theta));
    if (!(c > 0.0)) return 0.0;
    double n = CDL_GLASS_INDEX, s2 = (1.0 - c * c) / (n * n);
    double ct = sqrt(fmax(0.0, 1.0 - s2));
    /* Fresnel reflectances of one face, s and p polarisation */
    double rs = (c - n * ct) / (c + n * ct), rp = (ct - n * c) / (ct + n * c);
    rs *= rs;
    rp *= rp;
    /* the internal transmittance along the slanted path */
    double tau = pow(g->internal, 1.0 / ct);
    double Ts = tau * (1.0 - rs) * (1.0 - rs) / (1.0 - rs * rs * tau * tau);
    double Tp = tau * (1.0 - rp) * (1.0 - rp) / (1.0 - rp * rp * tau * tau);
    return 0.5 * (Ts + Tp);
}
