/* photometry_plot.c - the polar intensity diagram of a luminaire, drawn
 * with cairo (photometry_polar.h), and as an SVG file. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "graphics/text.h"
#include "lights/photometry/photometry_internal.h"
#include "lights/photometry/photometry_polar.h"
#include "radiometry/constants.h"

/* The rings: a step of 1, 2, 2.5 or 5 x 10^k, 3 to 6 of them, the outer
 * one the smallest such value at or above the peak (a 247 cd/klm peak
 * gets 5 rings of 50 up to 250). */
#define MIN_RINGS 3
#define MAX_RINGS 6

static double fit_rings(double peak, int *rings)
{
    static const double mantissa[4] = {1.0, 2.0, 2.5, 5.0};
    double best = 0.0;
    *rings = 4;
    if (!(peak > 0.0) || !isfinite(peak)) return 1.0;
    double e0 = floor(log10(peak / MAX_RINGS));
    for (int e = 0; e < 2; ++e)
        for (int m = 0; m < 4; ++m) {
            double step = mantissa[m] * pow(10.0, e0 + e);
            int n = (int)ceil(peak / step * (1.0 - 1e-12));
            if (n < MIN_RINGS || n > MAX_RINGS) continue;
            if (best == 0.0 || n * step < best) {
                best = n * step;
                *rings = n;
            }
        }
    return best > 0.0 ? best : peak;
}

double cdl_photometry_plot_scale(const cdl_photometry *p, double *per_klm, int *rings)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    /* the table's own integral (in W/sr x sr for a radiometric file: W/sr per kW) */
    double flux = !m->absolute && m->rated_lamp_flux_lm > 0.0 ? m->rated_lamp_flux_lm : p->flux_lm;
    /* cd/klm = I x 1000 / flux */
    *per_klm = flux > 0.0 ? 1000.0 / flux : 0.0;
    int n;
    double top = fit_rings(p->max_cd * *per_klm, &n);
    if (rings) *rings = n;
    return top;
}

/* One curve: the frame's vertical plane through C = c_right (drawn to the
 * right of nadir) and c_right + 180 (to the left). */
typedef struct polar_curve {
    double c_right;
    double r, g, b;
    int dash; /* 0 solid, 1 dashed, 2 dotted */
    char label[96];
} polar_curve;

/* theta from -180 (the left side's zenith) through 0 (nadir) to 180: the
 * curve's radius in points at that plot angle. */
static double curve_radius(const cdl_photometry *p, const polar_curve *c, double t, double per_klm, double top)
{
    double plane = t >= 0.0 ? c->c_right : fmod(c->c_right + 180.0, 360.0);
    return CDL_POLAR_RADIUS * cdl_photometry_intensity_c_gamma(p, plane, fabs(t)).cd * per_klm / top;
}

static void trace_curve(cairo_t *cr, const cdl_photometry *p, const polar_curve *c, double per_klm, double top)
{
    for (int t = -180; t <= 180; ++t) {
        double r = curve_radius(p, c, t, per_klm, top), a = t * CDL_DEG_TO_RAD;
        double x = CDL_POLAR_CX + r * sin(a), y = CDL_POLAR_CY + r * cos(a);
        if (t == -180) cairo_move_to(cr, x, y);
        else cairo_line_to(cr, x, y);
    }
}

/* Is `c` within a degree of one of the planes drawn anyway (C0, C90, C180, C270)? */
static int on_main_plane(double c)
{
    double r = fmod(c, 90.0);
    return r < 1.0 || r > 89.0;
}

/* The planes drawn: C0-C180 and C90-C270 (type A/B: their V plane, H = 0,
 * and H plane, V = 0, with positive angles to the right), and the plane
 * through the peak where it is neither. */
static int plan_curves(const cdl_photometry *p, const cdl_photometry_summary *s, polar_curve *c)
{
    int n = 0, typed = p->type != CDL_PHOTOMETRIC_TYPE_C;
    c[n++] = (polar_curve){0.0, 0.8, 0.0, 0.0, 0, ""};
    c[n++] = (polar_curve){typed ? 270.0 : 90.0, 0.0, 0.0, 0.8, 1, ""};
    snprintf(c[0].label, sizeof c[0].label, "%s", typed ? "V plane, H = 0 (solid; V > 0 right)" : "C0-C180 (solid; C0 right)");
    snprintf(c[1].label, sizeof c[1].label, "%s",
             typed ? "H plane, V = 0 (dashed; H > 0 right)" : "C90-C270 (dashed; C90 right)");
    int rotational = p->symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    int axial = s->max_gamma_deg < 1.0 || s->max_gamma_deg > 179.0;
    if (!rotational && !axial && !on_main_plane(s->max_c_deg)) {
        c[n] = (polar_curve){s->max_c_deg, 0.0, 0.5, 0.0, 2, ""};
        if (typed)
            snprintf(c[n].label, sizeof c[n].label, "the plane through zero and the peak, H %.1f, V %.1f (dotted; "
                     "the peak right)", s->max_h_deg, s->max_v_deg);
        else
            snprintf(c[n].label, sizeof c[n].label, "C%.1f-C%.1f (dotted; through the peak, C%.1f right)",
                     s->max_c_deg, fmod(s->max_c_deg + 180.0, 360.0), s->max_c_deg);
        ++n;
    }
    return n;
}

/* The plot angle along which the ring labels sit: of the 12 between the
 * 30-degree rays, the one where every curve keeps farthest from every
 * ring over the width of a label. */
static double label_angle(const cdl_photometry *p, const polar_curve *c, int nc, double per_klm, double top, int rings)
{
    double best = 0.0, best_clearance = -1.0;
    for (int k = 0; k < 12; ++k) {
        double t = -165.0 + 30.0 * k, clearance = 1e9;
        for (int ring = 1; ring <= rings; ++ring) {
            double rr = CDL_POLAR_RADIUS * ring / rings;
            double half = (16.0 + 4.0) / rr * CDL_RAD_TO_DEG; /* half a label's width, and a margin */
            for (int q = -2; q <= 2; ++q)
                for (int i = 0; i < nc; ++i) {
                    double tt = t + half * q / 2.0;
                    if (fabs(tt) > 180.0) continue;
                    clearance = fmin(clearance, fabs(curve_radius(p, &c[i], tt, per_klm, top) - rr));
                }
        }
        /* prefer the upper half on a tie: downward light leaves it empty */
        if (clearance > best_clearance + 1e-9 || (fabs(clearance - best_clearance) <= 1e-9 && fabs(t) > fabs(best))) {
            best_clearance = clearance;
            best = t;
        }
    }
    return best;
}

/* The title inside the page: wrapped to its width, at a smaller size or
 * cut short if two lines do not hold it. Returns its height. */
static double draw_title(cairo_t *cr, const char *title)
{
    if (!title || !*title) return 0.0;
    const double width = CDL_POLAR_WIDTH - 32.0, max_height = 44.0;
    cdl_text_style style = {.size = 15.0, .align = CDL_TEXT_CENTRE, .wrap_width = width};
    double w, h;
    cdl_text_measure(cr, title, &style, &w, &h);
    if (h > max_height) {
        style.size = 12.0;
        cdl_text_measure(cr, title, &style, &w, &h);
    }
    char cut[512];
    snprintf(cut, sizeof cut, "%s", title);
    size_t n = strlen(cut);
    while (h > max_height && n > 4) {
        /* cut at a character boundary (not inside a UTF-8 sequence) and mark it */
        do --n;
        while (n > 0 && ((unsigned char)cut[n] & 0xC0) == 0x80);
        snprintf(cut + n, sizeof cut - n, "\u2026");
        cdl_text_measure(cr, cut, &style, &w, &h);
    }
    return cdl_text_draw(cr, CDL_POLAR_CX, 10.0, cut, &style);
}

/* The rings, labelled along the emptiest angle, and rays every 30 degrees. */
static void draw_grid(cairo_t *cr, double top, int rings, double angle)
{
    const cdl_text_style small = {.size = 12.0}, centred = {.size = 12.0, .align = CDL_TEXT_CENTRE};
    for (int t = -150; t <= 180; t += 30) {
        double a = t * CDL_DEG_TO_RAD;
        cairo_set_source_rgb(cr, 0.87, 0.87, 0.87);
        cairo_move_to(cr, CDL_POLAR_CX, CDL_POLAR_CY);
        cairo_line_to(cr, CDL_POLAR_CX + CDL_POLAR_RADIUS * sin(a), CDL_POLAR_CY + CDL_POLAR_RADIUS * cos(a));
        cairo_stroke(cr);
        char label[16];
        snprintf(label, sizeof label, "%d\u00b0", t < 0 ? -t : t);
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        cdl_text_draw(cr, CDL_POLAR_CX + (CDL_POLAR_RADIUS + 16.0) * sin(a),
                      CDL_POLAR_CY + (CDL_POLAR_RADIUS + 16.0) * cos(a) - 8.0, label, &centred);
    }
    for (int k = 1; k <= rings; ++k) {
        double r = CDL_POLAR_RADIUS * k / rings;
        cairo_set_source_rgb(cr, 0.73, 0.73, 0.73);
        cairo_new_sub_path(cr);
        cairo_arc(cr, CDL_POLAR_CX, CDL_POLAR_CY, r, 0.0, 2.0 * CDL_PI);
        cairo_stroke(cr);
    }
    for (int k = 1; k <= rings; ++k) {
        double r = CDL_POLAR_RADIUS * k / rings, a = angle * CDL_DEG_TO_RAD, w, h;
        char label[32];
        snprintf(label, sizeof label, "%g", top * k / rings);
        cdl_text_measure(cr, label, &small, &w, &h);
        double x = CDL_POLAR_CX + r * sin(a) - w / 2.0, y = CDL_POLAR_CY + r * cos(a) - h / 2.0;
        /* on a white patch, in their own grey (CDL_POLAR_RING_LABEL_GREY) */
        cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
        cairo_rectangle(cr, x - 1.0, y, w + 2.0, h);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, CDL_POLAR_RING_LABEL_GREY, CDL_POLAR_RING_LABEL_GREY, CDL_POLAR_RING_LABEL_GREY);
        cdl_text_draw(cr, x, y, label, &small);
    }
}

/* Below the diagram: each curve's key, then the peak and the beam angles;
 * the unit to the right. */
static void draw_legend(cairo_t *cr, const cdl_photometry *p, const cdl_photometry_summary *s, const polar_curve *c,
                        int nc, double per_klm)
{
    const cdl_text_style small = {.size = 11.0}, right = {.size = 11.0, .align = CDL_TEXT_RIGHT};
    const double y0 = CDL_POLAR_HEIGHT - 86.0, step = 16.0;
    for (int i = 0; i < nc; ++i) {
        cairo_set_source_rgb(cr, c[i].r, c[i].g, c[i].b);
        cdl_text_draw(cr, 16.0, y0 + step * i, c[i].label, &small);
    }
    int radiometric = cdl_photometry_get_metadata(p)->radiometric, typed = p->type != CDL_PHOTOMETRIC_TYPE_C;
    const char *unit = radiometric ? "W/sr per kW" : "cd/klm";
    char line[160];
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    snprintf(line, sizeof line, "%s, %s down", unit, typed ? "photometric zero (H = V = 0)" : "nadir");
    cdl_text_draw(cr, CDL_POLAR_WIDTH - 16.0, y0, line, &right);
    if (typed)
        snprintf(line, sizeof line, "peak %.4g %s at H %.1f, V %.1f", p->max_cd * per_klm, unit, s->max_h_deg,
                 s->max_v_deg);
    else
        snprintf(line, sizeof line, "peak %.4g %s at C %.1f, \u03b3 %.1f", p->max_cd * per_klm, unit, s->max_c_deg,
                 s->max_gamma_deg);
    cdl_text_draw(cr, 16.0, y0 + step * nc, line, &small);
    char a[2][24];
    for (int k = 0; k < 2; ++k)
        if (s->beam_angle_deg[k] >= 0.0) snprintf(a[k], sizeof a[k], "%.1f\u00b0", s->beam_angle_deg[k]);
        else snprintf(a[k], sizeof a[k], "not defined");
    if (s->spread_about_peak)
        snprintf(line, sizeof line, "beam (50 %%) %s in the vertical plane through the peak, %s across it", a[0], a[1]);
    else snprintf(line, sizeof line, "beam (50 %%) %s in C0-C180, %s in C90-C270", a[0], a[1]);
    cdl_text_draw(cr, 16.0, y0 + step * (nc + 1), line, &small);
}

void cdl_polar_diagram_draw(cairo_t *cr, const cdl_polar_diagram *d)
{
    const cdl_photometry *p = d->photometry;
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    double per_klm = 0.0;
    int rings;
    double top = cdl_photometry_plot_scale(p, &per_klm, &rings);
    polar_curve curves[3];
    int nc = plan_curves(p, &s, curves);
    cairo_save(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_rectangle(cr, 0.0, 0.0, CDL_POLAR_WIDTH, CDL_POLAR_HEIGHT);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    draw_title(cr, d->title);
    cairo_set_line_width(cr, 1.0);
    draw_grid(cr, top, rings, label_angle(p, curves, nc, per_klm, top, rings));
    cairo_set_line_width(cr, 2.0);
    for (int i = 0; i < nc; ++i) {
        const double dashed[2] = {6.0, 4.0}, dotted[2] = {1.5, 3.0};
        cairo_set_dash(cr, curves[i].dash == 1 ? dashed : dotted, curves[i].dash ? 2 : 0, 0.0);
        cairo_set_source_rgb(cr, curves[i].r, curves[i].g, curves[i].b);
        trace_curve(cr, p, &curves[i], per_klm, top);
        cairo_stroke(cr);
    }
    cairo_set_dash(cr, NULL, 0, 0.0);
    draw_legend(cr, p, &s, curves, nc, per_klm);
    cairo_restore(cr);
}

static void draw_figure(cairo_t *cr, const void *user)
{
    cdl_polar_diagram_draw(cr, user);
}

cdl_figure cdl_polar_diagram_figure(cdl_polar_diagram *d)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(d->photometry);
    snprintf(d->accessible_title, sizeof d->accessible_title, "Polar intensity diagram%s%s (%s, nadir down)",
             d->title && *d->title ? ": " : "", d->title ? d->title : "", m->radiometric ? "W/sr per kW" : "cd/klm");
    return (cdl_figure){.width = CDL_POLAR_WIDTH, .height = CDL_POLAR_HEIGHT, .title = d->accessible_title,
                        .draw = draw_figure, .user = d};
}

cdl_status cdl_photometry_write_polar_svg(const cdl_photometry *p, const char *title, const char *path,
                                          cdl_error *err)
{
    cdl_polar_diagram d = {.photometry = p, .title = title};
    cdl_figure figure = cdl_polar_diagram_figure(&d);
    return cdl_figure_write_svg(&figure, path, err);
}
