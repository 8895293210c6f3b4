/* photometry_polar.h - the polar intensity diagram, drawn with cairo.
 *
 * Not a public header (it names cairo, a private dependency): `candela
 * info --plot` reaches it through cdl_photometry_write_polar_svg, and the
 * report (report/) draws the same figure on its pages and in its HTML.
 *
 * The diagram lighting catalogues print (EULUMDAT and DIALux style): the
 * C0-C180 plane solid red, the C90-C270 plane dashed blue, and where the
 * peak lies in neither, the plane through the peak dotted green; nadir at
 * the bottom, C0 (C90, the peak's C) to the right. A type A or B file
 * (floodlights) is drawn in its own planes through photometric zero: the
 * V plane (H = 0) solid, the H plane (V = 0) dashed, positive angles to the
 * right. Gamma every 30 degrees on rays from the centre; intensity on 3 to
 * 6 rings whose outer one fits the peak (cdl_photometry_plot_scale),
 * labelled along the ray between two 30-degree rays where the curves stay
 * farthest from them. Values in cd/klm (W/sr per kW for radiometric
 * files). Each curve samples the interpolated distribution every degree.
 * A title too wide for the page is wrapped, then set smaller, then cut
 * short. Below the diagram: each curve's key, the unit, the peak (value and
 * direction) and the beam angles (cdl_photometry_summary). The figure is
 * CDL_POLAR_WIDTH x CDL_POLAR_HEIGHT points, the centre at (CDL_POLAR_CX,
 * CDL_POLAR_CY), the outer ring of radius CDL_POLAR_RADIUS. Thread safety:
 * reads the photometry only.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_POLAR_H
#define CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_POLAR_H

#include <cairo.h>

#include "graphics/figure.h"
#include "lights/photometry/photometry.h"

#define CDL_POLAR_WIDTH 560.0
#define CDL_POLAR_HEIGHT 650.0
#define CDL_POLAR_CX 280.0
#define CDL_POLAR_CY 300.0
#define CDL_POLAR_RADIUS 220.0
/* The grey of the ring labels (all three channels), apart from the rays' 0.4. */
#define CDL_POLAR_RING_LABEL_GREY 0.3

typedef struct cdl_polar_diagram {
    const cdl_photometry *photometry;
    const char *title;                   /* drawn on top; NULL for none */
    char accessible_title[640];          /* filled by cdl_polar_diagram_figure */
} cdl_polar_diagram;

/* Draw the diagram with its top-left corner at the current origin. */
void cdl_polar_diagram_draw(cairo_t *cr, const cdl_polar_diagram *diagram);

/* The diagram as a figure (graphics/figure.h); `diagram` must outlive it. */
cdl_figure cdl_polar_diagram_figure(cdl_polar_diagram *diagram);

#endif
