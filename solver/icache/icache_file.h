/* icache_file.h - irradiance-cache records saved to a file, and reused only
 * by the scene and settings they were made for (`candela solve --cache`).
 *
 * A grid's records (icache.h) depend on the scene's geometry, materials and
 * lights, on the solver settings that shape them, on the grid's own points
 * and name (its random numbers are keyed by its name), and on nothing else:
 * not on other grids, the thread count, outputs or the PNG colours. The
 * file holds what they depend on beside them, so that a file made for
 * anything else is refused with a message saying what differs, and never
 * silently used.
 *
 * Format (version 1). Every integer little-endian, every real an IEEE 754
 * double (its 8 bytes little-endian); offsets in bytes:
 *
 *   0   8  magic "CDLICACH"
 *   8   4  u32  format version (1)
 *  12   8  u64  length of the whole file, checksum included
 *  20   4  u32  length n of the Candela version string (1 .. 63)
 *  24   n       the version string of the Candela that wrote it (ASCII)
 *       8  u64  scene hash: geometry   (scene_hash.h)
 *       8  u64  scene hash: materials
 *       8  u64  scene hash: lights
 *       4  u32  method (0 auto, 1 direct, 2 icache, 3 pathtrace)
 *       8  f64  target relative standard error (target_error or the quality's)
 *       4  i32  bounces (-1 auto)
 *       8  u64  seed
 *       4  i32  direct_samples (0 adaptive)
 *       4  u32  exact routes for partly hidden emitters (1 on, 0 off)
 *       4  u32  gradients in the interpolation (1 on, 0 off)
 *       8  u64  number of grids G; then G times:
 *       4  u32    length m of the grid's name (1 .. 4096), then m bytes: the name
 *       8  u64    number of points of the grid
 *       8  u64    hash of its points, normals and spacing (cdl_icache_grid_hash)
 *       8  u64    number of records R (at least 1 when the grid has points); then R times
 *     136  f64 x 17  p.x p.y p.z  n.x n.y n.z  E  var  radius  grad_r.x .y .z
 *                    grad_t.x .y .z  open  harmonic   (icache_record.h)
 *   last 8 u64  checksum: FNV-1a (content_hash.h) of every byte before it
 *
 * A file is read whole and checked before anything is used: its magic,
 * format version and length (a truncated file is caught by the length, a
 * changed byte by the checksum), every count against the bytes left, every
 * value finite (harmonic may be +infinity: all gather rays left the scene),
 * variances >= 0, radii > 0, no byte left over. Any failure is
 * CDL_ERR_INPUT naming the file and what was wrong; nothing is handed on.
 * Saving writes a temporary file beside the target, fsyncs and renames it
 * (atomic_file.h): a reader sees the old file or the new one, never part.
 *
 * Only grids solved by the irradiance cache have records; a grid solved by
 * path tracing or direct light only is not in the file. The file is for
 * the scene as a whole: a grid solved by the cache now must be in it with
 * the same points, and it may hold no other grid.
 */
#ifndef CANDELA_SOLVER_ICACHE_FILE_H
#define CANDELA_SOLVER_ICACHE_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "solver/grid/grid.h"
#include "solver/icache/icache.h"
#include "solver/scene/scene_internal.h"
#include "solver/scene/scene_hash.h"

#define CDL_ICACHE_FILE_FORMAT 1
#define CDL_ICACHE_FILE_VERSION_SIZE 64  /* the version string and its NUL */

/* The version a cache is made by, stored in the file and compared on
 * reading: Candela's, and the revision of how records are made. Bump the
 * revision whenever gathering, placement or interpolation would make other
 * records from the same scene and settings (2: records held to twice a
 * point's variance target, second-order term in the interpolation; 3:
 * spacing from the points, records of radius 0 serving their own point;
 * 4: luminaires spread over the remaining LM-63 solids and vertical
 * circles, the near-field cubature to 1/50 of the target: the light the
 * records gather changed). */
#define CDL_ICACHE_MAKER CANDELA_VERSION " records-4"
#define CDL_ICACHE_FILE_NAME_MAX 4096    /* longest grid name, bytes */

/* The solver settings records depend on (not threads, outputs or colours). */
typedef struct cdl_icache_settings {
    cdl_method method;
    double target;            /* relative standard error of a point's E */
    int bounces;              /* CDL_BOUNCES_AUTO or the most reflections */
    uint64_t seed;
    int direct_samples;       /* 0: adaptive */
    int exact_route;          /* 1: partly hidden emitters by their visible polygon where exact */
    int gradients;            /* 1: interpolation with the records' gradients */
} cdl_icache_settings;

/* What a file's records were made for. */
typedef struct cdl_icache_key {
    char version[CDL_ICACHE_FILE_VERSION_SIZE];  /* Candela version, e.g. "0.1.0" */
    cdl_scene_hashes scene;
    cdl_icache_settings settings;
} cdl_icache_key;

typedef struct cdl_icache_file_grid {
    char *name;
    uint64_t point_count;
    uint64_t points_hash;     /* cdl_icache_grid_hash */
    cdl_icache_records records;
} cdl_icache_file_grid;

typedef struct cdl_icache_file {
    cdl_icache_key key;
    cdl_icache_file_grid *grids;
    size_t grid_count;
} cdl_icache_file;

/* A grid's points, normals and spacing (the records' placement and reach
 * depend on them), hashed. */
uint64_t cdl_icache_grid_hash(const cdl_grid *grid);

/* The file's bytes (the format above) into *data (caller frees). */
cdl_status cdl_icache_file_encode(const cdl_icache_key *key, const cdl_icache_file_grid *grids, size_t grid_count,
                                  unsigned char **data, size_t *size, cdl_error *err);

/* Write the file at `path` atomically. */
cdl_status cdl_icache_file_save(const char *path, const cdl_icache_key *key, const cdl_icache_file_grid *grids,
                                size_t grid_count, cdl_error *err);

/* Check and decode the bytes of a file (`path` names it in messages) into
 * *out (released with cdl_icache_file_release); *out is untouched on
 * failure. */
cdl_status cdl_icache_file_parse(const unsigned char *data, size_t size, const char *path, cdl_icache_file *out,
                                 cdl_error *err);

/* Read and check the file at `path`. When it does not exist, *found = 0
 * and CDL_OK; otherwise *found = 1 and as cdl_icache_file_parse. */
cdl_status cdl_icache_file_load(const char *path, int *found, cdl_icache_file *out, cdl_error *err);

/* Was the file made for `now`? CDL_ERR_INPUT otherwise, with a message
 * naming the file and everything that differs: the Candela version, the
 * scene's geometry, materials or lights, each differing setting with its
 * value in the file and now. */
cdl_status cdl_icache_file_match_key(const cdl_icache_file *file, const char *path, const cdl_icache_key *now,
                                     cdl_error *err);

/* Match the grids the cache solves now (names[k], grids[k], k < count) with
 * the file's: each must be in it with the same points, and it may hold no
 * other. On success index[k] is the file's grid for grids[k]; otherwise
 * CDL_ERR_INPUT naming the file and the grid. */
cdl_status cdl_icache_file_match_grids(const cdl_icache_file *file, const char *path, const char *const *names,
                                       const cdl_grid *const *grids, size_t count, size_t *index, cdl_error *err);

void cdl_icache_file_release(cdl_icache_file *file);

#endif
