/* near_field_bound.c - where the point model of a luminous opening is close enough (near_field_bound.h). */
#include "lights/emitters/near_field_bound.h"

#include <math.h>

#include "base/error_report.h"
#include "lights/photometry/photometry.h"
#include "radiometry/constants.h"

/* The receiver's distance, in opening radii, at which K is measured: far
 * enough that the (R / d)^4 term is below 1/400 of the measured one. */
#define MEASURE_RADII 20.0
/* Directions of emission measured: rings of polar angle every 15 degrees
 * (13 rings), 12 azimuths on each ring but the poles: 11 x 12 + 2 = 134. */
#define RING_STEP_DEG 15.0
#define RING_AZIMUTHS 12
/* Directions carrying less than this share of the peak are left out. */
#define DIM_SHARE 1e-3

/* E of `e` at the receiver `distance` from `centre` along w, facing back. */
static int facing_illuminance(const cdl_emitter *e, cdl_vec3 centre, cdl_vec3 w, double distance, double *E)
{
    cdl_vec3 p = cdl_vec3_add(centre, cdl_vec3_scale(w, distance));
    cdl_illuminance out;
    if (cdl_emitter_exact_illuminance(e, p, cdl_vec3_scale(w, -1.0), &out, NULL) != CDL_OK) return 0;
    *E = out.lx;
    return isfinite(*E);
}

/* The largest relative difference between the two emitters over the
 * directions of emission, at `distance`. */
static double largest_difference(const cdl_emitter *point, const cdl_emitter *opening, cdl_vec3 centre,
                                 double distance)
{
    int rings = (int)lround(180.0 / RING_STEP_DEG);
    double peak = 0.0, worst = 0.0;
    /* Two passes: the peak first, then the differences where it is bright. */
    for (int pass = 0; pass < 2; ++pass)
        for (int r = 0; r <= rings; ++r) {
            double theta = r * RING_STEP_DEG * CDL_DEG_TO_RAD;
            int azimuths = (r == 0 || r == rings) ? 1 : RING_AZIMUTHS;
            for (int a = 0; a < azimuths; ++a) {
                double phi = 2.0 * CDL_PI * a / RING_AZIMUTHS;
                cdl_vec3 w = cdl_vec3_make(sin(theta) * cos(phi), sin(theta) * sin(phi), -cos(theta));
                double Ep, Eo;
                if (!facing_illuminance(point, centre, w, distance, &Ep)) continue;
                if (pass == 0) {
                    peak = fmax(peak, Ep);
                    continue;
                }
                if (!(Ep > DIM_SHARE * peak) || !facing_illuminance(opening, centre, w, distance, &Eo)) continue;
                worst = fmax(worst, fabs(Eo - Ep) / Ep);
            }
        }
    return worst;
}

cdl_status cdl_near_field_bound_measure(const cdl_goniometric_params *params, cdl_near_field_bound *out,
                                        cdl_error *err)
{
    const cdl_luminous_opening *o = &cdl_photometry_get_metadata(params->photometry)->opening;
    out->flat = cdl_luminous_opening_is_flat(o);
    out->radius_m = 0.5 * cdl_luminous_opening_largest_m(o);
    out->k = 1.0;
    if (!out->flat || !(out->radius_m > 0.0)) return CDL_OK;
    cdl_emitter *point = NULL, *opening = NULL;
    cdl_status st = cdl_emitter_create_goniometric(params, &point, err);
    if (st == CDL_OK) st = cdl_emitter_create_goniometric_opening(params, &opening, err);
    if (st == CDL_OK) {
        cdl_emitter_opening_set_tolerance(opening, 1e-7);
        double worst = largest_difference(point, opening, params->position, MEASURE_RADII * out->radius_m);
        /* At least the Lambertian disk's coefficient: a table measured flat
         * by these directions is no better than that. */
        out->k = fmax(1.0, worst * MEASURE_RADII * MEASURE_RADII);
    }
    cdl_emitter_release(point);
    cdl_emitter_release(opening);
    return st;
}

/* The solid's bound: the nearest face point's inverse square against the
 * centre's, plus the flat part's second-order term. */
static double solid_error(double R, double d)
{
    if (!(d > R)) return 1.0;
    double q = d / (d - R);
    return fmin(1.0, q * q - 1.0 + (R / d) * (R / d));
}

double cdl_near_field_bound_error(const cdl_near_field_bound *b, double d)
{
    if (!(d > 0.0)) return 1.0;
    if (b->flat) return fmin(1.0, b->k * (b->radius_m / d) * (b->radius_m / d));
    return solid_error(b->radius_m, d);
}

double cdl_near_field_bound_distance(const cdl_near_field_bound *b, double relative)
{
    double R = b->radius_m;
    if (!(R > 0.0) || !(relative > 0.0)) return 0.0;
    if (b->flat) return R * sqrt(b->k / relative);
    /* solid_error falls monotonically beyond R: bisect on d in (R, hi]. */
    double lo = R, hi = 2.0 * R;
    while (solid_error(R, hi) > relative) hi *= 2.0;
    for (int i = 0; i < 100 && hi - lo > 1e-9 * hi; ++i) {
        double mid = 0.5 * (lo + hi);
        if (solid_error(R, mid) > relative) lo = mid;
        else hi = mid;
    }
    return hi;
}
