/* intensity_map.c - an emitter's intensity on a grid over the octahedral map. */
#include "lights/emitters/intensity_map.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/octahedral.h"

struct cdl_intensity_map {
    int resolution;
    double scale;   /* resolution - 1: node spacing 1 / scale in (u, v) */
    float *I;       /* resolution^2 nodes, row j (v = j / scale) of nodes i (u = i / scale), cd */
};

cdl_status cdl_intensity_map_build(const cdl_emitter *emitter, int resolution, cdl_intensity_map **out,
                                   cdl_error *err)
{
    *out = NULL;
    if (resolution < 2)
        return cdl_error_set(err, CDL_ERR_USAGE, "intensity map: expected a resolution of at least 2, found %d",
                             resolution);
    cdl_intensity_map *m = malloc(sizeof *m);
    float *I = malloc((size_t)resolution * (size_t)resolution * sizeof *I);
    if (!m || !I) {
        free(m);
        free(I);
        return cdl_error_out_of_memory(err);
    }
    m->resolution = resolution;
    m->scale = (double)(resolution - 1);
    m->I = I;
    for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
            double cd = cdl_emitter_intensity(emitter, cdl_intensity_map_node_direction(m, i, j)).cd;
            I[(size_t)j * (size_t)resolution + (size_t)i] = cd > 0.0 && isfinite(cd) ? (float)cd : 0.0f;
        }
    *out = m;
    return CDL_OK;
}

void cdl_intensity_map_release(cdl_intensity_map *map)
{
    if (!map) return;
    free(map->I);
    free(map);
}

cdl_luminous_intensity cdl_intensity_map_lookup(const cdl_intensity_map *m, cdl_vec3 dir)
{
    double u, v;
    cdl_octahedral_encode(dir, &u, &v);
    /* Bilinear between the four nodes around (u, v); the last cell takes
     * u = 1 (and v = 1) so that the index stays inside. */
    double fx = u * m->scale, fy = v * m->scale;
    int last = m->resolution - 2;
    int i = fx <= 0.0 ? 0 : (int)fx, j = fy <= 0.0 ? 0 : (int)fy;
    if (i > last) i = last;
    if (j > last) j = last;
    double tx = fx - i, ty = fy - j;
    const float *row = &m->I[(size_t)j * (size_t)m->resolution + (size_t)i];
    const float *next = row + m->resolution;
    double a = row[0] + tx * (row[1] - row[0]), b = next[0] + tx * (next[1] - next[0]);
    double I = a + ty * (b - a);
    return cdl_candelas(I > 0.0 ? I : 0.0);
}

cdl_vec3 cdl_intensity_map_node_direction(const cdl_intensity_map *m, int i, int j)
{
    return cdl_octahedral_decode((double)i / m->scale, (double)j / m->scale);
}

cdl_luminous_intensity cdl_intensity_map_node(const cdl_intensity_map *m, int i, int j)
{
    return cdl_candelas(m->I[(size_t)j * (size_t)m->resolution + (size_t)i]);
}

int cdl_intensity_map_resolution(const cdl_intensity_map *m)
{
    return m->resolution;
}
