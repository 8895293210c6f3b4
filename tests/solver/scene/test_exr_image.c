/* OpenEXR Core: write float channels and attributes, read them back bit-exact. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "solver/scene/exr_image.h"

int main(void)
{
    /* 37 x 53 with ZIP (16 lines per chunk): the last chunk is partial. */
    const int w = 37, h = 53;
    static float y[37 * 53], e[37 * 53];
    for (int i = 0; i < w * h; ++i) {
        y[i] = (float)(i * 0.25 + 1e-3);
        e[i] = (float)(1e6 / (i + 1));
    }
    const char *path = CANDELA_TEST_TMPDIR "/test_exr_image.exr";
    cdl_exr_channel ch[2] = {{"Y", y}, {"E_direct", e}};
    cdl_exr_attribute at[2] = {{"units", "lx"}, {"quantity", "illuminance"}};
    cdl_error err;
    CHECK_OK(cdl_exr_write(path, w, h, ch, 2, at, 2, &err), &err);

    cdl_exr_image img;
    CHECK_OK(cdl_exr_read(path, &img, &err), &err);
    CHECK(img.width == w && img.height == h && img.channel_count == 2);
    const float *ry = cdl_exr_image_channel(&img, "Y");
    const float *re = cdl_exr_image_channel(&img, "E_direct");
    CHECK(ry && re);
    if (ry && re) {
        CHECK(memcmp(ry, y, sizeof y) == 0);
        CHECK(memcmp(re, e, sizeof e) == 0);
    }
    CHECK(cdl_exr_image_channel(&img, "nope") == NULL);
    cdl_exr_image_release(&img);

    char units[32];
    CHECK_OK(cdl_exr_read_string_attribute(path, "units", units, sizeof units, &err), &err);
    CHECK(strcmp(units, "lx") == 0);
    CHECK(cdl_exr_read_string_attribute(path, "missing", units, sizeof units, &err) == CDL_ERR_INPUT);

    /* Errors name the file and never crash. */
    CHECK(cdl_exr_read(CANDELA_TEST_TMPDIR "/does_not_exist.exr", &img, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "does_not_exist.exr") != NULL);
    const char *junk = CANDELA_TEST_TMPDIR "/junk.exr";
    FILE *f = fopen(junk, "wb");
    CHECK(f != NULL);
    if (f) {
        fputs("not an exr file at all", f);
        fclose(f);
    }
    CHECK(cdl_exr_read(junk, &img, &err) == CDL_ERR_INPUT);
    /* Writing into a missing directory fails cleanly. */
    CHECK(cdl_exr_write(CANDELA_TEST_TMPDIR "/no/such/dir/x.exr", w, h, ch, 2, at, 2, &err) == CDL_ERR_INTERNAL);
    unlink(path);
    unlink(junk);
    return check_finish();
}
