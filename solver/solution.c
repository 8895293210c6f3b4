/* solution.c - a solve's results in memory. */
#include "solver/solution.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cdl_status cdl_grid_solution_alloc(cdl_grid_solution *gs, int want_ao, cdl_error *err)
{
    size_t n = gs->grid.count ? gs->grid.count : 1;
    gs->E = calloc(n, sizeof(double));
    gs->E_direct = calloc(n, sizeof(double));
    gs->E_indirect = calloc(n, sizeof(double));
    gs->E_stderr = calloc(n, sizeof(double));
    gs->ao = want_ao ? calloc(n, sizeof(double)) : NULL;
    if (!gs->E || !gs->E_direct || !gs->E_indirect || !gs->E_stderr || (want_ao && !gs->ao))
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

void cdl_solution_release(cdl_solution *s)
{
    if (!s) return;
    for (size_t g = 0; g < s->grid_count && s->grids; ++g) {
        cdl_grid_solution *gs = &s->grids[g];
        cdl_grid_release(&gs->grid);
        free(gs->E);
        free(gs->E_direct);
        free(gs->E_indirect);
        free(gs->E_stderr);
        free(gs->ao);
        free(gs->Ez);
        free(gs->Esz);
        free(gs->Ez_stderr);
        free(gs->Esz_stderr);
        free(gs->L);
        free(gs->rho);
        free(gs->DF);
    }
    free(s->grids);
    free(s->plan_json);
    for (size_t i = 0; i < s->warning_count; ++i) free(s->warnings[i]);
    free(s->warnings);
    memset(s, 0, sizeof *s);
}
