/* photometry_summary.c - figures a lighting designer reads off a
 * distribution: flux by hemisphere and zone, light output ratio, maximum
 * intensity and its direction, beam and field angles, efficacy. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/sized_struct.h"
#include "lights/photometry/photometry_internal.h"
#include "radiometry/constants.h"

/* Samples per degree along a plane when looking for the maximum and the
 * crossings; each crossing is then refined by bisection. */
#define PLANE_SAMPLES_PER_DEG 20

/* A great circle of directions through d (unit), turning towards e (unit,
 * perpendicular to d): w(theta) = d cos(theta) + e sin(theta). */
typedef struct great_circle {
    cdl_vec3 d, e;
} great_circle;

static double circle_intensity(const cdl_photometry *p, const great_circle *g, double theta_deg)
{
    double t = theta_deg * CDL_DEG_TO_RAD;
    return cdl_photometry_intensity(p, cdl_vec3_add(cdl_vec3_scale(g->d, cos(t)), cdl_vec3_scale(g->e, sin(t)))).cd;
}

/* The plane through nadir: theta from nadir, positive toward C0 (or C90),
 * negative toward C180 (C270). */
static great_circle nadir_plane(cdl_photometry_plane plane)
{
    great_circle g = {cdl_vec3_make(0.0, 0.0, -1.0),
                      plane == CDL_PLANE_C0_C180 ? cdl_vec3_make(1.0, 0.0, 0.0) : cdl_vec3_make(0.0, 1.0, 0.0)};
    return g;
}

/* The crossing of `level` between theta a (value >= level) and b (< level). */
static double refine(const cdl_photometry *p, const great_circle *g, double a, double b, double level)
{
    for (int k = 0; k < 40; ++k) {
        double m = 0.5 * (a + b);
        if (circle_intensity(p, g, m) >= level) a = m;
        else b = m;
    }
    return 0.5 * (a + b);
}

/* Full angles at the given fractions of the circle's maximum, walking from
 * that maximum both ways to where the intensity first falls below the
 * level (-1 when it never does, or the span exceeds 180 degrees: a beam
 * wider than a half-space has no angle). */
static void circle_spreads(const cdl_photometry *p, const great_circle *g, const double *fractions, int count,
                           double *out)
{
    for (int f = 0; f < count; ++f) out[f] = -1.0;
    const int n = 360 * PLANE_SAMPLES_PER_DEG;
    const double step = 1.0 / PLANE_SAMPLES_PER_DEG;
    double *I = malloc((size_t)n * sizeof *I);
    if (!I) return;
    int peak = 0;
    for (int k = 0; k < n; ++k) {
        I[k] = circle_intensity(p, g, -180.0 + step * k);
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
        double tr = refine(p, g, t0 + step * (right - 1), t0 + step * right, level);
        double tl = refine(p, g, t0 - step * (left - 1), t0 - step * left, level);
        double spread = tr - tl;
        out[f] = spread <= 180.0 ? spread : -1.0;
    }
    free(I);
}

double cdl_photometry_spread_angle(const cdl_photometry *p, cdl_photometry_plane plane, double fraction)
{
    double out;
    great_circle g = nadir_plane(plane);
    circle_spreads(p, &g, &fraction, 1, &out);
    return out;
}

/* A distribution is measured about its peak when its maximum lies more
 * than PEAK_OFF_NADIR_DEG from nadir and nadir has less than
 * PEAK_NADIR_SHARE of it, and it is not rotationally symmetric (a
 * rotationally symmetric batwing keeps the planes through nadir, where its
 * beam reads the same in both): an asymmetric batwing, an asymmetric or wall-pack
 * distribution, a floodlight (IES LM-35 and CIE 43 measure a flood's
 * spreads in the planes through its beam axis, the direction of maximum
 * intensity). A downlight whose maximum sits a step off nadir by noise
 * keeps the planes through nadir. */
#define PEAK_OFF_NADIR_DEG 10.0
#define PEAK_NADIR_SHARE 0.9

/* A table whose every plane is the same (a single plane, or an EULUMDAT
 * file of Isym 0 with equal planes): its beam is a cone about nadir, and
 * the planes through nadir show it the same in every direction. */
static int is_rotational(const cdl_photometry *p)
{
    if (p->type != CDL_PHOTOMETRIC_TYPE_C) return 0;
    double tol = 1e-9 * p->max_cd;
    for (size_t i = 1; i < p->nh; ++i)
        for (size_t j = 0; j < p->nv; ++j)
            if (fabs(p->cd[i * p->nv + j] - p->cd[j]) > tol) return 0;
    return 1;
}

static void spreads(const cdl_photometry *p, cdl_photometry_summary *s)
{
    /* beam: 50 % of the maximum, field: 10 % (IES / CIE usage) */
    const double fractions[2] = {0.5, 0.1};
    cdl_vec3 peak = cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, s->max_c_deg, s->max_gamma_deg);
    double nadir = cdl_photometry_intensity(p, cdl_vec3_make(0.0, 0.0, -1.0)).cd;
    great_circle circles[2] = {nadir_plane(CDL_PLANE_C0_C180), nadir_plane(CDL_PLANE_C90_C270)};
    cdl_vec3 up = cdl_vec3_make(0.0, 0.0, 1.0);
    cdl_vec3 vertical = cdl_vec3_sub(up, cdl_vec3_scale(peak, cdl_vec3_dot(up, peak)));
    if (s->max_gamma_deg > PEAK_OFF_NADIR_DEG && nadir < PEAK_NADIR_SHARE * s->max_intensity.cd &&
        cdl_vec3_length(vertical) > 1e-9 && !is_rotational(p)) {
        s->spread_about_peak = 1;
        s->spread_axis_c_deg = s->max_c_deg;
        s->spread_axis_gamma_deg = s->max_gamma_deg;
        /* In the vertical plane through the peak, and across it. */
        circles[0].d = peak;
        circles[0].e = cdl_vec3_normalize(vertical);
        circles[1].d = peak;
        circles[1].e = cdl_vec3_cross(peak, circles[0].e);
    }
    for (int k = 0; k < 2; ++k) {
        double spread[2];
        circle_spreads(p, &circles[k], fractions, 2, spread);
        s->beam_angle_deg[k] = spread[0];
        s->field_angle_deg[k] = spread[1];
    }
}

/* A radiometric table's figures as what they are: W and W/sr, and NaN for
 * every luminous field (photometry_units.c). */
static void radiometric_figures(const cdl_photometry *p, cdl_photometry_summary *s)
{
    double k = p->meta.radiometric_scale;
    s->radiometric = 1;
    s->radiant_flux = cdl_watts(p->flux_lm * k);
    s->max_radiant_intensity = cdl_watts_per_sr(p->max_cd * k);
    for (int z = 0; z < CDL_PHOTOMETRY_ZONES; ++z) {
        s->radiant_zone_flux[z] = cdl_watts(s->zone_flux[z].lm * k);
        s->zone_flux[z] = cdl_lumens(NAN);
    }
    s->flux = s->downward_flux = s->upward_flux = s->luminaire_flux = cdl_lumens(NAN);
    if (s->lamp_flux_known) s->lamp_flux = cdl_lumens(NAN);
    s->max_intensity = s->luminaire_max_intensity = cdl_candelas(NAN);
}

void cdl_photometry_summarize(const cdl_photometry *p, cdl_photometry_summary *summary)
{
    cdl_photometry_summary all;
    cdl_photometry_summary_compute(p, &all);
    cdl_sized_struct_fill(summary, &all, sizeof all);
}

void cdl_photometry_summary_compute(const cdl_photometry *p, cdl_photometry_summary *s)
{
    memset(s, 0, sizeof *s);
    s->size = sizeof *s;
    const cdl_photometry_metadata *m = &p->meta;
    double flux = p->flux_lm; /* the table's integral in its own unit (lm, or W/sr x sr) */
    s->flux = cdl_lumens(flux);
    s->downward_flux = cdl_photometry_zone_flux(p, 0.0, 90.0);
    s->upward_flux = cdl_lumens(fmax(0.0, flux - s->downward_flux.lm));
    double zones[CDL_PHOTOMETRY_ZONES];
    cdl_photometry_zones(p, zones);
    for (int k = 0; k < CDL_PHOTOMETRY_ZONES; ++k) s->zone_flux[k] = cdl_lumens(zones[k]);
    s->downward_fraction = flux > 0.0 ? s->downward_flux.lm / flux : 0.0;
    s->upward_fraction = flux > 0.0 ? s->upward_flux.lm / flux : 0.0;
    if (!m->absolute && m->rated_lamp_flux_lm > 0.0) {
        s->lamp_flux_known = 1;
        s->lamp_flux = cdl_lumens(m->rated_lamp_flux_lm);
        s->lor_known = 1;
        /* light output ratio = luminaire flux / lamp flux (CIE 121) */
        s->lor = flux / m->rated_lamp_flux_lm;
    }
    s->max_intensity = cdl_candelas(p->max_cd);
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
    spreads(p, s);
    /* The luminaire in a scene: the table times the ballast (output) factor,
     * as the goniometric emitter applies it and as EULUMDAT, which has no
     * field for it, carries it folded into the lamp flux (ldt_write.c). */
    s->output_factor = cdl_photometry_output_factor(p);
    s->luminaire_flux = cdl_lumens(flux * s->output_factor);
    s->luminaire_max_intensity = cdl_candelas(p->max_cd * s->output_factor);
    if (m->radiometric) {
        radiometric_figures(p, s);
        return;
    }
    if (m->input_watts > 0.0) {
        s->efficacy_known = 1;
        /* luminaire efficacy = luminaire flux / input power; the table is for
         * the reference ballast, the input power for the real one */
        s->efficacy = cdl_lumens_per_watt(flux * s->output_factor / m->input_watts);
    }
}
