/* The report's isolux lines of a point source over a plane lie on the
 * circles where the closed form gives the labelled illuminance.
 *
 * A point source of I = 1000 cd at height h = 2 m above the plane z = 0
 * gives E(r) = I h / (h^2 + r^2)^(3/2) at distance r from its foot (the
 * inverse square law times the cosine of incidence, cos = h / d). A rect
 * grid of 40 x 40 points over [-4, 4]^2 m (spacing s = 0.2 m) is built as
 * the solver builds it (cdl_grid_build), its points given the closed-form
 * E, and the contours traced as the report traces them, at the levels it
 * labels (cdl_contour_levels between the grid's Emin and Emax).
 *
 * Tolerance: a contour's vertex lies on the segment between two
 * neighbouring points A and B, where the linear interpolation of E(A) and
 * E(B) equals the level. Linear interpolation over a segment of length s
 * errs by at most s^2 / 8 max |E''| (E'' the second derivative along the
 * segment), so at the vertex P |E(P) - level| <= s^2 / 8 max |E''|; the
 * test bounds max |E''| on that segment from the closed form (central
 * differences at 41 places, 10 % added for what falls between them). In
 * distance from the source's foot that is |r(P) - r_level| <= that bound
 * divided by |dE/dr| between r(P) and r_level (E is monotone in r).
 * The lines must also go all the way round: the segments' angular spans
 * about the foot cover every 5-degree sector of each circle inside the grid.
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "radiometry/constants.h"
#include "report/contour.h"
#include "solver/grid/grid.h"

static const double I = 1000.0, h = 2.0;

static double E_at(double r)
{
    /* E = I cos(theta) / d^2 = I h / d^3 */
    return I * h / pow(h * h + r * r, 1.5);
}

static double E_point(cdl_vec3 p)
{
    return E_at(hypot(p.x, p.y));
}

static double dE_dr(double r)
{
    return -3.0 * I * h * r / pow(h * h + r * r, 2.5);
}

/* The largest |E''| along the segment a -> b, by central differences. */
static double max_second_derivative(cdl_vec3 a, cdl_vec3 b)
{
    double len = cdl_vec3_distance(a, b), step = len / 40.0, worst = 0.0;
    cdl_vec3 dir = cdl_vec3_scale(cdl_vec3_sub(b, a), 1.0 / len);
    for (int k = 0; k <= 40; ++k) {
        cdl_vec3 p = cdl_vec3_madd(a, k * step, dir);
        double d2 = (E_point(cdl_vec3_madd(p, step, dir)) - 2.0 * E_point(p) + E_point(cdl_vec3_madd(p, -step, dir))) /
                    (step * step);
        worst = fmax(worst, fabs(d2));
    }
    return 1.1 * worst;
}

/* The two grid points whose segment holds raster position (x, y): the
 * crossing lies on a horizontal or vertical line between pixel centres. */
static void segment_ends(const cdl_grid *g, double x, double y, cdl_vec3 *a, cdl_vec3 *b)
{
    double fx = x - 0.5, fy = y - 0.5;
    int on_column = fabs(fx - round(fx)) < 1e-9; /* x on a column of centres: the segment runs along y */
    double ax = on_column ? round(fx) : floor(fx), ay = on_column ? floor(fy) : round(fy);
    double bx = on_column ? ax : ax + 1.0, by = on_column ? ay + 1.0 : ay;
    *a = cdl_contour_world_position(g, ax + 0.5, ay + 0.5);
    *b = cdl_contour_world_position(g, bx + 0.5, by + 0.5);
}

int main(void)
{
    cdl_grid_spec spec = {0};
    spec.name = "plane";
    spec.kind = CDL_GRID_RECT;
    spec.origin = cdl_vec3_make(-4.0, -4.0, 0.0);
    spec.u = cdl_vec3_make(8.0, 0.0, 0.0);
    spec.v = cdl_vec3_make(0.0, 8.0, 0.0);
    spec.nu = spec.nv = 40;
    cdl_grid g;
    cdl_error err;
    CHECK_OK(cdl_grid_build(&spec, &g, &err), &err);
    double *E = malloc(g.count * sizeof *E);
    CHECK(E != NULL);
    if (!E) return check_finish();
    for (size_t i = 0; i < g.count; ++i) E[i] = E_point(g.points[i]);

    /* The levels the report labels, between the grid's Emin and Emax: 50,
     * 100, 150 and 200 lx, whose circles (r = 2.77, 1.84, 1.26, 0.80 m) lie
     * inside the grid. */
    double lo = E[0], hi = E[0];
    for (size_t i = 1; i < g.count; ++i) {
        lo = fmin(lo, E[i]);
        hi = fmax(hi, E[i]);
    }
    double levels[8];
    size_t n = cdl_contour_levels(lo, hi, levels, 8);
    CHECK_MSG(n == 4 && levels[0] == 50.0 && levels[3] == 200.0, "%zu levels from %g to %g lx", n, lo, hi);

    for (size_t l = 0; l < n; ++l) {
        double level = levels[l];
        /* r where E = level: (h^2 + r^2)^(3/2) = I h / level */
        double r_level = sqrt(pow(I * h / level, 2.0 / 3.0) - h * h);
        cdl_contour_segment *seg = NULL;
        size_t count = 0;
        CHECK_OK(cdl_contour_trace_grid(&g, E, level, &seg, &count, &err), &err);
        CHECK_MSG(count >= 12, "level %g: %zu segments", level, count);
        int sector_hit[72] = {0};
        size_t worst_vertex = 0;
        double worst_ratio = 0.0;
        for (size_t k = 0; k < count; ++k)
            for (int end = 0; end < 2; ++end) {
                double x = end ? seg[k].x1 : seg[k].x0, y = end ? seg[k].y1 : seg[k].y0;
                cdl_vec3 p = cdl_contour_world_position(&g, x, y), a, b;
                segment_ends(&g, x, y, &a, &b);
                double s = cdl_vec3_distance(a, b);
                double bound_E = s * s / 8.0 * max_second_derivative(a, b);
                double r = hypot(p.x, p.y);
                double slope = fmin(fabs(dE_dr(r)), fabs(dE_dr(r_level)));
                double ratio = fabs(r - r_level) / (bound_E / slope);
                if (ratio > worst_ratio) {
                    worst_ratio = ratio;
                    worst_vertex = k;
                }
                CHECK_MSG(fabs(E_point(p) - level) <= bound_E, "level %g: E %.6g at (%.4f, %.4f), bound %.3g", level,
                          E_point(p), p.x, p.y, bound_E);
                CHECK_MSG(fabs(r - r_level) <= bound_E / slope, "level %g: r %.5f, circle %.5f, bound %.3g m", level,
                          r, r_level, bound_E / slope);
            }
        for (size_t k = 0; k < count; ++k) {
            /* the sectors the segment's shorter arc passes (a segment spans far less than half a turn) */
            double a0 = atan2(seg[k].y0 - 20.0, seg[k].x0 - 20.0), a1 = atan2(seg[k].y1 - 20.0, seg[k].x1 - 20.0);
            double d = remainder(a1 - a0, 2.0 * CDL_PI);
            for (int t = 0; t <= 16; ++t) {
                double a = a0 + d * t / 16.0;
                sector_hit[(int)floor((a + 3.0 * CDL_PI) / (2.0 * CDL_PI) * 72.0) % 72] = 1;
            }
        }
        int sectors = 0;
        for (int s = 0; s < 72; ++s) sectors += sector_hit[s];
        CHECK_MSG(sectors == 72, "level %g: the line covers %d of 72 sectors", level, sectors);
        printf("level %g lx: %zu segments on r = %.4f m, worst |dr| at %.2f of its bound (vertex %zu)\n", level,
               count, r_level, worst_ratio, worst_vertex);
        free(seg);
    }
    /* A level outside the values draws nothing. */
    cdl_contour_segment *none = NULL;
    size_t none_count = 1;
    CHECK_OK(cdl_contour_trace_grid(&g, E, 1000.0, &none, &none_count, &err), &err);
    CHECK(none_count == 0);
    free(none);
    free(E);
    cdl_grid_release(&g);
    return check_finish();
}
