/* surface_output.h - the files of surface maps and their statistics.
 *
 * Per mapped surface NAME (its map_name), in OUTDIR/surfaces/:
 *   NAME.csv      x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,L_cd_m2
 *                 one row per vertex (numbers as the grids' CSVs write them);
 *                 E_stderr_lx joins the value's own error and the rms error of
 *                 the linear interpolant over the vertex's triangles;
 *                 L = rho E / pi;
 *   NAME.tri.csv  a,b,c: each triangle's vertices as 0-based rows of NAME.csv,
 *                 counter-clockwise seen from the front (the normal's side).
 * And OUTDIR/scene.glb (gltf_output.h): the mapped surfaces in the false
 * colours of one linear lux scale over all of them (the maps' OpenColorIO
 * view; its top at 99 % of the area, cdl_lux_scale_linear_for_areas) with
 * their illuminance, the other surfaces grey, a
 * marker at each luminaire (area luminaires at their shape's centre).
 *
 * Statistics (summary.json "surfaces"), over the linear interpolant the
 * map is: Em = (1/A) sum over triangles of A_t (E_a + E_b + E_c) / 3;
 * Emin and Emax the vertices' (a linear function on a triangle takes its
 * extremes at corners); U0 = Emin / Em; L_mean likewise of rho E / pi;
 * stderr_mean_rel the area-weighted mean of E_stderr / E where E > 0.
 *
 * Every file written atomically; a non-finite value is refused
 * (CDL_ERR_INTERNAL naming the file). Thread safety: reentrant.
 */
#ifndef CANDELA_SOLVER_OUTPUT_SURFACE_OUTPUT_H
#define CANDELA_SOLVER_OUTPUT_SURFACE_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/scene/scene_internal.h"
#include "solver/solution_internal.h"

typedef struct cdl_surface_stats {
    double area_m2;
    double Em_lx, Emin_lx, Emax_lx, U0;
    double L_mean_cd_m2;
    double stderr_mean_rel;
    size_t vertices, triangles;
} cdl_surface_stats;

void cdl_surface_solution_stats(const cdl_surface_solution *map, cdl_surface_stats *stats);

/* The area each vertex of a mesh stands for: a third of each of its
 * triangles', into area[0 .. vertex_count). */
void cdl_mesh_vertex_areas(const double *xyz, size_t vertex_count, const uint32_t *triangles, size_t triangle_count,
                           double *area);

/* NAME.csv and NAME.tri.csv of one map into `folder` (which exists). */
cdl_status cdl_surface_write_csv(const cdl_surface_solution *map, const char *folder, const char *name,
                                 cdl_error *err);

/* OUTDIR/scene.glb of the solution's maps, shapes and the scene's luminaires. */
cdl_status cdl_surface_write_glb(const cdl_scene *scene, const cdl_solution *solution, const char *path,
                                 const char *ocio_config, cdl_error *err);

#endif
