/* report_surfaces.h - the surface maps in the report: their table, requirements and the room in 3D.
 *
 * What `candela report` reads of a solve's surface maps: each
 * entry of summary.json's "surfaces", its mapped surface in the scene (by
 * name; a map the scene no longer has is refused), and OUTDIR/surfaces/
 * NAME.csv and NAME.tri.csv, checked against the summary: as many vertices
 * and triangles, every index in range, and Em recomputed from the CSV
 * (the area-weighted mean of the linear interpolant, surface_output.h)
 * equal to the summary's to 1e-9. A missing or stale file is CDL_ERR_INPUT
 * naming it.
 *
 * The section it adds to the report: a table (a row per map: area, Em,
 * Emin, Emax, U0 printed to their stated error as the grids' table prints
 * them, the mean luminance, vertices, and the check against the surface's
 * requirements, EN 12464-1:2021 4.3's for walls and ceilings), then the
 * room in 3D (surface_view.h) with the scene's luminaires.
 *
 * Ownership: the surfaces own what they read; the document keeps them
 * (its figure draws from them) and releases them.
 */
#ifndef CANDELA_REPORT_SURFACES_H
#define CANDELA_REPORT_SURFACES_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "report/report_document.h"
#include "report/report_input.h"
#include "report/surface_view.h"

typedef struct cdl_report_surface {
    const cdl_surface_spec *spec;    /* in the input's scene */
    size_t vertex_count, triangle_count;
    double *xyz, *E, *E_stderr;
    uint32_t *triangles;
    double area_m2, Em, Emin, Emax, U0, L_mean, stderr_mean_rel, stderr_max_rel;
} cdl_report_surface;

typedef struct cdl_report_surfaces {
    cdl_report_surface *items;
    size_t count;
    cdl_view_mesh *meshes;
    cdl_vec3 *luminaires;
    size_t luminaire_count;
    cdl_surface_view view;
    int view_ready;
} cdl_report_surfaces;

/* Read the solve's surface maps (none when the summary has no "surfaces"). */
cdl_status cdl_report_surfaces_read(const cdl_report_input *in, cdl_report_surfaces **out, cdl_error *err);
void cdl_report_surfaces_release(cdl_report_surfaces *surfaces);

/* Append the section to the document (nothing when there are no maps); the
 * document then owns `surfaces`. */
cdl_status cdl_report_surfaces_section(cdl_report_document *document, const cdl_report_input *in,
                                       cdl_report_surfaces *surfaces, cdl_error *err);

#endif
