/* glare_output.c - summary.json's "glare" and glare.csv. */
#include "solver/output/glare_output.h"

#include <stdio.h>

#include "base/atomic_file.h"
#include "solver/output/grid_result.h"

static cJSON *vec3_json(cdl_vec3 v)
{
    const double xyz[3] = {v.x, v.y, v.z};
    return cJSON_CreateDoubleArray(xyz, 3);
}

static cJSON *label_json(const cdl_scene *scene, size_t k)
{
    char label[200];
    cdl_luminaire_spec_label(&scene->luminaires[k], label, sizeof label);
    return cJSON_CreateString(label);
}

/* One observer's object. */
static cJSON *observer_json(const cdl_scene *scene, const cdl_observer_spec *o, const cdl_observer_result *r)
{
    cJSON *j = cJSON_CreateObject();
    if (!j) return NULL;
    cJSON_AddStringToObject(j, "observer", o->name);
    cJSON_AddStringToObject(j, "json_path", o->json_path);
    cJSON_AddItemToObject(j, "eye", vec3_json(o->eye));
    cJSON_AddItemToObject(j, "view", vec3_json(o->view));
    if (r->defined) {
        cJSON_AddNumberToObject(j, "ugr", r->ugr);
        cJSON_AddNumberToObject(j, "ugr_stderr", r->ugr_stderr);
    } else {
        cJSON_AddNullToObject(j, "ugr");
        cJSON_AddNullToObject(j, "ugr_stderr");
    }
    cJSON_AddNumberToObject(j, "background_cd_m2", r->background_cd_m2);
    cJSON_AddNumberToObject(j, "background_stderr_cd_m2", r->background_stderr_cd_m2);
    if (o->required_ugr > 0.0) cJSON_AddNumberToObject(j, "UGR_L", o->required_ugr);
    else cJSON_AddNullToObject(j, "UGR_L");
    cJSON *sources = cJSON_AddArrayToObject(j, "sources");
    for (size_t k = 0; sources && k < r->source_count; ++k) {
        const cdl_glare_source_result *s = &r->sources[k];
        cJSON *e = cJSON_CreateObject();
        if (!e) break;
        cJSON_AddItemToObject(e, "luminaire", label_json(scene, s->luminaire));
        cJSON_AddNumberToObject(e, "L_cd_m2", s->L_cd_m2);
        cJSON_AddNumberToObject(e, "omega_sr", s->omega_sr);
        cJSON_AddNumberToObject(e, "omega_stderr_sr", s->omega_stderr_sr);
        cJSON_AddBoolToObject(e, "omega_exact", s->omega_exact);
        cJSON_AddNumberToObject(e, "p", s->p);
        cJSON_AddNumberToObject(e, "term", s->term);
        cJSON_AddNumberToObject(e, "term_stderr", s->term_stderr);
        cJSON_AddItemToArray(sources, e);
    }
    cJSON *excluded = cJSON_AddArrayToObject(j, "excluded");
    for (size_t k = 0; excluded && k < r->excluded_count; ++k) {
        cJSON *e = cJSON_CreateObject();
        if (!e) break;
        cJSON_AddItemToObject(e, "luminaire", label_json(scene, r->excluded[k].luminaire));
        cJSON_AddStringToObject(e, "reason", r->excluded[k].reason);
        cJSON_AddItemToArray(excluded, e);
    }
    return j;
}

cJSON *cdl_glare_summary_json(const cdl_scene *scene, const cdl_solution *sol)
{
    cJSON *glare = cJSON_CreateArray();
    for (size_t i = 0; glare && i < sol->observer_count && i < scene->observer_count; ++i) {
        cJSON *o = observer_json(scene, &scene->observers[i], &sol->observers[i]);
        if (!o) {
            cJSON_Delete(glare);
            return NULL;
        }
        cJSON_AddItemToArray(glare, o);
    }
    return glare;
}

cdl_status cdl_glare_write_csv(const cdl_scene *scene, const cdl_solution *sol, const char *path, cdl_error *err)
{
    cdl_atomic_file f;
    cdl_status st = cdl_atomic_file_open(&f, path, err);
    if (st != CDL_OK) return st;
    fputs("name,x,y,z,view_x,view_y,view_z,ugr,ugr_stderr,background_cd_m2,background_stderr_cd_m2\n", f.fp);
    for (size_t i = 0; i < sol->observer_count && i < scene->observer_count; ++i) {
        const cdl_observer_spec *o = &scene->observers[i];
        const cdl_observer_result *r = &sol->observers[i];
        const double v[10] = {o->eye.x, o->eye.y,  o->eye.z, o->view.x, o->view.y, o->view.z,
                              r->ugr,   r->ugr_stderr, r->background_cd_m2, r->background_stderr_cd_m2};
        fputs(o->name, f.fp);
        for (int k = 0; k < 10; ++k) {
            char buf[CDL_CSV_NUMBER_SIZE] = "";
            /* no rating: empty cells, never a made-up number */
            if (r->defined || (k != 6 && k != 7)) cdl_csv_format_number(v[k], buf);
            fprintf(f.fp, ",%s", buf);
        }
        fputc('\n', f.fp);
    }
    return cdl_atomic_file_commit(&f, err);
}
