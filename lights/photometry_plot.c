/* photometry_plot.c - the polar intensity diagram of a luminaire as SVG.
 *
 * The diagram lighting catalogues print (EULUMDAT and DIALux style): the
 * C0-C180 plane solid, the C90-C270 plane dashed, nadir at the bottom,
 * C0 (C90) to the right, C180 (C270) to the left, gamma every 30 degrees
 * on rays from the centre and intensity on rings. Values in cd/klm, the
 * intensity per 1000 lm of the rated lamp flux (the luminaire's own flux
 * for absolute photometry), so luminaires of different output compare;
 * files in radiometric units plot W/sr per kW. Each curve samples the
 * interpolated distribution every degree. The file is written atomically
 * in the same plain SVG as the bench's plot (bench_report.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lights/photometry.h"
#include "radiometry/atomic_file.h"
#include "radiometry/constants.h"

/* Geometry of the drawing, in SVG user units. */
enum { WIDTH = 560, HEIGHT = 600, CX = 280, CY = 300, RADIUS = 220 };

/* The smallest 1-2-5 value at or above v (> 0). */
static double round_up_125(double v)
{
    double e = pow(10.0, floor(log10(v)));
    static const double m[] = {1.0, 2.0, 5.0, 10.0};
    for (int k = 0; k < 4; ++k)
        if (m[k] * e >= v * (1.0 - 1e-12)) return m[k] * e;
    return 10.0 * e;
}

/* Text for XML: &, <, > and quotes escaped, control bytes dropped. */
static void put_xml_text(FILE *fp, const char *s)
{
    for (; *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (c == '&') fputs("&amp;", fp);
        else if (c == '<') fputs("&lt;", fp);
        else if (c == '>') fputs("&gt;", fp);
        else if (c == '"') fputs("&quot;", fp);
        else if (c >= 0x20 && c < 0x7F) fputc(c, fp);
        else if (c >= 0x80) fputc('?', fp); /* the file's encoding is unknown: never invalid XML */
    }
}

double cdl_photometry_plot_scale(const cdl_photometry *p, double *per_klm)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    double flux = !m->absolute && m->rated_lamp_flux_lm > 0.0 ? m->rated_lamp_flux_lm : cdl_photometry_flux(p).lm;
    /* cd/klm = I x 1000 / flux */
    *per_klm = flux > 0.0 ? 1000.0 / flux : 0.0;
    double top = cdl_photometry_max_intensity(p).cd * *per_klm;
    return top > 0.0 ? round_up_125(top) : 1.0;
}

/* One plane's curve: theta from -180 (C180 or C270 side, zenith) through 0
 * (nadir) to 180, x = cx + r sin theta, y = cy + r cos theta. */
static void put_curve(FILE *fp, const cdl_photometry *p, double c_right, double per_klm, double ring_max,
                      const char *style)
{
    fprintf(fp, "<polyline fill=\"none\" %s points=\"", style);
    for (int t = -180; t <= 180; ++t) {
        double c = t >= 0 ? c_right : fmod(c_right + 180.0, 360.0), gamma = fabs((double)t);
        double v = cdl_photometry_intensity_c_gamma(p, c, gamma).cd * per_klm;
        double r = RADIUS * v / ring_max, a = t * CDL_DEG_TO_RAD;
        fprintf(fp, "%s%.3f,%.3f", t > -180 ? " " : "", CX + r * sin(a), CY + r * cos(a));
    }
    fputs("\"/>\n", fp);
}

cdl_status cdl_photometry_write_polar_svg(const cdl_photometry *p, const char *title, const char *path,
                                          cdl_error *err)
{
    double per_klm = 0.0;
    double ring_max = cdl_photometry_plot_scale(p, &per_klm);
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const char *unit = m->radiometric ? "W/sr per kW" : "cd/klm";
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st != CDL_OK) return st;
    FILE *fp = f.fp;
    fprintf(fp,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" "
            "font-family=\"sans-serif\" font-size=\"12\">\n"
            "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n",
            WIDTH, HEIGHT, WIDTH, HEIGHT);
    fputs("<text x=\"280\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">", fp);
    put_xml_text(fp, title ? title : "");
    fputs("</text>\n", fp);
    /* Rings at quarters of the scale, labelled along the C0 side's 90 degree ray... */
    for (int k = 1; k <= 4; ++k) {
        double r = RADIUS * k / 4.0;
        fprintf(fp, "<circle cx=\"%d\" cy=\"%d\" r=\"%.3f\" fill=\"none\" stroke=\"#bbb\"/>\n", CX, CY, r);
        fprintf(fp, "<text x=\"%.1f\" y=\"%d\" fill=\"#666\">%g</text>\n", CX + 3.0, (int)lround(CY + r) - 3,
                ring_max * k / 4.0);
    }
    /* ... and rays every 30 degrees of gamma, labelled outside the outer ring. */
    for (int t = -150; t <= 180; t += 30) {
        double a = t * CDL_DEG_TO_RAD;
        fprintf(fp, "<line x1=\"%d\" y1=\"%d\" x2=\"%.3f\" y2=\"%.3f\" stroke=\"#ddd\"/>\n", CX, CY,
                CX + RADIUS * sin(a), CY + RADIUS * cos(a));
        fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" fill=\"#666\">%d&#176;</text>\n",
                CX + (RADIUS + 16) * sin(a), CY + (RADIUS + 16) * cos(a) + 4, abs(t));
    }
    put_curve(fp, p, 0.0, per_klm, ring_max, "stroke=\"#c00\" stroke-width=\"2\" id=\"c0-c180\"");
    put_curve(fp, p, 90.0, per_klm, ring_max,
              "stroke=\"#00c\" stroke-width=\"2\" stroke-dasharray=\"6,4\" id=\"c90-c270\"");
    fprintf(fp,
            "<text x=\"16\" y=\"%d\" fill=\"#c00\">C0-C180 (solid; C0 right)</text>\n"
            "<text x=\"16\" y=\"%d\" fill=\"#00c\">C90-C270 (dashed; C90 right)</text>\n"
            "<text x=\"%d\" y=\"%d\" text-anchor=\"end\">%s, nadir down</text>\n"
            "</svg>\n",
            HEIGHT - 34, HEIGHT - 16, WIDTH - 16, HEIGHT - 16, unit);
    return cdl_atomic_file_commit(&f, err);
}
