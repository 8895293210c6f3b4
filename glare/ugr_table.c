/* ugr_table.c - the standard UGR table of a luminaire (CIE 190:2010). */
#include <math.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"
#include "glare/position_index.h"
#include "glare/room_flux.h"
#include "glare/ugr.h"
#include "glare/ugr_table.h"
#include "glare/ugr_table_conditions.h"

#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"

/* CIE 190:2010 4.2: X and Y in multiples of H, the catalogue's rows */
const double cdl_ugr_table_rooms[CDL_UGR_TABLE_ROOMS][2] = {
    {2, 2}, {2, 3}, {2, 4}, {2, 6}, {2, 8}, {2, 12}, {4, 2},  {4, 3}, {4, 4}, {4, 6},
    {4, 8}, {4, 12}, {8, 4}, {8, 6}, {8, 8}, {8, 12}, {12, 4}, {12, 6}, {12, 8}};

/* CIE 190:2010 4.2: ceiling, walls, floor (the reference plane) */
const double cdl_ugr_table_reflectances[CDL_UGR_TABLE_REFLECTANCE_SETS][3] = {
    {0.70, 0.50, 0.20}, {0.70, 0.30, 0.20}, {0.50, 0.50, 0.20}, {0.50, 0.30, 0.20}, {0.30, 0.30, 0.20}};

/* What every room's computation shares: the luminaire and its fluxes. */
typedef struct table_luminaire {
    const cdl_photometry *photometry;
    const cdl_luminous_opening *opening;
    double scale;            /* output factor */
    double cumulative_lm[4]; /* to cos(gamma) = 0.75, 0.5, 0.25, 0, output factor applied */
    double upward_lm;
} table_luminaire;

/* The sum of L^2 omega / p^2 over the array seen from the middle of the
 * X wall, the luminaires crosswise (view 0) or endwise (view 1). */
static cdl_ugr_sum array_glare(const table_luminaire *lum, double X, size_t nx, size_t ny, double S, int view)
{
    const double H = CDL_UGR_TABLE_HEIGHT_M;
    cdl_ugr_sum sum = {0.0, 0.0, 0};
    for (size_t j = 0; j < ny; ++j) {
        double R = (j + 0.5) * S;
        for (size_t i = 0; i < nx; ++i) {
            double T = -0.5 * X + (i + 0.5) * S, p;
            if (cdl_glare_position_index(R, T, H, &p) != CDL_GLARE_IN_VIEW) continue;
            /* towards the eye in the luminaire's frame (x along C0, y along
             * C90, z up): crosswise C0 faces the observer's wall, so the eye
             * lies at C = atan(T/R); endwise C90 faces it, C = 90 - atan(T/R)
             * (CIE 117:1995 eq. 4.5, 4.6; either sign of T is in the array) */
            cdl_vec3 dir = view == 0 ? cdl_vec3_make(R, -T, -H) : cdl_vec3_make(T, R, -H);
            double A = cdl_luminous_opening_projected_area(lum->opening, dir);
            double I = lum->scale * cdl_photometry_intensity(lum->photometry, dir).cd;
            if (!(A > 0.0) || !(I > 0.0)) continue;
            /* L = I / A_p, omega = A_p / r^2 (CIE 117:1995 4.5) */
            double r2 = R * R + T * T + H * H;
            cdl_ugr_sum_add(&sum, cdl_ugr_term_make(cdl_nits(I / A), 0.0, A / r2, 0.0, p));
        }
    }
    return sum;
}

/* One room of the table: its array, background luminances and ratings. */
static cdl_status table_room(const table_luminaire *lum, double shr, size_t index, cdl_ugr_table_room *out,
                             cdl_error *err)
{
    const double H = CDL_UGR_TABLE_HEIGHT_M, S = shr * H;
    double xh = cdl_ugr_table_rooms[index][0], yh = cdl_ugr_table_rooms[index][1];
    double X = xh * H, Y = yh * H;
    cdl_room room = {X, Y, H, (size_t)lround(xh / shr), (size_t)lround(yh / shr)};
    memset(out, 0, sizeof *out);
    out->x_h = xh;
    out->y_h = yh;
    out->luminaires = room.nx * room.ny;
    out->room_index = X * Y / (H * (X + Y));
    double fgl[4];
    cdl_status st = cdl_room_geometric_factors(&room, fgl, err);
    if (st != CDL_OK) return st;
    /* CIE 190 eq. 9 to 12: direct lumens on the eye's plane, the walls, the ceiling */
    double floor_lm = 0.0;
    for (int k = 0; k < 4; ++k) floor_lm += fgl[k] * lum->cumulative_lm[k];
    out->direct_floor_lm = floor_lm;
    out->direct_walls_lm = lum->cumulative_lm[3] - floor_lm;
    out->direct_ceiling_lm = lum->upward_lm;
    double walls_m2 = 2.0 * H * (X + Y);
    for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
        const double *rho = cdl_ugr_table_reflectances[s];
        cdl_room_reflectances r = {rho[0], rho[1], rho[2]};
        cdl_room_transfer t;
        cdl_room_transfer_factors(&room, &r, &t);
        /* CIE 190 eq. 7, 8b: the walls' indirect illuminance; Lb = E_WID / pi */
        double E_wid = (double)out->luminaires *
                       (out->direct_floor_lm * t.floor_to_walls + out->direct_walls_lm * t.walls_to_walls +
                        out->direct_ceiling_lm * t.ceiling_to_walls) /
                       walls_m2;
        out->background_cd_m2[s] = E_wid * CDL_INV_PI;
    }
    for (int view = 0; view < 2; ++view) {
        cdl_ugr_sum sum = array_glare(lum, X, room.nx, room.ny, S, view);
        for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
            cdl_ugr u;
            st = cdl_ugr_evaluate(&sum, cdl_nits(out->background_cd_m2[s]), 0.0, &u, err);
            if (st != CDL_OK) return st;
            out->defined[view] = u.defined;
            out->ugr[view][s] = u.value;
        }
    }
    return CDL_OK;
}

/* The options: SHR positive, dividing every room side into whole spacings. */
static cdl_status check_options(const cdl_ugr_table_options *o, cdl_error *err)
{
    double shr = o->spacing_to_height;
    if (!(shr > 0.0) || !isfinite(shr) || shr > 2.0 || 1.0 / shr > 1000.0)
        return cdl_error_set(err, CDL_ERR_USAGE, "UGR table: spacing to height ratio: expected 0.001 to 2, found %g",
                             shr);
    for (size_t i = 0; i < CDL_UGR_TABLE_ROOMS; ++i)
        for (int k = 0; k < 2; ++k) {
            double n = cdl_ugr_table_rooms[i][k] / shr;
            if (fabs(n - nearbyint(n)) > 1e-9 * n)
                return cdl_error_set(err, CDL_ERR_USAGE,
                                     "UGR table: spacing to height ratio %g does not divide the %gH side of the "
                                     "standard rooms into whole spacings (0.25, 0.5, 1 or 2 do)",
                                     shr, cdl_ugr_table_rooms[i][k]);
        }
    return CDL_OK;
}

/* Why a photometry cannot be rated, or CDL_OK. */
static cdl_status check_rateable(const cdl_photometry *p, cdl_error *err)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    if (m->radiometric)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "cannot rate glare: the table is radiant intensity (%s), and UGR rates luminance in cd/m2",
                             m->units_keyword[0] ? m->units_keyword : "W/sr");
    if (!cdl_luminous_opening_is_spread(&m->opening))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "cannot rate glare: the file gives no luminous opening (shape %s, %g x %g x %g m); UGR "
                             "weighs the luminance of the luminous parts, I / A (CIE 117:1995 4.5), which needs their area",
                             cdl_luminous_shape_name(m->opening.shape), m->opening.width_m, m->opening.length_m,
                             m->opening.height_m);
    return CDL_OK;
}

cdl_status cdl_ugr_table_compute(const cdl_photometry *photometry, const cdl_ugr_table_options *options,
                                 cdl_ugr_table *table, cdl_error *err)
{
    cdl_ugr_table_options given = CDL_UGR_TABLE_OPTIONS_INIT;
    cdl_sized_struct_read(&given, sizeof given, options);
    const cdl_ugr_table_options *o = &given;
    cdl_status st = check_options(o, err);
    if (st == CDL_OK) st = check_rateable(photometry, err);
    if (st != CDL_OK) return st;
    table_luminaire lum;
    lum.photometry = photometry;
    lum.opening = cdl_photometry_opening(photometry);
    lum.scale = cdl_photometry_output_factor(photometry);
    double half[4];
    cdl_luminous_flux cone[4];
    for (int k = 0; k < 4; ++k) half[k] = acos(cdl_room_zone_cosines[k]) * CDL_RAD_TO_DEG;
    cdl_photometry_cone_fluxes(photometry, half, 4, cone);
    for (int k = 0; k < 4; ++k) lum.cumulative_lm[k] = lum.scale * cone[k].lm;
    lum.upward_lm = lum.scale * cdl_photometry_zone_flux(photometry, 90.0, 180.0).lm;
    double flux = lum.cumulative_lm[3] + lum.upward_lm;
    for (int k = 0; k < 4; ++k)
        if (!isfinite(lum.cumulative_lm[k])) return cdl_error_out_of_memory(err);
    if (!(flux > 0.0) || !isfinite(flux))
        return cdl_error_set(err, CDL_ERR_INPUT, "cannot rate glare: the table gives no light (flux %g lm)", flux);
    cdl_ugr_table t;
    memset(&t, 0, sizeof t);
    t.size = sizeof t;
    t.spacing_to_height = o->spacing_to_height;
    t.output_factor = lum.scale;
    t.flux_lm = flux;
    memcpy(t.reflectances, cdl_ugr_table_reflectances, sizeof t.reflectances);
    for (size_t i = 0; i < CDL_UGR_TABLE_ROOMS; ++i) {
        st = table_room(&lum, o->spacing_to_height, i, &t.rooms[i], err);
        if (st != CDL_OK) return st;
    }
    cdl_sized_struct_fill(table, &t, sizeof t);
    return CDL_OK;
}
