/* sampling.h - solid angles and direction sampling used by the solver.
 *
 * Directions are returned in a local frame with z along the surface normal
 * (see frame.h to take them to world space). Every sampler documents its pdf
 * with respect to solid angle.
 */
#ifndef CANDELA_RADIOMETRY_SAMPLING_H
#define CANDELA_RADIOMETRY_SAMPLING_H

#include "radiometry/units.h"
#include "radiometry/vec3.h"

/* Solid angle of a right circular cone of half-angle alpha (radians):
 * Omega = 2 pi (1 - cos alpha), evaluated as 4 pi sin^2(alpha / 2) so that
 * tiny cones keep full relative precision. alpha in [0, pi]. */
cdl_solid_angle cdl_cone_solid_angle(double half_angle_rad);

/* Stratified cosine-weighted hemisphere sample for stratum (j, k) of an
 * M x N grid (j < M along theta, k < N along phi), jittered by u1, u2 in [0, 1):
 *   theta = arccos sqrt(1 - (j + u1) / M),  phi = 2 pi (k + u2) / N.
 * Each stratum carries equal cosine-weighted measure, so the estimator
 *   E = (pi / (M N)) * sum L(direction)
 * is the irradiance from radiance L (pdf = cos(theta) / pi). */
cdl_vec3 cdl_sample_cosine_hemisphere_stratified(int j, int k, int M, int N, double u1, double u2);

/* Cosine-weighted hemisphere sample (Malley's method), pdf = cos(theta) / pi. */
cdl_vec3 cdl_sample_cosine_hemisphere(double u1, double u2);

/* Uniform direction on the unit sphere, pdf = 1 / (4 pi). */
cdl_vec3 cdl_sample_uniform_sphere(double u1, double u2);

/* Uniform direction inside a cone about +z of half-angle with cosine
 * cos_max, pdf = 1 / (2 pi (1 - cos_max)). */
cdl_vec3 cdl_sample_uniform_cone(double cos_max, double u1, double u2);

/* Uniform point on a triangle as barycentric (b0, b1); b2 = 1 - b0 - b1
 * (square-root parameterisation, Turk 1990 / Shirley). */
void cdl_sample_uniform_triangle(double u1, double u2, double *b0, double *b1);

#endif
