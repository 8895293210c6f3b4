/* solve_ranks.c - a solve shared by ranks: the public entry points and the steps one process does not need. */
#include "solver/solve_ranks.h"

#include <stdlib.h>
#include <string.h>

#include "base/content_hash.h"
#include "base/error_report.h"
#include "solver/icache/icache_file.h"
#include "solver/pool.h"
#include "solver/scene/scene_hash.h"
#include "solver/solve_internal.h"
#include "solver/solve_ranks_internal.h"

/* Everything the ranks must agree on before they split the work, as one
 * hash: the scene's content (scene_hash.h), every grid's points, outputs
 * and method, the observers, the mapped surfaces and the settings. */
static cdl_status scene_key(const cdl_solve_state *state, uint64_t *key, cdl_error *err)
{
    const cdl_scene *scene = state->scene;
    cdl_scene_hashes parts;
    cdl_status st = cdl_scene_hash(scene, &state->lights, &parts, err);
    if (st != CDL_OK) return st;
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&h, parts.geometry);
    cdl_content_hash_u64(&h, parts.materials);
    cdl_content_hash_u64(&h, parts.lights);
    const cdl_solver_settings *set = &state->out->settings;
    cdl_content_hash_u64(&h, (uint64_t)set->method);
    cdl_content_hash_f64(&h, state->target);
    cdl_content_hash_u64(&h, set->seed);
    cdl_content_hash_u64(&h, (uint64_t)set->bounces);
    cdl_content_hash_u64(&h, (uint64_t)set->direct_samples);
    cdl_content_hash_u64(&h, (uint64_t)set->ao_samples);
    cdl_content_hash_u64(&h, (uint64_t)state->indirect);
    for (size_t g = 0; g < scene->grid_count; ++g) {
        const cdl_grid_spec *spec = &scene->grids[g];
        cdl_content_hash_u64(&h, cdl_icache_grid_hash(&state->out->grids[g].grid));
        cdl_content_hash_u64(&h, state->grids[g].key);
        cdl_content_hash_u64(&h, (uint64_t)state->grids[g].method);
        uint64_t outputs = (uint64_t)spec->want_ao | (uint64_t)spec->want_cylindrical << 1 |
                           (uint64_t)spec->want_semicylindrical << 2 | (uint64_t)spec->want_luminance << 3 |
                           (uint64_t)state->grids[g].vertical_sampled << 4;
        cdl_content_hash_u64(&h, outputs);
    }
    cdl_content_hash_u64(&h, scene->observer_count);
    if (scene->observer_count) cdl_content_hash_u64(&h, cdl_icache_grid_hash(&state->observer_points.grid));
    for (size_t k = 0; k < scene->surface_count; ++k) cdl_content_hash_u64(&h, (uint64_t)scene->surfaces[k].mapped);
    *key = h.value;
    return CDL_OK;
}

cdl_status cdl_solve_ranks_check_scene(cdl_solve_state *state, cdl_error *err)
{
    cdl_rank_group *group = state->ranks;
    if (cdl_rank_group_count(group) == 1) return CDL_OK;
    uint64_t key = 0;
    cdl_status st = cdl_rank_agree(group, scene_key(state, &key, err), err);
    if (st != CDL_OK) return st;
    /* The largest key and its complement's: both match every rank's only
     * when every rank has the same key. Likewise the cache file's use. */
    int reused = state->cache.reused;
    uint64_t v[4] = {key, ~key, (uint64_t)reused, (uint64_t)!reused};
    st = cdl_rank_max_u64(group, v, 4, err);
    if (st != CDL_OK) return st;
    if (v[0] != key || v[1] != ~key)
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: the %d ranks do not hold the same scene: they loaded different scene files, settings, "
                           "photometric files or images, or built different grid points (different builds of "
                           "Candela or of its libraries); every rank must read the same files with the same build",
                           state->scene->path, group->count);
    else if (v[2] && v[3])
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: the cache file is read by some ranks and missing on others: every rank must see the "
                           "same file (a shared folder)",
                           state->options.cache_path);
    /* Every rank reached the same verdict from the same reduced values. */
    if (st != CDL_OK) group->failure_agreed = 1;
    return st;
}

cdl_status cdl_solve_ranks_collect_job(cdl_solve_state *state, cdl_grid_job *job, cdl_error *err)
{
    cdl_rank_group *group = state->ranks;
    if (cdl_rank_group_count(group) == 1) return CDL_OK;
    cdl_grid_solution *gs = job->gs;
    int direct_kept = !cdl_grid_job_direct_everywhere(state, job);
    int vertical = gs->Ez_stderr || gs->Esz_stderr;
    /* What the integrators kept: direct light and the outputs computed
     * with it unless it went everywhere; interreflection and the sampled
     * part of the vertical outputs always. */
    double *arrays[] = {
        direct_kept ? gs->E_direct : NULL,
        direct_kept ? job->var_direct : NULL,
        direct_kept ? gs->ao : NULL,
        direct_kept ? gs->ao_stderr : NULL,
        direct_kept || vertical ? gs->Ez : NULL,
        direct_kept || vertical ? gs->Esz : NULL,
        gs->E_indirect,
        job->var_indirect,
        gs->Ez_stderr,
        gs->Esz_stderr,
    };
    cdl_status st = CDL_OK;
    for (size_t k = 0; st == CDL_OK && k < sizeof arrays / sizeof *arrays; ++k)
        if (arrays[k])
            st = cdl_rank_gather_items(group, arrays[k], sizeof(double), gs->grid.count, CDL_RANK_KEEP_ALIGN, err);
    return st;
}

cdl_status cdl_solve_ranks_report(cdl_solve_state *state, double t0, double cpu0, cdl_error *err)
{
    cdl_rank_report *reports = NULL;
    cdl_status st = cdl_rank_reports_gather(state->ranks, state->threads, t0, cpu0, state->out->compute_seconds,
                                            &reports, err);
    if (st != CDL_OK || !reports) return st;
    state->out->ranks = reports;
    state->out->rank_count = (size_t)cdl_rank_group_count(state->ranks);
    return CDL_OK;
}

/* ---- the public entry points (solve_ranks.h) ----------------------------------------- */

cdl_status cdl_solve_scene_ranks(const cdl_scene *scene, const cdl_solve_options *options, const cdl_ranks *ranks,
                                 cdl_solution **out, int *agreed, cdl_error *err)
{
    *out = NULL;
    if (agreed) *agreed = 0;
    cdl_rank_group group;
    cdl_status st = cdl_rank_group_init(&group, ranks, err);
    if (st != CDL_OK) return st;
    cdl_solution *solution = calloc(1, sizeof *solution);
    if (!solution) return cdl_error_out_of_memory(err);
    st = cdl_solve_scene_shared(scene, options, NULL, &group, solution, err);
    if (agreed) *agreed = st == CDL_OK || group.failure_agreed;
    if (st != CDL_OK || group.rank != 0) {
        free(solution);
        return st;
    }
    *out = solution;
    return CDL_OK;
}

cdl_status cdl_ranks_agree(const cdl_ranks *ranks, cdl_status status, cdl_error *err)
{
    cdl_rank_group group;
    cdl_error bad;
    cdl_status st = cdl_rank_group_init(&group, ranks, &bad);
    if (st != CDL_OK) {
        if (err) *err = bad;
        return st;
    }
    return cdl_rank_agree(&group, status, err);
}
