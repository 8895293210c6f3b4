/* solution.h - a solve's results: per grid, per point, and what the solve says about them.
 *
 * A cdl_solution is an opaque handle made by cdl_solve_scene (solve.h).
 * For each grid, in the scene's order, it holds the calculation points and
 * their normals, and per point the illuminance E = E_direct + E_indirect
 * on the plane of the point's normal with its one-sigma standard error
 * E_stderr (0 only where every term is exact; about 95 % of points lie
 * within two of it of the truth), and the outputs the grid asked for. The
 * solve as a whole carries its plan (what was modelled and why, as JSON),
 * its warnings and its costs.
 *
 * Units: lux (E and its parts, Ez, Esz and their errors), cd/m^2 (L),
 * metres (points), square metres (weights), seconds; AO is a fraction.
 * Ownership: the solution is the caller's, freed with cdl_solution_release
 * (NULL is fine); the arrays and strings its accessors return belong to it
 * and live as long as it does. It does not refer to the scene it came
 * from, which may be released first.
 * Thread safety: a finished solution is only read, from any number of
 * threads; release it once, when nothing reads it.
 * Errors: none of these calls fails; a grid index beyond the count gives
 * NULL or 0.
 */
#ifndef CANDELA_SOLVER_SOLUTION_H
#define CANDELA_SOLVER_SOLUTION_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/vec3.h"
#include "solver/scene/scene.h"

typedef struct cdl_solution cdl_solution;

/* A quantity a solution holds per point of a grid. */
typedef enum cdl_grid_quantity {
    CDL_GRID_E,               /* illuminance E = E_direct + E_indirect, lx */
    CDL_GRID_E_DIRECT,        /* from the lights directly, lx */
    CDL_GRID_E_INDIRECT,      /* interreflected, lx (0 when not modelled) */
    CDL_GRID_E_STDERR,        /* one-sigma standard error of E, lx */
    CDL_GRID_AO,              /* ambient occlusion, [0, 1] ("outputs": ["ao"]) */
    CDL_GRID_AO_STDERR,       /* its standard error (0 only where nothing can hide the sky) */
    CDL_GRID_EZ,              /* cylindrical illuminance, lx ("cylindrical") */
    CDL_GRID_EZ_STDERR,       /* its standard error where part of it is sampled, lx */
    CDL_GRID_ESZ,             /* semicylindrical illuminance, lx ("semicylindrical") */
    CDL_GRID_ESZ_STDERR,      /* its standard error where part of it is sampled, lx */
    CDL_GRID_L,               /* luminance rho E / pi of the surface under the point, cd/m^2 ("luminance") */
    CDL_GRID_DF               /* daylight factor 100 E / E_h under the CIE overcast sky, percent
                               * ("daylight_factor") */
} cdl_grid_quantity;

/* A grid's statistics in EN 12464-1's terms. Set `size` to
 * sizeof(cdl_grid_summary) before the call (CDL_GRID_SUMMARY_INIT): the
 * library fills only the fields that size covers, so a program built with
 * an older, shorter struct keeps working. */
typedef struct cdl_grid_summary {
    size_t size;
    size_t count;             /* points */
    double area_m2;           /* the area the points stand for (polygon and rect grids; 0 for points) */
    double E_avg_lx;          /* Em: the area-weighted mean of E (the plain mean for points grids) */
    double E_min_lx, E_max_lx;
    double U0;                /* uniformity Emin / Em (0 when Em = 0) */
    double Ud;                /* diversity Emin / Emax (0 when Emax = 0) */
    double stderr_mean_rel;   /* E_stderr / E over the lit points: the area-weighted mean */
    double stderr_max_rel;    /* and the worst */
} cdl_grid_summary;
#define CDL_GRID_SUMMARY_INIT                                                                                         \
    {.size = sizeof(cdl_grid_summary), .count = 0, .area_m2 = 0.0, .E_avg_lx = 0.0, .E_min_lx = 0.0, .E_max_lx = 0.0,  \
     .U0 = 0.0, .Ud = 0.0, .stderr_mean_rel = 0.0, .stderr_max_rel = 0.0}

/* What the solve did, as a whole. Set `size` as for cdl_grid_summary
 * (CDL_SOLUTION_INFO_INIT). */
typedef struct cdl_solution_info {
    size_t size;
    cdl_method method;        /* the method used (DIRECT when nothing reflects under AUTO) */
    cdl_quality quality;
    double target_error;      /* the relative standard error asked of E per point */
    uint64_t seed;
    int threads;              /* worker threads used */
    double seconds;           /* the whole solve */
    double compute_seconds;   /* the grids' points only (setup excluded) */
    uint64_t rays;            /* rays traced */
    uint64_t records;         /* irradiance-cache records used, all grids */
    uint64_t records_gathered;/* of those, gathered by this solve (the others read from a cache file) */
    int cache_reused;         /* 1: the records came from the cache file */
    double installed_w;       /* input watts of the luminaires whose files give them */
    size_t luminaires_with_watts, luminaires_without_watts;
    int ranks;                /* processes that shared the solve (solve_ranks.h); 1 for one process */
} cdl_solution_info;
#define CDL_SOLUTION_INFO_INIT                                                                                        \
    {.size = sizeof(cdl_solution_info), .method = CDL_METHOD_AUTO, .quality = CDL_QUALITY_NORMAL, .target_error = 0.0, \
     .seed = 0, .threads = 0, .seconds = 0.0, .compute_seconds = 0.0, .rays = 0, .records = 0, .records_gathered = 0, \
     .cache_reused = 0, .installed_w = 0.0, .luminaires_with_watts = 0, .luminaires_without_watts = 0, .ranks = 1}

/* Free a solution (NULL is fine). */
void cdl_solution_release(cdl_solution *solution);

/* The solve as a whole (info->size set by the caller). */
void cdl_solution_get_info(const cdl_solution *solution, cdl_solution_info *info);

/* The grids, in the scene's order. */
size_t cdl_solution_grid_count(const cdl_solution *solution);
const char *cdl_solution_grid_name(const cdl_solution *solution, size_t grid);
size_t cdl_solution_grid_point_count(const cdl_solution *solution, size_t grid);

/* The grid's points and their unit normals (point_count each), and the
 * area each point stands for (m^2; 1 for every point of a points grid). */
const cdl_vec3 *cdl_solution_grid_points(const cdl_solution *solution, size_t grid);
const cdl_vec3 *cdl_solution_grid_normals(const cdl_solution *solution, size_t grid);
const double *cdl_solution_grid_weights(const cdl_solution *solution, size_t grid);

/* One quantity at every point of a grid (point_count values, in the grid's
 * order); NULL when the grid has none (an output it did not ask for, a
 * standard error of a vertical output that is exact). */
const double *cdl_solution_grid_values(const cdl_solution *solution, size_t grid, cdl_grid_quantity quantity);

/* The grid's statistics (summary->size set by the caller). */
void cdl_solution_grid_summary(const cdl_solution *solution, size_t grid, cdl_grid_summary *summary);

/* The plan: for every light and grid what was modelled and why, and for
 * interreflected light which method each grid took; a JSON object as text
 * (the "plan" of summary.json). */
const char *cdl_solution_plan_json(const cdl_solution *solution);

/* What a user must hear about: a luminaire that lights no grid point, a
 * dark grid, a scene without light, points where two surfaces meet. Each a
 * sentence naming the luminaire or grid. */
size_t cdl_solution_warning_count(const cdl_solution *solution);
const char *cdl_solution_warning(const cdl_solution *solution, size_t index);

#endif
