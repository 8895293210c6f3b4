/* csv_output.c - NAME.csv: one row per grid point, numbers that read back exactly. */
#include "solver/output/grid_result.h"

#include <stdlib.h>
#include <string.h>

/* The shortest of 15, 16 and 17 significant digits that strtod reads back
 * as exactly `v` (0.1 stays "0.1", not "0.10000000000000001"). 17 digits
 * always suffice for binary64 (IEEE 754-2008, 5.12.2: Pmin = 17), and glibc
 * converts correctly rounded both ways, so every number round-trips. */
static void format_number(double v, char buf[CDL_CSV_NUMBER_SIZE])
{
    for (int digits = 15; digits <= 17; ++digits) {
        snprintf(buf, CDL_CSV_NUMBER_SIZE, "%.*g", digits, v);
        if (strtod(buf, NULL) == v) return;
    }
}

void cdl_csv_format_number(double v, char buf[CDL_CSV_NUMBER_SIZE])
{
    /* through a buffer of its own: GCC's sanitizer build cannot see that a
     * caller's is never NULL, and warns */
    char own[CDL_CSV_NUMBER_SIZE];
    format_number(v, own);
    memcpy(buf, own, sizeof own);
}

void cdl_csv_write_numbers(FILE *fp, const double *values, size_t n)
{
    char buf[CDL_CSV_NUMBER_SIZE];
    for (size_t k = 0; k < n; ++k) {
        format_number(values[k], buf);
        if (k > 0) fputc(',', fp);
        fputs(buf, fp);
    }
    fputc('\n', fp);
}

cdl_status cdl_grid_result_write_csv(const cdl_grid_result *result, const char *path, cdl_error *err)
{
    cdl_status st = cdl_grid_result_check(result, path, err);
    if (st != CDL_OK) return st;
    cdl_atomic_file file;
    st = cdl_atomic_file_open(&file, path, err);
    if (st != CDL_OK) return st;

    /* The fixed ten, then the extra columns present (DESIGN.md: area_m2
     * for polygon grids, then the outputs the grid asked for). */
    const cdl_grid *grid = result->grid;
    const struct {
        const char *name;
        const double *values;
    } extra[] = {{"area_m2", result->area_m2},       {"AO", result->ao},   {"AO_stderr", result->ao_stderr},
                 {"Ez_lx", result->Ez},
                 {"Ez_stderr_lx", result->Ez_stderr}, {"Esz_lx", result->Esz}, {"Esz_stderr_lx", result->Esz_stderr},
                 {"L_cd_m2", result->L},           {"DF_percent", result->DF}};
    enum { EXTRA = sizeof extra / sizeof extra[0] };
    fputs(CDL_GRID_CSV_COLUMNS, file.fp);
    for (int c = 0; c < EXTRA; ++c)
        if (extra[c].values) fprintf(file.fp, ",%s", extra[c].name);
    fputc('\n', file.fp);
    for (size_t i = 0; i < grid->count; ++i) {
        const cdl_vec3 p = grid->points[i], nrm = grid->normals[i];
        double row[10 + EXTRA] = {p.x,  p.y,         p.z,          nrm.x,        nrm.y,
                                  nrm.z, result->E[i], result->E_direct[i], result->E_indirect[i], result->E_stderr[i]};
        size_t n = 10;
        for (int c = 0; c < EXTRA; ++c)
            if (extra[c].values) row[n++] = extra[c].values[i];
        cdl_csv_write_numbers(file.fp, row, n);
    }
    /* commit checks the stream's error flag: a failed write above is reported there. */
    return cdl_atomic_file_commit(&file, err);
}
