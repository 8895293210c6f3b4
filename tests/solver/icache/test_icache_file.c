/* The irradiance cache's file (solver/icache/icache_file.h, `solve --cache`):
 *  - a solve that finds no file gathers records and writes them; a solve of
 *    the same scene and settings reads them, gathers none, and gives the
 *    same bytes (on another thread count);
 *  - the file round-trips every field bit for bit;
 *  - a truncated file (at every byte of its header, inside its records),
 *    one with any single byte flipped, with bytes added, with impossible
 *    counts or non-finite values is refused, naming the file;
 *  - a file made for another scene (geometry, reflectance, light), other
 *    settings (target_error, seed), other grids (a moved point, a grid added
 *    or removed) or another Candela version is refused with a message
 *    naming what differs, and left as it was. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "base/content_hash.h"
#include "solver/icache/icache_file.h"
#include "solver/solve_fixture.h"

/* The scene and what each test changes in it. */
typedef struct variant {
    double rho, intensity, target, floor_x, box_top;
    int seed;
    int wall;                 /* 1: the wall grid too */
    int extra;                /* 1: a third grid */
} variant;

static const variant base = {0.5, 1000.0, 0.02, 0.1, 3.0, 1, 1, 0};

/* A closed 4 x 4 x 3 m box, rho 0.5, one point light, a 20 x 20 floor grid
 * and a 10 x 6 wall grid, both by the irradiance cache at 2 %. */
static void scene_json(const variant *v, char *buf, size_t size)
{
    snprintf(buf, size,
             "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,%.17g], "
             "\"inward\": true, \"reflectance\": %.17g}],"
             " \"luminaires\": [{\"type\": \"point\", \"position\": [2,2,2.5], \"intensity_cd\": %.17g}],"
             " \"grids\": [{\"name\": \"floor\", \"type\": \"rect\", \"origin\": [%.17g,0.1,0.8], \"u\": [3.8,0,0], "
             "\"v\": [0,3.8,0], \"nu\": 20, \"nv\": 20}%s%s],"
             " \"solver\": {\"method\": \"icache\", \"target_error\": %.17g, \"seed\": %d}}",
             v->box_top, v->rho, v->intensity, v->floor_x,
             v->wall ? ", {\"name\": \"wall\", \"type\": \"rect\", \"origin\": [0,0.2,0.2], \"u\": [0,3.6,0], "
                       "\"v\": [0,0,2.6], \"nu\": 10, \"nv\": 6}"
                     : "",
             v->extra ? ", {\"name\": \"desk\", \"type\": \"rect\", \"origin\": [1,1,0.75], \"u\": [1,0,0], "
                        "\"v\": [0,1,0], \"nu\": 5, \"nv\": 5}"
                      : "",
             v->target, v->seed);
}

/* Solve the variant with the cache file `cache`; the status, *err filled. */
static cdl_status solve(const variant *v, const char *cache, int threads, cdl_scene **scene, cdl_solution *sol,
                        cdl_error *err)
{
    char json[4096];
    scene_json(v, json, sizeof json);
    cdl_error_clear(err);
    *scene = NULL;
    memset(sol, 0, sizeof *sol);
    cdl_status st = cdl_scene_load_string(json, CANDELA_TEST_TMPDIR "/inline.json", scene, err);
    if (st != CDL_OK) return st;
    cdl_solve_options o = CDL_SOLVE_OPTIONS_INIT;
    o.threads = threads;
    o.cache_path = cache;
    return cdl_solve_scene_into(*scene, &o, NULL, sol, err);
}

/* The plan's interreflection "paths": paths traced by this solve. */
static double plan_paths(const cdl_solution *sol)
{
    cJSON *plan = cJSON_Parse(sol->plan_json);
    cJSON *paths = cJSON_GetObjectItem(cJSON_GetObjectItem(plan, "interreflection"), "paths");
    double n = cJSON_IsNumber(paths) ? paths->valuedouble : -1.0;
    cJSON_Delete(plan);
    return n;
}

static int same_doubles(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, n * sizeof *a) == 0;
}

/* The two solves of one scene: the first writes the file, the second reads
 * it and must give the same bytes without gathering. */
static void test_reuse(const char *cache, const char *dir)
{
    cdl_scene *s1, *s2;
    cdl_solution a, b;
    cdl_error err;
    CHECK_OK(solve(&base, cache, 2, &s1, &a, &err), &err);
    CHECK(access(cache, F_OK) == 0);
    CHECK(a.cache_reused == 0);
    CHECK(a.records > 0 && a.records_gathered == a.records);
    CHECK(plan_paths(&a) > 0.0);
    CHECK_MSG(fixture_count_entries(dir) == 1, "the cache file alone, no temporary file: %d entries",
              fixture_count_entries(dir));

    CHECK_OK(solve(&base, cache, 1, &s2, &b, &err), &err);
    CHECK(b.cache_reused == 1);
    CHECK_MSG(b.records == a.records && b.records_gathered == 0, "records %llu (gathered %llu), first solve %llu",
              (unsigned long long)b.records, (unsigned long long)b.records_gathered, (unsigned long long)a.records);
    CHECK_MSG(plan_paths(&b) == 0.0, "reuse traced %g paths", plan_paths(&b));
    CHECK(strstr(b.plan_json, "\"reused\":true") != NULL);
    CHECK(a.grid_count == 2 && b.grid_count == 2);
    for (size_t g = 0; g < a.grid_count && g < b.grid_count; ++g) {
        size_t n = a.grids[g].grid.count;
        CHECK(b.grids[g].grid.count == n);
        CHECK_MSG(same_doubles(a.grids[g].E, b.grids[g].E, n), "grid %zu: E differs on reuse", g);
        CHECK_MSG(same_doubles(a.grids[g].E_stderr, b.grids[g].E_stderr, n), "grid %zu: E_stderr differs", g);
        CHECK_MSG(same_doubles(a.grids[g].E_indirect, b.grids[g].E_indirect, n), "grid %zu: E_indirect differs", g);
        /* The cache does hold the interreflection: it is not zero. */
        double sum = 0.0;
        for (size_t i = 0; i < n; ++i) sum += b.grids[g].E_indirect[i];
        CHECK(sum > 0.0);
    }
    fixture_release(s1, &a);
    fixture_release(s2, &b);
}

static void check_same_file(const cdl_icache_file *x, const cdl_icache_file *y)
{
    CHECK(strcmp(x->key.version, y->key.version) == 0);
    CHECK(memcmp(&x->key.scene, &y->key.scene, sizeof x->key.scene) == 0);
    const cdl_icache_settings *a = &x->key.settings, *b = &y->key.settings;
    CHECK(a->method == b->method && memcmp(&a->target, &b->target, sizeof a->target) == 0 &&
          a->bounces == b->bounces && a->seed == b->seed && a->direct_samples == b->direct_samples &&
          a->exact_route == b->exact_route && a->gradients == b->gradients);
    CHECK(x->grid_count == y->grid_count);
    for (size_t g = 0; g < x->grid_count && g < y->grid_count; ++g) {
        const cdl_icache_file_grid *p = &x->grids[g], *q = &y->grids[g];
        CHECK(strcmp(p->name, q->name) == 0 && p->point_count == q->point_count && p->points_hash == q->points_hash);
        CHECK(p->records.count == q->records.count);
        /* a record is 17 doubles: compared bit for bit */
        if (p->records.count == q->records.count)
            CHECK(memcmp(p->records.items, q->records.items, p->records.count * sizeof *p->records.items) == 0);
    }
}

/* Save, load: every field as it was, bit for bit, including values a
 * gather makes rarely (an infinite harmonic mean, -0, subnormals). */
static void test_round_trip(const char *cache, const char *dir)
{
    cdl_error err;
    cdl_error_clear(&err); /* calls set it only when they fail */
    cdl_icache_file f;
    int found = 0;
    CHECK_OK(cdl_icache_file_load(cache, &found, &f, &err), &err);
    CHECK(found);
    if (!found || err.status != CDL_OK) return;
    CHECK(strcmp(f.key.version, CDL_ICACHE_MAKER) == 0);
    CHECK(f.grid_count == 2 && f.key.settings.target == 0.02 && f.key.settings.seed == 1);
    cdl_icache_record *r = &f.grids[0].records.items[0];
    r->harmonic = INFINITY;
    r->open = 1.0;
    r->grad_t.x = -0.0;
    r->grad_r.y = 4.9406564584124654e-324;
    r->E = 1.7976931348623157e308;
    f.key.settings.bounces = CDL_BOUNCES_AUTO;
    f.key.settings.direct_samples = 12345;
    f.key.settings.exact_route = 0;
    f.key.settings.seed = 0xfedcba9876543210ull;
    char path[700];
    snprintf(path, sizeof path, "%s/round.bin", dir);
    CHECK_OK(cdl_icache_file_save(path, &f.key, f.grids, f.grid_count, &err), &err);
    cdl_icache_file g;
    CHECK_OK(cdl_icache_file_load(path, &found, &g, &err), &err);
    if (err.status == CDL_OK) {
        check_same_file(&f, &g);
        CHECK(signbit(g.grids[0].records.items[0].grad_t.x));
        cdl_icache_file_release(&g);
    }
    unlink(path);
    /* And the file itself: decoding and encoding again gives its bytes. */
    size_t size = 0;
    char *bytes = fixture_read_file(cache, &size);
    cdl_icache_file h;
    unsigned char *again = NULL;
    size_t again_size = 0;
    CHECK_OK(cdl_icache_file_parse((const unsigned char *)bytes, size, cache, &h, &err), &err);
    if (err.status == CDL_OK) {
        CHECK_OK(cdl_icache_file_encode(&h.key, h.grids, h.grid_count, &again, &again_size, &err), &err);
        CHECK(again && again_size == size && memcmp(again, bytes, size) == 0);
        cdl_icache_file_release(&h);
    }
    free(again);
    free(bytes);
    cdl_icache_file_release(&f);
}

/* The checksum of a changed buffer recomputed: what is left to refuse it is
 * the check of its counts and values. */
static void reseal(unsigned char *data, size_t size)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, data, size - 8);
    for (int i = 0; i < 8; ++i) data[size - 8 + i] = (unsigned char)(h.value >> (8 * i));
}

/* Parsing must fail, say `word`, name the file, and leave *out as it was. */
static int refused(const unsigned char *data, size_t size, const char *word)
{
    cdl_icache_file out;
    memset(&out, 0xab, sizeof out);
    cdl_icache_file before = out;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = cdl_icache_file_parse(data, size, "cache.bin", &out, &err);
    int ok = st == CDL_ERR_INPUT && strncmp(err.message, "cache.bin: ", 11) == 0 && strstr(err.message, word) &&
             memcmp(&out, &before, sizeof out) == 0;
    if (st == CDL_OK) cdl_icache_file_release(&out);
    if (!ok) fprintf(stderr, "status %d, message: %s\n", (int)st, err.message);
    return ok;
}

static void test_damaged(const char *cache)
{
    size_t size = 0;
    unsigned char *data = (unsigned char *)fixture_read_file(cache, &size);
    if (!data) {
        CHECK(0);
        return;
    }
    /* The header: magic 8, format 4, length 8, version string length 4,
     * the string, hashes 24, settings 36, grid count 8, the first grid's
     * name length 4, name "floor" 5, three counts 24; then its records. */
    size_t header = 24 + strlen(CDL_ICACHE_MAKER) + 24 + 36 + 8 + 4 + 5 + 24;
    CHECK(size > header + 1000);
    /* Truncated at every byte of the header, and within the records. */
    int all = 1;
    for (size_t n = 0; n <= header + 200 && n < size; ++n) all &= refused(data, n, "truncated");
    for (size_t n = header + 200; n < size; n += 331) all &= refused(data, n, "truncated");
    all &= refused(data, size - 1, "truncated");
    all &= refused(data, size - 8, "truncated");
    CHECK_MSG(all, "every truncation refused as truncated");

    /* Any byte changed: refused (the checksum, or the length or magic it covers). */
    all = 1;
    for (size_t i = 0; i < size; ++i) {
        unsigned char was = data[i];
        data[i] = (unsigned char)(was ^ (i % 7 == 0 ? 0xff : 0x01));
        all &= refused(data, size, "");
        data[i] = was;
    }
    CHECK_MSG(all, "every flipped byte refused");
    data[size / 2] ^= 0x10;
    CHECK(refused(data, size, "checksum"));
    data[size / 2] ^= 0x10;

    /* Bytes added at the end. */
    unsigned char *longer = malloc(size + 1);
    memcpy(longer, data, size);
    longer[size] = 0;
    CHECK(refused(longer, size + 1, "bytes added"));
    free(longer);

    /* Another format version, and not a cache at all. */
    data[8] = 2;
    CHECK(refused(data, size, "format version 2"));
    data[8] = 1;
    CHECK(refused((const unsigned char *)"{\"version\": 1}", 14, "CDLICACH"));

    /* Valid checksum, impossible content: a record count beyond the file,
     * a non-finite value, a negative variance. */
    size_t count_at = header - 8;
    unsigned char keep[8];
    memcpy(keep, data + count_at, 8);
    memset(data + count_at, 0xff, 8);
    reseal(data, size);
    CHECK(refused(data, size, "room for"));
    memcpy(data + count_at, keep, 8);
    size_t E_at = header + 6 * 8, var_at = header + 7 * 8;
    memcpy(keep, data + E_at, 8);
    const double nan = NAN, negative = -1.0;
    memcpy(data + E_at, &nan, 8); /* this test runs on little-endian machines (x86, ARM) */
    reseal(data, size);
    CHECK(refused(data, size, "not finite: E"));
    memcpy(data + E_at, keep, 8);
    memcpy(keep, data + var_at, 8);
    memcpy(data + var_at, &negative, 8);
    reseal(data, size);
    CHECK(refused(data, size, "var (expected a variance >= 0)"));
    memcpy(data + var_at, keep, 8);
    reseal(data, size);

    /* Through a solve: a truncated file on disk is refused, and left alone. */
    char cut[700];
    snprintf(cut, sizeof cut, "%s.cut", cache);
    FILE *fp = fopen(cut, "wb");
    if (fp) {
        fwrite(data, 1, size / 2, fp);
        fclose(fp);
    }
    cdl_scene *scene;
    cdl_solution sol;
    cdl_error err;
    CHECK(solve(&base, cut, 2, &scene, &sol, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, cut) && strstr(err.message, "truncated"), "%s", err.message);
    cdl_scene_release(scene);
    CHECK(fixture_file_is(cut, (const char *)data, size / 2));
    unlink(cut);
    free(data);
}

/* A solve of `v` with the cache made for `base` is refused, naming what
 * differs, and the file is left as it was. */
static void expect_refusal(const char *cache, const variant *v, const char *what, const char *word)
{
    size_t size = 0;
    char *before = fixture_read_file(cache, &size);
    cdl_scene *scene;
    cdl_solution sol;
    cdl_error err;
    cdl_status st = solve(v, cache, 2, &scene, &sol, &err);
    CHECK_MSG(st == CDL_ERR_INPUT, "%s: status %d (%s)", what, (int)st, err.message);
    CHECK_MSG(strncmp(err.message, cache, strlen(cache)) == 0 && strstr(err.message, word),
              "%s: expected the file and \"%s\" in: %s", what, word, err.message);
    printf("%s: %s\n", what, err.message);
    if (st == CDL_OK) cdl_solution_clear(&sol);
    cdl_scene_release(scene);
    CHECK_MSG(fixture_file_is(cache, before, size), "%s: the cache file was changed", what);
    free(before);
}

static void test_stale(const char *cache, const char *dir)
{
    /* rho, intensity, target, floor_x, box_top, seed, wall, extra */
    static const struct {
        const char *what, *word;
        variant v;
    } cases[] = {
        {"reflectance", "changed since: the reflectances", {0.55, 1000.0, 0.02, 0.1, 3.0, 1, 1, 0}},
        {"light", "changed since: the lights", {0.5, 1001.0, 0.02, 0.1, 3.0, 1, 1, 0}},
        {"geometry", "changed since: the surfaces' geometry", {0.5, 1000.0, 0.02, 0.1, 3.1, 1, 1, 0}},
        {"target_error", "target_error 0.02 in the cache, 0.03 now", {0.5, 1000.0, 0.03, 0.1, 3.0, 1, 1, 0}},
        {"seed", "seed 1 in the cache, 7 now", {0.5, 1000.0, 0.02, 0.1, 3.0, 7, 1, 0}},
        {"grid point", "grid 'floor' changed: its points", {0.5, 1000.0, 0.02, 0.1000001, 3.0, 1, 1, 0}},
        {"grid added", "grid 'desk' is not in the irradiance cache", {0.5, 1000.0, 0.02, 0.1, 3.0, 1, 1, 1}},
        {"grid removed", "holds grid 'wall'", {0.5, 1000.0, 0.02, 0.1, 3.0, 1, 0, 0}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c)
        expect_refusal(cache, &cases[c].v, cases[c].what, cases[c].word);

    /* Another Candela version. */
    cdl_icache_file f;
    int found = 0;
    cdl_error err;
    cdl_error_clear(&err); /* calls set it only when they fail */
    CHECK_OK(cdl_icache_file_load(cache, &found, &f, &err), &err);
    if (err.status != CDL_OK) return;
    snprintf(f.key.version, sizeof f.key.version, "0.0.9");
    char old[700];
    snprintf(old, sizeof old, "%s/old.bin", dir);
    CHECK_OK(cdl_icache_file_save(old, &f.key, f.grids, f.grid_count, &err), &err);
    cdl_icache_file_release(&f);
    expect_refusal(old, &base, "version", "written by Candela 0.0.9, this is Candela " CDL_ICACHE_MAKER);
    unlink(old);
}

int main(void)
{
    char dir[512], cache[600];
    CHECK(fixture_folder("test_icache_file", dir, sizeof dir));
    snprintf(cache, sizeof cache, "%s/c.bin", dir);
    test_reuse(cache, dir);
    test_round_trip(cache, dir);
    test_damaged(cache);
    test_stale(cache, dir);
    CHECK_MSG(fixture_count_entries(dir) == 1, "only the cache file left: %d entries", fixture_count_entries(dir));
    unlink(cache);
    return check_finish();
}
