/* solution_internal.h - a solve's results in memory, behind the public handle of solution.h (not public).
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
#ifndef CANDELA_SOLVER_SOLUTION_INTERNAL_H
#define CANDELA_SOLVER_SOLUTION_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "base/error_report.h"
#include "solver/grid/grid.h"
#include "solver/rank_group.h"
#include "solver/scene/scene_internal.h"
#include "solver/solution.h"

/* Installed power (summary.json "power"): the luminaire files' input
 * watts, one per luminaire placed (copies of an array each count); per
 * grid, of the luminaires over it (cdl_solve_sum_power). */
typedef struct cdl_power_summary {
    double installed_w;               /* sum over the luminaires whose files give their input watts */
    size_t luminaires_counted;        /* luminaires with a wattage */
    size_t luminaires_without_watts;  /* point, spot and area luminaires, files without one */
} cdl_power_summary;

typedef struct cdl_grid_solution {
    char *name;                       /* the grid's name (a copy: the solution outlives its scene) */
    cdl_grid_kind kind;
    cdl_grid grid;
    double *E, *E_direct, *E_indirect, *E_stderr;
    double *ao, *ao_stderr;           /* NULL unless asked for */
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
    /* Installed power over the grid: the luminaires whose position,
     * projected along the grid's normal, falls within its outline on the
     * side its points face (rect and polygon grids; none for points). */
    cdl_power_summary power;
} cdl_grid_solution;

/* One luminaire rated at an observer (CIE 117:1995 UGR): its term
 * L^2 omega / p^2 in the sum. */
typedef struct cdl_glare_source_result {
    size_t luminaire;                 /* its index in scene->luminaires */
    double L_cd_m2;                   /* luminance of its luminous parts towards the eye, I / A_p */
    double omega_sr;                  /* their solid angle at the eye, less what surfaces hide */
    double omega_stderr_sr;           /* its standard error (0 where nothing can hide them) */
    int omega_exact;                  /* 1: the luminous parts' solid angle is exact; 0: CIE 117's A_p / r^2
                                       * (cylinders, ellipsoids: glare/glare_source.h) */
    double p;                         /* Guth's position index */
    double term, term_stderr;         /* L^2 omega / p^2 (cd^2 m^-4 sr) and its standard error */
} cdl_glare_source_result;

/* A luminaire that adds nothing to an observer's rating, and why. */
typedef struct cdl_glare_exclusion {
    size_t luminaire;                 /* its index in scene->luminaires */
    const char *reason;               /* static text: "behind the eye", "beyond T/R = 3", "below the line of
                                       * sight", "above the position index table", "no light towards the
                                       * eye", "no luminous area: a point source cannot be rated", ... */
} cdl_glare_exclusion;

/* The glare at one observer (scene->observers[i]). */
typedef struct cdl_observer_result {
    int defined;                      /* 0: no rated luminaire in view sends light to the eye, or the
                                       * background is dark: no rating (ugr 0) */
    double ugr, ugr_stderr;           /* UGR = 8 log10((0.25 / Lb) sum terms) and its standard error */
    double background_cd_m2;          /* Lb = E_b / pi, E_b at the eye on the plane facing the line of sight
                                       * from everything but the luminaires' direct light */
    double background_stderr_cd_m2;
    cdl_glare_source_result *sources; /* the luminaires in view, in scene order */
    size_t source_count;
    cdl_glare_exclusion *excluded;    /* the others (skies excepted: they are background) */
    size_t excluded_count;
} cdl_observer_result;

/* A surface map: the illuminance on a mapped surface's front
 * side at the vertices of a mesh that follows the light
 * (solver/geometry/surface_mesh.h). E_stderr holds, with the value's own
 * error, the rms error of the linear interpolant over the vertex's
 * triangles, so that it states how far the map may be off around the
 * vertex. A box's faces are one map whose vertices carry their own face's
 * normal (a vertex on a box edge appears once per face). */
typedef struct cdl_surface_solution {
    size_t surface;                   /* its index in scene->surfaces */
    size_t vertex_count, triangle_count;
    double *xyz, *normal;             /* 3 per vertex; normals unit, the front side's */
    uint32_t *triangles;              /* 3 per triangle: vertex rows, counter-clockwise seen from the front */
    double *E, *E_direct, *E_indirect, *E_stderr; /* lux, per vertex */
    double *rho;                      /* the reflectance at each vertex (a box: its face's) */
    double *L;                        /* rho E / pi, cd/m^2 */
    double area_m2;                   /* of the triangles */
} cdl_surface_solution;

/* A surface that is not mapped, as scene.glb shows it (grey): its
 * triangles as the ray scene has them (a sphere tessellated). */
typedef struct cdl_surface_shape {
    size_t surface;                   /* its index in scene->surfaces, or SIZE_MAX for an area luminaire's shape */
    size_t vertex_count, triangle_count;
    double *xyz, *normal;
    uint32_t *triangles;
} cdl_surface_shape;

struct cdl_solution {
    cdl_method method;                /* the method actually used */
    cdl_solver_settings settings;     /* with quality-derived knobs filled in */
    double target_error;              /* the relative standard error asked of E per point */
    int threads_used;
    cdl_grid_solution *grids;         /* scene->grid_count */
    size_t grid_count;
    cdl_surface_solution *surfaces;   /* the mapped surfaces, in the scene's order */
    size_t surface_count;
    cdl_surface_shape *shapes;        /* with surface maps: the other surfaces, for scene.glb */
    size_t shape_count;
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
    /* Glare (the glare integrator): one result per scene observer, in order. */
    cdl_observer_result *observers;
    size_t observer_count;
    /* The ranks that shared the solve, in rank order (one without ranks). */
    cdl_rank_report *ranks;
    size_t rank_count;
};

/* Zeroed arrays for the grid's points (gs->grid built): E, E_direct,
 * E_indirect, E_stderr, and ao when want_ao. */
cdl_status cdl_grid_solution_alloc(cdl_grid_solution *gs, int want_ao, cdl_error *err);

/* Zeroed arrays for the outputs `spec` asks for beyond E and ao:
 * Ez, Esz, L with rho, and DF. Ownership: the grid solution's (released with
 * the solution). Errors: CDL_ERR_INTERNAL (out of memory). */
cdl_status cdl_grid_solution_alloc_outputs(cdl_grid_solution *gs, const cdl_grid_spec *spec, cdl_error *err);

/* Zeroed Ez_stderr / Esz_stderr for the vertical outputs gs has. Ownership:
 * the grid solution's. Errors: CDL_ERR_INTERNAL (out of memory). */
cdl_status cdl_grid_solution_alloc_vertical_stderr(cdl_grid_solution *gs, cdl_error *err);

/* Free a grid solution's arrays, its name and its grid, and zero it. */
void cdl_grid_solution_release(cdl_grid_solution *gs);

/* Append a warning (printf-style) to the solution's list; CDL_ERR_INTERNAL
 * when out of memory. Not thread-safe for one solution. */
cdl_status cdl_solution_add_warning(cdl_solution *solution, cdl_error *err, const char *fmt, ...) CDL_PRINTF(3, 4);

/* Free what the solution holds and zero it, leaving the struct itself (a
 * solution on the caller's stack; NULL and a zeroed solution are fine).
 * cdl_solution_release (solution.h) frees a solution and its struct. */
void cdl_solution_clear(cdl_solution *solution);

#endif
