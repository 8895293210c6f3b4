/* report_method.c - method and accuracy: what the plan modelled, each light
 * and grid by name (report_sections.h). */
#include "report/report_sections.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Most rows of the direct-light table; the rest are in summary.json's plan. */
#define ROUTE_ROWS_MAX 200
/* Most grids one route row names. */
#define ROUTE_GRIDS_MAX 64

/* The plan's light label with what the scene calls it: "luminaires[0]
 * (Row A, 1 of 4) linear.ies (goniometric)", "luminaires[2] desk lamp
 * (point)". */
static void light_name(const cdl_report_input *in, const cJSON *light, char *out, size_t size)
{
    const cJSON *label = cJSON_GetObjectItemCaseSensitive(light, "light");
    const cJSON *kind = cJSON_GetObjectItemCaseSensitive(light, "kind");
    const char *text = cJSON_IsString(label) ? label->valuestring : "?";
    const char *what = cJSON_IsString(kind) ? kind->valuestring : "";
    size_t entry = 0;
    const cdl_luminaire_spec *l = NULL;
    if (sscanf(text, "luminaires[%zu]", &entry) == 1)
        for (size_t k = 0; k < in->scene->luminaire_count && !l; ++k)
            if (in->scene->luminaires[k].entry == entry) l = &in->scene->luminaires[k];
    /* the name, unless the plan's label has it already, else the file */
    const char *also = l && l->name && !strstr(text, l->name) ? l->name
                       : l && l->file                        ? cdl_report_file_name(l->file)
                                                             : NULL;
    if (also) snprintf(out, size, "%s %s (%s)", text, also, what);
    else snprintf(out, size, "%s (%s)", text, what);
}

/* 1 when g (a grid's route, in a light's "grids") is the first of its
 * light's grids with that route: each route is one row. */
static int first_of_route(const cJSON *grids, const cJSON *g)
{
    if (!cJSON_IsString(g)) return 0;
    for (const cJSON *h = grids->child; h != g; h = h->next)
        if (cJSON_IsString(h) && strcmp(h->valuestring, g->valuestring) == 0) return 0;
    return 1;
}

/* One row per light and route: the grids that light reaches that way. */
static size_t route_rows(const cJSON *direct)
{
    size_t rows = 0;
    for (const cJSON *light = direct->child; light; light = light->next) {
        const cJSON *grids = cJSON_GetObjectItemCaseSensitive(light, "grids");
        for (const cJSON *g = cJSON_IsObject(grids) ? grids->child : NULL; g; g = g->next)
            rows += (size_t)first_of_route(grids, g);
    }
    return rows;
}

static void direct_routes(cdl_report_builder *b, const cdl_report_input *in)
{
    const cJSON *direct = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(in->summary, "plan"), "direct");
    if (!cJSON_IsArray(direct)) return;
    size_t rows = route_rows(direct), shown = rows < ROUTE_ROWS_MAX ? rows : ROUTE_ROWS_MAX;
    if (rows == 0) return;
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "Direct light, as the plan chose it for each light and grid:");
    cdl_report_block *t = cdl_report_table(b, 3, shown + 1, 1);
    cdl_report_cell(b, t, 0, 0, "light");
    cdl_report_cell(b, t, 0, 1, "grids");
    cdl_report_cell(b, t, 0, 2, "how the direct light was computed, and why");
    size_t r = 0;
    for (const cJSON *light = direct->child; light && r < shown; light = light->next) {
        const cJSON *grids = cJSON_GetObjectItemCaseSensitive(light, "grids");
        char name[256];
        light_name(in, light, name, sizeof name);
        for (const cJSON *g = cJSON_IsObject(grids) ? grids->child : NULL; g && r < shown; g = g->next) {
            if (!first_of_route(grids, g)) continue;
            /* every grid this light reaches by the same route */
            char list[ROUTE_GRIDS_MAX * 24] = "";
            size_t used = 0;
            for (const cJSON *h = g; h && used + 1 < sizeof list; h = h->next)
                if (cJSON_IsString(h) && strcmp(h->valuestring, g->valuestring) == 0) {
                    int n = snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", h->string);
                    used = n > 0 && used + (size_t)n < sizeof list ? used + (size_t)n : sizeof list - 1;
                }
            ++r;
            cdl_report_cell(b, t, r, 0, "%s", name);
            cdl_report_cell(b, t, r, 1, "%s", list);
            cdl_report_cell(b, t, r, 2, "%s", g->valuestring);
        }
    }
    if (shown < rows)
        cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0, "And %zu more rows: summary.json's plan lists every light.",
                        rows - shown);
}

static void interreflection(cdl_report_builder *b, const cdl_report_input *in)
{
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
    if (!any) return;
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

void cdl_report_method_section(cdl_report_builder *b, const cdl_report_input *in)
{
    cdl_report_add_block(b, CDL_BLOCK_PAGE_BREAK);
    cdl_report_text(b, CDL_BLOCK_HEADING, 2, "Method and accuracy");
    interreflection(b, in);
    direct_routes(b, in);
    cdl_report_text(b, CDL_BLOCK_PARAGRAPH, 0,
                    "Error statement. Every point's illuminance carries a one-sigma standard error (E_stderr_lx in "
                    "the grid's CSV), zero where the light was computed exactly. The stated errors are calibrated: "
                    "over points with known answers about 95 %% lie within two standard errors of the truth. The "
                    "solve aimed at a relative standard error of %.3g %% per point; the summary gives, per grid, "
                    "the mean and the worst stated error actually reached. The errors are those of the computation "
                    "for the scene as described (geometry, reflectances, photometric files, maintenance factors), "
                    "not of the description itself.",
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
