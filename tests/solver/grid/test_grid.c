/* Calculation grids: the EN 12464-1 spacing rule, rect cell centres and
 * raster order, polygon grids that cover exactly the polygon's area (minus
 * holes) with points no farther apart than the spacing, and points grids. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/grid/grid.h"
#include "solver/geometry/mesh2d.h"

static cdl_scene *load(const char *grids)
{
    char json[4096];
    snprintf(json, sizeof json, "{\"version\": 1, \"grids\": [%s]}", grids);
    cdl_error err;
    cdl_scene *s = NULL;
    CHECK_OK(cdl_scene_load_string(json, "grids.json", &s, &err), &err);
    return s;
}

/* Is (x, y) inside the polygon ring xy (crossing number)? */
static int inside(const double *ring, int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const double *a = &ring[2 * i], *b = &ring[2 * j];
        if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) in = !in;
    }
    return in;
}

static void test_auto_spacing(void)
{
    /* p = 0.2 x 5^log10(d): d = 10 m -> 1 m, d = 1 m -> 0.2 m, d = 100 m -> 5 m
     * (powers of ten: exact up to pow's rounding, 1e-15). */
    CHECK_REL(cdl_grid_auto_spacing(10.0), 1.0, 1e-15);
    CHECK_REL(cdl_grid_auto_spacing(1.0), 0.2, 1e-15);
    CHECK_REL(cdl_grid_auto_spacing(100.0), 5.0, 1e-14);
    /* In between, the same rule written as 0.2 d^log10(5) (values computed
     * independently in double precision; 1e-14 allows pow's rounding). */
    CHECK_REL(cdl_grid_auto_spacing(4.0), 0.5270500640101247, 1e-14);
    CHECK_REL(cdl_grid_auto_spacing(50.0), 3.0800592217225162, 1e-14);
    CHECK_REL(cdl_grid_auto_spacing(0.5), 0.12320236886890062, 1e-14);
    /* Capped at 10 m: 0.2 x 5^log10(d) reaches 10 m at d = 10^(ln 50 / ln 5) = 269.6 m. */
    CHECK_REL(cdl_grid_auto_spacing(200.0), 8.116727049819133, 1e-14);
    CHECK(cdl_grid_auto_spacing(269.0) < 10.0);
    CHECK(cdl_grid_auto_spacing(270.0) == 10.0);
    CHECK(cdl_grid_auto_spacing(1000.0) == 10.0);
    CHECK(cdl_grid_auto_spacing(1e6) == 10.0);
    CHECK(cdl_grid_auto_spacing(0.0) == 0.0 && cdl_grid_auto_spacing(-1.0) == 0.0);
}

static void test_rect(void)
{
    cdl_scene *s = load("{\"name\": \"workplane\", \"type\": \"rect\", \"origin\": [0.4,0.4,0.8], \"u\": [3.2,0,0],"
                        " \"v\": [0,3.2,0], \"nu\": 9, \"nv\": 9},"
                        "{\"name\": \"wall\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [0,2,0], \"v\": [0,0,1],"
                        " \"nu\": 4, \"nv\": 2, \"normal\": [-3,0,0]}");
    if (!s) return;
    cdl_error err;
    cdl_grid g;
    CHECK_OK(cdl_grid_build(&s->grids[0], &g, &err), &err);
    CHECK(g.count == 81 && g.raster_width == 9 && g.raster_height == 9);
    /* Cell centres, i fastest: point (i, j) = origin + (i + 0.5)/9 u + (j + 0.5)/9 v. */
    int ok = 1;
    double wsum = 0.0;
    for (int j = 0; j < 9; ++j)
        for (int i = 0; i < 9; ++i) {
            cdl_vec3 p = g.points[j * 9 + i];
            ok &= fabs(p.x - (0.4 + (i + 0.5) / 9 * 3.2)) < 1e-15 && fabs(p.y - (0.4 + (j + 0.5) / 9 * 3.2)) < 1e-15 &&
                  p.z == 0.8 && g.normals[j * 9 + i].z == 1.0;
            wsum += g.weights[j * 9 + i];
        }
    CHECK(ok);
    /* Weights are cell areas: they add up to |u x v| = 10.24 m^2. */
    CHECK_REL(wsum, 10.24, 1e-14);
    /* Raster: row 0 is the v = 1 edge, column 0 the u = 0 edge. */
    CHECK(g.raster_index[0] == 72 && g.raster_index[8] == 80 && g.raster_index[80] == 8 && g.raster_index[72] == 0);
    CHECK_REL(g.spacing_m, 3.2 / 9, 1e-15);
    CHECK_REL(g.pixel_size_m, 3.2 / 9, 1e-15);
    cdl_grid_release(&g);

    /* A vertical grid with its own (normalised) normal. */
    CHECK_OK(cdl_grid_build(&s->grids[1], &g, &err), &err);
    CHECK(g.count == 8 && g.normals[5].x == -1.0 && g.normals[5].y == 0.0);
    CHECK(g.points[5].y == 0.75 && g.points[5].z == 0.75 && g.points[5].x == 0.0);
    cdl_grid_release(&g);
    cdl_scene_release(s);
}

/* Checks every polygon grid shares: weights add up to `area`, points inside
 * and on the plane, neighbours within the spacing, raster consistent. */
static void check_polygon_grid(const cdl_grid *g, double area, const double *ring, int n, const double *hole, int nh,
                               double z)
{
    double wsum = 0.0;
    int on_plane = 1, in = 1;
    for (size_t k = 0; k < g->count; ++k) {
        wsum += g->weights[k];
        on_plane &= g->points[k].z == z && g->normals[k].z == 1.0;
        in &= inside(ring, n, g->points[k].x, g->points[k].y) && !(hole && inside(hole, nh, g->points[k].x, g->points[k].y));
    }
    /* Triangle areas summed: rounding only (1e-12 for thousands of terms). */
    CHECK_REL(wsum, area, 1e-12);
    CHECK(on_plane);
    CHECK(in);
    /* Each point has a neighbour within the mesh's longest edge (centroids
     * of triangles whose edges are at most e are at most e apart across a
     * shared edge), e = sqrt(5) p. */
    int spaced = 1;
    for (size_t k = 0; k < g->count; ++k) {
        double nearest = INFINITY;
        for (size_t m = 0; m < g->count; ++m)
            if (m != k) nearest = fmin(nearest, cdl_vec3_distance(g->points[k], g->points[m]));
        spaced &= nearest <= CDL_GRID_MESH_EDGE * g->spacing_m;
    }
    CHECK(g->count < 2 || spaced);
    /* The spacing is EN 12464-1's p: about one point per p^2, as a square
     * grid of spacing p has. The mesh grades finer at corners and holes,
     * and a small polygon has few triangles: 0.7 to 1.6 points per p^2
     * where the polygon holds at least 40 p^2 (measured: squares of 16 to
     * 1600 p^2 0.91 to 1.0, the L-shaped room with a column 1.17). */
    double per_p2 = (double)g->count * g->spacing_m * g->spacing_m / area;
    if (area >= 40.0 * g->spacing_m * g->spacing_m)
        CHECK_MSG(per_p2 >= 0.7 && per_p2 <= 1.6, "%.3g points per p^2 (p = %g m, %zu points over %g m^2)", per_p2,
                  g->spacing_m, g->count, area);
    /* Raster: pixel_size = p / 4; inside pixels cover the area up to the
     * pixels cut by the outline (perimeter x pixel, bounded here by 4 pixels
     * per metre of the polygon's bounding box side). */
    CHECK_REL(g->pixel_size_m, g->spacing_m / 4, 1e-15);
    size_t covered = 0;
    int valid = 1;
    for (int i = 0; i < g->raster_width * g->raster_height; ++i) {
        valid &= g->raster_index[i] >= -1 && g->raster_index[i] < (int32_t)g->count;
        covered += g->raster_index[i] >= 0;
    }
    CHECK(valid);
    double px = g->pixel_size_m;
    double perimeter_bound = 4.0 * (g->raster_width + g->raster_height) * px;
    CHECK_MSG(fabs(covered * px * px - area) <= perimeter_bound * px, "raster area %g, polygon %g",
              covered * px * px, area);
}

static void test_polygon(void)
{
    cdl_scene *s = load(
        /* DESIGN.md's desk: a 4 x 4 square minus a 2 x 2 corner triangle, area 14 */
        "{\"name\": \"desk\", \"type\": \"polygon\", \"vertices\": [[0,0,0.8],[4,0,0.8],[4,2,0.8],[2,4,0.8],[0,4,0.8]],"
        " \"spacing\": \"auto\"},"
        /* an L-shaped room 10 x 5 + 4 x 3 with a 0.6 x 0.6 column: 61.64 m^2, 1 m spacing */
        "{\"name\": \"room\", \"type\": \"polygon\", \"vertices\": [[0,0,0],[10,0,0],[10,8,0],[6,8,0],[6,5,0],[0,5,0]],"
        " \"holes\": [[[2,2,0],[2.6,2,0],[2.6,2.6,0],[2,2.6,0]]], \"spacing\": 1},"
        /* a tilted roof panel, 3 x 2 in its plane, auto spacing from its own size */
        "{\"name\": \"roof\", \"type\": \"polygon\", \"vertices\": [[0,0,3],[3,0,3],[3,1.2,4.6],[0,1.2,4.6]]},"
        /* too fine a spacing for its size */
        "{\"name\": \"huge\", \"type\": \"polygon\", \"vertices\": [[0,0,0],[100,0,0],[100,100,0],[0,100,0]], \"spacing\": 0.01}");
    if (!s) return;
    cdl_error err;
    cdl_grid g;
    CHECK_OK(cdl_grid_build(&s->grids[0], &g, &err), &err);
    const double desk[] = {0, 0, 4, 0, 4, 2, 2, 4, 0, 4};
    /* Bounding rectangle 4 x 4 along the first edge: d = 4, p = 0.2 x 5^log10(4). */
    CHECK_REL(g.spacing_m, 0.5270500640101247, 1e-14);
    CHECK(g.count > 30); /* 14 m^2 at p = 0.53 m: about 50 points */
    check_polygon_grid(&g, 14.0, desk, 5, NULL, 0, 0.8);
    CHECK(g.raster_width == (int)ceil(4.0 / (g.spacing_m / 4)) && g.raster_height == g.raster_width);
    /* Row 0 is the top (y = 4): its right end lies in the cut-off corner
     * (x + y > 6), its left end inside. */
    CHECK(g.raster_index[g.raster_width - 1] == -1);
    CHECK(g.raster_index[0] >= 0);
    cdl_grid_release(&g);

    CHECK_OK(cdl_grid_build(&s->grids[1], &g, &err), &err);
    const double room[] = {0, 0, 10, 0, 10, 8, 6, 8, 6, 5, 0, 5};
    const double column[] = {2, 2, 2.6, 2, 2.6, 2.6, 2, 2.6};
    CHECK(g.spacing_m == 1.0);
    check_polygon_grid(&g, 50.0 + 12.0 - 0.36, room, 6, column, 4, 0.0);
    cdl_grid_release(&g);

    CHECK_OK(cdl_grid_build(&s->grids[2], &g, &err), &err);
    /* The panel is 3 m by |(0, 1.2, 1.6)| = 2 m: d = 3, area 6, normal (0, -0.8, 0.6). */
    CHECK_REL(g.spacing_m, 0.2 * pow(5.0, log10(3.0)), 1e-15);
    double wsum = 0.0, off_plane = 0.0, normal_err = 0.0;
    for (size_t k = 0; k < g.count; ++k) {
        wsum += g.weights[k];
        /* The plane through (0, 0, 3) with normal (0, -0.8, 0.6). */
        off_plane = fmax(off_plane, fabs(-0.8 * g.points[k].y + 0.6 * (g.points[k].z - 3.0)));
        normal_err = fmax(normal_err, cdl_vec3_distance(g.normals[k], cdl_vec3_make(0, -0.8, 0.6)));
    }
    CHECK_REL(wsum, 6.0, 1e-13);
    /* Coordinates of a few metres: double rounding leaves ~1e-15 m. */
    CHECK_ABS(off_plane, 0.0, 1e-14);
    CHECK_ABS(normal_err, 0.0, 1e-15);
    cdl_grid_release(&g);

    cdl_error_clear(&err);
    CHECK(cdl_grid_build(&s->grids[3], &g, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "grids[3].spacing: expected a spacing giving at most 10000000 points") != NULL, "%s",
              err.message);
    CHECK(g.points == NULL && g.count == 0);
    cdl_scene_release(s);
}

static void test_points(void)
{
    cdl_scene *s = load("{\"name\": \"probes\", \"type\": \"points\", \"points\": [{\"p\": [1,2,3], \"n\": [0,0,5]},"
                        " {\"p\": [4,5,6], \"n\": [3,4,0]}], \"outputs\": [\"ao\"]}");
    if (!s) return;
    cdl_error err;
    cdl_grid g;
    CHECK(s->grids[0].want_ao == 1);
    CHECK_OK(cdl_grid_build(&s->grids[0], &g, &err), &err);
    CHECK(g.count == 2 && g.raster_width == 0 && g.raster_height == 0 && g.raster_index == NULL);
    CHECK(g.points[1].x == 4 && g.points[1].z == 6 && g.weights[0] == 1.0 && g.weights[1] == 1.0);
    CHECK(g.normals[0].z == 1.0);
    /* Normalised (3, 4, 0): within an ulp or two of (0.6, 0.8, 0). */
    CHECK_ABS(g.normals[1].x, 0.6, 2e-16);
    CHECK_ABS(g.normals[1].y, 0.8, 2e-16);
    cdl_grid_release(&g);
    cdl_scene_release(s);
}

/* Refinement that would need more vertices than allowed stops with an error. */
static void test_bounded_refinement(void)
{
    const double square[] = {0, 0, 4, 0, 4, 4, 0, 4};
    cdl_ring2d ring = {square, 4};
    cdl_mesh2d m;
    cdl_error err;
    /* A 4 m square at 0.5 m needs well over 50 vertices (about 5 points per p^2, half as many vertices). */
    cdl_error_clear(&err);
    CHECK(cdl_mesh2d_triangulate_bounded(ring, NULL, 0, 0.5, 50, &m, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "the mesh needs more points than allowed") != NULL);
    CHECK(m.xy == NULL && m.triangles == NULL);
    CHECK_OK(cdl_mesh2d_triangulate_bounded(ring, NULL, 0, 0.5, 5000, &m, &err), &err);
    CHECK(m.vertex_count > 50 && m.vertex_count <= 5000);
    CHECK_REL(m.area, 16.0, 1e-14);
    cdl_mesh2d_release(&m);
}

int main(void)
{
    test_bounded_refinement();
    test_auto_spacing();
    test_rect();
    test_polygon();
    test_points();
    return check_finish();
}
