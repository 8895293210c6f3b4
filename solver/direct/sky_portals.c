/* sky_portals.c - the panes of glass as portals of the sky (sky_portals.h). */
#include "solver/direct/sky_portals.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/distribution2d.h"
#include "radiometry/ray_triangle.h"
#include "radiometry/sampling.h"

static cdl_vec3 vertex(const double *xyz, uint32_t i)
{
    return cdl_vec3_make(xyz[3 * (size_t)i], xyz[3 * (size_t)i + 1], xyz[3 * (size_t)i + 2]);
}

cdl_status cdl_sky_portals_build(const cdl_scene_geometry *geometry, cdl_sky_portals *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    if (!geometry || !cdl_scene_geometry_has_glass(geometry)) return CDL_OK;
    size_t pieces = cdl_scene_geometry_piece_count(geometry), total = 0;
    for (size_t g = 0; g < pieces; ++g) {
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(geometry, g);
        if (piece->transmittance > 0.0) total += piece->triangle_count;
    }
    if (total == 0 || total > CDL_SKY_PORTALS_MAX) return CDL_OK;
    out->triangles = malloc(total * sizeof *out->triangles);
    out->cdf = malloc(total * sizeof *out->cdf);
    if (!out->triangles || !out->cdf) {
        cdl_sky_portals_release(out);
        return cdl_error_out_of_memory(err);
    }
    for (size_t g = 0; g < pieces; ++g) {
        const cdl_geometry_piece *piece = cdl_scene_geometry_piece(geometry, g);
        if (!(piece->transmittance > 0.0)) continue;
        const double *xyz;
        const uint32_t *tri;
        size_t nv, nt = cdl_scene_geometry_piece_triangles(geometry, g, &xyz, &nv, &tri);
        for (size_t t = 0; t < nt; ++t) {
            cdl_vec3 a = vertex(xyz, tri[3 * t]), b = vertex(xyz, tri[3 * t + 1]), c = vertex(xyz, tri[3 * t + 2]);
            cdl_portal_triangle *pt = &out->triangles[out->count];
            pt->v0 = a;
            pt->e1 = cdl_vec3_sub(b, a);
            pt->e2 = cdl_vec3_sub(c, a);
            cdl_vec3 m = cdl_vec3_cross(pt->e1, pt->e2);
            double len = cdl_vec3_length(m);
            if (!(len > 0.0)) continue;
            pt->normal = cdl_vec3_scale(m, 1.0 / len);
            pt->area = 0.5 * len;
            out->area += pt->area;
            out->cdf[out->count++] = out->area;
        }
    }
    if (!(out->area > 0.0)) {
        cdl_sky_portals_release(out);
        return CDL_OK;
    }
    for (size_t t = 0; t < out->count; ++t) out->cdf[t] /= out->area;
    out->cdf[out->count - 1] = 1.0;
    return CDL_OK;
}

void cdl_sky_portals_release(cdl_sky_portals *portals)
{
    free(portals->triangles);
    free(portals->cdf);
    memset(portals, 0, sizeof *portals);
}

double cdl_sky_portals_pdf(const cdl_sky_portals *portals, cdl_vec3 p, cdl_vec3 dir)
{
    double pdf = 0.0;
    for (size_t i = 0; i < portals->count; ++i) {
        const cdl_portal_triangle *t = &portals->triangles[i];
        double d = cdl_ray_triangle_distance(t->v0, t->e1, t->e2, p, dir);
        if (!(d > 0.0)) continue;
        /* dA = d^2 dw / |cos theta| (the change of measure from area to solid angle) */
        double c = fabs(cdl_vec3_dot(t->normal, dir));
        if (c > 0.0) pdf += d * d / (portals->area * c);
    }
    return pdf;
}

int cdl_sky_portals_sample(const cdl_sky_portals *portals, cdl_vec3 p, double u1, double u2, cdl_vec3 *dir,
                           double *pdf)
{
    *pdf = 0.0;
    if (portals->count == 0) return 0;
    /* a triangle by its share of the area, u1 rescaled within the share */
    double ur;
    size_t k = cdl_distribution_invert_cdf(portals->cdf, portals->count, u1, &ur);
    const cdl_portal_triangle *t = &portals->triangles[k];
    double b0, b1;
    cdl_sample_uniform_triangle(ur, u2, &b0, &b1);
    cdl_vec3 x = cdl_vec3_madd(cdl_vec3_madd(t->v0, b1, t->e1), 1.0 - b0 - b1, t->e2);
    cdl_vec3 w = cdl_vec3_sub(x, p);
    double len = cdl_vec3_length(w);
    if (!(len > 0.0)) return 0;
    *dir = cdl_vec3_scale(w, 1.0 / len);
    *pdf = cdl_sky_portals_pdf(portals, p, *dir);
    return *pdf > 0.0 && isfinite(*pdf);
}
