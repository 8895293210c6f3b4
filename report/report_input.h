/* report_input.h - what `candela report` reads: a solve's folder, checked.
 *
 * From OUTDIR: summary.json (written by this very Candela version), the
 * scene it names (its absolute path, else the path as given), each grid's
 * NAME.csv. The grids are rebuilt from the scene (cdl_grid_build: the same
 * points, the raster the maps are drawn on) and every CSV is held to them
 * and to the summary: the same points in the same order, and the
 * statistics recomputed from its E column equal to summary.json's. A file
 * that fails is missing or stale, and the message says which file and what
 * differs. The printed numbers are summary.json's own values.
 *
 * Requirements (EN 12464-1, per grid: Em_lx and U0) come from the scene's
 * grids ("requirements") and from a JSON file {"GRID": {"Em_lx": 500,
 * "U0": 0.6}}, which overrides the scene grid by grid.
 *
 * Glare (when the scene has observers): summary.json's "glare", one entry
 * per observer by name, and glare.csv holding the same numbers
 * (report_glare.c).
 *
 * Luminaire types: goniometric luminaires grouped by file (the photometry
 * read for the schedule and its polar diagram), other luminaires one type
 * per scene entry.
 *
 * Errors: CDL_ERR_INPUT naming the file (and JSON path) and what was
 * expected; CDL_ERR_INTERNAL for memory. Ownership: the caller's; release
 * with cdl_report_input_release.
 */
#ifndef CANDELA_REPORT_INPUT_H
#define CANDELA_REPORT_INPUT_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "lights/photometry/photometry.h"
#include "base/error.h"
#include "solver/grid/grid.h"
#include "solver/output/grid_result.h"
#include "solver/scene/scene_internal.h"

typedef struct cdl_report_grid {
    const cdl_grid_spec *spec;     /* in the input's scene */
    cdl_grid grid;                 /* rebuilt from the spec */
    double *E, *E_stderr;          /* per point, from NAME.csv */
    size_t min_index, max_index;   /* the points of Emin and Emax */
    /* summary.json's values */
    size_t count;
    double Em, Emin, Emax, U0, Ud, stderr_mean_rel, stderr_max_rel, spacing_m;
    /* requirements: 0 when none */
    double required_Em_lx, required_U0;
    const char *interreflection_method; /* from the plan ("icache", "pathtrace"), or NULL */
    const char *interreflection_why;
} cdl_report_grid;

typedef struct cdl_report_luminaire_type {
    const cdl_luminaire_spec *first; /* the first luminaire of the type */
    cdl_photometry *photometry;      /* goniometric only */
    size_t count;                    /* luminaires of the type in the scene */
    double maintenance_min, maintenance_max;
} cdl_report_luminaire_type;

/* An observer's glare, as summary.json's "glare" gives it (report_glare.c
 * reads it and holds glare.csv to it). */
typedef struct cdl_report_observer {
    const cdl_observer_spec *spec;   /* in the input's scene */
    int defined;                     /* 0: no rating (ugr null) */
    double ugr, ugr_stderr;
    double background_cd_m2, background_stderr_cd_m2;
    size_t sources;                  /* luminaires in view */
} cdl_report_observer;

typedef struct cdl_report_input {
    char *out_dir;
    char *summary_path;
    char *requirements_path;         /* as given, or NULL */
    cJSON *summary;
    cdl_scene *scene;
    cdl_report_grid *grids;
    size_t grid_count;
    cdl_report_luminaire_type *types;
    size_t type_count;
    cdl_report_observer *observers;  /* one per scene observer (none without) */
    size_t observer_count;
} cdl_report_input;

/* Read and check OUTDIR (above); requirements_path may be NULL. */
cdl_status cdl_report_input_read(const char *out_dir, const char *requirements_path, cdl_report_input **out,
                                 cdl_error *err);
void cdl_report_input_release(cdl_report_input *input);

/* summary.json's string at `key` (a top-level key, or "a.b" one level
 * down), or NULL. */
const char *cdl_report_summary_string(const cdl_report_input *input, const char *key);
/* summary.json's number at `key` (as above), or `fallback`. */
double cdl_report_summary_number(const cdl_report_input *input, const char *key, double fallback);

#endif
