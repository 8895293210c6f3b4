/* candela/candela.h - libcandela's public interface in one include.
 *
 * Which headers are public is decided here: CMake installs exactly the
 * headers this file includes (under include/candela/, keeping their
 * folders), and the shared library exports exactly the functions they
 * declare (a version script made from them; Candela's install tests check both).
 *
 *   base/error.h            status codes and the message buffer of every fallible call
 *   radiometry/units.h            quantities whose units the compiler checks (cdl_lux, cdl_candelas, ...)
 *   radiometry/constants.h        physical and photometric constants, each with its source
 *   radiometry/conversions.h      named conversions: inverse square, Lambert, efficacy, imperial units
 *   radiometry/quantity.h         quantities as people type them ("46.45 fc", "3000 lm")
 *   radiometry/vec3.h             the 3-vector every position and direction is (inline)
 *   radiometry/cie_tables.h       CIE V(lambda) and V'(lambda)
 *   radiometry/spectrum.h         sampled spectra, Planck's law, luminous efficacy of a spectrum
 *   lights/photometry/photometry.h           photometric files: read (IES LM-63, EULUMDAT), summarise,
 *                                 convert (remap, resample), write
 *   lights/emitters/emitter.h              point, spot, goniometric, area, directional and sky emitters
 *   glare/ugr_table.h             a luminaire's CIE 190 UGR table (19 standard rooms, 5 reflectance sets)
 *   solver/scene/scene.h          a scene from a file or a JSON string
 *   solver/progress.h             progress reports and cancelling of long calls
 *   solver/solution.h             results in memory: E, direct, indirect, stderr per point
 *   solver/solve_options.h        the options of a solve
 *   solver/solve.h                solving a scene
 *   solver/output/solution_write.h  writing a solve's files (CSV, EXR, PNG, summary.json)
 *
 * Why these: they are what a program needs to do what the `candela`
 * command does (units and conversions, spectra, photometric files,
 * emitters, scenes, solving, results, outputs) and each is a stable
 * description of physics or of the scene and output formats. Everything else is
 * machinery that may change without notice and is not installed: every
 * *_internal.h, the readers' lexer and writers' helpers, sampling and the
 * random number generator, geometry (polygons and their CGAL meshing, ray
 * queries, occluders), the thread pool, the direct solver's strategies,
 * the path tracer, the irradiance cache and its file, the output writers'
 * parts, and the bench. Embree, CGAL, OpenColorIO, OpenEXR and cJSON are
 * implementation details: no public header includes them, and a program
 * linking the shared library needs only -lcandela.
 *
 * Conventions every public function follows (its own comment says what is
 * particular to it):
 *  - Units: SI and CIE units, named in the type (units.h) or in the name
 *    of the parameter or field (`_deg`, `_m`, `_lx`, `_cd_m2`); positions
 *    in metres in a right-handed world frame with z up; angles in degrees
 *    unless a name says radians.
 *  - Ownership: an object a call creates (`cdl_*_create`, `_read_*`,
 *    `_load`, `cdl_solve_scene`) belongs to the caller, who frees it with
 *    the matching `_release` (which accepts NULL). Pointers handed in are
 *    borrowed for the duration of the call unless the comment says
 *    otherwise. Strings and arrays returned by queries belong to the object
 *    queried and live as long as it does; `const char *` names of enum
 *    values are static.
 *  - Thread safety: there is no global mutable state. Functions that only
 *    read their arguments may be called from any number of threads at once
 *    (finished objects are immutable); a call that modifies or releases an
 *    object must not run concurrently with other calls on that object.
 *    Calls that use threads themselves (cdl_solve_scene) say so.
 *  - Errors: a fallible call returns a cdl_status (CDL_OK on success) and
 *    fills the caller's cdl_error (which may be NULL) with a message that
 *    names the input and what was expected; outputs are left untouched or
 *    NULL on failure. Library code never prints and never exits.
 *
 * Versions. CDL_VERSION_MAJOR, _MINOR and _PATCH are the release this
 * header belongs to, at compile time; cdl_version() is the release of the
 * library a program runs with ("0.1.0", what `candela --version` prints).
 * cdl_abi_version() is the ABI version, the number in the shared library's
 * SONAME (libcandela.so.N): it moves whenever a public type's definition
 * changes or a public function is removed or changes its signature, so a
 * program is never loaded with a libcandela whose structs differ from
 * those it was compiled with (Candela's build keeps the history of the
 * public types' fingerprint and its tests fail when they change under a
 * recorded version). Public structs that may grow begin with their own
 * `size` (set it with the struct's INIT macro): the library reads and
 * writes only the fields a caller's struct has.
 *
 * From C++, include this header (not the individual ones): it gives every
 * declaration C linkage.
 */
#ifndef CANDELA_CANDELA_H
#define CANDELA_CANDELA_H

/* The release of these headers (CMakeLists.txt reads the project's version
 * from here: this is its one source). */
#define CDL_VERSION_MAJOR 0
#define CDL_VERSION_MINOR 1
#define CDL_VERSION_PATCH 0

#ifdef __cplusplus
/* The system headers the public headers use, outside the extern "C" block. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {
#endif

#include "base/error.h"
#include "radiometry/units.h"
#include "radiometry/constants.h"
#include "radiometry/conversions.h"
#include "radiometry/quantity.h"
#include "radiometry/vec3.h"
#include "radiometry/cie_tables.h"
#include "radiometry/spectrum.h"
#include "lights/photometry/photometry.h"
#include "lights/emitters/emitter.h"
#include "glare/ugr_table.h"
#include "solver/scene/scene.h"
#include "solver/progress.h"
#include "solver/solution.h"
#include "solver/solve_options.h"
#include "solver/solve.h"
#include "solver/output/solution_write.h"

/* The release of the library, "MAJOR.MINOR.PATCH", the same string
 * `candela --version` prints. Static storage; thread-safe; never fails. */
const char *cdl_version(void);

/* The ABI version of the library, the N of its SONAME libcandela.so.N.
 * Thread-safe; never fails. */
int cdl_abi_version(void);

#ifdef __cplusplus
}
#endif

#endif
