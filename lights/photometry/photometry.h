/* photometry.h - one photometric model for IES LM-63 and EULUMDAT data.
 *
 * A cdl_photometry holds a luminaire's measured intensity distribution in
 * absolute candela (the file's candela multiplier / conversion factor and,
 * for relative EULUMDAT data, the lamp flux already applied), its angle grid
 * and symmetry, lamp data, luminous opening, keywords, and tilt data.
 *
 * Coordinate convention (the "photometric frame"), used by every function
 * that takes a direction: right-handed, nadir (gamma = 0, type C) along -z,
 * the C = 0 half-plane containing +x, C = 90 containing +y, so that
 *     direction = (sin g cos C, sin g sin C, -cos g).
 * C therefore runs counter-clockwise seen from above (from +z).
 *
 * How the file formats land in this frame (decided once, used everywhere):
 *
 *  - EULUMDAT C-planes and gamma are the frame's C and gamma, unchanged.
 *  - IES type C: vertical angle V is gamma; horizontal angle H is measured
 *    counter-clockwise seen from BELOW the luminaire (clockwise from above),
 *    so the frame plane is  C = (360 - H) mod 360.  This is what real
 *    converters do (FORMAT_NOTES section 3: the IES H90 plane holds the
 *    EULUMDAT C270 data), so an IES file and its EULUMDAT conversion light a
 *    scene alike. Radiance's ies2rad reads 90-270 tables the same way but a
 *    full 0-360 table with H counter-clockwise from above (H90 towards +y):
 *    compared with Radiance such a table appears mirrored in y (measured:
 *    the mirrored results agree to 1e-4). For symmetric tables (single
 *    plane, 0-90, 0-180) the mirror changes nothing; it matters for 0-360
 *    and 90-270 data.
 *  - IES type B (floodlights): photometric zero (H = 0, V = 0) points along
 *    -z; the polar axis is the y axis; V rotates the measuring plane about y
 *    toward +x, H is the lateral angle inside the plane, positive toward -y:
 *        direction = (sin V cos H, -sin H, -cos V cos H),
 *    dOmega = cos H dH dV (Radiance source.cal srcB_vert / srcB_horiz).
 *  - IES type A (automotive): photometric zero along -z; the polar axis is
 *    the x axis; H turns the measuring half-plane about x (positive toward
 *    -y), V is the latitude inside it (positive toward +x):
 *        direction = (sin V, -cos V sin H, -cos V cos H),
 *    dOmega = cos V dV dH. Near the beam axis types A and B agree: H is the
 *    lateral (left-right) angle and V the elevation.
 *  - Type A/B sets whose H (or V) list runs 0..90 are mirrored (H -> -H,
 *    V -> -V), as LM-63-2002 describes for laterally symmetric luminaires.
 *
 * Interpolation is bilinear in the table's two angles (C and gamma for type
 * C, H and V for types A and B), with symmetry expansion and wrap-around at
 * C = 360; the intensity is zero outside the measured angle ranges. Every
 * flux below is the exact integral of that interpolated distribution.
 *
 * Application factors are NOT in the table: ballast factor, tilt factor,
 * maintenance factor and scene multipliers are applied by the emitter at
 * render time (see cdl_photometry_output_factor and cdl_photometry_tilt_factor).
 *
 * Thread-safety: a finished cdl_photometry is immutable; every query is
 * thread-safe. Releasing one must not overlap other calls on it.
 *
 * Units: candela, lumen, degrees (angles), metres (luminous opening),
 * watts; factors dimensionless. Ownership: a cdl_photometry made by
 * cdl_photometry_read_*, _create*, _remap_c or _resample_type_c belongs to
 * the caller, who frees it with cdl_photometry_release (NULL is fine).
 * Pointers a query returns (metadata, table arrays, keywords, warnings)
 * point into the photometry and live as long as it does. Text from
 * cdl_photometry_format_* is malloc'd: the caller frees it with free();
 * notes are freed with cdl_photometry_notes_free. Inputs are copied.
 * Errors: CDL_ERR_INPUT names the file and line ("FILE:LINE: expected ...,
 * found ...") or the bad argument; CDL_ERR_INTERNAL for memory and I/O.
 * On failure *out is NULL.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_H
#define CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_H

#include <stddef.h>

#include "base/error.h"
#include "radiometry/units.h"
#include "radiometry/vec3.h"

typedef enum cdl_photometric_type {
    CDL_PHOTOMETRIC_TYPE_C = 1, /* polar axis vertical (LM-63 code 1, EULUMDAT) */
    CDL_PHOTOMETRIC_TYPE_B = 2, /* polar axis horizontal, floodlights (code 2) */
    CDL_PHOTOMETRIC_TYPE_A = 3  /* automotive (code 3) */
} cdl_photometric_type;

/* Symmetry of the stored table. The first five apply to type C (stored
 * C range in brackets, in the photometric frame), the last three to types A/B. */
typedef enum cdl_photometry_symmetry {
    CDL_PHOTOMETRY_SYMMETRY_NONE = 0,          /* C: full circle; A/B: H and V as given */
    CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL,        /* C: one plane, I independent of C */
    CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180, /* C: [0, 180], I(C) = I(360 - C) */
    CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270,/* C: [90, 270], I(C) = I(180 - C) */
    CDL_PHOTOMETRY_SYMMETRY_QUADRANT,          /* C: [0, 90], both mirrors */
    CDL_PHOTOMETRY_SYMMETRY_LATERAL,           /* A/B: H stored 0..90, I(-H) = I(H) */
    CDL_PHOTOMETRY_SYMMETRY_VERTICAL,          /* A/B: V stored 0..90, I(-V) = I(V) */
    CDL_PHOTOMETRY_SYMMETRY_LATERAL_VERTICAL   /* A/B: both */
} cdl_photometry_symmetry;

/* A short stable name ("none", "rotational", "bilateral-c0-c180", ...). */
const char *cdl_photometry_symmetry_name(cdl_photometry_symmetry symmetry);

typedef struct cdl_photometry cdl_photometry;

/* How a file is read. Start from CDL_PHOTOMETRY_READ_OPTIONS_INIT (it sets
 * `size`, so that fields added later keep their defaults for a program
 * built before them). */
typedef struct cdl_photometry_read_options {
    size_t size;             /* sizeof(cdl_photometry_read_options) */
    int strict;              /* 1: warnings become errors */
    int no_external_files;   /* 1: refuse TILT=<file> instead of opening it (fuzzing, sandboxes) */
} cdl_photometry_read_options;
#define CDL_PHOTOMETRY_READ_OPTIONS_INIT {.size = sizeof(cdl_photometry_read_options), .strict = 0, .no_external_files = 0}

/* Read an IES (any LM-63 version) or EULUMDAT file; the format is detected
 * from the content, not the extension. Errors: CDL_ERR_INPUT with
 * "FILE:LINE: expected ..., found ...". */
cdl_status cdl_photometry_read_file(const char *path, const cdl_photometry_read_options *options,
                                    cdl_photometry **out, cdl_error *err);

/* Same, from bytes in memory. `name` is used in messages and, for
 * TILT=<file>, as the path the tilt file is resolved against (may be NULL:
 * messages say "<memory>" and TILT=<file> is refused). */
cdl_status cdl_photometry_read_memory(const void *data, size_t size, const char *name,
                                      const cdl_photometry_read_options *options, cdl_photometry **out,
                                      cdl_error *err);

/* Build a type C table from arrays (used by tests and by programs that make
 * distributions): planes c_deg[nc] (ascending, within [0, 360]), angles
 * gamma_deg[ng] (ascending, within [0, 180]), candela[nc * ng] with plane
 * index outermost. Symmetry is inferred from the C range exactly as for IES
 * horizontal angles (single plane: rotational; 0..90: quadrant; 0..180:
 * bilateral; 90..270: bilateral about 90-270; otherwise full). */
cdl_status cdl_photometry_create_type_c(const double *c_deg, size_t nc, const double *gamma_deg, size_t ng,
                                        const double *candela, cdl_photometry **out, cdl_error *err);

/* Build a table of any photometric type. For type C, h_deg are frame C
 * planes and v_deg gamma angles (as cdl_photometry_create_type_c); for types
 * A and B, h_deg are the horizontal angles H and v_deg the vertical angles V
 * (each within [-90, 90] for the latitude-like angle and [-180, 180] for the
 * other; a list running 0..90 is mirrored). candela[nh * nv], H outermost. */
cdl_status cdl_photometry_create(cdl_photometric_type type, const double *h_deg, size_t nh, const double *v_deg,
                                 size_t nv, const double *candela, cdl_photometry **out, cdl_error *err);

/* Free a photometry (NULL is fine); nothing may use it afterwards. */
void cdl_photometry_release(cdl_photometry *photometry);

/* I(direction) in candela, direction in the photometric frame (need not be
 * unit length), interpolated linearly in C and in gamma (bilinear), with
 * symmetry expansion and wrap-around; zero outside the measured gamma range. */
cdl_luminous_intensity cdl_photometry_intensity(const cdl_photometry *photometry, cdl_vec3 direction);

/* Same, by angles in degrees (type C meaning: C azimuth, gamma from nadir). */
cdl_luminous_intensity cdl_photometry_intensity_c_gamma(const cdl_photometry *photometry, double c_deg,
                                                        double gamma_deg);

/* For a type C table with a single plane (rotational symmetry) and gamma in
 * [0, 180]: I(gamma) in candela, the same value as
 * cdl_photometry_intensity_c_gamma(p, any C, gamma). The direct solver's
 * hot path; the caller checks the table's type and symmetry. */
double cdl_photometry_intensity_one_plane(const cdl_photometry *photometry, double gamma_deg);

/* Total flux: the exact integral of the interpolated distribution over the
 * sphere. A radiometric file (metadata.radiometric: its table is radiant
 * intensity, W/sr) has no lumens: NaN, never its watts as lumens; ask
 * cdl_photometry_radiant_flux, or cdl_photometry_luminous_flux for a status.
 * Application factors (the ballast factor) are not in it: times
 * cdl_photometry_output_factor, it is the luminaire's flux in a scene. */
cdl_luminous_flux cdl_photometry_flux(const cdl_photometry *photometry);

/* The same with a status: CDL_ERR_INPUT (naming the file's unit and the
 * keyword that says so) for a radiometric file; *flux untouched then. */
cdl_status cdl_photometry_luminous_flux(const cdl_photometry *photometry, cdl_luminous_flux *flux, cdl_error *err);

/* Radiant flux in W of a radiometric file: the table's exact integral
 * times its unit (1e-3 for mW/sr). CDL_ERR_INPUT for a photometric file,
 * whose radiant flux needs a spectrum (radiometry/spectrum.h). */
cdl_status cdl_photometry_radiant_flux(const cdl_photometry *photometry, cdl_radiant_flux *flux, cdl_error *err);

/* Flux into the directions whose frame gamma (angle from -z) lies in
 * [gamma_lo_deg, gamma_hi_deg]. Exact for type C tables and for the two
 * hemispheres of every type; for other windows of type A/B tables it is a
 * quadrature (cut at the window's edges and refined to the table's finest
 * spacing) scaled to the hemisphere's exact flux, so never more than it. In the table's unit times
 * sr (the lumens of a photometric file; for a radiometric one the same
 * integral of its W/sr values, which cdl_photometry_summary gives in W). */
cdl_luminous_flux cdl_photometry_zone_flux(const cdl_photometry *photometry, double gamma_lo_deg,
                                           double gamma_hi_deg);

/* The flux within each of n cones about nadir, of half angles
 * half_angle_deg[0 .. n - 1] (ascending, within [0, 90]), into out: as
 * cdl_photometry_zone_flux(photometry, 0, half_angle_deg[k]) each, but a
 * type A/B table's from one quadrature cut at every cone's edge (the CIE
 * flux code's three cones, a UGR table's four). */
void cdl_photometry_cone_fluxes(const cdl_photometry *photometry, const double *half_angle_deg, size_t n,
                                cdl_luminous_flux *out);

/* Largest tabulated intensity. */
cdl_luminous_intensity cdl_photometry_max_intensity(const cdl_photometry *photometry);

/* Render-time output factor from the file: the ballast factor (LM-63
 * record B field 1; 1 for EULUMDAT) times, for LM-63-1995 and older, the
 * ballast-lamp photometric factor. Never the LM-63-2019 file-generation code. */
double cdl_photometry_output_factor(const cdl_photometry *photometry);

/* Tilt multiplier at an installed tilt angle in degrees (linear
 * interpolation in the file's TILT table, clamped at its ends); 1 when the
 * file has TILT=NONE. */
double cdl_photometry_tilt_factor(const cdl_photometry *photometry, double tilt_deg);

/* ---- the stored table ---------------------------------------------------- */

/* A read-only view of the stored (symmetry-reduced) table. For type C,
 * horizontal_deg are frame C planes (see the convention above), vertical_deg
 * gamma; for types A/B, the file's H and V. candela[i * vertical_count + j]. */
typedef struct cdl_photometry_table {
    cdl_photometric_type type;
    cdl_photometry_symmetry symmetry;
    size_t horizontal_count, vertical_count;
    const double *horizontal_deg;
    const double *vertical_deg;
    const double *candela;
} cdl_photometry_table;

/* Fill *table (caller's) with a view of the stored table; its arrays
 * belong to the photometry and live as long as it does. Never fails. */
void cdl_photometry_get_table(const cdl_photometry *photometry, cdl_photometry_table *table);

/* Frame direction of the table's angle pair (h, v) (types A/B/C as above). */
cdl_vec3 cdl_photometry_direction(cdl_photometric_type type, double h_deg, double v_deg);

/* The type C gamma (degrees from the frame's nadir, -z) of a unit vector,
 * accurate everywhere: acos(cos gamma) where it is well conditioned
 * (|cos gamma| < 0.7), asin(sin gamma) near the poles, where acos loses
 * digits. Half the cost of atan2(hypot(x, y), -z), as exact. */
double cdl_photometry_gamma_deg(cdl_vec3 unit);

/* ---- file data ----------------------------------------------------------- */

typedef enum cdl_photometry_format {
    CDL_PHOTOMETRY_FORMAT_TABLE = 0,  /* built in memory (cdl_photometry_create*) */
    CDL_PHOTOMETRY_FORMAT_IES,        /* IES LM-63, any version */
    CDL_PHOTOMETRY_FORMAT_EULUMDAT
} cdl_photometry_format;

/* Shape of the luminous opening. LM-63-2002/2019 Table 1 names, 1995 and
 * 1986 codes mapped onto them; UNKNOWN keeps a code found in no table (the
 * raw numbers stay in cdl_luminous_opening.raw). "Length" lies along the
 * C0-C180 plane (IES photometric horizontal), "width" across it. */
typedef enum cdl_luminous_shape {
    CDL_LUMINOUS_SHAPE_POINT = 0,
    CDL_LUMINOUS_SHAPE_RECTANGLE,
    CDL_LUMINOUS_SHAPE_BOX,                      /* rectangular with luminous sides */
    CDL_LUMINOUS_SHAPE_CIRCLE,                   /* horizontal disk, diameter = width = length */
    CDL_LUMINOUS_SHAPE_ELLIPSE,
    CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER,
    CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER,
    CDL_LUMINOUS_SHAPE_SPHERE,
    CDL_LUMINOUS_SHAPE_ELLIPSOID,
    CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG,  /* axis along the C0-C180 plane */
    CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS, /* axis along the C90-C270 plane */
    CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE,          /* facing the C0 direction */
    CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE,
    CDL_LUMINOUS_SHAPE_UNKNOWN
} cdl_luminous_shape;

/* A short stable name of a shape ("point", "rectangle", "circle", ...);
 * static storage. */
const char *cdl_luminous_shape_name(cdl_luminous_shape shape);

typedef struct cdl_luminous_opening {
    cdl_luminous_shape shape;
    double width_m, length_m, height_m; /* magnitudes in metres (diameter for round shapes) */
    double raw[3];                      /* IES width, length, height as written (file units), else 0 */
    int units_type;                     /* IES units: 1 feet, 2 metres; 0 when not from IES */
    /* A box whose sides are luminous to different heights (EULUMDAT lines
     * 18-21): the luminous height of the sides facing C0, C90, C180 and
     * C270, each from the bottom of the box, which is as tall as the
     * tallest; height_m is then their mean (LM-63's one height). All 0:
     * every side luminous over height_m. */
    double side_height_m[4];
} cdl_luminous_opening;

/* 1 when the opening is flat with a non-zero size (a rectangle, circle or
 * ellipse in the luminaire's x-y plane, or LM-63-2019's vertical circle
 * or ellipse in its y-z plane): what cdl_emitter_create_goniometric_opening
 * spreads light over as a flat opening. */
int cdl_luminous_opening_is_flat(const cdl_luminous_opening *opening);

/* 1 when cdl_emitter_create_goniometric_opening spreads light over the
 * opening: a flat one (cdl_luminous_opening_is_flat), or a luminous solid
 * of non-zero size (a box with luminous sides, vertical cylinder, vertical
 * elliptic cylinder, sphere, ellipsoid, or horizontal cylinder along or
 * across): every shape of LM-63-2019's Table 1 but the point. */
int cdl_luminous_opening_is_spread(const cdl_luminous_opening *opening);

/* The luminous height in metres of a box's side facing C0, C90, C180 or
 * C270 (side 0 to 3; side_height_m, or height_m where the sides do not
 * differ); 0 for another side index. */
double cdl_luminous_opening_box_side_height_m(const cdl_luminous_opening *opening, int side);

/* The opening's largest dimension in metres (its diagonal for rectangles
 * and boxes, the longest axis of round shapes, the diagonal of a
 * cylinder's side view); 0 for a point. Near-field distances are counted
 * in it. */
double cdl_luminous_opening_largest_m(const cdl_luminous_opening *opening);

/* The opening's area projected on a plane normal to `dir` (luminaire frame:
 * x along the length, C0; y along the width, C90; z up; any length > 0),
 * in m^2, every shape of LM-63 Table 1 (half the summed |n.dir| A of a
 * convex body's faces; an ellipsoid's pi sqrt(b^2 c^2 x^2 + a^2 c^2 y^2 +
 * a^2 b^2 z^2)); 0 for points and unknown shapes. */
double cdl_luminous_opening_projected_area(const cdl_luminous_opening *opening, cdl_vec3 dir);

/* Luminance of the luminous opening seen from the direction (c_deg,
 * gamma_deg) of the photometric frame (type C angles, whatever the table's
 * type): average = I / A_projected (the luminance of a source, CIE S 017
 * 17-21-050), the table's intensity over the opening's projected area in
 * that direction. maximum = the greatest luminance over the visible part
 * of the opening in that direction: the near-field model spreads the
 * intensity evenly over the opening (emitter_opening.c), so it equals the
 * average. Both 0 where the opening has no projected area (a point, an
 * unknown shape, a flat opening seen edge-on). Intensities as in the table
 * (cd, multiplier applied). */
void cdl_photometry_opening_luminance(const cdl_photometry *photometry, double c_deg, double gamma_deg,
                                      cdl_luminance *average, cdl_luminance *maximum);

/* ---- the file's header ------------------------------------------------------ */

/* One lamp set. An IES file has one (lamp count x lumens per lamp); an
 * EULUMDAT file has 1..20, the first being the measured equipment and the
 * others alternatives. */
typedef struct cdl_photometry_lamp_set {
    int count;          /* number of lamps (EULUMDAT: negative = absolute photometry) */
    double flux_lm;     /* total rated flux of the set, all lamps; 0 when unknown */
    double watts;       /* input power incl. ballast; 0 when unknown */
    char type[128];     /* lamp type / description ("" when unknown) */
    char colour[64];    /* colour appearance / CCT as written */
    char cri[64];       /* colour rendering group / index as written */
} cdl_photometry_lamp_set;

/* Which format the photometry was read from (CDL_PHOTOMETRY_FORMAT_TABLE
 * when built in memory), and the LM-63 version of an IES file (1986, 1991,
 * 1995, 2002 or 2019; 0 when not IES). */
cdl_photometry_format cdl_photometry_get_format(const cdl_photometry *photometry);
int cdl_photometry_ies_version(const cdl_photometry *photometry);

/* The input power the file states, in watts (0 when unknown); its ballast
 * (output) factor (1 when the format has none); 1 for absolute photometry
 * (no lamp reference); 1 when the table is radiant intensity (W/sr, its
 * figures never lumens: cdl_photometry_radiant_flux). */
double cdl_photometry_input_watts(const cdl_photometry *photometry);
double cdl_photometry_ballast_factor(const cdl_photometry *photometry);
int cdl_photometry_is_absolute(const cdl_photometry *photometry);
int cdl_photometry_is_radiometric(const cdl_photometry *photometry);

/* The luminous opening the file gives (a point when it gives none). */
const cdl_luminous_opening *cdl_photometry_opening(const cdl_photometry *photometry);

/* The lamp sets: their number, and a copy of set `index` into *out
 * (returns 0 and leaves *out untouched past the end). */
size_t cdl_photometry_lamp_set_count(const cdl_photometry *photometry);
int cdl_photometry_get_lamp_set(const cdl_photometry *photometry, size_t index, cdl_photometry_lamp_set *out);

/* The texts a file names in either format (cdl_photometry_get_text). */
typedef enum cdl_photometry_text {
    CDL_PHOTOMETRY_MANUFACTURER,            /* IES [MANUFAC], EULUMDAT line 1 */
    CDL_PHOTOMETRY_LUMINAIRE,               /* [LUMINAIRE], line 9 */
    CDL_PHOTOMETRY_CATALOGUE,               /* [LUMCAT], line 10 */
    CDL_PHOTOMETRY_LAMP                     /* [LAMP] or [LAMPCAT], the first lamp set's type */
} cdl_photometry_text;

/* What the file names: the maker, the luminaire, its catalogue number, the
 * lamp; "" when the file does not say. */
const char *cdl_photometry_get_text(const cdl_photometry *photometry, cdl_photometry_text which);

/* The file's keywords in order: their number, and each one's name (without
 * brackets: "MANUFAC", "_ABSOLUTELUMENS"; "" for free text) and value
 * ([MORE] continuations joined with '\n'); NULL past the end. An IES
 * file's keywords as written; an EULUMDAT file has few (its fields have
 * fixed lines). */
size_t cdl_photometry_keyword_count(const cdl_photometry *photometry);
const char *cdl_photometry_keyword_name(const cdl_photometry *photometry, size_t index);
const char *cdl_photometry_keyword_text(const cdl_photometry *photometry, size_t index);

/* The value of the first keyword named `key` (case-insensitive), or NULL. */
const char *cdl_photometry_keyword_value(const cdl_photometry *photometry, const char *key);

/* Warnings found while reading (inconsistent header values, non-standard
 * but readable constructs). Each is one line naming the file (and the line
 * when it points at one), a stable code that names the check
 * ("lor-above-1", "ldt-lorl-mismatch", ...: docs/photometry-warnings.md
 * lists every code and what fires it), and the line of the file it points
 * at (0 when it is about the file as a whole). NULL / 0 past the end. */
size_t cdl_photometry_warning_count(const cdl_photometry *photometry);
const char *cdl_photometry_warning(const cdl_photometry *photometry, size_t index);
const char *cdl_photometry_warning_code(const cdl_photometry *photometry, size_t index);
unsigned cdl_photometry_warning_line(const cdl_photometry *photometry, size_t index);

/* ---- summary ------------------------------------------------------------- */

/* Which plane a beam or field angle is measured in: the great circle
 * through nadir and zenith containing C0 and C180 (the frame's x-z plane),
 * or C90 and C270 (the y-z plane). For types A/B the same frame planes are used. */
typedef enum cdl_photometry_plane { CDL_PLANE_C0_C180 = 0, CDL_PLANE_C90_C270 = 1 } cdl_photometry_plane;

/* Full angle in degrees between the two directions on either side of the
 * plane's maximum where the interpolated intensity falls to `fraction` of
 * that maximum (0.5: beam angle, 0.1: field angle, as in IES/CIE usage).
 * -1 when undefined: no light in the plane, or it never falls that low. */
double cdl_photometry_spread_angle(const cdl_photometry *photometry, cdl_photometry_plane plane, double fraction);

/* The figures below are the table's, as written. The luminaire in a scene
 * gives them times output_factor (the ballast factor, cdl_photometry_output_factor):
 * luminaire_flux and luminaire_max_intensity are those products, what an
 * IES file and its EULUMDAT conversion (which folds the factor into the
 * lamp flux) both read as. For a radiometric file (radiometric = 1) the
 * luminous fields are NaN and the radiant ones hold the table's figures in
 * W and W/sr. */
typedef struct cdl_photometry_summary {
    size_t size;                             /* sizeof(cdl_photometry_summary): set by the caller
                                                (CDL_PHOTOMETRY_SUMMARY_INIT); only the fields it covers are filled */
    cdl_luminous_flux flux;                  /* exact integral of the table */
    cdl_luminous_flux downward_flux;         /* frame gamma in [0, 90] (below the horizontal) */
    cdl_luminous_flux upward_flux;           /* frame gamma in [90, 180] */
    cdl_luminous_flux zone_flux[18];         /* zone k: gamma in [10k, 10k + 10] */
    double downward_fraction;                /* downward / total, 0 without light */
    int lamp_flux_known;                     /* relative photometry: rated lamp flux given */
    cdl_luminous_flux lamp_flux;             /* rated lamp flux (all lamps), 0 when unknown */
    int lor_known;
    double lor;                              /* light output ratio: flux / lamp flux */
    cdl_luminous_intensity max_intensity;    /* largest tabulated value */
    double max_c_deg, max_gamma_deg;         /* its frame direction */
    double max_h_deg, max_v_deg;             /* its angles in the table (frame C/gamma for type C, H/V for A/B) */
    double beam_angle_deg[2];                /* [CDL_PLANE_C0_C180], [CDL_PLANE_C90_C270]; -1 undefined */
    double field_angle_deg[2];
    int efficacy_known;
    cdl_luminous_efficacy efficacy;          /* flux x output factor / input watts */
    /* Where the beam and field angles are measured: spread_about_peak 0,
     * in the C0-C180 and C90-C270 planes through nadir (also for a
     * rotationally symmetric batwing, which reads the same in both); 1 (a
     * maximum off nadir of a distribution that is not rotationally
     * symmetric: batwing, asymmetric, wall-pack and flood ones), in
     * the vertical plane through the peak ([0]) and the plane across it
     * through the peak ([1]). Either way about the peak of that plane and
     * undefined (-1) when the half (tenth) level does not close within
     * 180 degrees. */
    int spread_about_peak;
    double spread_axis_c_deg, spread_axis_gamma_deg; /* the peak, when about it */
    /* Radiometric files (metadata.radiometric): the table's integral,
     * zones and maximum as what they are, in W and W/sr; the luminous
     * fields above are then NaN. */
    int radiometric;
    cdl_radiant_flux radiant_flux;
    cdl_radiant_intensity max_radiant_intensity;
    cdl_radiant_flux radiant_zone_flux[18];  /* zone k: gamma in [10k, 10k + 10] */
    /* The luminaire as it lights a scene: the figures above times the output factor. */
    double output_factor;
    cdl_luminous_flux luminaire_flux;
    cdl_luminous_intensity luminaire_max_intensity;
    double upward_fraction;                  /* upward / total, 0 without light */
} cdl_photometry_summary;

#define CDL_PHOTOMETRY_SUMMARY_INIT {.size = sizeof(cdl_photometry_summary)}

/* Fill *summary (caller's, its size set) with the figures above, all from
 * the table (flux: the exact integral; efficacy from the stated input
 * watts). Never fails. */
void cdl_photometry_summarize(const cdl_photometry *photometry, cdl_photometry_summary *summary);

/* ---- figures for lighting design ------------------------------------------ */

#define CDL_DIRECT_RATIO_COUNT 10

/* EULUMDAT's direct ratios (lines 27-36) are given for these ten room
 * indices k = a b / (h (a + b)): 0.60, 0.80, 1.00, 1.25, 1.50, 2.00, 2.50,
 * 3.00, 4.00 and 5.00 (index 0..9; 0 outside). */
double cdl_direct_ratio_room_index(int k);

/* The direct ratios (CIE 52, LiTG): for each room index, the share of the
 * luminaire's total flux that reaches the work plane directly, in a square
 * room whose luminaires are spread evenly over the ceiling at a spacing
 * equal to their height above the work plane, each in the middle of its
 * cell (direct_ratios.c states the model and its formula). Fractions 0..1,
 * growing with k; all 0 for a table without flux. Unitless, so also for
 * radiometric tables. Errors: CDL_ERR_INTERNAL (memory). */
cdl_status cdl_photometry_direct_ratios(const cdl_photometry *photometry, double ratio[CDL_DIRECT_RATIO_COUNT],
                                        cdl_error *err);

/* The CIE flux code (CIE 52): n[0..2] the percent of the downward flux
 * within 41.4, 60 and 75.5 degrees of nadir, n[3] the downward flux and
 * n[4] the whole flux in percent of the lamp flux (the luminaire's own for
 * absolute photometry). Unrounded; printed as whole numbers. */
void cdl_photometry_cie_flux_code(const cdl_photometry *photometry, double n[5]);

/* IES TM-15-11 zones and BUG rating (bug_rating.c: zone edges, the front
 * direction and the limits' source). zone_lm in the order FL, FM, FH, FVH,
 * BL, BM, BH, BVH, UL, UH (cdl_bug_zone_name), lumens of the luminaire as
 * it operates (times the output factor); b, u, g from 0 to 5. */
#define CDL_BUG_ZONES 10
typedef struct cdl_bug_rating {
    int b, u, g;
    double zone_lm[CDL_BUG_ZONES];
} cdl_bug_rating;

/* A zone's short name ("FL", ..., "UH"); "" outside 0..9. */
const char *cdl_bug_zone_name(int zone);

/* Errors: CDL_ERR_INPUT for a radiometric file (the rating counts lumens),
 * CDL_ERR_INTERNAL (memory). */
cdl_status cdl_photometry_bug_rating(const cdl_photometry *photometry, cdl_bug_rating *rating, cdl_error *err);

/* ---- transforming -------------------------------------------------------- */

/* A type C copy with every plane moved to C' = (sign x C + offset) mod 360
 * (sign +1 or -1, offset a multiple of 90 keeps symmetric grids symmetric),
 * stored with the most compact symmetry that represents the data exactly
 * (rotational, quadrant, bilateral, or none). sign = +1, offset = 0 just
 * compacts. Metadata is copied. Type A/B tables are refused. */
cdl_status cdl_photometry_remap_c(const cdl_photometry *photometry, int sign, double offset_deg,
                                  cdl_photometry **out, cdl_error *err);

/* A type C copy of any table, sampled from the interpolated distribution on
 * C-planes every dc_deg and gamma angles every dg_deg (both dividing 360
 * and 180), then compacted. For types A/B this is a resampling (EULUMDAT
 * knows only type C): the flux changes slightly. */
cdl_status cdl_photometry_resample_type_c(const cdl_photometry *photometry, double dc_deg, double dg_deg,
                                          cdl_photometry **out, cdl_error *err);

/* ---- writing ------------------------------------------------------------- */

/* What a target format could not hold, one line each (for stderr). */
typedef struct cdl_photometry_notes {
    size_t count;
    char **items;
} cdl_photometry_notes;
#define CDL_PHOTOMETRY_NOTES_INIT {0, NULL}
/* Free the notes' lines and leave them empty (NULL and empty notes are fine). */
void cdl_photometry_notes_free(cdl_photometry_notes *notes);

/* How a file is written. Start from CDL_PHOTOMETRY_WRITE_OPTIONS_INIT (it
 * sets `size`, as for the read options). */
typedef struct cdl_photometry_write_options {
    size_t size;            /* sizeof(cdl_photometry_write_options) */
    int ies_version;        /* IES output: 2019 (also when 0) or 2002 */
    const char *file_name;  /* EULUMDAT line 11; NULL: the output file's name */
} cdl_photometry_write_options;
#define CDL_PHOTOMETRY_WRITE_OPTIONS_INIT {.size = sizeof(cdl_photometry_write_options), .ies_version = 2019, .file_name = NULL}

/* The file text in a malloc'd buffer (*text, NUL-terminated, *length
 * bytes). IES: LM-63-2019 or -2002, lines end in CR LF as the standard
 * says; horizontal angles H = (360 - C) mod 360 (photometry.h). EULUMDAT:
 * intensities in cd/klm of lamp set 1 (for absolute photometry: of the
 * integrated flux, with a negative lamp count), CR LF. Both write the most
 * compact symmetry that represents the table exactly. `lost` (may be NULL)
 * receives what the format cannot hold. */
cdl_status cdl_photometry_format_ies(const cdl_photometry *photometry, const cdl_photometry_write_options *options,
                                     char **text, size_t *length, cdl_photometry_notes *lost, cdl_error *err);
cdl_status cdl_photometry_format_ldt(const cdl_photometry *photometry, const cdl_photometry_write_options *options,
                                     char **text, size_t *length, cdl_photometry_notes *lost, cdl_error *err);

/* ---- plotting (photometry_plot.c) ---------------------------------------- */

/* The polar intensity diagram as SVG at `path` (atomically), drawn by
 * cairo: the C0-C180 (solid) and C90-C270 (dashed) planes in cd/klm, and
 * the plane through the peak (dotted) when it is neither; type A/B tables
 * in their V and H planes; nadir down, `title` on top (wrapped or cut to
 * fit) and in the SVG's <title>; the peak and the beam angles below. */
cdl_status cdl_photometry_write_polar_svg(const cdl_photometry *photometry, const char *title, const char *path,
                                          cdl_error *err);
/* The diagram's scale: its outer ring's value, the smallest n x step at
 * or above the largest cd/klm with a step of 1, 2, 2.5 or 5 x 10^k and 3
 * to 6 rings (their count in *rings, which may be NULL), and in *per_klm
 * the factor from cd to cd/klm (1000 / the rated lamp flux, or the table's
 * flux for absolute photometry). */
double cdl_photometry_plot_scale(const cdl_photometry *photometry, double *per_klm, int *rings);

/* Write a file atomically (temporary name, then rename). */
cdl_status cdl_photometry_write_file(const cdl_photometry *photometry, const char *path, cdl_photometry_format format,
                                     const cdl_photometry_write_options *options, cdl_photometry_notes *lost,
                                     cdl_error *err);

#endif
