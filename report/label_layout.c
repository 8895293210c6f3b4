/* label_layout.c - greedy placement of map labels without overlaps (label_layout.h). */
#include "report/label_layout.h"

int cdl_label_boxes_clash(const cdl_label_box *a, const cdl_label_box *b, double gap)
{
    return a->x0 < b->x1 + gap && b->x0 < a->x1 + gap && a->y0 < b->y1 + gap && b->y0 < a->y1 + gap;
}

/* The box centred at (x, y) is inside bounds and clear of obstacles and of
 * the labels placed so far. */
static int free_at(const cdl_label_box *box, const cdl_label_box *obstacles, size_t obstacle_count,
                   const cdl_label_box *bounds, double gap, const cdl_label_box *boxes, const int *placed, size_t before)
{
    if (box->x0 < bounds->x0 || box->y0 < bounds->y0 || box->x1 > bounds->x1 || box->y1 > bounds->y1) return 0;
    for (size_t k = 0; k < obstacle_count; ++k)
        if (cdl_label_boxes_clash(box, &obstacles[k], gap)) return 0;
    for (size_t k = 0; k < before; ++k)
        if (placed[k] && cdl_label_boxes_clash(box, &boxes[k], gap)) return 0;
    return 1;
}

void cdl_label_layout(const cdl_label_request *labels, size_t count, const cdl_label_box *obstacles,
                      size_t obstacle_count, cdl_label_box bounds, double gap, cdl_label_box *boxes, int *placed)
{
    for (size_t k = 0; k < count; ++k) {
        const cdl_label_request *l = &labels[k];
        placed[k] = 0;
        for (size_t c = 0; c < l->centre_count && !placed[k]; ++c) {
            double x = l->centres[2 * c], y = l->centres[2 * c + 1];
            cdl_label_box box = {x - 0.5 * l->width, y - 0.5 * l->height, x + 0.5 * l->width, y + 0.5 * l->height};
            if (!free_at(&box, obstacles, obstacle_count, &bounds, gap, boxes, placed, k)) continue;
            boxes[k] = box;
            placed[k] = 1;
        }
    }
}
