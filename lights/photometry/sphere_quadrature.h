/* sphere_quadrature.h - the interpolated distribution sampled on a grid of
 * directions for integrals whose weight is not a simple zone (the direct
 * ratios' flux transfer, the TM-15 zones split front and back).
 *
 * Gamma (from nadir) over [g0, g1] and C over the full circle are cut at
 * every step of dg and of 360 / nc degrees and, for a type C table, also at
 * the table's own angles (its C planes with their mirror images under every
 * symmetry, and its gammas), so that the bilinear interpolant is a product
 * of linear pieces on each cell of the quadrature however narrow the
 * table's features: a 0.3 degree spot is integrated, never missed or
 * counted as a whole 0.5 degree ring. Each gamma interval gets two
 * Gauss-Legendre nodes (exact for a cubic in gamma), each C interval the
 * midpoint rule (exact for the interpolant's linear pieces); no node falls
 * on a cut, so a zone edge at a whole step (gamma = 30, 60, 80, 90;
 * C = 90, 270 for nc a multiple of 4) never holds a node. A type A or B
 * table's cells do not follow C and gamma: its steps are refined to its
 * finest angle spacing (down to 1/64 degree, and only as far as keeps the
 * nodes within 2^23) so that no cell of the table is narrower than the
 * quadrature's.
 *
 * Node (i, j) holds I(gamma_i, C_j), the ring weight
 * w_i = sin(gamma_i) x (its interval / 2) in radians and the C weight
 * c_j = its interval in radians, so that sum_ij I_ij w_i c_j is the flux
 * into [g0, g1]. Internal to lights/.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_SPHERE_QUADRATURE_H
#define CANDELA_LIGHTS_PHOTOMETRY_SPHERE_QUADRATURE_H

#include <stddef.h>

#include "lights/photometry/photometry_internal.h"

typedef struct cdl_sphere_quadrature {
    size_t ng, nc;
    double *gamma_deg; /* ng */
    double *weight;    /* ng: sin(gamma) d gamma of ring i (radians) */
    double *c_deg;     /* nc */
    double *c_weight;  /* nc: d C of node j (radians) */
    double *cd;        /* ng x nc, ring i outermost */
} cdl_sphere_quadrature;

/* Sample p (as tabulated: no output factor); 0 when out of memory. */
int cdl_sphere_quadrature_sample(const cdl_photometry *p, double g0_deg, double g1_deg, double dg_deg, size_t nc,
                                 cdl_sphere_quadrature *q);

/* The same, gamma also cut at gamma_cuts[0 .. ncuts - 1] (degrees; those
 * outside (g0, g1) ignored): no ring then straddles a cut, so the rings
 * below a cut hold exactly the quadrature's flux up to it. */
int cdl_sphere_quadrature_sample_cut(const cdl_photometry *p, double g0_deg, double g1_deg, double dg_deg, size_t nc,
                                     const double *gamma_cuts, size_t ncuts, cdl_sphere_quadrature *q);

/* The flux (in the table's unit) of the sampled nodes, sum_ij I_ij w_i c_j. */
double cdl_sphere_quadrature_flux(const cdl_sphere_quadrature *q);

void cdl_sphere_quadrature_free(cdl_sphere_quadrature *q);

#endif
