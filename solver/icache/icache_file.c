/* icache_file.c - the cache file: encode, check and decode, compare with now. */
#include "solver/icache/icache_file.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/atomic_file.h"
#include "base/content_hash.h"
#include "base/error_report.h"
#include "base/file_bytes.h"

static const unsigned char magic[8] = {'C', 'D', 'L', 'I', 'C', 'A', 'C', 'H'};

/* Doubles a record holds in the file, in the order of the format. */
#define RECORD_DOUBLES 17
#define RECORD_BYTES (8 * RECORD_DOUBLES)
/* Bytes before the version string: magic, format, length, string length. */
#define LEAD_BYTES 24
/* Bytes from the scene hashes to the grid count: 3 hashes, the settings
 * (4 + 8 + 4 + 8 + 4 + 4 + 4), the count. */
#define KEY_BYTES (24 + 36 + 8)
/* A grid's bytes besides its name and records: name length, points, hash, records. */
#define GRID_BYTES (4 + 8 + 8 + 8)
#define CHECKSUM_BYTES 8

uint64_t cdl_icache_grid_hash(const cdl_grid *grid)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&h, (uint64_t)grid->count);
    for (size_t i = 0; i < grid->count; ++i) {
        cdl_content_hash_vec3(&h, grid->points[i]);
        cdl_content_hash_vec3(&h, grid->normals[i]);
    }
    cdl_content_hash_f64(&h, grid->spacing_m);
    /* "auto" takes the cache only for grids with a raster */
    cdl_content_hash_u64(&h, grid->raster_width > 0);
    return h.value;
}

static void record_to_values(const cdl_icache_record *r, double v[RECORD_DOUBLES])
{
    const double values[RECORD_DOUBLES] = {r->p.x,      r->p.y,      r->p.z,      r->n.x,      r->n.y,    r->n.z,
                                           r->E,        r->var,      r->radius,   r->grad_r.x, r->grad_r.y,
                                           r->grad_r.z, r->grad_t.x, r->grad_t.y, r->grad_t.z, r->open,   r->harmonic};
    memcpy(v, values, sizeof values);
}

static void record_from_values(const double v[RECORD_DOUBLES], cdl_icache_record *r)
{
    r->p = cdl_vec3_make(v[0], v[1], v[2]);
    r->n = cdl_vec3_make(v[3], v[4], v[5]);
    r->E = v[6];
    r->var = v[7];
    r->radius = v[8];
    r->grad_r = cdl_vec3_make(v[9], v[10], v[11]);
    r->grad_t = cdl_vec3_make(v[12], v[13], v[14]);
    r->open = v[15];
    r->harmonic = v[16];
}

/* ---- encoding ------------------------------------------------------------------- */

static unsigned char *put_u32(unsigned char *at, uint32_t v)
{
    for (int i = 0; i < 4; ++i) *at++ = (unsigned char)(v >> (8 * i));
    return at;
}

static unsigned char *put_u64(unsigned char *at, uint64_t v)
{
    for (int i = 0; i < 8; ++i) *at++ = (unsigned char)(v >> (8 * i));
    return at;
}

static unsigned char *put_f64(unsigned char *at, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return put_u64(at, bits);
}

static unsigned char *put_bytes(unsigned char *at, const void *data, size_t n)
{
    memcpy(at, data, n);
    return at + n;
}

cdl_status cdl_icache_file_encode(const cdl_icache_key *key, const cdl_icache_file_grid *grids, size_t grid_count,
                                  unsigned char **data, size_t *size, cdl_error *err)
{
    *data = NULL;
    *size = 0;
    size_t vlen = strnlen(key->version, sizeof key->version);
    if (vlen == 0 || vlen >= sizeof key->version)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "irradiance cache: expected a version string of 1 to %zu bytes",
                             sizeof key->version - 1);
    size_t total = LEAD_BYTES + vlen + KEY_BYTES + CHECKSUM_BYTES;
    for (size_t g = 0; g < grid_count; ++g) {
        size_t m = strlen(grids[g].name);
        if (m == 0 || m > CDL_ICACHE_FILE_NAME_MAX)
            return cdl_error_set(err, CDL_ERR_INPUT, "grid '%.64s': expected a name of 1 to %d bytes for the "
                                 "irradiance cache file, found %zu", grids[g].name, CDL_ICACHE_FILE_NAME_MAX, m);
        /* no size_t overflow: each term stays below a quarter of its range */
        if (total > SIZE_MAX / 4 || grids[g].records.count > SIZE_MAX / 4 / RECORD_BYTES)
            return cdl_error_out_of_memory(err);
        total += GRID_BYTES + m + grids[g].records.count * RECORD_BYTES;
    }
    unsigned char *buf = malloc(total);
    if (!buf) return cdl_error_out_of_memory(err);
    unsigned char *at = put_bytes(buf, magic, sizeof magic);
    at = put_u32(at, CDL_ICACHE_FILE_FORMAT);
    at = put_u64(at, (uint64_t)total);
    at = put_u32(at, (uint32_t)vlen);
    at = put_bytes(at, key->version, vlen);
    at = put_u64(at, key->scene.geometry);
    at = put_u64(at, key->scene.materials);
    at = put_u64(at, key->scene.lights);
    const cdl_icache_settings *s = &key->settings;
    at = put_u32(at, (uint32_t)s->method);
    at = put_f64(at, s->target);
    at = put_u32(at, (uint32_t)(int32_t)s->bounces);
    at = put_u64(at, s->seed);
    at = put_u32(at, (uint32_t)(int32_t)s->direct_samples);
    at = put_u32(at, s->exact_route != 0);
    at = put_u32(at, s->gradients != 0);
    at = put_u64(at, (uint64_t)grid_count);
    for (size_t g = 0; g < grid_count; ++g) {
        const cdl_icache_file_grid *fg = &grids[g];
        size_t m = strlen(fg->name);
        at = put_u32(at, (uint32_t)m);
        at = put_bytes(at, fg->name, m);
        at = put_u64(at, fg->point_count);
        at = put_u64(at, fg->points_hash);
        at = put_u64(at, (uint64_t)fg->records.count);
        for (size_t r = 0; r < fg->records.count; ++r) {
            double v[RECORD_DOUBLES];
            record_to_values(&fg->records.items[r], v);
            for (int k = 0; k < RECORD_DOUBLES; ++k) at = put_f64(at, v[k]);
        }
    }
    cdl_content_hash sum = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&sum, buf, (size_t)(at - buf));
    at = put_u64(at, sum.value);
    *data = buf;
    *size = (size_t)(at - buf);
    return CDL_OK;
}

cdl_status cdl_icache_file_save(const char *path, const cdl_icache_key *key, const cdl_icache_file_grid *grids,
                                size_t grid_count, cdl_error *err)
{
    unsigned char *data = NULL;
    size_t size = 0;
    cdl_status st = cdl_icache_file_encode(key, grids, grid_count, &data, &size, err);
    if (st != CDL_OK) return st;
    st = cdl_atomic_file_write_all(path, data, size, err);
    free(data);
    return st;
}

/* ---- decoding ------------------------------------------------------------------- */

typedef struct reader {
    const unsigned char *data;
    size_t end;               /* readable bytes: all, then all but the checksum */
    size_t at;
    const char *path;
    const char *state;        /* "truncated" before the checksum is checked, "damaged" after */
    cdl_error *err;
} reader;

/* The next n bytes, or NULL when the readable bytes end first (error set). */
static const unsigned char *take(reader *r, size_t n, const char *what)
{
    if (r->end - r->at < n) {
        cdl_error_set(r->err, CDL_ERR_INPUT,
                      "%s: not a valid irradiance cache file: %s: expected %zu bytes of %s at byte %zu, found %zu",
                      r->path, r->state, n, what, r->at, r->end - r->at);
        return NULL;
    }
    const unsigned char *p = r->data + r->at;
    r->at += n;
    return p;
}

static uint32_t get_u32_at(const unsigned char *p)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= (uint32_t)p[i] << (8 * i);
    return v;
}

static uint64_t get_u64_at(const unsigned char *p)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= (uint64_t)p[i] << (8 * i);
    return v;
}

static int get_u32(reader *r, const char *what, uint32_t *v)
{
    const unsigned char *p = take(r, 4, what);
    if (p) *v = get_u32_at(p);
    return p != NULL;
}

static int get_u64(reader *r, const char *what, uint64_t *v)
{
    const unsigned char *p = take(r, 8, what);
    if (p) *v = get_u64_at(p);
    return p != NULL;
}

static int get_f64(reader *r, const char *what, double *v)
{
    uint64_t bits;
    if (!get_u64(r, what, &bits)) return 0;
    memcpy(v, &bits, sizeof *v);
    return 1;
}

static cdl_status invalid(const reader *r, const char *fmt, ...) CDL_PRINTF(2, 3);
static cdl_status invalid(const reader *r, const char *fmt, ...)
{
    char what[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cdl_error_set(r->err, CDL_ERR_INPUT, "%s: not a valid irradiance cache file: %s", r->path, what);
}

static void release_grids(cdl_icache_file_grid *grids, size_t count)
{
    for (size_t g = 0; g < count; ++g) {
        free(grids[g].name);
        cdl_icache_records_release(&grids[g].records);
    }
    free(grids);
}

/* Magic, format version, length and checksum: the whole file is there and
 * as written. */
static cdl_status check_frame(reader *r, size_t size)
{
    /* What begins otherwise is no cache (however short); what begins so but
     * ends within the magic is a truncated one. */
    size_t n = size < sizeof magic ? size : sizeof magic;
    if (n > 0 && memcmp(r->data, magic, n) != 0)
        return invalid(r, "expected it to begin with \"CDLICACH\": not an irradiance cache file of Candela");
    if (!take(r, sizeof magic, "the magic \"CDLICACH\"")) return r->err->status;
    uint32_t format;
    uint64_t length;
    if (!get_u32(r, "the format version", &format)) return r->err->status;
    if (format != CDL_ICACHE_FILE_FORMAT)
        return invalid(r, "format version %" PRIu32 ", this Candela reads version %d", format,
                       CDL_ICACHE_FILE_FORMAT);
    if (!get_u64(r, "the file's length", &length)) return r->err->status;
    if (length != (uint64_t)size)
        return invalid(r, "%s: its header says %" PRIu64 " bytes, the file has %zu",
                       length > (uint64_t)size ? "truncated" : "bytes added at its end", length, size);
    if (size < LEAD_BYTES + CHECKSUM_BYTES) return invalid(r, "truncated: %zu bytes, too few for a header", size);
    cdl_content_hash sum = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&sum, r->data, size - CHECKSUM_BYTES);
    if (sum.value != get_u64_at(r->data + size - CHECKSUM_BYTES))
        return invalid(r, "damaged: its checksum does not match its content");
    r->end = size - CHECKSUM_BYTES;
    r->state = "damaged";
    return CDL_OK;
}

static cdl_status read_key(reader *r, cdl_icache_key *key)
{
    uint32_t vlen, method, bounces, samples, exact, gradients;
    if (!get_u32(r, "the version string's length", &vlen)) return r->err->status;
    if (vlen == 0 || vlen >= sizeof key->version)
        return invalid(r, "damaged: a version string of %" PRIu32 " bytes (expected 1 to %zu)", vlen,
                       sizeof key->version - 1);
    const unsigned char *v = take(r, vlen, "the version string");
    if (!v) return r->err->status;
    for (uint32_t i = 0; i < vlen; ++i)
        if (v[i] < 0x20 || v[i] > 0x7e) return invalid(r, "damaged: the version string holds a byte 0x%02x", v[i]);
    memcpy(key->version, v, vlen);
    key->version[vlen] = '\0';
    cdl_icache_settings *s = &key->settings;
    if (!get_u64(r, "the geometry hash", &key->scene.geometry) ||
        !get_u64(r, "the materials hash", &key->scene.materials) ||
        !get_u64(r, "the lights hash", &key->scene.lights) || !get_u32(r, "the method", &method) ||
        !get_f64(r, "the target error", &s->target) || !get_u32(r, "the bounces", &bounces) ||
        !get_u64(r, "the seed", &s->seed) || !get_u32(r, "direct_samples", &samples) ||
        !get_u32(r, "the exact-route flag", &exact) || !get_u32(r, "the gradients flag", &gradients))
        return r->err->status;
    if (method > CDL_METHOD_PATHTRACE) return invalid(r, "damaged: method %" PRIu32 " (expected 0 to 3)", method);
    if (!(isfinite(s->target) && s->target > 0.0))
        return invalid(r, "damaged: target error %g (expected a finite number > 0)", s->target);
    if (exact > 1 || gradients > 1) return invalid(r, "damaged: a flag other than 0 or 1");
    s->method = (cdl_method)method;
    s->bounces = (int32_t)bounces;
    s->direct_samples = (int32_t)samples;
    s->exact_route = (int)exact;
    s->gradients = (int)gradients;
    return CDL_OK;
}

/* A record's values must be such as a gather makes: what is wrong with
 * them, or NULL. */
static const char *record_fault(const double v[RECORD_DOUBLES])
{
    static const char *const names[RECORD_DOUBLES] = {"p.x", "p.y", "p.z", "n.x", "n.y", "n.z", "E", "var", "radius",
                                                      "grad_r.x", "grad_r.y", "grad_r.z", "grad_t.x", "grad_t.y",
                                                      "grad_t.z", "open", "harmonic"};
    for (int k = 0; k < RECORD_DOUBLES - 1; ++k)
        if (!isfinite(v[k])) return names[k];
    if (!(v[16] > 0.0)) return "harmonic (expected > 0, or +infinity)";
    if (!(v[7] >= 0.0)) return "var (expected a variance >= 0)";
    if (!(v[8] >= 0.0)) return "radius (expected >= 0; 0: a record serving only its own point)";
    if (!(v[15] <= 1.0 && v[15] >= 0.0)) return "open (expected a fraction in [0, 1])";
    return NULL;
}

static cdl_status read_grid(reader *r, size_t g, cdl_icache_file_grid *fg)
{
    uint32_t m;
    if (!get_u32(r, "a grid name's length", &m)) return r->err->status;
    if (m == 0 || m > CDL_ICACHE_FILE_NAME_MAX)
        return invalid(r, "damaged: grid %zu: a name of %" PRIu32 " bytes (expected 1 to %d)", g, m,
                       CDL_ICACHE_FILE_NAME_MAX);
    const unsigned char *name = take(r, m, "a grid name");
    if (!name) return r->err->status;
    if (memchr(name, '\0', m)) return invalid(r, "damaged: grid %zu: a NUL byte in its name", g);
    fg->name = malloc((size_t)m + 1);
    if (!fg->name) return cdl_error_out_of_memory(r->err);
    memcpy(fg->name, name, m);
    fg->name[m] = '\0';
    uint64_t count;
    if (!get_u64(r, "a grid's point count", &fg->point_count) || !get_u64(r, "a grid's hash", &fg->points_hash) ||
        !get_u64(r, "a grid's record count", &count))
        return r->err->status;
    if (count > (r->end - r->at) / RECORD_BYTES)
        return invalid(r, "damaged: grid '%s' says %" PRIu64 " records, the file has room for %zu", fg->name, count,
                       (r->end - r->at) / RECORD_BYTES);
    if (count == 0 && fg->point_count > 0)
        return invalid(r, "damaged: grid '%s' has %" PRIu64 " points and no record", fg->name, fg->point_count);
    fg->records.items = malloc((count ? (size_t)count : 1) * sizeof *fg->records.items);
    if (!fg->records.items) return cdl_error_out_of_memory(r->err);
    fg->records.capacity = (size_t)count;
    for (size_t i = 0; i < (size_t)count; ++i) {
        double v[RECORD_DOUBLES];
        for (int k = 0; k < RECORD_DOUBLES; ++k)
            if (!get_f64(r, "a record", &v[k])) return r->err->status;
        const char *fault = record_fault(v);
        if (fault) {
            int finite = strchr(fault, ' ') != NULL;
            return invalid(r, "damaged: grid '%s' record %zu: %s%s", fg->name, i, finite ? "" : "a value that is not "
                           "finite: ", fault);
        }
        record_from_values(v, &fg->records.items[i]);
        fg->records.count = i + 1;
    }
    return CDL_OK;
}

cdl_status cdl_icache_file_parse(const unsigned char *data, size_t size, const char *path, cdl_icache_file *out,
                                 cdl_error *err)
{
    reader r = {data, size, 0, path, "truncated", err};
    cdl_status st = check_frame(&r, size);
    cdl_icache_file f;
    memset(&f, 0, sizeof f);
    if (st == CDL_OK) st = read_key(&r, &f.key);
    uint64_t count = 0;
    if (st == CDL_OK && !get_u64(&r, "the grid count", &count)) st = err->status;
    if (st == CDL_OK && count > (r.end - r.at) / (GRID_BYTES + 1))
        st = invalid(&r, "damaged: %" PRIu64 " grids, the file has room for %zu", count,
                     (r.end - r.at) / (GRID_BYTES + 1));
    if (st == CDL_OK) {
        f.grids = calloc(count ? (size_t)count : 1, sizeof *f.grids);
        if (!f.grids) st = cdl_error_out_of_memory(err);
    }
    for (size_t g = 0; st == CDL_OK && g < (size_t)count; ++g) {
        st = read_grid(&r, g, &f.grids[g]);
        f.grid_count = g + 1;
        for (size_t h = 0; st == CDL_OK && h < g; ++h)
            if (strcmp(f.grids[h].name, f.grids[g].name) == 0)
                st = invalid(&r, "damaged: grid '%s' appears twice", f.grids[g].name);
    }
    if (st == CDL_OK && r.at != r.end) st = invalid(&r, "damaged: %zu bytes after the last grid", r.end - r.at);
    if (st != CDL_OK) {
        release_grids(f.grids, f.grid_count);
        return st;
    }
    *out = f;
    return CDL_OK;
}

cdl_status cdl_icache_file_load(const char *path, int *found, cdl_icache_file *out, cdl_error *err)
{
    struct stat info;
    *found = 0;
    if (stat(path, &info) != 0 && errno == ENOENT) return CDL_OK;
    *found = 1;
    char *data = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "irradiance cache file", SIZE_MAX / 2, &data, &size, err);
    if (st == CDL_OK) st = cdl_icache_file_parse((const unsigned char *)data, size, path, out, err);
    free(data);
    return st;
}

void cdl_icache_file_release(cdl_icache_file *file)
{
    release_grids(file->grids, file->grid_count);
    memset(file, 0, sizeof *file);
}

/* ---- made for this scene? ------------------------------------------------------- */

/* Append to a message being built in buf (of size `size`). */
static void append(char *buf, size_t size, const char *fmt, ...) CDL_PRINTF(3, 4);
static void append(char *buf, size_t size, const char *fmt, ...)
{
    size_t n = strlen(buf);
    if (n + 1 >= size) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + n, size - n, fmt, ap);
    va_end(ap);
}

static const char *refuse_hint = "; remove the file (or give another) to compute the records anew";

static void describe_bounces(int bounces, char *buf, size_t size)
{
    if (bounces == CDL_BOUNCES_AUTO)
        snprintf(buf, size, "auto");
    else
        snprintf(buf, size, "%d", bounces);
}

static const char *on_off(int flag)
{
    return flag ? "on" : "off";
}

cdl_status cdl_icache_file_match_key(const cdl_icache_file *file, const char *path, const cdl_icache_key *now,
                                     cdl_error *err)
{
    const cdl_icache_key *was = &file->key;
    if (strcmp(was->version, now->version) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: the irradiance cache was written by Candela %s, this is Candela %s (records are "
                             "not carried from one version to another)%s",
                             path, was->version, now->version, refuse_hint);
    char scene[256] = "";
    if (was->scene.geometry != now->scene.geometry) append(scene, sizeof scene, ", the surfaces' geometry");
    if (was->scene.materials != now->scene.materials)
        append(scene, sizeof scene, ", the reflectances (or two-sidedness)");
    if (was->scene.lights != now->scene.lights)
        append(scene, sizeof scene, ", the lights (luminaires, their files, or emitting surfaces)");
    char settings[512] = "";
    const cdl_icache_settings *a = &was->settings, *b = &now->settings;
    if (a->method != b->method)
        append(settings, sizeof settings, "; method %s in the cache, %s now", cdl_method_name(a->method),
               cdl_method_name(b->method));
    if (a->target != b->target)
        append(settings, sizeof settings, "; target_error %.6g in the cache, %.6g now", a->target, b->target);
    if (a->bounces != b->bounces) {
        char x[32], y[32];
        describe_bounces(a->bounces, x, sizeof x);
        describe_bounces(b->bounces, y, sizeof y);
        append(settings, sizeof settings, "; bounces %s in the cache, %s now", x, y);
    }
    if (a->seed != b->seed)
        append(settings, sizeof settings, "; seed %" PRIu64 " in the cache, %" PRIu64 " now", a->seed, b->seed);
    if (a->direct_samples != b->direct_samples)
        append(settings, sizeof settings, "; direct_samples %d in the cache, %d now", a->direct_samples,
               b->direct_samples);
    if (a->exact_route != b->exact_route)
        append(settings, sizeof settings, "; exact routes for partly hidden emitters %s in the cache, %s now",
               on_off(a->exact_route), on_off(b->exact_route));
    if (a->gradients != b->gradients)
        append(settings, sizeof settings, "; cache gradients %s in the cache, %s now", on_off(a->gradients),
               on_off(b->gradients));
    if (!scene[0] && !settings[0]) return CDL_OK;
    char what[800] = "";
    if (scene[0]) append(what, sizeof what, "made for another scene (changed since: %s)", scene + 2);
    if (settings[0]) append(what, sizeof what, "%smade with other settings: %s", scene[0] ? " and " : "", settings + 2);
    return cdl_error_set(err, CDL_ERR_INPUT, "%s: the irradiance cache was %s%s", path, what, refuse_hint);
}

cdl_status cdl_icache_file_match_grids(const cdl_icache_file *file, const char *path, const char *const *names,
                                       const cdl_grid *const *grids, size_t count, size_t *index, cdl_error *err)
{
    unsigned char *used = calloc(file->grid_count ? file->grid_count : 1, 1);
    if (!used) return cdl_error_out_of_memory(err);
    cdl_status st = CDL_OK;
    for (size_t k = 0; k < count && st == CDL_OK; ++k) {
        size_t j = 0;
        while (j < file->grid_count && strcmp(file->grids[j].name, names[k]) != 0) ++j;
        if (j == file->grid_count) {
            char held[512] = "";
            for (size_t h = 0; h < file->grid_count; ++h)
                append(held, sizeof held, "%s'%s'", h ? ", " : "", file->grids[h].name);
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: grid '%s' is not in the irradiance cache (it holds %s%s)%s", path, names[k],
                               file->grid_count ? "grids " : "no grid", held, refuse_hint);
            break;
        }
        const cdl_icache_file_grid *fg = &file->grids[j];
        if (fg->point_count != (uint64_t)grids[k]->count)
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: grid '%s' changed: %" PRIu64 " points in the irradiance cache, %zu now%s", path,
                               names[k], fg->point_count, grids[k]->count, refuse_hint);
        else if (fg->points_hash != cdl_icache_grid_hash(grids[k]))
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: grid '%s' changed: its points, normals or spacing differ from the irradiance "
                               "cache's%s", path, names[k], refuse_hint);
        used[j] = 1;
        index[k] = j;
    }
    for (size_t j = 0; j < file->grid_count && st == CDL_OK; ++j)
        if (!used[j])
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s: the irradiance cache holds grid '%s', which the scene does not solve by the "
                               "irradiance cache now (no such grid, or another method)%s",
                               path, file->grids[j].name, refuse_hint);
    free(used);
    return st;
}
