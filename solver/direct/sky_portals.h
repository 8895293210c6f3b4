/* sky_portals.h - the panes of glass a room's sky light comes in through,
 * as a second way to sample the sky at a path vertex.
 *
 * Inside a room the sky is seen only through its windows: a direction
 * drawn from the sky's own sampler (cosine-weighted or by luminance over the
 * whole sky) finds a window with the probability of the window's share of
 * the hemisphere, a few per cent, and a path vertex's estimate of the sky
 * is then mostly 0 and rarely large. Drawing a point on the panes instead
 * (uniform over their area) finds the sky every time it can be seen. The
 * two are combined by multiple importance sampling with the balance
 * heuristic, one sample from each (Veach and Guibas, "Optimally combining
 * sampling techniques for Monte Carlo rendering", SIGGRAPH 1995; windows
 * as "portals" of an environment light: Bitterli, Novak and Jarosz,
 * "Portal-masked environment map sampling", EGSR 2015):
 *     E = sum_{w in {w_sky, w_pane}} L(w) cos(w) T(w) / (p_sky(w) + p_pane(w)),
 * T the transmission along w (the panes' angle-dependent transmittance,
 * 0 past anything opaque). Unbiased wherever the sky is seen, through a
 * pane or not: the sky's own sampler still covers every direction.
 *
 * The panes are the scene's pieces with "transmittance", as the ray scene
 * holds them (their triangles); scenes with more pane triangles than
 * CDL_SKY_PORTALS_MAX are left to the sky's sampler alone (a direction's
 * pane density needs every pane triangle tested). */
#ifndef CANDELA_SOLVER_DIRECT_SKY_PORTALS_H
#define CANDELA_SOLVER_DIRECT_SKY_PORTALS_H

#include <stddef.h>

#include "base/error.h"
#include "radiometry/vec3.h"
#include "solver/scene/scene_geometry.h"

#define CDL_SKY_PORTALS_MAX 256

typedef struct cdl_portal_triangle {
    cdl_vec3 v0, e1, e2;      /* corner and edges, world coordinates (m) */
    cdl_vec3 normal;          /* unit */
    double area;              /* m^2 */
} cdl_portal_triangle;

typedef struct cdl_sky_portals {
    cdl_portal_triangle *triangles;
    double *cdf;              /* cumulative areas over the total, one per triangle */
    size_t count;             /* 0: no portals (no glass, or too much of it) */
    double area;              /* m^2, all of them */
} cdl_sky_portals;

/* The geometry's panes as portals (none without glass or with more than
 * CDL_SKY_PORTALS_MAX triangles of it). */
cdl_status cdl_sky_portals_build(const cdl_scene_geometry *geometry, cdl_sky_portals *out, cdl_error *err);
void cdl_sky_portals_release(cdl_sky_portals *portals);

/* A direction from p towards a point drawn uniformly over the panes' area
 * (u1, u2 in [0, 1)), and its density in solid angle at p
 * (cdl_sky_portals_pdf); 0 when the point drawn lies in p's own plane or
 * the portals are empty. */
int cdl_sky_portals_sample(const cdl_sky_portals *portals, cdl_vec3 p, double u1, double u2, cdl_vec3 *dir,
                           double *pdf);

/* The density in solid angle at p with which cdl_sky_portals_sample draws
 * unit direction dir: over every pane triangle the ray from p along dir
 * crosses, t^2 / (A |cos theta|), t its distance, theta the angle to the
 * pane's normal, A the panes' area. */
double cdl_sky_portals_pdf(const cdl_sky_portals *portals, cdl_vec3 p, cdl_vec3 dir);

#endif
