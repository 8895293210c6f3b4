/* NAME.csv: header, grid order, numbers that read back as the very same
 * doubles, and refusal of values that are not numbers. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "grid_result_fixture.h"
#include "radiometry/constants.h"

/* Split one CSV line (ending at '\n' or '\0') into at most max numbers with
 * strtod; returns the count, or -1 if a field is not entirely a number. */
static int parse_row(const char *line, double *out, int max)
{
    int n = 0;
    const char *p = line;
    for (;;) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || n == max) return -1;
        out[n++] = v;
        if (*end == ',')
            p = end + 1;
        else if (*end == '\n' || *end == '\0')
            return n;
        else
            return -1;
    }
}

/* Line `index` (0 = header) of text, or NULL. */
static const char *line_at(const char *text, int index)
{
    const char *p = text;
    for (int i = 0; i < index && p; ++i) {
        p = strchr(p, '\n');
        if (p) ++p;
    }
    return p && *p ? p : NULL;
}

static int count_lines(const char *text)
{
    int n = 0;
    for (const char *p = text; *p; ++p) n += *p == '\n';
    return n;
}

int main(void)
{
    char dir[512], path[600], missing[600];
    CHECK(fixture_folder("test_csv_output", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/workplane.csv", dir);
    cdl_error err;
    fixture f;

    /* A 2 x 2 grid whose values are doubles with no short decimal form:
     * each must come back from the text bit for bit. */
    CHECK(fixture_rect(&f, 2, 2, 0.3, 0.7, 0.1 + 0.2)); /* z = 0.30000000000000004 */
    /* closed-form direct illuminance E = I cos(theta) / d^2 of a 1000 cd point
     * 2 m above the plane at 1 m horizontal offset: 1000 x (2/sqrt 5) / 5 */
    const double closed_form = 1000.0 * (2.0 / sqrt(5.0)) / 5.0;
    const double awkward[4][4] = {
        {closed_form, closed_form, 0.0, 0.0},
        {0.1, 1.0 / 3.0, 2.0 / 3.0 - 1.0 / 3.0, 5e-324},          /* shortest "0.1"; a denormal */
        {CDL_PI * 1e5, nextafter(1.0, 2.0), 1e-300, 123456789.12345679}, /* needs 17 digits; tiny */
        {DBL_MAX, 1.0 / 7.0, 4.0 / 7.0, 1e22},
    };
    for (int i = 0; i < 4; ++i) {
        f.E[i] = awkward[i][0];
        f.E_direct[i] = awkward[i][1];
        f.E_indirect[i] = awkward[i][2];
        f.E_stderr[i] = awkward[i][3];
    }
    f.grid.normals[3] = cdl_vec3_make(0.0, sin(0.1), cos(0.1));
    CHECK_OK(cdl_grid_result_write_csv(&f.result, path, &err), &err);
    char *text = fixture_read_file(path, NULL);
    CHECK(text != NULL);
    if (text) {
        const char *header = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx\n";
        CHECK(strncmp(text, header, strlen(header)) == 0);
        CHECK(count_lines(text) == 5);
        for (int i = 0; i < 4; ++i) {
            const char *line = line_at(text, i + 1);
            double v[12];
            CHECK(line && parse_row(line, v, 12) == 10);
            if (!line || parse_row(line, v, 12) != 10) continue;
            /* grid order: row i is point i */
            const cdl_vec3 p = f.grid.points[i], n = f.grid.normals[i];
            CHECK(v[0] == p.x && v[1] == p.y && v[2] == p.z);
            CHECK(v[3] == n.x && v[4] == n.y && v[5] == n.z);
            for (int c = 0; c < 4; ++c)
                CHECK_MSG(v[6 + c] == awkward[i][c], "row %d column %d: %.17g read back as %.17g", i, c,
                          awkward[i][c], v[6 + c]);
        }
        /* The shortest round-trip form is used: 0.1 is "0.1", not 0.10000000000000001. */
        CHECK(strstr(text, ",0.1,") != NULL);
        CHECK(strstr(text, "0.10000000000000001") == NULL);
        free(text);
    }
    CHECK(fixture_count_entries(dir) == 1);

    /* With AO: one more column, header ",AO". */
    CHECK(fixture_add_ao(&f));
    for (int i = 0; i < 4; ++i) f.ao[i] = 0.25 * i + 1.0 / 3.0 * (i == 3 ? 0 : 1);
    CHECK_OK(cdl_grid_result_write_csv(&f.result, path, &err), &err);
    text = fixture_read_file(path, NULL);
    CHECK(text != NULL);
    if (text) {
        const char *header = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,AO\n";
        CHECK(strncmp(text, header, strlen(header)) == 0);
        for (int i = 0; i < 4; ++i) {
            const char *line = line_at(text, i + 1);
            double v[12];
            CHECK(line && parse_row(line, v, 12) == 11);
            if (line && parse_row(line, v, 12) == 11) CHECK(v[10] == f.ao[i]);
        }
        free(text);
    }
    char *before = fixture_read_file(path, NULL);

    /* Not a number: refused with a message naming the file, column and
     * point; the previous file is untouched and nothing is left behind. */
    f.E_indirect[2] = NAN;
    CHECK(cdl_grid_result_write_csv(&f.result, path, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "workplane.csv") && strstr(err.message, "E_indirect_lx") &&
                  strstr(err.message, "point 2") && strstr(err.message, "NaN"),
              "%s", err.message);
    f.E_indirect[2] = 0.0;
    f.ao[1] = -INFINITY;
    CHECK(cdl_grid_result_write_csv(&f.result, path, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "AO") && strstr(err.message, "point 1") && strstr(err.message, "infinity"), "%s",
              err.message);
    f.ao[1] = 0.5;
    f.grid.normals[0].z = INFINITY;
    CHECK(cdl_grid_result_write_csv(&f.result, path, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "nz of point 0"), "%s", err.message);
    f.grid.normals[0].z = 1.0;
    f.result.E_stderr = NULL;
    CHECK(cdl_grid_result_write_csv(&f.result, path, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "E_stderr_lx"), "%s", err.message);
    f.result.E_stderr = f.E_stderr;
    /* A raster entry beyond the points is a broken grid. */
    f.grid.raster_index[3] = 4;
    CHECK(cdl_grid_result_write_csv(&f.result, path, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "raster pixel (1, 1)") && strstr(err.message, "point 4"), "%s", err.message);
    f.grid.raster_index[3] = 1;
    CHECK(before && fixture_file_is(path, before, strlen(before)));
    free(before);
    CHECK(fixture_count_entries(dir) == 1);

    /* A missing folder is an I/O error naming the file. */
    snprintf(missing, sizeof missing, "%s/missing/workplane.csv", dir);
    CHECK(cdl_grid_result_write_csv(&f.result, missing, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "missing/workplane.csv"), "%s", err.message);
    fixture_free(&f);

    /* An empty grid: the header alone. */
    CHECK(fixture_rect(&f, 0, 0, 1.0, 1.0, 0.0));
    CHECK_OK(cdl_grid_result_write_csv(&f.result, path, &err), &err);
    text = fixture_read_file(path, NULL);
    CHECK(text && strcmp(text, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx\n") == 0);
    free(text);
    fixture_free(&f);

    unlink(path);
    return check_finish();
}
