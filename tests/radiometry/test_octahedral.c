/* The octahedral map (radiometry/octahedral.h): every direction comes back
 * from its (u, v) to the rounding of a few operations, (u, v) stays in the
 * unit square, the poles and the equator land where the construction puts
 * them, and the square's edges fold onto themselves (the points mirrored
 * about an edge's midpoint name one direction), which is what lets a table
 * on the square's grid be interpolated across the fold. */
#include <math.h>

#include "check.h"
#include "base/rng.h"
#include "radiometry/constants.h"
#include "radiometry/octahedral.h"

static double distance(cdl_vec3 a, cdl_vec3 b)
{
    return cdl_vec3_length(cdl_vec3_sub(a, b));
}

int main(void)
{
    /* 1. Round trips of directions uniform over the sphere, and of a few on
     *    the octahedron's edges and vertices; 1e-14: a handful of roundings
     *    of numbers of order 1 in the projection and the normalisation. */
    cdl_rng_key key = {7, 1};
    double worst = 0.0;
    int outside = 0;
    for (uint64_t k = 0; k < 20000; ++k) {
        double r[2];
        cdl_rng_uniform2(key, k, r);
        double z = 2.0 * r[0] - 1.0, s = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * r[1];
        cdl_vec3 d = cdl_vec3_make(s * cos(phi), s * sin(phi), z);
        double u, v;
        cdl_octahedral_encode(d, &u, &v);
        outside += !(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0);
        worst = fmax(worst, distance(cdl_octahedral_decode(u, v), d));
    }
    const cdl_vec3 special[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                                {1, 1, 0}, {-1, 1, 0}, {1, -1, 1}, {-1, -1, -1}, {0.5, 0, -1}, {0, -0.5, -1}};
    for (size_t k = 0; k < sizeof special / sizeof *special; ++k) {
        cdl_vec3 d = cdl_vec3_normalize(special[k]);
        double u, v;
        cdl_octahedral_encode(special[k], &u, &v); /* any length */
        outside += !(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0);
        worst = fmax(worst, distance(cdl_octahedral_decode(u, v), d));
    }
    CHECK_MSG(worst < 1e-14, "worst round trip %.3g", worst);
    CHECK(outside == 0);

    /* 2. Where the construction puts things: +z at the centre, -z at every
     *    corner, the equator on the diamond |x| + |y| = 1 of the square
     *    (x = 2u - 1, y = 2v - 1). */
    double u, v;
    cdl_octahedral_encode(cdl_vec3_make(0, 0, 1), &u, &v);
    CHECK_ABS(u, 0.5, 0.0);
    CHECK_ABS(v, 0.5, 0.0);
    const double corner[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (int c = 0; c < 4; ++c)
        CHECK(distance(cdl_octahedral_decode(corner[c][0], corner[c][1]), cdl_vec3_make(0, 0, -1)) < 1e-15);
    for (int k = 0; k < 16; ++k) {
        double phi = CDL_TWO_PI * k / 16.0;
        cdl_octahedral_encode(cdl_vec3_make(cos(phi), sin(phi), 0.0), &u, &v);
        CHECK_ABS(fabs(2.0 * u - 1.0) + fabs(2.0 * v - 1.0), 1.0, 1e-15);
    }

    /* 3. The fold: (t, 0) and (1 - t, 0), (0, t) and (0, 1 - t), and so on
     *    along the four edges, decode to the same direction (1e-15: the
     *    mirrored coordinates are the same numbers up to one rounding of
     *    1 - t). */
    double fold = 0.0;
    for (int k = 0; k <= 40; ++k) {
        double t = k / 40.0;
        fold = fmax(fold, distance(cdl_octahedral_decode(t, 0.0), cdl_octahedral_decode(1.0 - t, 0.0)));
        fold = fmax(fold, distance(cdl_octahedral_decode(t, 1.0), cdl_octahedral_decode(1.0 - t, 1.0)));
        fold = fmax(fold, distance(cdl_octahedral_decode(0.0, t), cdl_octahedral_decode(0.0, 1.0 - t)));
        fold = fmax(fold, distance(cdl_octahedral_decode(1.0, t), cdl_octahedral_decode(1.0, 1.0 - t)));
    }
    CHECK_MSG(fold < 1e-15, "fold mismatch %.3g", fold);

    /* 4. Continuity: directions 1e-6 rad apart map to points at most a few
     *    1e-6 apart anywhere (the map's stretch is bounded, about 2 at worst). */
    double stretch = 0.0;
    for (uint64_t k = 0; k < 5000; ++k) {
        double r[2];
        cdl_rng_uniform2(key, 100000 + k, r);
        double z = 2.0 * r[0] - 1.0, s = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * r[1];
        cdl_vec3 d = cdl_vec3_make(s * cos(phi), s * sin(phi), z);
        cdl_vec3 e = cdl_vec3_normalize(cdl_vec3_add(d, cdl_vec3_make(1e-6 * (r[1] - 0.5), 1e-6 * (r[0] - 0.5), 1e-6)));
        double u1, v1, u2, v2;
        cdl_octahedral_encode(d, &u1, &v1);
        cdl_octahedral_encode(e, &u2, &v2);
        double du = hypot(u2 - u1, v2 - v1), dd = distance(d, e);
        /* across the fold the nearest image of the point is the mirrored one */
        double dm = fmin(fmin(hypot(u2 - (1.0 - u1), v2 - v1), hypot(u2 - u1, v2 - (1.0 - v1))), du);
        if (dd > 0.0) stretch = fmax(stretch, fmin(du, dm) / dd);
    }
    CHECK_MSG(stretch < 4.0, "stretch %.3g", stretch);
    return check_finish();
}
