/* solution.c - a solve's results in memory, and the public accessors of solution.h. */
#include "solver/solution_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/sized_struct.h"

cdl_status cdl_grid_solution_alloc(cdl_grid_solution *gs, int want_ao, cdl_error *err)
{
    size_t n = gs->grid.count ? gs->grid.count : 1;
    gs->E = calloc(n, sizeof(double));
    gs->E_direct = calloc(n, sizeof(double));
    gs->E_indirect = calloc(n, sizeof(double));
    gs->E_stderr = calloc(n, sizeof(double));
    gs->ao = want_ao ? calloc(n, sizeof(double)) : NULL;
    gs->ao_stderr = want_ao ? calloc(n, sizeof(double)) : NULL;
    if (!gs->E || !gs->E_direct || !gs->E_indirect || !gs->E_stderr || (want_ao && (!gs->ao || !gs->ao_stderr)))
        return cdl_error_out_of_memory(err);
    return CDL_OK;
}

cdl_status cdl_grid_solution_alloc_outputs(cdl_grid_solution *gs, const cdl_grid_spec *spec, cdl_error *err)
{
    size_t n = gs->grid.count ? gs->grid.count : 1;
    if (spec->want_cylindrical && !(gs->Ez = calloc(n, sizeof(double)))) return cdl_error_out_of_memory(err);
    if (spec->want_semicylindrical && !(gs->Esz = calloc(n, sizeof(double)))) return cdl_error_out_of_memory(err);
    if (spec->want_luminance &&
        (!(gs->L = calloc(n, sizeof(double))) || !(gs->rho = calloc(n, sizeof(double)))))
        return cdl_error_out_of_memory(err);
    if (spec->want_daylight_factor && !(gs->DF = calloc(n, sizeof(double)))) return cdl_error_out_of_memory(err);
    return CDL_OK;
}

cdl_status cdl_solution_add_warning(cdl_solution *s, cdl_error *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char **grown = realloc(s->warnings, (s->warning_count + 1) * sizeof *grown);
    if (!grown) return cdl_error_out_of_memory(err);
    s->warnings = grown;
    char *text = malloc((size_t)(n > 0 ? n : 0) + 1);
    if (!text) return cdl_error_out_of_memory(err);
    va_start(ap, fmt);
    vsnprintf(text, (size_t)(n > 0 ? n : 0) + 1, fmt, ap);
    va_end(ap);
    s->warnings[s->warning_count++] = text;
    return CDL_OK;
}

cdl_status cdl_grid_solution_alloc_vertical_stderr(cdl_grid_solution *gs, cdl_error *err)
{
    size_t n = gs->grid.count ? gs->grid.count : 1;
    if (gs->Ez && !(gs->Ez_stderr = calloc(n, sizeof(double)))) return cdl_error_out_of_memory(err);
    if (gs->Esz && !(gs->Esz_stderr = calloc(n, sizeof(double)))) return cdl_error_out_of_memory(err);
    return CDL_OK;
}

void cdl_grid_solution_release(cdl_grid_solution *gs)
{
    free(gs->name);
    cdl_grid_release(&gs->grid);
    free(gs->E);
    free(gs->E_direct);
    free(gs->E_indirect);
    free(gs->E_stderr);
    free(gs->ao);
    free(gs->ao_stderr);
    free(gs->Ez);
    free(gs->Esz);
    free(gs->Ez_stderr);
    free(gs->Esz_stderr);
    free(gs->L);
    free(gs->rho);
    free(gs->DF);
    memset(gs, 0, sizeof *gs);
}

void cdl_solution_clear(cdl_solution *s)
{
    if (!s) return;
    for (size_t g = 0; g < s->grid_count && s->grids; ++g) cdl_grid_solution_release(&s->grids[g]);
    free(s->grids);
    for (size_t k = 0; k < s->surface_count && s->surfaces; ++k) {
        cdl_surface_solution *m = &s->surfaces[k];
        free(m->xyz);
        free(m->normal);
        free(m->triangles);
        free(m->E);
        free(m->E_direct);
        free(m->E_indirect);
        free(m->E_stderr);
        free(m->rho);
        free(m->L);
    }
    free(s->surfaces);
    for (size_t k = 0; k < s->shape_count && s->shapes; ++k) {
        free(s->shapes[k].xyz);
        free(s->shapes[k].normal);
        free(s->shapes[k].triangles);
    }
    free(s->shapes);
    free(s->plan_json);
    for (size_t i = 0; i < s->warning_count; ++i) free(s->warnings[i]);
    free(s->warnings);
    for (size_t i = 0; i < s->observer_count && s->observers; ++i) {
        free(s->observers[i].sources);
        free(s->observers[i].excluded);
    }
    free(s->observers);
    free(s->ranks);
    memset(s, 0, sizeof *s);
}

void cdl_solution_release(cdl_solution *s)
{
    cdl_solution_clear(s);
    free(s);
}

/* ---- the public accessors (solution.h) ------------------------------------------- */

void cdl_solution_get_info(const cdl_solution *s, cdl_solution_info *info)
{
    cdl_solution_info all = {.size = sizeof all,
                             .method = s->method,
                             .quality = s->settings.quality,
                             .target_error = s->target_error,
                             .seed = s->settings.seed,
                             .threads = s->threads_used,
                             .seconds = s->seconds,
                             .compute_seconds = s->compute_seconds,
                             .rays = s->rays,
                             .records = s->records,
                             .records_gathered = s->records_gathered,
                             .cache_reused = s->cache_reused,
                             .installed_w = s->power.installed_w,
                             .luminaires_with_watts = s->power.luminaires_counted,
                             .luminaires_without_watts = s->power.luminaires_without_watts,
                             .ranks = s->rank_count > 0 ? (int)s->rank_count : 1};
    cdl_sized_struct_fill(info, &all, sizeof all);
}

size_t cdl_solution_grid_count(const cdl_solution *s)
{
    return s->grid_count;
}

static const cdl_grid_solution *grid_at(const cdl_solution *s, size_t grid)
{
    return grid < s->grid_count ? &s->grids[grid] : NULL;
}

const char *cdl_solution_grid_name(const cdl_solution *s, size_t grid)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    return gs ? gs->name : NULL;
}

size_t cdl_solution_grid_point_count(const cdl_solution *s, size_t grid)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    return gs ? gs->grid.count : 0;
}

const cdl_vec3 *cdl_solution_grid_points(const cdl_solution *s, size_t grid)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    return gs ? gs->grid.points : NULL;
}

const cdl_vec3 *cdl_solution_grid_normals(const cdl_solution *s, size_t grid)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    return gs ? gs->grid.normals : NULL;
}

const double *cdl_solution_grid_weights(const cdl_solution *s, size_t grid)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    return gs ? gs->grid.weights : NULL;
}

const double *cdl_solution_grid_values(const cdl_solution *s, size_t grid, cdl_grid_quantity quantity)
{
    const cdl_grid_solution *gs = grid_at(s, grid);
    if (!gs) return NULL;
    switch (quantity) {
    case CDL_GRID_E: return gs->E;
    case CDL_GRID_E_DIRECT: return gs->E_direct;
    case CDL_GRID_E_INDIRECT: return gs->E_indirect;
    case CDL_GRID_E_STDERR: return gs->E_stderr;
    case CDL_GRID_AO: return gs->ao;
    case CDL_GRID_AO_STDERR: return gs->ao_stderr;
    case CDL_GRID_EZ: return gs->Ez;
    case CDL_GRID_EZ_STDERR: return gs->Ez_stderr;
    case CDL_GRID_ESZ: return gs->Esz;
    case CDL_GRID_ESZ_STDERR: return gs->Esz_stderr;
    case CDL_GRID_L: return gs->L;
    case CDL_GRID_DF: return gs->DF;
    }
    return NULL;
}

const char *cdl_solution_plan_json(const cdl_solution *s)
{
    return s->plan_json ? s->plan_json : "{}";
}

size_t cdl_solution_warning_count(const cdl_solution *s)
{
    return s->warning_count;
}

const char *cdl_solution_warning(const cdl_solution *s, size_t index)
{
    return index < s->warning_count ? s->warnings[index] : NULL;
}
