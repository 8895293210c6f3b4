/* annual.c - an annual daylight study, from the weather file to the files (see the header). */
#include "daylight/annual.h"

#include <cblas.h>
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/error_report.h"
#include "base/strings.h"
#include "daylight/annual_output.h"
#include "daylight/epw.h"
#include "daylight/occupancy.h"
#include "solver/daylight/daylight_coefficients.h"
#include "solver/output/grid_result.h"
#include "solver/output/json_numbers.h"
#include "solver/output/ranks_json.h"
#include "solver/output/solution_write.h"
#include "solver/pool.h"

/* Most paths a point's coefficients take (the cost's bound). */
#define ANNUAL_MAX_PATHS 65536.0

/* Everything a run holds. */
typedef struct annual_state {
    const cdl_scene *scene;
    cdl_annual_options o;
    const char *weather;
    const char *out_dir;
    int threads;
    cdl_rank_group *ranks;                /* NULL: alone */
    int root;                             /* 1 on rank 0 (or alone): the one that computes the hours and writes */
    double target;
    cdl_epw epw;
    unsigned char *occupied, *daylight;
    char occupancy[300];
    cdl_reinhart_patches patches;
    cdl_annual_skies skies;
    int *row_of_hour;                     /* per hour: its row of the hourly arrays, -1 for none */
    size_t *hour_of_row;                  /* per row: its hour */
    cdl_daylight_scene ds;
    double *overcast;                     /* cie_overcast: the sky of 1 lx horizontal over the patches */
    cJSON *grids;                         /* the summary's "grids" */
    uint64_t paths, rays;
    size_t exact_points, sampled_points;
    cdl_annual_result *result;
    cdl_rank_report *reports;             /* rank 0: every rank's (summary.json "ranks") */
} annual_state;

/* OpenBLAS's count of its own threads, where the BLAS is OpenBLAS (weak:
 * NULL with another BLAS, whose calls are then taken as single-threaded). */
extern void openblas_set_num_threads(int threads) __attribute__((weak));
extern int openblas_get_num_threads(void) __attribute__((weak));

/* Hours a BLAS call takes: a fixed block, so that each hour's row comes
 * from a product of the same shape whatever the threads and ranks. */
#define PRODUCT_ROWS 512

typedef struct product_job {
    const float *sky, *coef;
    size_t rows, points, patches;
    float *out;
} product_job;

static cdl_status product_blocks(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    (void)err;
    const product_job *jb = shared;
    for (size_t b = begin; b < end; ++b) {
        size_t r0 = b * PRODUCT_ROWS, n = jb->rows - r0 < PRODUCT_ROWS ? jb->rows - r0 : PRODUCT_ROWS;
        /* out (n x points) = sky (n x patches) coef^T (patches x points) */
        cblas_sgemm(CblasRowMajor, CblasNoTrans, CblasTrans, (int)n, (int)jb->points, (int)jb->patches, 1.0f,
                    jb->sky + r0 * jb->patches, (int)jb->patches, jb->coef, (int)jb->patches, 0.0f,
                    jb->out + r0 * jb->points, (int)jb->points);
    }
    return CDL_OK;
}

/* A threaded BLAS splits one product among threads as it sees the machine's
 * cores (and a launcher's binding), and its sums' rounding follows the split:
 * here the product is cut into blocks of PRODUCT_ROWS hours on Candela's
 * threads, each block one single-threaded call, so that the bytes depend on
 * neither the BLAS's threads nor Candela's. */
cdl_status cdl_annual_product(const float *sky, size_t rows, const float *coef, size_t points, size_t patches,
                              float *out, int threads, cdl_error *err)
{
    if (rows == 0 || points == 0) return CDL_OK;
    int blas_threads = openblas_get_num_threads && openblas_set_num_threads ? openblas_get_num_threads() : 0;
    if (blas_threads > 1) openblas_set_num_threads(1);
    product_job jb = {sky, coef, rows, points, patches, out};
    cdl_pool_task task = {.count = (rows + PRODUCT_ROWS - 1) / PRODUCT_ROWS, .chunk = 1, .run = product_blocks,
                          .shared = &jb, .stage = "hours"};
    cdl_status st = cdl_pool_run(&task, threads, NULL, err);
    if (blas_threads > 1) openblas_set_num_threads(blas_threads);
    return st;
}

/* ---- the year --------------------------------------------------------------------- */

static cdl_status read_year(annual_state *s, cdl_error *err)
{
    cdl_status st = cdl_epw_read(s->weather, &s->epw, err);
    if (st != CDL_OK) return st;
    size_t H = s->epw.count;
    s->occupied = calloc(H, 1);
    s->daylight = calloc(H, 1);
    double *diffuse = malloc(H * sizeof *diffuse);
    if (!s->occupied || !s->daylight || !diffuse) {
        free(diffuse);
        return cdl_error_out_of_memory(err);
    }
    st = cdl_occupancy_read(s->o.occupancy, &s->epw, s->occupied, s->occupancy, sizeof s->occupancy, err);
    if (st != CDL_OK) {
        free(diffuse);
        return cdl_error_prefix(err, "--occupancy: ");
    }
    /* the daylight hours by the file's diffuse horizontal illuminance, or
     * its irradiance where any illuminance is missing (the ranking is the same
     * but for the efficacy's variation) */
    int all = 1;
    for (size_t h = 0; h < H; ++h) all &= !isnan(s->epw.hours[h].diffuse_horizontal_lx);
    for (size_t h = 0; h < H; ++h)
        diffuse[h] = all ? s->epw.hours[h].diffuse_horizontal_lx : s->epw.hours[h].diffuse_horizontal_w_m2;
    st = cdl_annual_daylight_hours(diffuse, H, s->daylight, err);
    free(diffuse);
    return st;
}

/* The patches (every rank; agreed before the skies, which the ranks share). */
static cdl_status make_patches(annual_state *s, cdl_error *err)
{
    /* the overcast sky's single column over the finest patches (its luminance
     * taken as each patch's mean: 1.5-degree rows) */
    int mf = s->o.sky == CDL_ANNUAL_SKY_CIE_OVERCAST ? CDL_REINHART_MAX_MF : s->o.mf;
    cdl_status st = cdl_reinhart_init(&s->patches, mf, cdl_vec3_make(0.0, 0.0, 1.0), s->o.north, err);
    return st != CDL_OK ? cdl_error_prefix(err, "--north: ") : CDL_OK;
}

/* The year's skies (shared by the ranks: agreed, or failed in an exchange),
 * then each hour's row and each row's hour. */
static cdl_status make_skies(annual_state *s, cdl_error *err)
{
    cdl_annual_sky_options so = {s->o.sky, s->o.ground_reflectance, s->threads, s->ranks};
    cdl_status st = cdl_annual_skies_compute(&s->epw, &so, &s->patches, &s->skies, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", s->weather);
    s->row_of_hour = malloc(s->epw.count * sizeof *s->row_of_hour);
    if (!s->row_of_hour) return cdl_error_out_of_memory(err);
    s->hour_of_row = malloc((s->skies.rows ? s->skies.rows : 1) * sizeof *s->hour_of_row);
    if (!s->hour_of_row) return cdl_error_out_of_memory(err);
    for (size_t h = 0; h < s->epw.count; ++h) {
        s->row_of_hour[h] = s->skies.hour[h].row;
        if (s->row_of_hour[h] >= 0) s->hour_of_row[s->row_of_hour[h]] = h;
    }
    return CDL_OK;
}

/* ---- perez: the coefficients and the hours ------------------------------------------ */

typedef struct sun_job {
    const annual_state *s;
    size_t g, points;
    float *E_sun;
    const cdl_rank_deal *deal;            /* row r at cdl_rank_deal_row(deal, r) */
} sun_job;

/* The direct sun of each row's hour: E_dn max(0, n.s) T at every point. */
static cdl_status direct_suns(void *shared, void *local, size_t begin, size_t end, cdl_error *err)
{
    (void)local;
    (void)err;
    const sun_job *jb = shared;
    for (size_t r = begin; r < end; ++r) {
        const cdl_annual_hour *hr = &jb->s->skies.hour[jb->s->hour_of_row[r]];
        float *row = jb->E_sun + cdl_rank_deal_row(jb->deal, r) * jb->points;
        if (!(hr->direct_normal_lx > 0.0)) {
            memset(row, 0, jb->points * sizeof *row);
            continue;
        }
        cdl_daylight_direct_sun(&jb->s->ds, jb->g, hr->to_sun, row);
        for (size_t i = 0; i < jb->points; ++i) row[i] = (float)(hr->direct_normal_lx * row[i]);
    }
    return CDL_OK;
}

/* Probe hours for the patches' discretisation: each month's lit hour of the
 * greatest direct normal illuminance (of the greatest diffuse where none has
 * sun); their rows into rows[12], how many returned. */
static size_t probe_rows(const annual_state *s, size_t rows[12])
{
    size_t count = 0;
    for (int month = 1; month <= 12; ++month) {
        int best = -1;
        double score = 0.0;
        for (size_t h = 0; h < s->skies.hours; ++h) {
            const cdl_annual_hour *hr = &s->skies.hour[h];
            if (s->epw.hours[h].month != month || hr->row < 0) continue;
            double v = hr->direct_normal_lx * 1e6 + hr->diffuse_lx;
            if (best < 0 || v > score) {
                best = hr->row;
                score = v;
            }
        }
        if (best >= 0) rows[count++] = (size_t)best;
    }
    return count;
}

/* Rank 0's part of the discretisation: the probe hours through the coarse
 * patches (c's direct part) and the fine ones (f's), into disc. */
static cdl_status discretisation_probes(const annual_state *s, const cdl_daylight_grid_coefficients *c,
                                        const cdl_reinhart_patches *fine, const cdl_daylight_grid_coefficients *f,
                                        const float *E, double *disc, cdl_error *err)
{
    size_t N = c->points, K = c->patches;
    size_t rows[12], P = probe_rows(s, rows), KF = (size_t)fine->count;
    float *sky = malloc(KF * sizeof *sky);
    double *top = calloc(N ? N : 1, sizeof *top);
    cdl_status st = sky && top ? CDL_OK : cdl_error_out_of_memory(err);
    for (size_t q = 0; st == CDL_OK && q < P; ++q)
        for (size_t i = 0; i < N; ++i) top[i] = fmax(top[i], E[rows[q] * N + i]);
    for (size_t q = 0; st == CDL_OK && q < P; ++q) {
        const cdl_annual_hour *hr = &s->skies.hour[s->hour_of_row[rows[q]]];
        st = cdl_annual_sky_patches(hr, fine, s->o.ground_reflectance, sky, err);
        const float *coarse = s->skies.patch + rows[q] * K;
        for (size_t i = 0; st == CDL_OK && i < N; ++i) {
            double Et = E[rows[q] * N + i];
            if (!c->exact[i] || !f->exact[i] || !(Et > 0.01 * top[i])) continue;
            double Em = 0.0, Ef = 0.0;
            for (size_t k = 0; k < K; ++k) Em += (double)c->direct[i * K + k] * coarse[k];
            for (size_t k = 0; k < KF; ++k) Ef += (double)f->sky[i * KF + k] * sky[k];
            disc[i] = fmax(disc[i], 1.5 * fabs(Em - Ef) / Et);
        }
    }
    free(sky);
    free(top);
    return st;
}

/* The patches' discretisation at each point, estimated: the direct light of
 * the probe hours' skies through these patches and through patches half
 * their size (MF doubled; the direct part exact both ways), the difference
 * times 1.5 (the error falls at least threefold when the patches halve:
 * measured 3.4 and 4.4 times from MF 1 to 2 and 2 to 4 on a window room),
 * relative to the hour's E at the point; the largest over the probes (hours
 * where the point gets less than 1 % of its brightest probe left out).
 * 0 where the direct part was sampled, or MF 8 cannot be halved. */
static cdl_status discretisation(annual_state *s, size_t g, const cdl_daylight_grid_coefficients *c, const float *E,
                                 double *disc, cdl_error *err)
{
    size_t N = c->points;
    if (s->root) memset(disc, 0, N * sizeof *disc);
    if (2 * s->patches.mf > CDL_REINHART_MAX_MF) return CDL_OK;
    cdl_reinhart_patches fine;
    cdl_status st = cdl_rank_agree(
        s->ranks, cdl_reinhart_init(&fine, 2 * s->patches.mf, s->patches.frame.n, s->patches.frame.s, err), err);
    if (st != CDL_OK) return st;
    /* the finer patches' direct part, shared by the ranks */
    cdl_daylight_coefficient_options co = {.patches = &fine, .target = s->target, .direct_only = 1,
                                           .seed = s->scene->settings.seed, .threads = s->threads,
                                           .ranks = s->ranks, .max_paths = 1.0};
    cdl_daylight_grid_coefficients f;
    st = cdl_daylight_coefficients_compute(&s->ds, g, &co, &f, err);
    if (st != CDL_OK) return st;
    if (s->root) st = discretisation_probes(s, c, &fine, &f, E, disc, err);
    cdl_daylight_coefficients_release(&f);
    return cdl_rank_agree(s->ranks, st, err);
}

/* Grid g's hours under the Perez skies: E (rows x points), E_sun likewise
 * (rank 0; elsewhere both NULL). */
static cdl_status perez_hours(annual_state *s, size_t g, float **E_out, float **E_sun_out, double *rel_stderr,
                              cdl_daylight_grid_coefficients *c, cdl_error *err)
{
    size_t N = s->ds.grids[g].count, R = s->skies.rows, K = (size_t)s->patches.count;
    cdl_daylight_coefficient_options co = {.patches = &s->patches, .suns = s->skies.suns,
                                           .sun_count = s->skies.sun_count, .target = s->target, .keep_direct = 1,
                                           .seed = s->scene->settings.seed, .threads = s->threads,
                                           .ranks = s->ranks, .max_paths = ANNUAL_MAX_PATHS,
                                           .progress = s->o.progress};
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_daylight_coefficients_compute(&s->ds, g, &co, c, err);
    if (st != CDL_OK) return st;
    s->result->seconds_coefficients += cdl_pool_now_seconds() - t0;
    if (s->root) memcpy(rel_stderr, c->sky_rel_stderr, N * sizeof *rel_stderr);
    /* the direct sun hour by hour, the hours dealt among the ranks (units of
     * 16: a chunk of the pool); rank 0 gets every hour's, and alone makes E */
    cdl_rank_deal deal = cdl_rank_deal_make(s->ranks, R, 16);
    size_t sun_rows = cdl_rank_deal_rows(&deal);
    float *E = s->root ? malloc((R ? R : 1) * (N ? N : 1) * sizeof *E) : NULL;
    float *E_sun = malloc((sun_rows ? sun_rows : 1) * (N ? N : 1) * sizeof *E_sun);
    st = cdl_rank_agree(s->ranks, (E || !s->root) && E_sun ? CDL_OK : cdl_error_out_of_memory(err), err);
    t0 = cdl_pool_now_seconds();
    sun_job jb = {s, g, N, E_sun, &deal};
    cdl_pool_task task = {.count = R, .chunk = deal.unit, .run = direct_suns, .shared = &jb, .stage = "direct sun",
                          .outputs = {{E_sun, N * sizeof *E_sun}}};
    cdl_workers workers = {.threads = s->threads, .progress = &s->o.progress, .ranks = s->ranks};
    if (st == CDL_OK) st = cdl_pool_run_dealt(&task, &workers, &deal, err);
    s->result->seconds_suns += cdl_pool_now_seconds() - t0;
    t0 = cdl_pool_now_seconds();
    if (st == CDL_OK && s->root) st = cdl_annual_product(s->skies.patch, R, c->sky, N, K, E, s->threads, err);
    /* each hour's sun: its direct light traced, its interreflection by its bin */
    for (size_t h = 0; st == CDL_OK && s->root && h < s->skies.hours; ++h) {
        const cdl_annual_hour *hr = &s->skies.hour[h];
        if (hr->row < 0 || hr->sun < 0) continue;
        float *e = E + (size_t)hr->row * N;
        const float *d = E_sun + (size_t)hr->row * N;
        float dn = (float)hr->direct_normal_lx;
        for (size_t i = 0; i < N; ++i) e[i] += d[i] + dn * c->sun[i * c->suns + (size_t)hr->sun];
    }
    s->result->seconds_hours += cdl_pool_now_seconds() - t0;
    /* the stated error: the sampling's and the patches' (estimated) */
    double *disc = s->root ? malloc((N ? N : 1) * sizeof *disc) : NULL;
    if (st == CDL_OK) st = cdl_rank_agree(s->ranks, disc || !s->root ? CDL_OK : cdl_error_out_of_memory(err), err);
    if (st == CDL_OK) st = discretisation(s, g, c, E, disc, err);
    for (size_t i = 0; st == CDL_OK && s->root && i < N; ++i) {
        s->result->grids[g].discretisation_mean_rel += disc[i] / (double)N;
        s->result->grids[g].discretisation_max_rel = fmax(s->result->grids[g].discretisation_max_rel, disc[i]);
        rel_stderr[i] = hypot(rel_stderr[i], disc[i]);
    }
    free(disc);
    if (st != CDL_OK || !s->root) {
        free(E);
        free(E_sun);
        return st;
    }
    *E_out = E;
    *E_sun_out = E_sun;
    return CDL_OK;
}

/* Grid g's hours under the overcast sky: its one coefficient per point, E
 * under the sky of 1 lx horizontal (the daylight factor / 100, interreflection
 * included), times each hour's diffuse horizontal illuminance (rank 0;
 * elsewhere E NULL). */
static cdl_status overcast_hours(annual_state *s, size_t g, float **E_out, double *rel_stderr, double *DF,
                                 cdl_daylight_grid_coefficients *c, cdl_error *err)
{
    size_t N = s->ds.grids[g].count, R = s->skies.rows;
    cdl_daylight_coefficient_options co = {.patches = &s->patches, .target = s->target,
                                           .reference_sky = s->overcast, .collapse = 1,
                                           .seed = s->scene->settings.seed, .threads = s->threads,
                                           .ranks = s->ranks, .max_paths = ANNUAL_MAX_PATHS,
                                           .progress = s->o.progress};
    double t0 = cdl_pool_now_seconds();
    cdl_status st = cdl_daylight_coefficients_compute(&s->ds, g, &co, c, err);
    if (st != CDL_OK) return st;
    s->result->seconds_coefficients += cdl_pool_now_seconds() - t0;
    /* rank 0 alone makes the hours */
    float *E = NULL;
    if (s->root) {
        for (size_t i = 0; i < N; ++i) {
            DF[i] = 100.0 * (double)c->sky[i];
            rel_stderr[i] = c->sky_rel_stderr[i];
        }
        if (!(E = malloc((R ? R : 1) * (N ? N : 1) * sizeof *E))) st = cdl_error_out_of_memory(err);
    }
    for (size_t h = 0; E && h < s->skies.hours; ++h) {
        const cdl_annual_hour *hr = &s->skies.hour[h];
        if (hr->row < 0) continue;
        for (size_t i = 0; i < N; ++i) E[(size_t)hr->row * N + i] = (float)(DF[i] / 100.0 * hr->diffuse_lx);
    }
    *E_out = E;
    return cdl_rank_agree(s->ranks, st, err);
}

/* ---- one grid ----------------------------------------------------------------------- */

/* Numbers into o under their keys. */
typedef struct named_number {
    const char *key;
    double value;
} named_number;

static void add_numbers(cJSON *o, const named_number *v, size_t count)
{
    for (size_t i = 0; i < count; ++i) cJSON_AddNumberToObject(o, v[i].key, v[i].value);
}

static cJSON *grid_summary(const cdl_annual_grid_result *r, const cdl_daylight_grid_coefficients *c)
{
    const cdl_grid_annual_metrics *m = &r->metrics;
    cJSON *o = cJSON_CreateObject();
    const named_number values[] = {{"count", (double)r->points},
                                   {"sDA300_percent", m->sDA300},
                                   {"ASE1000_percent", m->ASE1000},
                                   {"DA300_mean_percent", m->DA300_mean},
                                   {"UDI_fell_short_percent", m->UDI_fell_short},
                                   {"UDI_percent", m->UDI},
                                   {"UDI_exceeded_percent", m->UDI_exceeded}};
    add_numbers(o, values, sizeof values / sizeof values[0]);
    cJSON *en = cJSON_AddObjectToObject(o, "EN17037");
    cJSON_AddStringToObject(en, "level", m->en_level);
    for (int l = 0; l < CDL_EN17037_LEVELS; ++l) {
        cJSON *lv = cJSON_AddObjectToObject(en, cdl_en17037_levels[l].name);
        cJSON_AddNumberToObject(lv, "target_lx", cdl_en17037_levels[l].target_lx);
        cJSON_AddNumberToObject(lv, "minimum_target_lx", cdl_en17037_levels[l].minimum_lx);
        cJSON_AddNumberToObject(lv, "target_hours_percent", m->en_target_hours[l]);
        cJSON_AddNumberToObject(lv, "minimum_hours_percent", m->en_minimum_hours[l]);
        cJSON_AddBoolToObject(lv, "met", m->en_met[l]);
    }
    cJSON *co = cJSON_AddObjectToObject(o, "coefficients");
    cJSON_AddNumberToObject(co, "stderr_mean_rel", r->stderr_mean_rel);
    cJSON_AddNumberToObject(co, "stderr_max_rel", r->stderr_max_rel);
    cJSON_AddNumberToObject(co, "discretisation_mean_rel", r->discretisation_mean_rel);
    cJSON_AddNumberToObject(co, "discretisation_max_rel", r->discretisation_max_rel);
    if (c) {
        cJSON_AddNumberToObject(co, "exact_direct_points", (double)c->routes.exact);
        cJSON_AddNumberToObject(co, "through_glass_direct_points", (double)c->routes.through_glass);
        size_t sampled = 0;
        for (int k = 0; k < CDL_ROUTE_COUNT; ++k) sampled += c->routes.sampled[k];
        cJSON_AddNumberToObject(co, "sampled_direct_points", (double)sampled);
        cJSON_AddNumberToObject(co, "paths", (double)c->paths);
        cJSON_AddNumberToObject(co, "rays", (double)c->rays);
    }
    return o;
}

/* Rank 0's part of grid g: its metrics and files from the hours E (and E_sun). */
static cdl_status finish_grid(annual_state *s, size_t g, const float *E, const float *E_sun, const double *rel,
                              const double *DF, const cdl_daylight_grid_coefficients *c, cdl_error *err)
{
    int overcast = s->o.sky == CDL_ANNUAL_SKY_CIE_OVERCAST;
    const cdl_grid *grid = &s->ds.grids[g];
    size_t N = grid->count;
    cdl_annual_grid_result *r = &s->result->grids[g];
    cdl_point_metrics *pm = calloc(N ? N : 1, sizeof *pm);
    if (!pm) return cdl_error_out_of_memory(err);
    double t0 = cdl_pool_now_seconds();
    cdl_annual_input in = {s->epw.count, N, E, E_sun, s->row_of_hour, s->occupied, s->daylight, grid->weights};
    cdl_status st = cdl_annual_metrics_compute(&in, pm, &r->metrics, err);
    s->result->seconds_metrics += cdl_pool_now_seconds() - t0;
    for (size_t i = 0; i < N; ++i) {
        r->stderr_mean_rel += rel[i] / (double)N;
        if (rel[i] > r->stderr_max_rel) r->stderr_max_rel = rel[i];
    }
    double ase_max = 0.0;
    for (size_t i = 0; i < N; ++i) ase_max = fmax(ase_max, pm[i].ASE_hours);
    cdl_annual_grid_files files = {r->name, s->scene->grids[g].kind == CDL_GRID_POLYGON, grid, pm, rel,
                                   overcast ? DF : NULL, ase_max};
    const char *ocio = s->o.ocio_config ? s->o.ocio_config : cdl_default_ocio_config();
    if (st == CDL_OK) st = cdl_annual_write_grid(s->out_dir, &files, ocio, err);
    char name[128];
    snprintf(name, sizeof name, "%s.hourly", r->name);
    char *path = st == CDL_OK ? cdl_path_join(s->out_dir, name, ".bin") : NULL;
    if (st == CDL_OK && !path) st = cdl_error_out_of_memory(err);
    if (st == CDL_OK)
        st = cdl_annual_write_hourly(path, CDL_HOURLY_ILLUMINANCE, s->epw.count, N, s->row_of_hour, E, err);
    free(path);
    if (st == CDL_OK && E_sun) {
        snprintf(name, sizeof name, "%s.sun", r->name);
        path = cdl_path_join(s->out_dir, name, ".bin");
        st = path ? cdl_annual_write_hourly(path, CDL_HOURLY_DIRECT_SUN, s->epw.count, N, s->row_of_hour, E_sun, err)
                  : cdl_error_out_of_memory(err);
        free(path);
    }
    if (st == CDL_OK) cJSON_AddItemToObject(s->grids, r->name, grid_summary(r, c));
    free(pm);
    return st;
}

/* Grid g: its coefficients and direct sun (shared by the ranks), then on
 * rank 0 its hours, metrics and files; the ranks agree on how it went. */
static cdl_status run_grid(annual_state *s, size_t g, cdl_error *err)
{
    int overcast = s->o.sky == CDL_ANNUAL_SKY_CIE_OVERCAST;
    size_t N = s->ds.grids[g].count;
    cdl_annual_grid_result *r = &s->result->grids[g];
    r->points = N;
    r->name = cdl_string_copy(s->scene->grids[g].name);
    /* per point on rank 0: the stated error and DF */
    double *rel = s->root ? calloc(N ? N : 1, sizeof *rel) : NULL, *DF = s->root ? calloc(N ? N : 1, sizeof *DF) : NULL;
    float *E = NULL, *E_sun = NULL;
    cdl_daylight_grid_coefficients c;
    memset(&c, 0, sizeof c);
    int ok = r->name && (!s->root || (rel && DF));
    cdl_status st = cdl_rank_agree(s->ranks, ok ? CDL_OK : cdl_error_out_of_memory(err), err);
    /* the hours: agreed by the ranks, or failed in an exchange (the caller ends the job) */
    if (st == CDL_OK)
        st = overcast ? overcast_hours(s, g, &E, rel, DF, &c, err) : perez_hours(s, g, &E, &E_sun, rel, &c, err);
    int agree = st == CDL_OK;
    if (st == CDL_OK && s->root) st = finish_grid(s, g, E, E_sun, rel, DF, &c, err);
    cdl_daylight_coefficients_release(&c);
    free(E);
    free(E_sun);
    free(rel);
    free(DF);
    return agree ? cdl_rank_agree(s->ranks, st, err) : st;
}

/* ---- summary.json ------------------------------------------------------------------- */

static void add_vec3(cJSON *o, const char *key, cdl_vec3 v)
{
    const double a[3] = {v.x, v.y, v.z};
    cJSON_AddItemToObject(o, key, cJSON_CreateDoubleArray(a, 3));
}

static cJSON *weather_summary(const annual_state *s)
{
    cJSON *w = cJSON_CreateObject();
    cJSON_AddStringToObject(w, "file", s->weather);
    cJSON_AddStringToObject(w, "city", s->epw.city);
    cJSON_AddStringToObject(w, "country", s->epw.country);
    cJSON_AddNumberToObject(w, "latitude_deg", s->epw.latitude_deg);
    cJSON_AddNumberToObject(w, "longitude_deg", s->epw.longitude_deg);
    cJSON_AddNumberToObject(w, "time_zone_h", s->epw.time_zone_h);
    cJSON_AddNumberToObject(w, "elevation_m", s->epw.elevation_m);
    cJSON_AddNumberToObject(w, "hours", (double)s->epw.count);
    cJSON_AddNumberToObject(w, "sun_year", s->epw.year);
    cJSON_AddBoolToObject(w, "sun_year_from_file", s->epw.year_from_file);
    cJSON_AddNumberToObject(w, "dew_point_missing_hours", (double)s->epw.dew_point_missing);
    return w;
}

static cJSON *sky_summary(const annual_state *s)
{
    const cdl_annual_skies *k = &s->skies;
    cJSON *o = cJSON_CreateObject();
    int perez = s->o.sky == CDL_ANNUAL_SKY_PEREZ;
    cJSON_AddStringToObject(o, "model", perez ? "perez" : "cie_overcast");
    cJSON *pt = cJSON_AddObjectToObject(o, "patches");
    cJSON_AddNumberToObject(pt, "mf", s->patches.mf);
    cJSON_AddNumberToObject(pt, "sky_patches", s->patches.count - 1);
    cJSON_AddStringToObject(pt, "convention",
                            "Reinhart (reinhartb.cal): 144 MF^2 + 1 sky patches, rows of 90 / (7 MF + 0.5) degrees "
                            "from the horizon, the cap last, each row from north eastwards; column 0 the ground");
    cJSON_AddStringToObject(o, "words",
                            perez ? "Perez all-weather sky (1993) of each hour's direct normal and diffuse horizontal "
                                    "irradiance and dew point, Perez 1990 efficacies; the sun at the hour's middle by "
                                    "the SPA, its direct light traced each hour, its interreflection by sun bins"
                                  : "CIE standard overcast sky scaled to each hour's diffuse horizontal illuminance "
                                    "(the file's field 19); no sun: every hour is the daylight factor times it");
    cJSON_AddNumberToObject(o, "hours_with_light", (double)k->rows);
    if (perez) {
        cJSON_AddNumberToObject(o, "ground_reflectance", s->o.ground_reflectance);
        cJSON_AddNumberToObject(o, "sun_bins", (double)k->sun_count);
        cJSON_AddNumberToObject(o, "clamped_hours", (double)k->clamped_hours);
        cJSON_AddNumberToObject(o, "fallback_hours", (double)k->fallback_hours);
        cJSON_AddNumberToObject(o, "dew_point_default_hours", (double)k->dew_point_default_hours);
        cJSON_AddNumberToObject(o, "left_out_hours", (double)k->left_out_hours);
        cJSON_AddNumberToObject(o, "left_out_irradiation_wh_m2", k->left_out_wh_m2);
    }
    add_vec3(o, "north", s->patches.frame.s);
    add_vec3(o, "up", s->patches.frame.n);
    return o;
}

static cdl_status write_summary(annual_state *s, cdl_error *err)
{
    cdl_annual_result *r = s->result;
    cJSON *root = cJSON_CreateObject();
    cJSON *a = cJSON_AddObjectToObject(root, "annual");
    cJSON_AddStringToObject(root, "candela_version", CANDELA_VERSION);
    cJSON_AddStringToObject(root, "scene", s->scene->path);
    cJSON_AddItemToObject(a, "weather", weather_summary(s));
    cJSON_AddItemToObject(a, "sky", sky_summary(s));
    cJSON_AddStringToObject(a, "occupancy", s->occupancy);
    cJSON_AddNumberToObject(a, "occupied_hours", (double)r->occupied_hours);
    cJSON_AddNumberToObject(a, "daylight_hours", (double)r->daylight_hours);
    cJSON_AddStringToObject(a, "daylight_hours_words",
                            "EN 17037: the half of the year's hours with the greatest diffuse horizontal illuminance");
    cJSON *co = cJSON_AddObjectToObject(a, "coefficients");
    cJSON_AddNumberToObject(co, "target_error", s->target);
    cJSON_AddStringToObject(co, "stderr_words",
                            s->o.sky == CDL_ANNUAL_SKY_PEREZ
                                ? "per point, the relative standard error of the sampled part under a uniform sky "
                                  "(direct sky exact where the exact route sees it; interreflection by paths) and the "
                                  "patches' discretisation (estimated from the direct light of each month's sunniest "
                                  "hour through patches half the size, 1.5 x the difference), added in quadrature"
                                : "per point, the relative standard error of E under the overcast sky (its "
                                  "interreflection by paths; direct light exact where the exact route sees the sky); "
                                  "the sky's luminance taken as its mean over patches of 1.5 degrees (MF 8)");
    cJSON_AddNumberToObject(co, "seed", (double)s->scene->settings.seed);
    cJSON_AddNumberToObject(co, "threads", s->threads);
    const named_number seconds[] = {{"skies", r->seconds_skies},
                                    {"coefficients", r->seconds_coefficients},
                                    {"direct_sun", r->seconds_suns},
                                    {"hours", r->seconds_hours},
                                    {"metrics", r->seconds_metrics}};
    add_numbers(cJSON_AddObjectToObject(a, "seconds"), seconds, sizeof seconds / sizeof seconds[0]);
    cdl_ranks_json_add(root, s->reports, (size_t)cdl_rank_group_count(s->ranks));
    cJSON_AddItemToObject(root, "grids", s->grids);
    s->grids = NULL;
    cdl_json_numbers_exact(root);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return cdl_error_out_of_memory(err);
    char *path = cdl_path_join(s->out_dir, "summary", ".json");
    cdl_status st = path ? CDL_OK : cdl_error_out_of_memory(err);
    cdl_atomic_file f;
    if (st == CDL_OK) st = cdl_atomic_file_open(&f, path, err);
    if (st == CDL_OK) {
        fputs(text, f.fp);
        fputc('\n', f.fp);
        st = cdl_atomic_file_commit(&f, err);
    }
    free(path);
    free(text);
    return st;
}

/* annual.csv: a row per grid, the grid's metrics as summary.json has them. */
static cdl_status write_grid_table(const annual_state *s, cdl_error *err)
{
    char *path = cdl_path_join(s->out_dir, "annual", ".csv");
    if (!path) return cdl_error_out_of_memory(err);
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    free(path);
    if (st != CDL_OK) return st;
    fputs("grid,points,sDA300_percent,ASE1000_percent,DA300_mean_percent,UDI_fell_short_percent,UDI_percent,"
          "UDI_exceeded_percent,EN17037_level,EN17037_minimum_met,EN17037_medium_met,EN17037_high_met,"
          "stderr_mean_rel,stderr_max_rel\n",
          f.fp);
    for (size_t g = 0; g < s->result->grid_count; ++g) {
        const cdl_annual_grid_result *r = &s->result->grids[g];
        const cdl_grid_annual_metrics *m = &r->metrics;
        fprintf(f.fp, "%s,%zu", r->name, r->points);
        const double v[6] = {m->sDA300, m->ASE1000, m->DA300_mean, m->UDI_fell_short, m->UDI, m->UDI_exceeded};
        for (int k = 0; k < 6; ++k) {
            char num[CDL_CSV_NUMBER_SIZE];
            cdl_csv_format_number(v[k], num);
            fprintf(f.fp, ",%s", num);
        }
        fprintf(f.fp, ",%s,%d,%d,%d", m->en_level, m->en_met[0], m->en_met[1], m->en_met[2]);
        char a[CDL_CSV_NUMBER_SIZE], b[CDL_CSV_NUMBER_SIZE];
        cdl_csv_format_number(r->stderr_mean_rel, a);
        cdl_csv_format_number(r->stderr_max_rel, b);
        fprintf(f.fp, ",%s,%s\n", a, b);
    }
    return cdl_atomic_file_commit(&f, err);
}

/* ---- the run ------------------------------------------------------------------------ */

static void state_release(annual_state *s)
{
    cdl_epw_release(&s->epw);
    free(s->occupied);
    free(s->daylight);
    cdl_annual_skies_release(&s->skies);
    free(s->row_of_hour);
    free(s->hour_of_row);
    cdl_daylight_scene_release(&s->ds);
    free(s->overcast);
    cJSON_Delete(s->grids);
    free(s->reports);
}

static cdl_status check_options(const cdl_annual_options *o, cdl_error *err)
{
    if (o->mf != 1 && o->mf != 2 && o->mf != 4)
        return cdl_error_set(err, CDL_ERR_USAGE, "--mf: expected 1, 2 or 4, found %d", o->mf);
    if (!(o->ground_reflectance >= 0.0 && o->ground_reflectance <= 1.0))
        return cdl_error_set(err, CDL_ERR_USAGE, "--ground-reflectance: expected a number in [0, 1], found %g",
                             o->ground_reflectance);
    return CDL_OK;
}

cdl_status cdl_annual_run(const cdl_scene *scene, const char *weather, const cdl_annual_options *options,
                          const char *out_dir, cdl_annual_result *result, cdl_error *err)
{
    memset(result, 0, sizeof *result);
    double t_start = cdl_pool_now_seconds();
    annual_state s;
    memset(&s, 0, sizeof s);
    s.scene = scene;
    s.o = *options;
    s.weather = weather;
    s.out_dir = out_dir;
    s.result = result;
    s.target = cdl_solver_settings_target(&scene->settings);
    s.ranks = options->ranks;
    s.root = cdl_rank_group_rank(s.ranks) == 0;
    s.threads = options->threads >= 0 ? options->threads : scene->settings.threads;
    if (s.threads <= 0) s.threads = cdl_pool_default_threads(s.ranks ? s.ranks->ranks.local_count : 1);
    double cpu0 = cdl_pool_cpu_seconds();
    /* Each rank's own steps, agreed: a file one rank cannot read ends every rank. */
    cdl_status st = check_options(options, err);
    /* the scene first: a scene an annual study cannot take is said before the weather is read */
    if (st == CDL_OK) st = cdl_daylight_scene_build(scene, &s.ds, err);
    if (st == CDL_OK) st = read_year(&s, err);
    if (st == CDL_OK) st = make_patches(&s, err);
    st = cdl_rank_agree(s.ranks, st, err);
    double t0 = cdl_pool_now_seconds();
    if (st == CDL_OK) st = make_skies(&s, err);
    result->seconds_skies = cdl_pool_now_seconds() - t0;
    if (st == CDL_OK) {
        if (s.o.sky == CDL_ANNUAL_SKY_CIE_OVERCAST) {
            if (!(s.overcast = malloc((size_t)s.patches.count * sizeof *s.overcast))) st = cdl_error_out_of_memory(err);
            else cdl_annual_overcast_patches(&s.patches, s.overcast);
        }
        result->grid_count = scene->grid_count;
        result->grids = calloc(scene->grid_count ? scene->grid_count : 1, sizeof *result->grids);
        s.grids = cJSON_CreateObject();
        if (st == CDL_OK && (!result->grids || !s.grids)) st = cdl_error_out_of_memory(err);
        st = cdl_rank_agree(s.ranks, st, err);
    }
    for (size_t g = 0; st == CDL_OK && g < scene->grid_count; ++g) st = run_grid(&s, g, err);
    if (st == CDL_OK) {
        result->hours = s.epw.count;
        result->lit_hours = s.skies.rows;
        result->occupied_hours = scene->grid_count ? result->grids[0].metrics.occupied_hours : 0;
        result->daylight_hours = scene->grid_count ? result->grids[0].metrics.daylight_hours : 0;
        result->seconds_total = cdl_pool_now_seconds() - t_start;
        double work = result->seconds_skies + result->seconds_coefficients + result->seconds_suns;
        st = cdl_rank_reports_gather(s.ranks, s.threads, t_start, cpu0, work, &s.reports, err);
        /* rank 0 writes the tables; every rank learns how it went */
        if (st == CDL_OK) {
            if (s.root) st = write_grid_table(&s, err);
            if (st == CDL_OK && s.root) st = write_summary(&s, err);
            st = cdl_rank_agree(s.ranks, st, err);
        }
    }
    state_release(&s);
    if (st != CDL_OK) cdl_annual_result_release(result);
    return st;
}

void cdl_annual_result_release(cdl_annual_result *result)
{
    if (!result) return;
    for (size_t g = 0; result->grids && g < result->grid_count; ++g) free(result->grids[g].name);
    free(result->grids);
    memset(result, 0, sizeof *result);
}
