/* grid_stats.c - average, minimum, maximum and uniformity of a grid's illuminance. */
#include "solver/output/grid_result.h"

#include <math.h>
#include <string.h>

/* Neumaier's compensated sum: a grid of a million points keeps the mean to
 * a few ulps instead of losing digits to rounding in a running total. */
typedef struct compensated_sum {
    double sum, carry;
} compensated_sum;

static void compensated_add(compensated_sum *s, double x)
{
    double t = s->sum + x;
    if (fabs(s->sum) >= fabs(x))
        s->carry += (s->sum - t) + x;
    else
        s->carry += (x - t) + s->sum;
    s->sum = t;
}

/* Mean of `values` weighted by the area each point stands for (as Em),
 * minimum, maximum and min / mean (0 when the mean is 0). */
static void value_stats(const double *values, const double *w, size_t n, cdl_value_stats *out)
{
    memset(out, 0, sizeof *out);
    if (!values || n == 0) return;
    compensated_sum weighted = {0.0, 0.0}, weight = {0.0, 0.0}, plain = {0.0, 0.0};
    out->min = out->max = values[0];
    for (size_t i = 0; i < n; ++i) {
        out->min = fmin(out->min, values[i]);
        out->max = fmax(out->max, values[i]);
        compensated_add(&plain, values[i]);
        if (w) {
            compensated_add(&weighted, w[i] * values[i]);
            compensated_add(&weight, w[i]);
        }
    }
    double total = weight.sum + weight.carry;
    out->avg = total > 0.0 ? (weighted.sum + weighted.carry) / total : (plain.sum + plain.carry) / (double)n;
    out->U0 = out->avg != 0.0 ? out->min / out->avg : 0.0;
}

void cdl_grid_result_stats(const cdl_grid_result *result, cdl_grid_stats *stats)
{
    memset(stats, 0, sizeof *stats);
    const cdl_grid *grid = result->grid;
    size_t n = grid ? grid->count : 0;
    if (n == 0 || !result->E) return;
    const double *E = result->E;
    const double *w = grid->weights;

    compensated_sum weighted = {0.0, 0.0}, weight = {0.0, 0.0}, plain = {0.0, 0.0};
    double lo = E[0], hi = E[0];
    for (size_t i = 0; i < n; ++i) {
        if (E[i] < lo) lo = E[i];
        if (E[i] > hi) hi = E[i];
        compensated_add(&plain, E[i]);
        if (w) {
            compensated_add(&weighted, w[i] * E[i]);
            compensated_add(&weight, w[i]);
        }
    }
    double total_weight = weight.sum + weight.carry;
    /* Average illuminance over the area (EN 12464-1's Em, here of the values
     * given): the mean of E with each point weighted by the area it stands for. */
    double Em = total_weight > 0.0 ? (weighted.sum + weighted.carry) / total_weight : (plain.sum + plain.carry) / (double)n;

    stats->count = n;
    stats->E_avg_lx = Em;
    stats->E_min_lx = lo;
    stats->E_max_lx = hi;
    /* Uniformity U0 = Emin / Em (EN 12464-1) and diversity Ud = Emin / Emax
     * (DESIGN.md, summary.json); 0 when the denominator is 0. */
    stats->U0 = Em != 0.0 ? lo / Em : 0.0;
    stats->Ud = hi != 0.0 ? lo / hi : 0.0;
    if (w && grid->raster_width > 0) stats->area_m2 = total_weight;
    value_stats(result->Ez, total_weight > 0.0 ? w : NULL, n, &stats->Ez);
    value_stats(result->Esz, total_weight > 0.0 ? w : NULL, n, &stats->Esz);
    value_stats(result->L, total_weight > 0.0 ? w : NULL, n, &stats->L);
    value_stats(result->DF, total_weight > 0.0 ? w : NULL, n, &stats->DF);

    if (!result->E_stderr) return;
    compensated_sum rel = {0.0, 0.0}, rel_weight = {0.0, 0.0};
    for (size_t i = 0; i < n; ++i) {
        double s = result->E_stderr[i];
        if (s > stats->stderr_max_lx) stats->stderr_max_lx = s;
        if (!(E[i] > 0.0)) continue;
        double r = s / E[i];
        if (r > stats->stderr_max_rel) stats->stderr_max_rel = r;
        double wi = w && total_weight > 0.0 ? w[i] : 1.0;
        compensated_add(&rel, wi * r);
        compensated_add(&rel_weight, wi);
    }
    double rw = rel_weight.sum + rel_weight.carry;
    stats->stderr_mean_rel = rw > 0.0 ? (rel.sum + rel.carry) / rw : 0.0;
}
