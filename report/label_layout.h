/* label_layout.h - labels on a map placed so that none hides another.
 *
 * Each label is a box of its own size (points) with candidate centres in
 * order of preference (an isolux line's label: the midpoints of its
 * segments, nearest the line's middle first; a marker's: around the
 * marker). Greedily, in the labels' order, each takes its first candidate
 * whose box lies inside `bounds` and clears, by `gap`, every obstacle (the
 * luminaires' symbols and footprints, the min and max markers) and every
 * label placed before it; a label with no such candidate is left out
 * rather than drawn over another. So no two placed boxes overlap, by
 * construction, and the first labels (the min and max values) are placed
 * whenever any of their candidates is free. O(labels x candidates x
 * placed): maps have at most a few dozen labels. Pure; thread-safe.
 */
#ifndef CANDELA_REPORT_LABEL_LAYOUT_H
#define CANDELA_REPORT_LABEL_LAYOUT_H

#include <stddef.h>

typedef struct cdl_label_box {
    double x0, y0, x1, y1;           /* x0 <= x1, y0 <= y1 */
} cdl_label_box;

typedef struct cdl_label_request {
    double width, height;            /* the label's box */
    const double *centres;           /* candidate centres: x, y pairs, best first */
    size_t centre_count;
} cdl_label_request;

/* 1 when a and b come closer than gap (overlap, or touch with gap > 0). */
int cdl_label_boxes_clash(const cdl_label_box *a, const cdl_label_box *b, double gap);

/* Place `labels` (above): placed[k] = 1 and boxes[k] its box, or placed[k] = 0. */
void cdl_label_layout(const cdl_label_request *labels, size_t count, const cdl_label_box *obstacles,
                      size_t obstacle_count, cdl_label_box bounds, double gap, cdl_label_box *boxes, int *placed);

#endif
