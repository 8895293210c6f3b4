/* info_ugr.c - the UGR table of `candela info --ugr`. */
#include <math.h>
#include <stdlib.h>

#include "info_ugr.h"

#include "glare/ugr_table_conditions.h"

static const char *const set_rows[3] = {"ceiling", "walls", "floor"};

void cdl_info_ugr_print(const cdl_ugr_table *t, FILE *out)
{
    fprintf(out, "%-16sCIE 190:2010 standard rooms, UGR by CIE 117:1995: luminaires at spacing %g H over the\n",
            "UGR table", t->spacing_to_height);
    fprintf(out, "%-16sceiling, H = %g m above the eye, %.6g lm each%s; the observer at the middle of a wall\n", "",
            CDL_UGR_TABLE_HEIGHT_M, t->flux_lm, t->output_factor != 1.0 ? " (output factor applied)" : "");
    fprintf(out, "%-16slooking along Y; crosswise: the luminaires' C0 plane along the line of sight\n", "");
    for (int k = 0; k < 3; ++k) {
        fprintf(out, "  %-14s", set_rows[k]);
        for (int view = 0; view < 2; ++view) {
            for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s)
                fprintf(out, " %5.2f", cdl_ugr_table_reflectances[s][k]);
            fprintf(out, "%s", view == 0 ? "  |" : "\n");
        }
    }
    fprintf(out, "  %-14s %-29s  | %s\n", "room X x Y", "viewed crosswise", "viewed endwise");
    for (int i = 0; i < CDL_UGR_TABLE_ROOMS; ++i) {
        const cdl_ugr_table_room *r = &t->rooms[i];
        char room[32];
        snprintf(room, sizeof room, "%gH x %gH", r->x_h, r->y_h);
        fprintf(out, "  %-14s", room);
        for (int view = 0; view < 2; ++view) {
            for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
                if (r->defined[view]) fprintf(out, " %5.1f", r->ugr[view][s]);
                else fprintf(out, " %5s", "-");
            }
            fprintf(out, "%s", view == 0 ? "  |" : "\n");
        }
    }
}

static cJSON *number_array(const double *x, const int *defined, size_t n)
{
    cJSON *a = cJSON_CreateArray();
    for (size_t i = 0; a && i < n; ++i)
        cJSON_AddItemToArray(a, defined && !defined[0] ? cJSON_CreateNull() : cJSON_CreateNumber(x[i]));
    return a;
}

cJSON *cdl_info_ugr_json(const cdl_ugr_table *t)
{
    cJSON *j = cJSON_CreateObject();
    if (!j) return NULL;
    cJSON_AddStringToObject(j, "method", "CIE 190:2010 standard table, UGR by CIE 117:1995 eq. 4.1, background "
                                         "by CIE 190's flux transfer");
    cJSON_AddNumberToObject(j, "spacing_to_height", t->spacing_to_height);
    cJSON_AddNumberToObject(j, "height_m", CDL_UGR_TABLE_HEIGHT_M);
    cJSON_AddNumberToObject(j, "flux_lm", t->flux_lm);
    cJSON_AddNumberToObject(j, "output_factor", t->output_factor);
    cJSON *sets = cJSON_AddArrayToObject(j, "reflectances");
    for (int s = 0; sets && s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
        cJSON *o = cJSON_CreateObject();
        for (int k = 0; o && k < 3; ++k) cJSON_AddNumberToObject(o, set_rows[k], cdl_ugr_table_reflectances[s][k]);
        cJSON_AddItemToArray(sets, o);
    }
    cJSON *rooms = cJSON_AddArrayToObject(j, "rooms");
    for (int i = 0; rooms && i < CDL_UGR_TABLE_ROOMS; ++i) {
        const cdl_ugr_table_room *r = &t->rooms[i];
        cJSON *o = cJSON_CreateObject();
        if (!o) break;
        cJSON_AddNumberToObject(o, "x_h", r->x_h);
        cJSON_AddNumberToObject(o, "y_h", r->y_h);
        cJSON_AddNumberToObject(o, "luminaires", (double)r->luminaires);
        cJSON_AddNumberToObject(o, "room_index", r->room_index);
        cJSON_AddNumberToObject(o, "direct_floor_lm", r->direct_floor_lm);
        cJSON_AddNumberToObject(o, "direct_walls_lm", r->direct_walls_lm);
        cJSON_AddNumberToObject(o, "direct_ceiling_lm", r->direct_ceiling_lm);
        cJSON_AddItemToObject(o, "background_cd_m2", number_array(r->background_cd_m2, NULL, 5));
        cJSON_AddItemToObject(o, "crosswise", number_array(r->ugr[0], &r->defined[0], 5));
        cJSON_AddItemToObject(o, "endwise", number_array(r->ugr[1], &r->defined[1], 5));
        cJSON_AddItemToArray(rooms, o);
    }
    return j;
}

int cdl_info_ugr_parse_shr(const char *value, double *shr)
{
    char *end = NULL;
    double v = strtod(value, &end);
    if (end == value || *end != '\0' || !(v > 0.0) || !isfinite(v)) {
        fprintf(stderr, "candela info: --ugr-shr: expected a spacing to height ratio above 0 (0.25, 0.5, 1), found "
                        "'%s'\n(see 'candela info --help')\n", value);
        return 2;
    }
    *shr = v;
    return 0;
}
