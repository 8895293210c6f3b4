/* report_surfaces.c - the surface maps' section of the report (report_surfaces.h). */
#include "report/report_surfaces.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file_bytes.h"
#include "report/report_numbers.h"
#include "report/summary_table.h"
#include "base/error_report.h"

/* A map's CSV holds at most as many bytes as a grid's. */
#define CSV_MAX_BYTES ((size_t)4 << 30)

static char *join(const char *folder, const char *name, const char *ext)
{
    size_t n = strlen(folder) + strlen(name) + strlen(ext) + 16;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/surfaces/%s%s", folder, name, ext);
    return p;
}

static double number(const cJSON *o, const char *key)
{
    const cJSON *n = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(n) ? n->valuedouble : NAN;
}

/* The rows of a CSV after its header, `columns` numbers each, into values
 * (columns x rows, the caller's to free). */
static cdl_status read_rows(const char *path, const char *header, size_t columns, size_t rows, double **values,
                            cdl_error *err)
{
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "surface map", CSV_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    *values = malloc((columns * rows + 1) * sizeof **values);
    if (!*values) {
        free(text);
        return cdl_error_out_of_memory(err);
    }
    size_t h = strlen(header);
    if (strncmp(text, header, h) != 0 || text[h] != '\n') {
        free(text);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected the header %s (solve again)", path, header);
    }
    const char *p = text + h + 1;
    for (size_t r = 0; r < rows; ++r)
        for (size_t c = 0; c < columns; ++c) {
            char *end;
            (*values)[r * columns + c] = strtod(p, &end);
            char want = c + 1 < columns ? ',' : '\n';
            if (end == p || *end != want || !isfinite((*values)[r * columns + c])) {
                free(text);
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: row %zu: expected %zu numbers as summary.json's count says (the file is "
                                     "damaged or from another solve: solve again)",
                                     path, r + 1, columns);
            }
            p = end + 1;
        }
    int extra = *p != '\0';
    free(text);
    if (extra)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: more rows than summary.json's count (solve again)", path);
    return CDL_OK;
}

/* One map: its summary entry, its scene surface, its two CSVs, checked. */
static cdl_status read_map(const cdl_report_input *in, const cJSON *o, cdl_report_surface *s, cdl_error *err)
{
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(o, "name");
    if (!cJSON_IsString(name))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: surfaces: an entry without a name (solve again)",
                             in->summary_path);
    for (size_t k = 0; k < in->scene->surface_count && !s->spec; ++k)
        if (in->scene->surfaces[k].mapped && strcmp(in->scene->surfaces[k].map_name, name->valuestring) == 0)
            s->spec = &in->scene->surfaces[k];
    if (!s->spec)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: surfaces: %s: the scene %s maps no such surface (the scene changed after the "
                             "solve: solve again)",
                             in->summary_path, name->valuestring, in->scene->path);
    double vertices = number(o, "vertices"), triangles = number(o, "triangles");
    s->area_m2 = number(o, "area_m2");
    s->Em = number(o, "Em_lx");
    s->Emin = number(o, "Emin_lx");
    s->Emax = number(o, "Emax_lx");
    s->U0 = number(o, "U0");
    s->L_mean = number(o, "L_mean_cd_m2");
    s->stderr_mean_rel = number(o, "stderr_mean_rel");
    if (!(vertices >= 3 && triangles >= 1) || !isfinite(s->Em))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: surfaces: %s: expected its counts and statistics (solve again)",
                             in->summary_path, name->valuestring);
    s->vertex_count = (size_t)vertices;
    s->triangle_count = (size_t)triangles;
    char *csv = join(in->out_dir, name->valuestring, ".csv"), *tri = join(in->out_dir, name->valuestring, ".tri.csv");
    double *rows = NULL, *idx = NULL;
    cdl_status st = csv && tri ? read_rows(csv, "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,L_cd_m2", 11,
                                           s->vertex_count, &rows, err)
                               : cdl_error_out_of_memory(err);
    if (st == CDL_OK) st = read_rows(tri, "a,b,c", 3, s->triangle_count, &idx, err);
    s->xyz = malloc((3 * s->vertex_count + 1) * sizeof *s->xyz);
    s->E = malloc((s->vertex_count + 1) * sizeof *s->E);
    s->E_stderr = malloc((s->vertex_count + 1) * sizeof *s->E_stderr);
    s->triangles = malloc((3 * s->triangle_count + 1) * sizeof *s->triangles);
    if (st == CDL_OK && (!s->xyz || !s->E || !s->E_stderr || !s->triangles)) st = cdl_error_out_of_memory(err);
    for (size_t v = 0; st == CDL_OK && v < s->vertex_count; ++v) {
        memcpy(&s->xyz[3 * v], &rows[11 * v], 3 * sizeof *s->xyz);
        s->E[v] = rows[11 * v + 6];
        s->E_stderr[v] = rows[11 * v + 9];
        if (s->E[v] > 0.0) s->stderr_max_rel = fmax(s->stderr_max_rel, s->E_stderr[v] / s->E[v]);
    }
    double area = 0.0, integral = 0.0;
    for (size_t t = 0; st == CDL_OK && t < s->triangle_count; ++t) {
        for (int k = 0; k < 3; ++k) {
            double i = idx[3 * t + (size_t)k];
            if (!(i >= 0 && i < (double)s->vertex_count && i == floor(i))) {
                st = cdl_error_set(err, CDL_ERR_INPUT, "%s: row %zu: a vertex row that %s does not have (solve again)",
                                   tri, t + 1, csv);
                break;
            }
            s->triangles[3 * t + (size_t)k] = (uint32_t)i;
        }
        if (st != CDL_OK) break;
        const uint32_t *v = &s->triangles[3 * t];
        const double *a = &s->xyz[3 * v[0]], *b = &s->xyz[3 * v[1]], *c = &s->xyz[3 * v[2]];
        cdl_vec3 n = cdl_vec3_cross(cdl_vec3_make(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
                                    cdl_vec3_make(c[0] - a[0], c[1] - a[1], c[2] - a[2]));
        double at = 0.5 * cdl_vec3_length(n);
        area += at;
        integral += at * (s->E[v[0]] + s->E[v[1]] + s->E[v[2]]) / 3.0;
    }
    if (st == CDL_OK && !(area > 0.0 && fabs(integral / area - s->Em) <= 1e-9 * fmax(1.0, fabs(s->Em))))
        st = cdl_error_set(err, CDL_ERR_INPUT,
                           "%s: its Em (%.10g lx) is not summary.json's (%.10g lx): the files are from different "
                           "solves (solve again)",
                           csv, area > 0.0 ? integral / area : 0.0, s->Em);
    free(rows);
    free(idx);
    free(csv);
    free(tri);
    return st;
}

/* Where the luminaires are drawn: as scene.glb places them. */
static cdl_status luminaire_places(const cdl_scene *scene, cdl_report_surfaces *s, cdl_error *err)
{
    s->luminaires = malloc((scene->luminaire_count + 1) * sizeof *s->luminaires);
    if (!s->luminaires) return cdl_error_out_of_memory(err);
    for (size_t l = 0; l < scene->luminaire_count; ++l) {
        const cdl_luminaire_spec *lum = &scene->luminaires[l];
        if (lum->kind == CDL_LUMINAIRE_POINT || lum->kind == CDL_LUMINAIRE_SPOT ||
            lum->kind == CDL_LUMINAIRE_GONIOMETRIC)
            s->luminaires[s->luminaire_count++] = lum->position;
        else if (lum->kind == CDL_LUMINAIRE_AREA && lum->shape.kind == CDL_SURFACE_RECT)
            s->luminaires[s->luminaire_count++] =
                cdl_vec3_madd(cdl_vec3_madd(lum->shape.origin, 0.5, lum->shape.u), 0.5, lum->shape.v);
        else if (lum->kind == CDL_LUMINAIRE_AREA && lum->shape.kind == CDL_SURFACE_DISK)
            s->luminaires[s->luminaire_count++] = lum->shape.center;
    }
    return CDL_OK;
}

cdl_status cdl_report_surfaces_read(const cdl_report_input *in, cdl_report_surfaces **out, cdl_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return cdl_error_out_of_memory(err);
    cdl_report_surfaces *s = *out;
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(in->summary, "surfaces");
    if (!list) return CDL_OK;
    if (!cJSON_IsArray(list))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: surfaces: expected a list of surface maps", in->summary_path);
    size_t n = (size_t)cJSON_GetArraySize(list);
    s->items = calloc(n + 1, sizeof *s->items);
    s->meshes = calloc(n + 1, sizeof *s->meshes);
    if (!s->items || !s->meshes) return cdl_error_out_of_memory(err);
    for (const cJSON *o = list->child; o; o = o->next) {
        cdl_report_surface *m = &s->items[s->count++];
        cdl_status st = read_map(in, o, m, err);
        if (st != CDL_OK) return st;
        s->meshes[s->count - 1] =
            (cdl_view_mesh){m->spec->map_name, m->xyz, m->vertex_count, m->triangles, m->triangle_count, m->E};
    }
    return luminaire_places(in->scene, s, err);
}

void cdl_report_surfaces_release(cdl_report_surfaces *s)
{
    if (!s) return;
    for (size_t k = 0; k < s->count; ++k) {
        free(s->items[k].xyz);
        free(s->items[k].E);
        free(s->items[k].E_stderr);
        free(s->items[k].triangles);
    }
    if (s->view_ready) cdl_surface_view_release(&s->view);
    free(s->items);
    free(s->meshes);
    free(s->luminaires);
    free(s);
}

/* ---- the section ------------------------------------------------------------------------ */

static cdl_report_block *push(cdl_report_document *d, cdl_report_block_kind kind, int *failed)
{
    if (d->count == d->capacity) {
        size_t cap = d->capacity ? 2 * d->capacity : 32;
        cdl_report_block *grown = realloc(d->blocks, cap * sizeof *grown);
        if (!grown) {
            *failed = 1;
            return NULL;
        }
        d->blocks = grown;
        d->capacity = cap;
    }
    cdl_report_block *b = &d->blocks[d->count++];
    memset(b, 0, sizeof *b);
    b->kind = kind;
    return b;
}

static char *text(int *failed, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static char *text(int *failed, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *t = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (!t) {
        *failed = 1;
        return NULL;
    }
    va_start(ap, fmt);
    vsnprintf(t, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return t;
}

/* The row of map m as the grids' table prints its numbers. */
static void row_of(const cdl_report_surface *m, cdl_report_row *row)
{
    static const cdl_grid_spec points = {.kind = CDL_GRID_POINTS};
    cdl_report_grid g = {.spec = &points};
    g.count = m->vertex_count;
    g.Em = m->Em;
    g.Emin = m->Emin;
    g.Emax = m->Emax;
    g.U0 = m->U0;
    g.stderr_mean_rel = m->stderr_mean_rel;
    g.stderr_max_rel = m->stderr_max_rel;
    /* the vertices of Emin and Emax, whose stated errors theirs are */
    g.E = m->E;
    g.E_stderr = m->E_stderr;
    for (size_t v = 1; v < m->vertex_count; ++v) {
        if (m->E[v] < m->E[g.min_index]) g.min_index = v;
        if (m->E[v] > m->E[g.max_index]) g.max_index = v;
    }
    if (m->vertex_count == 0) g.E_stderr = NULL;
    g.required_Em_lx = m->spec->required_Em_lx;
    g.required_U0 = m->spec->required_U0;
    cdl_report_row_of(&g, row);
}

static void add_table(cdl_report_document *d, const cdl_report_surfaces *s, int *failed)
{
    static const char *const heads[] = {"surface", "area m2", "Em lx", "Emin lx", "Emax lx", "U0", "L mean cd/m2",
                                        "vertices", "requirements"};
    cdl_report_block *t = push(d, CDL_BLOCK_TABLE, failed);
    if (!t) return;
    t->columns = 9;
    t->rows = s->count + 1;
    t->header = 1;
    t->cells = calloc(t->columns * t->rows, sizeof *t->cells);
    if (!t->cells) {
        *failed = 1;
        return;
    }
    for (size_t c = 0; c < 9; ++c) t->cells[c] = text(failed, "%s", heads[c]);
    for (size_t k = 0; k < s->count; ++k) {
        const cdl_report_surface *m = &s->items[k];
        cdl_report_row row;
        row_of(m, &row);
        char **r = &t->cells[(k + 1) * 9];
        char L[32];
        cdl_report_format(L, sizeof L, m->L_mean, m->L_mean * m->stderr_mean_rel);
        r[0] = text(failed, "%s", m->spec->map_name);
        r[1] = text(failed, "%.4g", m->area_m2);
        r[2] = text(failed, "%s", row.Em);
        r[3] = text(failed, "%s", row.Emin);
        r[4] = text(failed, "%s", row.Emax);
        r[5] = text(failed, "%s", row.U0);
        r[6] = text(failed, "%s", L);
        r[7] = text(failed, "%zu", m->vertex_count);
        r[8] = row.has_requirements ? text(failed, "%s; %s", row.verdict, row.requirements) : text(failed, "none given");
    }
}

cdl_status cdl_report_surfaces_section(cdl_report_document *d, const cdl_report_input *in, cdl_report_surfaces *s,
                                       cdl_error *err)
{
    (void)in;
    d->surfaces = s;
    if (s->count == 0) return CDL_OK;
    int failed = 0;
    cdl_report_block *b = push(d, CDL_BLOCK_PAGE_BREAK, &failed);
    if ((b = push(d, CDL_BLOCK_HEADING, &failed))) {
        b->level = 2;
        b->text = text(&failed, "Surfaces");
    }
    if ((b = push(d, CDL_BLOCK_PARAGRAPH, &failed)))
        b->text = text(&failed,
                       "The illuminance on the front of each mapped surface, on a mesh refined where the light "
                       "changes: Em is the area-weighted mean of the map (linear between its vertices), Emin and "
                       "Emax its vertices' extremes, U0 = Emin / Em, L = rho E / pi the mean luminance. Each number is "
                       "printed to the decimal place of its stated error, which includes the interpolation between "
                       "vertices. EN 12464-1:2021, 4.3 asks of a room's walls and ceiling a maintained Em (say 50 lx "
                       "and 30 lx) with U0 >= 0.10; requirements come from the scene's surfaces.");
    add_table(d, s, &failed);
    if (failed) return cdl_error_out_of_memory(err);
    cdl_status st = cdl_surface_view_prepare(&s->view, s->meshes, s->count, s->luminaires, s->luminaire_count,
                                             err);
    if (st != CDL_OK) return cdl_error_prefix(err, "the surfaces in 3D: ");
    s->view_ready = 1;
    if ((b = push(d, CDL_BLOCK_FIGURE, &failed))) {
        b->figure = cdl_surface_view_figure(&s->view);
        b->figure_scale = 1.0;
    }
    return failed ? cdl_error_out_of_memory(err) : CDL_OK;
}
