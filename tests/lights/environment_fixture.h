/* environment_fixture.h - the image skies the environment tests build. */
#ifndef CANDELA_TESTS_ENVIRONMENT_FIXTURE_H
#define CANDELA_TESTS_ENVIRONMENT_FIXTURE_H

#include "check.h"
#include "lights/emitters/emitter.h"

/* A W x H image sky (scale 1.5), over the whole sphere or (upper = 1)
 * the upper hemisphere only; the test releases it. */
static inline cdl_emitter *environment_fixture_image(int W, int H, const float *img, int upper)
{
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    p.image = img;
    p.width = W;
    p.height = H;
    p.scale = 1.5;
    p.upper_hemisphere_only = upper;
    cdl_emitter *e = NULL;
    cdl_error err;
    CHECK_OK(cdl_emitter_create_environment(&p, &e, &err), &err);
    return e;
}

#endif
