/* test_record_octree.c - the octree of record spheres: a lookup finds every
 * sphere holding the point, each once, in increasing id order, whatever
 * order the spheres were stored in. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"
#include "solver/icache/record_octree.h"

#define SPHERES 3000
#define LOOKUPS 4000

/* A small deterministic generator for the test's positions (splitmix64). */
static double next_unit(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

typedef struct sphere {
    cdl_vec3 c;
    double r;
} sphere;

static void run(int shuffled)
{
    uint64_t s = shuffled ? 7 : 3;
    sphere *sp = malloc(SPHERES * sizeof *sp);
    uint32_t *order = malloc(SPHERES * sizeof *order);
    if (!sp || !order) {
        CHECK(0);
        free(sp);
        free(order);
        return;
    }
    /* radii over three decades: spheres at many depths of a 10 m box */
    for (int i = 0; i < SPHERES; ++i) {
        sp[i].c = cdl_vec3_make(10.0 * next_unit(&s), 10.0 * next_unit(&s), 10.0 * next_unit(&s));
        sp[i].r = 0.01 * pow(1000.0, next_unit(&s));
        order[i] = (uint32_t)i;
    }
    if (shuffled)
        for (int i = SPHERES - 1; i > 0; --i) {
            int j = (int)(next_unit(&s) * (i + 1));
            uint32_t t = order[i];
            order[i] = order[j];
            order[j] = t;
        }
    cdl_bounds3 box = {cdl_vec3_make(0, 0, 0), cdl_vec3_make(10, 10, 10)};
    cdl_record_octree *tree = NULL;
    cdl_error err = {0};
    CHECK(cdl_record_octree_create(box, &tree, &err) == CDL_OK);
    for (int k = 0; tree && k < SPHERES; ++k)
        CHECK(cdl_record_octree_insert(tree, order[k], sp[order[k]].c, sp[order[k]].r, &err) == CDL_OK);
    uint32_t *ids = NULL;
    size_t capacity = 0, missed = 0, unordered = 0, found = 0;
    unsigned char *seen = calloc(SPHERES, 1);
    for (int q = 0; tree && seen && q < LOOKUPS; ++q) {
        cdl_vec3 p = cdl_vec3_make(10.0 * next_unit(&s), 10.0 * next_unit(&s), 10.0 * next_unit(&s));
        size_t m = cdl_record_octree_lookup(tree, p, &ids, &capacity);
        CHECK(m != (size_t)-1);
        if (m == (size_t)-1) break;
        for (size_t c = 0; c < m; ++c) {
            CHECK(ids[c] < SPHERES);
            if (c > 0 && !(ids[c - 1] < ids[c])) ++unordered; /* ascending, no id twice */
            if (ids[c] < SPHERES) seen[ids[c]] = 1;
        }
        /* every sphere holding p is among them (brute force) */
        for (int i = 0; i < SPHERES; ++i) {
            cdl_vec3 d = cdl_vec3_sub(p, sp[i].c);
            if (cdl_vec3_dot(d, d) <= sp[i].r * sp[i].r) {
                missed += !seen[i];
                ++found;
            }
        }
        for (size_t c = 0; c < m; ++c)
            if (ids[c] < SPHERES) seen[ids[c]] = 0;
    }
    fprintf(stderr, "%s: %zu spheres held the lookups' points, %zu missed, %zu out of order\n",
            shuffled ? "stored out of order" : "stored in order", found, missed, unordered);
    CHECK_MSG(found > LOOKUPS, "the spheres held too few points (%zu) to test the lookups", found);
    CHECK_MSG(missed == 0, "%zu spheres holding the point were not returned", missed);
    CHECK_MSG(unordered == 0, "%zu ids out of increasing order", unordered);
    free(seen);
    free(ids);
    cdl_record_octree_release(tree);
    free(sp);
    free(order);
}

int main(void)
{
    run(0);
    run(1);
    return check_finish();
}
