/* photometry_plot.c - the polar intensity diagram of a luminaire, drawn
 * with cairo (photometry_polar.h), and as an SVG file. */
#include <math.h>
#include <stdio.h>

#include "graphics/text.h"
#include "lights/photometry/photometry_internal.h"
#include "lights/photometry/photometry_polar.h"
#include "radiometry/constants.h"

/* The smallest 1-2-5 value at or above v (> 0). */
static double round_up_125(double v)
{
    double e = pow(10.0, floor(log10(v)));
    static const double m[] = {1.0, 2.0, 5.0, 10.0};
    for (int k = 0; k < 4; ++k)
        if (m[k] * e >= v * (1.0 - 1e-12)) return m[k] * e;
    return 10.0 * e;
}

double cdl_photometry_plot_scale(const cdl_photometry *p, double *per_klm)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    /* the table's own integral (in W/sr x sr for a radiometric file: W/sr per kW) */
    double flux = !m->absolute && m->rated_lamp_flux_lm > 0.0 ? m->rated_lamp_flux_lm : p->flux_lm;
    /* cd/klm = I x 1000 / flux */
    *per_klm = flux > 0.0 ? 1000.0 / flux : 0.0;
    double top = cdl_photometry_max_intensity(p).cd * *per_klm;
    return top > 0.0 ? round_up_125(top) : 1.0;
}

/* One plane's curve: theta from -180 (C180 or C270 side, zenith) through 0
 * (nadir) to 180, x = cx + r sin theta, y = cy + r cos theta. */
static void trace_curve(cairo_t *cr, const cdl_photometry *p, double c_right, double per_klm, double ring_max)
{
    for (int t = -180; t <= 180; ++t) {
        double c = t >= 0 ? c_right : fmod(c_right + 180.0, 360.0), gamma = fabs((double)t);
        double v = cdl_photometry_intensity_c_gamma(p, c, gamma).cd * per_klm;
        double r = CDL_POLAR_RADIUS * v / ring_max, a = t * CDL_DEG_TO_RAD;
        double x = CDL_POLAR_CX + r * sin(a), y = CDL_POLAR_CY + r * cos(a);
        if (t == -180) cairo_move_to(cr, x, y);
        else cairo_line_to(cr, x, y);
    }
}

void cdl_polar_diagram_draw(cairo_t *cr, const cdl_polar_diagram *d)
{
    const cdl_photometry *p = d->photometry;
    double per_klm = 0.0;
    double ring_max = cdl_photometry_plot_scale(p, &per_klm);
    const char *unit = cdl_photometry_get_metadata(p)->radiometric ? "W/sr per kW" : "cd/klm";
    cairo_save(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_rectangle(cr, 0.0, 0.0, CDL_POLAR_WIDTH, CDL_POLAR_HEIGHT);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cdl_text_draw(cr, CDL_POLAR_CX, 10.0, d->title, &(cdl_text_style){.size = 15.0, .align = CDL_TEXT_CENTRE});
    cairo_set_line_width(cr, 1.0);
    const cdl_text_style small = {.size = 12.0}, centred = {.size = 12.0, .align = CDL_TEXT_CENTRE};
    /* Rings at quarters of the scale, labelled along the nadir ray... */
    for (int k = 1; k <= 4; ++k) {
        double r = CDL_POLAR_RADIUS * k / 4.0;
        cairo_set_source_rgb(cr, 0.73, 0.73, 0.73);
        cairo_new_sub_path(cr);
        cairo_arc(cr, CDL_POLAR_CX, CDL_POLAR_CY, r, 0.0, 2.0 * CDL_PI);
        cairo_stroke(cr);
        char label[32];
        snprintf(label, sizeof label, "%g", ring_max * k / 4.0);
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        cdl_text_draw(cr, CDL_POLAR_CX + 3.0, CDL_POLAR_CY + r - 16.0, label, &small);
    }
    /* ... and rays every 30 degrees of gamma, labelled outside the outer ring. */
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
    cairo_set_line_width(cr, 2.0);
    cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
    trace_curve(cr, p, 0.0, per_klm, ring_max);
    cairo_stroke(cr);
    const double dash[2] = {6.0, 4.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.8);
    trace_curve(cr, p, 90.0, per_klm, ring_max);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
    cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
    cdl_text_draw(cr, 16.0, CDL_POLAR_HEIGHT - 48.0, "C0-C180 (solid; C0 right)", &small);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.8);
    cdl_text_draw(cr, 16.0, CDL_POLAR_HEIGHT - 30.0, "C90-C270 (dashed; C90 right)", &small);
    char note[64];
    snprintf(note, sizeof note, "%s, nadir down", unit);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cdl_text_draw(cr, CDL_POLAR_WIDTH - 16.0, CDL_POLAR_HEIGHT - 30.0, note,
                  &(cdl_text_style){.size = 12.0, .align = CDL_TEXT_RIGHT});
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
