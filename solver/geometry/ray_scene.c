/* ray_scene.c - Embree 3 scene of triangle meshes and exact spheres.
 *
 * Embree stores single-precision floats. To keep precision for scenes far
 * from the origin, geometry is kept in double until commit, then translated
 * so that the scene's bounding-box centre is the origin before conversion to
 * float; query origins are translated the same way (in double).
 */
#include "solver/geometry/ray_scene.h"

#include <embree3/rtcore.h>
#include "radiometry/bounds.h"
#include <float.h>
#include <math.h>
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

struct cdl_ray_scene {
    RTCDevice device;
    RTCScene scene;
    pending_geometry *geometry;
    size_t geometry_count, geometry_capacity;
    size_t triangle_count;
    cdl_vec3 offset;     /* world = local + offset */
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
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(s->scene, geom, (unsigned)g);
        rtcReleaseGeometry(geom);
        /* The doubles are no longer needed. */
        free(pg->xyz);
        free(pg->triangles);
        pg->xyz = NULL;
        pg->triangles = NULL;
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

static void fill_ray(struct RTCRay *ray, const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far)
{
    cdl_vec3 o = cdl_vec3_sub(origin, s->offset);
    ray->org_x = (float)o.x;
    ray->org_y = (float)o.y;
    ray->org_z = (float)o.z;
    ray->dir_x = (float)dir.x;
    ray->dir_y = (float)dir.y;
    ray->dir_z = (float)dir.z;
    ray->tnear = (float)t_near;
    ray->tfar = isfinite(t_far) && t_far < FLT_MAX ? (float)t_far : INFINITY;
    ray->time = 0.0f;
    ray->mask = 0xFFFFFFFFu;
    ray->id = 0;
    ray->flags = 0;
}

int cdl_ray_scene_occluded(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far)
{
    if (!s->geometry_count) return 0;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay ray;
    fill_ray(&ray, s, origin, dir, t_near, t_far);
    rtcOccluded1(s->scene, &ctx, &ray);
    return ray.tfar == -INFINITY;
}

int cdl_ray_scene_intersect(const cdl_ray_scene *s, cdl_vec3 origin, cdl_vec3 dir, double t_near, double t_far,
                            cdl_ray_hit *hit)
{
    if (!s->geometry_count) return 0;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRayHit rh;
    fill_ray(&rh.ray, s, origin, dir, t_near, t_far);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s->scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    hit->t = rh.ray.tfar;
    hit->geom_id = rh.hit.geomID;
    hit->prim_id = rh.hit.primID;
    hit->u = rh.hit.u;
    hit->v = rh.hit.v;
    hit->normal = cdl_vec3_normalize(cdl_vec3_make(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
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
