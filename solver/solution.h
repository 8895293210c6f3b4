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

#include "radiometry/error.h"
#include "solver/grid/grid.h"
#include "solver/scene/scene.h"

typedef struct cdl_grid_solution {
    cdl_grid grid;
    double *E, *E_direct, *E_indirect, *E_stderr;
    double *ao;                       /* NULL unless asked for */
    /* Points lying where two surfaces meet (on the one they face and within
     * Embree's float resolution of another whose plane holds their normal,
     * as at the foot of a wall): their normal cannot say which side of that
     * surface is meant. Each reports the limit from the side the grid is
     * meant for (direct_grid.c); they are counted and reported, never
     * silently. */
    size_t edge_point_count;
    size_t first_edge_point;          /* index of the first, when any */
} cdl_grid_solution;

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
} cdl_solution;

/* Zeroed arrays for the grid's points (gs->grid built): E, E_direct,
 * E_indirect, E_stderr, and ao when want_ao. */
cdl_status cdl_grid_solution_alloc(cdl_grid_solution *gs, int want_ao, cdl_error *err);

/* Free what the solution holds and zero it (NULL and a zeroed solution are fine). */
void cdl_solution_release(cdl_solution *solution);

#endif
