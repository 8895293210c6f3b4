/* photometry_summary.c - figures a lighting designer reads off a
 * distribution: flux by hemisphere and zone, light output ratio, maximum
 * intensity and its direction, beam and field angles, efficacy. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lights/photometry_internal.h"
#include "radiometry/constants.h"

/* Samples per degree along a plane when looking for the maximum and the
 * crossings; each crossing is then refined by bisection. */
#define PLANE_SAMPLES_PER_DEG 20

static double plane_intensity(const cdl_photometry *p, cdl_photometry_plane plane, double theta_deg)
{
    /* theta measured from nadir, positive toward C0 (or C90), negative toward C180 (C270) */
    double t = theta_deg * CDL_DEG_TO_RAD;
    cdl_vec3 d = plane == CDL_PLANE_C0_C180 ? cdl_vec3_make(sin(t), 0.0, -cos(t)) : cdl_vec3_make(0.0, sin(t), -cos(t));
    return cdl_photometry_intensity(p, d).cd;
}

/* The crossing of `level` between theta a (value >= level) and b (< level). */
static double refine(const cdl_photometry *p, cdl_photometry_plane plane, double a, double b, double level)
{
    for (int k = 0; k < 40; ++k) {
        double m = 0.5 * (a + b);
        if (plane_intensity(p, plane, m) >= level) a = m;
        else b = m;
    }
    return 0.5 * (a + b);
}

/* Full angles at the given fractions of the plane's maximum (-1 when undefined). */
static void plane_spreads(const cdl_photometry *p, cdl_photometry_plane plane, const double *fractions, int count,
                          double *out)
{
    for (int f = 0; f < count; ++f) out[f] = -1.0;
    const int n = 360 * PLANE_SAMPLES_PER_DEG;
    const double step = 1.0 / PLANE_SAMPLES_PER_DEG;
    double *I = malloc((size_t)n * sizeof *I);
    if (!I) return;
    int peak = 0;
    for (int k = 0; k < n; ++k) {
        I[k] = plane_intensity(p, plane, -180.0 + step * k);
        if (I[k] > I[peak]) peak = k;
    }
    for (int f = 0; f < count && I[peak] > 0.0; ++f) {
        if (!(fractions[f] > 0.0 && fractions[f] < 1.0)) continue;
        double level = fractions[f] * I[peak];
        /* walk both ways round the circle from the peak to the first sample below the level */
        int right = -1, left = -1;
        for (int s = 1; s < n && right < 0; ++s)
            if (I[(peak + s) % n] < level) right = s;
        for (int s = 1; s < n && left < 0; ++s)
            if (I[((peak - s) % n + n) % n] < level) left = s;
        if (right < 0 || left < 0) continue;
        double t0 = -180.0 + step * peak;
        double tr = refine(p, plane, t0 + step * (right - 1), t0 + step * right, level);
        double tl = refine(p, plane, t0 - step * (left - 1), t0 - step * left, level);
        out[f] = fmin(tr - tl, 360.0);
    }
    free(I);
}

double cdl_photometry_spread_angle(const cdl_photometry *p, cdl_photometry_plane plane, double fraction)
{
    double out;
    plane_spreads(p, plane, &fraction, 1, &out);
    return out;
}

void cdl_photometry_summarize(const cdl_photometry *p, cdl_photometry_summary *s)
{
    memset(s, 0, sizeof *s);
    s->flux = cdl_photometry_flux(p);
    s->downward_flux = cdl_photometry_zone_flux(p, 0.0, 90.0);
    s->upward_flux = cdl_lumens(fmax(0.0, s->flux.lm - s->downward_flux.lm));
    double zones[CDL_PHOTOMETRY_ZONES];
    cdl_photometry_zones(p, zones);
    for (int k = 0; k < CDL_PHOTOMETRY_ZONES; ++k) s->zone_flux[k] = cdl_lumens(zones[k]);
    s->downward_fraction = s->flux.lm > 0.0 ? s->downward_flux.lm / s->flux.lm : 0.0;
    const cdl_photometry_metadata *m = &p->meta;
    if (!m->absolute && m->rated_lamp_flux_lm > 0.0) {
        s->lamp_flux_known = 1;
        s->lamp_flux = cdl_lumens(m->rated_lamp_flux_lm);
        s->lor_known = 1;
        /* light output ratio = luminaire flux / lamp flux (CIE 121) */
        s->lor = s->flux.lm / m->rated_lamp_flux_lm;
    }
    s->max_intensity = cdl_photometry_max_intensity(p);
    s->max_h_deg = p->h[p->max_i];
    s->max_v_deg = p->v[p->max_j];
    if (p->type == CDL_PHOTOMETRIC_TYPE_C) {
        s->max_c_deg = s->max_h_deg;
        s->max_gamma_deg = s->max_v_deg;
    } else {
        cdl_vec3 d = cdl_photometry_direction(p->type, s->max_h_deg, s->max_v_deg);
        double c, g;
        cdl_photometry_direction_to_hv(CDL_PHOTOMETRIC_TYPE_C, d, &c, &g);
        s->max_c_deg = c;
        s->max_gamma_deg = g;
    }
    /* beam: 50 % of the maximum, field: 10 % (IES / CIE usage) */
    const double fractions[2] = {0.5, 0.1};
    for (int k = 0; k < 2; ++k) {
        double spread[2];
        plane_spreads(p, (cdl_photometry_plane)k, fractions, 2, spread);
        s->beam_angle_deg[k] = spread[0];
        s->field_angle_deg[k] = spread[1];
    }
    if (m->input_watts > 0.0) {
        s->efficacy_known = 1;
        /* luminaire efficacy = luminaire flux / input power; the table is for
         * the reference ballast, the input power for the real one */
        s->efficacy = cdl_lumens_per_watt(s->flux.lm * cdl_photometry_output_factor(p) / m->input_watts);
    }
}
