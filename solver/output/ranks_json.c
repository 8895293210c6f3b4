/* ranks_json.c - summary.json's "ranks" (ranks_json.h). */
#include "solver/output/ranks_json.h"

void cdl_ranks_json_add(cJSON *root, const cdl_rank_report *reports, size_t n)
{
    cJSON *ranks = cJSON_AddObjectToObject(root, "ranks");
    cJSON_AddNumberToObject(ranks, "count", n ? (double)n : 1.0);
    cJSON *threads = cJSON_AddArrayToObject(ranks, "threads");
    cJSON *seconds = cJSON_AddArrayToObject(ranks, "seconds");
    cJSON *work = cJSON_AddArrayToObject(ranks, "work_seconds");
    cJSON *work_cpu = cJSON_AddArrayToObject(ranks, "work_cpu_seconds");
    cJSON *cpu = cJSON_AddArrayToObject(ranks, "cpu_seconds");
    cJSON *bytes = cJSON_AddArrayToObject(ranks, "bytes_received");
    cJSON *rss = cJSON_AddArrayToObject(ranks, "peak_rss_bytes");
    for (size_t r = 0; r < n; ++r) {
        cJSON_AddItemToArray(threads, cJSON_CreateNumber((double)reports[r].threads));
        cJSON_AddItemToArray(seconds, cJSON_CreateNumber(reports[r].seconds));
        cJSON_AddItemToArray(work, cJSON_CreateNumber(reports[r].work_seconds));
        cJSON_AddItemToArray(work_cpu, cJSON_CreateNumber(reports[r].work_cpu_seconds));
        cJSON_AddItemToArray(cpu, cJSON_CreateNumber(reports[r].cpu_seconds));
        cJSON_AddItemToArray(bytes, cJSON_CreateNumber((double)reports[r].bytes_received));
        cJSON_AddItemToArray(rss, cJSON_CreateNumber((double)reports[r].peak_rss_bytes));
    }
}
