/* grid_result_fixture.h - hand-built grids and results for the writer tests
 * (file_fixture.h: a private folder per test and whole-file reads).
 *
 * The grids are made here, not by cdl_grid_build, so the writers are tested
 * on their own. A rect grid follows grid.h: nu x nv points at cell centres,
 * i fastest; raster nu x nv with row 0 at the v = 1 edge.
 */
#ifndef CANDELA_TESTS_GRID_RESULT_FIXTURE_H
#define CANDELA_TESTS_GRID_RESULT_FIXTURE_H

#include <stdlib.h>
#include <string.h>

#include "file_fixture.h"
#include "solver/output/grid_result.h"

typedef struct fixture {
    cdl_grid grid;
    double *E, *E_direct, *E_indirect, *E_stderr, *ao;
    cdl_grid_result result;
} fixture;

/* A rect grid of nu x nv points over size_u x size_v metres at height z,
 * normals +z, weights the cell area, all values zero, no AO. */
static inline int fixture_rect(fixture *f, int nu, int nv, double size_u, double size_v, double z)
{
    memset(f, 0, sizeof *f);
    size_t n = (size_t)nu * (size_t)nv;
    f->grid.count = n;
    f->grid.points = calloc(n ? n : 1, sizeof(cdl_vec3));
    f->grid.normals = calloc(n ? n : 1, sizeof(cdl_vec3));
    f->grid.weights = calloc(n ? n : 1, sizeof(double));
    f->grid.raster_index = calloc(n ? n : 1, sizeof(int32_t));
    f->E = calloc(n ? n : 1, sizeof(double));
    f->E_direct = calloc(n ? n : 1, sizeof(double));
    f->E_indirect = calloc(n ? n : 1, sizeof(double));
    f->E_stderr = calloc(n ? n : 1, sizeof(double));
    if (!f->grid.points || !f->grid.normals || !f->grid.weights || !f->grid.raster_index || !f->E || !f->E_direct ||
        !f->E_indirect || !f->E_stderr)
        return 0;
    f->grid.raster_width = nu;
    f->grid.raster_height = nv;
    f->grid.pixel_size_m = size_u / nu;
    /* Lying along +x and +y from the origin (maps' axes). */
    f->grid.raster_corner = cdl_vec3_make(0, 0, z);
    f->grid.raster_right = cdl_vec3_make(1, 0, 0);
    f->grid.raster_up = cdl_vec3_make(0, 1, 0);
    f->grid.pixel_width_m = size_u / nu;
    f->grid.pixel_height_m = size_v / nv;
    f->grid.spacing_m = size_u / nu;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            size_t k = (size_t)j * (size_t)nu + (size_t)i;
            f->grid.points[k] = cdl_vec3_make((i + 0.5) / nu * size_u, (j + 0.5) / nv * size_v, z);
            f->grid.normals[k] = cdl_vec3_make(0, 0, 1);
            f->grid.weights[k] = size_u / nu * size_v / nv;
            /* raster row r shows v index nv - 1 - r: row 0 is the v = 1 edge */
            f->grid.raster_index[(size_t)(nv - 1 - j) * (size_t)nu + (size_t)i] = (int32_t)k;
        }
    f->result.name = "fixture";
    f->result.grid = &f->grid;
    f->result.E = f->E;
    f->result.E_direct = f->E_direct;
    f->result.E_indirect = f->E_indirect;
    f->result.E_stderr = f->E_stderr;
    return 1;
}

/* Add an AO array (zeros) to the result. */
static inline int fixture_add_ao(fixture *f)
{
    f->ao = calloc(f->grid.count ? f->grid.count : 1, sizeof(double));
    f->result.ao = f->ao;
    return f->ao != NULL;
}

static inline void fixture_free(fixture *f)
{
    free(f->grid.points);
    free(f->grid.normals);
    free(f->grid.weights);
    free(f->grid.raster_index);
    free(f->E);
    free(f->E_direct);
    free(f->E_indirect);
    free(f->E_stderr);
    free(f->ao);
    memset(f, 0, sizeof *f);
}

#endif
