/* environment_peaks.h - an image environment's brightest pixels (a sun)
 * over a convex spherical polygon of directions, integrated exactly
 * (private to lights/ and its callers in solver/).
 *
 * A solver that samples the sky a point sees through an opening uniformly
 * in projected solid angle (solver/direct/sky_region.h) rarely meets a sun
 * of a few pixels a thousand times brighter than the sky, and where it
 * does the sample is huge: the variance is the sun's. Taken out of the
 * integrand, the sun needs no sample at all:
 *     int_R L cos dw = sum_b L_b Q_b(R) + int_R L' cos dw,
 * the sum over the pixels b brighter than a cut, Q_b(R) the projected
 * solid angle of pixel b's part inside R about the receiver's normal, and
 * L' the sky with those pixels taken out (whatever stands in their place
 * is integrated on the other side, as its own Q_b(R) times its value).
 *
 * Q_b(R) in closed form: R's part in the pixel's columns is R clipped by
 * the two meridian planes phi = phi_a, phi_b (planes through the axis:
 * the clip of a convex spherical polygon is one again); its part in the
 * pixel's rows is the difference of two caps,
 *     Q = F(cos theta_b) - F(cos theta_a),  F(c) = int over {z >= c} of n.w dw,
 * each by the boundary integral int_A w dw = (1/2) contour w x dw
 * (environment_pixels.h, Arvo 1995): along a great-circle arc from p to q
 * w x dw integrates to the arc's unit normal p x q / |p x q| times its
 * angle; along the parallel z = c, which runs eastwards with the cap on
 * its left, by cdl_env_parallel_flux, from where the polygon's boundary
 * leaves the cap to where it comes back (the next entry eastwards: within
 * one pixel's columns the parallel's arcs are shorter than pi).
 * The pixels brighter than the cut are found from the block maxima of the
 * image's pyramid (environment_bounds.h): only blocks brighter than the
 * cut are opened, so the cost is the bright pixels, not the region.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_PEAKS_H
#define CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_PEAKS_H

#include "lights/emitters/emitter.h"

/* Vertices of a polygon the peak sums accept (the two meridian clips add
 * two). */
#define CDL_ENV_PEAK_MAX_VERTICES 40

/* What the bright pixels over a polygon add up to. */
typedef struct cdl_env_peaks {
    double LQ;   /* sum of L_b Q_b, cd/m^2 sr (the image's scale applied): lx */
    double Q;    /* sum of Q_b, sr */
    int pixels;  /* bright pixels met (the polygon's extent touches them, whether it covers them or not) */
} cdl_env_peaks;

/* Add to *sum the pixels of image environment `emitter` whose luminance
 * (scale applied) is above L_cut and that the convex spherical polygon
 * dirs[0 .. count) may cover (unit world directions, 3 <= count <=
 * CDL_ENV_PEAK_MAX_VERTICES - 2, edges the shorter great-circle arcs,
 * either orientation, within the hemisphere of unit world normal n):
 * their L_b Q_b and Q_b about n; *rest_hi: a bound on the other pixels
 * the polygon may cover (each at most it, and it at most L_cut; as tight
 * as cdl_emitter_luminance_bounds's). Returns 0 when the emitter is not
 * an image environment (or one narrower than 4 pixels), when the polygon
 * has too many vertices, or when sum->pixels would pass max_pixels (the
 * sums are then partial and must not be used); 1 otherwise. Thread-safe. */
int cdl_env_peaks_add(const cdl_emitter *emitter, const cdl_vec3 *dirs, int count, cdl_vec3 n, double L_cut,
                      int max_pixels, cdl_env_peaks *sum, double *rest_hi);

/* Q of the part of pixel (i, j)'s cell inside the convex spherical polygon
 * poly[0 .. count) (unit vectors in the emitter's frame, counter-clockwise
 * seen from outside, count <= CDL_ENV_PEAK_MAX_VERTICES - 2) about unit
 * n_local (the emitter's frame), the polygon within n's hemisphere. */
double cdl_env_peaks_cell_polygon(const cdl_emitter *emitter, int i, int j, const cdl_vec3 *poly, int count,
                                  cdl_vec3 n_local);

/* The same for any cell theta in [theta_a, theta_b], phi in [phi_a, phi_b]
 * of the frame the polygon is given in (radians, 0 <= theta_a < theta_b <=
 * pi, 0 < phi_b - phi_a < pi); 0 for a polygon of fewer than 3 or more than
 * CDL_ENV_PEAK_MAX_VERTICES - 2 vertices. */
double cdl_env_cell_polygon(double theta_a, double theta_b, double phi_a, double phi_b, const cdl_vec3 *poly,
                            int count, cdl_vec3 n_local);

#endif
