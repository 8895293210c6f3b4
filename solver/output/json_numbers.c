/* json_numbers.c - numbers in a cJSON tree printed so that they read back exactly. */
#include "solver/output/json_numbers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solver/output/grid_result.h"

void cdl_json_numbers_exact(cJSON *item)
{
    for (; item; item = item->next) {
        if (item->child) cdl_json_numbers_exact(item->child);
        if (!cJSON_IsNumber(item)) continue;
        double v = item->valuedouble;
        /* cJSON writes integers of int range as integers, exactly, and
         * non-finite numbers as null: both are left to it */
        if (!isfinite(v) || (v == floor(v) && fabs(v) < 2147483647.0)) continue;
        char buf[CDL_CSV_NUMBER_SIZE];
        cdl_csv_format_number(v, buf); /* the CSVs' digits: the shortest that read back exactly */
        char *text = malloc(strlen(buf) + 1);
        if (!text) continue;
        memcpy(text, buf, strlen(buf) + 1);
        item->type = cJSON_Raw;
        item->valuestring = text;
    }
}
