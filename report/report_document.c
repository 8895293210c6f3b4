/* report_document.c - the blocks of the report (report_document.h). */
#include "report/report_document.h"
#include "report/report_surfaces.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "base/error_report.h"
#include "base/strings.h"
#include "report/grid_map.h"
#include "report/report_builder.h"
#include "report/report_daylight.h"
#include "report/report_glare.h"
#include "report/report_sections.h"
#include "report/summary_table.h"

int cdl_report_cell_verdict(const char *cell)
{
    if (!cell) return 0;
    if (strncmp(cell, "pass", 4) == 0) return 1;
    if (strncmp(cell, "FAIL", 4) == 0) return -1;
    return 0;
}

/* ---- the cover ------------------------------------------------------------------- */

/* The title: --title, else the scene's "name", else its file's name
 * without folder and extension ("office" for data/office/office.json). */
static char *make_title(const cdl_report_input *in, const char *title)
{
    if (title) return cdl_string_copy(title);
    if (in->scene->name) return cdl_string_copy(in->scene->name);
    const char *given = cdl_report_summary_string(in, "scene");
    const char *file = cdl_report_file_name(given ? given : in->scene->path);
    const char *dot = strrchr(file, '.');
    return cdl_string_copy_n(file, dot && dot != file ? (size_t)(dot - file) : strlen(file));
}

/* The project block: what the designer signs, from the scene's "project"
 * and a --project file. */
static void project_block(cdl_report_builder *b, const cdl_report_input *in)
{
    const cdl_scene_project *p = &in->project;
    const char *labels[4] = {"Project", "Client", "Designer", "Date"};
    const char *values[4] = {p->project, p->client, p->designer, p->date};
    size_t rows = 0;
    for (size_t k = 0; k < 4; ++k) rows += values[k] != NULL;
    if (rows > 0) {
        cdl_report_block *t = cdl_report_table(b, 2, rows, 0);
        size_t r = 0;
        for (size_t k = 0; k < 4; ++k) {
            if (!values[k]) continue;
            cdl_report_cell(b, t, r, 0, "%s", labels[k]);
            cdl_report_cell(b, t, r++, 1, "%s", values[k]);
        }
    }
    if (p->notes) cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Notes: %s", p->notes);
}

static void cover(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_text(b, CDL_BLOCK_HEADING, 1, "%s", b->doc->title);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Lighting report: illuminance calculation");
    project_block(b, in);
    /* The date of the solve: summary.json's modification time, so that the
     * same folder always gives the same report. */
    char date[64] = "unknown";
    struct stat sb;
    if (stat(in->summary_path, &sb) == 0) {
        struct tm t;
        gmtime_r(&sb.st_mtime, &t);
        strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &t);
    }
    const char *bounces = cdl_report_summary_string(in, "settings.bounces");
    char bounce_text[32];
    if (!bounces) {
        snprintf(bounce_text, sizeof bounce_text, "%g", cdl_report_summary_number(in, "settings.bounces", 0));
        bounces = bounce_text;
    }
    const char *given = cdl_report_summary_string(in, "scene");
    const char *method = cdl_report_summary_string(in, "method");
    const char *quality = cdl_report_summary_string(in, "quality");
    cdl_report_block *t = cdl_report_table(b, 2, 10, 0);
    size_t r = 0;
    cdl_report_cell(b, t, r, 0, "Scene file");
    cdl_report_cell(b, t, r++, 1, "%s", cdl_report_file_name(given ? given : in->scene->path));
    cdl_report_cell(b, t, r, 0, "Results");
    cdl_report_cell(b, t, r++, 1, "%s", cdl_report_file_name(in->out_dir));
    cdl_report_cell(b, t, r, 0, "Solved");
    cdl_report_cell(b, t, r++, 1, "%s", date);
    cdl_report_cell(b, t, r, 0, "Candela");
    cdl_report_cell(b, t, r++, 1, "%s", cdl_report_summary_string(in, "candela_version"));
    cdl_report_cell(b, t, r, 0, "Method");
    cdl_report_cell(b, t, r++, 1, "%s (interreflection: bounces %s)", method ? method : "?", bounces);
    cdl_report_cell(b, t, r, 0, "Quality");
    cdl_report_cell(b, t, r++, 1, "%s, target standard error %.3g %% of E per point", quality ? quality : "?",
                    100.0 * cdl_report_summary_number(in, "target_error", 0.0));
    cdl_report_cell(b, t, r, 0, "Seed");
    cdl_report_cell(b, t, r++, 1, "%.0f", cdl_report_summary_number(in, "settings.seed", 0.0));
    cdl_report_cell(b, t, r, 0, "Threads");
    double threads = cdl_report_summary_number(in, "settings.threads", 0.0);
    double ranks = cdl_report_summary_number(in, "ranks.count", 1.0); /* MPI ranks sharing the solve */
    if (ranks > 1.0)
        cdl_report_cell(b, t, r++, 1, "%.0f on each of %.0f ranks (results depend on neither)", threads, ranks);
    else
        cdl_report_cell(b, t, r++, 1, "%.0f (results do not depend on it)", threads);
    cdl_report_cell(b, t, r, 0, "Solve time");
    cdl_report_cell(b, t, r++, 1, "%.1f s, %.4g rays", cdl_report_summary_number(in, "seconds", 0.0),
                    cdl_report_summary_number(in, "rays", 0.0));
    cdl_report_cell(b, t, r, 0, "Grids, luminaires");
    cdl_report_cell(b, t, r++, 1, "%zu grids, %zu luminaires of %zu types", in->grid_count,
                    in->scene->luminaire_count, in->type_count);
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
}

/* ---- the maps -------------------------------------------------------------------- */

static size_t map_count(const cdl_report_input *in)
{
    size_t n = 0;
    for (size_t g = 0; g < in->grid_count; ++g)
        if (in->grids[g].spec->kind != CDL_GRID_POINTS && in->grids[g].grid.raster_width > 0)
            n += in->grids[g].field_count;
    return n;
}

/* A map of every quantity of every rect and polygon grid. */
static cdl_status maps(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    cdl_report_document *d = b->doc;
    size_t n = map_count(in);
    if (n == 0) return CDL_OK;
    d->maps = calloc(n, sizeof *d->maps);
    if (!d->maps) return cdl_error_out_of_memory(err);
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Maps");
    for (size_t g = 0; g < in->grid_count; ++g) {
        const cdl_report_grid *grid = &in->grids[g];
        if (grid->spec->kind == CDL_GRID_POINTS || grid->grid.raster_width <= 0) continue;
        for (size_t k = 0; k < grid->field_count; ++k) {
            const cdl_report_field *f = &grid->fields[k];
            cdl_grid_map *m = &d->maps[d->map_count];
            cdl_status st = cdl_grid_map_prepare(m, in, grid, k, err);
            if (st != CDL_OK) return cdl_error_prefix(err, "the map of grid %s: ", grid->spec->name);
            ++d->map_count;
            cdl_report_field_text v;
            cdl_report_field_text_of(f, &v);
            const char *u = f->unit[0] ? " " : "";
            /* a heading per map, so that its caption and its figure stay together on a page */
            if (k == 0) cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s", grid->spec->name);
            else cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s: %s", grid->spec->name, f->symbol);
            cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                            "%s grid, %zu points, %s %s: mean %s%s%s, min %s%s%s, max %s%s%s, min / mean %s.",
                            grid->spec->kind == CDL_GRID_RECT ? "Rectangular" : "Polygon", grid->count, f->what,
                            f->symbol, v.mean, u, f->unit, v.min, u, f->unit, v.max, u, f->unit, v.ratio);
            cdl_report_figure(b, cdl_grid_map_figure(m), 1.0);
        }
    }
    return CDL_OK;
}

/* ---- the document --------------------------------------------------------------------- */

cdl_status cdl_report_document_build(const cdl_report_input *in, const cdl_report_options *options,
                                     cdl_report_document **out, cdl_error *err)
{
    *out = NULL;
    cdl_report_document *d = calloc(1, sizeof *d);
    if (!d) return cdl_error_out_of_memory(err);
    cdl_report_builder b = {d, 0};
    d->title = make_title(in, options ? options->title : NULL);
    if (!d->title) b.failed = 1;
    cdl_status st = CDL_OK;
    if (!b.failed) {
        cover(&b, in);
        cdl_report_summary_section(&b, in);
        cdl_report_room_section(&b, in);
        st = cdl_report_luminaire_section(&b, in, err);
        if (st == CDL_OK) st = cdl_report_glare_tables(&b, in, err);
        if (st == CDL_OK) st = maps(&b, in, err);
        struct cdl_report_surfaces *surfaces = NULL;
        if (st == CDL_OK) st = cdl_report_surfaces_read(in, &surfaces, err);
        if (st == CDL_OK) st = cdl_report_surfaces_section(d, in, surfaces, err);
        else cdl_report_surfaces_release(surfaces);
        if (st == CDL_OK) st = cdl_report_glare_section(&b, in, err);
        if (st == CDL_OK && options && options->values) cdl_report_values_section(&b, in);
        if (st == CDL_OK) cdl_report_method_section(&b, in);
    }
    if (st == CDL_OK && b.failed) st = cdl_error_out_of_memory(err);
    if (st != CDL_OK) {
        cdl_report_document_release(d);
        return st;
    }
    *out = d;
    return CDL_OK;
}

void cdl_report_document_release(cdl_report_document *d)
{
    if (!d) return;
    for (size_t k = 0; k < d->count; ++k) {
        cdl_report_block *block = &d->blocks[k];
        free(block->text);
        if (block->cells)
            for (size_t c = 0; c < block->rows * block->columns; ++c) free(block->cells[c]);
        free(block->cells);
    }
    for (size_t k = 0; k < d->map_count; ++k) cdl_grid_map_release(&d->maps[k]);
    cdl_report_surfaces_release(d->surfaces);
    free(d->maps);
    free(d->diagrams);
    cdl_report_glare_plan_release(d->glare_plan);
    cdl_report_images_release(d->images, d->image_count);
    free(d->blocks);
    free(d->title);
    free(d);
}
