/* What the polar diagram says below its curves (photometry_plot.c): drawn
 * on a PDF page by cairo, its text read back with pdftotext (poppler-utils,
 * which scripts/setup.sh installs): the peak in cd/klm and its direction,
 * the beam angles and the key of each curve, for a downlight, a table
 * peaking at C 233.8 (its plane through the peak named) and a type B
 * floodlight (its V and H planes, and photometric zero down). And the beam
 * angles of a rotationally symmetric batwing are the same in both planes:
 * I = 1000 (1 - ((gamma - 40) / 50)^2) falls to half at gamma = 40 +- 50
 * sqrt(1/2) within each lobe, a beam of 100 sqrt(1/2) = 70.71 degrees. */
#include <cairo-pdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry/photometry_polar.h"

#define TMP CANDELA_TEST_TMPDIR

/* The diagram's text, as pdftotext reads it from a PDF of it (malloc'd). */
static char *diagram_text(const cdl_photometry *p, const char *name)
{
    char pdf[512], cmd[1200];
    snprintf(pdf, sizeof pdf, "%s/%s.pdf", TMP, name);
    cairo_surface_t *surface = cairo_pdf_surface_create(pdf, CDL_POLAR_WIDTH, CDL_POLAR_HEIGHT);
    cairo_t *cr = cairo_create(surface);
    cdl_polar_diagram d = {.photometry = p, .title = name};
    cdl_polar_diagram_draw(cr, &d);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    cairo_surface_destroy(surface);
    snprintf(cmd, sizeof cmd, "pdftotext -raw '%s' -", pdf);
    FILE *f = popen(cmd, "r");
    char *text = calloc(1 << 16, 1);
    size_t n = f && text ? fread(text, 1, (1 << 16) - 1, f) : 0;
    if (f) pclose(f);
    CHECK_MSG(n > 0, "%s: no text from pdftotext", name);
    return text;
}

static void expect_text(const char *text, const char *what)
{
    CHECK_MSG(text && strstr(text, what), "'%s' not in the diagram's text:\n%s", what, text ? text : "");
}

static cdl_photometry *table(cdl_photometric_type type, const double *h, size_t nh, const double *v, size_t nv,
                             double (*f)(double, double))
{
    double *cd = malloc(nh * nv * sizeof *cd);
    for (size_t i = 0; i < nh; ++i)
        for (size_t j = 0; j < nv; ++j) cd[i * nv + j] = f(h[i], v[j]);
    cdl_photometry *p = NULL;
    cdl_error err;
    CHECK_OK(cdl_photometry_create(type, h, nh, v, nv, cd, &p, &err), &err);
    free(cd);
    return p;
}

static double downlight(double c, double g) { return (void)c, g <= 90.0 ? 247.0 * cos(g * 3.14159265358979 / 180.0) : 0.0; }
static double toward_233(double c, double g) { return g <= 90.0 ? 100.0 + (fabs(c - 233.8) < 1e-9 ? 300.0 * sin(g * 3.14159265358979 / 180.0) : 0.0) : 0.0; }
static double flood(double h, double v) { return 500.0 * exp(-(h * h + v * v) / 800.0); }
static double batwing(double c, double g) { return (void)c, g <= 90.0 ? fmax(0.0, 1000.0 * (1.0 - pow((g - 40.0) / 50.0, 2.0))) : 0.0; }

int main(void)
{
    if (system("pdftotext -v > /dev/null 2>&1") != 0) {
        printf("SKIPPED: pdftotext (poppler-utils) is not installed\n");
        return 77;
    }
    double c0 = 0.0, g[19], gb[181];
    for (int j = 0; j < 19; ++j) g[j] = 10.0 * j;
    for (int j = 0; j < 181; ++j) gb[j] = 0.5 * j;
    /* absolute photometry: cd/klm of the table's own flux, 247 pi lm (to 1e-5 at
     * half-degree steps): 247 x 1000 / (247 pi) = 318.3 */
    cdl_photometry *p = table(CDL_PHOTOMETRIC_TYPE_C, &c0, 1, gb, 181, downlight);
    char *text = diagram_text(p, "downlight");
    expect_text(text, "peak 318.3 cd/klm at C 0.0, \xce\xb3 0.0"); /* 1000 / pi */
    expect_text(text, "C0-C180 (solid; C0 right)");
    expect_text(text, "C90-C270 (dashed; C90 right)");
    expect_text(text, "in C0-C180");
    CHECK(!strstr(text, "through the peak"));
    free(text);
    cdl_photometry_release(p);

    double c[5] = {0.0, 90.0, 180.0, 233.8, 270.0};
    p = table(CDL_PHOTOMETRIC_TYPE_C, c, 5, g, 19, toward_233);
    text = diagram_text(p, "asymmetric");
    expect_text(text, "C233.8-C53.8 (dotted; through the peak, C233.8 right)");
    expect_text(text, "at C 233.8, \xce\xb3 90.0");
    free(text);
    cdl_photometry_release(p);

    double hv[37];
    for (int j = 0; j < 37; ++j) hv[j] = -90.0 + 5.0 * j;
    p = table(CDL_PHOTOMETRIC_TYPE_B, hv, 37, hv, 37, flood);
    text = diagram_text(p, "flood");
    expect_text(text, "V plane, H = 0 (solid; V > 0 right)");
    expect_text(text, "H plane, V = 0 (dashed; H > 0 right)");
    expect_text(text, "photometric zero (H = V = 0) down");
    expect_text(text, "at H 0.0, V 0.0");
    free(text);
    cdl_photometry_release(p);

    p = table(CDL_PHOTOMETRIC_TYPE_C, &c0, 1, gb, 181, batwing);
    cdl_photometry_summary s = CDL_PHOTOMETRY_SUMMARY_INIT;
    cdl_photometry_summarize(p, &s);
    CHECK(!s.spread_about_peak);
    /* 0.01 degree: the table samples the parabola every half degree, and linear
     * interpolation moves its half-level crossing by less than that */
    CHECK_ABS(s.beam_angle_deg[0], 100.0 * sqrt(0.5), 0.01);
    CHECK_ABS(s.beam_angle_deg[1], 100.0 * sqrt(0.5), 0.01);
    CHECK_ABS(s.beam_angle_deg[0], s.beam_angle_deg[1], 1e-9);
    cdl_photometry_release(p);
    return check_finish();
}
