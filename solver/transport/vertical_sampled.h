/* vertical_sampled.h - cylindrical and semicylindrical illuminance from all
 * but delta lights: extended emitters, skies and interreflection, sampled
 * to a target with a stated error (vertical_sampled.c). */
#ifndef CANDELA_SOLVER_TRANSPORT_VERTICAL_SAMPLED_H
#define CANDELA_SOLVER_TRANSPORT_VERTICAL_SAMPLED_H

#include <stdint.h>

#include "base/error.h"
#include "solver/grid/grid.h"
#include "solver/pool.h"
#include "solver/transport/path.h"

typedef struct cdl_vertical_context {
    cdl_path_context path;    /* lights, geometry (may be NULL: nothing reflects or hides), seed, bounces */
    int indirect;             /* 1: add the reflected light (one path per sample); needs geometry */
    double target;            /* relative standard error of E_z per point */
    double max_samples;       /* most samples per point */
} cdl_vertical_context;

typedef struct cdl_vertical_estimate {
    double Ez, Esz;           /* lux: the sampled part */
    double Ez_var, Esz_var;   /* variances of those means */
    uint64_t samples;
} cdl_vertical_estimate;

/* At p (normal n), the semicylinder facing the unit horizontal `facing`;
 * on_surface: p lies on a surface, which hides every direction behind n.
 * Ez_exact is the exact part already known (delta lights), used only to
 * set the target. `stream` keys the random numbers. */
void cdl_vertical_sampled_point(const cdl_vertical_context *ctx, uint64_t stream, cdl_vec3 p, cdl_vec3 n,
                                cdl_vec3 facing, int on_surface, double Ez_exact, cdl_vertical_estimate *out,
                                cdl_path_stats *stats);

/* Every point of a grid: Ez and Esz (either may be NULL) gain the sampled
 * part, Ez_stderr and Esz_stderr (with them) receive its standard error,
 * on the workers (pool.h). Semicylinders face each point's normal's
 * horizontal part. on_surface (NULL: no point does): per point, 1 where it
 * lies on a surface. Counts over all ranks are added to *stats. */
cdl_status cdl_vertical_sampled_grid(const cdl_vertical_context *ctx, const cdl_grid *grid, size_t grid_index,
                                     const unsigned char *on_surface, double *Ez, double *Esz, double *Ez_stderr,
                                     double *Esz_stderr, const cdl_workers *workers, const char *stage,
                                     cdl_path_stats *stats, cdl_error *err);

#endif
