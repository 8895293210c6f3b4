/* Emission cones: a solver skips points outside them, so no light may
 * leave an emitter outside its cone. Checked on many directions. */
#include <math.h>

#include "check.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"
#include "base/rng.h"
#include "radiometry/sampling.h"

/* Over 20000 uniform directions: I = 0 wherever dot(w, axis) <= cos_min,
 * and I > 0 somewhere inside (the cone is not vacuous). */
static void check_cone(const cdl_emitter *e, const char *what)
{
    cdl_vec3 pos, axis;
    double cos_min;
    CHECK_MSG(cdl_emitter_emission_cone(e, &pos, &axis, &cos_min), "%s: expected a cone", what);
    int outside_lit = 0, inside_lit = 0;
    for (int i = 0; i < 20000; ++i) {
        double u[2];
        cdl_rng_uniform2((cdl_rng_key){3, 9}, (uint64_t)i, u);
        cdl_vec3 w = cdl_sample_uniform_sphere(u[0], u[1]);
        double I = cdl_emitter_intensity(e, w).cd;
        if (cdl_vec3_dot(w, axis) <= cos_min) outside_lit += I > 0.0;
        else inside_lit += I > 0.0;
        /* and the delta evaluation agrees, for a receiver facing the light */
        cdl_vec3 p = cdl_vec3_madd(pos, 2.0, w);
        cdl_delta_light d;
        if (cdl_vec3_dot(w, axis) <= cos_min) CHECK(!cdl_emitter_eval_delta(e, p, cdl_vec3_neg(w), &d));
    }
    CHECK_MSG(outside_lit == 0, "%s: %d directions outside the cone carry light", what, outside_lit);
    CHECK_MSG(inside_lit > 100, "%s: only %d lit directions inside", what, inside_lit);
}

int main(void)
{
    cdl_error err;
    cdl_emitter *e = NULL;

    /* Spots: smoothstep profile (cone = half angle) and cos^n (hemisphere). */
    cdl_spot_params sp = {cdl_vec3_make(1, 2, 3), cdl_vec3_make(0.3, -0.2, -1), cdl_candelas(500), 0, 35.0, 20.0, 0.0};
    CHECK_OK(cdl_emitter_create_spot(&sp, &e, &err), &err);
    if (e) {
        cdl_vec3 pos, axis;
        double c;
        CHECK(cdl_emitter_emission_cone(e, &pos, &axis, &c));
        CHECK_ABS(c, cos(35.0 * CDL_DEG_TO_RAD), 1e-15);
        check_cone(e, "smoothstep spot");
        cdl_emitter_release(e);
    }
    sp.use_exponent = 1;
    sp.exponent = 3.0;
    CHECK_OK(cdl_emitter_create_spot(&sp, &e, &err), &err);
    if (e) {
        check_cone(e, "cos^3 spot");
        cdl_emitter_release(e);
    }

    /* Goniometric: a bilateral type C table lit to 75 degrees (the 80 degree
     * row is zero), rotated; the cone is the rotated nadir and 80 degrees. */
    const double c_deg[3] = {0, 90, 180};
    double g_deg[19], cd[3 * 19];
    for (int j = 0; j < 19; ++j) {
        g_deg[j] = 10.0 * j;
        for (int i = 0; i < 3; ++i) cd[i * 19 + j] = g_deg[j] <= 75.0 ? 300.0 + 40.0 * i - 3.0 * g_deg[j] : 0.0;
    }
    cdl_photometry *ph = NULL;
    CHECK_OK(cdl_photometry_create_type_c(c_deg, 3, g_deg, 19, cd, &ph, &err), &err);
    if (ph) {
        cdl_goniometric_params gp = CDL_GONIOMETRIC_PARAMS_DEFAULT;
        gp.position = cdl_vec3_make(0, 0, 3);
        gp.rotation_deg[0] = 25.0;
        gp.rotation_deg[2] = -60.0;
        gp.photometry = ph;
        CHECK_OK(cdl_emitter_create_goniometric(&gp, &e, &err), &err);
        if (e) {
            cdl_vec3 pos, axis;
            double c;
            CHECK(cdl_emitter_emission_cone(e, &pos, &axis, &c));
            CHECK_ABS(c, cos(80.0 * CDL_DEG_TO_RAD), 1e-15);
            check_cone(e, "goniometric");
            cdl_emitter_release(e);
        }
        cdl_photometry_release(ph);
    }
    /* An uplight component (light at gamma = 180) means no cone. */
    for (int j = 0; j < 19; ++j)
        for (int i = 0; i < 3; ++i) cd[i * 19 + j] = 100.0;
    CHECK_OK(cdl_photometry_create_type_c(c_deg, 3, g_deg, 19, cd, &ph, &err), &err);
    if (ph) {
        cdl_goniometric_params gp = CDL_GONIOMETRIC_PARAMS_DEFAULT;
        gp.photometry = ph;
        CHECK_OK(cdl_emitter_create_goniometric(&gp, &e, &err), &err);
        cdl_vec3 pos, axis;
        double c;
        if (e) CHECK(!cdl_emitter_emission_cone(e, &pos, &axis, &c));
        cdl_emitter_release(e);
        cdl_photometry_release(ph);
    }
    /* Point lights radiate everywhere: no cone. */
    cdl_point_params pp = {cdl_vec3_make(0, 0, 0), cdl_candelas(10)};
    CHECK_OK(cdl_emitter_create_point(&pp, &e, &err), &err);
    cdl_vec3 pos, axis;
    double c;
    if (e) CHECK(!cdl_emitter_emission_cone(e, &pos, &axis, &c));
    cdl_emitter_release(e);
    return check_finish();
}
