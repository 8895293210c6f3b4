/* report_input.c - a solve's folder read back and held to itself (report_input.h). */
#include "report/report_input.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/error_report.h"
#include "base/file_bytes.h"
#include "base/strings.h"
#include "report/report_glare.h"

/* summary.json and a requirements file are small; a CSV holds at most
 * CDL_GRID_MAX_POINTS rows of under 400 bytes. */
#define SUMMARY_MAX_BYTES ((size_t)64 << 20)
#define CSV_MAX_BYTES ((size_t)4 << 30)

static const char csv_header[] = CDL_GRID_CSV_COLUMNS;

static const cJSON *member(const cJSON *object, const char *dotted)
{
    const char *dot = strchr(dotted, '.');
    if (!dot) return cJSON_GetObjectItemCaseSensitive(object, dotted);
    char head[64];
    snprintf(head, sizeof head, "%.*s", (int)(dot - dotted), dotted);
    return cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(object, head), dot + 1);
}

const char *cdl_report_summary_string(const cdl_report_input *in, const char *key)
{
    const cJSON *v = member(in->summary, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

double cdl_report_summary_number(const cdl_report_input *in, const char *key, double fallback)
{
    const cJSON *v = member(in->summary, key);
    return cJSON_IsNumber(v) ? v->valuedouble : fallback;
}

/* ---- summary.json and the scene -------------------------------------------------- */

static cdl_status read_summary(cdl_report_input *in, cdl_error *err)
{
    struct stat sb;
    if (stat(in->out_dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected the folder of a solve's results, found no such folder",
                             in->out_dir);
    if (stat(in->summary_path, &sb) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: not the output of `candela solve`: summary.json is missing (run `candela solve "
                             "SCENE -o %s` first)",
                             in->out_dir, in->out_dir);
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(in->summary_path, "solve summary", SUMMARY_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    in->summary = cJSON_ParseWithLength(text, size);
    free(text);
    if (!cJSON_IsObject(in->summary))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected the JSON object `candela solve` writes, found %s",
                             in->summary_path, in->summary ? "another JSON value" : "text that is not JSON");
    const char *version = cdl_report_summary_string(in, "candela_version");
    if (!version)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: candela_version: missing (not written by `candela solve`)",
                             in->summary_path);
    if (strcmp(version, CANDELA_VERSION) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: written by Candela %s, this is Candela %s: solve the scene again with this version",
                             in->summary_path, version, CANDELA_VERSION);
    if (!cJSON_IsObject(member(in->summary, "grids")))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: grids: missing (expected an object of the grids' statistics)",
                             in->summary_path);
    return CDL_OK;
}

static cdl_status load_scene(cdl_report_input *in, cdl_error *err)
{
    const char *absolute = cdl_report_summary_string(in, "scene_absolute_path");
    const char *given = cdl_report_summary_string(in, "scene");
    struct stat sb;
    const char *path = absolute && stat(absolute, &sb) == 0 ? absolute : given;
    if (!path)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: scene: missing (expected the scene file's path)",
                             in->summary_path);
    if (stat(path, &sb) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: the scene it names, %s, is missing", in->summary_path, path);
    cdl_status st = cdl_scene_load(path, &in->scene, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "%s names the scene: ", in->summary_path);
    return CDL_OK;
}

/* The scene as it is now against what the solve recorded it depended on
 * (scene_inputs.h): a changed part makes every number in the folder stale. */
static cdl_status check_inputs(const cdl_report_input *in, cdl_error *err)
{
    char where[512];
    snprintf(where, sizeof where, "%s: inputs", in->summary_path);
    cdl_scene_inputs then, now;
    cdl_status st = cdl_scene_inputs_from_json(member(in->summary, "inputs"), where, &then, err);
    if (st != CDL_OK) return st;
    st = cdl_scene_inputs_collect(in->scene, &now, err);
    if (st != CDL_OK) {
        cdl_scene_inputs_release(&then);
        return st;
    }
    char changes[1024];
    size_t n = cdl_scene_inputs_describe_changes(&then, &now, changes, sizeof changes);
    if (n > 0 || cdl_scene_inputs_hash(&then) != cdl_scene_inputs_hash(&now))
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: stale: the scene %s changed since the solve: %s (its results no longer describe it: "
                           "solve again)",
                           in->summary_path, in->scene->path, n > 0 ? changes : "its parts differ");
    cdl_scene_inputs_release(&then);
    cdl_scene_inputs_release(&now);
    return st;
}

/* ---- the grids -------------------------------------------------------------------- */

static cdl_status summary_grid_number(const cdl_report_input *in, const cJSON *o, const char *grid, const char *key,
                                      double *out, cdl_error *err)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: grids.%s.%s: expected a number", in->summary_path, grid, key);
    *out = v->valuedouble;
    return CDL_OK;
}

static cdl_status read_summary_grid(const cdl_report_input *in, cdl_report_grid *g, cdl_error *err)
{
    const char *name = g->spec->name;
    const cJSON *o = cJSON_GetObjectItemCaseSensitive(member(in->summary, "grids"), name);
    if (!cJSON_IsObject(o))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: grids.%s: missing, but the scene %s has that grid (the scene changed after the "
                             "solve: solve again)",
                             in->summary_path, name, in->scene->path);
    double count = 0.0;
    cdl_status st = summary_grid_number(in, o, name, "count", &count, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "E_avg_lx", &g->Em, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "E_min_lx", &g->Emin, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "E_max_lx", &g->Emax, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "U0", &g->U0, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "Ud", &g->Ud, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "stderr_mean_rel", &g->stderr_mean_rel, err);
    if (st == CDL_OK) st = summary_grid_number(in, o, name, "stderr_max_rel", &g->stderr_max_rel, err);
    if (st != CDL_OK) return st;
    g->count = (size_t)count;
    const cJSON *spacing = cJSON_GetObjectItemCaseSensitive(o, "spacing_m");
    g->spacing_m = cJSON_IsNumber(spacing) ? spacing->valuedouble : g->grid.spacing_m;
    /* installed power over the grid's area, where every luminaire over it has a wattage */
    const cJSON *area = cJSON_GetObjectItemCaseSensitive(o, "area_m2");
    const cJSON *power = cJSON_GetObjectItemCaseSensitive(o, "power_w");
    const cJSON *density = cJSON_GetObjectItemCaseSensitive(o, "power_density_w_m2");
    const cJSON *over = cJSON_GetObjectItemCaseSensitive(o, "luminaires_over");
    g->area_m2 = cJSON_IsNumber(area) ? area->valuedouble : 0.0;
    g->power_w = cJSON_IsNumber(power) ? power->valuedouble : 0.0;
    g->power_density_w_m2 = cJSON_IsNumber(density) ? density->valuedouble : 0.0;
    g->luminaires_over = cJSON_IsNumber(over) && over->valuedouble >= 0.0 ? (size_t)over->valuedouble : 0;
    const cJSON *plan = member(member(in->summary, "plan"), "interreflection.grids");
    const cJSON *gp = cJSON_GetObjectItemCaseSensitive(plan, name);
    const cJSON *method = cJSON_GetObjectItemCaseSensitive(gp, "method");
    const cJSON *why = cJSON_GetObjectItemCaseSensitive(gp, "why");
    g->interreflection_method = cJSON_IsString(method) ? method->valuestring : NULL;
    g->interreflection_why = cJSON_IsString(why) ? why->valuestring : NULL;
    return CDL_OK;
}

/* Two coordinates equal as the CSV carries them (17 significant digits,
 * read back exactly): a tolerance of 1e-9 m relative to the scene's scale
 * only forgives the last digit of a recomputation. */
static int same_coordinate(double a, double b)
{
    return fabs(a - b) <= 1e-9 * (1.0 + fabs(a) + fabs(b));
}

/* The quantities a grid's CSV carries per point (after the fixed ten, the
 * outputs a grid asks for), with the column of their standard error and
 * the prefix of their statistics in summary.json ("Ez" for Ez_avg_lx). */
static const struct known_field {
    const char *column, *stderr_column, *symbol, *unit, *what, *summary, *summary_unit;
} known_fields[] = {
    {"E_lx", "E_stderr_lx", "E", "lx", "illuminance", "E", "lx"},
    {"Ez_lx", "Ez_stderr_lx", "Ez", "lx", "cylindrical illuminance", "Ez", "lx"},
    {"Esz_lx", "Esz_stderr_lx", "Esz", "lx", "semicylindrical illuminance", "Esz", "lx"},
    {"L_cd_m2", NULL, "L", "cd/m2", "luminance", "L", "cd_m2"},
    {"AO", "AO_stderr", "AO", "", "ambient occlusion (the unoccluded share of the hemisphere)", NULL, NULL},
};
enum { KNOWN_FIELDS = sizeof known_fields / sizeof known_fields[0] };

/* Most columns a CSV may have: the fixed ten and every extra column. */
#define CSV_MAX_COLUMNS 32

/* What each column of a CSV is: the fixed ten, or a field's values or
 * standard errors (column_field/column_is_stderr), or ignored (-1). */
typedef struct csv_layout {
    size_t columns;
    int field[CSV_MAX_COLUMNS];
    int is_stderr[CSV_MAX_COLUMNS];
} csv_layout;

static const struct known_field *known_field_of(const char *name, int *is_stderr)
{
    for (size_t k = 0; k < KNOWN_FIELDS; ++k) {
        if (strcmp(name, known_fields[k].column) == 0) {
            *is_stderr = 0;
            return &known_fields[k];
        }
        if (known_fields[k].stderr_column && strcmp(name, known_fields[k].stderr_column) == 0) {
            *is_stderr = 1;
            return &known_fields[k];
        }
    }
    return NULL;
}

/* The field of `g` for column `name` (values or standard errors), made
 * when new; -1 when the column is not a quantity (area_m2, an unknown
 * error column). */
static int field_for_column(cdl_report_grid *g, const char *name, int *is_stderr)
{
    const struct known_field *k = known_field_of(name, is_stderr);
    if (!k && (strcmp(name, "area_m2") == 0 || strstr(name, "stderr"))) return -1;
    const char *column = k ? k->column : name;
    for (size_t f = 0; f < g->field_count; ++f)
        if (strcmp(g->fields[f].column, column) == 0) return (int)f;
    if (g->field_count == CDL_REPORT_MAX_FIELDS) return -1;
    cdl_report_field *f = &g->fields[g->field_count];
    if (k) {
        *f = (cdl_report_field){.column = k->column, .symbol = k->symbol, .unit = k->unit, .what = k->what};
    } else {
        snprintf(f->column_name, sizeof f->column_name, "%s", name);
        f->column = f->symbol = f->what = f->column_name;
        f->unit = "";
    }
    return (int)g->field_count++;
}

/* The header: the fixed ten, then extra columns, each a field's. */
static cdl_status read_header(const char *path, const char *text, cdl_report_grid *g, csv_layout *layout,
                              cdl_error *err)
{
    size_t fixed = sizeof csv_header - 1;
    if (strncmp(text, csv_header, fixed) != 0 || (text[fixed] != '\n' && text[fixed] != ','))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:1: expected the header %s..., found another", path, csv_header);
    memset(layout, 0, sizeof *layout);
    g->fields[0] = (cdl_report_field){.column = known_fields[0].column, .symbol = "E", .unit = "lx",
                                      .what = known_fields[0].what};
    g->field_count = 1;
    layout->columns = 10;
    for (size_t c = 0; c < 10; ++c) layout->field[c] = -1;
    layout->field[6] = 0;
    layout->field[9] = 0;
    layout->is_stderr[9] = 1;
    const char *p = text + fixed;
    while (*p == ',') {
        const char *start = ++p;
        p += strcspn(p, ",\n");
        char name[32];
        if (layout->columns == CSV_MAX_COLUMNS || (size_t)(p - start) >= sizeof name || p == start)
            return cdl_error_set(err, CDL_ERR_INPUT, "%s:1: expected at most %d column names of under 32 letters",
                                 path, CSV_MAX_COLUMNS);
        snprintf(name, sizeof name, "%.*s", (int)(p - start), start);
        int is_stderr = 0;
        layout->field[layout->columns] = field_for_column(g, name, &is_stderr);
        layout->is_stderr[layout->columns++] = is_stderr;
    }
    return CDL_OK;
}

static cdl_status allocate_fields(cdl_report_grid *g, cdl_error *err)
{
    size_t n = g->grid.count ? g->grid.count : 1;
    for (size_t f = 0; f < g->field_count; ++f) {
        g->fields[f].values = calloc(n, sizeof(double));
        g->fields[f].stderr_values = calloc(n, sizeof(double));
        if (!g->fields[f].values || !g->fields[f].stderr_values) return cdl_error_out_of_memory(err);
    }
    g->E = g->fields[0].values;
    g->E_stderr = g->fields[0].stderr_values;
    return CDL_OK;
}

/* One row of `layout->columns` finite numbers into the point's values. */
static cdl_status read_row(const char *path, size_t row, const char **line, const csv_layout *layout,
                           cdl_report_grid *g, cdl_error *err)
{
    double v[CSV_MAX_COLUMNS];
    char *end = (char *)*line;
    for (size_t k = 0; k < layout->columns; ++k) {
        const char *start = end;
        v[k] = strtod(start, &end);
        int last = k + 1 == layout->columns;
        int separated = last ? *end == '\n' || *end == '\0' : *end == ',';
        if (end == start || !isfinite(v[k]) || !separated)
            return cdl_error_set(err, CDL_ERR_INPUT, "%s:%zu: expected %zu finite numbers separated by commas", path,
                                 row + 2, layout->columns);
        if (!last) ++end;
    }
    cdl_vec3 p = g->grid.points[row];
    if (!same_coordinate(v[0], p.x) || !same_coordinate(v[1], p.y) || !same_coordinate(v[2], p.z))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:%zu: stale: the point (%.17g, %.17g, %.17g) is not the scene's point %zu of grid %s "
                             "(%.17g, %.17g, %.17g): the scene changed after the solve (solve again)",
                             path, row + 2, v[0], v[1], v[2], row, g->spec->name, p.x, p.y, p.z);
    for (size_t k = 0; k < layout->columns; ++k) {
        if (layout->field[k] < 0) continue;
        cdl_report_field *f = &g->fields[layout->field[k]];
        (layout->is_stderr[k] ? f->stderr_values : f->values)[row] = v[k];
    }
    *line = end;
    return CDL_OK;
}

/* Parse NAME.csv into the grid's fields, checking its points against the grid. */
static cdl_status read_csv(const char *path, cdl_report_grid *g, cdl_error *err)
{
    struct stat sb;
    if (stat(path, &sb) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: missing (summary.json lists grid %s; solve again)", path,
                             g->spec->name);
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "grid results", CSV_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    csv_layout layout;
    st = read_header(path, text, g, &layout, err);
    if (st == CDL_OK) st = allocate_fields(g, err);
    size_t n = g->grid.count, row = 0;
    const char *line = strchr(text, '\n');
    while (st == CDL_OK && line && line[1]) {
        ++line;
        if (row >= n) {
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: stale: more rows than the %zu points the scene's grid %s has (solve again)", path,
                               n, g->spec->name);
            break;
        }
        st = read_row(path, row, &line, &layout, g, err);
        ++row;
        line = strchr(line, '\n');
    }
    free(text);
    if (st == CDL_OK && row != n)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: stale: %zu rows, the scene's grid %s has %zu points (solve again)",
                           path, row, g->spec->name, n);
    return st;
}

/* The outputs the scene's grid asks for, each a column of its CSV. */
static cdl_status check_outputs(const char *csv, const cdl_report_grid *g, cdl_error *err)
{
    const struct {
        int wanted;
        const char *column, *output;
    } outputs[] = {{g->spec->want_ao, "AO", "ao"},
                   {g->spec->want_cylindrical, "Ez_lx", "cylindrical"},
                   {g->spec->want_semicylindrical, "Esz_lx", "semicylindrical"},
                   {g->spec->want_luminance, "L_cd_m2", "luminance"}};
    for (size_t k = 0; k < sizeof outputs / sizeof outputs[0]; ++k) {
        int found = 0;
        for (size_t f = 0; f < g->field_count; ++f) found |= strcmp(g->fields[f].column, outputs[k].column) == 0;
        if (outputs[k].wanted && !found)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: stale: no column %s, but the scene's grid %s asks for \"%s\" (solve again)", csv,
                                 outputs[k].column, g->spec->name, outputs[k].output);
    }
    return CDL_OK;
}

/* A field's statistics as the solve computes E's (grid_stats.c), its
 * stated errors relative; L's from E's relative error. */
static void field_stats(cdl_report_grid *g, cdl_report_field *f)
{
    size_t n = g->grid.count;
    if (strcmp(f->column, "L_cd_m2") == 0)
        for (size_t i = 0; i < n; ++i) f->stderr_values[i] = g->E[i] > 0.0 ? f->values[i] * g->E_stderr[i] / g->E[i] : 0.0;
    cdl_grid_result r = {.name = g->spec->name, .grid = &g->grid, .E = f->values, .E_direct = f->values,
                         .E_indirect = f->values, .E_stderr = f->stderr_values};
    cdl_grid_stats s;
    cdl_grid_result_stats(&r, &s);
    f->avg = s.E_avg_lx;
    f->min = s.E_min_lx;
    f->max = s.E_max_lx;
    f->U0 = s.U0;
    f->stderr_mean_rel = s.stderr_mean_rel;
    f->stderr_max_rel = s.stderr_max_rel;
    f->min_index = f->max_index = 0;
    for (size_t i = 1; i < n; ++i) {
        if (f->values[i] < f->values[f->min_index]) f->min_index = i;
        if (f->values[i] > f->values[f->max_index]) f->max_index = i;
    }
}

/* A statistic recomputed from the CSV against summary.json's (the same
 * doubles summed in the same order give the same sums; 1e-12 relative
 * forgives nothing a real change could hide behind). */
static cdl_status same_statistic(const char *csv, const char *summary, const char *what, double from_csv,
                                 double from_summary, cdl_error *err)
{
    if (fabs(from_csv - from_summary) > 1e-12 * fmax(fabs(from_csv), fabs(from_summary)))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: stale: its %s is %.17g, %s says %.17g (the files come from different solves: "
                             "solve again)",
                             csv, what, from_csv, summary, from_summary);
    return CDL_OK;
}

/* Each field's statistics; E's and the outputs summary.json states held to it. */
static cdl_status check_against_summary(const cdl_report_input *in, const char *csv, cdl_report_grid *g,
                                        cdl_error *err)
{
    for (size_t k = 0; k < g->field_count; ++k) field_stats(g, &g->fields[k]);
    const cdl_report_field *E = &g->fields[0];
    cdl_status st = same_statistic(csv, in->summary_path, "count", (double)g->grid.count, (double)g->count, err);
    if (st == CDL_OK) st = same_statistic(csv, in->summary_path, "E_avg_lx", E->avg, g->Em, err);
    if (st == CDL_OK) st = same_statistic(csv, in->summary_path, "E_min_lx", E->min, g->Emin, err);
    if (st == CDL_OK) st = same_statistic(csv, in->summary_path, "E_max_lx", E->max, g->Emax, err);
    g->min_index = E->min_index;
    g->max_index = E->max_index;
    /* the numbers printed are summary.json's */
    g->fields[0].avg = g->Em;
    g->fields[0].min = g->Emin;
    g->fields[0].max = g->Emax;
    g->fields[0].U0 = g->U0;
    const cJSON *o = cJSON_GetObjectItemCaseSensitive(member(in->summary, "grids"), g->spec->name);
    for (size_t k = 1; k < g->field_count && st == CDL_OK; ++k) {
        cdl_report_field *f = &g->fields[k];
        int ignored = 0;
        const struct known_field *known = known_field_of(f->column, &ignored);
        if (!known || !known->summary) continue;
        double *mine[4] = {&f->avg, &f->min, &f->max, &f->U0};
        const char *what[4] = {"avg", "min", "max", "U0"};
        for (int q = 0; q < 4 && st == CDL_OK; ++q) {
            char key[48];
            if (q < 3) snprintf(key, sizeof key, "%s_%s_%s", known->summary, what[q], known->summary_unit);
            else snprintf(key, sizeof key, "%s_U0", known->summary);
            double stated = 0.0;
            st = summary_grid_number(in, o, g->spec->name, key, &stated, err);
            if (st == CDL_OK) st = same_statistic(csv, in->summary_path, key, *mine[q], stated, err);
            *mine[q] = stated;
        }
    }
    return st;
}

static cdl_status read_grids(cdl_report_input *in, cdl_error *err)
{
    const cdl_scene *scene = in->scene;
    in->grids = calloc(scene->grid_count ? scene->grid_count : 1, sizeof *in->grids);
    if (!in->grids) return cdl_error_out_of_memory(err);
    in->grid_count = scene->grid_count;
    /* Every grid of the summary is in the scene. */
    for (const cJSON *o = member(in->summary, "grids")->child; o; o = o->next) {
        int found = 0;
        for (size_t g = 0; g < scene->grid_count && !found; ++g) found = strcmp(scene->grids[g].name, o->string) == 0;
        if (!found)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: grids.%s: the scene %s has no such grid (the scene changed after the solve: "
                                 "solve again)",
                                 in->summary_path, o->string, scene->path);
    }
    for (size_t k = 0; k < scene->grid_count; ++k) {
        cdl_report_grid *g = &in->grids[k];
        g->spec = &scene->grids[k];
        g->required_Em_lx = g->spec->required_Em_lx;
        g->required_U0 = g->spec->required_U0;
        cdl_status st = cdl_grid_build(g->spec, &g->grid, err);
        if (st == CDL_OK) st = read_summary_grid(in, g, err);
        char *csv = cdl_path_join(in->out_dir, g->spec->name, ".csv");
        if (!csv) return cdl_error_out_of_memory(err);
        if (st == CDL_OK) st = read_csv(csv, g, err);
        if (st == CDL_OK) st = check_outputs(csv, g, err);
        if (st == CDL_OK) st = check_against_summary(in, csv, g, err);
        free(csv);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

/* ---- requirements ----------------------------------------------------------------- */

static cdl_status requirement_number(const char *path, const cJSON *o, const char *grid, const char *key, double hi,
                                     double *out, cdl_error *err)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v) return CDL_OK;
    if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble) || !(v->valuedouble > 0.0) || v->valuedouble > hi)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %s.%s: expected a number > 0%s", path, grid, key,
                             hi < 2.0 ? " and <= 1" : "");
    *out = v->valuedouble;
    return CDL_OK;
}

static cdl_status read_requirements(cdl_report_input *in, const char *path, cdl_error *err)
{
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "requirements file", SUMMARY_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    cJSON *root = cJSON_ParseWithLength(text, size);
    free(text);
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: expected a JSON object of grids' requirements, {\"GRID\": {\"Em_lx\": 500, \"U0\": "
                             "0.6}}",
                             path);
    }
    for (const cJSON *o = root->child; o && st == CDL_OK; o = o->next) {
        cdl_report_grid *g = NULL;
        for (size_t k = 0; k < in->grid_count && !g; ++k)
            if (strcmp(in->grids[k].spec->name, o->string) == 0) g = &in->grids[k];
        if (!g) {
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s: %s: the scene %s has no grid of that name", path, o->string,
                               in->scene->path);
            break;
        }
        int keys = 0, unknown = 0;
        for (const cJSON *k = o->child; k; k = k->next, ++keys)
            unknown |= strcmp(k->string, "Em_lx") != 0 && strcmp(k->string, "U0") != 0;
        if (!cJSON_IsObject(o) || keys == 0 || unknown) {
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s: %s: expected {\"Em_lx\": lux, \"U0\": Emin / Em} (one or both)",
                               path, o->string);
            break;
        }
        double Em = 0.0, U0 = 0.0;
        st = requirement_number(path, o, o->string, "Em_lx", 1e12, &Em, err);
        if (st == CDL_OK) st = requirement_number(path, o, o->string, "U0", 1.0, &U0, err);
        if (st == CDL_OK) {
            g->required_Em_lx = Em;
            g->required_U0 = U0;
        }
    }
    cJSON_Delete(root);
    return st;
}

/* ---- luminaire types -------------------------------------------------------------- */

static int same_type(const cdl_luminaire_spec *a, const cdl_luminaire_spec *b)
{
    if (a->kind != b->kind) return 0;
    if (a->kind == CDL_LUMINAIRE_GONIOMETRIC) return strcmp(a->file, b->file) == 0;
    return a->entry == b->entry;
}

const cdl_report_luminaire_type *cdl_report_type_of(const cdl_report_input *in, const cdl_luminaire_spec *l)
{
    for (size_t j = 0; j < in->type_count; ++j)
        if (same_type(in->types[j].first, l)) return &in->types[j];
    return NULL;
}

static cdl_status read_types(cdl_report_input *in, cdl_error *err)
{
    const cdl_scene *scene = in->scene;
    in->types = calloc(scene->luminaire_count ? scene->luminaire_count : 1, sizeof *in->types);
    if (!in->types) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        const cdl_luminaire_spec *l = &scene->luminaires[k];
        cdl_report_luminaire_type *t = NULL;
        for (size_t j = 0; j < in->type_count && !t; ++j)
            if (same_type(in->types[j].first, l)) t = &in->types[j];
        if (!t) {
            t = &in->types[in->type_count++];
            t->first = l;
            t->maintenance_min = t->maintenance_max = l->maintenance_factor;
            if (l->kind == CDL_LUMINAIRE_GONIOMETRIC) {
                cdl_status st = cdl_photometry_read_file(l->file, NULL, &t->photometry, err);
                if (st != CDL_OK) return cdl_error_prefix(err, "%s: ", l->json_path);
            }
        }
        ++t->count;
        t->maintenance_min = fmin(t->maintenance_min, l->maintenance_factor);
        t->maintenance_max = fmax(t->maintenance_max, l->maintenance_factor);
    }
    return CDL_OK;
}

/* ---- the project block ---------------------------------------------------------- */

/* The scene's project, each field replaced by the file's where it gives one. */
static cdl_status read_project(cdl_report_input *in, const char *path, cdl_error *err)
{
    cdl_scene_project file = {0};
    if (path) {
        in->project_path = cdl_string_copy(path);
        if (!in->project_path) return cdl_error_out_of_memory(err);
        cdl_status st = cdl_scene_project_load(path, &file, err);
        if (st != CDL_OK) return st;
    }
    const cdl_scene_project *scene = &in->scene->project;
    char *const *from_file[] = {&file.project, &file.client, &file.designer, &file.date, &file.notes};
    char *const *from_scene[] = {&scene->project, &scene->client, &scene->designer, &scene->date, &scene->notes};
    char **into[] = {&in->project.project, &in->project.client, &in->project.designer, &in->project.date,
                     &in->project.notes};
    int failed = 0;
    for (size_t k = 0; k < sizeof into / sizeof into[0]; ++k) {
        const char *text = *from_file[k] ? *from_file[k] : *from_scene[k];
        *into[k] = text ? cdl_string_copy(text) : NULL;
        failed |= text && !*into[k];
    }
    cdl_scene_project_free(&file);
    return failed ? cdl_error_out_of_memory(err) : CDL_OK;
}

cdl_status cdl_report_input_read(const char *out_dir, const cdl_report_options *options, cdl_report_input **out,
                                 cdl_error *err)
{
    const char *requirements_path = options ? options->requirements_path : NULL;
    *out = NULL;
    cdl_report_input *in = calloc(1, sizeof *in);
    if (!in) return cdl_error_out_of_memory(err);
    in->out_dir = cdl_string_copy(out_dir);
    in->summary_path = cdl_path_join(out_dir, "summary", ".json");
    cdl_status st = in->out_dir && in->summary_path ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = read_summary(in, err);
    if (st == CDL_OK) st = load_scene(in, err);
    if (st == CDL_OK) st = check_inputs(in, err);
    if (st == CDL_OK) st = read_grids(in, err);
    if (st == CDL_OK && requirements_path) {
        in->requirements_path = cdl_string_copy(requirements_path);
        st = in->requirements_path ? read_requirements(in, requirements_path, err) : cdl_error_out_of_memory(err);
    }
    if (st == CDL_OK) st = read_project(in, options ? options->project_path : NULL, err);
    if (st == CDL_OK) st = read_types(in, err);
    if (st == CDL_OK) st = cdl_report_glare_read(in, err);
    if (st != CDL_OK) {
        cdl_report_input_release(in);
        return st;
    }
    *out = in;
    return CDL_OK;
}

void cdl_report_input_release(cdl_report_input *in)
{
    if (!in) return;
    for (size_t k = 0; k < in->grid_count; ++k) {
        cdl_grid_release(&in->grids[k].grid);
        for (size_t f = 0; f < in->grids[k].field_count; ++f) {
            free(in->grids[k].fields[f].values);
            free(in->grids[k].fields[f].stderr_values);
        }
    }
    for (size_t k = 0; k < in->type_count; ++k) cdl_photometry_release(in->types[k].photometry);
    free(in->grids);
    free(in->types);
    free(in->observers);
    cdl_scene_release(in->scene);
    cJSON_Delete(in->summary);
    free(in->summary_path);
    free(in->requirements_path);
    cdl_scene_project_free(&in->project);
    free(in->project_path);
    free(in->out_dir);
    free(in);
}
