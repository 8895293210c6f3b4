/* A report map of a real solve (grid_map.h, plan_symbols.h): a floor lit
 * by two 1.2 m x 0.06 m linear luminaires (one turned 90 degrees), a
 * floodlight aimed across the room and a mast carrying two aimed spots,
 * solved (direct light), written and read back as `candela report` reads
 * a folder. On its map:
 *   - each linear luminaire is its opening's footprint: 1.2 m by 0.06 m at
 *     the map's scale, along x for the one, along y for the turned one;
 *   - the floodlight and the spots have aiming lines ending at their aim
 *     points; the two spots share a plan position: a mast;
 *   - no two placed labels overlap, none covers a luminaire's symbol or a
 *     min or max marker, all lie inside the map, and the min and max
 *     values and most contour levels are labelled. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "report/grid_map.h"
#include "report/plan_symbols.h"
#include "report/report_input.h"
#include "solver/output/solution_write.h"
#include "solver/solve.h"

static const char scene_json[] =
    "{\"version\": 1,\n"
    " \"surfaces\": [{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [8, 6, 3], \"inward\": true,"
    "                 \"reflectance\": 0, \"open\": [\"-y\"]}],\n"
    " \"luminaires\": [\n"
    "  {\"type\": \"goniometric\", \"file\": \"linear.ies\", \"position\": [2, 3, 2.8]},\n"
    "  {\"type\": \"goniometric\", \"file\": \"linear.ies\", \"position\": [4.5, 3, 2.8], \"rotation\": [0, 0, 90]},\n"
    "  {\"type\": \"goniometric\", \"file\": \"downlight.ies\", \"position\": [7.5, 0.5, 2.5], \"aim\": [4, 4, 0]},\n"
    "  {\"type\": \"spot\", \"position\": [1, 1, 2.9], \"aim\": [3, 1.5, 0], \"intensity_cd\": 3000,"
    "   \"half_angle\": 30},\n"
    "  {\"type\": \"spot\", \"position\": [1, 1, 2.5], \"aim\": [1.5, 4, 0], \"intensity_cd\": 3000,"
    "   \"half_angle\": 30}],\n"
    " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [0, 0, 0.8], \"u\": [8, 0, 0],"
    "             \"v\": [0, 6, 0], \"nu\": 32, \"nv\": 24}],\n"
    " \"solver\": {\"method\": \"direct\"}}\n";

static int copy_file(const char *from, const char *to)
{
    size_t n = 0;
    char *text = fixture_read_file(from, &n);
    int ok = text && fixture_write_file(to, text);
    free(text);
    return ok;
}

/* Where the map puts a world point (grid_map.c's projection). */
static void page_of(const cdl_grid_map *m, cdl_vec3 p, double *x, double *y)
{
    const cdl_grid *g = &m->grid->grid;
    double rx, ry;
    cdl_grid_map_raster_position(g, p, &rx, &ry);
    *x = m->map_x + rx * g->pixel_width_m * m->metres_to_points;
    *y = m->map_y + ry * g->pixel_height_m * m->metres_to_points;
}

static void extent(const cdl_plan_symbol *s, double *w, double *h)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < s->outline_count; ++k)
        for (int c = 0; c < 2; ++c) {
            lo[c] = fmin(lo[c], s->outline[2 * k + c]);
            hi[c] = fmax(hi[c], s->outline[2 * k + c]);
        }
    *w = hi[0] - lo[0];
    *h = hi[1] - lo[1];
}

static void check_symbols(const cdl_grid_map *m)
{
    CHECK(m->symbol_count == 5);
    if (m->symbol_count != 5) return;
    const double scale = m->metres_to_points, tol = 1e-9 * scale; /* the same doubles, turned and projected */
    double w, h;
    /* the linear luminaire along x (C0, its length), then the one turned 90 degrees */
    CHECK(m->symbols[0].outline_count == 4 && m->symbols[1].outline_count == 4);
    extent(&m->symbols[0], &w, &h);
    CHECK_ABS(w, 1.2 * scale, tol);
    CHECK_ABS(h, 0.06 * scale, tol);
    extent(&m->symbols[1], &w, &h);
    CHECK_ABS(w, 0.06 * scale, tol);
    CHECK_ABS(h, 1.2 * scale, tol);
    CHECK(!m->symbols[0].aimed && !m->symbols[1].aimed && !m->symbols[0].mast);
    /* the floodlight and the two spots: aiming lines to their aim points */
    const cdl_vec3 aims[3] = {{4, 4, 0}, {3, 1.5, 0}, {1.5, 4, 0}};
    for (int k = 0; k < 3; ++k) {
        const cdl_plan_symbol *s = &m->symbols[2 + k];
        double x, y;
        page_of(m, aims[k], &x, &y);
        CHECK_MSG(s->aimed, "luminaire %d has no aiming line", 2 + k);
        CHECK_ABS(s->aim_x, x, 1e-9 * scale); /* the same projection */
        CHECK_ABS(s->aim_y, y, 1e-9 * scale);
    }
    /* the spots share a mast; the floodlight stands alone */
    CHECK(m->symbols[3].mast && m->symbols[4].mast && !m->symbols[2].mast);
}

static void check_labels(const cdl_grid_map *m)
{
    cdl_label_box bounds = {m->map_x, m->map_y, m->map_x + m->map_w, m->map_y + m->map_h};
    size_t placed_levels = 0;
    for (size_t k = 0; k < m->label_count; ++k) {
        const cdl_grid_map_label *l = &m->labels[k];
        if (!l->placed) continue;
        placed_levels += k >= 2;
        const cdl_label_box *b = &l->box;
        CHECK_MSG(b->x0 >= bounds.x0 && b->y0 >= bounds.y0 && b->x1 <= bounds.x1 && b->y1 <= bounds.y1,
                  "label \"%s\" outside the map", l->text);
        for (size_t j = 0; j < k; ++j)
            CHECK_MSG(!m->labels[j].placed || !cdl_label_boxes_clash(b, &m->labels[j].box, 0.0),
                      "labels \"%s\" and \"%s\" overlap", m->labels[j].text, l->text);
        for (size_t s = 0; s < m->symbol_count; ++s)
            CHECK_MSG(!cdl_label_boxes_clash(b, &m->symbols[s].box, 0.0), "label \"%s\" covers luminaire %zu", l->text,
                      s);
        const double mx[2] = {m->min_x, m->max_x}, my[2] = {m->min_y, m->max_y};
        for (int e = 0; e < 2; ++e) {
            cdl_label_box mark = {mx[e] - 4.0, my[e] - 4.0, mx[e] + 4.0, my[e] + 4.0};
            CHECK_MSG(!cdl_label_boxes_clash(b, &mark, 0.0), "label \"%s\" covers the %s marker", l->text,
                      e ? "max" : "min");
        }
    }
    CHECK(m->labels[0].placed && m->labels[1].placed);
    CHECK(strncmp(m->labels[0].text, "min ", 4) == 0 && strncmp(m->labels[1].text, "max ", 4) == 0);
    printf("%zu of %zu contour levels labelled\n", placed_levels, m->level_count);
    CHECK(m->level_count >= 3 && 2 * placed_levels >= m->level_count);
}

int main(void)
{
    char folder[512], path[700], out[700];
    CHECK(fixture_folder("grid_map", folder, sizeof folder));
    snprintf(path, sizeof path, "%s/linear.ies", folder);
    CHECK(copy_file(CANDELA_SOURCE_DIR "/data/office/linear.ies", path));
    snprintf(path, sizeof path, "%s/downlight.ies", folder);
    CHECK(copy_file(CANDELA_SOURCE_DIR "/data/office/downlight.ies", path));
    snprintf(path, sizeof path, "%s/scene.json", folder);
    CHECK(fixture_write_file(path, scene_json));
    snprintf(out, sizeof out, "%s/out", folder);

    cdl_error err;
    cdl_scene *scene = NULL;
    cdl_solution *sol = NULL;
    cdl_report_input *in = NULL;
    CHECK_MSG(cdl_scene_load(path, &scene, &err) == CDL_OK, "%s", err.message);
    if (scene) CHECK_MSG(cdl_solve_scene(scene, NULL, &sol, &err) == CDL_OK, "%s", err.message);
    if (sol) CHECK_MSG(cdl_solution_prepare_folder(out, &err) == CDL_OK, "%s", err.message);
    if (sol) CHECK_MSG(cdl_solution_write(scene, sol, out, NULL, &err) == CDL_OK, "%s", err.message);
    if (sol) CHECK_MSG(cdl_report_input_read(out, NULL, &in, &err) == CDL_OK, "%s", err.message);
    if (in) {
        cdl_grid_map m;
        CHECK_MSG(cdl_grid_map_prepare(&m, in, &in->grids[0], 0, &err) == CDL_OK, "%s", err.message);
        check_symbols(&m);
        check_labels(&m);
        cdl_grid_map_release(&m);
    }
    cdl_report_input_release(in);
    cdl_solution_release(sol);
    cdl_scene_release(scene);
    return check_finish();
}
