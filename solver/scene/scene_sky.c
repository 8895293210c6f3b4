/* scene_sky.c - a daylight sky and its sun as emitters (scene_sky.h). */
#include "solver/scene/scene_sky.h"

#include <stdio.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/environment/perez_sky.h"
#include "radiometry/constants.h"

/* Where the sun is, in words: "sun at azimuth A, altitude H degrees
 * (SPA: latitude, longitude at TIME)". */
static void describe_sun(const cdl_daylight_spec *d, char *out, size_t size)
{
    if (!d->has_sun) {
        snprintf(out, size, "no sun given (this sky does not depend on it)");
        return;
    }
    int n = snprintf(out, size, "sun at azimuth %.4f, altitude %.4f degrees", d->sun_azimuth_deg, d->sun_altitude_deg);
    if (d->from_site && n > 0 && (size_t)n < size)
        snprintf(out + n, size - (size_t)n, " (NREL SPA for latitude %.6g, longitude %.6g, %.6g m at %s, Delta T %.3g s)",
                 d->latitude_deg, d->longitude_deg, d->elevation_m, d->time, d->delta_t_s);
}

static cdl_status make_sun(const cdl_luminaire_spec *sp, double E_dn, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    if (!(E_dn > 0.0)) return CDL_OK;
    if (!(sp->daylight.sun_altitude_deg > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "direct normal illuminance %g lx: expected the sun above the horizon to give it, found "
                             "an altitude of %.4g degrees",
                             E_dn, sp->daylight.sun_altitude_deg);
    cdl_directional_params p = {cdl_vec3_neg(sp->daylight.sun), cdl_lux(E_dn * sp->maintenance_factor),
                                CDL_SUN_ANGULAR_DIAMETER_DEG};
    return cdl_emitter_create_directional(&p, out, err);
}

static cdl_status build_cie(const cdl_luminaire_spec *sp, cdl_scene_sky_emitters *out, cdl_error *err)
{
    const cdl_daylight_spec *d = &sp->daylight;
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    p.up = sp->up;
    p.sky = CDL_SKY_CIE_GENERAL;
    p.cie_type = d->cie_type;
    p.sun = d->sun;
    p.scale_to_horizontal = d->scale_to_horizontal;
    p.horizontal = cdl_lux(d->diffuse_horizontal * sp->maintenance_factor);
    p.luminance = cdl_nits(sp->luminance_cd_m2 * sp->maintenance_factor);
    cdl_status st = cdl_emitter_create_environment(&p, &out->sky, err);
    if (st == CDL_OK) st = make_sun(sp, d->direct_normal, &out->sun, err);
    if (st != CDL_OK) return st;
    char sun[256];
    describe_sun(d, sun, sizeof sun);
    cdl_vec3 up = cdl_vec3_normalize(sp->up);
    cdl_illuminance E_h;
    cdl_emitter_exact_illuminance(out->sky, cdl_vec3_make(0, 0, 0), up, &E_h, NULL);
    cdl_luminance L_z = cdl_emitter_radiance(out->sky, cdl_vec3_make(0, 0, 0), up, up, NULL);
    snprintf(out->description, sizeof out->description,
             "CIE standard general sky type %d (ISO 15469:2004): zenith luminance %.6g cd/m2, unobstructed horizontal "
             "illuminance %.6g lx; %s%s",
             d->cie_type, L_z.cd_m2, E_h.lx, sun,
             out->sun ? "; the sun a disk of 0.533 degrees" : "");
    return CDL_OK;
}

static cdl_status build_perez(const cdl_luminaire_spec *sp, cdl_scene_sky_emitters *out, cdl_error *err)
{
    const cdl_daylight_spec *d = &sp->daylight;
    cdl_perez_input in = {90.0 - d->sun_altitude_deg, d->day_of_year, !d->radiometric, d->direct_normal,
                          d->diffuse_horizontal, d->dew_point_c, 0};
    cdl_perez_sky perez;
    cdl_status st = cdl_perez_sky_compute(&in, &perez, err);
    if (st != CDL_OK) return st;
    cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
    p.up = sp->up;
    p.sky = CDL_SKY_PEREZ;
    memcpy(p.perez, perez.coefficients, sizeof p.perez);
    p.sun = d->sun;
    p.scale_to_horizontal = 1;
    p.horizontal = cdl_lux(perez.diffuse_horizontal_lx * sp->maintenance_factor);
    st = cdl_emitter_create_environment(&p, &out->sky, err);
    if (st == CDL_OK) st = make_sun(sp, perez.direct_normal_lx, &out->sun, err);
    if (st != CDL_OK) return st;
    char sun[256];
    describe_sun(d, sun, sizeof sun);
    snprintf(out->description, sizeof out->description,
             "Perez all-weather sky (1993; efficacies Perez 1990): clearness %.4g (category %d), brightness %.4g, "
             "diffuse horizontal %.6g lx (%.6g W/m2, %.4g lm/W), direct normal %.6g lx (%.6g W/m2, %.4g lm/W), "
             "precipitable water %.3g cm; coefficients a %.4g, b %.4g, c %.4g, d %.4g, e %.4g; %s%s",
             perez.clearness, perez.category, perez.brightness, perez.diffuse_horizontal_lx,
             perez.diffuse_horizontal_w_m2, perez.diffuse_efficacy_lm_w, perez.direct_normal_lx,
             perez.direct_normal_w_m2, perez.direct_efficacy_lm_w, perez.precipitable_water_cm,
             perez.coefficients[0], perez.coefficients[1], perez.coefficients[2], perez.coefficients[3],
             perez.coefficients[4], sun, out->sun ? "; the sun a disk of 0.533 degrees" : "");
    return CDL_OK;
}

cdl_status cdl_scene_sky_build(const cdl_luminaire_spec *sp, cdl_scene_sky_emitters *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    cdl_status st = sp->sky == CDL_SCENE_SKY_PEREZ ? build_perez(sp, out, err) : build_cie(sp, out, err);
    if (st != CDL_OK) {
        cdl_emitter_release(out->sky);
        cdl_emitter_release(out->sun);
        memset(out, 0, sizeof *out);
    }
    return st;
}
