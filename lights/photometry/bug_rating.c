/* bug_rating.c - the IES TM-15-11 luminaire classification of an outdoor
 * luminaire's lumens and its BUG (backlight, uplight, glare) rating
 * (TM-15-11 Addendum A).
 *
 * Zones (TM-15-11 section 3), by vertical angle from nadir, split front
 * and back by the vertical plane across the luminaire's front direction:
 *   FL / BL 0-30, FM / BM 30-60, FH / BH 60-80, FVH / BVH 80-90 degrees;
 *   UL 90-100 and UH 100-180 degrees, all round.
 * Front is the half-space towards IES H = 0, the frame's C = 0 (TM-15's
 * "forward light: 270 to 90 degrees horizontal"; in IES roadway files the
 * street side, H = 90 and H = 270 running along the road). EULUMDAT road
 * luminaires often put the street side at C90: their rating here treats
 * C0 as the front all the same.
 *
 * The rating is the lowest number whose every limit the zones keep within
 * (lumens of the luminaire as it operates: the table times its output
 * factor). The limits are TM-15-11 Addendum A's Tables as the
 * IES/IDA Model Lighting Ordinance (2011) reprints them (Table C); the
 * TM-15 text itself was not available to us. The glare limits are those
 * for asymmetric (type I to IV) distributions.
 */
#include <math.h>

#include "base/error_report.h"
#include "lights/photometry/sphere_quadrature.h"
#include "radiometry/constants.h"

enum { FL, FM, FH, FVH, BL, BM, BH, BVH, UL, UH };

/* Limits in lumens for ratings 0..4 (5: beyond). */
static const double backlight_limits[3][5] = {
    /* BH */ {110, 500, 1000, 2500, 5000},
    /* BM */ {220, 1000, 2500, 5000, 8500},
    /* BL */ {110, 500, 1000, 2500, 5000}};
static const int backlight_zones[3] = {BH, BM, BL};
static const double uplight_limits[2][5] = {
    /* UH */ {0, 10, 50, 500, 1000},
    /* UL */ {0, 10, 50, 500, 1000}};
static const int uplight_zones[2] = {UH, UL};
static const double glare_limits[4][5] = {
    /* FVH */ {10, 75, 150, 300, 500},
    /* BVH */ {10, 75, 150, 300, 500},
    /* FH */ {660, 1800, 5000, 7500, 12000},
    /* BH */ {110, 500, 1000, 2500, 5000}};
static const int glare_zones[4] = {FVH, BVH, FH, BH};

/* Quadrature of the zones: 0.5 degree steps of gamma, C every degree
 * (no node on a zone's edge: those fall on whole degrees and on C = 90, 270). */
#define BUG_GAMMA_STEP_DEG 0.5
#define BUG_C_NODES 360

const char *cdl_bug_zone_name(int zone)
{
    static const char *const names[CDL_BUG_ZONES] = {"FL", "FM", "FH", "FVH", "BL", "BM", "BH", "BVH", "UL", "UH"};
    return zone >= 0 && zone < CDL_BUG_ZONES ? names[zone] : "";
}

/* The lowest rating whose limits every listed zone keeps within. */
static int rate(const double *lumens, const double (*limits)[5], const int *zones, int count)
{
    for (int r = 0; r < 5; ++r) {
        int within = 1;
        /* a zone at its limit is within it; 1e-9 lm of quadrature noise over a 0 limit is not light */
        for (int z = 0; z < count; ++z) within &= lumens[zones[z]] <= limits[z][r] + 1e-9;
        if (within) return r;
    }
    return 5;
}

/* Lumens of the lower-hemisphere zones, by quadrature. */
static int lower_zones(const cdl_photometry *p, double *zone)
{
    cdl_sphere_quadrature q;
    if (!cdl_sphere_quadrature_sample(p, 0.0, 90.0, BUG_GAMMA_STEP_DEG, BUG_C_NODES, &q)) return 0;
    static const double edge[4] = {30.0, 60.0, 80.0, 90.0};
    for (size_t i = 0; i < q.ng; ++i) {
        int band = 0;
        while (band < 3 && q.gamma_deg[i] > edge[band]) ++band;
        for (size_t j = 0; j < q.nc; ++j) {
            int front = cos(q.c_deg[j] * CDL_DEG_TO_RAD) > 0.0;
            zone[(front ? FL : BL) + band] += q.cd[i * q.nc + j] * q.c_weight[j] * q.weight[i];
        }
    }
    cdl_sphere_quadrature_free(&q);
    return 1;
}

cdl_status cdl_photometry_bug_rating(const cdl_photometry *p, cdl_bug_rating *out, cdl_error *err)
{
    *out = (cdl_bug_rating){0};
    if (p->meta.radiometric)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "a BUG rating counts lumens, and the table is radiant intensity in %s ([%s])",
                             cdl_photometry_intensity_unit(p), p->meta.units_keyword);
    double *z = out->zone_lm;
    if (!lower_zones(p, z)) return cdl_error_out_of_memory(err);
    /* uplight zones are whole rings: exact for type C (photometry_flux.c) */
    z[UL] = cdl_photometry_zone_flux(p, 90.0, 100.0).lm;
    z[UH] = cdl_photometry_zone_flux(p, 100.0, 180.0).lm;
    double k = cdl_photometry_output_factor(p);
    for (int i = 0; i < CDL_BUG_ZONES; ++i) z[i] *= k;
    out->b = rate(z, backlight_limits, backlight_zones, 3);
    out->u = rate(z, uplight_limits, uplight_zones, 2);
    out->g = rate(z, glare_limits, glare_zones, 4);
    return CDL_OK;
}
