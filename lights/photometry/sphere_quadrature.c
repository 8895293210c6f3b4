/* sphere_quadrature.c - the distribution sampled for weighted integrals (sphere_quadrature.h). */
#include "lights/photometry/sphere_quadrature.h"

#include <math.h>
#include <stdlib.h>

#include "radiometry/constants.h"

/* Gauss-Legendre, 2 nodes on [-1, 1], weights 1 (Abramowitz and Stegun 25.4.29). */
static const double gl2 = 0.57735026918962576451; /* 1 / sqrt(3) */

int cdl_sphere_quadrature_sample(const cdl_photometry *p, double g0, double g1, double dg, size_t nc,
                                 cdl_sphere_quadrature *q)
{
    size_t steps = (size_t)llround((g1 - g0) / dg);
    q->ng = 2 * steps;
    q->nc = nc;
    q->gamma_deg = malloc(q->ng * sizeof *q->gamma_deg);
    q->weight = malloc(q->ng * sizeof *q->weight);
    q->c_deg = malloc(nc * sizeof *q->c_deg);
    q->cd = malloc(q->ng * nc * sizeof *q->cd);
    if (!q->gamma_deg || !q->weight || !q->c_deg || !q->cd) {
        cdl_sphere_quadrature_free(q);
        return 0;
    }
    double dc = CDL_TWO_PI / (double)nc;
    for (size_t j = 0; j < nc; ++j) q->c_deg[j] = ((double)j + 0.5) * 360.0 / (double)nc;
    for (size_t s = 0; s < steps; ++s)
        for (int k = 0; k < 2; ++k) {
            size_t i = 2 * s + (size_t)k;
            double g = g0 + dg * ((double)s + 0.5 + 0.5 * (k ? gl2 : -gl2));
            q->gamma_deg[i] = g;
            q->weight[i] = sin(g * CDL_DEG_TO_RAD) * 0.5 * dg * CDL_DEG_TO_RAD * dc;
            for (size_t j = 0; j < nc; ++j)
                q->cd[i * nc + j] = cdl_photometry_intensity_c_gamma(p, q->c_deg[j], g).cd;
        }
    return 1;
}

void cdl_sphere_quadrature_free(cdl_sphere_quadrature *q)
{
    free(q->gamma_deg);
    free(q->weight);
    free(q->c_deg);
    free(q->cd);
    q->gamma_deg = q->weight = q->c_deg = q->cd = NULL;
    q->ng = q->nc = 0;
}
