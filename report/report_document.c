/* report_document.c - the blocks of the report (report_document.h). */
#include "report/report_document.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "base/error_report.h"
#include "base/strings.h"
#include "lights/photometry/photometry_polar.h"
#include "report/report_builder.h"
#include "report/report_daylight.h"
#include "report/report_glare.h"
#include "report/grid_map.h"
#include "report/summary_table.h"
#include "lights/photometry/photometry_metadata.h"

int cdl_report_cell_verdict(const char *cell)
{
    if (!cell) return 0;
    if (strncmp(cell, "pass", 4) == 0) return 1;
    if (strncmp(cell, "FAIL", 4) == 0) return -1;
    return 0;
}

/* ---- 1. cover ----------------------------------------------------------------------- */

/* The scene as the solve was given it (the file read may be its absolute path). */
static const char *scene_name(const cdl_report_input *in)
{
    const char *given = cdl_report_summary_string(in, "scene");
    return given ? given : in->scene->path;
}

static void cover(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_text(b, CDL_BLOCK_HEADING, 1, "%s", b->doc->title);
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
    cdl_report_block *t = cdl_report_table(b, 2, 10, 0);
    const char *method = cdl_report_summary_string(in, "method");
    const char *quality = cdl_report_summary_string(in, "quality");
    size_t r = 0;
    cdl_report_cell(b, t, r, 0, "Scene");
    cdl_report_cell(b, t, r++, 1, "%s", scene_name(in));
    cdl_report_cell(b, t, r, 0, "Results");
    cdl_report_cell(b, t, r++, 1, "%s", in->out_dir);
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
    cdl_report_cell(b, t, r++, 1, "%.0f (results do not depend on it)", cdl_report_summary_number(in, "settings.threads", 0.0));
    cdl_report_cell(b, t, r, 0, "Solve time");
    cdl_report_cell(b, t, r++, 1, "%.1f s, %.4g rays", cdl_report_summary_number(in, "seconds", 0.0),
         cdl_report_summary_number(in, "rays", 0.0));
    cdl_report_cell(b, t, r, 0, "Grids, luminaires");
    cdl_report_cell(b, t, r++, 1, "%zu grids, %zu luminaires of %zu types", in->grid_count, in->scene->luminaire_count,
         in->type_count);
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
}

/* ---- 2. summary --------------------------------------------------------------------- */

static void summary(cdl_report_builder *b, const cdl_report_input *in, const char *requirements_path)
{
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Summary");
    int any_requirements = 0;
    for (size_t g = 0; g < in->grid_count; ++g)
        any_requirements |= in->grids[g].required_Em_lx > 0.0 || in->grids[g].required_U0 > 0.0;
    size_t columns = any_requirements ? 11 : 10;
    cdl_report_block *t = cdl_report_table(b, columns, in->grid_count + 1, 1);
    cdl_report_cell(b, t, 0, 0, "grid");
    for (size_t c = 0; c + 1 < columns; ++c) cdl_report_cell(b, t, 0, c + 1, "%s", cdl_report_row_headings[c]);
    for (size_t g = 0; g < in->grid_count; ++g) {
        cdl_report_row row;
        cdl_report_row_of(&in->grids[g], &row);
        const char *values[9] = {row.Em, row.Emin, row.Emax, row.U0, row.Ud,
                                 row.count, row.spacing, row.error_mean, row.error_max};
        cdl_report_cell(b, t, g + 1, 0, "%s", in->grids[g].spec->name);
        for (size_t c = 0; c < 9; ++c) cdl_report_cell(b, t, g + 1, c + 1, "%s", values[c]);
        if (any_requirements) {
            if (row.has_requirements) cdl_report_cell(b, t, g + 1, 10, "%s; %s", row.verdict, row.requirements);
            else cdl_report_cell(b, t, g + 1, 10, "none given");
        }
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
               "Em is the area-weighted mean illuminance, U0 = Emin / Em the uniformity and Ud = Emin / Emax the "
               "diversity (EN 12464-1), all as summary.json gives them. The errors are the stated one-sigma "
               "relative standard errors of E per point (mean and worst over the points); every number is printed "
               "to the decimal place of its own stated error (Em: Em x the mean error, Emin and Emax: x the worst, "
               "U0 and Ud: the sum of their parts' relative errors), so no digit is shown that the error does not "
               "support.%s%s%s%s",
               any_requirements ? " Requirements (maintained illuminance Em and uniformity U0 for the task area) "
                                  "come from the scene's grids"
                                : "",
               any_requirements && requirements_path ? " and from " : "",
               any_requirements && requirements_path ? requirements_path : "", any_requirements ? "." : "");
}

/* ---- 3. maps ------------------------------------------------------------------------ */

static cdl_status maps(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    cdl_report_document *d = b->doc;
    d->maps = calloc(in->grid_count ? in->grid_count : 1, sizeof *d->maps);
    if (!d->maps) return cdl_error_out_of_memory(err);
    int first = 1;
    for (size_t g = 0; g < in->grid_count; ++g) {
        const cdl_report_grid *grid = &in->grids[g];
        if (grid->spec->kind == CDL_GRID_POINTS || grid->grid.raster_width <= 0) continue;
        cdl_grid_map *m = &d->maps[d->map_count];
        cdl_status st = cdl_grid_map_prepare(m, in, grid, err);
        if (st != CDL_OK) return cdl_error_prefix(err, "the map of grid %s: ", grid->spec->name);
        ++d->map_count;
        if (first) {
            cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
            cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Maps");
            first = 0;
        }
        cdl_report_row row;
        cdl_report_row_of(grid, &row);
        cdl_report_text(b, CDL_BLOCK_HEADING, 3, "%s", grid->spec->name);
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "%s grid, %zu points: Em %s lx, Emin %s lx, Emax %s lx, U0 %s.",
                   grid->spec->kind == CDL_GRID_RECT ? "Rectangular" : "Polygon", grid->count, row.Em, row.Emin,
                   row.Emax, row.U0);
        cdl_report_figure(b, cdl_grid_map_figure(m), 1.0);
    }
    return CDL_OK;
}

/* ---- 4. luminaire schedule ------------------------------------------------------------ */

static const char *kind_name(cdl_luminaire_kind k)
{
    static const char *const names[] = {"point", "spot", "goniometric", "area", "directional", "environment"};
    return (unsigned)k < 6 ? names[k] : "?";
}

/* A keyword's text up to its first line end, or "" (file text of any encoding). */
static void first_line(char *out, size_t size, const char *s)
{
    snprintf(out, size, "%.*s", s ? (int)strcspn(s, "\r\n") : 0, s ? s : "");
}

static void schedule_row(cdl_report_builder *b, cdl_report_block *t, size_t r, const cdl_report_luminaire_type *type)
{
    const cdl_luminaire_spec *l = type->first;
    char mf[48];
    if (type->maintenance_min == type->maintenance_max) snprintf(mf, sizeof mf, "%.3g", type->maintenance_min);
    else snprintf(mf, sizeof mf, "%.3g to %.3g", type->maintenance_min, type->maintenance_max);
    if (!type->photometry) {
        cdl_report_cell(b, t, r, 0, "%s %s%s%s", l->json_path, kind_name(l->kind), l->name ? ": " : "", l->name ? l->name : "");
        for (int c = 1; c < 8; ++c) cdl_report_cell(b, t, r, (size_t)c, "-");
        if (l->kind == CDL_LUMINAIRE_POINT || l->kind == CDL_LUMINAIRE_SPOT || l->kind == CDL_LUMINAIRE_AREA) {
            if (l->has_flux) cdl_report_cell(b, t, r, 4, "%.4g lm", l->flux_lm);
            else if (l->has_intensity) cdl_report_cell(b, t, r, 4, "%.4g cd", l->intensity_cd);
            else if (l->has_luminance) cdl_report_cell(b, t, r, 4, "%.4g cd/m2", l->luminance_cd_m2);
        }
        cdl_report_cell(b, t, r, 8, "%s", mf);
        cdl_report_cell(b, t, r, 9, "%zu", type->count);
        return;
    }
    const cdl_photometry *p = type->photometry;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_summary s;
    cdl_photometry_summary_compute(p, &s);
    char maker[160], catalogue[160], lamp[160];
    first_line(maker, sizeof maker, cdl_photometry_get_text(p, CDL_PHOTOMETRY_MANUFACTURER));
    first_line(catalogue, sizeof catalogue, cdl_photometry_get_text(p, CDL_PHOTOMETRY_CATALOGUE));
    first_line(lamp, sizeof lamp, cdl_photometry_get_text(p, CDL_PHOTOMETRY_LAMP));
    const char *slash = strrchr(l->file, '/');
    cdl_report_cell(b, t, r, 0, "%s", slash ? slash + 1 : l->file);
    cdl_report_cell(b, t, r, 1, "%s", maker[0] ? maker : "-");
    cdl_report_cell(b, t, r, 2, "%s", catalogue[0] ? catalogue : "-");
    cdl_report_cell(b, t, r, 3, "%s", lamp[0] ? lamp : "-");
    /* the luminaire's flux as the solve used it: the table times its ballast (output) factor */
    if (s.radiometric) cdl_report_cell(b, t, r, 4, "%.4g W (radiant)", s.radiant_flux.W * s.output_factor);
    else cdl_report_cell(b, t, r, 4, "%.4g lm", s.luminaire_flux.lm);
    if (m->input_watts > 0.0) cdl_report_cell(b, t, r, 5, "%.4g W", m->input_watts);
    else cdl_report_cell(b, t, r, 5, "-");
    if (s.efficacy_known) cdl_report_cell(b, t, r, 6, "%.4g lm/W", s.efficacy.lm_W);
    else cdl_report_cell(b, t, r, 6, "-");
    cdl_report_cell(b, t, r, 7, "%s", s.lamp_flux_known ? "relative" : "absolute");
    cdl_report_cell(b, t, r, 8, "%s", mf);
    cdl_report_cell(b, t, r, 9, "%zu", type->count);
}

static cdl_status schedule(cdl_report_builder *b, const cdl_report_input *in, cdl_error *err)
{
    cdl_report_document *d = b->doc;
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Luminaire schedule");
    cdl_report_block *t = cdl_report_table(b, 10, in->type_count + 1, 1);
    static const char *const headings[10] = {"luminaire",    "manufacturer", "catalogue", "lamp",
                                             "flux",         "input power",  "efficacy",  "photometry",
                                             "maint. factor", "count"};
    for (size_t c = 0; c < 10; ++c) cdl_report_cell(b, t, 0, c, "%s", headings[c]);
    for (size_t k = 0; k < in->type_count; ++k) schedule_row(b, t, k + 1, &in->types[k]);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
               "Flux is the exact integral of the file's interpolated table (before the maintenance factor and any "
               "scene multiplier); input power and efficacy as the file states them. Polar diagrams: C0-C180 "
               "solid, C90-C270 dashed, in cd/klm (intensity per 1000 lm of the rated lamp flux, or of the "
               "luminaire's flux for absolute photometry).");
    d->diagrams = calloc(in->type_count ? in->type_count : 1, sizeof *d->diagrams);
    if (!d->diagrams) return cdl_error_out_of_memory(err);
    for (size_t k = 0; k < in->type_count; ++k) {
        if (!in->types[k].photometry) continue;
        cdl_polar_diagram *pd = &d->diagrams[d->diagram_count++];
        const char *slash = strrchr(in->types[k].first->file, '/');
        pd->photometry = in->types[k].photometry;
        pd->title = slash ? slash + 1 : in->types[k].first->file;
        cdl_report_figure(b, cdl_polar_diagram_figure(pd), 0.6); /* two to an A4 page */
    }
    return CDL_OK;
}

/* ---- 5. method and accuracy ----------------------------------------------------------- */

/* The distinct direct-light routes of the plan, each with how many
 * (light, grid) pairs took it. */
static void direct_routes(cdl_report_builder *b, const cdl_report_input *in)
{
    const cJSON *plan = cJSON_GetObjectItemCaseSensitive(in->summary, "plan");
    const cJSON *direct = cJSON_GetObjectItemCaseSensitive(plan, "direct");
    if (!cJSON_IsArray(direct)) return;
    enum { MAX_ROUTES = 32 };
    const char *route[MAX_ROUTES];
    size_t uses[MAX_ROUTES], n = 0, others = 0;
    for (const cJSON *light = direct->child; light; light = light->next) {
        const cJSON *grids = cJSON_GetObjectItemCaseSensitive(light, "grids");
        for (const cJSON *g = cJSON_IsObject(grids) ? grids->child : NULL; g; g = g->next) {
            if (!cJSON_IsString(g)) continue;
            size_t k = 0;
            while (k < n && strcmp(route[k], g->valuestring) != 0) ++k;
            if (k == n) {
                if (n == MAX_ROUTES) {
                    ++others;
                    continue;
                }
                route[n] = g->valuestring;
                uses[n++] = 0;
            }
            ++uses[k];
        }
    }
    if (n == 0) return;
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Direct light, as the plan chose it for each light and grid:");
    cdl_report_block *t = cdl_report_table(b, 2, n + 1 + (others ? 1 : 0), 1);
    cdl_report_cell(b, t, 0, 0, "light and grid pairs");
    cdl_report_cell(b, t, 0, 1, "how the direct light was computed, and why");
    for (size_t k = 0; k < n; ++k) {
        cdl_report_cell(b, t, k + 1, 0, "%zu", uses[k]);
        cdl_report_cell(b, t, k + 1, 1, "%s", route[k]);
    }
    if (others) {
        cdl_report_cell(b, t, n + 1, 0, "%zu", others);
        cdl_report_cell(b, t, n + 1, 1, "other routes (see summary.json's plan)");
    }
}

static void method(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Method and accuracy");
    const cJSON *plan = cJSON_GetObjectItemCaseSensitive(in->summary, "plan");
    const cJSON *ir = cJSON_GetObjectItemCaseSensitive(plan, "interreflection");
    const cJSON *why = cJSON_GetObjectItemCaseSensitive(ir, "why");
    const cJSON *modelled = cJSON_GetObjectItemCaseSensitive(ir, "modelled");
    const cJSON *bounces = cJSON_GetObjectItemCaseSensitive(ir, "bounces");
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Interreflection: %s%s%s%s%s%s",
               cJSON_IsTrue(modelled) ? "modelled" : "not modelled", cJSON_IsString(why) ? ": " : "",
               cJSON_IsString(why) ? why->valuestring : "", cJSON_IsString(bounces) ? ". Bounces: " : "",
               cJSON_IsString(bounces) ? bounces->valuestring : "", ".");
    int any = 0;
    for (size_t g = 0; g < in->grid_count; ++g) any |= in->grids[g].interreflection_method != NULL;
    if (any) {
        cdl_report_block *t = cdl_report_table(b, 3, in->grid_count + 1, 1);
        cdl_report_cell(b, t, 0, 0, "grid");
        cdl_report_cell(b, t, 0, 1, "interreflection");
        cdl_report_cell(b, t, 0, 2, "why");
        for (size_t g = 0; g < in->grid_count; ++g) {
            const cdl_report_grid *grid = &in->grids[g];
            cdl_report_cell(b, t, g + 1, 0, "%s", grid->spec->name);
            cdl_report_cell(b, t, g + 1, 1, "%s", grid->interreflection_method ? grid->interreflection_method : "-");
            cdl_report_cell(b, t, g + 1, 2, "%s", grid->interreflection_why ? grid->interreflection_why : "-");
        }
    }
    direct_routes(b, in);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
               "Error statement. Every point's illuminance carries a one-sigma standard error (E_stderr_lx in the "
               "grid's CSV), zero where the light was computed exactly. The stated errors are calibrated: over "
               "points with known answers about 95 %% lie within two standard errors of the truth. The solve "
               "aimed at a relative standard error of %.3g %% per point; the summary gives, per grid, the mean "
               "and the worst stated error actually reached. The errors are those of the computation for the "
               "scene as described (geometry, reflectances, photometric files, maintenance factors), not of the "
               "description itself.",
               100.0 * cdl_report_summary_number(in, "target_error", 0.0));
    const cJSON *warnings = cJSON_GetObjectItemCaseSensitive(in->summary, "warnings");
    size_t w = (size_t)cJSON_GetArraySize(warnings);
    if (w == 0) {
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "The solve gave no warnings.");
        return;
    }
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "The solve gave %zu warning%s:", w, w == 1 ? "" : "s");
    cdl_report_block *t = cdl_report_table(b, 1, w, 0);
    size_t k = 0;
    for (const cJSON *item = warnings->child; item; item = item->next, ++k)
        cdl_report_cell(b, t, k, 0, "%s", cJSON_IsString(item) ? item->valuestring : "?");
}

/* ---- the document --------------------------------------------------------------------- */

cdl_status cdl_report_document_build(const cdl_report_input *in, const char *title, cdl_report_document **out,
                                     cdl_error *err)
{
    *out = NULL;
    cdl_report_document *d = calloc(1, sizeof *d);
    if (!d) return cdl_error_out_of_memory(err);
    cdl_report_builder b = {d, 0};
    if (title) {
        d->title = cdl_string_copy(title);
    } else {
        size_t n = strlen(scene_name(in)) + 32;
        d->title = malloc(n);
        if (d->title) snprintf(d->title, n, "Lighting report: %s", scene_name(in));
    }
    if (!d->title) b.failed = 1;
    cdl_status st = CDL_OK;
    if (!b.failed) {
        cover(&b, in);
        summary(&b, in, in->requirements_path);
        st = maps(&b, in, err);
        if (st == CDL_OK) st = cdl_report_glare_section(&b, in, err);
        if (st == CDL_OK) st = schedule(&b, in, err);
        if (st == CDL_OK) st = cdl_report_glare_tables(&b, in, err);
        if (st == CDL_OK) method(&b, in);
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
    free(d->maps);
    free(d->diagrams);
    cdl_report_glare_plan_release(d->glare_plan);
    cdl_report_images_release(d->images, d->image_count);
    free(d->blocks);
    free(d->title);
    free(d);
}
