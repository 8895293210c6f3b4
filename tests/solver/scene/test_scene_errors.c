/* Every class of bad scene is refused with CDL_ERR_INPUT and a message
 * "office.json: <JSON path>: expected <what>, found <what>" (or, for JSON
 * syntax, "office.json:LINE:COLUMN: invalid JSON ..."). Each case checks
 * the path and the expectation the message must contain. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "solver/scene/scene_internal.h"

#define DATA CANDELA_SOURCE_DIR "/tests/data/scene/"

/* Pieces that make the rest of a scene valid. */
#define GRID "{\"name\": \"g\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]}"
#define GRIDS "\"grids\": [" GRID "]"
#define RECT "\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0]"
#define SURFACE(body) "{\"version\": 1, \"surfaces\": [{" body "}], " GRIDS "}"
#define LUMINAIRE(body) "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,1], " \
                        "\"intensity_cd\": 1}, {" body "}], " GRIDS "}"
#define GRID_CASE(body) "{\"version\": 1, \"grids\": [" GRID ", {" body "}]}"
#define SQUARE "[[0,0,0],[4,0,0],[4,4,0],[0,4,0]]"

typedef struct error_case {
    const char *json;
    const char *fragment;   /* must appear in the message, after "office.json: " */
} error_case;

static const error_case cases[] = {
    /* structure */
    {"[1, 2]", "office.json: expected a scene (a JSON object), found an array of 2 items"},
    {"{\"version\": 1, \"versio\": 1, " GRIDS "}", "office.json: versio: expected a key of a scene"},
    {"{\"version\": 2, " GRIDS "}", "office.json: version: expected the scene format version 1, found the number 2"},
    {"{" GRIDS "}", "office.json: version: expected the scene format version 1, found nothing"},
    {"{\"version\": 1}", "office.json: grids: expected a list of at least one calculation grid, found nothing"},
    {"{\"version\": 1, \"grids\": []}", "office.json: grids: expected a list of at least one calculation grid"},
    {"{\"version\": 1, \"surfaces\": {}, " GRIDS "}", "office.json: surfaces: expected a list of surfaces, found an object"},
    /* unknown and duplicate keys */
    {SURFACE(RECT ", \"reflectance\": 0.5, \"colour\": 1"), "office.json: surfaces[0].colour: expected a key of a rect surface"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"u\": [0,0,1]"), "office.json: surfaces[0].u: expected each key once, found \"u\" a second time"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"inward\": true"), "surfaces[0].inward: expected a key of a rect surface"},
    {SURFACE("\"type\": \"cone\""), "surfaces[0].type: expected one of the strings \"rect\""},
    {SURFACE("\"u\": [1,0,0]"), "surfaces[0].type: expected one of the strings \"rect\", \"polygon\", \"box\", \"disk\", \"sphere\", \"mesh\", found nothing"},
    /* wrong types and missing values */
    {SURFACE(RECT), "surfaces[0].reflectance: expected a number in [0, 1], found nothing (the key is missing)"},
    {SURFACE("\"type\": \"rect\", \"origin\": \"here\", \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].origin: expected an array of 3 numbers, found the string \"here\""},
    {SURFACE("\"type\": \"rect\", \"origin\": [0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].origin: expected an array of 3 numbers, found an array of 2 items"},
    {SURFACE("\"type\": \"rect\", \"origin\": [0,null,0], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].origin[1]: expected a finite number of magnitude at most 1e+12, found null"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"two_sided\": \"yes\""), "surfaces[0].two_sided: expected true or false"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"name\": 3"), "surfaces[0].name: expected a non-empty string, found the number 3"},
    /* non-finite numbers (JSON has no NaN; 1e999 overflows to infinity) */
    {SURFACE(RECT ", \"reflectance\": 1e999"), "surfaces[0].reflectance: expected a number in [0, 1], found a number too large for a double (+inf)"},
    {SURFACE("\"type\": \"rect\", \"origin\": [0,0,-1e999], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].origin[2]: expected a finite number of magnitude at most 1e+12, found a number too large for a double (-inf)"},
    /* magnitudes beyond any scene */
    {SURFACE("\"type\": \"rect\", \"origin\": [0,0,2e12], \"u\": [1,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].origin[2]: expected a finite number of magnitude at most 1e+12, found the number 2e+12"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1e300"),
     "luminaires[1].intensity_cd: expected a number >= 0 of magnitude at most 1e+12, found the number 1e+300"},
    /* reflectance and luminance ranges */
    {SURFACE(RECT ", \"reflectance\": 1.5"), "surfaces[0].reflectance: expected a number in [0, 1], found the number 1.5"},
    {SURFACE(RECT ", \"reflectance\": -0.1"), "surfaces[0].reflectance: expected a number in [0, 1], found the number -0.1"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"luminance_cd_m2\": -3"), "surfaces[0].luminance_cd_m2: expected a number >= 0"},
    /* zero-length and parallel vectors */
    {SURFACE("\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [0,0,0], \"v\": [0,1,0], \"reflectance\": 0"),
     "surfaces[0].u: expected a non-zero vector of 3 numbers, found the zero vector"},
    {SURFACE("\"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [-2,0,0], \"reflectance\": 0"),
     "surfaces[0].v: expected a vector not parallel to u"},
    {SURFACE("\"type\": \"disk\", \"center\": [0,0,0], \"normal\": [0,0,0], \"radius\": 1, \"reflectance\": 0"),
     "surfaces[0].normal: expected a non-zero vector of 3 numbers, found the zero vector"},
    {SURFACE("\"type\": \"disk\", \"center\": [0,0,0], \"normal\": [0,0,1], \"radius\": 0, \"reflectance\": 0"),
     "surfaces[0].radius: expected a number > 0, found the number 0"},
    {SURFACE("\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": -1, \"reflectance\": 0"),
     "surfaces[0].radius: expected a number > 0, found the number -1"},
    /* polygons */
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[1,1,1],[2,2,2],[3,3,3]], \"reflectance\": 0"),
     "surfaces[0].vertices: expected a polygon with an area, found points that all lie on one line"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[1,0,0]], \"reflectance\": 0"),
     "surfaces[0].vertices: expected a list of at least 3 points"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,4,0],[2,5,0.5],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[3]: expected a point in the plane of the polygon's outer ring"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,4,0],[2,-1,0],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[0]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at surfaces[0].vertices[3]"},
    /* A bow tie whose lobes cancel has no net area, but it is not a line:
     * the message names the crossing edges, not "points on one line". */
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[0,4,0],[4,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[1]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at surfaces[0].vertices[3]"},
    /* The same bow tie tilted out of the axes planes, as a grid. */
    {GRID_CASE("\"name\": \"bow\", \"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,3],[0,4,0],[4,4,3]]"),
     "grids[1].vertices[1]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at grids[1].vertices[3]"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,0,0],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[2]: expected a point different from the one before it"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[2,0,0],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[1]: expected a vertex where the outline turns"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[5,5,0],[6,5,0],[6,6,0]]], \"reflectance\": 0"),
     "surfaces[0].holes[0]: expected a hole inside the outer ring, found one outside it"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[1,1,0],[5,1,0],[1,2,0]]], \"reflectance\": 0"),
     "surfaces[0].vertices[1]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at surfaces[0].holes[0][0]"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[1,1,0],[3,1,0],[3,3,0],[1,3,0]], [[1.5,1.5,0],[2,1.5,0],[2,2,0]]], \"reflectance\": 0"),
     "surfaces[0].holes[1]: expected holes that do not lie inside each other, found one inside surfaces[0].holes[0]"},
    /* Features below 1e-9 of the polygon's size: artefacts that meshing would grade down to. */
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,1e-12,0],[4,4,0],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[2]: expected a point different from the one before it (farther than 1e-9 of the polygon's size), found one 1e-12 m from it"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[1,1e-300,0],[2,1,0],[1,1,0]]], \"reflectance\": 0"),
     "surfaces[0].vertices[0]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at surfaces[0].holes[0][0]"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,4,0],[2.0000000001,4,0],[2,0.5,0],[1.9999999999,4,0],[0,4,0]], \"reflectance\": 0"),
     "surfaces[0].vertices[4]: expected a vertex where the outline turns, found one that folds the outline back onto an edge (or makes a spike thinner"},
    {SURFACE("\"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[1,1,0],[2,1,0],[2,2,1]]], \"reflectance\": 0"),
     "surfaces[0].holes[0][2]: expected a point in the plane of the polygon's outer ring, found one 1 m away"},
    /* boxes */
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,0,3], \"reflectance\": 0.5"),
     "surfaces[0].max: expected every coordinate greater than min's"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"floor\": 0.2, \"walls\": 1.2, \"ceiling\": 0.7}"),
     "surfaces[0].reflectance.walls: expected a number in [0, 1], found the number 1.2"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"floor\": 0.2, \"walls\": 0.5}"),
     "surfaces[0].reflectance.ceiling: expected a number in [0, 1], found nothing"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"floor\": 0.2, \"-x\": 0.5}"),
     "surfaces[0].reflectance.-x: expected one naming per box (floor, walls, ceiling)"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"roof\": 0.2}"),
     "surfaces[0].reflectance.roof: expected a face name"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": 0.5, \"open\": [\"roof\"]"),
     "surfaces[0].open[0]: expected a face name (-x, +x, -y, +y, -z, +z, floor, walls, ceiling), found the string \"roof\""},
    /* open names faces, by either naming: the room's window wall with its reflectances by floor, walls,
     * ceiling; a closed wall's number is still needed */
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"floor\": 0.2, \"ceiling\": 0.7}, \"open\": [\"-y\"]"),
     "surfaces[0].reflectance.walls: expected a number in [0, 1], found nothing"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": 0.5, \"open\": [\"walls\", \"floor\", \"ceiling\"]"),
     "surfaces[0].open: expected at least one face left closed"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"-x\": 0.1, \"+x\": 0.1, \"-y\": 0.1, \"+y\": 0.1, \"-z\": 0.1}"),
     "surfaces[0].reflectance.+z: expected a number in [0, 1], found nothing"},
    {SURFACE("\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": \"white\""),
     "surfaces[0].reflectance: expected a number in [0, 1] or an object of per-face numbers"},
    /* meshes */
    {SURFACE("\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"triangles\": [[0,1,3]], \"reflectance\": 0"),
     "surfaces[0].triangles[0][2]: expected an integer in [0, 2], found the number 3"},
    {SURFACE("\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,0],[2,0,0]], \"triangles\": [[0,1,2]], \"reflectance\": 0"),
     "surfaces[0].triangles[0]: expected a triangle with an area, found three points on one line"},
    {SURFACE("\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"triangles\": [[0,1]], \"reflectance\": 0"),
     "surfaces[0].triangles[0]: expected a triangle [i, j, k] of 3 vertex indices, found an array of 2 items"},
    {SURFACE("\"type\": \"mesh\", \"file\": \"cube.obj\", \"vertices\": [[0,0,0]], \"reflectance\": 0"),
     "surfaces[0].file: expected either a file or inline vertices and triangles"},
    {SURFACE("\"type\": \"mesh\", \"reflectance\": 0"),
     "surfaces[0]: expected a mesh \"file\" or \"vertices\" and \"triangles\", found neither"},
    {SURFACE("\"type\": \"mesh\", \"file\": \"missing.obj\", \"reflectance\": 0"),
     "surfaces[0].file: " CANDELA_SOURCE_DIR "/tests/data/scene/missing.obj: cannot open the mesh file"},
    {SURFACE("\"type\": \"mesh\", \"file\": \"broken.obj\", \"reflectance\": 0"),
     "surfaces[0].file: " CANDELA_SOURCE_DIR "/tests/data/scene/broken.obj:5: expected vertex indices up to the number of vertices"},
    {SURFACE("\"type\": \"mesh\", \"file\": \"design_example.json\", \"reflectance\": 0"),
     "surfaces[0].file: " CANDELA_SOURCE_DIR "/tests/data/scene/design_example.json: expected a mesh file ending in .obj, .off or .ply"},
    /* luminaires: intensities, fluxes, angles */
    {LUMINAIRE("\"type\": \"point\", \"position\": \"up\", \"intensity_cd\": 100"),
     "office.json: luminaires[1].position: expected an array of 3 numbers, found the string \"up\""},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": -100"),
     "luminaires[1].intensity_cd: expected a number >= 0, found the number -100"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"flux_lm\": -1"), "luminaires[1].flux_lm: expected a number >= 0"},
    /* values typed with a unit: the unit must exist and fit the field */
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": \"25 W\""),
     "office.json: luminaires[1].intensity_cd: '25 W' is a power; expected a luminous intensity (cd, kcd)"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"flux_lm\": \"500 lx\""),
     "luminaires[1].flux_lm: '500 lx' is an illuminance; expected a luminous flux"},
    {LUMINAIRE("\"type\": \"directional\", \"direction\": [0,0,-1], \"illuminance_lx\": \"3000 lm\""),
     "luminaires[1].illuminance_lx: '3000 lm' is a luminous flux; expected an illuminance (lx, fc, lm/m2)"},
    {LUMINAIRE("\"type\": \"directional\", \"direction\": [0,0,-1], \"illuminance_lx\": \"500 lux2\""),
     "luminaires[1].illuminance_lx: '500 lux2': unknown unit 'lux2'; expected a unit of illuminance"},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": \"1200\""),
     "luminaires[1].luminance_cd_m2: '1200': missing unit; expected a unit of luminance (cd/m2, nit, fL)"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": \"-5 cd\""),
     "luminaires[1].intensity_cd: expected a number >= 0, found the string \"-5 cd\""},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": \"2e9 kcd\""),
     "luminaires[1].intensity_cd: expected a number >= 0 of magnitude at most 1e+12, found the string \"2e9 kcd\""},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"luminance_cd_m2\": \"2 cd\""),
     "surfaces[0].luminance_cd_m2: '2 cd' is a luminous intensity; expected a luminance"},
    /* dimensionless values take no unit */
    {SURFACE(RECT ", \"reflectance\": \"0.5 lx\""),
     "surfaces[0].reflectance: expected a number in [0, 1], found the string \"0.5 lx\""},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1, \"flux_lm\": 1"),
     "luminaires[1].flux_lm: expected either \"intensity_cd\" or \"flux_lm\", found both"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1]"),
     "luminaires[1]: expected exactly one of \"intensity_cd\" and \"flux_lm\", found neither"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1, \"direction\": [0,0,1]"),
     "luminaires[1].direction: expected a key of a point luminaire"},
    {LUMINAIRE("\"type\": \"laser\""), "luminaires[1].type: expected one of the strings \"point\""},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1"),
     "luminaires[1].half_angle: expected a half angle in (0, 180] degrees (or \"exponent\" instead), found nothing"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"half_angle\": 190"),
     "luminaires[1].half_angle: expected a half angle in (0, 180] degrees"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"half_angle\": 0"),
     "luminaires[1].half_angle: expected a half angle in (0, 180] degrees"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"half_angle\": 30, \"falloff_start\": 35"),
     "luminaires[1].falloff_start: expected an angle in [0, half_angle = 30] degrees, found the number 35"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"half_angle\": 30, \"falloff_start\": -1"),
     "luminaires[1].falloff_start: expected an angle in [0, half_angle = 30] degrees"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"exponent\": 2, \"half_angle\": 30"),
     "luminaires[1].half_angle: expected no beam edge on a cos^n spot"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,-1], \"intensity_cd\": 1, \"exponent\": -2"),
     "luminaires[1].exponent: expected a number >= 0"},
    {LUMINAIRE("\"type\": \"spot\", \"position\": [0,0,1], \"direction\": [0,0,0], \"intensity_cd\": 1, \"exponent\": 2"),
     "luminaires[1].direction: expected a non-zero vector of 3 numbers, found the zero vector"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1, \"maintenance_factor\": 0"),
     "luminaires[1].maintenance_factor: expected a number in (0, 1], found the number 0"},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1, \"maintenance_factor\": 1.2"),
     "luminaires[1].maintenance_factor: expected a number in (0, 1]"},
    /* goniometric */
    {LUMINAIRE("\"type\": \"goniometric\", \"position\": [0,0,1]"),
     "luminaires[1].file: expected a non-empty string, found nothing"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\""),
     "luminaires[1].position: expected an array of 3 numbers, found nothing"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"rotation\": [0,0]"),
     "luminaires[1].rotation: expected an array of 3 numbers"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"multiplier\": -1"),
     "luminaires[1].multiplier: expected a number >= 0"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"flux_lm\": 0"),
     "luminaires[1].flux_lm: expected a number > 0"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"body\": 1"),
     "luminaires[1].body: expected true, false or an object {\"reflectance\": R}, found the number 1"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"body\": {\"reflectance\": 1.5}"),
     "luminaires[1].body.reflectance: expected a number in [0, 1], found the number 1.5"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"body\": {\"colour\": 1}"),
     "luminaires[1].body.colour: expected a key of a luminaire body"},
    {LUMINAIRE("\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,1], \"body\": {\"reflectance\": \"grey\"}"),
     "luminaires[1].body.reflectance: expected a number in [0, 1], found the string \"grey\""},
    {LUMINAIRE("\"type\": \"point\", \"position\": [0,0,1], \"intensity_cd\": 1, \"body\": false"),
     "luminaires[1].body: expected a key of a point luminaire"},
    /* area */
    {LUMINAIRE("\"type\": \"area\", \"luminance_cd_m2\": 100"),
     "luminaires[1].shape: expected an area luminaire's shape (a JSON object), found nothing"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1}, \"luminance_cd_m2\": 1"),
     "luminaires[1].shape.type: expected one of the strings \"rect\", \"polygon\", \"disk\", \"mesh\", found the string \"sphere\""},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {" RECT ", \"reflectance\": 0.5}, \"luminance_cd_m2\": 1"),
     "luminaires[1].shape.reflectance: expected only geometric keys in a shape (put it on the luminaire)"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {" RECT "}, \"luminance_cd_m2\": -1"),
     "luminaires[1].luminance_cd_m2: expected a number >= 0, found the number -1"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {" RECT "}"),
     "luminaires[1]: expected exactly one of \"luminance_cd_m2\" and \"flux_lm\", found neither"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {" RECT "}, \"flux_lm\": 10, \"reflectance\": 2"),
     "luminaires[1].reflectance: expected a number in [0, 1]"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {\"type\": \"polygon\", \"vertices\": [[0,0,3],[4,0,3],[4,4,3],[2,-1,3],[0,4,3]]}, \"flux_lm\": 10"),
     "luminaires[1].shape.vertices[0]: expected a simple polygon"},
    {LUMINAIRE("\"type\": \"area\", \"shape\": {\"type\": \"disk\", \"center\": [0,0,3], \"normal\": [0,0,0], \"radius\": 1}, \"flux_lm\": 10"),
     "luminaires[1].shape.normal: expected a non-zero vector"},
    /* directional and environment */
    {LUMINAIRE("\"type\": \"directional\", \"direction\": [0,0,0], \"illuminance_lx\": 1"),
     "luminaires[1].direction: expected a non-zero vector of 3 numbers, found the zero vector"},
    {LUMINAIRE("\"type\": \"directional\", \"direction\": [0,0,-1]"),
     "luminaires[1].illuminance_lx: expected a number >= 0, found nothing"},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": 1, \"file\": \"sky.exr\""),
     "luminaires[1].file: expected either \"luminance_cd_m2\" or \"file\", found both"},
    {LUMINAIRE("\"type\": \"environment\""), "luminaires[1]: expected exactly one of \"luminance_cd_m2\" and \"file\""},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": 1, \"hemisphere\": \"lower\""),
     "luminaires[1].hemisphere: expected one of the strings \"full\", \"upper\", found the string \"lower\""},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": 1, \"up\": [0,0,0]"),
     "luminaires[1].up: expected a non-zero vector"},
    {LUMINAIRE("\"type\": \"environment\", \"sky\": \"cie_clear\", \"zenith_luminance_cd_m2\": 1"),
     "luminaires[1].sky: expected one of the strings \"uniform\", \"cie_overcast\", \"cie\", \"perez\", found the "
     "string \"cie_clear\""},
    {LUMINAIRE("\"type\": \"environment\", \"sky\": \"cie_overcast\", \"luminance_cd_m2\": 1"),
     "luminaires[1].luminance_cd_m2: expected no \"luminance_cd_m2\", \"file\", \"scale\" or \"hemisphere\" with "
     "\"sky\": \"cie_overcast\""},
    {LUMINAIRE("\"type\": \"environment\", \"sky\": \"cie_overcast\""),
     "luminaires[1].zenith_luminance_cd_m2: expected"},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": 1, \"zenith_luminance_cd_m2\": 1"),
     "luminaires[1].zenith_luminance_cd_m2: expected \"zenith_luminance_cd_m2\" only with \"sky\": \"cie_overcast\" "
     "or \"cie\""},
    {LUMINAIRE("\"type\": \"environment\", \"luminance_cd_m2\": 1, \"scale\": 2"),
     "luminaires[1].scale: expected \"scale\" only with an image \"file\""},
    {LUMINAIRE("\"type\": \"environment\", \"file\": \"sky.exr\", \"scale\": -2"), "luminaires[1].scale: expected a number >= 0"},
    /* grids */
    {GRID_CASE("\"name\": \"a/b\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]"),
     "grids[1].name: expected a grid name usable as a file name"},
    {GRID_CASE("\"name\": \"..\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]"),
     "grids[1].name: expected a grid name usable as a file name"},
    {GRID_CASE("\"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]"),
     "grids[1].name: expected a grid name usable as a file name (1 to 64 letters, digits, '.', '_', '-', not starting with '.' or '-'), found nothing"},
    {GRID_CASE("\"name\": \"G\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}]"),
     "grids[1].name: expected a grid name not used before (ignoring case), found \"G\", already the name of grids[0]"},
    {GRID_CASE("\"name\": \"r\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 0, \"nv\": 2"),
     "grids[1].nu: expected an integer in [1, 10000000], found the number 0"},
    {GRID_CASE("\"name\": \"r\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 2.5, \"nv\": 2"),
     "grids[1].nu: expected an integer in [1, 10000000], found the number 2.5"},
    {GRID_CASE("\"name\": \"r\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 5000, \"nv\": 5000"),
     "grids[1].nv: expected nu x nv at most 10000000 points"},
    {GRID_CASE("\"name\": \"r\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [0,1,0], \"nu\": 2, \"nv\": 2, \"normal\": [0,0,0]"),
     "grids[1].normal: expected a non-zero vector"},
    {GRID_CASE("\"name\": \"r\", \"type\": \"rect\", \"origin\": [0,0,0], \"u\": [1,0,0], \"v\": [3,0,0], \"nu\": 2, \"nv\": 2"),
     "grids[1].v: expected a vector not parallel to u"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"polygon\", \"vertices\": " SQUARE ", \"spacing\": -1"),
     "grids[1].spacing: expected a spacing in metres > 0 or \"auto\", found the number -1"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"polygon\", \"vertices\": " SQUARE ", \"spacing\": \"fine\""),
     "grids[1].spacing: expected a spacing in metres > 0 or \"auto\", found the string \"fine\""},
    {GRID_CASE("\"name\": \"p\", \"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[3,1,0],[5,1,0],[5,2,0]]]"),
     "grids[1].vertices[1]: expected a simple polygon (no two edges cross, touch or come within 1e-9 of its size), found the edge starting here meets the edge starting at grids[1].holes[0][0]"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"polygon\", \"vertices\": " SQUARE ", \"holes\": [[[6,6,0],[7,6,0],[7,7,0]]]"),
     "grids[1].holes[0]: expected a hole inside the outer ring"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,0]}]"),
     "grids[1].points[0].n: expected a non-zero vector of 3 numbers, found the zero vector"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0]}]"),
     "grids[1].points[0].n: expected a non-zero vector of 3 numbers, found nothing"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": []"), "grids[1].points: expected a non-empty list of points"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1], \"w\": 1}]"),
     "grids[1].points[0].w: expected a key of a calculation point (p, n)"},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}], \"outputs\": [\"lux\"]"),
     "grids[1].outputs[0]: expected one of the strings \"ao\", \"cylindrical\", \"semicylindrical\", \"luminance\", "
     "\"daylight_factor\", found the string \"lux\""},
    {GRID_CASE("\"name\": \"p\", \"type\": \"points\", \"points\": [{\"p\": [0,0,0], \"n\": [0,0,1]}], \"spacing\": 1"),
     "grids[1].spacing: expected a key of a points grid (name, type, points, outputs, requirements)"},
    /* solver */
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"method\": \"fast\"}}",
     "solver.method: expected one of the strings \"auto\", \"direct\", \"icache\", \"pathtrace\", found the string \"fast\""},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"quality\": 3}}", "solver.quality: expected one of the strings \"draft\""},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"direct_samples\": 0}}", "solver.direct_samples: expected an integer in [1, 16777216]"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"ao_samples\": 1.5}}", "solver.ao_samples: expected an integer in [1, 16777216]"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"bounces\": -1}}", "solver.bounces: expected \"auto\" or a whole number of reflections in [0, 10000], found the number -1"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"bounces\": \"many\"}}", "solver.bounces: expected \"auto\" or a whole number"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"target_error\": 0}}", "solver.target_error: expected a relative standard error per point as a fraction in [1e-05, 0.5]"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"target_error\": \"1 %\"}}", "solver.target_error: expected a relative standard error"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"seed\": -1}}", "solver.seed: expected an integer in [0, 9007199254740992]"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"threads\": 1e999}}", "solver.threads: expected an integer in [0, 4096], found a number too large"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"sampels\": 4}}", "solver.sampels: expected a key of the solver settings"},
    /* surface maps */
    {"{\"version\": 1, \"surfaces\": [{" RECT ", \"reflectance\": 0.5, \"name\": \"wall\"}], " GRIDS
     ", \"solver\": {\"surface_maps\": [\"wal\"]}}",
     "solver.surface_maps[0]: expected the name of a surface in \"surfaces\", found \"wal\", which no surface has"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"surface_maps\": \"some\"}}",
     "solver.surface_maps: expected \"all\", \"none\" or a list of surface names, found the string \"some\""},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"surface_maps\": true}}",
     "solver.surface_maps: expected \"all\", \"none\" or a list of surface names, found true"},
    {"{\"version\": 1, " GRIDS ", \"solver\": {\"surface_maps\": [3]}}",
     "solver.surface_maps[0]: expected a surface name, found the number 3"},
    {"{\"version\": 1, \"surfaces\": [{" RECT ", \"reflectance\": 0.5, \"name\": \"wall\"}], " GRIDS
     ", \"solver\": {\"surface_maps\": [\"wall\", \"wall\"]}}",
     "solver.surface_maps[1]: expected each surface named once"},
    {"{\"version\": 1, \"surfaces\": [{" RECT ", \"reflectance\": 0.5, \"name\": \"east wall\"}], " GRIDS
     ", \"solver\": {\"surface_maps\": \"all\"}}",
     "surfaces[0].name: expected the name of a mapped surface usable as a file name"},
    {"{\"version\": 1, \"surfaces\": [{" RECT ", \"reflectance\": 0.5, \"name\": \"Wall\"}, {" RECT
     ", \"reflectance\": 0.5, \"name\": \"wall\"}], " GRIDS ", \"solver\": {\"surface_maps\": \"all\"}}",
     "surfaces[1].name: expected a mapped surface's name not used by another (ignoring case), found \"wall\", "
     "already surfaces[0]'s"},
    {"{\"version\": 1, \"surfaces\": [{" RECT ", \"reflectance\": 0.5, \"name\": \"surface_1\"}, {" RECT
     ", \"reflectance\": 0.5}], " GRIDS ", \"solver\": {\"surface_maps\": \"all\"}}",
     "surfaces[1].type: expected a mapped surface's name not used by another (ignoring case), found \"surface_1\""},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"requirements\": {\"U0\": 2}"),
     "surfaces[0].requirements.U0: expected a number in (0, 1]"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"requirements\": {}"),
     "surfaces[0].requirements: expected at least one of Em_lx and U0"},
    {SURFACE(RECT ", \"reflectance\": 0.5, \"requirements\": {\"UGR\": 19}"),
     "surfaces[0].requirements.UGR: expected a key of requirements"},
    {LUMINAIRE("\"type\": \"area\", \"luminance_cd_m2\": 1, \"shape\": {" RECT ", \"requirements\": {\"U0\": 0.1}}"),
     "luminaires[1].shape.requirements: expected only geometric keys in a shape"},
};

static void check_case(const error_case *c, size_t index)
{
    cdl_error err;
    cdl_scene *s = NULL;
    cdl_error_clear(&err);
    cdl_status st = cdl_scene_load_string(c->json, DATA "office.json", &s, &err);
    CHECK_MSG(st == CDL_ERR_INPUT && s == NULL, "case %zu: status %d for %s", index, (int)st, c->json);
    /* The message starts with the scene file and contains path and expectation. */
    CHECK_MSG(strncmp(err.message, DATA "office.json", strlen(DATA "office.json")) == 0, "case %zu: %s", index,
              err.message);
    CHECK_MSG(strstr(err.message, c->fragment) != NULL, "case %zu:\n  message  %s\n  expected %s", index, err.message,
              c->fragment);
    cdl_scene_release(s);
}

/* JSON syntax errors give line and column. */
static void check_syntax(const char *json, const char *fragment)
{
    cdl_error err;
    cdl_scene *s = NULL;
    cdl_error_clear(&err);
    CHECK(cdl_scene_load_string(json, "office.json", &s, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "message \"%s\" lacks \"%s\"", err.message, fragment);
}

int main(void)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) check_case(&cases[i], i);

    check_syntax("{\n  \"version\": 1,\n  \"grids\": [1 2]\n}", "office.json:3:15: invalid JSON: expected a well-formed JSON document, found a syntax error at or before \"2]\"");
    /* cJSON stops at or after the error: here at the end of the text. */
    check_syntax("{\"version\": 1,}", "office.json:1:16: invalid JSON: expected a well-formed JSON document, found a "
                                      "syntax error at or before the end of the file");
    check_syntax("", "office.json:1:1: invalid JSON");
    check_syntax("{\"version\": NaN}", "office.json:1:13: invalid JSON");
    check_syntax("{\"version\": 1} extra", "office.json:1:16: invalid JSON");

    /* A file that is not a scene: NUL byte, missing file, a directory. */
    cdl_error err;
    cdl_scene *s = NULL;
    const char *path = CANDELA_TEST_TMPDIR "/test_scene_errors_nul.json";
    FILE *fp = fopen(path, "wb");
    CHECK(fp != NULL);
    if (fp) {
        fwrite("{\n \"version\"\0: 1}", 1, 17, fp);
        fclose(fp);
        CHECK(cdl_scene_load(path, &s, &err) == CDL_ERR_INPUT);
        CHECK_MSG(strstr(err.message, "test_scene_errors_nul.json:2:11: invalid JSON: expected text, found a NUL byte"),
                  "%s", err.message);
        remove(path);
    }
    CHECK(cdl_scene_load(DATA "no_such_scene.json", &s, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "no_such_scene.json: cannot open the scene file") != NULL);
    CHECK(cdl_scene_load(DATA, &s, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "expected a scene file, found a directory") != NULL);
    return check_finish();
}
