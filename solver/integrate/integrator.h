/* integrator.h - the solve's state, one grid's job, and the integrators that compute it.
 *
 * A solve runs in three steps, as pbrt's integrators do (solve.c):
 *  1. plan (solve_plan.c): the scene's geometry and lights are built once,
 *     the method is chosen, every grid is built and checked, and each
 *     grid's interreflection method is decided, all before any long work;
 *  2. integrate: each grid, as a cdl_grid_job, goes through the table of
 *     integrators in order; each integrator says whether it applies to the
 *     job and, when it does, adds its part (direct light, interreflected
 *     light by the cache or by paths, the sampled part of the vertical
 *     outputs) to the job's buffers and its facts to the job for the plan;
 *  3. finish (solve_finish.c): each grid's parts are combined (E = E_direct
 *     + E_indirect, its standard error from the two variances) and checked;
 *     then what the solve says besides its numbers (warnings, installed
 *     power, the cache file, the plan's JSON from plan_json.c).
 *
 * A variance lives in a variance buffer of the job (var_direct,
 * var_indirect), never in a result array. Integrators do not write the
 * plan's JSON: they leave counts and routes in the job, and plan_json.c
 * narrates them. A new method (glare at observers, surface maps, daylight
 * coefficients) is a new entry of a table, not code in solve.c: the grids'
 * (cdl_integrator) or the solve's (cdl_solve_integrator, run once before
 * the grids: the surface maps). Glare rates observers, not grid points: the
 * observers are one more job (`observers`), whose direct part is the
 * background's.
 *
 * Not public. Thread safety: one state per solve; integrators run their
 * own worker threads (pool.h) and return when those are done.
 */
#ifndef CANDELA_SOLVER_INTEGRATE_INTEGRATOR_H
#define CANDELA_SOLVER_INTEGRATE_INTEGRATOR_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/direct/direct.h"
#include "solver/geometry/surface_mesh.h"
#include "solver/icache/icache.h"
#include "solver/icache/icache_file.h"
#include "solver/pathtrace/pathtrace.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_lights.h"
#include "solver/solution_internal.h"
#include "solver/solve_debug.h"
#include "solver/solve_options.h"
#include "solver/transport/vertical_sampled.h"

/* The irradiance-cache file of a solve (solve_cache.c). */
typedef struct cdl_solve_cache {
    const char *path;                 /* NULL: no file asked for */
    cdl_icache_key key;
    size_t *grids;                    /* the grids the irradiance cache solves */
    size_t count;
    int reused;                       /* 1: their records were read from the file */
    uint64_t records_read;
} cdl_solve_cache;

/* What planning decided for one grid. */
typedef struct cdl_grid_plan {
    uint64_t key;                     /* keys its random numbers: a hash of its name */
    double daylight_E_h;              /* "daylight_factor": the overcast sky's horizontal illuminance, lx */
    cdl_method method;                /* its interreflection: ICACHE or PATHTRACE; DIRECT when none */
    double score;                     /* points x target, which chose the method under "auto" */
    int vertical_sampled;             /* its vertical outputs need the sampled part */
} cdl_grid_plan;

/* Everything a solve holds from planning to finishing. */
typedef struct cdl_solve_state {
    const cdl_scene *scene;           /* borrowed */
    cdl_solve_options options;
    cdl_solve_debug debug;
    cdl_solution *out;                /* borrowed: the results being filled */
    double target;                    /* relative standard error asked of E per point (computed once) */
    int indirect;                     /* 1: interreflection is modelled */
    const char *reflector;            /* the first surface that reflects (its JSON path), NULL when none */
    double reflector_rho;
    char reflector_label[CDL_JSON_PATH_SIZE + 16]; /* a luminaire's body as the reflector: "luminaires[2]'s body" */
    int threads;
    cdl_rank_group *ranks;            /* the ranks sharing the solve (rank_group.h), NULL: this process alone */

    cdl_scene_geometry *geometry;     /* owned */
    size_t pieces;                    /* its surface pieces (0: nothing can occlude or reflect) */
    cdl_occluder_index *occluders;    /* owned; NULL without geometry */
    cdl_sky_portals portals;          /* owned: the panes a sky comes in through (empty without a sky or glass) */
    cdl_scene_lights lights;          /* owned */

    cdl_direct_context direct;
    cdl_pathtrace_context pathtrace;
    cdl_icache_context icache;
    cdl_vertical_context vertical;

    cdl_grid_plan *grids;             /* per grid of the scene */
    cdl_icache_records *records;      /* per grid: the cache's records (read from the file or gathered) */
    cdl_solve_cache cache;

    /* Totals over the grids, for the plan and the solution. */
    cdl_direct_sample_stats direct_stats;
    cdl_path_stats pathtrace_stats;
    cdl_icache_stats icache_stats;
    cdl_path_stats vertical_stats;

    /* Scratch reused from grid to grid (per light). */
    cdl_light_strategy *strategies;
    cdl_direct_route_tally *routes;

    /* Surface maps (integrate_surfaces.c), made before the grids: their
     * interreflection method, the meshing's counts, and the one cache the
     * maps and the grids the cache serves share (NULL without maps). */
    cdl_method surface_method;
    cdl_surface_mesh_stats surface_stats;
    size_t surface_records;           /* records the maps' points placed */
    cdl_icache_shared *shared_cache;  /* owned */

    struct cdl_plan_json *plan;       /* owned: the plan's JSON as it is narrated (plan_json.h) */

    /* Glare (solve_observers.c, integrate_glare.c): the scene's observers
     * go through the table as one job of their own, their eyes its points
     * and their lines of sight its normals; its direct light is the
     * background's (every light but the luminaires), its interreflection
     * traced by paths. */
    cdl_grid_spec observer_spec;      /* a points grid: the eyes and lines of sight (arrays owned) */
    cdl_grid_solution observer_points;/* E at the eyes from the background (owned) */
    cdl_grid_plan observer_plan;
    cdl_direct_context background;    /* direct light from everything but the luminaires */
    cdl_scene_light *background_lights; /* copies of those lights (their emitters stay the state's) */
    struct cdl_glare_rated *rated;    /* per scene luminaire: how it is rated (solve_observers.h) */
    cdl_direct_sample_stats glare_stats; /* shadow rays the glare integrator cast */
    uint64_t glare_exact, glare_sampled; /* (observer, luminaire) pairs whose solid angle was exact, sampled */
} cdl_solve_state;

/* One grid going through the integrators. */
typedef struct cdl_grid_job {
    size_t index;                     /* in the scene's grids (the observers' job: grid_count) */
    int observers;                    /* 1: the observers' job (glare) */
    int everywhere;                   /* with ranks: 1: every rank holds every point's results (the glare
                                       * integrator needs them); 0: each keeps its block's until the job
                                       * ends and rank 0 gathers them */
    const cdl_direct_context *direct; /* the direct light it takes: the state's, or the background's */
    const cdl_grid_spec *spec;
    cdl_grid_solution *gs;            /* its results (borrowed from the solution) */
    const cdl_grid_plan *plan;
    double *var_direct;               /* per point: variance of E_direct (lx^2) */
    double *var_indirect;             /* per point: variance of E_indirect (lx^2); 0 without interreflection */
    unsigned char *on_surface;        /* per point, 1 where it lies on a surface (vertical outputs); NULL */
    size_t on_surface_count;
    /* Facts for the plan. */
    uint64_t records, passes, alone;  /* icache: records gathered for this grid, placement passes, own records */
    uint64_t paths;                   /* pathtrace: paths traced for this grid */
    cdl_pathtrace_convergence convergence; /* pathtrace: the exponent its plans took */
    uint64_t vertical_rays;           /* the vertical outputs' sampled part */
} cdl_grid_job;

typedef struct cdl_integrator {
    const char *name;
    int (*applies)(const cdl_solve_state *state, const cdl_grid_job *job);
    cdl_status (*run)(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err);
} cdl_integrator;

/* The integrators, in the order a grid goes through them. */
extern const cdl_integrator cdl_integrator_direct;      /* integrate_direct.c */
extern const cdl_integrator cdl_integrator_icache;      /* integrate_icache.c */
extern const cdl_integrator cdl_integrator_pathtrace;   /* integrate_pathtrace.c */
extern const cdl_integrator cdl_integrator_vertical;    /* integrate_vertical.c */
extern const cdl_integrator cdl_integrator_glare;       /* integrate_glare.c */

/* Integrators that run once for the whole solve, after planning and
 * before the grids: the surface maps, whose cache records the grids then
 * share. */
typedef struct cdl_solve_integrator {
    const char *name;
    int (*applies)(const cdl_solve_state *state);
    cdl_status (*run)(cdl_solve_state *state, cdl_error *err);
} cdl_solve_integrator;

extern const cdl_solve_integrator cdl_integrator_surfaces; /* integrate_surfaces.c */

/* The workers of a task of the solve: its threads and ranks, the results
 * everywhere or kept (pool.h). */
cdl_workers cdl_solve_workers(const cdl_solve_state *state, int everywhere);

/* Whether the job's direct light goes to every rank: where the job's
 * results do, and where the irradiance cache follows (it gathers records
 * at any point, with that point's direct light). */
int cdl_grid_job_direct_everywhere(const cdl_solve_state *state, const cdl_grid_job *job);

/* "grid NAME" or "grid NAME: WHAT", the stage a progress report names. */
void cdl_grid_job_stage(const cdl_grid_job *job, const char *what, char *out, size_t size);

#endif
