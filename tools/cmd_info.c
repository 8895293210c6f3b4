/* cmd_info.c - `candela info`: a summary of a luminaire file, as text or JSON. */
#include <cjson/cJSON.h>
#include <ctype.h>
#include <dirent.h>
#include <math.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "command.h"
#include "info_ugr.h"
#include "lights/photometry/photometry.h"
#include "solver/scene/scene.h"

static void print_help(FILE *out)
{
    fputs("usage: candela info LUMINAIRE [--json] [--strict] [--plot OUT.svg] [--ugr [--ugr-shr R]]\n"
          "       candela info FILE_OR_FOLDER... [--json] [--strict]\n"
          "\n"
          "Reads an IES LM-63 (any version) or EULUMDAT file and prints a summary:\n"
          "format and version, photometric type, symmetry, angle grid, lamp and\n"
          "integrated flux, light output ratio, efficacy, maximum intensity and its\n"
          "direction, beam (50 %) and field (10 %) angles, downward fraction, warnings.\n"
          "\n"
          "  --json     one JSON object on stdout instead of text (a JSON array for\n"
          "             several files)\n"
          "  --strict   treat warnings (inconsistent header values) as errors\n"
          "  --plot OUT.svg  also draw the polar intensity diagram (C0-C180 solid,\n"
          "             C90-C270 dashed, cd/klm, nadir down) into OUT.svg\n"
          "  --ugr      also the luminaire's UGR table as catalogues print it (CIE\n"
          "             190:2010): the 19 standard rooms 2H x 2H ... 12H x 8H (X across\n"
          "             the line of sight, Y along it, H = 2 m from the eye up to the\n"
          "             luminaires), the luminaires at spacing 0.25 H over the whole\n"
          "             ceiling, viewed crosswise (their C0 plane along the line of sight)\n"
          "             and endwise, reflectances ceiling/walls/floor 0.70/0.50/0.20,\n"
          "             0.70/0.30/0.20, 0.50/0.50/0.20, 0.50/0.30/0.20, 0.30/0.30/0.20;\n"
          "             UGR = 8 log10((0.25 / Lb) sum L^2 omega / p^2) (CIE 117:1995) with\n"
          "             L = I / A the luminance of the file's luminous opening towards\n"
          "             the eye, omega = A / r^2, p Guth's position index (CIE 117\n"
          "             Table 4.1), and Lb the walls' indirect illuminance over pi by\n"
          "             CIE 190's flux transfer between ceiling, walls and floor. The\n"
          "             luminaire's real flux (\"corrected\" table). A file without a\n"
          "             luminous opening (a point) cannot be rated: exit 1.\n"
          "  --ugr-shr R  the spacing to height ratio of the table (default 0.25; CIE\n"
          "             190's own example uses 1)\n"
          "\n"
          "Several files, or folders (every .ies and .ldt file in them and their\n"
          "subfolders, in name order): one line per file, then how many were read,\n"
          "had warnings or failed, and which failed; exit status 1 if any failed.\n"
          "\n"
          "Flux is the exact integral of the bilinearly interpolated table. Angles\n"
          "are in the photometric frame: gamma from nadir, C counter-clockwise seen\n"
          "from above, C0 along the luminaire's photometric horizontal; IES type C\n"
          "horizontal angles H map to C = (360 - H) mod 360 (see `candela convert\n"
          "--help`). Beam (50 %) and field (10 %) angles are full angles about the\n"
          "peak of a plane: the C0-C180 and C90-C270 planes through nadir for a\n"
          "distribution whose maximum is at or near nadir; for one whose maximum lies\n"
          "off nadir (batwing, asymmetric, wall-pack, floodlight) the vertical plane\n"
          "through the peak and the plane across it; null (\"not defined\") when the\n"
          "level is not reached within 180 degrees. Files whose table is in W/sr (a\n"
          "keyword such as [_INTENSITYUNITS] mW/sr: UV and infrared) are reported in\n"
          "W and W/sr, never lumens.\n"
          "\n"
          "JSON keys: file, format, version, photometric_type, symmetry, c_planes,\n"
          "gamma_angles (both as written in the file), stored_planes, lamp_flux_lm\n"
          "(null for absolute photometry), flux_lm, lor (null when unknown),\n"
          "max_intensity_cd, max_intensity_direction, beam_angle_deg and\n"
          "field_angle_deg ({\"c0_c180\", \"c90_c270\"}), downward_fraction,\n"
          "zone_flux_lm (18 zones of 10 degrees from nadir), efficacy_lm_per_w,\n"
          "input_watts, ballast_factor, output_factor, tilt, opening, keywords,\n"
          "spread_about (\"nadir\" or \"peak\", with spread_axis and the angles'\n"
          "keys vertical_plane and across), radiometric (with radiant_flux_w and\n"
          "max_radiant_intensity_w_sr), warnings; with --ugr, ugr_table (method,\n"
          "spacing_to_height, height_m, flux_lm, output_factor, reflectances, and\n"
          "rooms: x_h, y_h, luminaires, room_index, direct_floor_lm,\n"
          "direct_walls_lm, direct_ceiling_lm, background_cd_m2, crosswise and\n"
          "endwise, five values each in the order of reflectances).\n"
          "\n"
          "Exit status: 0 success, 1 bad input (any file), 2 usage error.\n", out);
}

static const char *type_letter(cdl_photometric_type t)
{
    return t == CDL_PHOTOMETRIC_TYPE_A ? "A" : t == CDL_PHOTOMETRIC_TYPE_B ? "B" : "C";
}

static void version_text(const cdl_photometry_metadata *m, char *buf, size_t size)
{
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES) snprintf(buf, size, "LM-63-%d", m->ies_version);
    else if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) snprintf(buf, size, "EULUMDAT");
    else snprintf(buf, size, "table");
}

/* Text from files is bytes: keep valid UTF-8, read anything else as Latin-1. */
static char *to_utf8(const char *s)
{
    size_t n = strlen(s);
    int valid = 1;
    for (size_t i = 0; i < n && valid;) {
        unsigned char c = (unsigned char)s[i];
        size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (len == 0 || i + len > n) valid = 0;
        for (size_t k = 1; valid && k < len; ++k)
            if (((unsigned char)s[i + k] >> 6) != 2) valid = 0;
        i += len ? len : 1;
    }
    char *out = malloc(2 * n + 1);
    if (!out) return NULL;
    if (valid) {
        memcpy(out, s, n + 1);
        return out;
    }
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x80) {
            out[k++] = (char)c;
        } else {
            out[k++] = (char)(0xC0 | (c >> 6));
            out[k++] = (char)(0x80 | (c & 0x3F));
        }
    }
    out[k] = '\0';
    return out;
}

static void add_string(cJSON *obj, const char *key, const char *value)
{
    char *u = to_utf8(value ? value : "");
    cJSON_AddStringToObject(obj, key, u ? u : "");
    free(u);
}

/* A finite number, or null. */
static void add_number(cJSON *obj, const char *key, int known, double value)
{
    if (known && isfinite(value)) cJSON_AddNumberToObject(obj, key, value);
    else cJSON_AddNullToObject(obj, key);
}

static void add_planes(cJSON *obj, const char *key, const double angles[2], int about_peak)
{
    cJSON *o = cJSON_AddObjectToObject(obj, key);
    add_number(o, about_peak ? "vertical_plane" : "c0_c180", angles[0] >= 0.0, angles[0]);
    add_number(o, about_peak ? "across" : "c90_c270", angles[1] >= 0.0, angles[1]);
}

static void add_array(cJSON *obj, const char *key, const double *x, size_t n)
{
    cJSON *a = cJSON_AddArrayToObject(obj, key);
    for (size_t i = 0; i < n; ++i) cJSON_AddItemToArray(a, cJSON_CreateNumber(isfinite(x[i]) ? x[i] : 0.0));
}

/* The viewing angles of the opening's luminance table: the C planes along
 * and across the luminaire, and the glare zone's gamma (CIE 117 tabulates
 * luminaire luminance at 45..85 degrees). */
static const double luminance_c_deg[4] = {0.0, 90.0, 180.0, 270.0};
static const double luminance_gamma_deg[6] = {0.0, 45.0, 55.0, 65.0, 75.0, 85.0};

/* What near-field light and glare need of the opening: its largest
 * dimension, the distance within which the solver spreads the light over
 * it, and its luminance (average and maximum over the visible opening)
 * at each viewing angle; null luminances for openings without area. */
static void add_opening_luminance(cJSON *op, const cdl_photometry *p)
{
    const cdl_luminous_opening *o = &cdl_photometry_get_metadata(p)->opening;
    double size = cdl_luminous_opening_largest_m(o);
    add_number(op, "largest_dimension_m", 1, size);
    cJSON_AddBoolToObject(op, "spread_by_solver", cdl_luminous_opening_is_spread(o));
    add_number(op, "near_field_distance_m", cdl_luminous_opening_is_spread(o), CDL_NEAR_FIELD_DISTANCES * size);
    cJSON *rows = cJSON_AddArrayToObject(op, "luminance");
    for (int c = 0; c < 4; ++c)
        for (int g = 0; g < 6; ++g) {
            cdl_luminance avg, max;
            cdl_photometry_opening_luminance(p, luminance_c_deg[c], luminance_gamma_deg[g], &avg, &max);
            cJSON *row = cJSON_CreateObject();
            cJSON_AddNumberToObject(row, "c_deg", luminance_c_deg[c]);
            cJSON_AddNumberToObject(row, "gamma_deg", luminance_gamma_deg[g]);
            int has_area = cdl_luminous_opening_projected_area(
                               o, cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, luminance_c_deg[c],
                                                           luminance_gamma_deg[g])) > 0.0;
            add_number(row, "average_cd_m2", has_area, avg.cd_m2);
            add_number(row, "maximum_cd_m2", has_area, max.cd_m2);
            cJSON_AddItemToArray(rows, row);
        }
}

static cJSON *info_json(const char *path, const cdl_photometry *p, const cdl_photometry_summary *s)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    char version[32];
    version_text(m, version, sizeof version);
    cJSON *j = cJSON_CreateObject();
    if (!j) return NULL;
    add_string(j, "file", path);
    add_string(j, "format", m->format == CDL_PHOTOMETRY_FORMAT_IES        ? "IES"
                            : m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? "EULUMDAT"
                                                                          : "table");
    add_string(j, "version", version);
    add_string(j, "version_tag", m->version_tag);
    add_string(j, "photometric_type", type_letter(t.type));
    add_string(j, "symmetry", cdl_photometry_symmetry_name(t.symmetry));
    cJSON_AddNumberToObject(j, "c_planes", (double)m->file_horizontal_count);
    cJSON_AddNumberToObject(j, "gamma_angles", (double)m->file_vertical_count);
    cJSON_AddNumberToObject(j, "stored_planes", (double)t.horizontal_count);
    cJSON_AddBoolToObject(j, "absolute_photometry", m->absolute);
    add_number(j, "lamp_flux_lm", s->lamp_flux_known, s->lamp_flux.lm);
    cJSON_AddNumberToObject(j, "lamps", (double)(m->lamp_set_count ? m->lamp_sets[0].count : 0));
    add_number(j, "flux_lm", !s->radiometric, s->flux.lm);
    add_number(j, "lor", s->lor_known, s->lor);
    add_number(j, "max_intensity_cd", !s->radiometric, s->max_intensity.cd);
    cJSON_AddBoolToObject(j, "radiometric", s->radiometric);
    if (s->radiometric) {
        add_number(j, "radiant_flux_w", 1, s->radiant_flux.W);
        add_number(j, "max_radiant_intensity_w_sr", 1, s->max_radiant_intensity.W_sr);
    }
    cJSON *dir = cJSON_AddObjectToObject(j, "max_intensity_direction");
    add_number(dir, "c_deg", 1, s->max_c_deg);
    add_number(dir, "gamma_deg", 1, s->max_gamma_deg);
    add_planes(j, "beam_angle_deg", s->beam_angle_deg, s->spread_about_peak);
    add_planes(j, "field_angle_deg", s->field_angle_deg, s->spread_about_peak);
    cJSON_AddStringToObject(j, "spread_about", s->spread_about_peak ? "peak" : "nadir");
    if (s->spread_about_peak) {
        cJSON *axis = cJSON_AddObjectToObject(j, "spread_axis");
        add_number(axis, "c_deg", 1, s->spread_axis_c_deg);
        add_number(axis, "gamma_deg", 1, s->spread_axis_gamma_deg);
    }
    add_number(j, "downward_fraction", 1, s->downward_fraction);
    add_number(j, "upward_fraction", 1, s->flux.lm > 0.0 ? s->upward_flux.lm / s->flux.lm : 0.0);
    double zones[18];
    for (int k = 0; k < 18; ++k) zones[k] = s->zone_flux[k].lm;
    add_array(j, "zone_flux_lm", zones, 18);
    add_number(j, "efficacy_lm_per_w", s->efficacy_known, s->efficacy.lm_W);
    add_number(j, "input_watts", m->input_watts > 0.0, m->input_watts);
    add_number(j, "ballast_factor", 1, m->ballast_factor);
    add_number(j, "output_factor", 1, cdl_photometry_output_factor(p));
    add_number(j, "candela_multiplier", 1, m->candela_multiplier);
    if (m->tilt_count > 0) {
        cJSON *tilt = cJSON_AddObjectToObject(j, "tilt");
        cJSON_AddNumberToObject(tilt, "geometry", m->tilt_geometry);
        add_array(tilt, "angles_deg", m->tilt_angles_deg, m->tilt_count);
        add_array(tilt, "factors", m->tilt_factors, m->tilt_count);
    } else {
        cJSON_AddNullToObject(j, "tilt");
    }
    cJSON *op = cJSON_AddObjectToObject(j, "opening");
    add_string(op, "shape", cdl_luminous_shape_name(m->opening.shape));
    add_number(op, "width_m", 1, m->opening.width_m);
    add_number(op, "length_m", 1, m->opening.length_m);
    add_number(op, "height_m", 1, m->opening.height_m);
    if (m->opening.shape == CDL_LUMINOUS_SHAPE_BOX) {
        /* each side's luminous height: C0, C90, C180, C270 */
        cJSON *sides = cJSON_AddArrayToObject(op, "side_heights_m");
        for (int k = 0; k < 4; ++k)
            cJSON_AddItemToArray(sides, cJSON_CreateNumber(cdl_luminous_opening_box_side_height_m(&m->opening, k)));
    }
    add_opening_luminance(op, p);
    cJSON *kw = cJSON_AddArrayToObject(j, "keywords");
    for (size_t i = 0; i < m->keyword_count; ++i) {
        cJSON *pair = cJSON_CreateObject();
        add_string(pair, "key", m->keywords[i].key);
        add_string(pair, "value", m->keywords[i].value);
        cJSON_AddItemToArray(kw, pair);
    }
    cJSON *w = cJSON_AddArrayToObject(j, "warnings");
    for (size_t i = 0; i < cdl_photometry_warning_count(p); ++i) {
        char *u = to_utf8(cdl_photometry_warning(p, i));
        cJSON_AddItemToArray(w, cJSON_CreateString(u ? u : ""));
        free(u);
    }
    return j;
}

/* One JSON value on stdout; CDL_EXIT_INTERNAL when it cannot be made. */
static int put_json(cJSON *j)
{
    char *text = j ? cJSON_Print(j) : NULL;
    cJSON_Delete(j);
    if (!text) return CDL_EXIT_INTERNAL;
    puts(text);
    cJSON_free(text);
    return CDL_EXIT_OK;
}

static void print_angle(const char *label, const double a[2], int about_peak)
{
    printf("%-16s", label);
    for (int k = 0; k < 2; ++k) {
        if (a[k] >= 0.0) printf("%.1f deg", a[k]);
        else printf("not defined");
        if (about_peak) printf("%s", k == 0 ? " (vertical plane through the peak), " : " (across it)\n");
        else printf("%s", k == 0 ? " (C0-C180), " : " (C90-C270)\n");
    }
}

static void print_text(const char *path, const cdl_photometry *p, const cdl_photometry_summary *s)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    char version[32];
    version_text(m, version, sizeof version);
    printf("%-16s%s\n", "file", path);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES)
        printf("%-16sIES %s%s%s%s\n", "format", version, m->version_tag[0] ? " (tag '" : " (no version tag)",
               m->version_tag, m->version_tag[0] ? "')" : "");
    else
        printf("%-16sEULUMDAT (Isym %d, Ityp %d)\n", "format", m->ldt_isym, m->ldt_ityp);
    const char *name = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? m->ldt_luminaire_name
                                                                   : cdl_photometry_keyword_value(p, "LUMINAIRE");
    const char *maker = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? m->ldt_company
                                                                    : cdl_photometry_keyword_value(p, "MANUFAC");
    if (maker && *maker) printf("%-16s%s\n", "manufacturer", maker);
    if (name && *name) printf("%-16s%.*s\n", "luminaire", (int)strcspn(name, "\n"), name);
    printf("%-16stype %s, symmetry %s, %zu x %zu angles in the file (%zu planes stored)\n", "photometry",
           type_letter(t.type), cdl_photometry_symmetry_name(t.symmetry), m->file_horizontal_count,
           m->file_vertical_count, t.horizontal_count);
    if (s->lamp_flux_known)
        printf("%-16s%d x %.6g lm = %.6g lm rated (relative photometry)\n", "lamps",
               m->lamp_sets[0].count, s->lamp_flux.lm / (m->lamp_sets[0].count ? abs(m->lamp_sets[0].count) : 1),
               s->lamp_flux.lm);
    else
        printf("%-16sabsolute photometry (no lamp reference)\n", "lamps");
    if (s->radiometric)
        printf("%-16s%.6g W radiant (integrated; the table is radiant intensity in %s, as [%s] says: no "
               "lumens), downward %.1f %%\n",
               "flux", s->radiant_flux.W, m->radiometric_scale == 1.0 ? "W/sr" : m->radiometric_scale == 1e-3 ? "mW/sr"
                                                                                                              : "uW/sr",
               m->units_keyword, 100.0 * s->downward_fraction);
    else
        printf("%-16s%.6g lm (integrated), downward %.1f %%, upward %.1f %%\n", "flux", s->flux.lm,
               100.0 * s->downward_fraction, s->flux.lm > 0.0 ? 100.0 * s->upward_flux.lm / s->flux.lm : 0.0);
    if (s->lor_known) printf("%-16s%.1f %%\n", "LOR", 100.0 * s->lor);
    if (m->input_watts > 0.0) printf("%-16s%.6g W\n", "input power", m->input_watts);
    if (s->efficacy_known)
        printf("%-16s%.1f lm/W%s\n", "efficacy", s->efficacy.lm_W,
               cdl_photometry_output_factor(p) != 1.0 ? " (output factor applied)" : "");
    if (cdl_photometry_output_factor(p) != 1.0)
        printf("%-16s%.4g (applied at render time, not in the table)\n", "output factor", cdl_photometry_output_factor(p));
    if (s->radiometric)
        printf("%-16s%.6g W/sr at C %.4g, gamma %.4g", "max intensity", s->max_radiant_intensity.W_sr, s->max_c_deg,
               s->max_gamma_deg);
    else
        printf("%-16s%.6g cd at C %.4g, gamma %.4g", "max intensity", s->max_intensity.cd, s->max_c_deg,
               s->max_gamma_deg);
    if (m->format == CDL_PHOTOMETRY_FORMAT_IES && t.type == CDL_PHOTOMETRIC_TYPE_C)
        printf(" (IES H %.4g, V %.4g)", fmod(360.0 - s->max_c_deg, 360.0), s->max_gamma_deg);
    else if (t.type != CDL_PHOTOMETRIC_TYPE_C)
        printf(" (type %s H %.4g, V %.4g)", type_letter(t.type), s->max_h_deg, s->max_v_deg);
    printf("\n");
    print_angle("beam angle", s->beam_angle_deg, s->spread_about_peak);
    print_angle("field angle", s->field_angle_deg, s->spread_about_peak);
    if (s->spread_about_peak)
        printf("%-16speak at C %.4g, gamma %.4g (its maximum lies off nadir: angles about it)\n", "beam axis",
               s->spread_axis_c_deg, s->spread_axis_gamma_deg);
    printf("%-16s%s", "opening", cdl_luminous_shape_name(m->opening.shape));
    if (m->opening.shape != CDL_LUMINOUS_SHAPE_POINT)
        printf(", %.4g x %.4g x %.4g m (width x length x height)", m->opening.width_m, m->opening.length_m,
               m->opening.height_m);
    const double *sh = m->opening.side_height_m;
    if (m->opening.shape == CDL_LUMINOUS_SHAPE_BOX && (sh[0] > 0.0 || sh[1] > 0.0 || sh[2] > 0.0 || sh[3] > 0.0))
        printf(", sides luminous to %.4g (C0), %.4g (C90), %.4g (C180), %.4g (C270) m, the height their mean", sh[0],
               sh[1], sh[2], sh[3]);
    printf("\n");
    if (cdl_luminous_opening_is_spread(&m->opening))
        printf("%-16sspread over its opening within %.3g m (%g x its largest dimension %.3g m)\n", "near field",
               CDL_NEAR_FIELD_DISTANCES * cdl_luminous_opening_largest_m(&m->opening), CDL_NEAR_FIELD_DISTANCES,
               cdl_luminous_opening_largest_m(&m->opening));
    cdl_luminance nadir, max, c0, c90;
    cdl_photometry_opening_luminance(p, 0.0, 0.0, &nadir, &max);
    cdl_photometry_opening_luminance(p, 0.0, 65.0, &c0, &max);
    cdl_photometry_opening_luminance(p, 90.0, 65.0, &c90, &max);
    if (nadir.cd_m2 > 0.0 || c0.cd_m2 > 0.0 || c90.cd_m2 > 0.0)
        printf("%-16s%.4g cd/m2 at nadir; %.4g (C0) and %.4g (C90) at gamma 65 (average over the opening)\n",
               "luminance", nadir.cd_m2, c0.cd_m2, c90.cd_m2);
    if (m->tilt_count > 0)
        printf("%-16s%zu angles, geometry %d (factors %.4g..%.4g)\n", "tilt", m->tilt_count, m->tilt_geometry,
               m->tilt_factors[0], m->tilt_factors[m->tilt_count - 1]);
    printf("%-16s", "zones (lm)");
    for (int k = 0; k < 18; ++k) printf("%s%d-%d: %.4g", k == 0 ? "" : k % 6 == 0 ? "\n                " : ", ",
                                        10 * k, 10 * k + 10, s->zone_flux[k].lm);
    printf("\n");
    size_t nw = cdl_photometry_warning_count(p);
    if (nw == 0) printf("%-16snone\n", "warnings");
    for (size_t i = 0; i < nw; ++i) printf("%-16s%s\n", i == 0 ? "warnings" : "", cdl_photometry_warning(p, i));
}

/* ---- many files ------------------------------------------------------------------ */

typedef struct file_list {
    char **paths;
    size_t count, capacity;
} file_list;

static int list_add(file_list *l, const char *path)
{
    if (l->count == l->capacity) {
        size_t cap = l->capacity ? 2 * l->capacity : 64;
        char **grown = realloc(l->paths, cap * sizeof *grown);
        if (!grown) return 0;
        l->paths = grown;
        l->capacity = cap;
    }
    size_t n = strlen(path) + 1;
    l->paths[l->count] = malloc(n);
    if (!l->paths[l->count]) return 0;
    memcpy(l->paths[l->count++], path, n);
    return 1;
}

static void list_free(file_list *l)
{
    for (size_t i = 0; i < l->count; ++i) free(l->paths[i]);
    free(l->paths);
}

static int compare_paths(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* A photometric file by its name: .ies or .ldt, any case. */
static int photometric_name(const char *name)
{
    size_t n = strlen(name);
    if (n < 4 || name[0] == '.') return 0;
    const char *ext = name + n - 4;
    return ext[0] == '.' && ((tolower((unsigned char)ext[1]) == 'i' && tolower((unsigned char)ext[2]) == 'e' &&
                              tolower((unsigned char)ext[3]) == 's') ||
                             (tolower((unsigned char)ext[1]) == 'l' && tolower((unsigned char)ext[2]) == 'd' &&
                              tolower((unsigned char)ext[3]) == 't'));
}

/* Every photometric file under `folder` (depth-first, each folder's entries in name order). */
static int list_folder(file_list *l, const char *folder, int depth)
{
    DIR *d = opendir(folder);
    if (!d) return list_add(l, folder); /* reported when read */
    file_list here = {0};
    int ok = 1;
    for (struct dirent *e = readdir(d); e && ok; e = readdir(d)) {
        if (e->d_name[0] == '.') continue;
        char path[4096];
        size_t n = strlen(folder);
        snprintf(path, sizeof path, "%s%s%s", folder, n > 0 && folder[n - 1] == '/' ? "" : "/", e->d_name);
        struct stat sb;
        if (stat(path, &sb) != 0) continue;
        if ((S_ISDIR(sb.st_mode) && depth < 16) || (S_ISREG(sb.st_mode) && photometric_name(e->d_name)))
            ok = list_add(&here, path);
    }
    closedir(d);
    if (here.count) qsort(here.paths, here.count, sizeof *here.paths, compare_paths);
    for (size_t i = 0; ok && i < here.count; ++i) {
        struct stat sb;
        if (stat(here.paths[i], &sb) == 0 && S_ISDIR(sb.st_mode)) ok = list_folder(l, here.paths[i], depth + 1);
        else ok = list_add(l, here.paths[i]);
    }
    list_free(&here);
    return ok;
}

/* One line for a file read: format, flux, efficacy, beam, warnings. */
static void print_line(const char *path, const cdl_photometry *p, const cdl_photometry_summary *s)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    char version[32], flux[64], efficacy[48] = "", beam[96];
    version_text(m, version, sizeof version);
    if (s->radiometric) snprintf(flux, sizeof flux, "%.5g W radiant", s->radiant_flux.W);
    else snprintf(flux, sizeof flux, "%.5g lm", s->flux.lm);
    if (s->efficacy_known) snprintf(efficacy, sizeof efficacy, ", %.4g lm/W", s->efficacy.lm_W);
    char a[2][24];
    for (int k = 0; k < 2; ++k)
        if (s->beam_angle_deg[k] >= 0.0) snprintf(a[k], sizeof a[k], "%.3g", s->beam_angle_deg[k]);
        else snprintf(a[k], sizeof a[k], "-");
    snprintf(beam, sizeof beam, "beam %s/%s deg%s", a[0], a[1], s->spread_about_peak ? " about the peak" : "");
    size_t nw = cdl_photometry_warning_count(p);
    printf("ok    %s: %s, %s%s, %s, %zu warning%s\n", path, version, flux, efficacy, beam, nw, nw == 1 ? "" : "s");
}

static int run_many(const file_list *files, int json, const cdl_photometry_read_options *ro)
{
    cJSON *array = json ? cJSON_CreateArray() : NULL;
    char *bad = calloc(files->count ? files->count : 1, 1);
    if ((json && !array) || !bad) {
        cJSON_Delete(array);
        free(bad);
        return CDL_EXIT_INTERNAL;
    }
    size_t failed = 0, warned = 0, warnings = 0;
    for (size_t i = 0; i < files->count; ++i) {
        const char *path = files->paths[i];
        cdl_photometry *p = NULL;
        cdl_error err;
        cdl_error_clear(&err);
        if (cdl_photometry_read_file(path, ro, &p, &err) != CDL_OK) {
            ++failed;
            bad[i] = 1;
            if (json) {
                cJSON *o = cJSON_CreateObject();
                add_string(o, "file", path);
                add_string(o, "error", err.message);
                cJSON_AddItemToArray(array, o);
            } else {
                printf("FAIL  %s\n", err.message);
            }
            continue;
        }
        cdl_photometry_summary s;
        cdl_photometry_summarize(p, &s);
        size_t nw = cdl_photometry_warning_count(p);
        warnings += nw;
        warned += nw > 0;
        if (json) cJSON_AddItemToArray(array, info_json(path, p, &s));
        else print_line(path, p, &s);
        cdl_photometry_release(p);
    }
    int rc = CDL_EXIT_OK;
    if (json) {
        rc = put_json(array);
    } else {
        printf("%zu file%s: %zu read (%zu with warnings, %zu warning%s in all), %zu failed\n", files->count,
               files->count == 1 ? "" : "s", files->count - failed, warned, warnings, warnings == 1 ? "" : "s",
               failed);
    }
    if (failed > 0) {
        fprintf(stderr, "candela info: %zu of %zu files failed:\n", failed, files->count);
        /* Name them again on stderr, whatever went to stdout. */
        for (size_t i = 0; i < files->count; ++i)
            if (bad[i]) fprintf(stderr, "  %s\n", files->paths[i]);
    }
    free(bad);
    if (rc == CDL_EXIT_OK && failed > 0) rc = CDL_EXIT_INPUT;
    return rc;
}

static int run(int argc, char **argv)
{
    cdl_cli_option options[] = {{"json", 0, 0, 0, NULL},
                                {"strict", 0, 0, 0, NULL},
                                {"plot", 0, 1, 0, NULL},
                                {"ugr", 0, 0, 0, NULL},
                                {"ugr-shr", 0, 1, 0, NULL}};
    const size_t count = sizeof options / sizeof options[0];
    cdl_cli_result r;
    if (cdl_cli_scan(argc, argv, options, count, &r) != 0) {
        fprintf(stderr, "candela info: %s\n(see 'candela info --help')\n", r.message);
        return CDL_EXIT_USAGE;
    }
    if (r.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    if (r.positional_count < 1) {
        fprintf(stderr, "candela info: expected a luminaire file (or several, or folders), found none\n"
                        "(see 'candela info --help')\n");
        return CDL_EXIT_USAGE;
    }
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_DEFAULT;
    ro.strict = cdl_cli_find(options, count, "strict")->present;
    int json = cdl_cli_find(options, count, "json")->present;
    const cdl_cli_option *plot = cdl_cli_find(options, count, "plot");
    int ugr = cdl_cli_find(options, count, "ugr")->present;
    const cdl_cli_option *shr = cdl_cli_find(options, count, "ugr-shr");
    cdl_ugr_table_options uo = CDL_UGR_TABLE_OPTIONS_DEFAULT;
    if (shr->present && !ugr) {
        fprintf(stderr, "candela info: --ugr-shr: goes with --ugr\n(see 'candela info --help')\n");
        return CDL_EXIT_USAGE;
    }
    if (shr->present && cdl_info_ugr_parse_shr(shr->value, &uo.spacing_to_height) != 0) return CDL_EXIT_USAGE;
    /* Folders, and more than one file, are a batch: a line per file. */
    file_list files = {0};
    int batch = r.positional_count > 1;
    for (size_t i = 0; i < r.positional_count; ++i) {
        struct stat sb;
        int folder = stat(r.positional[i], &sb) == 0 && S_ISDIR(sb.st_mode);
        batch |= folder;
        if (!(folder ? list_folder(&files, r.positional[i], 0) : list_add(&files, r.positional[i]))) {
            list_free(&files);
            fprintf(stderr, "candela info: out of memory\n");
            return CDL_EXIT_INTERNAL;
        }
    }
    if (batch && (plot->present || ugr)) {
        list_free(&files);
        fprintf(stderr, "candela info: --%s: expected one luminaire file, found %zu files and folders\n"
                        "(see 'candela info --help')\n", plot->present ? "plot" : "ugr", r.positional_count);
        return CDL_EXIT_USAGE;
    }
    if (batch) {
        int rc = run_many(&files, json, &ro);
        list_free(&files);
        return fflush(stdout) != 0 ? CDL_EXIT_INTERNAL : rc;
    }
    list_free(&files);
    const char *path = r.positional[0];
    cdl_photometry *p = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = cdl_photometry_read_file(path, &ro, &p, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela info: %s\n", err.message);
        return (int)st;
    }
    cdl_photometry_summary s;
    cdl_photometry_summarize(p, &s);
    int rc = CDL_EXIT_OK;
    cdl_ugr_table table;
    if (ugr && (st = cdl_ugr_table_compute(p, &uo, &table, &err)) != CDL_OK) {
        fprintf(stderr, "candela info: %s: %s\n", path, err.message);
        cdl_photometry_release(p);
        return (int)st;
    }
    if (plot->present) {
        const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
        const char *name = m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? m->ldt_luminaire_name
                                                                       : cdl_photometry_keyword_value(p, "LUMINAIRE");
        char title[300];
        snprintf(title, sizeof title, "%.*s", (int)strcspn(name && *name ? name : path, "\n"),
                 name && *name ? name : path);
        st = cdl_photometry_write_polar_svg(p, title, plot->value, &err);
        if (st != CDL_OK) {
            fprintf(stderr, "candela info: --plot: %s\n", err.message);
            cdl_photometry_release(p);
            return (int)st;
        }
    }
    if (json) {
        cJSON *j = info_json(path, p, &s);
        if (j && ugr) cJSON_AddItemToObject(j, "ugr_table", cdl_info_ugr_json(&table));
        rc = put_json(j);
    } else {
        print_text(path, p, &s);
        if (ugr) {
            printf("\n");
            cdl_info_ugr_print(&table, stdout);
        }
    }
    cdl_photometry_release(p);
    if (fflush(stdout) != 0) {
        fprintf(stderr, "candela info: cannot write the output\n");
        return CDL_EXIT_INTERNAL;
    }
    return rc;
}

const cdl_command cdl_command_info = {"info", "summarise a luminaire file: format, flux, efficacy, beam/field angles, symmetry, max cd", run, print_help};
