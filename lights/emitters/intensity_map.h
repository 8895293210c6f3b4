/* intensity_map.h - an emitter's luminous intensity tabulated over the sphere, for cheap guesses.
 *
 * A sampler that draws one light among many weighs each by a guess of
 * what it gives, I cos / d^2 towards the point (Shirley, Wang and
 * Zimmerman, ACM TOG 15, 1996). Any positive guess keeps the draw
 * unbiased; a good one keeps it efficient. Evaluating a photometric table
 * exactly for every light at every path vertex (the direction into the
 * luminaire's frame, its C and gamma by atan2 and acos, the table's
 * bilinear interpolation) was the largest single cost of next-event
 * estimation in the example office. The map is the intensity at the nodes
 * of a regular grid over the octahedral map of the sphere
 * (radiometry/octahedral.h), interpolated bilinearly: a few multiplies and
 * four loads, no trigonometry.
 *
 * Between nodes it is an approximation of I (it rounds off the edge of a
 * sharp cut-off over one cell, whose corners lie up to 7.7 degrees apart at
 * the default resolution):
 * a weight, never an estimate. At the nodes it holds I to float precision;
 * where I is 0 over a whole cell (behind a downlight), it is exactly 0.
 *
 * A built map is immutable: lookups are thread-safe.
 */
#ifndef CANDELA_LIGHTS_EMITTERS_INTENSITY_MAP_H
#define CANDELA_LIGHTS_EMITTERS_INTENSITY_MAP_H

#include "base/error.h"
#include "lights/emitters/emitter.h"
#include "radiometry/units.h"
#include "radiometry/vec3.h"

typedef struct cdl_intensity_map cdl_intensity_map;

/* Nodes per side of the map by default: 64 x 64 floats, 16 KiB. */
#define CDL_INTENSITY_MAP_RESOLUTION 64

/* The map of cdl_emitter_intensity(emitter, w) at resolution x resolution
 * nodes (resolution >= 2); negative or non-finite intensities are kept as
 * 0. Errors: CDL_ERR_USAGE for a resolution below 2, out of memory. */
cdl_status cdl_intensity_map_build(const cdl_emitter *emitter, int resolution, cdl_intensity_map **out,
                                   cdl_error *err);
void cdl_intensity_map_release(cdl_intensity_map *map);

/* The interpolated intensity towards world direction `dir` (any length > 0). */
cdl_luminous_intensity cdl_intensity_map_lookup(const cdl_intensity_map *map, cdl_vec3 dir);

/* Node (i, j)'s direction (unit) and its tabulated intensity, 0 <= i, j <
 * resolution: what the map holds exactly. */
cdl_vec3 cdl_intensity_map_node_direction(const cdl_intensity_map *map, int i, int j);
cdl_luminous_intensity cdl_intensity_map_node(const cdl_intensity_map *map, int i, int j);

int cdl_intensity_map_resolution(const cdl_intensity_map *map);

#endif
