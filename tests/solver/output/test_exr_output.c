/* NAME.exr: channels and attributes read back with cdl_exr_read. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "grid_result_fixture.h"
#include "solver/scene/exr_image.h"

static char attribute(const char *path, const char *name, char *buf, size_t size)
{
    cdl_error err;
    if (cdl_exr_read_string_attribute(path, name, buf, size, &err) != CDL_OK) buf[0] = '\0';
    return buf[0];
}

int main(void)
{
    char dir[512], path[600], missing[600], value[128];
    CHECK(fixture_folder("test_exr_output", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/desk.exr", dir);
    cdl_error err;
    fixture f;

    /* A 4 x 3 rect grid with distinct values in every channel. */
    const int nu = 4, nv = 3;
    CHECK(fixture_rect(&f, nu, nv, 2.0, 1.5, 0.75));
    for (size_t k = 0; k < f.grid.count; ++k) {
        f.E_direct[k] = 100.0 + 10.0 * (double)k + 0.125;
        f.E_indirect[k] = 20.0 + (double)k / 3.0;
        f.E[k] = f.E_direct[k] + f.E_indirect[k];
        f.E_stderr[k] = k % 2 ? 0.0 : 0.5 + (double)k;
    }
    /* Make it a polygon-like raster: two pixels outside the grid. */
    f.grid.raster_index[0] = -1;
    f.grid.raster_index[(size_t)nu * nv - 1] = -1;
    const cdl_key_value settings[2] = {{"method", "direct"}, {"seed", "1"}};
    CHECK_OK(cdl_grid_result_write_exr(&f.result, path, settings, 2, &err), &err);
    CHECK(fixture_count_entries(dir) == 1); /* no temporary file left */

    cdl_exr_image img;
    CHECK_OK(cdl_exr_read(path, &img, &err), &err);
    CHECK(img.width == nu && img.height == nv && img.channel_count == 6);
    const char *names[6] = {"E", "Y", "E_direct", "E_indirect", "E_stderr", "mask"};
    const float *ch[6];
    int all = 1;
    for (int c = 0; c < 6; ++c) {
        ch[c] = cdl_exr_image_channel(&img, names[c]);
        CHECK_MSG(ch[c] != NULL, "channel %s", names[c]);
        all = all && ch[c];
    }
    if (all && img.width == nu && img.height == nv) {
        for (int p = 0; p < nu * nv; ++p) {
            int32_t idx = f.grid.raster_index[p];
            if (idx < 0) {
                for (int c = 0; c < 6; ++c) CHECK_MSG(ch[c][p] == 0.0f, "outside pixel %d channel %s", p, names[c]);
                continue;
            }
            /* float channels hold the double values rounded to float, exactly */
            CHECK(ch[0][p] == (float)f.E[idx]);
            CHECK(ch[1][p] == (float)f.E[idx]);
            CHECK(ch[2][p] == (float)f.E_direct[idx]);
            CHECK(ch[3][p] == (float)f.E_indirect[idx]);
            CHECK(ch[4][p] == (float)f.E_stderr[idx]);
            CHECK(ch[5][p] == 1.0f);
        }
        /* Orientation (grid.h): the top row is the v = 1 edge, column 0 the
         * u = 0 edge. Pixel (1, 0) shows point i = 1, j = nv - 1. */
        CHECK(ch[0][1] == (float)f.E[(size_t)(nv - 1) * nu + 1]);
        /* and the bottom-left pixel shows point 0 (at the origin corner) */
        CHECK(ch[0][(size_t)(nv - 1) * nu] == (float)f.E[0]);
    }
    cdl_exr_image_release(&img);
    CHECK(attribute(path, "units", value, sizeof value) && strcmp(value, "lx") == 0);
    CHECK(attribute(path, "quantity", value, sizeof value) && strcmp(value, "illuminance") == 0);
    CHECK(attribute(path, "method", value, sizeof value) && strcmp(value, "direct") == 0);
    CHECK(attribute(path, "seed", value, sizeof value) && strcmp(value, "1") == 0);

    /* Refusals leave the existing file byte for byte and no temporary file. */
    size_t before_len = 0;
    char *before = fixture_read_file(path, &before_len);
    f.E_stderr[5] = NAN;
    CHECK(cdl_grid_result_write_exr(&f.result, path, settings, 2, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "desk.exr") && strstr(err.message, "E_stderr_lx of point 5"), "%s", err.message);
    f.E_stderr[5] = 0.0;
    f.E[2] = 1e39; /* beyond FLT_MAX: would be inf as a float */
    CHECK(cdl_grid_result_write_exr(&f.result, path, settings, 2, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "32-bit float") && strstr(err.message, "point 2"), "%s", err.message);
    f.E[2] = 1.0;
    const cdl_key_value clash[1] = {{"units", "fc"}};
    CHECK(cdl_grid_result_write_exr(&f.result, path, clash, 1, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "reserved"), "%s", err.message);
    CHECK(fixture_file_is(path, before, before_len));
    free(before);
    CHECK(fixture_count_entries(dir) == 1);

    /* A missing folder: an I/O error naming the file. */
    snprintf(missing, sizeof missing, "%s/missing/desk.exr", dir);
    CHECK(cdl_grid_result_write_exr(&f.result, missing, NULL, 0, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "missing/desk.exr"), "%s", err.message);

    /* A points grid has no raster: no image, a clear refusal. */
    f.grid.raster_width = f.grid.raster_height = 0;
    CHECK(cdl_grid_result_write_exr(&f.result, path, NULL, 0, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "no raster"), "%s", err.message);
    fixture_free(&f);

    /* A one-pixel grid with no caller attributes works too. */
    CHECK(fixture_rect(&f, 1, 1, 1.0, 1.0, 0.0));
    f.E[0] = f.E_direct[0] = 42.0;
    CHECK_OK(cdl_grid_result_write_exr(&f.result, path, NULL, 0, &err), &err);
    CHECK_OK(cdl_exr_read(path, &img, &err), &err);
    const float *e = cdl_exr_image_channel(&img, "E");
    CHECK(img.width == 1 && img.height == 1 && e && e[0] == 42.0f);
    cdl_exr_image_release(&img);
    fixture_free(&f);

    unlink(path);
    return check_finish();
}
