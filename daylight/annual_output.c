/* annual_output.c - an annual study's hourly files, CSV and maps (see the header). */
#include "daylight/annual_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/error_report.h"
#include "base/file_bytes.h"
#include "base/strings.h"
#include "solver/output/grid_result.h"

/* ---- hourly files ----------------------------------------------------------------- */

static void put_u32(unsigned char *b, uint32_t v)
{
    for (int k = 0; k < 4; ++k) b[k] = (unsigned char)(v >> (8 * k));
}

static uint32_t get_u32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* a float's IEEE 754 bits, little-endian whatever the host's order */
static void put_f32(unsigned char *b, float v)
{
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    put_u32(b, u);
}

cdl_status cdl_annual_write_hourly(const char *path, uint32_t quantity, size_t hours, size_t points,
                                   const int *row_of_hour, const float *rows, cdl_error *err)
{
    if (hours > UINT32_MAX || points > UINT32_MAX)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: too many hours or points for the format", path);
    unsigned char header[CDL_HOURLY_HEADER_BYTES];
    memcpy(header, CDL_HOURLY_MAGIC, 8);
    put_u32(header + 8, (uint32_t)hours);
    put_u32(header + 12, (uint32_t)points);
    put_u32(header + 16, quantity);
    put_u32(header + 20, 0);
    unsigned char *line = malloc((points ? points : 1) * 4);
    if (!line) return cdl_error_out_of_memory(err);
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st != CDL_OK) {
        free(line);
        return st;
    }
    fwrite(header, 1, sizeof header, f.fp);
    for (size_t h = 0; h < hours; ++h) {
        const float *v = row_of_hour[h] >= 0 ? rows + (size_t)row_of_hour[h] * points : NULL;
        for (size_t i = 0; i < points; ++i) put_f32(line + 4 * i, v ? v[i] : 0.0f);
        fwrite(line, 4, points, f.fp);
    }
    free(line);
    return cdl_atomic_file_commit(&f, err);
}

cdl_status cdl_annual_read_hourly(const char *path, uint32_t *quantity, size_t *hours, size_t *points,
                                  float **values, cdl_error *err)
{
    *values = NULL;
    char *data = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "hourly file", (size_t)1 << 34, &data, &size, err);
    if (st != CDL_OK) return st;
    const unsigned char *b = (const unsigned char *)data;
    if (size < CDL_HOURLY_HEADER_BYTES || memcmp(b, CDL_HOURLY_MAGIC, 8) != 0) {
        free(data);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected an hourly file beginning %s", path, CDL_HOURLY_MAGIC);
    }
    *hours = get_u32(b + 8);
    *points = get_u32(b + 12);
    *quantity = get_u32(b + 16);
    size_t want = CDL_HOURLY_HEADER_BYTES + 4 * *hours * *points;
    if (size != want) {
        free(data);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected %zu bytes for %zu hours of %zu points, found %zu", path,
                             want, *hours, *points, size);
    }
    size_t count = *hours * *points;
    float *v = malloc((count ? count : 1) * sizeof *v);
    if (!v) {
        free(data);
        return cdl_error_out_of_memory(err);
    }
    for (size_t k = 0; k < *hours * *points; ++k) {
        uint32_t u = get_u32(b + CDL_HOURLY_HEADER_BYTES + 4 * k);
        memcpy(&v[k], &u, sizeof u);
    }
    free(data);
    *values = v;
    return CDL_OK;
}

/* ---- the CSV ----------------------------------------------------------------------- */

static cdl_status write_csv(const char *path, const cdl_annual_grid_files *g, cdl_error *err)
{
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st != CDL_OK) return st;
    fputs("x,y,z,nx,ny,nz", f.fp);
    if (g->polygon) fputs(",area_m2", f.fp);
    fputs(",DA300_percent,UDI_fell_short_percent,UDI_percent,UDI_exceeded_percent,ASE_hours,EN17037_target_percent,"
          "coefficient_rel_stderr",
          f.fp);
    if (g->DF) fputs(",DF_percent", f.fp);
    fputc('\n', f.fp);
    for (size_t i = 0; i < g->grid->count; ++i) {
        const cdl_point_metrics *m = &g->metrics[i];
        cdl_vec3 p = g->grid->points[i], n = g->grid->normals[i];
        double v[16] = {p.x, p.y, p.z, n.x, n.y, n.z};
        int k = 6;
        if (g->polygon) v[k++] = g->grid->weights[i];
        v[k++] = m->DA300;
        v[k++] = m->UDI_fell_short;
        v[k++] = m->UDI;
        v[k++] = m->UDI_exceeded;
        v[k++] = m->ASE_hours;
        v[k++] = m->EN17037_target;
        v[k++] = g->rel_stderr[i];
        if (g->DF) v[k++] = g->DF[i];
        for (int j = 0; j < k; ++j) {
            char num[CDL_CSV_NUMBER_SIZE];
            cdl_csv_format_number(v[j], num);
            fprintf(f.fp, "%s%s", j ? "," : "", num);
        }
        fputc('\n', f.fp);
    }
    return cdl_atomic_file_commit(&f, err);
}

/* ---- the maps ---------------------------------------------------------------------- */

typedef struct metric_map {
    const char *suffix, *what, *unit, *label;
    size_t offset;                        /* in cdl_point_metrics */
} metric_map;

static const metric_map maps[] = {
    {"_DA300", "daylight autonomy DA300, % of occupied hours at 300 lx or more", "%",
     "DA300", offsetof(cdl_point_metrics, DA300)},
    {"_UDI", "useful daylight illuminance UDI 100-3000 lx, % of occupied hours", "%", "UDI 100-3000 lx",
     offsetof(cdl_point_metrics, UDI)},
    {"_ASE", "annual sunlight exposure: occupied hours of direct sun at 1000 lx or more", "h", "ASE hours",
     offsetof(cdl_point_metrics, ASE_hours)},
    {"_EN17037", "EN 17037: % of the daylight hours at 300 lx or more", "%", "EN 17037 hours at 300 lx",
     offsetof(cdl_point_metrics, EN17037_target)},
};

static cdl_status write_map(const char *out_dir, const cdl_annual_grid_files *g, const metric_map *m, double *values,
                            const double *zeros, const char *ocio, cdl_error *err)
{
    double lo = 0.0, hi = 100.0, tick = 20.0, sum = 0.0, total = 0.0;
    for (size_t i = 0; i < g->grid->count; ++i) {
        values[i] = *(const double *)((const char *)&g->metrics[i] + m->offset);
        sum += g->grid->weights[i] * values[i];
        total += g->grid->weights[i];
    }
    if (m->unit[0] == 'h') {
        /* hours: to the most at any point, ticks at a 1-2-5 step, ten or fewer */
        double most = g->ase_hours_max > 0.0 ? g->ase_hours_max : 10.0;
        static const double mantissa[3] = {1.0, 2.0, 5.0};
        for (int k = 0;; ++k) {
            tick = mantissa[k % 3] * pow(10.0, k / 3);
            if (most / tick <= 10.0) break;
        }
        hi = tick * ceil(most / tick);
    }
    cdl_map_quantity q = {m->what, m->unit, lo, hi, tick, ""};
    snprintf(q.stats, sizeof q.stats, "%s: mean %.4g %s over the grid", m->label, total > 0.0 ? sum / total : 0.0,
             m->unit);
    cdl_grid_result r = {0};
    r.name = g->name;
    r.grid = g->grid;
    r.E = values;
    r.E_direct = r.E_indirect = r.E_stderr = zeros;
    r.quantity = &q;
    char name[128];
    snprintf(name, sizeof name, "%s%s", g->name, m->suffix);
    char *full = cdl_path_join(out_dir, name, ".png");
    if (!full) return cdl_error_out_of_memory(err);
    cdl_status st = cdl_grid_result_write_png(&r, full, ocio, err);
    free(full);
    return st;
}

cdl_status cdl_annual_write_grid(const char *out_dir, const cdl_annual_grid_files *g, const char *ocio_config,
                                 cdl_error *err)
{
    char *csv = cdl_path_join(out_dir, g->name, ".csv");
    if (!csv) return cdl_error_out_of_memory(err);
    cdl_status st = write_csv(csv, g, err);
    free(csv);
    if (st != CDL_OK || g->grid->raster_width <= 0) return st;
    size_t n = g->grid->count ? g->grid->count : 1;
    double *values = malloc(n * sizeof *values), *zeros = calloc(n, sizeof *zeros);
    if (!values || !zeros) st = cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < sizeof maps / sizeof maps[0]; ++k)
        st = write_map(out_dir, g, &maps[k], values, zeros, ocio_config, err);
    free(values);
    free(zeros);
    return st;
}
