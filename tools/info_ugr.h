/* info_ugr.h - `candela info --ugr`: a luminaire's CIE 190 UGR table as
 * text (the catalogue's layout) and as JSON. */
#ifndef CANDELA_TOOLS_INFO_UGR_H
#define CANDELA_TOOLS_INFO_UGR_H

#include <cjson/cJSON.h>
#include <stdio.h>

#include "glare/ugr_table.h"

/* The table as catalogues print it: reflectances over the columns, the
 * rooms down, crosswise then endwise. */
void cdl_info_ugr_print(const cdl_ugr_table *table, FILE *out);

/* The table as a JSON object (NULL when out of memory). */
cJSON *cdl_info_ugr_json(const cdl_ugr_table *table);

/* The value of --ugr-shr into *shr: a number above 0 (the library checks
 * the rest). Returns 0, or 2 after saying what was found on stderr. */
int cdl_info_ugr_parse_shr(const char *value, double *shr);

#endif
