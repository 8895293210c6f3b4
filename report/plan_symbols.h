/* plan_symbols.h - the luminaires as a plan shows them: footprints, aiming lines, masts.
 *
 * A map is a projection of the scene onto a grid's plane; on it each
 * luminaire is drawn as what it is:
 *   - a goniometric luminaire whose file gives a luminous opening: the
 *     opening's outline (a 1.24 m x 0.06 m linear luminaire is a long thin
 *     rectangle), turned as the luminaire is turned, projected: the convex
 *     hull of its corners (a luminous solid's top and bottom outlines), in
 *     the luminaire's frame x along the length (C0), y along the width
 *     (C90), z up (photometry.h); a vertical circle or ellipse faces C0;
 *   - an area luminaire: its shape's outline (the hull of its corners);
 *   - anything smaller on the page than SYMBOL_MIN points (a point source,
 *     a spot, a file without an opening): a ring with a cross;
 *   - an aimed or tilted luminaire (spot, goniometric) with its aiming
 *     line: from the luminaire to its aim point, or else to where its
 *     axis (the nadir, a spot's direction) meets the grid's plane, when that
 *     point is more than a few points away on the page (a floodlight's
 *     throw); a luminaire sharing its plan position with another is on a
 *     mast, drawn as a filled square.
 * Each symbol also gives the box map labels must keep clear of.
 *
 * Ownership: the caller's array (free). Errors: memory. Thread-safe.
 */
#ifndef CANDELA_REPORT_PLAN_SYMBOLS_H
#define CANDELA_REPORT_PLAN_SYMBOLS_H

#include <cairo.h>
#include <stddef.h>

#include "base/error.h"
#include "report/label_layout.h"
#include "report/report_input.h"

#define CDL_PLAN_OUTLINE_MAX 64

/* World to page points (x right, y down). */
typedef void (*cdl_plan_project_fn)(const void *user, cdl_vec3 world, double *x, double *y);

typedef struct cdl_plan_symbol {
    double outline[2 * CDL_PLAN_OUTLINE_MAX]; /* the footprint, a convex polygon in page points */
    size_t outline_count;                     /* 0: drawn as the ring and cross */
    int area;                                 /* an area luminaire (dashed outline) */
    double x, y;                              /* its centre on the page */
    int aimed;                                /* with an aiming line to (aim_x, aim_y) */
    double aim_x, aim_y;
    int mast;                                 /* shares its plan position with another luminaire */
    cdl_label_box box;                        /* what labels must keep clear of */
} cdl_plan_symbol;

typedef struct cdl_plan_view {
    cdl_plan_project_fn project;
    const void *user;
    cdl_vec3 plane_point, plane_normal;       /* the grid's plane (aiming lines end on it) */
} cdl_plan_view;

/* A symbol per scene luminaire placed (point, spot, goniometric, area), in
 * the scene's order; *out is the caller's to free. */
cdl_status cdl_plan_symbols_make(const cdl_report_input *in, const cdl_plan_view *view, cdl_plan_symbol **out,
                                 size_t *count, cdl_error *err);

/* Draw them: aiming lines, footprints (white fill, black outline; area
 * luminaires dashed), masts, the small symbols. */
void cdl_plan_symbols_draw(cairo_t *cr, const cdl_plan_symbol *symbols, size_t count);

#endif
