/* sort_doubles.h - an array of doubles sorted ascending (qsort with the one
 * comparison the library needs in many places: medians, quantiles, cuts).
 * NaNs must not be in the array. */
#ifndef CANDELA_BASE_SORT_DOUBLES_H
#define CANDELA_BASE_SORT_DOUBLES_H

#include <stddef.h>

void cdl_sort_doubles(double *x, size_t count);

#endif
