/* content_hash.h - a 64-bit hash of typed content, the same on every machine.
 *
 * FNV-1a (Fowler, Noll and Vo; 64-bit offset basis 0xcbf29ce484222325,
 * prime 0x100000001b3): for each byte b, h = (h xor b) x prime mod 2^64.
 * Not a cryptographic hash: it tells whether content changed, not whether
 * someone forged it. Each step is a bijection of h for a fixed byte, so two
 * inputs of the same length that differ in exactly one byte always hash
 * differently (a flipped byte in a file is always caught); otherwise a
 * change goes unnoticed with a chance of about 2^-64.
 *
 * Values are fed in a fixed byte order (little-endian) and doubles by their
 * IEEE 754 bits, so a hash means the same on any machine. A caller feeding
 * runs of varying length feeds their counts too, so that ("ab", "c") and
 * ("a", "bc") differ. Pure functions of their arguments; thread-safe.
 */
#ifndef CANDELA_BASE_CONTENT_HASH_H
#define CANDELA_BASE_CONTENT_HASH_H

#include <stddef.h>
#include <stdint.h>

#include "radiometry/vec3.h"

typedef struct cdl_content_hash {
    uint64_t value;
} cdl_content_hash;

#define CDL_CONTENT_HASH_INIT {0xcbf29ce484222325ull}

/* n bytes as they are (no length): the plain FNV-1a of a byte string. */
void cdl_content_hash_raw(cdl_content_hash *h, const void *data, size_t n);
/* 8 bytes, little-endian. */
void cdl_content_hash_u64(cdl_content_hash *h, uint64_t v);
/* The IEEE 754 bits of v, little-endian (-0 and 0 differ). */
void cdl_content_hash_f64(cdl_content_hash *h, double v);
void cdl_content_hash_vec3(cdl_content_hash *h, cdl_vec3 v);
/* The bytes of the file at `path`, then their count (u64). Returns 0, or
 * the errno of what failed (opening or reading; the hash is then of part
 * of the file and must not be used). */
int cdl_content_hash_file(cdl_content_hash *h, const char *path);

#endif
