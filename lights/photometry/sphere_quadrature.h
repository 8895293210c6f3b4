/* sphere_quadrature.h - the interpolated distribution sampled on a grid of
 * directions for integrals whose weight is not a simple zone (the direct
 * ratios' flux transfer, the TM-15 zones split front and back).
 *
 * Gamma (from nadir) from g0 to g1 in steps of dg, two Gauss-Legendre
 * nodes per step (exact for a cubic in gamma); C over the full circle by
 * the midpoint rule, nc nodes at (j + 0.5) 360 / nc degrees (exact for the
 * trigonometric polynomials of degree below nc; no node falls on C = 0, 90,
 * 180 or 270 when nc is a multiple of 4). Node (i, j) holds I(gamma_i, C_j)
 * and the solid-angle weight w_i = sin(gamma_i) x (dg / 2) x (2 pi / nc),
 * so that sum_ij I_ij w_i is the flux into [g0, g1]. Internal to lights/.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_SPHERE_QUADRATURE_H
#define CANDELA_LIGHTS_PHOTOMETRY_SPHERE_QUADRATURE_H

#include <stddef.h>

#include "lights/photometry/photometry_internal.h"

typedef struct cdl_sphere_quadrature {
    size_t ng, nc;
    double *gamma_deg; /* ng */
    double *weight;    /* ng: solid angle per node of ring i */
    double *c_deg;     /* nc */
    double *cd;        /* ng x nc, ring i outermost */
} cdl_sphere_quadrature;

/* Sample p (as tabulated: no output factor); 0 when out of memory. */
int cdl_sphere_quadrature_sample(const cdl_photometry *p, double g0_deg, double g1_deg, double dg_deg, size_t nc,
                                 cdl_sphere_quadrature *q);

void cdl_sphere_quadrature_free(cdl_sphere_quadrature *q);

#endif
