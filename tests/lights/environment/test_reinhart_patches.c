/* Tregenza and Reinhart sky patches (lights/environment/reinhart_patches.h):
 *  - the counts: 145, 577 and 2305 sky patches for MF 1, 2, 4 (144 MF^2 + 1),
 *    one more with the ground; Tregenza's rows of 30, 30, 24, 24, 18, 12, 6
 *    and the cap, and the row height 90 / (7 MF + 0.5) degrees;
 *  - the patches tile the sky: their solid angles sum to 2 pi, and each
 *    from its bounds in closed form agrees with a midpoint quadrature of
 *    cos(altitude) over them; a direction inside a patch's bounds maps back
 *    to that patch, north to the first patch of the horizon row, a
 *    direction a little east of north to the same and one past its edge to
 *    the next (eastwards);
 *  - the closed-form projected solid angles: all patches (ground
 *    included) sum to pi for any normal (the whole hemisphere in front of
 *    it); the sky's alone to pi for up; single patches against a midpoint
 *    quadrature of max(0, n.w) over them for tilted normals;
 *  - polygons over the patches (cdl_reinhart_add_polygon): the five faces
 *    of the cube over a receiving plane (the top and four half sides, as
 *    the exact route cuts the visible sky) tile its hemisphere, so what they
 *    add to each patch is the patch's own projected solid angle; a small
 *    quadrilateral inside one patch adds there its projected solid angle by
 *    Lambert's formula, and nothing elsewhere; one across the horizon
 *    splits between the ground and the sky as the horizon cuts it (Lambert's
 *    formula of each part).
 */
#include <math.h>

#include "check.h"
#include "lights/emitters/projected_solid_angle.h"
#include "lights/environment/reinhart_patches.h"
#include "radiometry/constants.h"

static void test_counts(void)
{
    static const int mf[3] = {1, 2, 4}, sky[3] = {145, 577, 2305};
    for (int i = 0; i < 3; ++i) {
        cdl_reinhart_patches p;
        cdl_error err;
        CHECK_OK(cdl_reinhart_init(&p, mf[i], cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 1, 0), &err), &err);
        CHECK(p.count == sky[i] + 1);
        CHECK(p.rows == 7 * mf[i] + 1 && p.row_count[p.rows - 1] == 1);
        CHECK_REL(p.alpha * 180.0 / CDL_PI, 90.0 / (7 * mf[i] + 0.5), 1e-14);
        if (mf[i] == 1) {
            static const int rows[8] = {30, 30, 24, 24, 18, 12, 6, 1};
            for (int r = 0; r < 8; ++r) CHECK(p.row_count[r] == rows[r]);
        }
    }
    cdl_reinhart_patches p;
    cdl_error err;
    CHECK(cdl_reinhart_init(&p, 0, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 1, 0), &err) == CDL_ERR_INPUT);
    CHECK(cdl_reinhart_init(&p, 2, cdl_vec3_make(0, 0, 1), cdl_vec3_make(0, 0, 3), &err) == CDL_ERR_INPUT);
}

/* int over patch k of f(w) dw by the midpoint rule on an m x m grid in
 * (sin altitude, azimuth), where dw = d(sin alt) d(az) exactly. */
static double patch_quadrature(const cdl_reinhart_patches *p, int k, cdl_vec3 n, int m)
{
    double a0, a1, z0, z1, sum = 0.0;
    cdl_reinhart_patch_bounds(p, k, &a0, &a1, &z0, &z1);
    double s0 = sin(a0), s1 = sin(a1);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            double s = s0 + (s1 - s0) * (i + 0.5) / m, az = z0 + (z1 - z0) * (j + 0.5) / m;
            cdl_vec3 w = cdl_reinhart_direction(p, asin(s), az);
            double c = n.x * w.x + n.y * w.y + n.z * w.z;
            sum += c > 0.0 ? c : 0.0;
        }
    return sum * (s1 - s0) * (z1 - z0) / (m * m);
}

static void test_tiling(void)
{
    /* up and north not the world's, to exercise the frame */
    cdl_vec3 up = cdl_vec3_normalize(cdl_vec3_make(0.1, -0.2, 1.0)), north = cdl_vec3_make(1, 1, 0);
    cdl_error err;
    for (int mf = 1; mf <= 4; mf *= 2) {
        cdl_reinhart_patches p;
        CHECK_OK(cdl_reinhart_init(&p, mf, up, north, &err), &err);
        double omega = 0.0;
        int back = 1;
        for (int k = 1; k < p.count; ++k) {
            omega += cdl_reinhart_solid_angle(&p, k);
            double a0, a1, z0, z1;
            cdl_reinhart_patch_bounds(&p, k, &a0, &a1, &z0, &z1);
            for (int i = 0; i < 3; ++i) {
                double alt = a0 + (a1 - a0) * (0.1 + 0.4 * i), az = z0 + (z1 - z0) * (0.9 - 0.4 * i);
                back &= cdl_reinhart_patch_of(&p, cdl_reinhart_direction(&p, alt, az)) == k;
            }
        }
        /* the sum of closed forms: rounding only */
        CHECK_REL(omega, CDL_TWO_PI, 1e-13);
        CHECK_MSG(back, "MF %d: directions inside each patch map back to it", mf);
        CHECK(cdl_reinhart_patch_of(&p, cdl_vec3_neg(up)) == CDL_REINHART_GROUND);
        CHECK(cdl_reinhart_patch_of(&p, up) == p.count - 1);
        /* north on the horizon row: patch 1; half its width east and a bit less: 1; a bit more: 2 */
        double w = CDL_TWO_PI / p.row_count[0];
        CHECK(cdl_reinhart_patch_at(&p, 0.01, 0.0) == 1);
        CHECK(cdl_reinhart_patch_at(&p, 0.01, 0.49 * w) == 1 && cdl_reinhart_patch_at(&p, 0.01, -0.49 * w) == 1);
        CHECK(cdl_reinhart_patch_at(&p, 0.01, 0.51 * w) == 2);
        CHECK(cdl_reinhart_patch_at(&p, 0.01, -0.51 * w) == p.row_count[0]);
        /* east (-t, west's opposite) in the third row (24, 60 or 120 patches for MF 1, 2, 4):
         * azimuth 90 is the middle of its patch a quarter round, counting from 0 */
        cdl_vec3 n = p.frame.s, e = cdl_vec3_neg(p.frame.t);
        double alt = 2.5 * p.alpha;
        CHECK(cdl_reinhart_patch_of(&p, cdl_vec3_add(cdl_vec3_scale(n, cos(alt)), cdl_vec3_scale(up, sin(alt)))) ==
              p.row_first[2]);
        CHECK(cdl_reinhart_patch_of(&p, cdl_vec3_add(cdl_vec3_scale(e, cos(alt)), cdl_vec3_scale(up, sin(alt)))) ==
              p.row_first[2] + p.row_count[2] / 4);
    }
}

static void test_projected(void)
{
    cdl_vec3 up = cdl_vec3_make(0, 0, 1);
    cdl_error err;
    cdl_reinhart_patches p;
    CHECK_OK(cdl_reinhart_init(&p, 2, up, cdl_vec3_make(0, 1, 0), &err), &err);
    const cdl_vec3 normals[4] = {up, cdl_vec3_make(1, 0, 0), cdl_vec3_normalize(cdl_vec3_make(0.3, -0.5, 0.8)),
                                 cdl_vec3_normalize(cdl_vec3_make(-0.2, 0.4, -0.9))};
    for (int i = 0; i < 4; ++i) {
        double all = 0.0, sky = 0.0;
        for (int k = 0; k < p.count; ++k) {
            double q = cdl_reinhart_projected_solid_angle(&p, k, normals[i]);
            all += q;
            if (k != CDL_REINHART_GROUND) sky += q;
        }
        /* closed forms summed: rounding only */
        CHECK_REL(all, CDL_PI, 1e-12);
        if (i == 0) CHECK_REL(sky, CDL_PI, 1e-12);
        /* a few patches against the midpoint rule: 400 x 400 cells, error
         * O(h^2) of the smooth part; where the plane of n cuts a patch the
         * kink costs O(h) of a cell row: 1e-4 of the patch's own */
        for (int k = 1; k < p.count; k += 97) {
            double q = cdl_reinhart_projected_solid_angle(&p, k, normals[i]);
            double ref = patch_quadrature(&p, k, normals[i], 400);
            CHECK_MSG(fabs(q - ref) <= 1e-4 * cdl_reinhart_solid_angle(&p, k), "normal %d patch %d: %.10g vs %.10g", i,
                      k, q, ref);
        }
    }
}

/* The five faces of the unit cube over the plane of n, each added. */
static void add_cube(const cdl_reinhart_patches *p, cdl_vec3 n, double *out)
{
    cdl_frame f = cdl_frame_from_normal(n);
    const cdl_vec3 sides[4] = {f.s, f.t, cdl_vec3_neg(f.s), cdl_vec3_neg(f.t)};
    cdl_vec3 top[4] = {cdl_vec3_sub(cdl_vec3_sub(n, f.s), f.t), cdl_vec3_sub(cdl_vec3_add(n, f.s), f.t),
                       cdl_vec3_add(cdl_vec3_add(n, f.s), f.t), cdl_vec3_add(cdl_vec3_sub(n, f.s), f.t)};
    CHECK(cdl_reinhart_add_polygon(p, top, 4, n, 1.0, out));
    for (int k = 0; k < 4; ++k) {
        cdl_vec3 a = sides[k], b = sides[(k + 1) % 4];
        cdl_vec3 q[4] = {cdl_vec3_sub(a, b), cdl_vec3_add(a, b), cdl_vec3_add(cdl_vec3_add(a, b), n),
                         cdl_vec3_add(cdl_vec3_sub(a, b), n)};
        CHECK(cdl_reinhart_add_polygon(p, q, 4, n, 1.0, out));
    }
}

static void test_polygons(void)
{
    cdl_error err;
    cdl_vec3 up = cdl_vec3_normalize(cdl_vec3_make(0.05, 0.1, 1.0));
    for (int mf = 1; mf <= 4; mf *= 2) {
        cdl_reinhart_patches p;
        CHECK_OK(cdl_reinhart_init(&p, mf, up, cdl_vec3_make(0.3, 1, 0), &err), &err);
        const cdl_vec3 normals[3] = {up, cdl_vec3_normalize(cdl_vec3_make(1, 0.2, 0.1)),
                                     cdl_vec3_normalize(cdl_vec3_make(-0.4, 0.3, -0.8))};
        double out[2400];
        for (int i = 0; i < 3; ++i) {
            for (int k = 0; k < p.count; ++k) out[k] = 0.0;
            add_cube(&p, normals[i], out);
            double worst = 0.0, sum = 0.0;
            for (int k = 0; k < p.count; ++k) {
                double want = cdl_reinhart_projected_solid_angle(&p, k, normals[i]);
                sum += out[k];
                if (fabs(out[k] - want) > worst) worst = fabs(out[k] - want);
            }
            /* two closed forms of the same areas: rounding, a few ulps of pi */
            CHECK_MSG(worst < 1e-12, "MF %d normal %d: worst patch differs by %.3g sr", mf, i, worst);
            CHECK_REL(sum, CDL_PI, 1e-12);
        }
        /* a small quadrilateral inside one patch of the third row */
        double a0 = 2.2 * p.alpha, a1 = 2.7 * p.alpha, w = CDL_TWO_PI / p.row_count[2], z0 = 3.1 * w, z1 = 3.3 * w;
        cdl_vec3 q[4] = {cdl_reinhart_direction(&p, a0, z0), cdl_vec3_scale(cdl_reinhart_direction(&p, a0, z1), 2.0),
                         cdl_reinhart_direction(&p, a1, z1), cdl_reinhart_direction(&p, a1, z0)};
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.2, -0.9, 0.3));
        for (int k = 0; k < p.count; ++k) out[k] = 0.0;
        CHECK(cdl_reinhart_add_polygon(&p, q, 4, n, 2.0, out));
        int home = p.row_first[2] + 3;
        double lambert = cdl_projected_solid_angle_polygon(q, 4, n), elsewhere = 0.0;
        for (int k = 0; k < p.count; ++k)
            if (k != home) elsewhere += out[k];
        /* the same polygon by two closed forms: rounding */
        CHECK_REL(out[home], 2.0 * lambert, 1e-11);
        CHECK(elsewhere == 0.0);
        /* across the horizon: the ground holds the part below it */
        cdl_vec3 x[4] = {cdl_reinhart_direction(&p, -0.2, 1.0), cdl_reinhart_direction(&p, -0.2, 1.2),
                         cdl_reinhart_direction(&p, 0.3, 1.2), cdl_reinhart_direction(&p, 0.3, 1.0)};
        cdl_vec3 h[2] = {cdl_reinhart_direction(&p, 0.0, 1.0), cdl_reinhart_direction(&p, 0.0, 1.2)};
        /* the horizon between two directions is a great circle: the parts
         * are the quadrilaterals cut by it */
        cdl_vec3 below[4] = {x[0], x[1], h[1], h[0]}, above[4] = {h[0], h[1], x[2], x[3]};
        /* a receiver facing it (the polygon within its hemisphere) */
        n = cdl_vec3_normalize(cdl_vec3_add(cdl_vec3_add(x[0], x[2]), cdl_vec3_make(0.1, 0.2, 0.3)));
        for (int k = 0; k < p.count; ++k) out[k] = 0.0;
        CHECK(cdl_reinhart_add_polygon(&p, x, 4, n, 1.0, out));
        double sky = 0.0;
        for (int k = 1; k < p.count; ++k) sky += out[k];
        CHECK_REL(out[CDL_REINHART_GROUND], cdl_projected_solid_angle_polygon(below, 4, n), 1e-11);
        CHECK_REL(sky, cdl_projected_solid_angle_polygon(above, 4, n), 1e-11);
    }
}

int main(void)
{
    test_polygons();
    test_counts();
    test_tiling();
    test_projected();
    return check_finish();
}
