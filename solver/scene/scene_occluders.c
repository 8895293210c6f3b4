/* scene_occluders.c - the scene's geometry pieces as an occluder index. */
#include "solver/scene/scene_occluders.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"

cdl_status cdl_scene_occluders_build(const cdl_scene_geometry *g, cdl_occluder_index **out, cdl_error *err)
{
    size_t pieces = cdl_scene_geometry_piece_count(g);
    size_t tri_cap = 0, vert_cap = 0, sph = 0;
    /* Disks enter as circumscribed 32-gons: a superset, so never a missed occluder. */
    const int disk_sides = 32;
    for (size_t i = 0; i < pieces; ++i) {
        const cdl_shape *s = &cdl_scene_geometry_piece(g, i)->shape;
        switch (s->kind) {
        case CDL_SHAPE_TRIANGLES: tri_cap += s->triangle_count; vert_cap += s->vertex_count; break;
        case CDL_SHAPE_RECT: tri_cap += 2; vert_cap += 4; break;
        case CDL_SHAPE_DISK: tri_cap += disk_sides; vert_cap += disk_sides + 1; break;
        case CDL_SHAPE_SPHERE: sph++; break;
        }
    }
    double *v = malloc((vert_cap + 1) * 3 * sizeof(double));
    uint32_t *t = malloc((tri_cap + 1) * 3 * sizeof(uint32_t));
    uint32_t *towner = malloc((tri_cap + 1) * sizeof(uint32_t));
    double *sc = malloc((sph + 1) * 3 * sizeof(double));
    double *sr = malloc((sph + 1) * sizeof(double));
    uint32_t *sowner = malloc((sph + 1) * sizeof(uint32_t));
    cdl_status st = CDL_OK;
    if (!v || !t || !towner || !sc || !sr || !sowner) {
        st = cdl_error_out_of_memory(err);
        goto done;
    }
    size_t nv = 0, nt = 0, ns = 0;
#define PUSH_V(p)                  \
    do {                           \
        v[3 * nv] = (p).x;         \
        v[3 * nv + 1] = (p).y;     \
        v[3 * nv + 2] = (p).z;     \
        nv++;                      \
    } while (0)
#define PUSH_T(a, b, c, o)         \
    do {                           \
        t[3 * nt] = (uint32_t)(a); \
        t[3 * nt + 1] = (uint32_t)(b); \
        t[3 * nt + 2] = (uint32_t)(c); \
        towner[nt] = (o);          \
        nt++;                      \
    } while (0)
    for (size_t i = 0; i < pieces; ++i) {
        const cdl_shape *s = &cdl_scene_geometry_piece(g, i)->shape;
        uint32_t o = (uint32_t)i;
        size_t base = nv;
        switch (s->kind) {
        case CDL_SHAPE_TRIANGLES:
            for (size_t k = 0; k < s->vertex_count; ++k)
                PUSH_V(cdl_vec3_make(s->vertices[3 * k], s->vertices[3 * k + 1], s->vertices[3 * k + 2]));
            for (size_t k = 0; k < s->triangle_count; ++k)
                PUSH_T(base + s->triangles[3 * k], base + s->triangles[3 * k + 1], base + s->triangles[3 * k + 2], o);
            break;
        case CDL_SHAPE_RECT:
            PUSH_V(s->origin);
            PUSH_V(cdl_vec3_add(s->origin, s->u));
            PUSH_V(cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v));
            PUSH_V(cdl_vec3_add(s->origin, s->v));
            PUSH_T(base, base + 1, base + 2, o);
            PUSH_T(base, base + 2, base + 3, o);
            break;
        case CDL_SHAPE_DISK: {
            cdl_frame disk = cdl_frame_from_normal(cdl_vec3_normalize(s->normal));
            /* The circumscribed polygon: its edges touch the circle at their middles. */
            double R = s->radius / cos(CDL_PI / disk_sides);
            PUSH_V(s->center);
            for (int k = 0; k < disk_sides; ++k) {
                double a = CDL_TWO_PI * k / disk_sides;
                PUSH_V(cdl_vec3_add(s->center, cdl_frame_to_world(&disk, cdl_vec3_make(R * cos(a), R * sin(a), 0.0))));
            }
            for (int k = 0; k < disk_sides; ++k) PUSH_T(base, base + 1 + k, base + 1 + (k + 1) % disk_sides, o);
            break;
        }
        case CDL_SHAPE_SPHERE:
            sc[3 * ns] = s->center.x;
            sc[3 * ns + 1] = s->center.y;
            sc[3 * ns + 2] = s->center.z;
            sr[ns] = s->radius;
            sowner[ns] = o;
            ns++;
            break;
        }
    }
#undef PUSH_V
#undef PUSH_T
    cdl_occluder_input in = {v, t, towner, nt, sc, sr, sowner, ns};
    st = cdl_occluder_index_build(&in, out, err);
done:
    free(v);
    free(t);
    free(towner);
    free(sc);
    free(sr);
    free(sowner);
    return st;
}
