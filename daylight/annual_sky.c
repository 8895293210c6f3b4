/* annual_sky.c - the hours of a weather file as skies over the patches (see the header). */
#include "daylight/annual_sky.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/emitter.h"
#include "lights/environment/perez_sky.h"
#include "lights/environment/solar_position.h"
#include "radiometry/constants.h"
#include "solver/pool.h"

typedef struct fill_job {
    const cdl_epw *epw;
    const cdl_reinhart_patches *p;
    const cdl_annual_sky_options *o;
    cdl_annual_skies *out;
    const size_t *row_hour;
    const cdl_rank_deal *deal;            /* row r's patches at cdl_rank_deal_row(deal, r) */
} fill_job;

/* Gauss-Legendre, 3 points on [0, 1]: nodes 1/2 +- sqrt(3/5)/2 and 1/2, weights 5/18, 8/18, 5/18. */
static const double gl_x[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
static const double gl_w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

/* L_k = int_k L cos Z dw / int_k cos Z dw; with s = sin(altitude), dw = ds d(az) and cos Z = s. */
static double patch_mean(const cdl_reinhart_patches *p, const cdl_emitter *e, int k)
{
    double a0, a1, z0, z1;
    cdl_reinhart_patch_bounds(p, k, &a0, &a1, &z0, &z1);
    double s0 = sin(a0), s1 = sin(a1), num = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = s0 + (s1 - s0) * gl_x[i], az = z0 + (z1 - z0) * gl_x[j];
            cdl_vec3 w = cdl_reinhart_direction(p, asin(s), az);
            num += gl_w[i] * gl_w[j] * cdl_emitter_radiance(e, w, w, w, NULL).cd_m2 * s;
        }
    /* both integrals over the same (s, az) box: its area cancels */
    return num / (0.5 * (s0 + s1));
}

cdl_status cdl_annual_sky_patches(const cdl_annual_hour *h, const cdl_reinhart_patches *p, double ground_reflectance,
                                  float *out, cdl_error *err)
{
    size_t K = (size_t)p->count;
    /* the ground lit by the sky and the sun, reflecting diffusely */
    double global = h->diffuse_lx + h->direct_normal_lx * sin(h->altitude_deg * CDL_DEG_TO_RAD);
    out[CDL_REINHART_GROUND] = (float)(ground_reflectance * global / CDL_PI);
    if (h->uniform) {
        for (size_t k = 1; k < K; ++k) out[k] = (float)(h->diffuse_lx / CDL_PI);
        return CDL_OK;
    }
    cdl_environment_params ep = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    ep.up = p->frame.n;
    ep.upper_hemisphere_only = 1;
    ep.sky = CDL_SKY_PEREZ;
    memcpy(ep.perez, h->perez, sizeof ep.perez);
    ep.sun = h->to_sun;
    ep.scale_to_horizontal = 1;
    ep.horizontal = cdl_lux(h->diffuse_lx);
    cdl_emitter *e = NULL;
    cdl_status st = cdl_emitter_create_environment(&ep, &e, err);
    if (st != CDL_OK) return st;
    for (size_t k = 1; k < K; ++k) out[k] = (float)patch_mean(p, e, (int)k);
    cdl_emitter_release(e);
    return CDL_OK;
}

static cdl_status fill_rows(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    const fill_job *jb = shared;
    size_t K = (size_t)jb->p->count;
    for (size_t r = begin; r < end; ++r) {
        const cdl_epw_hour *w = &jb->epw->hours[jb->row_hour[r]];
        cdl_status st = cdl_annual_sky_patches(&jb->out->hour[jb->row_hour[r]], jb->p, jb->o->ground_reflectance,
                                               jb->out->patch + cdl_rank_deal_row(jb->deal, r) * K, err);
        if (st != CDL_OK)
            return cdl_error_prefix(err, "line %d (month %d, day %d, hour %d): the Perez sky: ", w->line, w->month,
                                    w->day, w->hour);
    }
    return CDL_OK;
}

void cdl_annual_overcast_patches(const cdl_reinhart_patches *p, double *out)
{
    double Lz = 9.0 / (7.0 * CDL_PI);
    out[CDL_REINHART_GROUND] = 0.0;
    for (int k = 1; k < p->count; ++k) {
        double a0, a1, z0, z1;
        cdl_reinhart_patch_bounds(p, k, &a0, &a1, &z0, &z1);
        double s0 = sin(a0), s1 = sin(a1), q = s1 * s1 - s0 * s0;
        out[k] = Lz * (0.5 * q + 2.0 * (s1 * s1 * s1 - s0 * s0 * s0) / 3.0) / (1.5 * q);
    }
}

/* The sun at the middle of hour h of the file. */
static cdl_status place_sun(const cdl_epw *epw, const cdl_reinhart_patches *p, size_t h, cdl_annual_hour *out,
                            cdl_error *err)
{
    const cdl_epw_hour *w = &epw->hours[h];
    cdl_civil_time t = {epw->year, w->month, w->day, w->hour - 1, 30, 0.0, (int)lround(60.0 * epw->time_zone_h)};
    cdl_solar_site site = CDL_SOLAR_SITE_DEFAULT;
    site.latitude_deg = epw->latitude_deg;
    site.longitude_deg = epw->longitude_deg;
    site.elevation_m = epw->elevation_m;
    cdl_solar_position sp;
    cdl_status st = cdl_solar_position_compute(&site, &t, &sp, err);
    if (st != CDL_OK) return st;
    out->altitude_deg = sp.elevation_deg;
    out->azimuth_deg = sp.azimuth_deg;
    out->to_sun = cdl_reinhart_direction(p, sp.elevation_deg * CDL_DEG_TO_RAD, sp.azimuth_deg * CDL_DEG_TO_RAD);
    return CDL_OK;
}

/* The day of the year of a row (its place in the file: rows run from 1 January). */
static int day_of_year(size_t h)
{
    return (int)(h / 24) + 1;
}

/* An hour's Perez sky: *sky its coefficients, or a uniform fallback; 0
 * when the hour can give no light (left out). */
static int perez_hour(const cdl_epw *epw, size_t h, cdl_annual_hour *hr, cdl_annual_skies *out)
{
    const cdl_epw_hour *w = &epw->hours[h];
    double dew = w->dew_point_c;
    if (isnan(dew)) {
        dew = CDL_ANNUAL_DEW_POINT_C;
        out->dew_point_default_hours++;
    }
    cdl_perez_input in = {90.0 - hr->altitude_deg, day_of_year(h), 0, w->direct_normal_w_m2,
                          w->diffuse_horizontal_w_m2, dew, 1};
    cdl_perez_sky ps;
    cdl_error ignored;
    if (cdl_perez_sky_compute(&in, &ps, &ignored) == CDL_OK) {
        memcpy(hr->perez, ps.coefficients, sizeof hr->perez);
        hr->diffuse_lx = ps.diffuse_horizontal_lx;
        hr->direct_normal_lx = ps.direct_normal_lx;
        hr->clamped = ps.clamped;
        out->clamped_hours += ps.clamped != 0;
        return 1;
    }
    /* the model has no sky here (b >= 0 even clamped): a uniform sky of the
     * file's diffuse horizontal illuminance, and no sun */
    if (!(w->diffuse_horizontal_lx > 0.0)) return 0;
    hr->uniform = 1;
    hr->diffuse_lx = w->diffuse_horizontal_lx;
    hr->direct_normal_lx = 0.0;
    out->fallback_hours++;
    return 1;
}

/* The sun bins: the Tregenza patches the lit hours' suns fall in, each at
 * the direct-normal-weighted mean of their directions. */
static cdl_status sun_bins(const cdl_reinhart_patches *p, cdl_annual_skies *out, cdl_error *err)
{
    cdl_reinhart_patches t;
    cdl_status st = cdl_reinhart_init(&t, 1, p->frame.n, p->frame.s, err);
    if (st != CDL_OK) return st;
    cdl_vec3 sum[146];
    int index[146];
    for (int k = 0; k < t.count; ++k) {
        sum[k] = cdl_vec3_make(0.0, 0.0, 0.0);
        index[k] = -1;
    }
    for (size_t h = 0; h < out->hours; ++h) {
        cdl_annual_hour *hr = &out->hour[h];
        hr->sun = -1;
        if (hr->row < 0 || !(hr->direct_normal_lx > 0.0)) continue;
        int k = cdl_reinhart_patch_of(&t, hr->to_sun);
        sum[k] = cdl_vec3_madd(sum[k], hr->direct_normal_lx, hr->to_sun);
        if (index[k] < 0) index[k] = (int)out->sun_count++;
        hr->sun = index[k];
    }
    out->suns = malloc((out->sun_count ? out->sun_count : 1) * sizeof *out->suns);
    if (!out->suns) return cdl_error_out_of_memory(err);
    for (int k = 0; k < t.count; ++k)
        if (index[k] >= 0) out->suns[index[k]] = cdl_vec3_normalize(sum[k]);
    return CDL_OK;
}

/* Which hours give light, and what light (the rows); perez skies in *sky. */
static cdl_status classify_hours(const cdl_epw *epw, const cdl_annual_sky_options *o, const cdl_reinhart_patches *p,
                                 cdl_annual_skies *out, size_t *row_hour, cdl_error *err)
{
    for (size_t h = 0; h < epw->count; ++h) {
        const cdl_epw_hour *w = &epw->hours[h];
        cdl_annual_hour *hr = &out->hour[h];
        hr->row = -1;
        hr->sun = -1;
        cdl_status st = place_sun(epw, p, h, hr, err);
        if (st != CDL_OK) return st;
        if (o->kind == CDL_ANNUAL_SKY_CIE_OVERCAST) {
            if (isnan(w->diffuse_horizontal_lx))
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "line %d: field %d (diffuse horizontal illuminance, lx): expected a value for "
                                     "--sky cie_overcast, found the file's mark of a missing value",
                                     w->line, CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_ILLUMINANCE);
            if (!(w->diffuse_horizontal_lx > 0.0)) continue;
            hr->diffuse_lx = w->diffuse_horizontal_lx;
        } else {
            int light = w->diffuse_horizontal_w_m2 > 0.0 || w->direct_normal_w_m2 > 0.0;
            if (!(hr->altitude_deg > 0.0) || !(w->diffuse_horizontal_w_m2 > 0.0) || !perez_hour(epw, h, hr, out)) {
                if (light) {
                    out->left_out_hours++;
                    out->left_out_wh_m2 += w->diffuse_horizontal_w_m2 + w->direct_normal_w_m2;
                }
                continue;
            }
        }
        row_hour[out->rows] = h;
        hr->row = (int)out->rows++;
    }
    return CDL_OK;
}

cdl_status cdl_annual_skies_compute(const cdl_epw *epw, const cdl_annual_sky_options *o,
                                    const cdl_reinhart_patches *p, cdl_annual_skies *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    out->kind = o->kind;
    out->hours = epw->count;
    out->hour = calloc(epw->count, sizeof *out->hour);
    size_t *row_hour = calloc(epw->count, sizeof *row_hour);
    cdl_status st = out->hour && row_hour ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = classify_hours(epw, o, p, out, row_hour, err);
    /* rank 0 (or one process) a row for every lit hour, another rank its own */
    cdl_rank_deal deal = cdl_annual_skies_deal(o->ranks, out->rows);
    size_t rows = cdl_rank_deal_rows(&deal);
    if (st == CDL_OK && o->kind == CDL_ANNUAL_SKY_PEREZ &&
        !(out->patch = malloc((rows ? rows : 1) * (size_t)p->count * sizeof *out->patch)))
        st = cdl_error_out_of_memory(err);
    st = cdl_rank_agree(o->ranks, st, err);
    if (st == CDL_OK && o->kind == CDL_ANNUAL_SKY_PEREZ) {
        fill_job jb = {epw, p, o, out, row_hour, &deal};
        cdl_pool_task task = {.count = out->rows, .chunk = deal.unit, .run = fill_rows, .shared = &jb,
                              .stage = "skies", .outputs = {{out->patch, (size_t)p->count * sizeof *out->patch}}};
        cdl_progress_sink none = {0};
        cdl_workers workers = {.threads = o->threads > 0 ? o->threads : 1, .progress = &none, .ranks = o->ranks};
        st = cdl_pool_run_dealt(&task, &workers, &deal, err);
        if (st == CDL_OK) st = sun_bins(p, out, err);
    }
    free(row_hour);
    if (st != CDL_OK) cdl_annual_skies_release(out);
    return st;
}

void cdl_annual_skies_release(cdl_annual_skies *s)
{
    if (!s) return;
    free(s->hour);
    free(s->patch);
    free(s->suns);
    memset(s, 0, sizeof *s);
}

/* Hours differ in cost only as their sun does: units of 8 rows deal every
 * rank hours from the whole year. */
cdl_rank_deal cdl_annual_skies_deal(cdl_rank_group *ranks, size_t rows)
{
    return cdl_rank_deal_make(ranks, rows, 8);
}
