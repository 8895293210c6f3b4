/* solve.h - a scene in, illuminance on every grid out.
 *
 * cdl_solve_scene chooses the method, plans what each light needs on each
 * grid, and computes the results in memory (solution.h);
 * output/solution_write.h writes them as `candela solve` does.
 *
 * Methods: "direct" computes direct light only; "pathtrace" adds
 * interreflected light by paths from every point, "icache" by an
 * irradiance cache; "auto" picks, per grid, the cheapest method that gives
 * the whole answer for the target asked, which is "direct" when nothing in
 * the scene reflects light.
 *
 * Units: lux in the solution, seconds, threads. Ownership: the scene and
 * options are borrowed for the call; the solution is the caller's.
 * Thread safety: cdl_solve_scene itself runs on `threads` worker threads
 * (the calling thread among them) and returns when they are done; the
 * progress callback is only called on the calling thread. It keeps no
 * global state, so solves may run at once on different threads, each with
 * its own solution.
 */
#ifndef CANDELA_SOLVER_SOLVE_H
#define CANDELA_SOLVER_SOLVE_H

#include "base/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"
#include "solver/solve_options.h"

/* Solve every grid of `scene`; `options` may be NULL (the defaults). On
 * success *out is the caller's, freed with cdl_solution_release; on
 * failure it is NULL. Errors: CDL_ERR_INPUT for a scene that cannot be
 * solved as asked (an unreadable photometric file or image, a cache file
 * made for something else), the message naming the JSON path or file;
 * CDL_ERR_USAGE for options out of range; CDL_ERR_CANCELLED when the
 * progress callback asked to stop; CDL_ERR_INTERNAL for resources. */
cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution **out,
                           cdl_error *err);

#endif
