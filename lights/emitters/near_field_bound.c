/* near_field_bound.c - where the point model of a luminous opening is close enough (near_field_bound.h). */
#include "lights/emitters/near_field_bound.h"

#include <math.h>

#include "base/error_report.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"

/* The receiver's distance, in opening radii, at which K is measured: far
 * enough that the (R / d)^4 term is below 1/400 of the measured one. */
#define MEASURE_RADII 20.0
/* Directions of emission measured: rings of polar angle every 5 degrees
 * (37 rings), 24 azimuths on each ring but the poles: 35 x 24 + 2 = 842. */
#define RING_STEP_DEG 5.0
#define RING_AZIMUTHS 24
/* The largest error between the measured directions exceeds the largest
 * measured by up to this factor (a cos^8 beam on a 1.2 m slot: 1.13 at 15
 * degrees' spacing; tests/lights/emitters/test_near_field_bound.c). */
#define BETWEEN_DIRECTIONS 1.25
/* The point model's error in a direction counts relative to the light
 * there, but no less than this share of the peak: in a beam's fringe (a
 * downlight fading to nothing at 80 degrees) its relative error grows
 * without bound while the light it errs on is a few per cent of what the
 * luminaire gives; any point lit mostly by such a fringe is lit by little. */
#define DIM_SHARE 0.1

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
                if (!(peak > 0.0) || !facing_illuminance(opening, centre, w, distance, &Eo)) continue;
                worst = fmax(worst, fabs(Eo - Ep) / fmax(Ep, DIM_SHARE * peak));
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
        /* 1e-5: the cubature's error adds at most 1e-5 x 20^2 = 4e-3 to K (at least 1),
         * against the quarter of BETWEEN_DIRECTIONS; 1e-6 took three times as
         * long (0.08-0.11 s of the downlight room's 0.6, before its first ray) */
        cdl_emitter_opening_set_tolerance(opening, 1e-5);
        double worst = largest_difference(point, opening, params->position, MEASURE_RADII * out->radius_m);
        /* At least the Lambertian disk's coefficient: a table measured flat
         * by these directions is no better than that. */
        out->k = fmax(1.0, BETWEEN_DIRECTIONS * worst * MEASURE_RADII * MEASURE_RADII);
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

double cdl_near_field_switch_distance(const cdl_near_field_bound *b, double target)
{
    return fmax(CDL_NEAR_FIELD_DISTANCES * 2.0 * b->radius_m,
                cdl_near_field_bound_distance(b, CDL_NEAR_FIELD_SHARE * target));
}

cdl_status cdl_near_field_switch_distances(const cdl_photometry *photometry, const double *targets, size_t count,
                                           double *out, cdl_error *err)
{
    cdl_goniometric_params params = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    params.photometry = photometry;
    cdl_near_field_bound bound;
    cdl_status st = cdl_near_field_bound_measure(&params, &bound, err);
    for (size_t i = 0; st == CDL_OK && i < count; ++i) out[i] = cdl_near_field_switch_distance(&bound, targets[i]);
    return st;
}
