/* annual.h - an annual daylight study: every hour of a weather file at every
 * grid point, and the climate-based metrics (`candela annual`; not public).
 *
 * Steps (each timed, summary.json "seconds"):
 *  1. the weather file (epw.h), the occupancy (occupancy.h) and the
 *     daylight hours (annual_metrics.h);
 *  2. each hour's sky (annual_sky.h);
 *  3. --sky perez: the scene's daylight coefficients
 *     (solver/daylight/daylight_coefficients.h) for the sky's patches and the
 *     sun bins, and the direct sun of each hour with sunlight at every point
 *     (one ray each: max(0, n.s) T); --sky cie_overcast: one solve of the
 *     scene under the CIE overcast sky with its interreflection, whose
 *     daylight factor DF is each point's single coefficient (the overcast
 *     sky's shape is the same every hour: no patches, no discretisation);
 *  4. the hours: perez, E = S C^T (S the hours' patch luminances, C the
 *     points' coefficients) by one BLAS sgemm, then for each hour with sun
 *     E_dn (D + C_sun) at each point, D its direct sun and C_sun its sun
 *     bin's interreflected coefficient; cie_overcast, E = DF / 100 x the
 *     hour's diffuse horizontal illuminance;
 *  5. the metrics per point and per grid, and the files (annual_output.h).
 *
 * The stated error of the coefficients (summary.json "coefficients"): per
 * point the relative standard error of the sampled part under a uniform sky
 * (perez) or of E under the overcast sky (cie_overcast), and for perez the
 * patches' discretisation (a patch's luminance taken as its mean), estimated
 * at each month's sunniest hour against patches half the size, the two in
 * quadrature; its mean and worst per grid.
 *
 * Shared by ranks (options.ranks, `mpirun -np N candela annual`): every
 * rank reads the scene and the weather and classifies the hours; the
 * perez skies' rows (step 2), each grid's points for its coefficients and
 * the discretisation's (step 3, solver/daylight/daylight_coefficients.h)
 * and the hours' direct sun (step 3) are dealt among the ranks in small
 * units (rank_group.h's cdl_rank_deal: points far from a window cost many
 * times those near it, and every rank gets points from the whole grid);
 * their results go to rank 0 in windows of 8 MiB, and rank 0 alone does
 * step 4 and 5, writes and gets the results (the others' *result holds no
 * grids). Every point's and hour's random numbers are keyed by it, never
 * by who computes it, so the files are one process's, byte for byte, for
 * any number of ranks and threads. The function is then a collective:
 * after each step the ranks agree on how it went (a failure on any rank,
 * a weather file one of them cannot read, is every rank's, its message
 * naming the rank); a failure a rank meets alone in an exchange is
 * returned by it alone (options.ranks->failure_agreed 0: end the job).
 * summary.json's "ranks" holds each rank's threads, seconds, work,
 * CPU seconds, bytes received and peak memory (count 1 alone).
 *
 * Thread safety: a run owns everything it makes; the scene is only read.
 * The hours' product runs on the run's threads, one BLAS thread each
 * (cdl_annual_product).
 */
#ifndef CANDELA_DAYLIGHT_ANNUAL_H
#define CANDELA_DAYLIGHT_ANNUAL_H

#include <stddef.h>

#include "base/error.h"
#include "daylight/annual_metrics.h"
#include "daylight/annual_sky.h"
#include "radiometry/vec3.h"
#include "solver/progress.h"
#include "solver/rank_group.h"
#include "solver/scene/scene_internal.h"

typedef struct cdl_annual_options {
    cdl_annual_sky_kind sky;              /* default perez */
    int mf;                               /* Reinhart subdivision: 1 (145 patches, default), 2 (577), 4 (2305) */
    const char *occupancy;                /* "A-B" or a CSV file (occupancy.h); default "8-18" */
    double ground_reflectance;            /* the ground patch's reflectance, [0, 1]; default 0 */
    cdl_vec3 north;                       /* default +y (up is +z) */
    int threads;                          /* worker threads, 0 all cores; -1 (default): the scene's "threads" */
    const char *ocio_config;              /* the maps' OpenColorIO config; NULL: Candela's */
    cdl_progress_sink progress;
    cdl_rank_group *ranks;                /* NULL: this process alone; else the ranks sharing the study (below) */
} cdl_annual_options;
#define CDL_ANNUAL_OPTIONS_INIT                                                                                       \
    {CDL_ANNUAL_SKY_PEREZ, 1, "8-18", 0.0, {0.0, 1.0, 0.0}, -1, NULL, {NULL, NULL}, NULL}

/* What a run found, per grid (the files hold it all). */
typedef struct cdl_annual_grid_result {
    char *name;
    size_t points;
    cdl_grid_annual_metrics metrics;
    double stderr_mean_rel, stderr_max_rel; /* the coefficients' stated error (sampling and discretisation) */
    double discretisation_mean_rel, discretisation_max_rel; /* the patches' part of it (perez) */
} cdl_annual_grid_result;

typedef struct cdl_annual_result {
    cdl_annual_grid_result *grids;
    size_t grid_count;
    size_t hours, lit_hours, occupied_hours, daylight_hours;
    double seconds_skies, seconds_coefficients, seconds_suns, seconds_hours, seconds_metrics, seconds_total;
} cdl_annual_result;

/* Run the study of `scene` under the weather file at `weather` and write
 * its files into out_dir (prepared: cdl_solution_prepare_folder). */
cdl_status cdl_annual_run(const cdl_scene *scene, const char *weather, const cdl_annual_options *options,
                          const char *out_dir, cdl_annual_result *result, cdl_error *err);
void cdl_annual_result_release(cdl_annual_result *result);

/* E = skies x coefficients^T for `rows` hours: out[r * points + i] =
 * sum_k sky[r * patches + k] coef[i * patches + k], by BLAS (cblas_sgemm)
 * in blocks of 512 hours shared by `threads` (>= 1) threads, each call on
 * one BLAS thread (OpenBLAS's threads set to 1 meanwhile): the same bytes
 * for any count of threads, whatever cores the BLAS would take. Errors:
 * cdl_pool_run's (out of memory). */
cdl_status cdl_annual_product(const float *sky, size_t rows, const float *coef, size_t points, size_t patches,
                              float *out, int threads, cdl_error *err);

#endif
