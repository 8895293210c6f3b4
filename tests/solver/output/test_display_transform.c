/* OpenColorIO through the C shim, with the config shipped in data/ocio. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/output/display_transform.h"

#define CONFIG CANDELA_SOURCE_DIR "/data/ocio/config.ocio"

/* sRGB encoding (IEC 61966-2-1) of a linear value, computed independently. */
static double srgb_encode(double v)
{
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

int main(void)
{
    cdl_error err;
    cdl_display_transform *t = NULL;
    CHECK_OK(cdl_display_transform_open(CONFIG, "linear", "sRGB", "Standard", &t, &err), &err);
    if (t) {
        /* 18 % grey -> 0.4614 in sRGB; 0 and 1 stay fixed; the linear toe. */
        float px[12] = {0.18f, 0.18f, 0.18f, 0.0f, 1.0f, 0.5f, 0.002f, 0.02f, 0.9f, 0.25f, 0.75f, 0.05f};
        float in[12];
        memcpy(in, px, sizeof px);
        CHECK_OK(cdl_display_transform_apply(t, px, 4, &err), &err);
        /* OCIO's CPU path works in float: 1e-5 absolute is a few float ulps at 0.5. */
        for (int i = 0; i < 12; ++i) CHECK_ABS(px[i], srgb_encode(in[i]), 1e-5);
        CHECK_ABS(px[0], 0.4614, 1e-4);
        cdl_display_transform_release(t);
    }

    /* The false-colour view maps 0 to dark blue, 0.5 to green, 1 to red. */
    CHECK_OK(cdl_display_transform_open(CONFIG, "linear", "sRGB", "False colour", &t, &err), &err);
    if (t) {
        float px[9] = {0, 0, 0, 0.5f, 0.5f, 0.5f, 1, 1, 1};
        CHECK_OK(cdl_display_transform_apply(t, px, 3, &err), &err);
        CHECK_ABS(px[0], 0.0, 1e-5);
        CHECK_ABS(px[1], 0.0, 1e-5);
        CHECK_ABS(px[2], srgb_encode(0.5), 1e-4);
        CHECK_ABS(px[3], 0.0, 1e-5);
        CHECK_ABS(px[4], 1.0, 1e-4);
        CHECK_ABS(px[5], 0.0, 1e-5);
        CHECK_ABS(px[6], 1.0, 1e-4);
        CHECK_ABS(px[7], 0.0, 1e-5);
        CHECK_ABS(px[8], 0.0, 1e-5);
        cdl_display_transform_release(t);
    }

    /* A missing config or view is an error with a message. */
    CHECK(cdl_display_transform_open("/nonexistent.ocio", "linear", "sRGB", "Standard", &t, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "nonexistent.ocio") != NULL);
    CHECK(cdl_display_transform_open(CONFIG, "linear", "sRGB", "No such view", &t, &err) == CDL_ERR_INPUT);
    return check_finish();
}
