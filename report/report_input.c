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

/* Parse NAME.csv into E and E_stderr, checking its points against the grid. */
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
    size_t n = g->grid.count;
    g->E = malloc((n ? n : 1) * sizeof *g->E);
    g->E_stderr = malloc((n ? n : 1) * sizeof *g->E_stderr);
    if (!g->E || !g->E_stderr) {
        free(text);
        return cdl_error_out_of_memory(err);
    }
    if (strncmp(text, csv_header, sizeof csv_header - 1) != 0 ||
        (text[sizeof csv_header - 1] != '\n' && text[sizeof csv_header - 1] != ','))
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s:1: expected the header %s..., found another", path, csv_header);
    const char *line = strchr(text, '\n');
    size_t row = 0;
    while (st == CDL_OK && line && line[1]) {
        ++line;
        double v[10];
        char *end = (char *)line;
        int ok = 1;
        for (int k = 0; k < 10 && ok; ++k) {
            const char *start = end;
            v[k] = strtod(start, &end);
            int separated = k == 9 ? *end == '\n' || *end == ',' || *end == '\0' : *end == ',';
            ok = end != start && isfinite(v[k]) && separated;
            if (ok && k < 9) ++end;
        }
        if (!ok) {
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%zu: expected 10 finite numbers separated by commas", path,
                               row + 2);
            break;
        }
        if (row >= n) {
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: stale: more rows than the %zu points the scene's grid %s has (solve again)", path,
                               n, g->spec->name);
            break;
        }
        cdl_vec3 p = g->grid.points[row];
        if (!same_coordinate(v[0], p.x) || !same_coordinate(v[1], p.y) || !same_coordinate(v[2], p.z)) {
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s:%zu: stale: the point (%.17g, %.17g, %.17g) is not the scene's point %zu of grid %s "
                               "(%.17g, %.17g, %.17g): the scene changed after the solve (solve again)",
                               path, row + 2, v[0], v[1], v[2], row, g->spec->name, p.x, p.y, p.z);
            break;
        }
        g->E[row] = v[6];
        g->E_stderr[row] = v[9];
        ++row;
        line = strchr(end, '\n');
    }
    free(text);
    if (st == CDL_OK && row != n)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: stale: %zu rows, the scene's grid %s has %zu points (solve again)",
                           path, row, g->spec->name, n);
    return st;
}

/* The statistics of the CSV's E equal summary.json's (the same doubles
 * summed in the same order give the same sums; 1e-12 relative forgives
 * nothing a real change could hide behind). */
static cdl_status check_against_summary(const char *csv, const char *summary, cdl_report_grid *g, cdl_error *err)
{
    cdl_grid_result r = {.name = g->spec->name, .grid = &g->grid, .E = g->E, .E_direct = g->E, .E_indirect = g->E,
                         .E_stderr = g->E_stderr};
    cdl_grid_stats s;
    cdl_grid_result_stats(&r, &s);
    struct {
        const char *what;
        double csv, summary;
    } pairs[] = {{"count", (double)s.count, (double)g->count}, {"E_avg_lx", s.E_avg_lx, g->Em},
                 {"E_min_lx", s.E_min_lx, g->Emin},        {"E_max_lx", s.E_max_lx, g->Emax}};
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; ++k)
        if (fabs(pairs[k].csv - pairs[k].summary) > 1e-12 * fmax(fabs(pairs[k].csv), fabs(pairs[k].summary)))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: stale: its %s is %.17g, %s says %.17g (the files come from different solves: "
                                 "solve again)",
                                 csv, pairs[k].what, pairs[k].csv, summary, pairs[k].summary);
    g->min_index = g->max_index = 0;
    for (size_t i = 1; i < g->grid.count; ++i) {
        if (g->E[i] < g->E[g->min_index]) g->min_index = i;
        if (g->E[i] > g->E[g->max_index]) g->max_index = i;
    }
    return CDL_OK;
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
        if (st == CDL_OK) st = check_against_summary(csv, in->summary_path, g, err);
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

cdl_status cdl_report_input_read(const char *out_dir, const char *requirements_path, cdl_report_input **out,
                                 cdl_error *err)
{
    *out = NULL;
    cdl_report_input *in = calloc(1, sizeof *in);
    if (!in) return cdl_error_out_of_memory(err);
    in->out_dir = cdl_string_copy(out_dir);
    in->summary_path = cdl_path_join(out_dir, "summary", ".json");
    cdl_status st = in->out_dir && in->summary_path ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = read_summary(in, err);
    if (st == CDL_OK) st = load_scene(in, err);
    if (st == CDL_OK) st = read_grids(in, err);
    if (st == CDL_OK && requirements_path) {
        in->requirements_path = cdl_string_copy(requirements_path);
        st = in->requirements_path ? read_requirements(in, requirements_path, err) : cdl_error_out_of_memory(err);
    }
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
        free(in->grids[k].E);
        free(in->grids[k].E_stderr);
    }
    for (size_t k = 0; k < in->type_count; ++k) cdl_photometry_release(in->types[k].photometry);
    free(in->grids);
    free(in->types);
    free(in->observers);
    cdl_scene_release(in->scene);
    cJSON_Delete(in->summary);
    free(in->summary_path);
    free(in->requirements_path);
    free(in->out_dir);
    free(in);
}
