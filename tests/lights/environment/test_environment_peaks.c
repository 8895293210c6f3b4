/* Bright pixels of an image environment over a spherical polygon, exactly
 * (lights/environment/environment_peaks.h). The pixels' parts inside a polygon
 * partition it, so with every pixel above the cut the sum of their
 * projected solid angles is the polygon's own, by Lambert's formula
 * (lights/emitters/projected_solid_angle.h, which knows nothing of pixels): random
 * triangles and quads about random normals, around the pole and across the
 * azimuth seam, on images of three sizes, whole-sphere and upper-hemisphere.
 * A pixel wholly inside a polygon gets the closed form of its whole cell
 * (cdl_env_cell_projected_solid_angle). Only pixels above the cut count, at
 * most max_pixels of them, and the bound on the rest is the rest's. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "lights/emitters/emitter.h"
#include "lights/environment/environment_peaks.h"
#include "lights/environment/environment_pixels.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "base/rng.h"

#include "lights/environment_fixture.h"

static cdl_vec3 random_direction(cdl_rng_key key, uint64_t index)
{
    double u[2];
    cdl_rng_uniform2(key, index, u);
    double z = 2.0 * u[0] - 1.0, r = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * u[1];
    return cdl_vec3_make(r * cos(phi), r * sin(phi), z);
}

/* A convex polygon of `count` corners `size` radians (about) around c. */
static void polygon_about(cdl_vec3 c, double size, double turn, int count, cdl_vec3 *v)
{
    cdl_vec3 a = fabs(c.z) < 0.9 ? cdl_vec3_make(0, 0, 1) : cdl_vec3_make(1, 0, 0);
    cdl_vec3 s = cdl_vec3_normalize(cdl_vec3_cross(a, c)), t = cdl_vec3_cross(c, s);
    double r = tan(size);
    for (int i = 0; i < count; ++i) {
        double ang = CDL_TWO_PI * i / count + turn;
        v[i] = cdl_vec3_normalize(
            cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(s, r * cos(ang)), cdl_vec3_scale(t, r * sin(ang)))));
    }
}

/* Every pixel bright (the image all > cut): sum Q_b = Omega_p(polygon) and
 * sum L_b Q_b = L Omega_p, for polygons within the hemisphere of n (and of
 * the sky's up when upper-only). Returns the polygons checked. */
static int check_partition(int W, int H, int upper, uint64_t stream)
{
    float *img = malloc((size_t)W * H * sizeof *img);
    for (int i = 0; i < W * H; ++i) img[i] = 10.0f;
    cdl_emitter *e = environment_fixture_image(W, H, img, upper);
    cdl_rng_key key = {11, stream};
    uint64_t k = 0;
    int checked = 0;
    double worst = 0.0;
    for (int poly = 0; poly < 200; ++poly) {
        cdl_vec3 n = random_direction(key, k++), c = random_direction(key, k++);
        if (poly % 5 == 0) c = cdl_vec3_normalize(cdl_vec3_make(0.01, 0.02, upper ? 1.0 : -1.0)); /* a pole */
        if (poly % 5 == 1) c = cdl_vec3_normalize(cdl_vec3_make(-1.0, 0.001, 0.3));              /* the seam */
        double u[2];
        cdl_rng_uniform2(key, k++, u);
        int count = 3 + poly % 2;
        cdl_vec3 v[4];
        polygon_about(c, 0.02 + 0.6 * u[0], CDL_TWO_PI * u[1], count, v);
        /* within n's hemisphere, and above the horizon of an upper-only sky */
        int fits = 1, above = 1;
        for (int i = 0; i < count; ++i) {
            fits &= cdl_vec3_dot(v[i], n) > 0.0;
            above &= !upper || v[i].z > 0.0;
        }
        if (!above) continue;
        if (!fits) n = c; /* the corners lie within `size` < pi / 2 of c */
        double omega = fabs(cdl_projected_solid_angle_polygon(v, (size_t)count, n));
        cdl_env_peaks sum = {0.0, 0.0, 0};
        double rest_hi = -1.0;
        CHECK(cdl_env_peaks_add(e, v, count, n, 1.0, W * H, &sum, &rest_hi));
        double err = fabs(sum.Q - omega) / omega;
        worst = fmax(worst, err);
        /* up to ~10^4 pixels' pieces summed against Lambert's few terms:
         * rounding (measured 3e-13 at worst); an arc lost at a pole, the
         * error this guards against, was 1e-9 to 1e-4 */
        CHECK_MSG(err <= 1e-11, "%d x %d%s polygon %d: sum Q %.15g, Omega_p %.15g", W, H, upper ? " upper" : "", poly,
                  sum.Q, omega);
        CHECK_MSG(fabs(sum.LQ - 15.0 * sum.Q) <= 1e-12 * sum.LQ, "LQ %.15g, 15 Q %.15g", sum.LQ, 15.0 * sum.Q);
        CHECK(rest_hi == 0.0); /* no pixel at or below the cut */
        checked++;
    }
    printf("  %d x %d%s: %d polygons, worst |sum Q - Omega_p| / Omega_p %.2g\n", W, H, upper ? " upper" : "", checked,
           worst);
    cdl_emitter_release(e);
    free(img);
    return checked;
}

/* Pixel (i, j) of a 48 x 24 image inside a polygon much larger than it:
 * its whole cell's closed form. */
static void check_whole_cell(void)
{
    enum { W = 48, H = 24 };
    static float img[W * H];
    for (int i = 0; i < W * H; ++i) img[i] = 1.0f;
    cdl_emitter *e = environment_fixture_image(W, H, img, 0);
    const cdl_env_pixels *px = cdl_emitter_environment_pixels(e);
    static const int cells[][2] = {{3, 2}, {30, 11}, {47, 20}, {0, 0}, {17, 23}};
    for (int c = 0; c < 5; ++c) {
        int i = cells[c][0], j = cells[c][1];
        double th = 0.5 * (px->theta_a[j] + px->theta_b[j]), ph = 0.5 * (px->phi_a[i] + px->phi_a[i + 1]);
        cdl_vec3 mid = cdl_vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
        if (j == 0) mid = cdl_vec3_make(0, 0, 1);
        if (j == H - 1) mid = cdl_vec3_make(0, 0, -1);
        cdl_vec3 poly[4], n = mid;
        polygon_about(mid, 0.5, 0.1, 4, poly);
        double Q = cdl_env_peaks_cell_polygon(e, i, j, poly, 4, n);
        double exact = cdl_env_cell_projected_solid_angle(px->theta_a[j], px->theta_b[j], px->phi_a[i],
                                                          px->phi_a[i + 1], n);
        CHECK_MSG(fabs(Q - exact) <= 1e-12 * exact, "cell (%d, %d): Q %.15g, whole cell %.15g", i, j, Q, exact);
        /* the same polygon reversed: either orientation is accepted by the sum */
        cdl_vec3 rev[4] = {poly[3], poly[2], poly[1], poly[0]};
        cdl_env_peaks a = {0, 0, 0}, b = {0, 0, 0};
        double ra, rb;
        CHECK(cdl_env_peaks_add(e, poly, 4, n, 0.5, W * H, &a, &ra));
        CHECK(cdl_env_peaks_add(e, rev, 4, n, 0.5, W * H, &b, &rb));
        CHECK(fabs(a.Q - b.Q) <= 1e-13 && a.pixels == b.pixels);
    }
    cdl_emitter_release(e);
}

/* A sun of 2 x 2 pixels in a sky of 1 .. 4: only the sun is summed; the
 * rest's bound is the rest's greatest pixel the polygon's extent touches;
 * more bright pixels than allowed refuse. */
static void check_cut(void)
{
    enum { W = 64, H = 32 };
    static float img[W * H];
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) img[j * W + i] = 1.0f + 3.0f * (float)j / H;
    for (int j = 8; j < 10; ++j)
        for (int i = 40; i < 42; ++i) img[j * W + i] = 1e6f;
    cdl_emitter *e = environment_fixture_image(W, H, img, 0);
    const cdl_env_pixels *px = cdl_emitter_environment_pixels(e);
    /* a polygon about the sun's middle, wide enough to hold it whole */
    double th = px->theta_a[9], ph = px->phi_a[41];
    cdl_vec3 c = cdl_vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th)), v[4];
    polygon_about(c, 0.3, 0.2, 4, v);
    cdl_env_peaks sum = {0, 0, 0};
    double rest_hi;
    CHECK(cdl_env_peaks_add(e, v, 4, c, 100.0, 16, &sum, &rest_hi));
    CHECK_MSG(sum.pixels == 4, "%d bright pixels", sum.pixels);
    double Q = 0.0;
    for (int j = 8; j < 10; ++j)
        for (int i = 40; i < 42; ++i)
            Q += cdl_env_cell_projected_solid_angle(px->theta_a[j], px->theta_b[j], px->phi_a[i], px->phi_a[i + 1], c);
    CHECK_MSG(fabs(sum.Q - Q) <= 1e-12 * Q && fabs(sum.LQ - 1.5e6 * Q) <= 1e-12 * sum.LQ, "Q %.15g, sun %.15g", sum.Q,
              Q);
    /* the rest: rows to about theta + 0.3 rad + a margin row, at most 1.5 x 4 */
    CHECK_MSG(rest_hi > 1.5 * (1.0 + 3.0 * 9.0 / H) && rest_hi <= 1.5 * (1.0 + 3.0 * (H - 1.0) / H), "rest %g",
              rest_hi);
    sum = (cdl_env_peaks){0, 0, 0};
    CHECK(!cdl_env_peaks_add(e, v, 4, c, 100.0, 3, &sum, &rest_hi));
    cdl_emitter_release(e);
}

int main(void)
{
    static const int sizes[][2] = {{16, 8}, {96, 48}, {512, 256}};
    for (int k = 0; k < 3; ++k) {
        CHECK(check_partition(sizes[k][0], sizes[k][1], 0, 2u * (uint64_t)k) > 100);
        CHECK(check_partition(sizes[k][0], sizes[k][1], 1, 2u * (uint64_t)k + 1u) > 50);
    }
    check_whole_cell();
    check_cut();
    return check_finish();
}
