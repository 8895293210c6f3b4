/* solve.h - `candela solve`: a scene in, illuminance on every grid out.
 *
 * cdl_solve_scene chooses the method, plans what each light needs on each
 * grid, and computes (in memory, solution.h); output/solution_write.h writes
 * the files of DESIGN.md.
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
 * its own cdl_solution.
 */
#ifndef CANDELA_SOLVER_SOLVE_H
#define CANDELA_SOLVER_SOLVE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"
#include "solver/solve_options.h"

/* Solve every grid of `scene`; `options` may be NULL (the defaults). On
 * success the caller releases *out with cdl_solution_release; on failure
 * *out is left empty (releasing it is harmless). Errors: CDL_ERR_INPUT for
 * a scene that cannot be solved as asked (an unreadable photometric file
 * or image, a method not built yet, a cache file made for something else),
 * the message naming the JSON path or file; CDL_ERR_CANCELLED when the
 * progress callback asked to stop; CDL_ERR_INTERNAL for resources. */
cdl_status cdl_solve_scene(const cdl_scene *scene, const cdl_solve_options *options, cdl_solution *out,
                           cdl_error *err);

/* Does light reflect anywhere? The JSON path of the first surface (or area
 * luminaire) with a reflectance above 0, its reflectance in *rho; NULL
 * when nothing reflects (then only direct light is computed). */
const char *cdl_solve_first_reflector(const cdl_scene *scene, double *rho);

#endif
