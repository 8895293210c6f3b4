/* json_numbers.h - JSON numbers that read back as the doubles written.
 *
 * cJSON prints a number with 15 significant digits whenever that reads
 * back within a rounding of the value (1.7.15: its compare_double allows
 * one DBL_EPSILON relative), so a JSON number could differ in its last bit
 * from the same double in a CSV, which prints the shortest digits that
 * read back exactly: summary.json's UGR was 25.3781186166556 where
 * glare.csv said 25.378118616655602. Before a tree is printed, every
 * finite number that is not a small integer is given, as the text cJSON
 * writes for it, the shortest of 15, 16 or 17 significant digits that
 * strtod turns back into the very same double.
 */
#ifndef CANDELA_SOLVER_OUTPUT_JSON_NUMBERS_H
#define CANDELA_SOLVER_OUTPUT_JSON_NUMBERS_H

#include <cjson/cJSON.h>

/* Every number under `item` (itself included) made exact as above; a
 * number whose text cannot be allocated keeps cJSON's own printing. */
void cdl_json_numbers_exact(cJSON *item);

#endif
