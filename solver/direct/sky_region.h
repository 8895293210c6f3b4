/* sky_region.h - the part of a sky a point sees past planar occluders, as a
 * domain to integrate over (private to direct/).
 *
 * The exact route (direct_exact_route.c) finds the visible sky as convex
 * pieces on the five faces of a cube over the point. A uniform sky needs
 * only their projected solid angle. An image or CIE overcast sky varies
 * over them, so its illuminance is the integral of L cos over the pieces,
 *     E = int_R L(w) cos(theta) dw,
 * taken here by sampling the pieces themselves: every sample is a direction
 * the point sees, so no shadow ray is traced and the visibility step that
 * makes a deep opening costly (most samples of the whole sky hidden) is
 * gone; what is left is the sky's own variation over R. The caller writes
 *     E = L_ref Omega_p(R) + int_R (L - L_ref) cos dw
 * with a reference luminance L_ref, the first term exact, so a sky of one
 * luminance over R (an image's pixels all alike there, bounded by
 * cdl_emitter_luminance_bounds) is exact and a smooth one nearly so.
 *
 * Sampling: a fan triangle of a piece with probability proportional to its
 * projected solid angle Omega_p (Lambert's polygon formula), then a point
 * uniform in its area (Shirley's square-root map); in solid angle
 *     pdf(w) = (Omega_p,k / Omega_p(R)) (1 / A_k) d^3 / h,
 * d the distance to the point on the face and h the face's distance from
 * the apex (dA = d^2 dw / cos alpha, cos alpha = h / d). Its weight
 * cos(theta) / pdf varies across a triangle only as cos(theta) h / d^3
 * does, about its mean Omega_p,k / A_k.
 *
 * A sun: pixels of an image sky brighter than a cut L_c (the caller's:
 * several times the sky's typical luminance) are taken out of the sampled
 * integral and summed exactly over their part of R (lights/
 * environment_peaks.h):
 *     E = L_ref Omega_p(R) + sum_b (L_b - L_ref) Q_b(R) + int_R (L' - L_ref) cos dw,
 * L' the sky with those pixels at L_ref (cdl_sky_region_luminance), so
 * the sampled part sees the sky without its sun and its bounds are those
 * of L' (at most L_c).
 */
#ifndef CANDELA_SOLVER_SKY_REGION_H
#define CANDELA_SOLVER_SKY_REGION_H

#include "lights/emitters/emitter.h"
#include "base/error.h"
#include "solver/geometry/visible_polygon.h"

typedef struct cdl_sky_region cdl_sky_region;

/* The region of faces[0 .. face_count) (their pieces, as left by
 * subtraction) seen from p with unit normal n, under `sky` (an
 * environment, borrowed: it must outlive the region). Pixels of an image
 * sky brighter than L_cut (cd/m^2; INFINITY: none) are summed exactly,
 * at most max_bright of them over the region's pieces (beyond that
 * cdl_sky_region_too_bright says so and the region must not be used).
 * CDL_ERR_OUT_OF_MEMORY on failure. A region that holds nothing has
 * Omega_p = 0 and must not be sampled. */
cdl_status cdl_sky_region_create(const cdl_visible_face *faces, int face_count, cdl_vec3 p, cdl_vec3 n,
                                 const cdl_emitter *sky, double L_cut, int max_bright, cdl_sky_region **out,
                                 cdl_error *err);
void cdl_sky_region_release(cdl_sky_region *region);

/* Omega_p(R), sr. */
double cdl_sky_region_projected_solid_angle(const cdl_sky_region *region);

/* 1 when more than max_bright pixels above the cut were met. */
int cdl_sky_region_too_bright(const cdl_sky_region *region);

/* Q of the bright pixels' part of R, sr: > 0 when R sees some of them. */
double cdl_sky_region_bright_solid_angle(const cdl_sky_region *region);

/* The exact part of E: L_ref Omega_p(R) + sum_b (L_b - L_ref) Q_b(R), lx. */
double cdl_sky_region_exact_part(const cdl_sky_region *region);

/* L'(w): the sky's luminance towards w (cd/m^2), L_ref where its pixel is
 * brighter than the cut. */
double cdl_sky_region_luminance(const cdl_sky_region *region, cdl_vec3 w);

/* Bounds on L' over R, cd/m^2. */
void cdl_sky_region_luminance_bounds(const cdl_sky_region *region, double *lo, double *hi);

/* L_ref: the sky's luminance towards the middle of R's largest triangle. */
double cdl_sky_region_reference_luminance(const cdl_sky_region *region);

/* A direction w in R from (u1, u2) in [0, 1)^2 (stratified pairs give
 * stratified directions) and its weight cos(theta) / pdf, sr; 0 (weight
 * 0) where the direction grazes the receiver's plane. */
int cdl_sky_region_sample(const cdl_sky_region *region, double u1, double u2, cdl_vec3 *w, double *weight);

#endif
