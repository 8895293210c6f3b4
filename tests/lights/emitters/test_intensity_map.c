/* The intensity map (lights/emitters/intensity_map.h), the one-light
 * draw's far-field guess:
 *  - an isotropic point holds its intensity everywhere (to float rounding);
 *  - at its nodes the map holds the emitter's intensity exactly (to float
 *    rounding), for a turned, asymmetric table;
 *  - its flux, the integral of the interpolated intensity over the sphere,
 *    is the emitter's flux to the bilinear interpolation's error;
 *  - behind a downlight (no light beyond gamma 80 degrees) it is exactly 0
 *    wherever the four nodes around a direction are dark;
 *  - a resolution below 2 is refused. */
#include <math.h>

#include "check.h"
#include "base/rng.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/intensity_map.h"
#include "lights/photometry/photometry.h"
#include "radiometry/constants.h"

static cdl_photometry *read_table(const char *name, cdl_error *err)
{
    char path[512];
    snprintf(path, sizeof path, "%s/data/office/%s", CANDELA_SOURCE_DIR, name);
    cdl_photometry_read_options opts = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *ph = NULL;
    CHECK_OK(cdl_photometry_read_file(path, &opts, &ph, err), err);
    return ph;
}

static cdl_emitter *place(const cdl_photometry *ph, double rx, double ry, double rz, cdl_error *err)
{
    cdl_goniometric_params p = CDL_GONIOMETRIC_PARAMS_DEFAULT;
    p.position = cdl_vec3_make(1.0, 2.0, 3.0);
    p.rotation_deg[0] = rx;
    p.rotation_deg[1] = ry;
    p.rotation_deg[2] = rz;
    p.photometry = ph;
    cdl_emitter *e = NULL;
    CHECK_OK(cdl_emitter_create_goniometric(&p, &e, err), err);
    return e;
}

/* The integral of the map's intensity over the sphere (lm), by the
 * midpoint rule on an n x n grid in (z, phi), equal-area cells. */
static double map_flux(const cdl_intensity_map *m, int n)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double z = -1.0 + 2.0 * (i + 0.5) / n, s = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * (j + 0.5) / n;
            sum += cdl_intensity_map_lookup(m, cdl_vec3_make(s * cos(phi), s * sin(phi), z)).cd;
        }
    return sum * CDL_FOUR_PI / ((double)n * n);
}

/* The map's flux against the emitter's, within rel; releases both. */
static void check_flux(cdl_intensity_map *m, cdl_emitter *e, const char *what, double rel)
{
    double phi = cdl_emitter_flux(e).lm, mapped = map_flux(m, 1000);
    CHECK_REL(mapped, phi, rel);
    fprintf(stderr, "%s: flux %.3f lm, of its map %.3f lm (%.2g relative)\n", what, phi, mapped,
            fabs(mapped - phi) / phi);
    cdl_intensity_map_release(m);
    cdl_emitter_release(e);
}

int main(void)
{
    cdl_error err;
    cdl_error_clear(&err);

    /* 1. Isotropic: 1e-7 relative, a float's rounding of 250 cd. */
    cdl_point_params pp = {cdl_vec3_make(0, 0, 0), cdl_candelas(250.0)};
    cdl_emitter *point = NULL;
    CHECK_OK(cdl_emitter_create_point(&pp, &point, &err), &err);
    cdl_intensity_map *m = NULL;
    CHECK_OK(cdl_intensity_map_build(point, CDL_INTENSITY_MAP_RESOLUTION, &m, &err), &err);
    cdl_rng_key key = {3, 9};
    double worst = 0.0;
    for (uint64_t k = 0; k < 2000; ++k) {
        double r[2];
        cdl_rng_uniform2(key, k, r);
        cdl_vec3 d = cdl_vec3_make(r[0] - 0.5, r[1] - 0.5, (double)(k % 7) / 3.0 - 1.0);
        if (!(cdl_vec3_length(d) > 0.0)) continue;
        worst = fmax(worst, fabs(cdl_intensity_map_lookup(m, d).cd - 250.0) / 250.0);
    }
    CHECK_MSG(worst <= 1e-7, "isotropic map off by %.3g", worst);
    cdl_intensity_map_release(m);
    cdl_emitter_release(point);

    /* 2. and 3. The linear luminaire, I(C, g) = 800 cos(g)^(1 + 1.2 cos^2 C),
     *    turned about all three axes. */
    cdl_photometry *linear = read_table("linear.ies", &err);
    cdl_emitter *e = linear ? place(linear, 20.0, -35.0, 50.0, &err) : NULL;
    if (e) {
        CHECK_OK(cdl_intensity_map_build(e, CDL_INTENSITY_MAP_RESOLUTION, &m, &err), &err);
        int res = cdl_intensity_map_resolution(m);
        CHECK(res == CDL_INTENSITY_MAP_RESOLUTION);
        /* at the nodes: the emitter's intensity, to a float's rounding
         * (6e-8) of the table's largest value */
        double node_err = 0.0;
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                cdl_vec3 w = cdl_intensity_map_node_direction(m, i, j);
                double exact = cdl_emitter_intensity(e, w).cd;
                node_err = fmax(node_err, fabs(cdl_intensity_map_node(m, i, j).cd - exact));
                node_err = fmax(node_err, fabs(cdl_intensity_map_lookup(m, w).cd - exact));
            }
        CHECK_MSG(node_err <= 800.0 * 1e-6, "nodes off by %.3g cd", node_err);
        /* The flux: the bilinear interpolant of a smooth I errs by about
         * (h^2 / 8) I'' per cell, h ~ 3 degrees (0.05 rad) here and I'' of
         * the order of I per rad^2: 3e-4 relative; the midpoint rule on
         * 1000 x 1000 cells adds far less. 1e-3 leaves room for the
         * distribution's kink along the horizon (no light upwards). */
        check_flux(m, e, "linear luminaire", 1e-3);
    }
    cdl_photometry_release(linear);

    /* 4. The downlight, unturned: no light beyond gamma = 80 degrees
     *    (fading to 0 cd from 75), so none upwards. Directions above the
     *    horizon have all four nodes around them beyond 80 degrees (a cell's
     *    corners lie within 7.7 degrees of one another): exactly 0. */
    cdl_photometry *down = read_table("downlight.ies", &err);
    e = down ? place(down, 0.0, 0.0, 0.0, &err) : NULL;
    if (e) {
        CHECK_OK(cdl_intensity_map_build(e, CDL_INTENSITY_MAP_RESOLUTION, &m, &err), &err);
        int lit = 0;
        for (uint64_t k = 0; k < 4000; ++k) {
            double r[2];
            cdl_rng_uniform2(key, 10000 + k, r);
            double z = 1e-9 + (1.0 - 1e-9) * r[0], s = sqrt(fmax(0.0, 1.0 - z * z)), a = CDL_TWO_PI * r[1];
            lit += cdl_intensity_map_lookup(m, cdl_vec3_make(s * cos(a), s * sin(a), z)).cd != 0.0;
        }
        CHECK_MSG(lit == 0, "%d of 4000 directions above a downlight lit", lit);
        /* and straight down, its 1000 cd at a node (the square's corner) */
        CHECK_REL(cdl_intensity_map_lookup(m, cdl_vec3_make(0, 0, -1)).cd, 1000.0, 1e-7);
        /* its cut-off's kinks (5-degree steps of the table from 60 to 80
         * degrees, slopes changing by up to 25 cd a degree) blur over a
         * cell each, a few 1e-4 of the flux: 1e-3 */
        check_flux(m, e, "downlight", 1e-3);
    }
    cdl_photometry_release(down);

    /* 5. Refused: a map of one node per side. */
    cdl_emitter *p2 = NULL;
    CHECK_OK(cdl_emitter_create_point(&pp, &p2, &err), &err);
    m = NULL;
    CHECK(cdl_intensity_map_build(p2, 1, &m, &err) == CDL_ERR_USAGE && m == NULL);
    cdl_emitter_release(p2);
    return check_finish();
}
