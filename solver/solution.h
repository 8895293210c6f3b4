/* solution.h - a solve's results in memory: per grid, per point.
 *
 * E = E_direct + E_indirect at every point, each in lux on the plane of the
 * point's normal; E_stderr is the one-sigma error of E (0 only where every
 * term is exact). A cdl_solution owns all its arrays; release it with
 * cdl_solution_release. Writing it to files is output/solution_write.h.
 *
 * Units: lux (E, E_direct, E_indirect, E_stderr), seconds, counts.
 * Thread safety: a finished solution is only read, from any number of
 * threads; release it once, when nothing reads it. Errors: only
 * cdl_grid_solution_alloc fails (CDL_ERR_INTERNAL, out of memory).
 */
#ifndef CANDELA_SOLVER_SOLUTION_H
#define CANDELA_SOLVER_SOLUTION_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene.h"

typedef struct cdl_grid_solution {
    cdl_grid grid;
    double *E, *E_direct, *E_indirect, *E_stderr;
    double *ao;                       /* NULL unless asked for */
    double *Ez, *Esz;                 /* cylindrical, semicylindrical illuminance (lux); NULL unless asked for */
    double *Ez_stderr, *Esz_stderr;   /* their standard errors where part of them is sampled; NULL where exact */
    double *L;                        /* luminance rho E / pi of the surface under each point (cd/m^2); NULL
                                         unless asked for */
    double *rho;                      /* with L: the reflectance of that surface at each point */
    double *DF;                       /* daylight factor 100 E / E_h, percent (E_h: the CIE overcast sky's
                                         unobstructed horizontal illuminance); NULL unless asked for */
    /* Points lying where two surfaces meet (on the one they face and within
     * Embree's float resolution of another whose plane holds their normal,
     * as at the foot of a wall): their normal cannot say which side of that
     * surface is meant. Each reports the limit from the side the grid is
     * meant for (direct_grid.c); they are counted and reported, never
     * silently. */
    size_t edge_point_count;
    size_t first_edge_point;          /* index of the first, when any */
} cdl_grid_solution;

/* Installed power (DESIGN.md summary.json "power"): the luminaire files'
 * input watts, one per luminaire placed (copies of an array each count). */
typedef struct cdl_power_summary {
    double installed_w;               /* sum over the luminaires whose files give their input watts */
    size_t luminaires_counted;        /* luminaires with a wattage */
    size_t luminaires_without_watts;  /* point, spot and area luminaires, files without one */
} cdl_power_summary;

typedef struct cdl_solution {
    cdl_method method;                /* the method actually used */
    cdl_solver_settings settings;     /* with quality-derived knobs filled in */
    int threads_used;
    cdl_grid_solution *grids;         /* scene->grid_count */
    size_t grid_count;
    char *plan_json;                  /* the "plan" object, JSON text */
    double seconds;                   /* the whole solve */
    double compute_seconds;           /* the grids' points only (setup excluded) */
    uint64_t rays;
    uint64_t records;                 /* irradiance-cache records used, all grids */
    uint64_t records_gathered;        /* of those, gathered by this solve (the others read from a cache file) */
    int cache_reused;                 /* 1: the records came from options->cache_path; 0: none asked for, or
                                         gathered and written to it */
    cdl_power_summary power;
    /* What a user must hear about (solve_checks.c): a luminaire that lights
     * no grid point, a dark grid, a scene without light, points where two
     * surfaces meet. Each a sentence naming the luminaire or grid. */
    char **warnings;
    size_t warning_count;
} cdl_solution;

/* Zeroed arrays for the grid's points (gs->grid built): E, E_direct,
 * E_indirect, E_stderr, and ao when want_ao. */
cdl_status cdl_grid_solution_alloc(cdl_grid_solution *gs, int want_ao, cdl_error *err);

/* Zeroed arrays for the outputs `spec` asks for beyond E and ao:
 * Ez, Esz, L with rho, and DF. Ownership: the grid solution's (released with
 * the solution). Errors: CDL_ERR_OUT_OF_MEMORY. */
cdl_status cdl_grid_solution_alloc_outputs(cdl_grid_solution *gs, const cdl_grid_spec *spec, cdl_error *err);

/* Zeroed Ez_stderr / Esz_stderr for the vertical outputs gs has. Ownership:
 * the grid solution's. Errors: CDL_ERR_OUT_OF_MEMORY. */
cdl_status cdl_grid_solution_alloc_vertical_stderr(cdl_grid_solution *gs, cdl_error *err);

/* Append a warning (printf-style) to the solution's list; CDL_ERR_INTERNAL
 * when out of memory. Not thread-safe for one solution. */
cdl_status cdl_solution_add_warning(cdl_solution *solution, cdl_error *err, const char *fmt, ...) CDL_PRINTF(3, 4);

/* Free what the solution holds and zero it (NULL and a zeroed solution are fine). */
void cdl_solution_release(cdl_solution *solution);

#endif
