/* glare_output.h - the glare of a solve's observers in its files:
 * summary.json's "glare" and glare.csv (DESIGN.md).
 *
 * Not public. Ownership: the scene and solution are borrowed for the call.
 */
#ifndef CANDELA_SOLVER_OUTPUT_GLARE_OUTPUT_H
#define CANDELA_SOLVER_OUTPUT_GLARE_OUTPUT_H

#include <cjson/cJSON.h>

#include "base/error.h"
#include "solver/scene/scene.h"
#include "solver/solution.h"

/* summary.json's "glare": one object per observer, in order - observer
 * (its name), json_path, eye, view, ugr (null without a rating), ugr_stderr,
 * background_cd_m2, background_stderr_cd_m2, UGR_L (null without a
 * requirement), sources [{luminaire, L_cd_m2, omega_sr, omega_stderr_sr,
 * omega_exact (false: CIE 117's A_p / r^2, for cylinders and ellipsoids), p,
 * term, term_stderr}], excluded [{luminaire, reason}] (luminaires by their
 * label). NULL when out of memory. */
cJSON *cdl_glare_summary_json(const cdl_scene *scene, const cdl_solution *solution);

/* glare.csv, atomically: header name,x,y,z,view_x,view_y,view_z,ugr,
 * ugr_stderr,background_cd_m2,background_stderr_cd_m2, a row per observer
 * in order; numbers as the grids' CSVs write them, ugr and its error empty
 * where there is no rating. */
cdl_status cdl_glare_write_csv(const cdl_scene *scene, const cdl_solution *solution, const char *path,
                               cdl_error *err);

#endif
