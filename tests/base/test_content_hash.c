/* The content hash: FNV-1a's published values, byte order fixed, and the
 * property the cache file relies on (one changed byte always shows). */
#include <string.h>

#include "check.h"
#include "base/content_hash.h"

static uint64_t raw(const char *s, size_t n)
{
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_raw(&h, s, n);
    return h.value;
}

int main(void)
{
    /* FNV-1a 64 test vectors (Fowler, Noll and Vo's reference list). */
    CHECK(raw("", 0) == 0xcbf29ce484222325ull);
    CHECK(raw("a", 1) == 0xaf63dc4c8601ec8cull);
    CHECK(raw("foobar", 6) == 0x85944171f73967e8ull);

    /* Integers little-endian, doubles by their bits: the same as hashing
     * those bytes, whatever the machine. */
    cdl_content_hash h = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_u64(&h, 0x0807060504030201ull);
    CHECK(h.value == raw("\x01\x02\x03\x04\x05\x06\x07\x08", 8));
    cdl_content_hash d = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_f64(&d, 1.0); /* 0x3ff0000000000000 */
    CHECK(d.value == raw("\x00\x00\x00\x00\x00\x00\xf0\x3f", 8));
    cdl_content_hash zero = CDL_CONTENT_HASH_INIT, minus_zero = CDL_CONTENT_HASH_INIT;
    cdl_content_hash_f64(&zero, 0.0);
    cdl_content_hash_f64(&minus_zero, -0.0);
    CHECK(zero.value != minus_zero.value);

    /* Every single-byte change of a 64-byte run changes the hash. */
    char base[64];
    for (int i = 0; i < 64; ++i) base[i] = (char)(i * 37);
    uint64_t ref = raw(base, sizeof base);
    int all_differ = 1;
    for (int i = 0; i < 64; ++i)
        for (int b = 1; b < 256; ++b) {
            char changed[64];
            memcpy(changed, base, sizeof changed);
            changed[i] = (char)(changed[i] ^ b);
            if (raw(changed, sizeof changed) == ref) all_differ = 0;
        }
    CHECK(all_differ);

    return check_finish();
}
