/* surface_view.h - the room in 3D: the report's axonometric false-colour
 * view of the surface maps.
 *
 * Two parallel (axonometric) views of the scene side by side, at one
 * scale: from above, looking down at 35 degrees across the room from its
 * -x -y side, and from below, looking up from its +x +y side. Each shows
 * the triangles that face it (a room's near walls, seen from behind, are
 * left out, so the view looks into the room; the floor and far walls in
 * the first, the ceiling and the other walls in the second), painted from
 * the farthest to the nearest. Mapped surfaces are Gouraud-shaded: each
 * triangle a cairo mesh-pattern patch whose corners carry their vertices'
 * false colours (a linear lux scale topped at 99 % of the area, lux_scale.h,
 * and the report's perceptually uniform palette, palette.h), so the colour
 * varies across it as the linear interpolant does;
 * unmapped surfaces are light grey, shaded by the angle they face the
 * viewer at; outlines of every surface are drawn thin and dark,
 * luminaires as yellow dots. A horizontal lux legend runs below.
 *
 * Drawn with cairo as a figure (graphics/figure.h) in points: on a PDF
 * page the patches are vector shading; cairo's SVG output rasterises them.
 * Ownership: the view borrows the meshes and luminaire positions (they
 * must outlive it) and owns its colours and orders; release frees them.
 * Errors: memory.
 */
#ifndef CANDELA_REPORT_SURFACE_VIEW_H
#define CANDELA_REPORT_SURFACE_VIEW_H

#include <stddef.h>
#include <stdint.h>

#include "graphics/figure.h"
#include "radiometry/vec3.h"
#include "solver/output/lux_scale.h"

typedef struct cdl_view_mesh {
    const char *name;
    const double *xyz;               /* vertex_count x 3, metres */
    size_t vertex_count;
    const uint32_t *triangles;       /* counter-clockwise seen from the front */
    size_t triangle_count;
    const double *E_lx;              /* vertex_count illuminances, or NULL (unmapped: grey) */
} cdl_view_mesh;

#define CDL_SURFACE_VIEW_PANELS 2

typedef struct cdl_view_triangle {
    uint32_t mesh, triangle;
} cdl_view_triangle;

typedef struct cdl_view_panel {
    cdl_vec3 towards;                /* unit, the direction the viewer looks */
    cdl_vec3 right, up;              /* the screen's axes in the world */
    double lo_right, hi_up;          /* the scene's leftmost and top screen coordinates, m */
    double x, y, w, h;               /* on the figure, points */
    cdl_view_triangle *order;        /* the triangles facing it, farthest first */
    size_t count;
    const char *caption;
} cdl_view_panel;

typedef struct cdl_surface_view {
    const cdl_view_mesh *meshes;
    size_t mesh_count;
    const cdl_vec3 *luminaires;
    size_t luminaire_count;
    cdl_lux_scale scale;
    uint8_t **rgb;                   /* per mesh: 3 per vertex, or NULL */
    uint32_t **outline;              /* per mesh: (a, b, triangle) per edge only one triangle has */
    size_t *outline_count;
    uint8_t legend_rgb[3 * 256];
    cdl_view_panel panel[CDL_SURFACE_VIEW_PANELS];
    double metres_to_points;
    double width, height;
    double legend_x, legend_y, legend_w;
    char title[96];
} cdl_surface_view;

/* Colour, project and order the meshes. */
cdl_status cdl_surface_view_prepare(cdl_surface_view *view, const cdl_view_mesh *meshes, size_t mesh_count,
                                    const cdl_vec3 *luminaires, size_t luminaire_count, cdl_error *err);
cdl_figure cdl_surface_view_figure(const cdl_surface_view *view);
void cdl_surface_view_release(cdl_surface_view *view);

/* Where a world point lands on the figure in a panel (points). */
void cdl_surface_view_project(const cdl_surface_view *view, int panel, cdl_vec3 p, double *x, double *y);

#endif
