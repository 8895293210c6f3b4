/* surface_output.c - surface maps' CSVs, statistics and scene.glb (surface_output.h). */
#include "solver/output/surface_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "radiometry/bounds.h"
#include "solver/output/false_colour.h"
#include "solver/output/gltf_output.h"
#include "solver/output/grid_result.h"
#include "solver/output/lux_scale.h"
#include "base/error_report.h"

/* ---- statistics ------------------------------------------------------------------- */

static double triangle_area(const double *xyz, const uint32_t *t)
{
    const double *a = &xyz[3 * t[0]], *b = &xyz[3 * t[1]], *c = &xyz[3 * t[2]];
    cdl_vec3 u = cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    cdl_vec3 v = cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    return 0.5 * cdl_vec3_length(cdl_vec3_cross(u, v));
}

void cdl_surface_solution_stats(const cdl_surface_solution *m, cdl_surface_stats *s)
{
    memset(s, 0, sizeof *s);
    s->vertices = m->vertex_count;
    s->triangles = m->triangle_count;
    double area = 0.0, E = 0.0, L = 0.0;
    for (size_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *v = &m->triangles[3 * t];
        double a = triangle_area(m->xyz, v);
        area += a;
        /* The mean of a linear function over a triangle is the mean of its corners. */
        E += a * (m->E[v[0]] + m->E[v[1]] + m->E[v[2]]) / 3.0;
        L += a * (m->L[v[0]] + m->L[v[1]] + m->L[v[2]]) / 3.0;
    }
    s->area_m2 = area;
    s->Em_lx = area > 0.0 ? E / area : 0.0;
    s->L_mean_cd_m2 = area > 0.0 ? L / area : 0.0;
    /* Relative to E, or to half of Em where E is below it: the map's own
     * tolerance (integrate_surfaces.c), so a vertex in a shadow at 1e-9 lx
     * does not make the mean relative error infinite. */
    double rel = 0.0, floor = 0.5 * s->Em_lx;
    for (size_t t = 0; floor > 0.0 && t < m->triangle_count; ++t) {
        const uint32_t *v = &m->triangles[3 * t];
        double a = triangle_area(m->xyz, v);
        for (int k = 0; k < 3; ++k) rel += a / 3.0 * m->E_stderr[v[k]] / fmax(m->E[v[k]], floor);
    }
    s->stderr_mean_rel = area > 0.0 && floor > 0.0 ? rel / area : 0.0;
    s->Emin_lx = m->vertex_count ? INFINITY : 0.0;
    s->Emax_lx = 0.0;
    for (size_t v = 0; v < m->vertex_count; ++v) {
        s->Emin_lx = fmin(s->Emin_lx, m->E[v]);
        s->Emax_lx = fmax(s->Emax_lx, m->E[v]);
    }
    s->U0 = s->Em_lx > 0.0 ? s->Emin_lx / s->Em_lx : 0.0;
}

void cdl_mesh_vertex_areas(const double *xyz, size_t vertex_count, const uint32_t *triangles, size_t triangle_count,
                           double *area)
{
    memset(area, 0, vertex_count * sizeof *area);
    for (size_t t = 0; t < triangle_count; ++t) {
        double a = triangle_area(xyz, &triangles[3 * t]) / 3.0;
        for (int k = 0; k < 3; ++k) area[triangles[3 * t + k]] += a;
    }
}

/* ---- CSV ---------------------------------------------------------------------------- */

static char *join(const char *folder, const char *name, const char *ext)
{
    size_t n = strlen(folder) + strlen(name) + strlen(ext) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s%s", folder, name, ext);
    return p;
}

static cdl_status check_finite(const cdl_surface_solution *m, const char *path, cdl_error *err)
{
    for (size_t v = 0; v < m->vertex_count; ++v) {
        double row[11] = {m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2], m->normal[3 * v], m->normal[3 * v + 1],
                          m->normal[3 * v + 2], m->E[v], m->E_direct[v], m->E_indirect[v], m->E_stderr[v], m->L[v]};
        for (int k = 0; k < 11; ++k)
            if (!isfinite(row[k]))
                return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: vertex %zu, column %d is not a number", path, v, k + 1);
    }
    return CDL_OK;
}

cdl_status cdl_surface_write_csv(const cdl_surface_solution *m, const char *folder, const char *name, cdl_error *err)
{
    char *csv = join(folder, name, ".csv"), *tri = join(folder, name, ".tri.csv");
    cdl_status st = csv && tri ? check_finite(m, csv, err) : cdl_error_out_of_memory(err);
    cdl_atomic_file f = {0};
    if (st == CDL_OK) st = cdl_atomic_file_open(&f, csv, err);
    if (st == CDL_OK) {
        fputs("x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,L_cd_m2\n", f.fp);
        for (size_t v = 0; v < m->vertex_count; ++v) {
            double row[11] = {m->xyz[3 * v],    m->xyz[3 * v + 1],    m->xyz[3 * v + 2], m->normal[3 * v],
                              m->normal[3 * v + 1], m->normal[3 * v + 2], m->E[v],         m->E_direct[v],
                              m->E_indirect[v],  m->E_stderr[v],       m->L[v]};
            cdl_csv_write_numbers(f.fp, row, 11);
        }
        st = cdl_atomic_file_commit(&f, err);
    }
    if (st == CDL_OK) st = cdl_atomic_file_open(&f, tri, err);
    if (st == CDL_OK) {
        fputs("a,b,c\n", f.fp);
        for (size_t t = 0; t < m->triangle_count; ++t)
            fprintf(f.fp, "%u,%u,%u\n", m->triangles[3 * t], m->triangles[3 * t + 1], m->triangles[3 * t + 2]);
        st = cdl_atomic_file_commit(&f, err);
    }
    free(csv);
    free(tri);
    return st;
}

/* ---- scene.glb -------------------------------------------------------------------------- */

/* Where a luminaire is drawn: its position, an area luminaire's shape's
 * centre; 0 for those with no place (directional light, skies). */
static int luminaire_place(const cdl_luminaire_spec *l, cdl_vec3 *at)
{
    switch (l->kind) {
    case CDL_LUMINAIRE_POINT:
    case CDL_LUMINAIRE_SPOT:
    case CDL_LUMINAIRE_GONIOMETRIC: *at = l->position; return 1;
    case CDL_LUMINAIRE_AREA: {
        const cdl_surface_spec *s = &l->shape;
        if (s->kind == CDL_SURFACE_RECT) {
            *at = cdl_vec3_madd(cdl_vec3_madd(s->origin, 0.5, s->u), 0.5, s->v);
        } else if (s->kind == CDL_SURFACE_DISK) {
            *at = s->center;
        } else {
            cdl_bounds3 b = cdl_bounds3_empty();
            for (size_t i = 0; i < s->outer.count; ++i) cdl_bounds3_grow(&b, s->outer.points[i]);
            for (size_t i = 0; i < s->mesh_vertex_count; ++i)
                cdl_bounds3_grow(&b, cdl_vec3_make(s->mesh_vertices[3 * i], s->mesh_vertices[3 * i + 1],
                                                   s->mesh_vertices[3 * i + 2]));
            *at = cdl_bounds3_centre(b);
        }
        return 1;
    }
    default: return 0;
    }
}

/* The false colours of every map's vertices on one linear lux scale. */
static cdl_status colours(const cdl_solution *sol, const char *ocio_config, uint8_t **rgb, cdl_error *err)
{
    size_t n = 0;
    for (size_t k = 0; k < sol->surface_count; ++k) n += sol->surfaces[k].vertex_count;
    double *E = malloc((n + 1) * sizeof *E), *t = malloc((n + 1) * sizeof *t), *area = malloc((n + 1) * sizeof *area);
    *rgb = malloc(3 * n + 3);
    cdl_status st = E && t && area && *rgb ? CDL_OK : cdl_error_out_of_memory(err);
    size_t i = 0;
    for (size_t k = 0; st == CDL_OK && k < sol->surface_count; ++k) {
        const cdl_surface_solution *s = &sol->surfaces[k];
        cdl_mesh_vertex_areas(s->xyz, s->vertex_count, s->triangles, s->triangle_count, area + i);
        for (size_t v = 0; v < s->vertex_count; ++v) E[i++] = s->E[v];
    }
    cdl_lux_scale scale = cdl_lux_scale_linear_for_areas(E, area, st == CDL_OK ? n : 0);
    for (size_t j = 0; st == CDL_OK && j < n; ++j) t[j] = cdl_lux_scale_position(&scale, cdl_lux(E[j]));
    cdl_display_transform *view = NULL;
    if (st == CDL_OK) st = cdl_display_transform_open(ocio_config, "linear", "sRGB", "False colour", &view, err);
    if (st == CDL_OK) st = cdl_false_colour_rgb8(view, t, n, *rgb, err);
    cdl_display_transform_release(view);
    free(E);
    free(t);
    free(area);
    return st;
}

cdl_status cdl_surface_write_glb(const cdl_scene *scene, const cdl_solution *sol, const char *path,
                                 const char *ocio_config, cdl_error *err)
{
    size_t meshes = sol->surface_count + sol->shape_count;
    cdl_gltf_mesh *m = calloc(meshes + 1, sizeof *m);
    cdl_gltf_marker *marks = calloc(scene->luminaire_count + 1, sizeof *marks);
    char (*labels)[96] = calloc(scene->luminaire_count + 1, sizeof *labels);
    uint8_t *rgb = NULL;
    cdl_status st = m && marks && labels ? colours(sol, ocio_config, &rgb, err) : cdl_error_out_of_memory(err);
    cdl_bounds3 box = cdl_bounds3_empty();
    size_t at = 0;
    for (size_t k = 0; st == CDL_OK && k < sol->surface_count; ++k) {
        const cdl_surface_solution *s = &sol->surfaces[k];
        m[k] = (cdl_gltf_mesh){scene->surfaces[s->surface].map_name, s->xyz, s->normal, s->vertex_count,
                               s->triangles, s->triangle_count, rgb + 3 * at, s->E};
        at += s->vertex_count;
        for (size_t v = 0; v < s->vertex_count; ++v)
            cdl_bounds3_grow(&box, cdl_vec3_make(s->xyz[3 * v], s->xyz[3 * v + 1], s->xyz[3 * v + 2]));
    }
    for (size_t k = 0; st == CDL_OK && k < sol->shape_count; ++k) {
        const cdl_surface_shape *s = &sol->shapes[k];
        const cdl_surface_spec *spec = &scene->surfaces[s->surface];
        m[sol->surface_count + k] = (cdl_gltf_mesh){spec->name ? spec->name : spec->json_path, s->xyz, s->normal,
                                                    s->vertex_count, s->triangles, s->triangle_count, NULL, NULL};
    }
    size_t n_marks = 0;
    for (size_t l = 0; st == CDL_OK && l < scene->luminaire_count; ++l) {
        if (!luminaire_place(&scene->luminaires[l], &marks[n_marks].position)) continue;
        cdl_luminaire_spec_label(&scene->luminaires[l], labels[n_marks], sizeof labels[n_marks]);
        marks[n_marks].name = labels[n_marks];
        ++n_marks;
    }
    /* Markers 2 % of the mapped surfaces' extent, within 3 and 30 cm. */
    double size = cdl_bounds3_is_empty(box) ? 0.1 : fmin(0.3, fmax(0.03, 0.02 * cdl_bounds3_diagonal(box)));
    cdl_gltf_scene glb = {m, meshes, marks, n_marks, size, "Candela " CANDELA_VERSION};
    if (st == CDL_OK) st = cdl_gltf_write(path, &glb, err);
    free(m);
    free(marks);
    free(labels);
    free(rgb);
    return st;
}
