/* vec3.h - small 3-vector maths in double precision.
 * Positions are in metres in world space (right-handed, z up) unless a
 * function says otherwise; directions are unit vectors where documented.
 * Ownership: values only. Thread safety: pure static inline functions,
 * thread-safe. Errors: none (a zero vector normalises to itself). They use
 * <math.h>: a program calling them links the maths library (-lm). */
#ifndef CANDELA_RADIOMETRY_VEC3_H
#define CANDELA_RADIOMETRY_VEC3_H

#include <float.h>
#include <math.h>

typedef struct cdl_vec3 { double x, y, z; } cdl_vec3;

static inline cdl_vec3 cdl_vec3_make(double x, double y, double z) { cdl_vec3 v = {x, y, z}; return v; }
static inline cdl_vec3 cdl_vec3_add(cdl_vec3 a, cdl_vec3 b) { return cdl_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline cdl_vec3 cdl_vec3_sub(cdl_vec3 a, cdl_vec3 b) { return cdl_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline cdl_vec3 cdl_vec3_scale(cdl_vec3 a, double k) { return cdl_vec3_make(a.x * k, a.y * k, a.z * k); }
static inline cdl_vec3 cdl_vec3_neg(cdl_vec3 a) { return cdl_vec3_make(-a.x, -a.y, -a.z); }
/* a + k b */
static inline cdl_vec3 cdl_vec3_madd(cdl_vec3 a, double k, cdl_vec3 b) { return cdl_vec3_make(a.x + k * b.x, a.y + k * b.y, a.z + k * b.z); }
static inline double cdl_vec3_dot(cdl_vec3 a, cdl_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline cdl_vec3 cdl_vec3_cross(cdl_vec3 a, cdl_vec3 b)
{
    return cdl_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double cdl_vec3_length_squared(cdl_vec3 a) { return cdl_vec3_dot(a, a); }
/* hypot-style length: no overflow or underflow for components near the double limits.
 * Where the sum of squares is within [2^-1000, 2^1000] it is the plain
 * square root (the largest square is then at least 2^-1002, so squares
 * lost to underflow are below 2^-74 of the sum, under an ulp; nothing
 * overflows); only beyond, or for NaN and infinities, is the vector scaled
 * by its largest component first (fmax is a library call without
 * -ffast-math, and this is on every ray's path). */
static inline double cdl_vec3_length(cdl_vec3 a)
{
    double s = a.x * a.x + a.y * a.y + a.z * a.z;
    if (s >= 0x1p-1000 && s <= 0x1p1000) return sqrt(s);
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0.0 || !isfinite(m)) return m;
    double x = a.x / m, y = a.y / m, z = a.z / m;
    return m * sqrt(x * x + y * y + z * z);
}
/* Unit vector along a; the zero vector stays zero. A length below the
 * smallest normal double (subnormal components) has a reciprocal beyond the
 * double range: such a vector is divided by its largest component first. */
static inline cdl_vec3 cdl_vec3_normalize(cdl_vec3 a)
{
    double len = cdl_vec3_length(a);
    if (!(len > 0.0)) return a;
    if (len < DBL_MIN) {
        double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
        a = cdl_vec3_make(a.x / m, a.y / m, a.z / m);
        len = cdl_vec3_length(a);
    }
    return cdl_vec3_scale(a, 1.0 / len);
}
static inline double cdl_vec3_distance(cdl_vec3 a, cdl_vec3 b) { return cdl_vec3_length(cdl_vec3_sub(a, b)); }
/* Component k (0: x, 1: y, 2: z). */
static inline double cdl_vec3_axis(cdl_vec3 a, int k) { return k == 0 ? a.x : (k == 1 ? a.y : a.z); }
static inline int cdl_vec3_is_finite(cdl_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

#endif
