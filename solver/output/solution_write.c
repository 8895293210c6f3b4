/* solution_write.c - the files of a solve: per grid CSV, EXR, PNG; summary.json. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "solver/output/solution_write.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/atomic_file.h"
#include "base/error_report.h"
#include "base/sized_struct.h"
#include "base/strings.h"
#include "solver/output/glare_output.h"
#include "solver/output/json_numbers.h"
#include "solver/output/grid_result.h"
#include "solver/output/ranks_json.h"
#include "solver/output/surface_output.h"
#include "solver/scene/scene_internal.h"
#include "solver/solution_internal.h"

/* Errors of the file system that are the machine's, not the path's. */
static cdl_status folder_failure_status(int code)
{
    return code == ENOSPC || code == EIO || code == ENOMEM || code == EDQUOT ? CDL_ERR_INTERNAL : CDL_ERR_INPUT;
}

/* What a path that is not a folder is, for messages. */
static const char *kind_of(const struct stat *sb)
{
    return S_ISREG(sb->st_mode) ? "a file" : "something that is not a folder";
}

cdl_status cdl_solution_prepare_folder(const char *out_dir, cdl_error *err)
{
    if (!out_dir || !out_dir[0])
        return cdl_error_set(err, CDL_ERR_INPUT, "expected a folder for the results, found an empty name");
    size_t n = strlen(out_dir);
    char *buf = malloc(n + 1);
    if (!buf) return cdl_error_out_of_memory(err);
    memcpy(buf, out_dir, n + 1);
    cdl_status st = CDL_OK;
    struct stat sb;
    /* mkdir -p, one component at a time; an existing component must be a folder. */
    for (size_t i = 1; i <= n && st == CDL_OK; ++i) {
        if (buf[i] != '/' && buf[i] != '\0') continue;
        char saved = buf[i];
        buf[i] = '\0';
        if (mkdir(buf, 0777) != 0) {
            int code = errno;
            if (code != EEXIST)
                st = cdl_error_set(err, folder_failure_status(code), "%s: cannot create the folder for the results%s%s: %s",
                                   out_dir, i < n ? " at " : "", i < n ? buf : "", strerror(code));
            else if (stat(buf, &sb) == 0 && !S_ISDIR(sb.st_mode))
                st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a folder for the results, found %s%s%s", out_dir,
                                   kind_of(&sb), i < n ? " at " : "", i < n ? buf : "");
        }
        buf[i] = saved;
    }
    free(buf);
    if (st != CDL_OK) return st;
    if (stat(out_dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a folder for the results, found something else", out_dir);
    /* Find out now, not after a long solve, that nothing can be written there. */
    if (access(out_dir, W_OK | X_OK) != 0) {
        int code = errno;
        return cdl_error_set(err, folder_failure_status(code), "%s: cannot write into the folder for the results: %s",
                             out_dir, strerror(code));
    }
    return CDL_OK;
}

void cdl_grid_solution_result(const cdl_grid_solution *gs, cdl_grid_result *out)
{
    memset(out, 0, sizeof *out);
    out->name = gs->name;
    out->grid = &gs->grid;
    out->E = gs->E;
    out->E_direct = gs->E_direct;
    out->E_indirect = gs->E_indirect;
    out->E_stderr = gs->E_stderr;
    out->ao = gs->ao;
    out->ao_stderr = gs->ao_stderr;
    /* The area each point stands for, for the CSV: polygon grids' points
     * differ (rect grids' are equal, points grids' have none). */
    out->area_m2 = gs->kind == CDL_GRID_POLYGON ? gs->grid.weights : NULL;
    out->Ez = gs->Ez;
    out->Esz = gs->Esz;
    out->L = gs->L;
    out->DF = gs->DF;
    out->Ez_stderr = gs->Ez_stderr;
    out->Esz_stderr = gs->Esz_stderr;
}

/* "surfaces": the surface maps' statistics (surface_output.h), in the scene's order. */
static void add_surfaces(cJSON *root, const cdl_scene *scene, const cdl_solution *sol)
{
    if (sol->surface_count == 0) return;
    cJSON *list = cJSON_AddArrayToObject(root, "surfaces");
    for (size_t k = 0; k < sol->surface_count; ++k) {
        cdl_surface_stats st;
        cdl_surface_solution_stats(&sol->surfaces[k], &st);
        const cdl_surface_spec *spec = &scene->surfaces[sol->surfaces[k].surface];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", spec->map_name);
        cJSON_AddStringToObject(o, "surface", spec->json_path);
        cJSON_AddNumberToObject(o, "area_m2", st.area_m2);
        cJSON_AddNumberToObject(o, "Em_lx", st.Em_lx);
        cJSON_AddNumberToObject(o, "Emin_lx", st.Emin_lx);
        cJSON_AddNumberToObject(o, "Emax_lx", st.Emax_lx);
        cJSON_AddNumberToObject(o, "U0", st.U0);
        cJSON_AddNumberToObject(o, "L_mean_cd_m2", st.L_mean_cd_m2);
        cJSON_AddNumberToObject(o, "stderr_mean_rel", st.stderr_mean_rel);
        cJSON_AddNumberToObject(o, "vertices", (double)st.vertices);
        cJSON_AddNumberToObject(o, "triangles", (double)st.triangles);
        cJSON_AddItemToArray(list, o);
    }
}

static cdl_status write_summary(const cdl_scene *scene, const cdl_solution *sol, const cdl_grid_stats *stats,
                                const char *path, cdl_error *err)
{
    cJSON *root = cJSON_CreateObject();
    if (!root) return cdl_error_out_of_memory(err);
    cJSON_AddStringToObject(root, "candela_version", CANDELA_VERSION);
    cJSON_AddStringToObject(root, "scene", scene->path);
    /* The same file wherever the reader stands (`candela report` run from
     * another folder finds the scene by it). */
    char *absolute = realpath(scene->path, NULL);
    if (absolute) cJSON_AddStringToObject(root, "scene_absolute_path", absolute);
    free(absolute);
    /* What the results depend on, part by part (scene_inputs.h): the
     * report refuses this folder once the scene no longer matches it. */
    cdl_scene_inputs inputs;
    cdl_status hashed = cdl_scene_inputs_collect(scene, &inputs, err);
    if (hashed != CDL_OK) {
        cJSON_Delete(root);
        return hashed;
    }
    cJSON *inputs_json = cdl_scene_inputs_to_json(&inputs);
    cdl_scene_inputs_release(&inputs);
    if (!inputs_json) {
        cJSON_Delete(root);
        return cdl_error_out_of_memory(err);
    }
    cJSON_AddItemToObject(root, "inputs", inputs_json);
    cJSON *grids = cJSON_AddObjectToObject(root, "grids");
    for (size_t g = 0; g < sol->grid_count; ++g) {
        cJSON *o = cJSON_AddObjectToObject(grids, scene->grids[g].name);
        cJSON_AddNumberToObject(o, "count", (double)stats[g].count);
        cJSON_AddNumberToObject(o, "E_avg_lx", stats[g].E_avg_lx);
        cJSON_AddNumberToObject(o, "E_min_lx", stats[g].E_min_lx);
        cJSON_AddNumberToObject(o, "E_max_lx", stats[g].E_max_lx);
        cJSON_AddNumberToObject(o, "U0", stats[g].U0);
        cJSON_AddNumberToObject(o, "Ud", stats[g].Ud);
        cJSON_AddNumberToObject(o, "stderr_mean_rel", stats[g].stderr_mean_rel);
        cJSON_AddNumberToObject(o, "stderr_max_rel", stats[g].stderr_max_rel);
        cJSON_AddNumberToObject(o, "E_stderr_max_lx", stats[g].stderr_max_lx);
        cJSON_AddNumberToObject(o, "edge_points", (double)sol->grids[g].edge_point_count);
        if (scene->grids[g].kind == CDL_GRID_POLYGON)
            cJSON_AddNumberToObject(o, "spacing_m", sol->grids[g].grid.spacing_m);
        const struct {
            const char *key;
            const double *values;
            const cdl_value_stats *stats;
        } extra[] = {{"Ez", sol->grids[g].Ez, &stats[g].Ez},
                     {"Esz", sol->grids[g].Esz, &stats[g].Esz},
                     {"L", sol->grids[g].L, &stats[g].L},
                     {"DF", sol->grids[g].DF, &stats[g].DF}};
        for (size_t k = 0; k < sizeof extra / sizeof extra[0]; ++k) {
            if (!extra[k].values) continue;
            /* Ez_avg_lx, Ez_min_lx, ...; L_avg_cd_m2, ...; DF_avg_percent, ... */
            const char *unit = k == 2 ? "cd_m2" : k == 3 ? "percent" : "lx";
            char key[32];
            const double v[3] = {extra[k].stats->avg, extra[k].stats->min, extra[k].stats->max};
            const char *what[3] = {"avg", "min", "max"};
            for (int q = 0; q < 3; ++q) {
                snprintf(key, sizeof key, "%s_%s_%s", extra[k].key, what[q], unit);
                cJSON_AddNumberToObject(o, key, v[q]);
            }
            snprintf(key, sizeof key, "%s_U0", extra[k].key);
            cJSON_AddNumberToObject(o, key, extra[k].stats->U0);
            /* A sampled part's worst stated error. */
            const double *err_values = k == 0 ? sol->grids[g].Ez_stderr : k == 1 ? sol->grids[g].Esz_stderr : NULL;
            if (err_values) {
                double worst = 0.0;
                for (size_t i = 0; i < sol->grids[g].grid.count; ++i) worst = fmax(worst, err_values[i]);
                snprintf(key, sizeof key, "%s_stderr_max_lx", extra[k].key);
                cJSON_AddNumberToObject(o, key, worst);
            }
        }
        /* Power density: the power of the luminaires over the grid (their
         * positions projected along its normal fall within it) over its
         * area, when each of their files gives its input watts. */
        if (stats[g].area_m2 > 0.0) {
            const cdl_power_summary *pw = &sol->grids[g].power;
            cJSON_AddNumberToObject(o, "area_m2", stats[g].area_m2);
            cJSON_AddNumberToObject(o, "luminaires_over", (double)(pw->luminaires_counted + pw->luminaires_without_watts));
            if (pw->luminaires_counted > 0 && pw->luminaires_without_watts == 0) {
                cJSON_AddNumberToObject(o, "power_w", pw->installed_w);
                cJSON_AddNumberToObject(o, "power_density_w_m2", pw->installed_w / stats[g].area_m2);
            }
        }
    }
    add_surfaces(root, scene, sol);
    cJSON *power = cJSON_AddObjectToObject(root, "power");
    if (sol->power.luminaires_counted > 0 && sol->power.luminaires_without_watts == 0) {
        cJSON_AddNumberToObject(power, "installed_w", sol->power.installed_w);
        cJSON_AddStringToObject(power, "why", "the sum of the luminaire files' input watts, one per luminaire placed");
    } else {
        cJSON_AddNullToObject(power, "installed_w");
        cJSON_AddStringToObject(power, "why",
                                sol->power.luminaires_counted + sol->power.luminaires_without_watts == 0
                                    ? "the scene has no luminaire (daylight only, or emitting surfaces)"
                                    : "not every luminaire's file gives its input watts (point, spot and area "
                                      "luminaires have none): no total and no W/m2");
        if (sol->power.luminaires_counted > 0)
            cJSON_AddNumberToObject(power, "known_w", sol->power.installed_w);
    }
    cJSON_AddNumberToObject(power, "luminaires_with_watts", (double)sol->power.luminaires_counted);
    cJSON_AddNumberToObject(power, "luminaires_without_watts", (double)sol->power.luminaires_without_watts);
    cJSON_AddStringToObject(root, "method", cdl_method_name(sol->method));
    cJSON_AddStringToObject(root, "quality", cdl_quality_name(sol->settings.quality));
    cJSON_AddNumberToObject(root, "target_error", sol->target_error);
    cJSON *set = cJSON_AddObjectToObject(root, "settings");
    cJSON_AddStringToObject(set, "method", cdl_method_name(sol->settings.method));
    cJSON_AddStringToObject(set, "quality", cdl_quality_name(sol->settings.quality));
    cJSON_AddNumberToObject(set, "target_error", sol->target_error);
    if (sol->settings.bounces == CDL_BOUNCES_AUTO)
        cJSON_AddStringToObject(set, "bounces", "auto");
    else
        cJSON_AddNumberToObject(set, "bounces", sol->settings.bounces);
    cJSON_AddNumberToObject(set, "seed", (double)sol->settings.seed);
    cJSON_AddNumberToObject(set, "threads", sol->threads_used);
    cJSON_AddNumberToObject(set, "direct_samples", sol->settings.direct_samples);
    cJSON_AddNumberToObject(set, "ao_samples", sol->settings.ao_samples);
    cJSON_AddNumberToObject(root, "seconds", sol->seconds);
    cdl_ranks_json_add(root, sol->ranks, sol->rank_count);
    cJSON_AddNumberToObject(root, "rays", (double)sol->rays);
    cJSON *plan = cJSON_Parse(sol->plan_json ? sol->plan_json : "{}");
    if (plan) cJSON_AddItemToObject(root, "plan", plan);
    if (scene->observer_count > 0) {
        cJSON *glare = cdl_glare_summary_json(scene, sol);
        if (!glare) {
            cJSON_Delete(root);
            return cdl_error_out_of_memory(err);
        }
        cJSON_AddItemToObject(root, "glare", glare);
    }
    cJSON *warnings = cJSON_AddArrayToObject(root, "warnings");
    for (size_t w = 0; w < sol->warning_count; ++w) cJSON_AddItemToArray(warnings, cJSON_CreateString(sol->warnings[w]));
    cdl_json_numbers_exact(root);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return cdl_error_out_of_memory(err);

    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st == CDL_OK) {
        fputs(text, f.fp);
        fputc('\n', f.fp);
        st = cdl_atomic_file_commit(&f, err);
    }
    free(text);
    return st;
}

/* OUTDIR/surfaces/NAME.csv and NAME.tri.csv per map, and OUTDIR/scene.glb. */
static cdl_status write_surfaces(const cdl_scene *scene, const cdl_solution *sol, const char *out_dir,
                                 const char *ocio_config, cdl_error *err)
{
    char *folder = cdl_path_join(out_dir, "surfaces", "");
    char *glb = cdl_path_join(out_dir, "scene", ".glb");
    cdl_status st = folder && glb ? cdl_solution_prepare_folder(folder, err) : cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < sol->surface_count; ++k)
        st = cdl_surface_write_csv(&sol->surfaces[k], folder, scene->surfaces[sol->surfaces[k].surface].map_name, err);
    if (st == CDL_OK) st = cdl_surface_write_glb(scene, sol, glb, ocio_config, err);
    free(folder);
    free(glb);
    return st;
}

cdl_status cdl_solution_write(const cdl_scene *scene, const cdl_solution *sol, const char *out_dir,
                              const cdl_solution_write_options *options, cdl_error *err)
{
    cdl_solution_write_options opts = CDL_SOLUTION_WRITE_OPTIONS_INIT;
    cdl_sized_struct_read(&opts, sizeof opts, options);
    const char *ocio_config = opts.ocio_config ? opts.ocio_config : cdl_default_ocio_config();
    cdl_status st = cdl_solution_prepare_folder(out_dir, err);
    if (st != CDL_OK) return st;
    cdl_grid_stats *stats = calloc(sol->grid_count ? sol->grid_count : 1, sizeof *stats);
    if (!stats) return cdl_error_out_of_memory(err);

    /* Settings recorded in every EXR. */
    char seed[32], threads[16], bounces[16], ds[16], as[16], target[32];
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)sol->settings.seed);
    snprintf(threads, sizeof threads, "%d", sol->threads_used);
    if (sol->settings.bounces == CDL_BOUNCES_AUTO)
        snprintf(bounces, sizeof bounces, "auto");
    else
        snprintf(bounces, sizeof bounces, "%d", sol->settings.bounces);
    snprintf(target, sizeof target, "%.17g", sol->target_error);
    snprintf(ds, sizeof ds, "%d", sol->settings.direct_samples);
    snprintf(as, sizeof as, "%d", sol->settings.ao_samples);
    const cdl_key_value attrs[] = {
        {"candela_version", CANDELA_VERSION}, {"scene", scene->path},
        {"method", cdl_method_name(sol->method)}, {"quality", cdl_quality_name(sol->settings.quality)},
        {"target_error", target}, {"seed", seed}, {"threads", threads}, {"bounces", bounces},
        {"direct_samples", ds}, {"ao_samples", as},
    };

    for (size_t g = 0; g < sol->grid_count && st == CDL_OK; ++g) {
        const cdl_grid_solution *gs = &sol->grids[g];
        cdl_grid_result r;
        cdl_grid_solution_result(gs, &r);
        r.map_log_scale = opts.map_log_scale;
        cdl_grid_result_stats(&r, &stats[g]);
        char *csv = cdl_path_join(out_dir, r.name, ".csv");
        char *exr = cdl_path_join(out_dir, r.name, ".exr");
        char *png = cdl_path_join(out_dir, r.name, ".png");
        if (!csv || !exr || !png) {
            st = cdl_error_out_of_memory(err);
        } else {
            st = cdl_grid_result_write_csv(&r, csv, err);
            if (st == CDL_OK && gs->grid.raster_width > 0) {
                st = cdl_grid_result_write_exr(&r, exr, attrs, sizeof attrs / sizeof attrs[0], err);
                if (st == CDL_OK) st = cdl_grid_result_write_png(&r, png, ocio_config, err);
            }
        }
        free(csv);
        free(exr);
        free(png);
    }
    if (st == CDL_OK && sol->surface_count > 0) st = write_surfaces(scene, sol, out_dir, ocio_config, err);
    if (st == CDL_OK && scene->observer_count > 0) {
        char *glare = cdl_path_join(out_dir, "glare", ".csv");
        st = glare ? cdl_glare_write_csv(scene, sol, glare, err) : cdl_error_out_of_memory(err);
        free(glare);
    }
    if (st == CDL_OK) {
        char *summary = cdl_path_join(out_dir, "summary", ".json");
        st = summary ? write_summary(scene, sol, stats, summary, err) : cdl_error_out_of_memory(err);
        free(summary);
    }
    free(stats);
    return st;
}

void cdl_solution_grid_summary(const cdl_solution *solution, size_t grid, cdl_grid_summary *summary)
{
    cdl_grid_summary all = {.size = sizeof all};
    if (grid < solution->grid_count) {
        cdl_grid_result r;
        cdl_grid_solution_result(&solution->grids[grid], &r);
        cdl_grid_stats stats;
        cdl_grid_result_stats(&r, &stats);
        all.count = stats.count;
        all.area_m2 = stats.area_m2;
        all.E_avg_lx = stats.E_avg_lx;
        all.E_min_lx = stats.E_min_lx;
        all.E_max_lx = stats.E_max_lx;
        all.U0 = stats.U0;
        all.Ud = stats.Ud;
        all.stderr_mean_rel = stats.stderr_mean_rel;
        all.stderr_max_rel = stats.stderr_max_rel;
    }
    cdl_sized_struct_fill(summary, &all, sizeof all);
}
