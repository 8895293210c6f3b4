/* ugr.h - the Unified Glare Rating (CIE 117:1995, eq. 4.1) and its error.
 *
 *     UGR = 8 log10( (0.25 / Lb) sum_i L_i^2 omega_i / p_i^2 )
 *
 *   symbol   meaning                                                 unit
 *   Lb       background luminance: the luminance of the field the    cd/m^2
 *            sources are seen against, E_ind / pi with E_ind the
 *            indirect illuminance at the eye (CIE 117 4.2)
 *   L_i      luminance of source i's luminous parts towards the eye  cd/m^2
 *   omega_i  solid angle of those parts at the eye                   sr
 *   p_i      Guth's position index of source i (position_index.h)    1
 *
 * CIE 117 gives the scale from 10 (just perceptible) to 30 (just
 * intolerable) in steps of 3; a number below 10 is still computed here.
 *
 * Errors: each term t_i = L_i^2 omega_i / p_i^2 and Lb may carry a stated
 * standard error (a sampled solid angle, a sampled background); they are
 * taken as independent and propagated to first order (the delta method):
 *     sigma_UGR = (8 / ln 10) sqrt( (sigma_S / S)^2 + (sigma_Lb / Lb)^2 ),
 *     sigma_S^2 = sum_i sigma_ti^2,   sigma_t / t = sqrt(4 (sigma_L/L)^2 +
 *     (sigma_omega/omega)^2),
 * which holds while the relative errors are small (below about 10 %).
 *
 * Units as above. Plain values, pure functions: thread-safe. Errors: the
 * functions that can fail say so.
 */
#ifndef CANDELA_GLARE_UGR_H
#define CANDELA_GLARE_UGR_H

#include <stddef.h>

#include "base/error.h"
#include "radiometry/units.h"

/* One source's term L^2 omega / p^2 (cd^2 m^-4 sr) and its standard error
 * from those of L and omega (0 when both are exact). 0 for p <= 0 (a
 * source outside the position index table contributes nothing). */
typedef struct cdl_ugr_term {
    double value;
    double sigma;
} cdl_ugr_term;

cdl_ugr_term cdl_ugr_term_make(cdl_luminance L, double L_stderr, double omega_sr, double omega_stderr, double p);

/* The sum of the terms, accumulated term by term. Start from {0}. */
typedef struct cdl_ugr_sum {
    double value;
    double variance;
    size_t count;  /* terms added with a value above 0 */
} cdl_ugr_sum;

void cdl_ugr_sum_add(cdl_ugr_sum *sum, cdl_ugr_term term);

typedef struct cdl_ugr {
    int defined;     /* 0: no source in view gives light (the sum is 0): no rating */
    double value;    /* UGR (0 when not defined) */
    double sigma;  /* its standard error (first order, above) */
} cdl_ugr;

/* The rating of a sum against a background luminance Lb with its standard
 * error. CDL_ERR_INPUT when Lb is not a positive finite number, its error
 * is negative or not finite, or the sum is negative or not finite (the
 * message says which); *out is then untouched. */
cdl_status cdl_ugr_evaluate(const cdl_ugr_sum *sum, cdl_luminance background, double background_stderr,
                            cdl_ugr *out, cdl_error *err);

#endif
