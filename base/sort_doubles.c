/* sort_doubles.c - see sort_doubles.h. */
#include "base/sort_doubles.h"

#include <stdlib.h>

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void cdl_sort_doubles(double *x, size_t count)
{
    if (count > 1) qsort(x, count, sizeof *x, compare_doubles);
}
