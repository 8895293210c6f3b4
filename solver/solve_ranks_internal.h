/* solve_ranks_internal.h - the steps a solve shared by ranks takes beyond one process's (solve_ranks.c; not public). */
#ifndef CANDELA_SOLVER_SOLVE_RANKS_INTERNAL_H
#define CANDELA_SOLVER_SOLVE_RANKS_INTERNAL_H

#include "base/error.h"
#include "solver/integrate/integrator.h"

/* After planning: do the ranks hold the same scene (geometry, materials,
 * lights and their files' bytes, every grid's points and outputs, the
 * observers, the surface maps), settings and cache file? CDL_ERR_INPUT,
 * on every rank, when not. Nothing without ranks. */
cdl_status cdl_solve_ranks_check_scene(cdl_solve_state *state, cdl_error *err);

/* After a grid's integrators: the parts each rank kept of its block of
 * the points (cdl_grid_job.everywhere 0) gathered to rank 0, in chunks. */
cdl_status cdl_solve_ranks_collect_job(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err);

/* At the end: each rank's threads, seconds since t0, seconds of work, CPU
 * seconds since cpu0 and bytes received, into rank 0's solution
 * (out->ranks). */
cdl_status cdl_solve_ranks_report(cdl_solve_state *state, double t0, double cpu0, cdl_error *err);

#endif
