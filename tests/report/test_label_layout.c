/* Map labels placed without overlaps (label_layout.h): in a crowd of 60
 * labels whose candidate places mostly collide, every placed box lies
 * inside the bounds and clear (by the gap) of every obstacle and of every
 * other placed box; a label left out had no free candidate (each one is
 * checked against the obstacles and the labels placed before it); the
 * first label is placed at its first free candidate; and two labels that
 * want the same place get it in order, the second moved to its next. */
#include <stdint.h>
#include <stdio.h>

#include "check.h"
#include "report/label_layout.h"

/* A small deterministic generator (numbers for the test's layout only). */
static double next(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static cdl_label_box box_at(double x, double y, double w, double h)
{
    return (cdl_label_box){x - 0.5 * w, y - 0.5 * h, x + 0.5 * w, y + 0.5 * h};
}

static int inside(const cdl_label_box *b, const cdl_label_box *bounds)
{
    return b->x0 >= bounds->x0 && b->y0 >= bounds->y0 && b->x1 <= bounds->x1 && b->y1 <= bounds->y1;
}

int main(void)
{
    /* Clash: overlapping, touching within the gap, apart. */
    cdl_label_box a = {0, 0, 10, 5}, b = {9, 4, 20, 8}, c = {10.5, 0, 12, 5}, d = {30, 30, 40, 40};
    CHECK(cdl_label_boxes_clash(&a, &b, 0.0) && cdl_label_boxes_clash(&b, &a, 0.0));
    CHECK(!cdl_label_boxes_clash(&a, &c, 0.0) && cdl_label_boxes_clash(&a, &c, 1.0));
    CHECK(!cdl_label_boxes_clash(&a, &d, 5.0));

    /* Two labels wanting the same first place: the first gets it, the second its next. */
    const double same[4] = {50, 50, 50, 80};
    cdl_label_request two[2] = {{30, 10, same, 2}, {30, 10, same, 2}};
    cdl_label_box bounds = {0, 0, 200, 100}, boxes[64];
    int placed[64];
    cdl_label_layout(two, 2, NULL, 0, bounds, 1.0, boxes, placed);
    CHECK(placed[0] && placed[1]);
    CHECK(boxes[0].x0 == 35 && boxes[0].y0 == 45);
    CHECK(boxes[1].x0 == 35 && boxes[1].y0 == 75);

    /* A crowd: 60 labels of 20 to 50 x 9 points, each with 12 candidate
     * centres scattered over a 200 x 100 map holding 6 obstacles. */
    enum { LABELS = 60, CANDIDATES = 12, OBSTACLES = 6 };
    uint64_t seed = 7;
    double centres[LABELS][2 * CANDIDATES];
    cdl_label_request crowd[LABELS];
    cdl_label_box obstacles[OBSTACLES];
    for (int k = 0; k < OBSTACLES; ++k)
        obstacles[k] = box_at(200.0 * next(&seed), 100.0 * next(&seed), 9.0, 9.0);
    for (int k = 0; k < LABELS; ++k) {
        for (int c = 0; c < 2 * CANDIDATES; c += 2) {
            centres[k][c] = 220.0 * next(&seed) - 10.0; /* some fall partly outside */
            centres[k][c + 1] = 110.0 * next(&seed) - 5.0;
        }
        crowd[k] = (cdl_label_request){20.0 + 30.0 * next(&seed), 9.0, centres[k], CANDIDATES};
    }
    const double gap = 1.0;
    cdl_label_layout(crowd, LABELS, obstacles, OBSTACLES, bounds, gap, boxes, placed);
    int count = 0;
    for (int k = 0; k < LABELS; ++k) {
        if (!placed[k]) {
            /* left out: every candidate was outside, or blocked by an obstacle or an earlier label */
            for (int c = 0; c < CANDIDATES; ++c) {
                cdl_label_box t = box_at(centres[k][2 * c], centres[k][2 * c + 1], crowd[k].width, crowd[k].height);
                int blocked = !inside(&t, &bounds);
                for (int o = 0; o < OBSTACLES && !blocked; ++o) blocked = cdl_label_boxes_clash(&t, &obstacles[o], gap);
                for (int j = 0; j < k && !blocked; ++j) blocked = placed[j] && cdl_label_boxes_clash(&t, &boxes[j], gap);
                CHECK_MSG(blocked, "label %d left out though its candidate %d was free", k, c);
            }
            continue;
        }
        ++count;
        CHECK_MSG(inside(&boxes[k], &bounds), "label %d outside the map", k);
        for (int o = 0; o < OBSTACLES; ++o)
            CHECK_MSG(!cdl_label_boxes_clash(&boxes[k], &obstacles[o], gap), "label %d on obstacle %d", k, o);
        for (int j = 0; j < k; ++j)
            CHECK_MSG(!placed[j] || !cdl_label_boxes_clash(&boxes[k], &boxes[j], gap), "labels %d and %d overlap", j,
                      k);
    }
    /* the crowd is a real one: some placed, some left out */
    printf("%d of %d labels placed\n", count, LABELS);
    CHECK(count >= 10 && count < LABELS);
    return check_finish();
}
