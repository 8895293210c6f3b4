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
#include "info_output.h"
#include "info_ugr.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"

static void print_help(FILE *out)
{
    fputs("usage: candela info LUMINAIRE [--json] [--strict] [--plot OUT.svg] [--ugr [--ugr-shr R]]\n"
          "       candela info FILE_OR_FOLDER... [--json] [--strict]\n"
          "\n"
          "Reads an IES LM-63 (any version) or EULUMDAT file and prints a summary:\n"
          "format and version, photometric type, symmetry, angle grid, lamp and\n"
          "integrated flux, light output ratio, efficacy, maximum intensity and its\n"
          "direction, beam (50 %) and field (10 %) angles, the opening, zonal flux,\n"
          "the CIE flux code, direct ratios, the IES TM-15 BUG rating, warnings.\n"
          "\n"
          "  --json     one JSON object on stdout instead of text (a JSON array for\n"
          "             several files)\n"
          "  --strict   treat warnings (inconsistent header values) as errors\n"
          "  --plot OUT.svg  also draw the polar intensity diagram into OUT.svg (cd/klm,\n"
          "             nadir down: C0-C180 solid, C90-C270 dashed, and the plane\n"
          "             through the peak dotted when it is neither; type B files in\n"
          "             their V and H planes; the scale fitted to the peak, which is\n"
          "             printed with the beam angles)\n"
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
          "Flux is the exact integral of the bilinearly interpolated table. Every\n"
          "flux and intensity is the luminaire's as it lights a scene: the table\n"
          "times its output factor (the IES ballast factor, and LM-63-1995's\n"
          "ballast-lamp factor), the convention `candela solve` uses and the one a\n"
          "converted EULUMDAT file carries in its lamp flux; where the factor is not\n"
          "1 the table's own figures are printed beside them. Angles are in the\n"
          "photometric frame: gamma from nadir, C counter-clockwise seen from above,\n"
          "C0 along the luminaire's photometric horizontal; IES type C horizontal\n"
          "angles H map to C = (360 - H) mod 360 (see `candela convert --help`).\n"
          "Beam (50 %) and field (10 %) angles are full angles about the peak of a\n"
          "plane: the C0-C180 and C90-C270 planes through nadir for a distribution\n"
          "whose maximum is at or near nadir, or that is rotationally symmetric; for\n"
          "one whose maximum lies off nadir (batwing, asymmetric, wall-pack,\n"
          "floodlight) the vertical plane through the peak and the plane across it;\n"
          "null (\"not defined\") when the level is not reached within 180 degrees.\n"
          "Files whose table is in W/sr (a keyword such as [_INTENSITYUNITS] mW/sr:\n"
          "UV and infrared) are reported in W, W/sr and W/m2/sr, never lumens.\n"
          "\n"
          "The CIE flux code (CIE 52) gives N1-N3, the percent of the downward flux\n"
          "within 41.4, 60 and 75.5 degrees of nadir, and N4, N5, the downward and\n"
          "total flux in percent of the lamp flux. Direct ratios are the share of the\n"
          "flux falling directly on the work plane for the room indices of EULUMDAT\n"
          "lines 27-36, computed for a square room whose luminaires are spread over\n"
          "the ceiling at a spacing equal to their height above the work plane (an\n"
          "EULUMDAT file's own ratios are shown beside them). The BUG rating (IES\n"
          "TM-15-11, Addendum A) takes the front as the half towards C0 (IES H0).\n"
          "\n"
          "Warnings carry a stable code, in the text as \"[code] message\" and in\n"
          "JSON as {\"code\", \"line\", \"message\"}; docs/photometry-warnings.md lists\n"
          "every code, what fires it and what to check.\n"
          "\n"
          "JSON keys: file, format, version, photometric_type, symmetry, c_planes,\n"
          "gamma_angles (both as written in the file), stored_planes, lamp_flux_lm\n"
          "(null for absolute photometry), flux_lm and max_intensity_cd (the\n"
          "luminaire's), table_flux_lm and table_max_intensity_cd (the table's),\n"
          "lor (null when unknown), max_intensity_direction, beam_angle_deg and\n"
          "field_angle_deg ({\"c0_c180\", \"c90_c270\"}), downward_fraction,\n"
          "upward_fraction, zone_flux_lm (18 zones of 10 degrees from nadir),\n"
          "efficacy_lm_per_w, input_watts, ballast_factor, output_factor, tilt,\n"
          "opening (its luminance table: average_cd_m2, maximum_cd_m2), keywords,\n"
          "spread_about (\"nadir\" or \"peak\", with spread_axis and the angles' keys\n"
          "vertical_plane and across), direct_ratios ({room_index, computed,\n"
          "stated}), cie_flux_code, bug_rating ({rating, b, u, g, zone_lm}),\n"
          "radiometric, warnings. A radiometric file has radiant_flux_w,\n"
          "max_radiant_intensity_w_sr, zone_flux_w, an opening \"radiance\" table\n"
          "(average_w_m2_sr, maximum_w_m2_sr), a null bug_rating, and null lumens\n"
          "and candela. With --ugr, ugr_table (method, spacing_to_height, height_m,\n"
          "flux_lm, output_factor, reflectances, and rooms: x_h, y_h, luminaires,\n"
          "room_index, direct_floor_lm, direct_walls_lm, direct_ceiling_lm,\n"
          "background_cd_m2, crosswise and endwise, five values each in the\n"
          "order of reflectances).\n"
          "\n"
          "Exit status: 0 success, 1 bad input (any file), 2 usage error.\n", out);
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
                char *file = cdl_info_utf8(path), *message = cdl_info_utf8(err.message);
                cJSON_AddStringToObject(o, "file", file ? file : "");
                cJSON_AddStringToObject(o, "error", message ? message : "");
                free(file);
                free(message);
                cJSON_AddItemToArray(array, o);
            } else {
                printf("FAIL  %s\n", err.message);
            }
            continue;
        }
        cdl_info_figures f;
        int ok = cdl_info_figures_compute(p, json, &f);
        size_t nw = cdl_photometry_warning_count(p);
        warnings += nw;
        warned += nw > 0;
        if (ok && json) cJSON_AddItemToArray(array, cdl_info_json(path, p, &f));
        else if (ok) cdl_info_print_line(path, p, &f);
        cdl_photometry_release(p);
        if (!ok) {
            cJSON_Delete(array);
            free(bad);
            return CDL_EXIT_INTERNAL;
        }
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
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    ro.strict = cdl_cli_find(options, count, "strict")->present;
    int json = cdl_cli_find(options, count, "json")->present;
    const cdl_cli_option *plot = cdl_cli_find(options, count, "plot");
    int ugr = cdl_cli_find(options, count, "ugr")->present;
    const cdl_cli_option *shr = cdl_cli_find(options, count, "ugr-shr");
    cdl_ugr_table_options uo = CDL_UGR_TABLE_OPTIONS_INIT;
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
    cdl_info_figures f;
    if (!cdl_info_figures_compute(p, 1, &f)) {
        fprintf(stderr, "candela info: out of memory\n");
        cdl_photometry_release(p);
        return CDL_EXIT_INTERNAL;
    }
    int rc = CDL_EXIT_OK;
    cdl_ugr_table table = CDL_UGR_TABLE_INIT;
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
        cJSON *j = cdl_info_json(path, p, &f);
        if (j && ugr) cJSON_AddItemToObject(j, "ugr_table", cdl_info_ugr_json(&table));
        rc = put_json(j);
    } else {
        cdl_info_print_text(path, p, &f);
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
