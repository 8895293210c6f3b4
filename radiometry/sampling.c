/* sampling.c - solid angles and direction sampling. */
#include "radiometry/sampling.h"

#include <math.h>

#include "radiometry/constants.h"

/* Solid angle of a cone: Omega = int_0^2pi int_0^alpha sin(t) dt dphi =
 * 2 pi (1 - cos alpha) = 4 pi sin^2(alpha / 2) (half-angle identity, which
 * avoids the cancellation of 1 - cos alpha for small alpha). */
cdl_solid_angle cdl_cone_solid_angle(double half_angle_rad)
{
    double s = sin(0.5 * half_angle_rad);
    return cdl_steradians(CDL_FOUR_PI * s * s);
}

static cdl_vec3 direction_from_angles(double cos_theta, double phi)
{
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    return cdl_vec3_make(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

cdl_vec3 cdl_sample_cosine_hemisphere_stratified(int j, int k, int M, int N, double u1, double u2)
{
    /* cos^2(theta) = 1 - (j + u1) / M is uniform in [0, 1]: the cosine-weighted
     * measure of the cap theta < t is sin^2(t), so equal steps in it are equal
     * measure. */
    double cos_theta = sqrt(fmax(0.0, 1.0 - ((double)j + u1) / (double)M));
    double phi = CDL_TWO_PI * ((double)k + u2) / (double)N;
    return direction_from_angles(cos_theta, phi);
}

cdl_vec3 cdl_sample_cosine_hemisphere(double u1, double u2)
{
    return cdl_sample_cosine_hemisphere_stratified(0, 0, 1, 1, u1, u2);
}

cdl_vec3 cdl_sample_uniform_sphere(double u1, double u2)
{
    double cos_theta = 1.0 - 2.0 * u1;
    return direction_from_angles(cos_theta, CDL_TWO_PI * u2);
}

cdl_vec3 cdl_sample_uniform_cone(double cos_max, double u1, double u2)
{
    double cos_theta = 1.0 - u1 * (1.0 - cos_max);
    return direction_from_angles(cos_theta, CDL_TWO_PI * u2);
}

void cdl_sample_uniform_triangle(double u1, double u2, double *b0, double *b1)
{
    double su = sqrt(u1);
    *b0 = 1.0 - su;
    *b1 = u2 * su;
}
