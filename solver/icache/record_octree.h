/* record_octree.h - an octree of record spheres: which irradiance-cache
 * records may serve a point.
 *
 * A record serves the points inside its sphere of influence (centre p_i,
 * radius r_i). Each record is stored at the depth whose cells are just big
 * enough to hold its sphere (cell half-size >= r_i), in every cell of that
 * depth its sphere's box overlaps (at most 8): large spheres sit high,
 * small ones low. A lookup walks from the root down to the deepest cell
 * holding p and collects the records of each cell it passes, which is every
 * record whose sphere might contain p (Ward, Rubinstein and Clear, "A ray
 * tracing solution for diffuse interreflection", SIGGRAPH 1988, keep their
 * records in the same kind of tree).
 */
#ifndef CANDELA_SOLVER_ICACHE_RECORD_OCTREE_H
#define CANDELA_SOLVER_ICACHE_RECORD_OCTREE_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/bounds.h"
#include "base/error.h"
#include "radiometry/vec3.h"

typedef struct cdl_record_octree cdl_record_octree;

/* An empty tree over `bounds` (points to look up lie inside it; spheres may
 * reach beyond). */
cdl_status cdl_record_octree_create(cdl_bounds3 bounds, cdl_record_octree **out, cdl_error *err);
void cdl_record_octree_release(cdl_record_octree *tree);

/* Store record `id` whose sphere is (centre, radius). */
cdl_status cdl_record_octree_insert(cdl_record_octree *tree, uint32_t id, cdl_vec3 centre, double radius,
                                    cdl_error *err);

/* The records whose spheres may contain p, in increasing id order (so a
 * caller's sums do not depend on how the tree was filled), into *ids
 * (grown with realloc; *capacity its size). Returns their count, or
 * (size_t)-1 when memory ran out. */
size_t cdl_record_octree_lookup(const cdl_record_octree *tree, cdl_vec3 p, uint32_t **ids, size_t *capacity);

#endif
