/* scene_hash.c - the scene's geometry, materials and lights, hashed. */
#include "solver/scene/scene_hash.h"

#include <string.h>

#include "base/content_hash.h"
#include "base/error_report.h"
#include "lights/photometry/photometry_metadata.h"

static void hash_ring(cdl_content_hash *h, const cdl_ring3 *ring)
{
    cdl_content_hash_u64(h, (uint64_t)ring->count);
    for (size_t i = 0; i < ring->count; ++i) cdl_content_hash_vec3(h, ring->points[i]);
}

/* A surface's shape: every shape field, whatever its kind (the loader
 * zeroes the fields a kind does not use). */
static void hash_shape(cdl_content_hash *h, const cdl_surface_spec *s)
{
    cdl_content_hash_u64(h, (uint64_t)s->kind);
    cdl_content_hash_vec3(h, s->origin);
    cdl_content_hash_vec3(h, s->u);
    cdl_content_hash_vec3(h, s->v);
    hash_ring(h, &s->outer);
    cdl_content_hash_u64(h, (uint64_t)s->hole_count);
    for (size_t k = 0; k < s->hole_count; ++k) hash_ring(h, &s->holes[k]);
    cdl_content_hash_vec3(h, s->box_min);
    cdl_content_hash_vec3(h, s->box_max);
    cdl_content_hash_u64(h, (uint64_t)s->inward);
    for (int f = 0; f < CDL_BOX_FACES; ++f) cdl_content_hash_u64(h, (uint64_t)s->face_open[f]);
    cdl_content_hash_vec3(h, s->center);
    cdl_content_hash_vec3(h, s->normal);
    cdl_content_hash_f64(h, s->radius);
    cdl_content_hash_u64(h, (uint64_t)s->mesh_vertex_count);
    for (size_t i = 0; i < 3 * s->mesh_vertex_count; ++i) cdl_content_hash_f64(h, s->mesh_vertices[i]);
    cdl_content_hash_u64(h, (uint64_t)s->mesh_triangle_count);
    for (size_t i = 0; i < 3 * s->mesh_triangle_count; ++i) cdl_content_hash_u64(h, s->mesh_triangles[i]);
}

static void hash_material(cdl_content_hash *h, const cdl_surface_spec *s)
{
    cdl_content_hash_f64(h, s->reflectance);
    for (int f = 0; f < CDL_BOX_FACES; ++f) cdl_content_hash_f64(h, s->face_reflectance[f]);
    cdl_content_hash_u64(h, (uint64_t)s->two_sided);
    cdl_content_hash_f64(h, s->transmittance);
}

/* The bytes of a file, with their count. */
static cdl_status hash_file(cdl_content_hash *h, const char *path, const cdl_scene *scene, const char *json_path,
                            cdl_error *err)
{
    int code = cdl_content_hash_file(h, path);
    if (code != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %s.file: %s: cannot read it to hash its content: %s",
                             scene->path, json_path, path, strerror(code));
    return CDL_OK;
}

/* A daylight sky's inputs: its sun and what scales it (the site and time
 * are in the sun's direction). */
static void hash_daylight(cdl_content_hash *h, const cdl_daylight_spec *d)
{
    cdl_content_hash_vec3(h, d->sun);
    cdl_content_hash_u64(h, (uint64_t)d->cie_type);
    cdl_content_hash_u64(h, (uint64_t)d->scale_to_horizontal);
    cdl_content_hash_u64(h, (uint64_t)d->radiometric);
    cdl_content_hash_f64(h, d->diffuse_horizontal);
    cdl_content_hash_f64(h, d->direct_normal);
    cdl_content_hash_f64(h, d->dew_point_c);
    cdl_content_hash_u64(h, (uint64_t)d->day_of_year);
}

static cdl_status hash_luminaire(cdl_content_hash *h, const cdl_scene *scene, const cdl_luminaire_spec *l,
                                 cdl_error *err)
{
    cdl_content_hash_u64(h, (uint64_t)l->kind);
    cdl_content_hash_vec3(h, l->position);
    cdl_content_hash_vec3(h, l->direction);
    cdl_content_hash_u64(h, (uint64_t)l->has_intensity);
    cdl_content_hash_u64(h, (uint64_t)l->has_flux);
    cdl_content_hash_f64(h, l->intensity_cd);
    cdl_content_hash_f64(h, l->flux_lm);
    cdl_content_hash_u64(h, (uint64_t)l->has_exponent);
    cdl_content_hash_f64(h, l->exponent);
    cdl_content_hash_f64(h, l->half_angle_deg);
    cdl_content_hash_f64(h, l->falloff_start_deg);
    for (int k = 0; k < 3; ++k) cdl_content_hash_f64(h, l->rotation_deg[k]);
    cdl_content_hash_f64(h, l->multiplier);
    cdl_content_hash_u64(h, (uint64_t)l->near_field);
    cdl_content_hash_u64(h, (uint64_t)l->body);
    cdl_content_hash_u64(h, (uint64_t)l->has_body_reflectance);
    cdl_content_hash_f64(h, l->body_reflectance);
    cdl_content_hash_f64(h, l->maintenance_factor);
    hash_shape(h, &l->shape);
    cdl_content_hash_u64(h, (uint64_t)l->has_luminance);
    cdl_content_hash_f64(h, l->luminance_cd_m2);
    cdl_content_hash_f64(h, l->illuminance_lx);
    cdl_content_hash_f64(h, l->scale);
    cdl_content_hash_vec3(h, l->up);
    cdl_content_hash_u64(h, (uint64_t)l->upper_hemisphere_only);
    cdl_content_hash_u64(h, (uint64_t)l->sky);
    cdl_content_hash_f64(h, l->angular_diameter_deg);
    hash_daylight(h, &l->daylight);
    cdl_content_hash_u64(h, l->file != NULL);
    return l->file ? hash_file(h, l->file, scene, l->json_path, err) : CDL_OK;
}

cdl_status cdl_scene_hash(const cdl_scene *scene, const cdl_scene_lights *lights, cdl_scene_hashes *out,
                          cdl_error *err)
{
    cdl_content_hash geometry = CDL_CONTENT_HASH_INIT, materials = CDL_CONTENT_HASH_INIT,
                     light = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&geometry, (uint64_t)scene->surface_count);
    cdl_content_hash_u64(&materials, (uint64_t)(scene->surface_count + scene->luminaire_count));
    cdl_content_hash_u64(&light, (uint64_t)scene->luminaire_count);
    for (size_t i = 0; i < scene->surface_count; ++i) {
        const cdl_surface_spec *s = &scene->surfaces[i];
        hash_shape(&geometry, s);
        hash_material(&materials, s);
        cdl_content_hash_f64(&light, s->luminance_cd_m2);
    }
    for (size_t i = 0; i < scene->luminaire_count; ++i) {
        const cdl_luminaire_spec *l = &scene->luminaires[i];
        cdl_content_hash_f64(&materials, l->reflectance);
        cdl_status st = hash_luminaire(&light, scene, l, err);
        if (st != CDL_OK) return st;
    }
    /* A photometric file's TILT=<file> table is not in its bytes: hash the
     * table each photometry holds, whatever its source. */
    cdl_content_hash_u64(&light, (uint64_t)lights->photometry_count);
    for (size_t i = 0; i < lights->photometry_count; ++i) {
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(lights->photometries[i]);
        cdl_content_hash_u64(&light, (uint64_t)m->tilt_kind);
        cdl_content_hash_u64(&light, (uint64_t)m->tilt_geometry);
        cdl_content_hash_u64(&light, (uint64_t)m->tilt_count);
        for (size_t k = 0; k < m->tilt_count; ++k) {
            cdl_content_hash_f64(&light, m->tilt_angles_deg[k]);
            cdl_content_hash_f64(&light, m->tilt_factors[k]);
        }
    }
    out->geometry = geometry.value;
    out->materials = materials.value;
    out->lights = light.value;
    return CDL_OK;
}
