/* grid.c - calculation points of rect, polygon and points grids (grid.h).
 *
 * Where a polygon grid's points lie: the polygon minus its holes is meshed
 * by CGAL's Delaunay refinement into triangles whose edges are at most the
 * spacing p and whose angles are at least about 20.6 degrees; each
 * triangle contributes one point, its centroid, weighted by its area. The
 * weights therefore add up to the polygon's area exactly (up to rounding),
 * averages are area-weighted integrals of the piecewise-constant field, and
 * no point is farther than p from its neighbours. Points never lie on the
 * boundary (a centroid is inside its triangle), so a grid drawn on a floor
 * between walls never sits in a wall.
 */
#include "solver/grid/grid.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "solver/geometry/polygon.h"

/* A polygon grid's raster has at most this many pixels along a side; the
 * pixel grows beyond p/4 when needed. */
#define RASTER_MAX_SIDE 4096
/* Points per p^2 of area the mesh makes (grid.h: CDL_GRID_MESH_EDGE), to
 * refuse a spacing that would take minutes before meshing. */
#define POINTS_PER_SQUARE_SPACING 1.0

/* EN 12464-1:2021, 4.3.3 (from EN 12464-1:2011, 4.4): maximum grid cell
 * size p = 0.2 x 5^log10(d), d the longer dimension of the calculation
 * area in metres; the standard also bounds p by 10 m. */
double cdl_grid_auto_spacing(double longest_dimension_m)
{
    if (!(longest_dimension_m > 0.0)) return 0.0;
    double p = 0.2 * pow(5.0, log10(longest_dimension_m));
    return fmin(p, 10.0);
}

static cdl_status alloc_points(cdl_grid *g, size_t n)
{
    g->count = n;
    g->points = malloc(n * sizeof *g->points);
    g->normals = malloc(n * sizeof *g->normals);
    g->weights = malloc(n * sizeof *g->weights);
    return g->points && g->normals && g->weights ? CDL_OK : CDL_ERR_INTERNAL;
}

static cdl_status build_rect(const cdl_grid_spec *spec, cdl_grid *g, cdl_error *err)
{
    size_t nu = (size_t)spec->nu, nv = (size_t)spec->nv;
    cdl_vec3 uxv = cdl_vec3_cross(spec->u, spec->v);
    cdl_vec3 n = cdl_vec3_normalize(spec->has_normal ? spec->normal : uxv);
    double cell_area = cdl_vec3_length(uxv) / (double)(nu * nv);
    if (alloc_points(g, nu * nv) != CDL_OK) return cdl_error_out_of_memory(err);
    g->raster_index = malloc(nu * nv * sizeof *g->raster_index);
    if (!g->raster_index) return cdl_error_out_of_memory(err);
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            /* Cell centres (DESIGN.md): origin + (i+0.5)/nu u + (j+0.5)/nv v. */
            size_t k = j * nu + i;
            g->points[k] = cdl_vec3_add(spec->origin, cdl_vec3_add(cdl_vec3_scale(spec->u, (i + 0.5) / (double)nu),
                                                                   cdl_vec3_scale(spec->v, (j + 0.5) / (double)nv)));
            g->normals[k] = n;
            g->weights[k] = cell_area;
            /* Row 0 of the image is the v = 1 edge. */
            g->raster_index[(nv - 1 - j) * nu + i] = (int32_t)k;
        }
    g->raster_width = spec->nu;
    g->raster_height = spec->nv;
    g->spacing_m = cdl_vec3_length(spec->u) / (double)nu;
    g->pixel_size_m = g->spacing_m;
    g->raster_corner = spec->origin;
    g->raster_right = cdl_vec3_normalize(spec->u);
    g->raster_up = cdl_vec3_normalize(spec->v);
    g->pixel_width_m = g->spacing_m;
    g->pixel_height_m = cdl_vec3_length(spec->v) / (double)nv;
    return CDL_OK;
}

/* Paint the pixels whose centres lie in triangle abc (counter-clockwise)
 * with `index`. Pixel (c, r) has its centre at (x0 + (c + 0.5) s, y1 - (r + 0.5) s). */
static void raster_triangle(cdl_grid *g, double x0, double y1, double s, const double *a, const double *b,
                            const double *c, int32_t index)
{
    double lo_x = fmin(a[0], fmin(b[0], c[0])), hi_x = fmax(a[0], fmax(b[0], c[0]));
    double lo_y = fmin(a[1], fmin(b[1], c[1])), hi_y = fmax(a[1], fmax(b[1], c[1]));
    long c0 = (long)floor((lo_x - x0) / s - 0.5), c1 = (long)ceil((hi_x - x0) / s - 0.5);
    long r0 = (long)floor((y1 - hi_y) / s - 0.5), r1 = (long)ceil((y1 - lo_y) / s - 0.5);
    if (c0 < 0) c0 = 0;
    if (r0 < 0) r0 = 0;
    if (c1 > g->raster_width - 1) c1 = g->raster_width - 1;
    if (r1 > g->raster_height - 1) r1 = g->raster_height - 1;
    const double *v[3] = {a, b, c};
    for (long r = r0; r <= r1; ++r)
        for (long col = c0; col <= c1; ++col) {
            double px = x0 + (col + 0.5) * s, py = y1 - (r + 0.5) * s;
            int inside = 1;
            for (int k = 0; k < 3 && inside; ++k) {
                const double *p = v[k], *q = v[(k + 1) % 3];
                inside = (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0]) >= 0.0;
            }
            if (inside) g->raster_index[(size_t)r * (size_t)g->raster_width + (size_t)col] = index;
        }
}

static cdl_status build_polygon(const cdl_grid_spec *spec, cdl_grid *g, cdl_error *err)
{
    cdl_polygon_plane plane;
    if (cdl_polygon_plane_of_checked(&spec->outer, spec->holes, spec->hole_count, &plane, err) != CDL_OK)
        return cdl_error_prefix(err, "%s: ", spec->json_path);
    /* Bounding rectangle in the plane, axes along the first edge and across it. */
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (size_t i = 0; i < spec->outer.count; ++i) {
        double x, y;
        cdl_polygon_project(&plane, spec->outer.points[i], &x, &y);
        x0 = fmin(x0, x);
        x1 = fmax(x1, x);
        y0 = fmin(y0, y);
        y1 = fmax(y1, y);
    }
    double width = x1 - x0, height = y1 - y0;
    double p = spec->spacing > 0.0 ? spec->spacing : cdl_grid_auto_spacing(fmax(width, height));

    /* Estimate the count from the outer ring's area before meshing. */
    double outer_area = cdl_polygon_outer_area(&plane, &spec->outer);
    double estimate = POINTS_PER_SQUARE_SPACING * outer_area / (p * p);
    if (estimate > (double)CDL_GRID_MAX_POINTS)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s.spacing: expected a spacing giving at most %d points, found %s%.6g m (about %.3g "
                             "points over %.6g m^2)",
                             spec->json_path, CDL_GRID_MAX_POINTS,
                             spec->spacing > 0.0 ? "" : "\"auto\", the EN 12464-1 spacing capped at ", p, estimate,
                             outer_area);

    /* A mesh has about half as many vertices as triangles: allow four times
     * the estimate, plus room for grading down to small features, then stop
     * (a vertex a hair's breadth from an edge would otherwise take minutes). */
    double vertex_cap = fmin((double)CDL_GRID_MAX_POINTS, 2.0 * estimate + 10000.0);
    cdl_mesh2d mesh;
    cdl_status st = cdl_polygon_triangulate(&plane, &spec->outer, spec->holes, spec->hole_count,
                                            CDL_GRID_MESH_EDGE * p, (size_t)vertex_cap, &mesh, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", spec->json_path);
    if (mesh.triangle_count > CDL_GRID_MAX_POINTS) {
        size_t n = mesh.triangle_count;
        cdl_mesh2d_release(&mesh);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s.spacing: expected a spacing giving at most %d points, found %zu",
                             spec->json_path, CDL_GRID_MAX_POINTS, n);
    }
    cdl_vec3 n = spec->has_normal ? cdl_vec3_normalize(spec->normal) : plane.normal;
    double pixel = fmax(p / 4.0, fmax(width, height) / RASTER_MAX_SIDE);
    g->raster_width = (int)fmax(1.0, ceil(width / pixel));
    g->raster_height = (int)fmax(1.0, ceil(height / pixel));
    size_t pixels = (size_t)g->raster_width * (size_t)g->raster_height;
    if (alloc_points(g, mesh.triangle_count) != CDL_OK ||
        !(g->raster_index = malloc(pixels * sizeof *g->raster_index))) {
        cdl_mesh2d_release(&mesh);
        return cdl_error_out_of_memory(err);
    }
    for (size_t i = 0; i < pixels; ++i) g->raster_index[i] = -1;
    for (size_t t = 0; t < mesh.triangle_count; ++t) {
        const double *a = &mesh.xy[2 * mesh.triangles[3 * t]];
        const double *b = &mesh.xy[2 * mesh.triangles[3 * t + 1]];
        const double *c = &mesh.xy[2 * mesh.triangles[3 * t + 2]];
        /* Centroid and area of a triangle: (a + b + c) / 3, |(b - a) x (c - a)| / 2. */
        double cx = (a[0] + b[0] + c[0]) / 3.0, cy = (a[1] + b[1] + c[1]) / 3.0;
        g->points[t] = cdl_polygon_lift(&plane, cx, cy);
        g->normals[t] = n;
        g->weights[t] = 0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        raster_triangle(g, x0, y1, pixel, a, b, c, (int32_t)t);
    }
    cdl_mesh2d_release(&mesh);
    g->spacing_m = p;
    g->pixel_size_m = pixel;
    double bottom = y1 - g->raster_height * pixel;
    g->raster_corner = cdl_polygon_lift(&plane, x0, bottom);
    g->raster_right = cdl_vec3_normalize(cdl_vec3_sub(cdl_polygon_lift(&plane, x0 + 1.0, bottom), g->raster_corner));
    g->raster_up = cdl_vec3_normalize(cdl_vec3_sub(cdl_polygon_lift(&plane, x0, bottom + 1.0), g->raster_corner));
    g->pixel_width_m = g->pixel_height_m = pixel;
    return CDL_OK;
}

static cdl_status build_points(const cdl_grid_spec *spec, cdl_grid *g, cdl_error *err)
{
    if (alloc_points(g, spec->point_count) != CDL_OK) return cdl_error_out_of_memory(err);
    for (size_t i = 0; i < spec->point_count; ++i) {
        g->points[i] = spec->points[i];
        g->normals[i] = cdl_vec3_normalize(spec->normals[i]);
        g->weights[i] = 1.0;
    }
    return CDL_OK;
}

cdl_status cdl_grid_build(const cdl_grid_spec *spec, cdl_grid *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_status st = CDL_OK;
    switch (spec->kind) {
    case CDL_GRID_RECT: st = build_rect(spec, out, err); break;
    case CDL_GRID_POLYGON: st = build_polygon(spec, out, err); break;
    case CDL_GRID_POINTS: st = build_points(spec, out, err); break;
    default: st = cdl_error_set(err, CDL_ERR_INTERNAL, "%s: unknown grid kind %d", spec->json_path, (int)spec->kind);
    }
    if (st != CDL_OK) cdl_grid_release(out);
    return st;
}

void cdl_grid_release(cdl_grid *grid)
{
    if (!grid) return;
    free(grid->points);
    free(grid->normals);
    free(grid->weights);
    free(grid->raster_index);
    memset(grid, 0, sizeof *grid);
}
