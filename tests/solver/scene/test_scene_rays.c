/* Ray epsilon and scale: the same furnished room built at 1e-3, 1 and 1e3
 * times its size must give identical occlusion answers for corresponding
 * rays, shadows on the floor must match the exact geometry, and points
 * lying exactly on a surface must see the whole hemisphere their normal
 * faces without hitting that surface, grazing directions included. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "radiometry/frame.h"
#include "base/rng.h"
#include "solver/scene/scene_geometry.h"

static const double scales[3] = {1e-3, 1.0, 1e3};

/* Piece ids, in the order of the surfaces below (the box has six faces). */
enum { ID_CEILING = 5, ID_TABLE = 6, ID_SPHERE = 7, ID_RAMP = 8, ID_DISK = 9, ID_TETRA = 10, ID_PANEL = 11 };

/* The ramp: a tilted square with a square hole, in the plane z = 0.2 + (y - 3) / 1.5. */
static double ramp_z(double y) { return 0.2 + (y - 3.0) / 1.5; }

static const cdl_vec3 light = {2.0, 2.5, 2.9};
static const cdl_vec3 disk_centre = {3.5, 1.0, 2.0};
#define DISK_RADIUS 0.3

/* "[x,y,z],[x,y,z],..." for n points scaled by s, into buf. */
static const char *points(char *buf, size_t size, double s, const double *v, int n)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int i = 0; i < n && len < size; ++i)
        len += (size_t)snprintf(buf + len, size - len, "%s[%.17g,%.17g,%.17g]", i ? "," : "", v[3 * i] * s,
                                v[3 * i + 1] * s, v[3 * i + 2] * s);
    return buf;
}

/* The room at scale s, as JSON. */
static void room_json(double s, char *out, size_t size)
{
    const double box[6] = {0, 0, 0, 4, 5, 3};
    const double table[9] = {1, 1, 0.75, 1.2, 0, 0, 0, 0.8, 0};
    const double sphere[3] = {3, 3.5, 1};
    const double ramp[12] = {0.5, 3, ramp_z(3), 2, 3, ramp_z(3), 2, 4.5, ramp_z(4.5), 0.5, 4.5, ramp_z(4.5)};
    const double hole[12] = {1, 3.5, ramp_z(3.5), 1, 4, ramp_z(4), 1.5, 4, ramp_z(4), 1.5, 3.5, ramp_z(3.5)};
    const double disk[3] = {disk_centre.x, disk_centre.y, disk_centre.z};
    const double tetra[12] = {3, 3.9, 0, 3.8, 3.9, 0, 3.4, 4.6, 0, 3.4, 4.1, 0.7};
    const double panel[9] = {1.5, 2, 3, 1, 0, 0, 0, -0.6, 0};
    /* One buffer per field: all are formatted before snprintf reads them. */
    char f[14][320];
    points(f[0], 320, s, box, 1);
    points(f[1], 320, s, box + 3, 1);
    points(f[2], 320, s, table, 1);
    points(f[3], 320, s, table + 3, 1);
    points(f[4], 320, s, table + 6, 1);
    points(f[5], 320, s, sphere, 1);
    points(f[6], 320, s, ramp, 4);
    points(f[7], 320, s, hole, 4);
    points(f[8], 320, s, disk, 1);
    points(f[9], 320, s, tetra, 4);
    points(f[10], 320, s, panel, 1);
    points(f[11], 320, s, panel + 3, 1);
    points(f[12], 320, s, panel + 6, 1);
    snprintf(out, size,
             "{\"version\": 1, \"surfaces\": ["
             "{\"type\": \"box\", \"min\": %s, \"max\": %s, \"inward\": true, \"reflectance\": 0.5},"
             "{\"type\": \"rect\", \"origin\": %s, \"u\": %s, \"v\": %s, \"reflectance\": 0.4},"
             "{\"type\": \"sphere\", \"center\": %s, \"radius\": %.17g, \"reflectance\": 0.5},"
             "{\"type\": \"polygon\", \"vertices\": [%s], \"holes\": [[%s]], \"reflectance\": 0.3},"
             "{\"type\": \"disk\", \"center\": %s, \"normal\": [-1,0,-1], \"radius\": %.17g, \"reflectance\": 0.2},"
             "{\"type\": \"mesh\", \"vertices\": [%s], \"triangles\": [[0,2,1],[0,1,3],[1,2,3],[2,0,3]],"
             " \"reflectance\": 0.5}],"
             " \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": %s, \"u\": %s,"
             " \"v\": %s}, \"luminance_cd_m2\": 1000}],"
             " \"grids\": [{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}]}",
             f[0], f[1], f[2], f[3], f[4], f[5], 0.4 * s, f[6], f[7], f[8], DISK_RADIUS * s, f[9], f[10], f[11], f[12]);
}

/* Does segment pq cross the table top or the disk? (Exact geometry.)
 * *margin receives how far (m) the crossing points lie from the edges of
 * those occluders: the disk is an inscribed fan, so shadow edges may move
 * by about 1e-4 m; closer calls are not compared. */
static int shadowed_exactly(cdl_vec3 p, cdl_vec3 q, double *margin)
{
    cdl_vec3 d = cdl_vec3_sub(q, p);
    double t = (0.75 - p.z) / d.z;
    cdl_vec3 x = cdl_vec3_madd(p, t, d);
    *margin = fmin(fmin(fabs(x.x - 1), fabs(x.x - 2.2)), fmin(fabs(x.y - 1), fabs(x.y - 1.8)));
    if (t > 0 && t < 1 && x.x > 1 && x.x < 2.2 && x.y > 1 && x.y < 1.8) return 1;
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(-1, 0, -1));
    t = cdl_vec3_dot(cdl_vec3_sub(disk_centre, p), n) / cdl_vec3_dot(d, n);
    x = cdl_vec3_madd(p, t, d);
    *margin = fmin(*margin, fabs(cdl_vec3_distance(x, disk_centre) - DISK_RADIUS));
    return t > 0 && t < 1 && cdl_vec3_distance(x, disk_centre) < DISK_RADIUS;
}

typedef struct surface_point {
    cdl_vec3 p, n;
    size_t piece;
} surface_point;

/* A point on one of the room's surfaces (unit scale), from two uniforms. */
static surface_point sample_surface(int which, const double *u)
{
    surface_point sp;
    switch (which) {
    case 0: /* the floor, away from the walls */
        sp.p = cdl_vec3_make(0.1 + 3.8 * u[0], 0.1 + 4.8 * u[1], 0.0);
        sp.n = cdl_vec3_make(0, 0, 1);
        sp.piece = 4;
        break;
    case 1: /* the table top */
        sp.p = cdl_vec3_make(1.0 + 1.2 * u[0], 1.0 + 0.8 * u[1], 0.75);
        sp.n = cdl_vec3_make(0, 0, 1);
        sp.piece = ID_TABLE;
        break;
    case 2: { /* the ramp, outside its hole */
        double y = 3.0 + 0.5 * u[1];
        sp.p = cdl_vec3_make(0.5 + 1.5 * u[0], y, ramp_z(y));
        sp.n = cdl_vec3_normalize(cdl_vec3_make(0, -1, 1.5));
        sp.piece = ID_RAMP;
        break;
    }
    default: { /* the sphere's outside, upper half */
        double z = u[0], phi = 6.283185307179586 * u[1], r = sqrt(1 - z * z);
        sp.n = cdl_vec3_make(r * cos(phi), r * sin(phi), z);
        sp.p = cdl_vec3_madd(cdl_vec3_make(3, 3.5, 1), 0.4, sp.n);
        sp.piece = ID_SPHERE;
    }
    }
    return sp;
}

int main(void)
{
    cdl_error err;
    cdl_scene *scenes[3] = {NULL, NULL, NULL};
    cdl_scene_geometry *geoms[3] = {NULL, NULL, NULL};
    static char json[8192];
    for (int k = 0; k < 3; ++k) {
        room_json(scales[k], json, sizeof json);
        CHECK_OK(cdl_scene_load_string(json, "room.json", &scenes[k], &err), &err);
        if (scenes[k]) CHECK_OK(cdl_scene_geometry_build(scenes[k], &geoms[k], &err), &err);
        if (!geoms[k]) {
            for (int j = 0; j <= k; ++j) {
                cdl_scene_geometry_release(geoms[j]);
                cdl_scene_release(scenes[j]);
            }
            return check_finish();
        }
    }
    CHECK(cdl_scene_geometry_piece_count(geoms[1]) == 12);
    CHECK(cdl_scene_geometry_piece(geoms[1], ID_PANEL)->is_luminaire);
    CHECK(cdl_scene_geometry_piece(geoms[1], 4)->box_face == CDL_BOX_NEG_Z);

    /* The epsilon scales with the scene: eps(s p) = s eps(p) up to rounding. */
    for (int i = 0; i < 4; ++i) {
        cdl_vec3 p = cdl_vec3_make(0.3 * i, 5.0 - i, 3.0 * i);
        double e1 = cdl_scene_geometry_ray_epsilon(geoms[1], p);
        CHECK(e1 > 0.0 && e1 < 1e-3);
        for (int k = 0; k < 3; k += 2)
            CHECK_REL(cdl_scene_geometry_ray_epsilon(geoms[k], cdl_vec3_scale(p, scales[k])) / scales[k], e1, 1e-12);
    }

    /* 1. Shadows of a point light on the floor: exact geometry, every scale. */
    cdl_rng_key key = {1, 7};
    int mismatches[3] = {0, 0, 0}, shadowed = 0, total = 0, close_calls = 0;
    for (uint64_t i = 0; i < 4000; ++i) {
        double u[2], margin;
        cdl_rng_uniform2(key, i, u);
        cdl_vec3 p = cdl_vec3_make(0.1 + 3.8 * u[0], 0.1 + 2.8 * u[1], 0.0);
        int expected = shadowed_exactly(p, light, &margin);
        if (margin < 1e-3) {
            ++close_calls;
            continue;
        }
        shadowed += expected;
        ++total;
        for (int k = 0; k < 3; ++k) {
            double s = scales[k];
            int got = cdl_scene_geometry_segment_occluded(geoms[k], cdl_vec3_scale(p, s), cdl_vec3_make(0, 0, 1),
                                                          cdl_vec3_scale(light, s), cdl_vec3_make(0, 0, 0));
            mismatches[k] += got != expected;
        }
    }
    /* Both outcomes occur, so the comparison means something. */
    CHECK_MSG(shadowed > total / 20 && shadowed < total / 2, "%d of %d floor points shadowed", shadowed, total);
    CHECK_MSG(close_calls < 40, "%d of 4000 floor points within 1 mm of a shadow edge", close_calls);
    for (int k = 0; k < 3; ++k) CHECK_MSG(mismatches[k] == 0, "scale %g: %d shadow mismatches", scales[k], mismatches[k]);

    /* 2. Random segments between surface points and points in the room or on
     * the ceiling panel: identical answers at every scale. */
    key.stream = 8;
    int differ = 0, blocked = 0, count = 0;
    for (uint64_t i = 0; i < 6000; ++i) {
        double u[2], v[2], w[2];
        cdl_rng_uniform2(key, 3 * i, u);
        cdl_rng_uniform2(key, 3 * i + 1, v);
        cdl_rng_uniform2(key, 3 * i + 2, w);
        surface_point sp = sample_surface((int)(i % 4), u);
        cdl_vec3 q, qn;
        if (i % 3 == 0) { /* on the emitting panel, flush with the ceiling */
            q = cdl_vec3_make(1.5 + v[0], 1.4 + 0.6 * v[1], 3.0);
            qn = cdl_vec3_make(0, 0, -1);
        } else {
            q = cdl_vec3_make(0.05 + 3.9 * v[0], 0.05 + 4.9 * v[1], 0.05 + 2.9 * w[0]);
            qn = cdl_vec3_make(0, 0, 0);
        }
        int answers[3];
        for (int k = 0; k < 3; ++k) {
            double s = scales[k];
            answers[k] = cdl_scene_geometry_segment_occluded(geoms[k], cdl_vec3_scale(sp.p, s), sp.n,
                                                             cdl_vec3_scale(q, s), qn);
        }
        differ += answers[0] != answers[1] || answers[2] != answers[1];
        blocked += answers[1];
        ++count;
    }
    CHECK_MSG(blocked > count / 20 && blocked < count * 19 / 20, "%d of %d segments blocked", blocked, count);
    CHECK_MSG(differ == 0, "%d of %d segments answer differently across scales", differ, count);

    /* 3. Points on a surface see their whole hemisphere: the first hit of
     * every ray leaving on the normal's side is another piece, and a short
     * ray is not occluded; directions down to 0.06 degrees above the plane. */
    static const double cosines[] = {1e-3, 1e-2, 0.1, 0.3, 0.6, 0.9, 1.0};
    key.stream = 9;
    int self_hits = 0, short_blocked = 0, rays = 0;
    for (int which = 0; which < 4; ++which)
        for (uint64_t i = 0; i < 40; ++i) {
            double u[2];
            cdl_rng_uniform2(key, 100 * (uint64_t)which + i, u);
            surface_point sp = sample_surface(which, u);
            cdl_frame f = cdl_frame_from_normal(sp.n);
            for (size_t c = 0; c < sizeof cosines / sizeof cosines[0]; ++c)
                for (int a = 0; a < 12; ++a) {
                    double ct = cosines[c], st = sqrt(1 - ct * ct), phi = 0.5236 * a + 0.1 * u[0];
                    cdl_vec3 dir = cdl_frame_to_world(&f, cdl_vec3_make(st * cos(phi), st * sin(phi), ct));
                    for (int k = 0; k < 3; ++k) {
                        double s = scales[k];
                        cdl_vec3 p = cdl_vec3_scale(sp.p, s);
                        cdl_ray_hit hit;
                        int got = cdl_scene_geometry_intersect(geoms[k], p, sp.n, dir, INFINITY, &hit);
                        self_hits += !got || hit.geom_id == sp.piece;
                        /* 2 mm at unit scale: nothing but the surface itself is that close. */
                        short_blocked += cdl_scene_geometry_ray_occluded(geoms[k], p, sp.n, dir, 0.002 * s);
                        ++rays;
                    }
                }
        }
    CHECK_MSG(self_hits == 0, "%d of %d rays from surface points hit their own surface (or nothing)", self_hits, rays);
    CHECK_MSG(short_blocked == 0, "%d of %d short rays from surface points were blocked", short_blocked, rays);

    /* The hit distance is measured from the point: straight up from the
     * floor the ceiling is 3 (scaled) away, float precision (1e-6 relative). */
    for (int k = 0; k < 3; ++k) {
        cdl_ray_hit hit;
        cdl_vec3 p = cdl_vec3_scale(cdl_vec3_make(0.5, 0.5, 0.0), scales[k]);
        CHECK(cdl_scene_geometry_intersect(geoms[k], p, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 1), INFINITY, &hit));
        CHECK(hit.geom_id == ID_CEILING);
        CHECK_REL(hit.t, 3.0 * scales[k], 1e-6);
        /* A segment that ends on the ceiling panel, given the panel's normal,
         * is not blocked by the panel or the ceiling it is flush with. */
        cdl_vec3 q = cdl_vec3_scale(cdl_vec3_make(2.0, 1.7, 3.0), scales[k]);
        CHECK(!cdl_scene_geometry_segment_occluded(geoms[k], cdl_vec3_scale(cdl_vec3_make(2.0, 2.5, 0.0), scales[k]),
                                                   cdl_vec3_make(0, 0, 1), q, cdl_vec3_make(0, 0, -1)));
        /* Under the table, the same panel is hidden. */
        CHECK(cdl_scene_geometry_segment_occluded(geoms[k], cdl_vec3_scale(cdl_vec3_make(1.6, 1.4, 0.0), scales[k]),
                                                  cdl_vec3_make(0, 0, 1), q, cdl_vec3_make(0, 0, -1)));
    }

    fprintf(stderr, "floor shadows: %d of %d points shadowed (%d close calls skipped); segments: %d of %d blocked; "
                    "%d rays from surface points\n", shadowed, total, close_calls, blocked, count, rays);
    for (int k = 0; k < 3; ++k) {
        cdl_scene_geometry_release(geoms[k]);
        cdl_scene_release(scenes[k]);
    }
    return check_finish();
}
