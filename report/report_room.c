/* report_room.c - the room and its surfaces: dimensions, areas, reflectances (report_sections.h). */
#include "report/report_sections.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "radiometry/constants.h"

/* The area of a planar ring: half the length of the sum of its edges'
 * cross products (Newell's method; any orientation, any plane). */
static double ring_area(const cdl_ring3 *r)
{
    cdl_vec3 sum = {0.0, 0.0, 0.0};
    for (size_t k = 0; k < r->count; ++k) sum = cdl_vec3_add(sum, cdl_vec3_cross(r->points[k], r->points[(k + 1) % r->count]));
    return 0.5 * cdl_vec3_length(sum);
}

static double box_face_area(const cdl_surface_spec *s, int face)
{
    cdl_vec3 d = cdl_vec3_sub(s->box_max, s->box_min);
    double e[3] = {d.x, d.y, d.z};
    int axis = face / 2;
    return e[(axis + 1) % 3] * e[(axis + 2) % 3];
}

/* A surface's area (m^2): a box's closed faces, a mesh's triangles. */
static double surface_area(const cdl_surface_spec *s)
{
    double area = 0.0;
    switch (s->kind) {
    case CDL_SURFACE_RECT: return cdl_vec3_length(cdl_vec3_cross(s->u, s->v));
    case CDL_SURFACE_POLYGON:
        area = ring_area(&s->outer);
        for (size_t h = 0; h < s->hole_count; ++h) area -= ring_area(&s->holes[h]);
        return area;
    case CDL_SURFACE_BOX:
        for (int f = 0; f < CDL_BOX_FACES; ++f) area += s->face_open[f] ? 0.0 : box_face_area(s, f);
        return area;
    case CDL_SURFACE_DISK: return CDL_PI * s->radius * s->radius;
    case CDL_SURFACE_SPHERE: return 4.0 * CDL_PI * s->radius * s->radius;
    case CDL_SURFACE_MESH:
        for (size_t t = 0; t < s->mesh_triangle_count; ++t) {
            cdl_vec3 c[3];
            for (int k = 0; k < 3; ++k) {
                const double *v = s->mesh_vertices + 3 * (size_t)s->mesh_triangles[3 * t + (size_t)k];
                c[k] = cdl_vec3_make(v[0], v[1], v[2]);
            }
            area += 0.5 * cdl_vec3_length(cdl_vec3_cross(cdl_vec3_sub(c[1], c[0]), cdl_vec3_sub(c[2], c[0])));
        }
        return area;
    }
    return 0.0;
}

static const char *const face_names[CDL_BOX_FACES] = {"-x", "+x", "-y", "+y", "-z", "+z"};

/* A box's reflectances: one number when its closed faces agree; "floor,
 * walls, ceiling" for a room whose walls agree; else face by face. */
static void box_reflectance(const cdl_surface_spec *s, char *out, size_t size)
{
    const double *r = s->face_reflectance;
    int all_same = 1, walls_same = 1;
    double first = -1.0, wall = -1.0;
    for (int f = 0; f < CDL_BOX_FACES; ++f) {
        if (s->face_open[f]) continue;
        if (first < 0.0) first = r[f];
        all_same &= r[f] == first;
        if (f < CDL_BOX_NEG_Z) {
            if (wall < 0.0) wall = r[f];
            walls_same &= r[f] == wall;
        }
    }
    if (all_same) {
        snprintf(out, size, "%.3g", first);
        return;
    }
    size_t used = 0;
    out[0] = '\0';
    if (walls_same && s->inward) {
        if (!s->face_open[CDL_BOX_NEG_Z]) used += (size_t)snprintf(out + used, size - used, "floor %.3g", r[CDL_BOX_NEG_Z]);
        if (wall >= 0.0 && used < size)
            used += (size_t)snprintf(out + used, size - used, "%swalls %.3g", used ? ", " : "", wall);
        if (!s->face_open[CDL_BOX_POS_Z] && used < size)
            snprintf(out + used, size - used, "%sceiling %.3g", used ? ", " : "", r[CDL_BOX_POS_Z]);
        return;
    }
    for (int f = 0; f < CDL_BOX_FACES && used < size; ++f)
        if (!s->face_open[f])
            used += (size_t)snprintf(out + used, size - used, "%s%s %.3g", used ? ", " : "", face_names[f], r[f]);
}

static void dimensions(const cdl_surface_spec *s, char *out, size_t size)
{
    cdl_vec3 d = cdl_vec3_sub(s->box_max, s->box_min);
    switch (s->kind) {
    case CDL_SURFACE_RECT:
        snprintf(out, size, "rectangle %.4g x %.4g m", cdl_vec3_length(s->u), cdl_vec3_length(s->v));
        break;
    case CDL_SURFACE_POLYGON:
        snprintf(out, size, "polygon of %zu vertices%s", s->outer.count, s->hole_count ? ", with holes" : "");
        break;
    case CDL_SURFACE_BOX: snprintf(out, size, "box %.4g x %.4g x %.4g m (x, y, z)", d.x, d.y, d.z); break;
    case CDL_SURFACE_DISK: snprintf(out, size, "disk, radius %.4g m", s->radius); break;
    case CDL_SURFACE_SPHERE: snprintf(out, size, "sphere, radius %.4g m", s->radius); break;
    case CDL_SURFACE_MESH:
        snprintf(out, size, "mesh of %zu triangles%s%s", s->mesh_triangle_count, s->file ? ", " : "",
                 s->file ? cdl_report_file_name(s->file) : "");
        break;
    }
}

/* Open faces, emission, one-sidedness, the side that faces in. */
static void notes(const cdl_surface_spec *s, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    if (s->kind == CDL_SURFACE_BOX) {
        int open = 0;
        for (int f = 0; f < CDL_BOX_FACES; ++f) open |= s->face_open[f];
        if (s->inward) used += (size_t)snprintf(out + used, size - used, "a room (faces inward)");
        for (int f = 0; f < CDL_BOX_FACES && open && used < size; ++f)
            if (s->face_open[f])
                used += (size_t)snprintf(out + used, size - used, "%s%s open", used ? "; " : "", face_names[f]);
    }
    if (s->luminance_cd_m2 > 0.0 && used < size)
        used += (size_t)snprintf(out + used, size - used, "%semits %.4g cd/m2", used ? "; " : "", s->luminance_cd_m2);
    if (!s->two_sided && used < size) snprintf(out + used, size - used, "%sone-sided", used ? "; " : "");
}

/* The first inward box: the room, in a sentence. */
static void room_sentence(cdl_report_builder *b, const cdl_scene *scene)
{
    for (size_t k = 0; k < scene->surface_count; ++k) {
        const cdl_surface_spec *s = &scene->surfaces[k];
        if (s->kind != CDL_SURFACE_BOX || !s->inward) continue;
        cdl_vec3 d = cdl_vec3_sub(s->box_max, s->box_min);
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                        "The room (%s%s%s): %.4g m x %.4g m, %.4g m high; floor area %.4g m2, volume %.4g m3.",
                        s->json_path, s->name ? " " : "", s->name ? s->name : "", d.x, d.y, d.z, d.x * d.y,
                        d.x * d.y * d.z);
        return;
    }
}

void cdl_report_room_section(cdl_report_builder *b, const cdl_report_input *in)
{
    const cdl_scene *scene = in->scene;
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Room and surfaces");
    if (scene->surface_count == 0) {
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "The scene has no surfaces: nothing blocks or reflects light.");
        return;
    }
    room_sentence(b, scene);
    cdl_report_block *t = cdl_report_table(b, 5, scene->surface_count + 1, 1);
    static const char *const headings[5] = {"surface", "shape and dimensions", "area (m2)", "reflectance", "notes"};
    for (size_t c = 0; c < 5; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    for (size_t k = 0; k < scene->surface_count; ++k) {
        const cdl_surface_spec *s = &scene->surfaces[k];
        char text[256];
        cdl_report_cell(b, t, k + 1, 0, "%s%s%s", s->json_path, s->name ? " " : "", s->name ? s->name : "");
        dimensions(s, text, sizeof text);
        cdl_report_cell(b, t, k + 1, 1, "%s", text);
        cdl_report_cell(b, t, k + 1, 2, "%.4g", surface_area(s));
        if (s->kind == CDL_SURFACE_BOX) box_reflectance(s, text, sizeof text);
        else snprintf(text, sizeof text, "%.3g", s->reflectance);
        cdl_report_cell(b, t, k + 1, 3, "%s", text);
        notes(s, text, sizeof text);
        cdl_report_cell(b, t, k + 1, 4, "%s", text[0] ? text : "-");
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Reflectances are diffuse (Lambertian), as the scene gives them; a box's area counts its closed "
                    "faces. The maintenance factor of each luminaire is in the luminaire list.");
}
