/* ray_scene.c - Embree 3 scene of triangle meshes and exact spheres.
 *
 * Embree stores single-precision floats. To keep precision for scenes far
 * from the origin, geometry is translated so that the scene's bounding-box
 * centre is the origin before conversion to float; query origins are
 * translated the same way (in double).
 *
 * Hits near the ends of a ray are resolved in double. Of the two ways to
 * make rays right at every scale - offsetting origins by the rounding bound
 * of each point (pbrt-v4's error bounds) or re-testing Embree's hits against
 * the double-precision geometry - this file does the second: an offset
 * bound on a float computation is a float ulp of the largest coordinate
 * Embree handles (tens of micrometres in a 1 km scene), too coarse for a
 * wall 0.1 mm from a point, while the double geometry locates that wall to
 * 1e-13 m. Embree is asked for every candidate on the segment lengthened by
 * a float margin at both ends (so no true hit near an end can be lost to
 * float rounding), and a filter function re-tests each candidate in double
 * (hit_double below): a surface counts only if the ray meets it at
 * t_near < t < t_far, and not if the ray's origin or its end lies on the
 * surface's plane (sphere) to within the double rounding bound. A point on
 * a floor is thus never shadowed by that floor, whatever the direction,
 * while a wall 1e-9 of the scene's size away does shadow it.
 */
#include "solver/geometry/ray_scene.h"

#include <embree3/rtcore.h>
#include "base/error_report.h"
#include "radiometry/bounds.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct pending_geometry {
    int is_sphere;
    double *xyz;          /* vertex_count x 3 (sphere: centre) */
    size_t vertex_count;
    uint32_t *triangles;  /* triangle_count x 3 */
    size_t triangle_count;
    double radius;
} pending_geometry;

/* Double rounding bound: a computed point, and a plane evaluated at it, are
 * within 2^-40 (about 4000 double ulps) of the largest coordinate magnitude
 * involved of where exact arithmetic puts them. */
#define ROUNDING_RELATIVE 0x1p-40
/* Embree's float errors: a few ulps (2^-23) of the local coordinates; the
 * query segment is lengthened by 2^7 of them at both ends. */
#define FLOAT_ULP 0x1p-23
#define FLOAT_MARGIN_ULPS 128.0
/* Barycentric slack of the double inside test: Embree's robust mode keeps
 * shared edges watertight, and a candidate it found on an edge must not be
 * rejected by a rounding of the double barycentrics. */
#define BARYCENTRIC_SLACK 0x1p-30

struct cdl_ray_scene {
    RTCDevice device;
    RTCScene scene;
    pending_geometry *geometry;
    size_t geometry_count, geometry_capacity;
    size_t triangle_count;
    cdl_vec3 offset;     /* world = local + offset */
    double half_size;    /* largest half-side of the bounding box (local magnitude of the geometry) */
    int committed;
    cdl_error *device_error; /* where the device error callback writes, during build */
};

static void device_error_callback(void *user, enum RTCError code, const char *str)
{
    cdl_ray_scene *s = user;
    if (s && s->device_error && s->device_error->status == CDL_OK)
        cdl_error_set(s->device_error, CDL_ERR_INTERNAL, "Embree error %d: %s", (int)code, str ? str : "");
}

cdl_status cdl_ray_scene_create(cdl_ray_scene **out, cdl_error *err)
{
    *out = NULL;
    cdl_ray_scene *s = calloc(1, sizeof *s);
    if (!s) return cdl_error_out_of_memory(err);
    s->device = rtcNewDevice(NULL);
    if (!s->device) {
        free(s);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "Embree: cannot create a device (error %d)",
                             (int)rtcGetDeviceError(NULL));
    }
    rtcSetDeviceErrorFunction(s->device, device_error_callback, s);
    if (!rtcGetDeviceProperty(s->device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED)) {
        rtcReleaseDevice(s->device);
        free(s);
        return cdl_error_set(err, CDL_ERR_INTERNAL,
                             "Embree was built without filter functions, which the double-precision ray tests need");
    }
    *out = s;
    return CDL_OK;
}

static cdl_status push_geometry(cdl_ray_scene *s, pending_geometry g, uint32_t *geom_id, cdl_error *err)
{
    if (s->committed) return cdl_error_set(err, CDL_ERR_INTERNAL, "ray scene: geometry added after commit");
    if (s->geometry_count == s->geometry_capacity) {
        size_t cap = s->geometry_capacity ? 2 * s->geometry_capacity : 8;
        pending_geometry *p = realloc(s->geometry, cap * sizeof *p);
        if (!p) return cdl_error_out_of_memory(err);
        s->geometry = p;
        s->geometry_capacity = cap;
    }
    s->geometry[s->geometry_count] = g;
    *geom_id = (uint32_t)s->geometry_count;
    s->geometry_count++;
    s->triangle_count += g.triangle_count;
    return CDL_OK;
}

cdl_status cdl_ray_scene_add_triangles(cdl_ray_scene *s, const double *xyz, size_t vertex_count,
                                       const uint32_t *triangles, size_t triangle_count, uint32_t *geom_id,
                                       cdl_error *err)
{
    for (size_t i = 0; i < triangle_count * 3; ++i)
        if (triangles[i] >= vertex_count)
            return cdl_error_set(err, CDL_ERR_INPUT, "triangle %zu refers to vertex %u of %zu", i / 3,
                                 (unsigned)triangles[i], vertex_count);
    pending_geometry g = {0};
    g.xyz = malloc(vertex_count * 3 * sizeof(double));
    g.triangles = malloc(triangle_count * 3 * sizeof(uint32_t));
    if (!g.xyz || !g.triangles) {
        free(g.xyz);
        free(g.triangles);
        return cdl_error_out_of_memory(err);
    }
    memcpy(g.xyz, xyz, vertex_count * 3 * sizeof(double));
    memcpy(g.triangles, triangles, triangle_count * 3 * sizeof(uint32_t));
    g.vertex_count = vertex_count;
    g.triangle_count = triangle_count;
    cdl_status st = push_geometry(s, g, geom_id, err);
    if (st != CDL_OK) {
        free(g.xyz);
        free(g.triangles);
    }
    return st;
}

cdl_status cdl_ray_scene_add_sphere(cdl_ray_scene *s, cdl_vec3 center, double radius, uint32_t *geom_id,
                                    cdl_error *err)
{
    pending_geometry g = {0};
    g.is_sphere = 1;
    g.xyz = malloc(3 * sizeof(double));
    if (!g.xyz) return cdl_error_out_of_memory(err);
    g.xyz[0] = center.x;
    g.xyz[1] = center.y;
    g.xyz[2] = center.z;
    g.vertex_count = 1;
    g.radius = radius;
    cdl_status st = push_geometry(s, g, geom_id, err);
    if (st != CDL_OK) free(g.xyz);
    return st;
}

/* One query in double: the ray Embree traces in float, as the caller gave it. */
typedef struct double_query {
    cdl_vec3 origin, dir;               /* world coordinates, dir as given */
    double t_near, t_far;
    cdl_vec3 end;                       /* origin + t_far dir when t_far is finite */
    int has_end;
    double margin, back;                /* the float margin (m) and the pull-back (units of |dir|) */
    int want_t;                         /* intersect: every hit's t in double */
    double best_t;                      /* closest accepted hit (intersect) */
    uint32_t best_geom, best_prim;
    uint32_t exclude;                   /* a geometry that never counts (CDL_RAY_EXCLUDE_NONE: none) */
} double_query;

/* What Embree hands the filter: its context, and the queries of the rays
 * traced together (one for rtcOccluded1 and rtcIntersect1, up to
 * STREAM_BLOCK for a stream), each ray's own found by the ray's id. */
typedef struct query_context {
    struct RTCIntersectContext context; /* first: Embree hands the filter a pointer to it */
    double_query *queries;
} query_context;

/* The larger of two finite numbers: a comparison, where fmax is a library
 * call without -ffast-math (the filter below runs for every candidate hit). */
static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

static double max_abs3(cdl_vec3 v)
{
    return max2(fabs(v.x), max2(fabs(v.y), fabs(v.z)));
}

static cdl_vec3 vertex_of(const pending_geometry *g, uint32_t index)
{
    const double *v = &g->xyz[3 * (size_t)index];
    return cdl_vec3_make(v[0], v[1], v[2]);
}

/* The double-precision re-test of a candidate triangle: the t of the hit,
 * or -1 when the ray does not meet it on the open segment. The plane
 * through a, b, c with (unnormalised) normal m: the origin's signed
 * distance is s_o = m.(o - a) / |m|, and the line meets the plane at
 * t = -m.(o - a) / m.d. An origin (or end) within the rounding bound of the
 * plane lies on it: the line then meets the plane there and nowhere else,
 * so the surface it lies on never counts. */
static double triangle_hit_double(const pending_geometry *g, uint32_t prim, const double_query *q)
{
    const uint32_t *tri = &g->triangles[3 * (size_t)prim];
    cdl_vec3 a = vertex_of(g, tri[0]), b = vertex_of(g, tri[1]), c = vertex_of(g, tri[2]);
    cdl_vec3 m = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a));
    double m_len = cdl_vec3_length(m);
    if (!(m_len > 0.0)) return -1.0;
    double scale = max2(max2(max_abs3(a), max_abs3(b)), max2(max_abs3(c), max_abs3(q->origin)));
    if (q->has_end) scale = max2(scale, max_abs3(q->end));
    double on_plane = ROUNDING_RELATIVE * scale * m_len;
    double s_o = cdl_vec3_dot(m, cdl_vec3_sub(q->origin, a));
    if (fabs(s_o) <= on_plane) return -1.0;
    if (q->has_end && fabs(cdl_vec3_dot(m, cdl_vec3_sub(q->end, a))) <= on_plane) return -1.0;
    double den = cdl_vec3_dot(m, q->dir);
    if (den == 0.0) return -1.0;
    double t = -s_o / den;
    if (!(t > q->t_near && t < q->t_far)) return -1.0;
    /* Barycentrics of the hit h: the areas of the sub-triangles against m. */
    cdl_vec3 h = cdl_vec3_madd(q->origin, t, q->dir);
    double m2 = m_len * m_len;
    double la = cdl_vec3_dot(m, cdl_vec3_cross(cdl_vec3_sub(b, h), cdl_vec3_sub(c, h))) / m2;
    double lb = cdl_vec3_dot(m, cdl_vec3_cross(cdl_vec3_sub(c, h), cdl_vec3_sub(a, h))) / m2;
    double lc = 1.0 - la - lb;
    if (la < -BARYCENTRIC_SLACK || lb < -BARYCENTRIC_SLACK || lc < -BARYCENTRIC_SLACK) return -1.0;
    return t;
}

/* The same for a sphere (centre c, radius r): the roots of
 * |o + t d - c|^2 = r^2, by the cancellation-free pair q / A, C / q
 * (Numerical Recipes 5.6), with C = (|o - c| - r)(|o - c| + r). An origin on
 * the sphere has the roots 0 (itself) and -2 (o - c).d / d.d (the far
 * side); an end on it drops the root nearest t_far. */
static double sphere_hit_double(const pending_geometry *g, const double_query *q)
{
    cdl_vec3 c = vertex_of(g, 0);
    double r = g->radius;
    cdl_vec3 oc = cdl_vec3_sub(q->origin, c);
    double A = cdl_vec3_dot(q->dir, q->dir), B = cdl_vec3_dot(oc, q->dir);
    double dist = cdl_vec3_length(oc);
    double scale = max2(max_abs3(c) + r, max_abs3(q->origin));
    if (q->has_end) scale = max2(scale, max_abs3(q->end));
    double bound = ROUNDING_RELATIVE * scale;
    double roots[2];
    int count = 0;
    if (fabs(dist - r) <= bound) {
        roots[count++] = -2.0 * B / A;
    } else {
        double C = (dist - r) * (dist + r);
        double disc = B * B - A * C;
        if (disc < 0.0) return -1.0;
        double qq = -(B + copysign(sqrt(disc), B));
        if (qq == 0.0) return -1.0;
        roots[count++] = qq / A;
        roots[count++] = C / qq;
    }
    if (q->has_end && fabs(cdl_vec3_length(cdl_vec3_sub(q->end, c)) - r) <= bound) {
        int nearest = 0;
        for (int k = 1; k < count; ++k)
            if (fabs(roots[k] - q->t_far) < fabs(roots[nearest] - q->t_far)) nearest = k;
        roots[nearest] = roots[--count];
    }
    double best = -1.0;
    for (int k = 0; k < count; ++k)
        if (roots[k] > q->t_near && roots[k] < q->t_far && (best < 0.0 || roots[k] < best)) best = roots[k];
    return best;
}

static double hit_double(const pending_geometry *g, uint32_t prim, const double_query *q)
{
    return g->is_sphere ? sphere_hit_double(g, q) : triangle_hit_double(g, prim, q);
}

/* Embree's filter: keep a candidate only if the double re-test agrees.
 * RTCHitN's primID is the 6th of its N-wide fields (rtcore_ray.h). */
static void filter_double(const struct RTCFilterFunctionNArguments *args)
{
    const query_context *qc = (const query_context *)args->context;
    const pending_geometry *g = args->geometryUserPtr;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        /* RTCRayN's id is its 11th field */
        double_query *q = &qc->queries[((const unsigned *)args->ray)[10 * args->N + i]];
        const float *h = (const float *)args->hit;
        uint32_t prim = ((const unsigned *)args->hit)[5 * args->N + i];
        /* RTCHitN's geomID is the 7th field */
        if (((const unsigned *)args->hit)[6 * args->N + i] == q->exclude) {
            args->valid[i] = 0;
            continue;
        }
        if (!q->want_t && !g->is_sphere) {
            /* Clear of both ends: Embree's own answer stands. The hit is
             * 2 margins along the normal from where the ray starts and ends
             * (Embree's float t counts from the pulled-back start), far
             * beyond Embree's few-ulp errors, so neither end lies on the
             * plane; and 1e-3 inside the triangle, far beyond the float
             * error of its barycentrics. */
            float u = h[3 * args->N + i], v = h[4 * args->N + i];
            float nx = h[i], ny = h[args->N + i], nz = h[2 * args->N + i];
            double tf = ((const float *)args->ray)[8 * args->N + i];
            double n_len = sqrt((double)nx * nx + (double)ny * ny + (double)nz * nz);
            double cos_n = n_len > 0.0 ? fabs(nx * q->dir.x + ny * q->dir.y + nz * q->dir.z) / n_len : 0.0;
            double from_start = (tf - q->back) * cos_n, to_end = (q->t_far - q->t_near + q->back - tf) * cos_n;
            if (from_start > 2.0 * q->margin && to_end > 2.0 * q->margin && u > 1e-3f && v > 1e-3f &&
                u + v < 1.0f - 1e-3f)
                continue;
        }
        double t = hit_double(g, prim, q);
        if (t < 0.0) {
            args->valid[i] = 0;
            continue;
        }
        if (t < q->best_t) {
            q->best_t = t;
            q->best_geom = ((const unsigned *)args->hit)[6 * args->N + i];
            q->best_prim = prim;
        }
    }
}

cdl_status cdl_ray_scene_commit(cdl_ray_scene *s, cdl_error *err)
{
    if (s->committed) return CDL_OK;
    cdl_error build_err;
    cdl_error_clear(&build_err);
    s->device_error = &build_err;

    /* Bounding box of everything, for the recentring offset. */
    cdl_bounds3 box = cdl_bounds3_empty();
    for (size_t g = 0; g < s->geometry_count; ++g) {
        const pending_geometry *pg = &s->geometry[g];
        double r = pg->is_sphere ? pg->radius : 0.0;
        for (size_t v = 0; v < pg->vertex_count; ++v) {
            cdl_vec3 p = cdl_vec3_make(pg->xyz[3 * v], pg->xyz[3 * v + 1], pg->xyz[3 * v + 2]);
            cdl_bounds3_grow(&box, cdl_vec3_sub(p, cdl_vec3_make(r, r, r)));
            cdl_bounds3_grow(&box, cdl_vec3_add(p, cdl_vec3_make(r, r, r)));
        }
    }
    s->offset = s->geometry_count ? cdl_bounds3_centre(box) : cdl_vec3_make(0, 0, 0);
    s->half_size = s->geometry_count ? 0.5 * max_abs3(cdl_vec3_sub(box.hi, box.lo)) : 0.0;
    const double off[3] = {s->offset.x, s->offset.y, s->offset.z};

    s->scene = rtcNewScene(s->device);
    rtcSetSceneFlags(s->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s->scene, RTC_BUILD_QUALITY_HIGH);
    for (size_t g = 0; g < s->geometry_count && build_err.status == CDL_OK; ++g) {
        pending_geometry *pg = &s->geometry[g];
        RTCGeometry geom;
        if (pg->is_sphere) {
            geom = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1);
            if (v) {
                for (int k = 0; k < 3; ++k) v[k] = (float)(pg->xyz[k] - off[k]);
                v[3] = (float)pg->radius;
            }
        } else {
            geom = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
            float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                               pg->vertex_count);
            unsigned *t = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                  3 * sizeof(unsigned), pg->triangle_count);
            if (v && t) {
                for (size_t i = 0; i < pg->vertex_count; ++i)
                    for (int k = 0; k < 3; ++k) v[3 * i + k] = (float)(pg->xyz[3 * i + k] - off[k]);
                for (size_t i = 0; i < 3 * pg->triangle_count; ++i) t[i] = pg->triangles[i];
            }
        }
        /* The doubles stay: the filter re-tests Embree's candidates with them. */
        rtcSetGeometryUserData(geom, pg);
        rtcSetGeometryIntersectFilterFunction(geom, filter_double);
        rtcSetGeometryOccludedFilterFunction(geom, filter_double);
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(s->scene, geom, (unsigned)g);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(s->scene);
    s->device_error = NULL;
    s->committed = 1;
    if (build_err.status != CDL_OK) {
        if (err) *err = build_err;
        return build_err.status;
    }
    return CDL_OK;
}

double cdl_ray_scene_resolution(const cdl_ray_scene *s, cdl_vec3 p)
{
    return FLOAT_ULP * max2(max_abs3(cdl_vec3_sub(p, s->offset)), s->half_size);
}

/* The query in double, and the float ray Embree traces for it: the same
 * line, lengthened by the float margin at both ends. */
static void start_query(double_query *q, struct RTCRay *ray, const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir,
                        double t_near, double t_far)
{
    q->origin = origin;
    q->dir = dir;
    q->t_near = t_near;
    q->t_far = t_far;
    q->has_end = isfinite(t_far);
    q->end = q->has_end ? cdl_vec3_madd(origin, t_far, dir) : origin;
    q->best_t = INFINITY;
    q->best_geom = q->best_prim = RTC_INVALID_GEOMETRY_ID;
    q->exclude = CDL_RAY_EXCLUDE_NONE;
    double margin = FLOAT_MARGIN_ULPS * cdl_ray_scene_resolution(s, origin);
    if (q->has_end) margin = max2(margin, FLOAT_MARGIN_ULPS * cdl_ray_scene_resolution(s, q->end));
    double dir_len = cdl_vec3_length(dir);
    double back = dir_len > 0.0 ? margin / dir_len : 0.0; /* in units of |dir| */
    q->margin = margin;
    q->back = back;
    q->want_t = 0;
    double start = t_near - back;
    cdl_vec3 o = cdl_vec3_sub(cdl_vec3_madd(origin, start, dir), s->offset);
    ray->org_x = (float)o.x;
    ray->org_y = (float)o.y;
    ray->org_z = (float)o.z;
    ray->dir_x = (float)dir.x;
    ray->dir_y = (float)dir.y;
    ray->dir_z = (float)dir.z;
    ray->tnear = 0.0f;
    double far = t_far - start + back;
    ray->tfar = isfinite(far) && far < FLT_MAX ? (float)far : INFINITY;
    ray->time = 0.0f;
    ray->mask = 0xFFFFFFFFu;
    ray->id = 0;
    ray->flags = 0;
}

int cdl_ray_scene_occluded(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far)
{
    return cdl_ray_scene_occluded_except(s, origin, dir, t_near, t_far, CDL_RAY_EXCLUDE_NONE);
}

int cdl_ray_scene_occluded_except(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far,
                                  uint32_t exclude)
{
    if (!s->geometry_count || !(t_far > t_near)) return 0;
    double_query q;
    struct RTCRay ray;
    start_query(&q, &ray, s, origin, dir, t_near, t_far);
    q.exclude = exclude;
    query_context qc = {.queries = &q};
    rtcInitIntersectContext(&qc.context);
    rtcOccluded1(s->scene, &qc.context, &ray);
    return ray.tfar == -INFINITY;
}

/* Many shadow rays at once, as Embree ray streams (rtcOccluded1M) of
 * STREAM_BLOCK rays each. Measured on bench_direct's shadow rays (chunks of
 * 16 points towards one light after another; docs/tuning.md): streams of
 * 64-256 traced them 1.49-1.55 times as fast as single rays (16: 1.40),
 * where packets of 8 (rtcOccluded8) managed 1.11-1.13 and packets of 16
 * under 1; a stream flagged coherent 0.84. Each ray keeps its own double
 * re-test (its query found by its id, the filter above), so the answers
 * are those of the single-ray query, ray for ray, whatever Embree's order
 * inside the stream. A ray is inactive in a stream when tnear > tfar. */
#define STREAM_BLOCK 128

void cdl_ray_scene_occluded_many(const cdl_ray_scene *s, const cdl_ray_segment *rays, size_t count,
                                 unsigned char *occluded)
{
    double_query q[STREAM_BLOCK];
    struct RTCRay stream[STREAM_BLOCK];
    for (size_t start = 0; start < count; start += STREAM_BLOCK) {
        size_t block = count - start < STREAM_BLOCK ? count - start : STREAM_BLOCK;
        size_t live = 0;
        for (size_t k = 0; k < block; ++k) {
            const cdl_ray_segment *r = &rays[start + k];
            if (s->geometry_count && r->t_far > r->t_near) {
                start_query(&q[k], &stream[k], s, r->origin, r->dir, r->t_near, r->t_far);
                q[k].exclude = r->exclude;
                ++live;
            } else {
                memset(&stream[k], 0, sizeof stream[k]);
                stream[k].tfar = -1.0f; /* inactive */
            }
            stream[k].id = (unsigned)k;
        }
        if (live > 0) {
            query_context qc = {.queries = q};
            rtcInitIntersectContext(&qc.context); /* incoherent: measured faster here than coherent */
            rtcOccluded1M(s->scene, &qc.context, stream, (unsigned)block, sizeof stream[0]);
        }
        for (size_t k = 0; k < block; ++k) occluded[start + k] = stream[k].tfar == -INFINITY;
    }
}

int cdl_ray_scene_intersect(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far,
                            cdl_ray_hit *hit)
{
    return cdl_ray_scene_intersect_except(s, origin, dir, t_near, t_far, CDL_RAY_EXCLUDE_NONE, hit);
}

int cdl_ray_scene_intersect_except(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near,
                                   double t_far, uint32_t exclude, cdl_ray_hit *hit)
{
    if (!s->geometry_count || !(t_far > t_near)) return 0;
    double_query q;
    struct RTCRayHit rh;
    start_query(&q, &rh.ray, s, origin, dir, t_near, t_far);
    q.want_t = 1;
    q.exclude = exclude;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    query_context qc = {.queries = &q};
    rtcInitIntersectContext(&qc.context);
    rtcIntersect1(s->scene, &qc.context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || q.best_geom == RTC_INVALID_GEOMETRY_ID) return 0;
    /* The closest hit the double re-test accepted (Embree's float order
     * can only differ from it between hits closer than its rounding). */
    const pending_geometry *g = &s->geometry[q.best_geom];
    hit->t = q.best_t;
    hit->geom_id = q.best_geom;
    hit->prim_id = q.best_prim;
    cdl_vec3 h = cdl_vec3_madd(origin, q.best_t, dir);
    if (g->is_sphere) {
        hit->u = hit->v = 0.0;
        hit->normal = cdl_vec3_normalize(cdl_vec3_sub(h, vertex_of(g, 0)));
    } else {
        const uint32_t *tri = &g->triangles[3 * (size_t)q.best_prim];
        cdl_vec3 a = vertex_of(g, tri[0]), b = vertex_of(g, tri[1]), c = vertex_of(g, tri[2]);
        cdl_vec3 m = cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a));
        double m2 = cdl_vec3_dot(m, m);
        /* Embree's convention: h = (1 - u - v) a + u b + v c. */
        hit->u = cdl_vec3_dot(m, cdl_vec3_cross(cdl_vec3_sub(c, h), cdl_vec3_sub(a, h))) / m2;
        hit->v = cdl_vec3_dot(m, cdl_vec3_cross(cdl_vec3_sub(a, h), cdl_vec3_sub(b, h))) / m2;
        hit->normal = cdl_vec3_normalize(m);
    }
    return 1;
}

size_t cdl_ray_scene_triangle_count(const cdl_ray_scene *s)
{
    return s->triangle_count;
}

void cdl_ray_scene_release(cdl_ray_scene *s)
{
    if (!s) return;
    for (size_t g = 0; g < s->geometry_count; ++g) {
        free(s->geometry[g].xyz);
        free(s->geometry[g].triangles);
    }
    free(s->geometry);
    if (s->scene) rtcReleaseScene(s->scene);
    if (s->device) rtcReleaseDevice(s->device);
    free(s);
}
