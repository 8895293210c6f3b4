/* ranks_json.h - summary.json's "ranks": the processes a run was shared by (not public).
 *
 * "ranks": {"count", and per rank in rank order "threads", "seconds",
 * "work_seconds", "work_cpu_seconds", "cpu_seconds", "bytes_received",
 * "peak_rss_bytes"} (rank_group.h's cdl_rank_report), written alike by
 * `candela solve` and `candela annual`; a run in one process has count 1.
 */
#ifndef CANDELA_SOLVER_OUTPUT_RANKS_JSON_H
#define CANDELA_SOLVER_OUTPUT_RANKS_JSON_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "solver/rank_group.h"

/* "ranks" added to `root` from reports[0 .. count - 1] (count 0: a count of 1, no arrays' entries). */
void cdl_ranks_json_add(cJSON *root, const cdl_rank_report *reports, size_t count);

#endif
