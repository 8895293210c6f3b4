/* scene_project.c - the scene's "name" and "project": what a report says it is.
 *
 *   "name": "Office, level 2"                        the report's title (else the file's stem)
 *   "project": {"project": "Refurbishment 2026",      each optional, free text, at most
 *               "client": "ACME Ltd", "designer":     CDL_SCENE_PROJECT_TEXT_MAX bytes;
 *               "J. Doe", "date": "2026-11-26",       "notes" may hold line breaks
 *               "notes": "Maintenance factors ..."}
 * None of it changes a result (scene_inputs.h leaves it out of the hashes
 * a report checks), so a name can be corrected after the solve.
 */
#include "solver/scene/scene_parse.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file_bytes.h"

/* Free text of reasonable length: a paragraph of notes, a line for the rest. */
#define CDL_SCENE_PROJECT_TEXT_MAX 4000
#define CDL_SCENE_NAME_MAX 200
/* A project file holds the few texts above. */
#define CDL_SCENE_PROJECT_FILE_MAX ((size_t)1 << 20)

const char *const cdl_scene_project_keys[] = {"project", "client", "designer", "date", "notes", NULL};

static cdl_status read_text(const cdl_scene_parse *ctx, const cJSON *node, const char *path, size_t max, char **out)
{
    if (!node) return CDL_OK;
    if (cJSON_IsString(node) && node->valuestring && strlen(node->valuestring) > max) {
        char expected[96];
        snprintf(expected, sizeof expected, "a text of at most %zu bytes", max);
        return cdl_scene_json_failf(ctx, path, expected, "%zu bytes", strlen(node->valuestring));
    }
    return cdl_scene_json_read_string(ctx, node, path, 0, out);
}

/* A project object at `path` (NULL node: none given). */
static cdl_status read_project(const cdl_scene_parse *ctx, const cJSON *node, const char *path, cdl_scene_project *out)
{
    char item[CDL_SCENE_PATH_MAX];
    if (!node) return CDL_OK;
    if (cdl_scene_json_check_object(ctx, node, path, "the project (project, client, designer, date, notes)",
                                    cdl_scene_project_keys) != CDL_OK)
        return CDL_ERR_INPUT;
    char **fields[] = {&out->project, &out->client, &out->designer, &out->date, &out->notes};
    for (size_t k = 0; cdl_scene_project_keys[k]; ++k) {
        const cJSON *v = cdl_scene_json_field(node, path, cdl_scene_project_keys[k], item);
        size_t max = strcmp(cdl_scene_project_keys[k], "notes") == 0 ? CDL_SCENE_PROJECT_TEXT_MAX : CDL_SCENE_NAME_MAX;
        if (read_text(ctx, v, item, max, fields[k]) != CDL_OK) return CDL_ERR_INPUT;
    }
    return CDL_OK;
}

cdl_status cdl_scene_json_read_about(const cdl_scene_parse *ctx, const cJSON *root, cdl_scene *scene)
{
    char p[CDL_SCENE_PATH_MAX];
    if (read_text(ctx, cdl_scene_json_field(root, "", "name", p), p, CDL_SCENE_NAME_MAX, &scene->name) != CDL_OK)
        return CDL_ERR_INPUT;
    const cJSON *project = cdl_scene_json_field(root, "", "project", p);
    return read_project(ctx, project, p, &scene->project);
}

void cdl_scene_project_free(cdl_scene_project *project)
{
    free(project->project);
    free(project->client);
    free(project->designer);
    free(project->date);
    free(project->notes);
    memset(project, 0, sizeof *project);
}

cdl_status cdl_scene_project_load(const char *path, cdl_scene_project *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "project file", CDL_SCENE_PROJECT_FILE_MAX, &text, &size, err);
    if (st != CDL_OK) return st;
    cJSON *root = cJSON_ParseWithLength(text, size);
    free(text);
    cdl_scene_parse ctx = {path, ".", err};
    if (!root)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: invalid JSON: expected an object {\"project\", \"client\", \"designer\", \"date\", "
                             "\"notes\"}",
                             path);
    /* the file holds what a scene's "project" holds */
    st = read_project(&ctx, root, "", out);
    cJSON_Delete(root);
    if (st != CDL_OK) cdl_scene_project_free(out);
    return st;
}
