/* photometry_polar.h - the polar intensity diagram, drawn with cairo.
 *
 * Not a public header (it names cairo, a private dependency): `candela
 * info --plot` reaches it through cdl_photometry_write_polar_svg, and the
 * report (report/) draws the same figure on its pages and in its HTML.
 *
 * The diagram lighting catalogues print (EULUMDAT and DIALux style): the
 * C0-C180 plane solid red, the C90-C270 plane dashed blue, nadir at the
 * bottom, C0 (C90) to the right, C180 (C270) to the left, gamma every 30
 * degrees on rays from the centre and intensity on rings at quarters of
 * the scale (cdl_photometry_plot_scale). Values in cd/klm (W/sr per kW for
 * radiometric files). Each curve samples the interpolated distribution
 * every degree. The figure is CDL_POLAR_WIDTH x CDL_POLAR_HEIGHT points,
 * the centre at (CDL_POLAR_CX, CDL_POLAR_CY), the outer ring of radius
 * CDL_POLAR_RADIUS. Thread safety: reads the photometry only.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_POLAR_H
#define CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_POLAR_H

#include <cairo.h>

#include "graphics/figure.h"
#include "lights/photometry/photometry.h"

#define CDL_POLAR_WIDTH 560.0
#define CDL_POLAR_HEIGHT 600.0
#define CDL_POLAR_CX 280.0
#define CDL_POLAR_CY 300.0
#define CDL_POLAR_RADIUS 220.0

typedef struct cdl_polar_diagram {
    const cdl_photometry *photometry;
    const char *title;                   /* drawn on top; NULL for none */
    char accessible_title[256];          /* filled by cdl_polar_diagram_figure */
} cdl_polar_diagram;

/* Draw the diagram with its top-left corner at the current origin. */
void cdl_polar_diagram_draw(cairo_t *cr, const cdl_polar_diagram *diagram);

/* The diagram as a figure (graphics/figure.h); `diagram` must outlive it. */
cdl_figure cdl_polar_diagram_figure(cdl_polar_diagram *diagram);

#endif
