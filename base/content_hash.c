/* content_hash.c - FNV-1a over typed values in a fixed byte order. */
#include "base/content_hash.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

void cdl_content_hash_raw(cdl_content_hash *h, const void *data, size_t n)
{
    const unsigned char *b = data;
    uint64_t v = h->value;
    /* FNV-1a: h = (h xor byte) x 0x100000001b3 (mod 2^64). */
    for (size_t i = 0; i < n; ++i) v = (v ^ b[i]) * 0x100000001b3ull;
    h->value = v;
}

void cdl_content_hash_u64(cdl_content_hash *h, uint64_t v)
{
    unsigned char b[8];
    for (int i = 0; i < 8; ++i) b[i] = (unsigned char)(v >> (8 * i));
    cdl_content_hash_raw(h, b, sizeof b);
}

void cdl_content_hash_f64(cdl_content_hash *h, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    cdl_content_hash_u64(h, bits);
}

void cdl_content_hash_vec3(cdl_content_hash *h, cdl_vec3 v)
{
    cdl_content_hash_f64(h, v.x);
    cdl_content_hash_f64(h, v.y);
    cdl_content_hash_f64(h, v.z);
}

int cdl_content_hash_file(cdl_content_hash *h, const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return errno ? errno : EIO;
    unsigned char buffer[65536];
    uint64_t total = 0;
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, fp)) > 0) {
        cdl_content_hash_raw(h, buffer, n);
        total += n;
    }
    int failed = ferror(fp) ? (errno ? errno : EIO) : 0;
    fclose(fp);
    cdl_content_hash_u64(h, total);
    return failed;
}
