/* annual_metrics.c - DA, UDI, ASE, sDA and EN 17037's daylight provision (see the header). */
#include "daylight/annual_metrics.h"

#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"

/* EN 17037:2018, Table A.1 (daylight provision through vertical and
 * inclined openings): target illuminance E_T over 50 % and minimum target
 * E_TM over 95 % of the reference plane, for half of the daylight hours. */
const cdl_en17037_level cdl_en17037_levels[CDL_EN17037_LEVELS] = {
    {"minimum", 300.0, 100.0}, {"medium", 500.0, 300.0}, {"high", 750.0, 500.0}};

/* share of the grid (in the weights' measure) */
static double weight_of(const cdl_annual_input *in, size_t i)
{
    return in->weights ? in->weights[i] : 1.0;
}

/* Counts per point over the hours. */
typedef struct point_counts {
    size_t da, short_, useful, exceeded, ase, en;
} point_counts;

/* EN 17037: for each daylight hour, the grid's share above each level's
 * two thresholds; the hours that count. */
static void en17037_hour(const cdl_annual_input *in, const float *E, double total, size_t *target, size_t *minimum)
{
    double at_t[CDL_EN17037_LEVELS] = {0}, at_m[CDL_EN17037_LEVELS] = {0};
    for (size_t i = 0; i < in->points; ++i) {
        double w = weight_of(in, i);
        for (int l = 0; l < CDL_EN17037_LEVELS; ++l) {
            if (E[i] >= cdl_en17037_levels[l].target_lx) at_t[l] += w;
            if (E[i] >= cdl_en17037_levels[l].minimum_lx) at_m[l] += w;
        }
    }
    for (int l = 0; l < CDL_EN17037_LEVELS; ++l) {
        if (at_t[l] >= 0.5 * total) target[l]++;
        if (at_m[l] >= 0.95 * total) minimum[l]++;
    }
}

cdl_status cdl_annual_metrics_compute(const cdl_annual_input *in, cdl_point_metrics *points,
                                      cdl_grid_annual_metrics *grid, cdl_error *err)
{
    memset(grid, 0, sizeof *grid);
    for (size_t h = 0; h < in->hours; ++h) {
        grid->occupied_hours += in->occupied[h] != 0;
        grid->daylight_hours += in->daylight[h] != 0;
    }
    if (grid->occupied_hours == 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "occupancy: expected at least one occupied hour, found none");
    if (grid->daylight_hours == 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected at least one daylight hour, found none");
    point_counts *c = calloc(in->points ? in->points : 1, sizeof *c);
    float *dark = calloc(in->points ? in->points : 1, sizeof *dark);
    if (!c || !dark) {
        free(c);
        free(dark);
        return cdl_error_out_of_memory(err);
    }
    double total = 0.0;
    for (size_t i = 0; i < in->points; ++i) total += weight_of(in, i);
    size_t en_t[CDL_EN17037_LEVELS] = {0}, en_m[CDL_EN17037_LEVELS] = {0};
    for (size_t h = 0; h < in->hours; ++h) {
        int row = in->row_of_hour ? in->row_of_hour[h] : (int)h;
        const float *E = row >= 0 ? in->E + (size_t)row * in->points : dark;
        const float *S = in->E_sun && row >= 0 ? in->E_sun + (size_t)row * in->points : NULL;
        if (in->occupied[h])
            for (size_t i = 0; i < in->points; ++i) {
                point_counts *p = &c[i];
                p->da += E[i] >= CDL_DA_LX;
                p->short_ += E[i] < CDL_UDI_LOW_LX;
                p->exceeded += E[i] > CDL_UDI_HIGH_LX;
                p->ase += S && S[i] >= CDL_ASE_LX;
            }
        if (in->daylight[h]) {
            for (size_t i = 0; i < in->points; ++i) c[i].en += E[i] >= cdl_en17037_levels[0].target_lx;
            en17037_hour(in, E, total, en_t, en_m);
        }
    }
    double occ = (double)grid->occupied_hours, day = (double)grid->daylight_hours;
    for (size_t i = 0; i < in->points; ++i) {
        point_counts *p = &c[i];
        p->useful = grid->occupied_hours - p->short_ - p->exceeded;
        cdl_point_metrics *m = &points[i];
        m->DA300 = 100.0 * (double)p->da / occ;
        m->UDI_fell_short = 100.0 * (double)p->short_ / occ;
        m->UDI = 100.0 * (double)p->useful / occ;
        m->UDI_exceeded = 100.0 * (double)p->exceeded / occ;
        m->ASE_hours = (double)p->ase;
        m->EN17037_target = 100.0 * (double)p->en / day;
        double w = weight_of(in, i) / (total > 0.0 ? total : 1.0);
        grid->sDA300 += m->DA300 >= CDL_SDA_SHARE ? 100.0 * w : 0.0;
        grid->ASE1000 += m->ASE_hours > CDL_ASE_HOURS ? 100.0 * w : 0.0;
        grid->UDI_fell_short += w * m->UDI_fell_short;
        grid->UDI += w * m->UDI;
        grid->UDI_exceeded += w * m->UDI_exceeded;
        grid->DA300_mean += w * m->DA300;
    }
    free(c);
    free(dark);
    grid->en_level = "none";
    for (int l = 0; l < CDL_EN17037_LEVELS; ++l) {
        grid->en_target_hours[l] = 100.0 * (double)en_t[l] / day;
        grid->en_minimum_hours[l] = 100.0 * (double)en_m[l] / day;
        grid->en_met[l] = grid->en_target_hours[l] >= 50.0 && grid->en_minimum_hours[l] >= 50.0;
        if (grid->en_met[l]) grid->en_level = cdl_en17037_levels[l].name;
    }
    return CDL_OK;
}

/* Hours in order of falling diffuse illuminance, ties to the earlier. */
typedef struct hour_value {
    double v;
    size_t h;
} hour_value;

static int by_diffuse(const void *a, const void *b)
{
    const hour_value *x = a, *y = b;
    if (x->v != y->v) return x->v > y->v ? -1 : 1;
    return x->h < y->h ? -1 : x->h > y->h;
}

cdl_status cdl_annual_daylight_hours(const double *diffuse_lx, size_t hours, unsigned char *daylight,
                                     cdl_error *err)
{
    hour_value *order = malloc((hours ? hours : 1) * sizeof *order);
    if (!order) return cdl_error_out_of_memory(err);
    for (size_t h = 0; h < hours; ++h) order[h] = (hour_value){diffuse_lx[h], h};
    qsort(order, hours, sizeof *order, by_diffuse);
    memset(daylight, 0, hours);
    for (size_t k = 0; k < hours / 2; ++k) daylight[order[k].h] = 1;
    free(order);
    return CDL_OK;
}
