/* solution.c - a solve's results in memory. */
#include "solver/solution.h"

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
    }
    free(s->grids);
    free(s->plan_json);
    memset(s, 0, sizeof *s);
}
