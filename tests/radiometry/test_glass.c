/* A thin pane's transmittance by angle (radiometry/glass.h):
 *  - at normal incidence the T_n it was made from, 0 at grazing incidence,
 *    falling with the angle;
 *  - its internal transmittance a equal to Radiance's transmissivity from
 *    transmittance for n = 1.52, tn = (sqrt(0.8402528435 + 0.0072522239
 *    T_n^2) - 0.9166530661) / 0.0036261119 / T_n (the Radiance reference
 *    manual, `glass`), to its constants' 10 digits;
 *  - at oblique incidence against the slab formula written here again from
 *    Snell's and Fresnel's laws (s and p averaged), to rounding;
 *  - clear glass without absorption (a = 1): at normal incidence (1 - r0) /
 *    (1 + r0) with r0 = (0.52 / 2.52)^2, and the largest T_n accepted;
 *  - bad transmittances refused.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "radiometry/glass.h"

/* the slab of internal transmittance a at incidence theta */
static double slab(double a, double theta)
{
    double n = 1.52, ci = cos(theta), st = sin(theta) / n, ct = sqrt(1.0 - st * st);
    double Rs = pow((ci - n * ct) / (ci + n * ct), 2), Rp = pow((n * ci - ct) / (n * ci + ct), 2);
    double t = pow(a, 1.0 / ct), sum = 0.0;
    const double R[2] = {Rs, Rp};
    for (int k = 0; k < 2; ++k) sum += t * (1 - R[k]) * (1 - R[k]) / (1 - R[k] * R[k] * t * t);
    return sum / 2;
}

int main(void)
{
    cdl_error err;
    const double Tn[4] = {0.1, 0.5, 0.8, 0.9};
    for (int k = 0; k < 4; ++k) {
        cdl_glass g;
        CHECK_OK(cdl_glass_from_transmittance(Tn[k], &g, &err), &err);
        double num = sqrt(0.8402528435 + 0.0072522239 * Tn[k] * Tn[k]) - 0.9166530661;
        double radiance = num / 0.0036261119 / Tn[k];
        /* Radiance's constants carry 10 digits (5e-11 each); the numerator
         * cancels to num, so its relative error is about 1e-10 / num (1e-6
         * at T_n = 0.1, 2e-9 at 0.9) */
        CHECK_REL(g.internal, radiance, 2e-10 / num);
        CHECK_REL(cdl_glass_transmittance(&g, 1.0), Tn[k], 1e-14);
        CHECK(cdl_glass_transmittance(&g, 0.0) == 0.0);
        double last = 2.0;
        for (int d = 0; d <= 89; d += 1) {
            double th = d * CDL_DEG_TO_RAD, T = cdl_glass_transmittance(&g, cos(th));
            CHECK_REL(T, slab(g.internal, th), 1e-13);
            CHECK(T < last + 1e-15);
            last = T;
            /* either side of the pane alike */
            CHECK(cdl_glass_transmittance(&g, -cos(th)) == T);
        }
    }
    double r0 = pow(0.52 / 2.52, 2);
    CHECK_REL(cdl_glass_max_transmittance(), (1 - r0) / (1 + r0), 1e-15);
    cdl_glass clear;
    CHECK_OK(cdl_glass_from_transmittance(cdl_glass_max_transmittance(), &clear, &err), &err);
    CHECK_REL(clear.internal, 1.0, 1e-12);
    const double bad[4] = {0.0, -0.2, 0.95, NAN};
    for (int k = 0; k < 4; ++k) {
        cdl_glass g;
        CHECK(cdl_glass_from_transmittance(bad[k], &g, &err) == CDL_ERR_INPUT);
        CHECK(strstr(err.message, "normal transmittance in (0, 0.9183]") != NULL);
    }
    return check_finish();
}
