/* near_field_bound.h - how far a luminaire with a luminous opening must be treated as extended.
 *
 * Seen from far away a luminaire is its photometric centre: E = I cos / d^2.
 * Nearer, its opening's extent matters, and the point model errs by
 *  - a flat opening (rectangle, circle, ellipse, vertical circle or
 *    ellipse): second order in the opening's size. E of the extended
 *    emitter is the mean of f(x) = I(w_x) cos / r_x^2 over the opening's
 *    points x; the opening's centroid is its centre, so the first-order
 *    term of f about the centre averages out and the error is
 *    K (R / d)^2, R the opening's circumradius (half its largest
 *    dimension). For a Lambertian disk on its axis exactly R^2 / (d^2 +
 *    R^2), so K = 1 there; the table's curvature and the receiver's
 *    direction raise it elsewhere, and K is measured per luminaire
 *    (cdl_near_field_bound_measure);
 *  - a luminous solid: first order, its visible side being nearer than its
 *    centre by up to R: at most (d / (d - R))^2 - 1 + (R / d)^2 (the
 *    nearest face point's inverse square, and the flat part's second-order
 *    term on top).
 * The solver spreads a luminaire over its opening wherever that error
 * could exceed a share of the target (solver/scene/scene_lights.c), so the
 * switch distance follows the accuracy asked instead of a fixed multiple
 * of the opening's size.
 *
 * Not public. Units: metres; errors relative. Thread-safe; measuring
 * creates and releases emitters of its own.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_NEAR_FIELD_BOUND_H
#define CANDELA_LIGHTS_EMITTERS_NEAR_FIELD_BOUND_H

#include "base/error.h"
#include "lights/emitters/emitter.h"

/* "auto" spreads a luminaire over its opening nearer than the distance
 * where the bound falls to CDL_NEAR_FIELD_SHARE of the target, and never
 * nearer than CDL_NEAR_FIELD_DISTANCES opening sizes. A quarter: a bias of
 * a quarter sigma adds 3 % to the error in quadrature and leaves the stated
 * error's calibration as it is. */
#define CDL_NEAR_FIELD_DISTANCES 5.0
#define CDL_NEAR_FIELD_SHARE 0.25

typedef struct cdl_near_field_bound {
    int flat;                 /* 1: a flat opening (second order); 0: a luminous solid (first order) */
    double radius_m;          /* R: half the opening's largest dimension */
    double k;                 /* flat: the measured coefficient K of K (R / d)^2 */
} cdl_near_field_bound;

/* The bound for the goniometric luminaire of `params` (its photometry has
 * a spread opening, cdl_luminous_opening_is_spread). For a flat opening K
 * is the largest relative difference between the point model and the
 * opening's cubature (to 1e-5) over 842 directions of emission (every 5
 * degrees of polar angle, 15 of azimuth), each seen from 20 R by a receiver
 * facing the luminaire, times 20^2, and a quarter more for the directions
 * between them; the difference counts relative to the point model's value
 * there, but to no less than a tenth of the peak (in a beam's fringe the
 * relative error grows without bound on light that is a few per cent of
 * the luminaire's). Errors: those of creating the emitters. */
cdl_status cdl_near_field_bound_measure(const cdl_goniometric_params *params, cdl_near_field_bound *out,
                                        cdl_error *err);

/* The bound on the point model's relative error at distance d (m) from the
 * opening's centre; 1 (no bound) within R for a solid. */
double cdl_near_field_bound_error(const cdl_near_field_bound *bound, double d);

/* The smallest distance beyond which the bound is at most `relative` (> 0). */
double cdl_near_field_bound_distance(const cdl_near_field_bound *bound, double relative);

/* Where "auto" switches for a solve's target error (relative): the bound's
 * distance for CDL_NEAR_FIELD_SHARE of it, at least CDL_NEAR_FIELD_DISTANCES
 * times the opening's largest dimension (2 R). */
double cdl_near_field_switch_distance(const cdl_near_field_bound *bound, double target);

/* The switch distances of a photometry's opening (placed as it is, at the
 * origin) for `count` targets, into out[]. Errors: those of measuring. */
cdl_status cdl_near_field_switch_distances(const cdl_photometry *photometry, const double *targets, size_t count,
                                           double *out, cdl_error *err);

#endif
