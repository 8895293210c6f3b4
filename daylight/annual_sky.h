/* annual_sky.h - each hour of a weather file as a sky over the patches (not public).
 *
 * The sun of each hour is placed by the SPA (lights/environment/
 * solar_position.h) at the hour's middle, h - 0.5 local standard time (the
 * file's time zone; its site's latitude, longitude and elevation; the
 * standard pressure and temperature for refraction).
 *
 * --sky perez: an hour with the sun above the horizon and diffuse light is
 * the Perez all-weather sky of its direct normal and diffuse horizontal
 * irradiance and dew point (11 C where the file has none) with the Perez
 * 1990 efficacies (perez_sky.h; inputs outside the model clamped to it, as
 * gendaymtx does, and counted). Each sky patch k takes the mean luminance
 * over it weighted by the cosine of the zenith angle,
 *     L_k = int_k L cos(Z) dw / int_k cos(Z) dw,
 * by a 3 x 3 Gauss-Legendre rule in (sin altitude, azimuth) over the patch,
 * so that the patches give the sky's horizontal illuminance (what the
 * model was scaled to) to the rule's accuracy; the ground patch takes
 * rho_g (E_dh + E_dn sin(altitude)) / pi, the light of a ground of
 * reflectance rho_g (default 0: the scene's own surfaces are its ground).
 * The sun's direct normal illuminance is kept apart: its direct light is
 * traced hour by hour, its interreflection goes through the sun bins (the
 * Tregenza patches the year's sun crosses, each at the direct-normal-
 * weighted mean direction of its hours).
 * Hours with the sun below the horizon at their middle give nothing; any
 * light the file holds for them is counted as left out (as are hours
 * whose Perez sky has no valid form even clamped, b >= 0, and no diffuse
 * illuminance in the file; with one, such an hour is a uniform sky of it,
 * and counted as a fallback).
 *
 * --sky cie_overcast: every hour is the CIE standard overcast sky scaled to
 * the file's diffuse horizontal illuminance (field 19), the sun left out:
 * the hour's illuminance at a point is its daylight factor times that.
 *
 * Thread safety: pure; the work runs on `threads` workers (and the
 * ranks given).
 */
#ifndef CANDELA_DAYLIGHT_ANNUAL_SKY_H
#define CANDELA_DAYLIGHT_ANNUAL_SKY_H

#include <stddef.h>

#include "base/error.h"
#include "daylight/epw.h"
#include "lights/environment/reinhart_patches.h"
#include "solver/rank_group.h"

typedef enum cdl_annual_sky_kind { CDL_ANNUAL_SKY_PEREZ, CDL_ANNUAL_SKY_CIE_OVERCAST } cdl_annual_sky_kind;

/* Default dew point where the weather file has none (gendaymtx's). */
#define CDL_ANNUAL_DEW_POINT_C 11.0

typedef struct cdl_annual_hour {
    double altitude_deg, azimuth_deg;     /* the sun at the hour's middle: apparent altitude, azimuth east of north */
    cdl_vec3 to_sun;                      /* unit, world */
    int row;                              /* its row of patch luminances, -1 when the hour gives no light */
    double diffuse_lx;                    /* the sky's horizontal illuminance */
    double direct_normal_lx;              /* the sun's (Perez), 0 without */
    int sun;                              /* its sun bin, -1 without */
    int clamped;                          /* the Perez inputs were clamped */
    double perez[5];                      /* its Perez coefficients a..e */
    int uniform;                          /* 1: a uniform sky of diffuse_lx / pi instead (the model failed) */
} cdl_annual_hour;

typedef struct cdl_annual_skies {
    cdl_annual_sky_kind kind;
    size_t hours;
    cdl_annual_hour *hour;                /* hours */
    size_t rows;                          /* the hours that give light */
    float *patch;                         /* perez: rows x patches->count, cd/m^2 (ground first) */
    cdl_vec3 *suns;                       /* perez: the sun bins' directions */
    size_t sun_count;
    size_t clamped_hours, dew_point_default_hours, left_out_hours, fallback_hours;
    double left_out_wh_m2;                /* their diffuse horizontal and direct normal irradiation, summed */
} cdl_annual_skies;

typedef struct cdl_annual_sky_options {
    cdl_annual_sky_kind kind;
    double ground_reflectance;            /* [0, 1] */
    int threads;                          /* >= 1 */
    cdl_rank_group *ranks;                /* NULL: one process; else the perez rows are dealt among the ranks
                                           * (cdl_annual_skies_deal) and only rank 0 ends with every row of
                                           * `patch`, the others with their own rows; the hours and the sun
                                           * bins are every rank's */
} cdl_annual_sky_options;

/* The CIE standard overcast sky, L = L_z (1 + 2 sin a) / 3 at altitude a
 * (Moon and Spencer 1942; CIE 110-1994), over the patches of p, scaled to 1
 * lx of unobstructed horizontal illuminance (L_z = 9 / (7 pi) cd/m^2):
 * each patch the cosine-weighted mean over it, in closed form
 *     L_k = L_z [ (s1^2 - s0^2) / 2 + 2 (s1^3 - s0^3) / 3 ] / (3 (s1^2 - s0^2) / 2),
 * s = sin a over the patch's rows (exact: the patches then give 1 lx on a
 * horizontal plane); the ground 0. out[p->count]. */
void cdl_annual_overcast_patches(const cdl_reinhart_patches *p, double *out);

/* A lit Perez hour's sky over any patches p: out[p->count] (cd/m^2, the
 * ground first), as the year's rows are made. */
cdl_status cdl_annual_sky_patches(const cdl_annual_hour *hour, const cdl_reinhart_patches *p, double ground_reflectance,
                                  float *out, cdl_error *err);

/* The year's skies over the patches p (their frame gives up and north).
 * With ranks, a collective (a failure on any rank is every rank's). */
cdl_status cdl_annual_skies_compute(const cdl_epw *epw, const cdl_annual_sky_options *o,
                                    const cdl_reinhart_patches *p, cdl_annual_skies *out, cdl_error *err);
void cdl_annual_skies_release(cdl_annual_skies *s);

/* How the `rows` lit hours' skies are dealt among `ranks` (NULL: one process). */
cdl_rank_deal cdl_annual_skies_deal(cdl_rank_group *ranks, size_t rows);

#endif
