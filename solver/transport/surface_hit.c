/* surface_hit.c - where a ray lands, which side, how much it reflects. */
#include "solver/transport/surface_hit.h"

cdl_vec3 cdl_transport_front_normal(const cdl_scene_geometry *geometry, uint32_t piece, uint32_t prim, cdl_vec3 p)
{
    const double *xyz;
    const uint32_t *tri;
    size_t vertices;
    size_t triangles = cdl_scene_geometry_piece_triangles(geometry, piece, &xyz, &vertices, &tri);
    if (triangles > 0 && prim < triangles) {
        const double *a = &xyz[3 * tri[3 * prim]], *b = &xyz[3 * tri[3 * prim + 1]], *c = &xyz[3 * tri[3 * prim + 2]];
        cdl_vec3 e1 = cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
        cdl_vec3 e2 = cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
        /* Counter-clockwise seen from the front: (b - a) x (c - a) faces it. */
        return cdl_vec3_normalize(cdl_vec3_cross(e1, e2));
    }
    const cdl_geometry_piece *pc = cdl_scene_geometry_piece(geometry, piece);
    cdl_vec3 out = cdl_vec3_normalize(cdl_vec3_sub(p, pc->shape.center));
    return pc->shape.inward ? cdl_vec3_neg(out) : out;
}

int cdl_transport_trace(const cdl_scene_geometry *geometry, cdl_vec3 p, cdl_vec3 p_normal, cdl_vec3 dir,
                        cdl_surface_hit *hit)
{
    cdl_ray_hit h;
    double T = 1.0, travelled = 0.0;
    const cdl_geometry_piece *piece = NULL;
    for (int panes = 0;; ++panes) {
        if (!cdl_scene_geometry_intersect(geometry, p, p_normal, dir, INFINITY, &h)) {
            hit->transmission = T; /* out to the sky through the panes met */
            return 0;
        }
        piece = cdl_scene_geometry_piece(geometry, h.geom_id);
        hit->transmission = 0.0;
        if (!piece) return 0;
        if (!(piece->transmittance > 0.0)) break;
        if (panes == CDL_GLASS_MAX_PANES) return 0;
        /* through the pane at its angle of incidence, on from its far side */
        T *= cdl_glass_transmittance(&piece->glass, cdl_vec3_dot(dir, h.normal));
        p = cdl_vec3_madd(p, h.t, dir);
        p_normal = h.normal;
        travelled += h.t;
    }
    hit->transmission = T;
    hit->p = cdl_vec3_madd(p, h.t, dir);
    hit->distance = travelled + h.t;
    hit->piece = h.geom_id;
    cdl_vec3 front = cdl_transport_front_normal(geometry, h.geom_id, h.prim_id, hit->p);
    hit->front = cdl_vec3_dot(front, dir) < 0.0;
    hit->n = hit->front ? front : cdl_vec3_neg(front);
    hit->reflectance = hit->front || piece->two_sided ? piece->reflectance : 0.0;
    return 1;
}
