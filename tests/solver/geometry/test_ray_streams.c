/* Shadow rays traced as Embree ray streams (cdl_ray_scene_occluded_many)
 * give, ray for ray, the answer of the single-ray query
 * (cdl_ray_scene_occluded_except): the same float rays and the same double
 * re-test of every candidate, whatever the stream's length and order.
 *
 * The scene: a 6 x 5 x 3 m room (inward box of 12 triangles), a field of
 * tessellated spheres and an exact sphere between floor and ceiling, a
 * table top. The rays: from floor points (origins on the floor's plane)
 * towards points of the ceiling (ends on its plane), light by light as a
 * direct chunk casts them; random rays in every direction, some of them
 * grazing the floor; rays along the shared diagonal of the table's two
 * triangles; rays with the exact sphere excluded; empty segments between
 * them; counts below one stream block (128 rays) and many blocks with a
 * remainder (12 000 rays). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "base/rng.h"
#include "radiometry/constants.h"
#include "solver/geometry/ray_scene.h"

static void add_quad(cdl_ray_scene *s, cdl_vec3 o, cdl_vec3 u, cdl_vec3 v, cdl_error *err)
{
    cdl_vec3 c[4] = {o, cdl_vec3_add(o, u), cdl_vec3_add(cdl_vec3_add(o, u), v), cdl_vec3_add(o, v)};
    double xyz[12];
    for (int k = 0; k < 4; ++k) {
        xyz[3 * k] = c[k].x;
        xyz[3 * k + 1] = c[k].y;
        xyz[3 * k + 2] = c[k].z;
    }
    const uint32_t tri[] = {0, 1, 2, 0, 2, 3};
    uint32_t id;
    CHECK_OK(cdl_ray_scene_add_triangles(s, xyz, 4, tri, 2, &id, err), err);
}

/* A sphere of 8 x 6 facets. */
static void add_ball(cdl_ray_scene *s, cdl_vec3 c, double r, cdl_error *err)
{
    enum { NU = 8, NV = 6 };
    double xyz[3 * (NU * (NV + 1))];
    uint32_t tri[6 * NU * NV];
    size_t nv = 0, nt = 0;
    for (int j = 0; j <= NV; ++j)
        for (int i = 0; i < NU; ++i) {
            double th = CDL_PI * j / NV, ph = 2.0 * CDL_PI * i / NU;
            xyz[3 * nv] = c.x + r * sin(th) * cos(ph);
            xyz[3 * nv + 1] = c.y + r * sin(th) * sin(ph);
            xyz[3 * nv + 2] = c.z + r * cos(th);
            ++nv;
        }
    for (int j = 0; j < NV; ++j)
        for (int i = 0; i < NU; ++i) {
            uint32_t a = (uint32_t)(j * NU + i), b = (uint32_t)(j * NU + (i + 1) % NU);
            uint32_t cc = a + NU, d = b + NU;
            tri[3 * nt] = a, tri[3 * nt + 1] = b, tri[3 * nt + 2] = d, ++nt;
            tri[3 * nt] = a, tri[3 * nt + 1] = d, tri[3 * nt + 2] = cc, ++nt;
        }
    uint32_t id;
    CHECK_OK(cdl_ray_scene_add_triangles(s, xyz, nv, tri, nt, &id, err), err);
}

static size_t compare(const cdl_ray_scene *s, const cdl_ray_segment *rays, size_t count, const char *what,
                      size_t *blocked)
{
    unsigned char *many = malloc(count ? count : 1);
    if (!many) return 0;
    cdl_ray_scene_occluded_many(s, rays, count, many);
    size_t differ = 0;
    for (size_t k = 0; k < count; ++k) {
        const cdl_ray_segment *r = &rays[k];
        int one = cdl_ray_scene_occluded_except(s, r->origin, r->dir, r->t_near, r->t_far, r->exclude);
        if (one != many[k] && differ++ < 5)
            fprintf(stderr, "%s, ray %zu: single %d, stream %d\n", what, k, one, many[k]);
        *blocked += many[k] != 0;
    }
    CHECK_MSG(differ == 0, "%s: %zu of %zu rays answered otherwise in streams", what, differ, count);
    free(many);
    return count;
}

int main(void)
{
    cdl_error err;
    cdl_ray_scene *s = NULL;
    CHECK_OK(cdl_ray_scene_create(&s, &err), &err);
    if (!s) return check_finish();
    /* the room, each face two triangles facing inward */
    add_quad(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 5, 0), cdl_vec3_make(6, 0, 0), &err);
    add_quad(s, cdl_vec3_make(0, 0, 3), cdl_vec3_make(6, 0, 0), cdl_vec3_make(0, 5, 0), &err);
    add_quad(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(6, 0, 0), cdl_vec3_make(0, 0, 3), &err);
    add_quad(s, cdl_vec3_make(0, 5, 0), cdl_vec3_make(0, 0, 3), cdl_vec3_make(6, 0, 0), &err);
    add_quad(s, cdl_vec3_make(0, 0, 0), cdl_vec3_make(0, 0, 3), cdl_vec3_make(0, 5, 0), &err);
    add_quad(s, cdl_vec3_make(6, 0, 0), cdl_vec3_make(0, 5, 0), cdl_vec3_make(0, 0, 3), &err);
    /* the table top: its shared diagonal from (2, 1.5) to (3.2, 2.3) */
    add_quad(s, cdl_vec3_make(2, 1.5, 0.75), cdl_vec3_make(1.2, 0, 0), cdl_vec3_make(0, 0.8, 0), &err);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j)
            add_ball(s, cdl_vec3_make(0.8 + 1.1 * i, 0.8 + 1.1 * j, 1.2 + 0.25 * ((i + j) % 3)), 0.22, &err);
    uint32_t sphere;
    CHECK_OK(cdl_ray_scene_add_sphere(s, cdl_vec3_make(4.2, 3.1, 1.9), 0.4, &sphere, &err), &err);
    CHECK_OK(cdl_ray_scene_commit(s, &err), &err);

    const size_t max_rays = 40000;
    cdl_ray_segment *rays = malloc(max_rays * sizeof *rays);
    if (!rays) return check_finish();
    size_t blocked = 0, total = 0, n = 0;
    cdl_rng_key key = {17, cdl_rng_stream_id(1, 2, 3)};
    uint64_t draw = 0;

    /* 1. Chunks of 16 floor points, 30 lights on the ceiling, light by
     *    light; every 7th light's segments excluded past the sphere, and an
     *    empty segment now and then. */
    for (int chunk = 0; chunk < 40; ++chunk) {
        double cx = 0.3 + 0.14 * chunk, cy = 0.4 + 0.1 * (chunk % 7);
        for (int l = 0; l < 30; ++l) {
            double u[2];
            cdl_rng_uniform2(key, draw++, u);
            cdl_vec3 light = cdl_vec3_make(0.2 + 5.6 * u[0], 0.2 + 4.6 * u[1], 3.0);
            for (int i = 0; i < 16; ++i) {
                cdl_vec3 p = cdl_vec3_make(cx + 0.05 * (i % 4), cy + 0.05 * (i / 4), 0.0);
                cdl_vec3 d = cdl_vec3_sub(light, p);
                double len = cdl_vec3_length(d);
                cdl_ray_segment r = {p, cdl_vec3_scale(d, 1.0 / len), 0.0, len,
                                     l % 7 == 0 ? sphere : CDL_RAY_EXCLUDE_NONE};
                if ((i + l) % 23 == 0) r.t_far = 0.0; /* empty */
                rays[n++] = r;
            }
        }
    }
    total += compare(s, rays, n, "floor points towards ceiling lights", &blocked);

    /* 2. Random segments anywhere in the room, in every direction, some of
     *    them nearly along the floor (1e-7 rad up). */
    n = 0;
    for (size_t k = 0; k < 12000; ++k) {
        double u[2], v[2], w[2];
        cdl_rng_uniform2(key, draw++, u);
        cdl_rng_uniform2(key, draw++, v);
        cdl_rng_uniform2(key, draw++, w);
        cdl_vec3 p = cdl_vec3_make(6.0 * u[0], 5.0 * u[1], k % 5 == 0 ? 0.0 : 3.0 * v[0]);
        double z = k % 5 == 0 ? 1e-7 : 2.0 * v[1] - 1.0, rr = sqrt(fmax(0.0, 1.0 - z * z));
        cdl_vec3 d = cdl_vec3_make(rr * cos(2.0 * CDL_PI * w[0]), rr * sin(2.0 * CDL_PI * w[0]), z);
        cdl_ray_segment r = {p, d, 0.0, k % 3 == 0 ? INFINITY : 0.5 + 6.0 * w[1], CDL_RAY_EXCLUDE_NONE};
        rays[n++] = r;
    }
    total += compare(s, rays, n, "random segments", &blocked);

    /* 3. Down onto the table's shared diagonal, and across it just above
     *    the top, in counts of 1, 3, 5, 17 and 33. */
    const size_t counts[] = {1, 3, 5, 17, 33};
    for (size_t c = 0; c < sizeof counts / sizeof *counts; ++c) {
        n = 0;
        for (size_t k = 0; k < counts[c]; ++k) {
            double t = (k + 0.5) / counts[c];
            cdl_vec3 on = cdl_vec3_make(2.0 + 1.2 * t, 1.5 + 0.8 * t, 0.75);
            if (k % 2 == 0) {
                cdl_ray_segment r = {cdl_vec3_make(on.x, on.y, 2.5), cdl_vec3_make(0, 0, -1), 0.0, 2.5,
                                     CDL_RAY_EXCLUDE_NONE};
                rays[n++] = r;
            } else {
                cdl_ray_segment r = {cdl_vec3_make(on.x - 0.8, on.y + 1.2, 0.75 + 1e-9),
                                     cdl_vec3_normalize(cdl_vec3_make(1.2, -1.8, 0)), 0.0, 3.0, CDL_RAY_EXCLUDE_NONE};
                rays[n++] = r;
            }
        }
        total += compare(s, rays, n, "onto and along the table's diagonal", &blocked);
    }
    fprintf(stderr, "%zu rays, %zu blocked: the same answers in streams and one by one\n", total, blocked);
    /* the rays must test both answers */
    CHECK(blocked > total / 10 && blocked < total - total / 10);
    free(rays);
    cdl_ray_scene_release(s);
    return check_finish();
}
