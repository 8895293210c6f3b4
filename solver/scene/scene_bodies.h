/* scene_bodies.h - luminaire bodies placed in the scene, as triangles or a sphere.
 *
 * A goniometric luminaire whose file gives a luminous opening has a body
 * (lights/photometry/luminaire_body.h) unless its entry says "body":
 * false. It is placed as the luminaire is (world_from_luminaire = Rz Ry Rx
 * of its rotation, then its position; each copy of an array its own) and
 * becomes one geometry piece (scene_geometry.c): it blocks the light of
 * every other emitter and of the interreflection, and reflects with
 * "body": {"reflectance": R} (default CDL_BODY_HOUSING_REFLECTANCE for a
 * housing the file sizes, 0 for an opening alone). Its own luminaire's
 * light passes it: every shadow ray and occluder test for a light leaves
 * out the light's own body (scene_lights.h, cdl_scene_light_own_piece), so
 * the luminaire's flux and distribution are the file's.
 *
 * Triangles: boxes as their 12 (a flat rectangle's 2), counter-clockwise
 * seen from outside (a flat body's front: the side away from its opening);
 * cylinders, disks and ellipses with CDL_DISK_SEGMENTS sides as disks are
 * (sagitta below 1e-4 of the radius); ellipsoids as CDL_BODY_SLICES x
 * CDL_BODY_SLICES / 2 quads; a sphere stays an exact sphere. Curved
 * bodies are marked so that the exact routes send them to sampling.
 */
#ifndef CANDELA_SOLVER_SCENE_BODIES_H
#define CANDELA_SOLVER_SCENE_BODIES_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "lights/photometry/luminaire_body.h"
#include "solver/scene/scene_internal.h"

/* A housing's reflectance where the scene gives none (a painted or
 * anodised metal luminaire, mid-grey). */
#define CDL_BODY_HOUSING_REFLECTANCE 0.5

/* Segments around an ellipsoid (its stacks are half as many): sagitta
 * r (1 - cos(pi / 96)) = 5.4e-4 r. */
#define CDL_BODY_SLICES 96

/* A body in world space: a triangle mesh (counter-clockwise seen from its
 * front, outward) or an exact sphere. */
typedef struct cdl_body_mesh {
    int is_sphere;
    cdl_vec3 center;             /* sphere */
    double radius;
    double *xyz;                 /* vertex_count x 3, owned (free) */
    size_t vertex_count;
    uint32_t *triangles;         /* triangle_count x 3, owned (free) */
    size_t triangle_count;
    int curved;                  /* 1: a cylinder, disk, ellipse or ellipsoid (sampled, never exact) */
} cdl_body_mesh;

/* The body of luminaire k of the scene: *body (kind CDL_BODY_NONE when it
 * has none: not goniometric, "body": false, or no opening) and its
 * reflectance. `cache` carries the last entry's body between calls, so
 * that the copies of one entry read its file once: zero it before the
 * first call. Errors (a file that cannot be read) carry the scene file and
 * the entry's JSON path. */
typedef struct cdl_body_cache {
    size_t entry;
    int valid;
    cdl_luminaire_body body;
} cdl_body_cache;

cdl_status cdl_scene_body_of(const cdl_scene *scene, size_t k, cdl_body_cache *cache, cdl_luminaire_body *body,
                             double *reflectance, cdl_error *err);

/* The body placed at position, turned by rotation_deg (as a goniometric
 * luminaire, lights/emitters/emitter.h), as a mesh or sphere. */
cdl_status cdl_scene_body_mesh(const cdl_luminaire_body *body, cdl_vec3 position, const double rotation_deg[3],
                               cdl_body_mesh *out, cdl_error *err);

void cdl_body_mesh_release(cdl_body_mesh *mesh);

#endif
