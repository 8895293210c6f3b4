/* contour.c - marching squares over a raster of values (contour.h). */
#include "report/contour.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "solver/grid/grid.h"

typedef struct segment_list {
    cdl_contour_segment *items;
    size_t count, capacity;
} segment_list;

static int push(segment_list *l, double x0, double y0, double x1, double y1)
{
    if (l->count == l->capacity) {
        size_t cap = l->capacity ? 2 * l->capacity : 256;
        cdl_contour_segment *grown = realloc(l->items, cap * sizeof *grown);
        if (!grown) return 0;
        l->items = grown;
        l->capacity = cap;
    }
    l->items[l->count++] = (cdl_contour_segment){x0, y0, x1, y1};
    return 1;
}

/* Where the level crosses the edge from a (at pa) to b (at pb): linear
 * interpolation, t = (level - a) / (b - a). */
static double crossing(double a, double b, double level)
{
    return (level - a) / (b - a);
}

cdl_status cdl_contour_trace(const double *v, int width, int height, double level, cdl_contour_segment **segments,
                             size_t *count, cdl_error *err)
{
    segment_list l = {0};
    for (int r = 0; r + 1 < height; ++r)
        for (int c = 0; c + 1 < width; ++c) {
            /* Corners counter-clockwise on screen from the top-left: 0 (c, r),
             * 1 (c+1, r), 2 (c+1, r+1), 3 (c, r+1). */
            double q[4] = {v[(size_t)r * width + c], v[(size_t)r * width + c + 1], v[(size_t)(r + 1) * width + c + 1],
                           v[(size_t)(r + 1) * width + c]};
            if (isnan(q[0]) || isnan(q[1]) || isnan(q[2]) || isnan(q[3])) continue;
            const double cx[4] = {c + 0.5, c + 1.5, c + 1.5, c + 0.5}, cy[4] = {r + 0.5, r + 0.5, r + 1.5, r + 1.5};
            int above[4], mask = 0;
            for (int k = 0; k < 4; ++k) {
                above[k] = q[k] >= level;
                mask |= above[k] << k;
            }
            if (mask == 0 || mask == 15) continue;
            /* The crossing on each edge k (corner k to corner k+1), if any. */
            double ex[4], ey[4];
            int crossed[4];
            for (int k = 0; k < 4; ++k) {
                int j = (k + 1) % 4;
                crossed[k] = above[k] != above[j];
                if (crossed[k]) {
                    double t = crossing(q[k], q[j], level);
                    ex[k] = cx[k] + t * (cx[j] - cx[k]);
                    ey[k] = cy[k] + t * (cy[j] - cy[k]);
                }
            }
            int ok = 1;
            if (crossed[0] && crossed[1] && crossed[2] && crossed[3]) {
                /* Saddle: the centre's mean decides which corners connect. */
                int centre_above = (q[0] + q[1] + q[2] + q[3]) / 4.0 >= level;
                if (centre_above == above[0]) {
                    /* corner 0's side joins the centre: cut off corners 1 and 3 */
                    ok = push(&l, ex[0], ey[0], ex[1], ey[1]) && push(&l, ex[2], ey[2], ex[3], ey[3]);
                } else {
                    ok = push(&l, ex[3], ey[3], ex[0], ey[0]) && push(&l, ex[1], ey[1], ex[2], ey[2]);
                }
            } else {
                int first = -1;
                for (int k = 0; k < 4 && ok; ++k) {
                    if (!crossed[k]) continue;
                    if (first < 0) first = k;
                    else ok = push(&l, ex[first], ey[first], ex[k], ey[k]);
                }
            }
            if (!ok) {
                free(l.items);
                *segments = NULL;
                *count = 0;
                return cdl_error_out_of_memory(err);
            }
        }
    *segments = l.items;
    *count = l.count;
    return CDL_OK;
}

/* A polygon grid's raster shows each triangle's point over the whole
 * triangle (several pixels a point): contours of that would follow the
 * triangles' edges in steps. There each pixel centre takes the inverse
 * distance weighted mean (Shepard 1968, weights 1 / d^2) of the points
 * shown within one spacing of it, which passes through every point's
 * value at the point and varies smoothly between them. Rasters of one
 * pixel a point (rect grids) are contoured as they are; so are rasters too
 * large to smooth quickly (beyond 4 million pixels). */
#define SMOOTH_MAX_PIXELS ((size_t)4 << 20)
#define SMOOTH_MAX_NEIGHBOURS 64

static double smoothed_value(const cdl_grid *g, const double *E, int c, int r, int reach)
{
    int32_t seen[SMOOTH_MAX_NEIGHBOURS];
    int n = 0;
    cdl_vec3 centre = cdl_contour_world_position(g, c + 0.5, r + 0.5);
    double sum_w = 0.0, sum = 0.0;
    for (int dr = -reach; dr <= reach; ++dr)
        for (int dc = -reach; dc <= reach; ++dc) {
            int cc = c + dc, rr = r + dr;
            if (cc < 0 || rr < 0 || cc >= g->raster_width || rr >= g->raster_height) continue;
            int32_t idx = g->raster_index[(size_t)rr * (size_t)g->raster_width + (size_t)cc];
            int known = idx < 0;
            for (int k = 0; k < n && !known; ++k) known = seen[k] == idx;
            if (known || n == SMOOTH_MAX_NEIGHBOURS) continue;
            seen[n++] = idx;
            double d2 = cdl_vec3_length_squared(cdl_vec3_sub(g->points[idx], centre));
            if (d2 < 1e-18) return E[idx];
            sum_w += 1.0 / d2;
            sum += E[idx] / d2;
        }
    return sum / sum_w;
}

cdl_status cdl_contour_trace_grid(const cdl_grid *g, const double *E, double level, cdl_contour_segment **segments,
                                  size_t *count, cdl_error *err)
{
    size_t pixels = (size_t)g->raster_width * (size_t)g->raster_height;
    double *values = malloc((pixels ? pixels : 1) * sizeof *values);
    if (!values) return cdl_error_out_of_memory(err);
    int smooth = pixels > g->count + g->count / 2 && pixels <= SMOOTH_MAX_PIXELS && g->pixel_width_m > 0.0;
    int reach = smooth ? (int)ceil(g->spacing_m / g->pixel_width_m) : 0;
    if (reach > 8) reach = 8;
    for (int r = 0; r < g->raster_height; ++r)
        for (int c = 0; c < g->raster_width; ++c) {
            size_t k = (size_t)r * (size_t)g->raster_width + (size_t)c;
            int32_t idx = g->raster_index[k];
            values[k] = idx < 0 ? NAN : smooth ? smoothed_value(g, E, c, r, reach) : E[idx];
        }
    cdl_status st = cdl_contour_trace(values, g->raster_width, g->raster_height, level, segments, count, err);
    free(values);
    return st;
}

cdl_vec3 cdl_contour_world_position(const cdl_grid *g, double x, double y)
{
    cdl_vec3 p = cdl_vec3_madd(g->raster_corner, x * g->pixel_width_m, g->raster_right);
    return cdl_vec3_madd(p, (g->raster_height - y) * g->pixel_height_m, g->raster_up);
}

size_t cdl_contour_levels(double lo, double hi, double *levels, size_t max_levels)
{
    if (!(hi > lo) || !(hi > 0.0) || max_levels == 0) return 0;
    /* The smallest 1-2-5 step giving at most 8 levels strictly inside. */
    double span = hi - lo, e = pow(10.0, floor(log10(span / 8.0)));
    static const double m[] = {1.0, 2.0, 5.0, 10.0, 20.0};
    for (int k = 0; k < 5; ++k) {
        double step = m[k] * e, first = floor(lo / step) + 1.0;
        size_t n = 0;
        while ((first + (double)n) * step < hi - 1e-9 * step) ++n;
        if (n > 8) continue;
        if (n > max_levels) n = max_levels;
        for (size_t j = 0; j < n; ++j) levels[j] = (first + (double)j) * step;
        return n;
    }
    return 0;
}
