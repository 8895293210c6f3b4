/* solve_cache.h - a solve's irradiance-cache file: opened before the grids, written after.
 *
 * The file (icache/icache_file.h) holds the records of the grids the cache
 * solves, keyed by everything they depend on (the scene's hash, the
 * settings, Candela's version). Not public.
 */
#ifndef CANDELA_SOLVER_SOLVE_CACHE_H
#define CANDELA_SOLVER_SOLVE_CACHE_H

#include "base/error.h"
#include "solver/integrate/integrator.h"

/* What the records depend on now; which grids the cache solves; and, when
 * the file exists and was made for them, their records (moved into
 * state->records). A missing file's folder must take it (checked now, not
 * after a long solve). */
cdl_status cdl_solve_cache_open(cdl_solve_state *state, cdl_error *err);

/* Write the records the solve gathered (atomically). */
cdl_status cdl_solve_cache_save(const cdl_solve_state *state, cdl_error *err);

void cdl_solve_cache_release(cdl_solve_cache *cache);

#endif
