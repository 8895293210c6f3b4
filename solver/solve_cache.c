/* solve_cache.c - a solve's irradiance-cache file (solve_cache.h). */
#include "solver/solve_cache.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/error_report.h"
#include "solver/icache/icache_file.h"
#include "solver/scene/scene_hash.h"

/* A missing cache file is written after the solve: its folder must take it. */
static cdl_status check_cache_folder(const char *path, cdl_error *err)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (slash == path ? 1 : (size_t)(slash - path)) : 1;
    char *folder = malloc(n + 1);
    if (!folder) return cdl_error_out_of_memory(err);
    memcpy(folder, slash ? path : ".", n);
    folder[n] = '\0';
    cdl_status st = CDL_OK;
    if (access(folder, W_OK | X_OK) != 0)
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: cannot write the irradiance cache file there: the folder %s is missing or not "
                           "writable", path, folder);
    free(folder);
    return st;
}

/* The key: everything the records depend on. */
static cdl_status make_key(const cdl_solve_state *state, cdl_icache_key *key, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    snprintf(key->version, sizeof key->version, "%s", CDL_ICACHE_MAKER);
    cdl_icache_settings *ks = &key->settings;
    ks->method = scene->settings.method;
    ks->target = state->target;
    ks->bounces = scene->settings.bounces;
    ks->seed = scene->settings.seed;
    ks->direct_samples = state->out->settings.direct_samples;
    ks->exact_route = !state->debug.no_exact_route;
    ks->gradients = !state->debug.no_cache_gradients;
    return cdl_scene_hash(scene, &state->lights, &key->scene, err);
}

/* Move the records of the file's grids into state->records. */
static cdl_status take_records(cdl_solve_state *state, cdl_icache_file *file, cdl_error *err)
{
    cdl_solve_cache *cache = &state->cache;
    size_t n = cache->count ? cache->count : 1;
    const char **names = malloc(n * sizeof *names);
    const cdl_grid **grids = malloc(n * sizeof *grids);
    size_t *index = malloc(n * sizeof *index);
    cdl_status st = names && grids && index ? cdl_icache_file_match_key(file, cache->path, &cache->key, err)
                                            : cdl_error_out_of_memory(err);
    for (size_t k = 0; st == CDL_OK && k < cache->count; ++k) {
        names[k] = state->scene->grids[cache->grids[k]].name;
        grids[k] = &state->out->grids[cache->grids[k]].grid;
    }
    if (st == CDL_OK) st = cdl_icache_file_match_grids(file, cache->path, names, grids, cache->count, index, err);
    for (size_t k = 0; st == CDL_OK && k < cache->count; ++k) {
        cdl_icache_records *from = &file->grids[index[k]].records;
        state->records[cache->grids[k]] = *from;
        cache->records_read += from->count;
        memset(from, 0, sizeof *from);
    }
    cache->reused = st == CDL_OK;
    free(names);
    free(grids);
    free(index);
    return st;
}

cdl_status cdl_solve_cache_open(cdl_solve_state *state, cdl_error *err)
{
    cdl_solve_cache *cache = &state->cache;
    cache->path = state->options.cache_path;
    if (!cache->path[0]) return cdl_error_set(err, CDL_ERR_USAGE, "cache: expected a file name, found an empty string");
    cdl_status st = make_key(state, &cache->key, err);
    if (st != CDL_OK) return st;
    size_t grid_count = state->scene->grid_count;
    cache->grids = malloc((grid_count ? grid_count : 1) * sizeof *cache->grids);
    if (!cache->grids) return cdl_error_out_of_memory(err);
    for (size_t g = 0; g < grid_count; ++g)
        if (state->grids[g].method == CDL_METHOD_ICACHE) cache->grids[cache->count++] = g;

    int found = 0;
    cdl_icache_file file;
    st = cdl_icache_file_load(cache->path, &found, &file, err);
    if (st != CDL_OK) return st;
    if (!found) return check_cache_folder(cache->path, err);
    st = take_records(state, &file, err);
    cdl_icache_file_release(&file);
    return st;
}

cdl_status cdl_solve_cache_save(const cdl_solve_state *state, cdl_error *err)
{
    const cdl_solve_cache *cache = &state->cache;
    cdl_icache_file_grid *grids = calloc(cache->count ? cache->count : 1, sizeof *grids);
    if (!grids) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < cache->count; ++k) {
        size_t g = cache->grids[k];
        grids[k].name = state->scene->grids[g].name;
        grids[k].point_count = state->out->grids[g].grid.count;
        grids[k].points_hash = cdl_icache_grid_hash(&state->out->grids[g].grid);
        grids[k].records = state->records[g];
    }
    cdl_status st = cdl_icache_file_save(cache->path, &cache->key, grids, cache->count, err);
    free(grids);
    return st;
}

void cdl_solve_cache_release(cdl_solve_cache *cache)
{
    free(cache->grids);
    memset(cache, 0, sizeof *cache);
}
