/* ugr.c - the Unified Glare Rating of a set of sources (CIE 117:1995). */
#include <math.h>

#include "base/error_report.h"
#include "glare/ugr.h"

cdl_ugr_term cdl_ugr_term_make(cdl_luminance L, double L_stderr, double omega_sr, double omega_stderr, double p)
{
    cdl_ugr_term t = {0.0, 0.0};
    if (!(p > 0.0) || !(L.cd_m2 > 0.0) || !(omega_sr > 0.0)) return t;
    /* the glare term of CIE 117:1995 eq. 4.1 */
    t.value = L.cd_m2 * L.cd_m2 * omega_sr / (p * p);
    /* first-order propagation: d ln t = 2 d ln L + d ln omega */
    double rL = L_stderr / L.cd_m2, rw = omega_stderr / omega_sr;
    t.sigma = t.value * sqrt(4.0 * rL * rL + rw * rw);
    return t;
}

void cdl_ugr_sum_add(cdl_ugr_sum *sum, cdl_ugr_term term)
{
    if (!(term.value > 0.0)) return;
    sum->value += term.value;
    sum->variance += term.sigma * term.sigma;
    ++sum->count;
}

cdl_status cdl_ugr_evaluate(const cdl_ugr_sum *sum, cdl_luminance background, double background_stderr,
                            cdl_ugr *out, cdl_error *err)
{
    double Lb = background.cd_m2;
    if (!(Lb > 0.0) || !isfinite(Lb))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "background luminance: expected a positive number of cd/m2, found %g (UGR divides by it)",
                             Lb);
    if (!(background_stderr >= 0.0) || !isfinite(background_stderr))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "background luminance's standard error: expected 0 or more, found %g", background_stderr);
    if (!(sum->value >= 0.0) || !isfinite(sum->value) || !(sum->variance >= 0.0) || !isfinite(sum->variance))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "glare sources: expected terms L^2 omega / p^2 of 0 or more, found a sum of %g (variance %g)",
                             sum->value, sum->variance);
    cdl_ugr r = {0, 0.0, 0.0};
    if (sum->value > 0.0) {
        r.defined = 1;
        /* CIE 117:1995 eq. 4.1 */
        r.value = 8.0 * log10(0.25 * sum->value / Lb);
        /* delta method: dUGR = (8 / ln 10)(dS / S - dLb / Lb), S and Lb independent */
        double rs = sqrt(sum->variance) / sum->value, rb = background_stderr / Lb;
        r.sigma = 8.0 / log(10.0) * sqrt(rs * rs + rb * rb);
    }
    *out = r;
    return CDL_OK;
}
