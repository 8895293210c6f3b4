/* Luminance bounds of environments over spherical polygons
 * (cdl_emitter_luminance_bounds, lights/environment/environment_bounds.h): never too
 * tight (every direction inside a polygon has its luminance within the
 * bounds), tight where the answer is known (a polygon inside a uniform cap
 * gets exactly the cap's luminance), for images of several sizes (the
 * block pyramid's levels), polygons around the poles and across the
 * azimuth seam, upper-hemisphere and CIE overcast skies. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "lights/emitters/emitter.h"
#include "radiometry/constants.h"
#include "base/rng.h"

#include "lights/environment_fixture.h"

static cdl_vec3 unit(double x, double y, double z)
{
    return cdl_vec3_normalize(cdl_vec3_make(x, y, z));
}

/* Random triangles and quads (convex: a random centre and corners around
 * it within `spread` radians); every one of 400 directions inside
 * (normalised convex combinations of the corners) must lie within the
 * bounds. Returns how many polygons were checked. */
static int check_contains(const cdl_emitter *e, double spread, uint64_t stream)
{
    cdl_rng_key key = {7, stream};
    uint64_t k = 0;
    int checked = 0;
    for (int poly = 0; poly < 300; ++poly) {
        double u[2];
        cdl_rng_uniform2(key, k++, u);
        double z = 2.0 * u[0] - 1.0, r = sqrt(fmax(0.0, 1.0 - z * z)), phi = CDL_TWO_PI * u[1];
        cdl_vec3 c = cdl_vec3_make(r * cos(phi), r * sin(phi), z);
        cdl_vec3 a = fabs(c.z) < 0.9 ? cdl_vec3_make(0, 0, 1) : cdl_vec3_make(1, 0, 0);
        cdl_vec3 s = cdl_vec3_normalize(cdl_vec3_cross(a, c)), t = cdl_vec3_cross(c, s);
        int count = 3 + poly % 2;
        cdl_vec3 v[4];
        double size = spread * (0.05 + u[0] * 0.95);
        for (int i = 0; i < count; ++i) {
            double ang = CDL_TWO_PI * i / count + 0.3 * u[1];
            v[i] = cdl_vec3_normalize(
                cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(s, size * cos(ang)), cdl_vec3_scale(t, size * sin(ang)))));
        }
        cdl_luminance lo, hi;
        CHECK(cdl_emitter_luminance_bounds(e, v, count, &lo, &hi));
        CHECK(lo.cd_m2 <= hi.cd_m2);
        for (int q = 0; q < 400; ++q) {
            double b[2];
            cdl_rng_uniform2(key, k++, b);
            /* a point of the fan triangle (v0, v_i, v_i+1) */
            int tri = 1 + q % (count - 2);
            double s1 = sqrt(b[0]);
            cdl_vec3 w = cdl_vec3_normalize(cdl_vec3_add(
                cdl_vec3_scale(v[0], 1.0 - s1),
                cdl_vec3_add(cdl_vec3_scale(v[tri], s1 * (1.0 - b[1])), cdl_vec3_scale(v[tri + 1], s1 * b[1]))));
            double pdf;
            double L = cdl_emitter_radiance(e, cdl_vec3_make(0, 0, 0), w, w, &pdf).cd_m2;
            CHECK_MSG(L >= lo.cd_m2 && L <= hi.cd_m2, "polygon %d: L = %g outside [%g, %g]", poly, L, lo.cd_m2,
                      hi.cd_m2);
        }
        checked++;
    }
    return checked;
}

int main(void)
{
    /* Noise images of three sizes: 1 pixel to 2 blocks of the pyramid's
     * top level per polygon, and 90-degree polygons over many blocks. */
    static const int sizes[][2] = {{16, 8}, {96, 48}, {1024, 512}};
    for (int k = 0; k < 3; ++k) {
        int W = sizes[k][0], H = sizes[k][1];
        float *img = malloc((size_t)W * H * sizeof *img);
        cdl_rng_key key = {3, (uint64_t)k};
        for (int i = 0; i < W * H; ++i) {
            double u[2];
            cdl_rng_uniform2(key, (uint64_t)i, u);
            img[i] = (float)(1000.0 * u[0] * u[0] + (u[1] < 0.001 ? 1e6 : 0.0));
        }
        for (int upper = 0; upper <= 1; ++upper) {
            cdl_emitter *e = environment_fixture_image(W, H, img, upper);
            if (!e) break;
            CHECK(check_contains(e, 0.05, (uint64_t)(10 * k + upper)) == 300);
            CHECK(check_contains(e, 0.8, (uint64_t)(10 * k + upper + 5)) == 300);
            cdl_emitter_release(e);
        }
        free(img);
    }

    /* Tight: a cap of 2000 (rows j < 12 of 48: 45 degrees) and 0 below;
     * a quad around the zenith out to 30 degrees and one at 20-40 degrees
     * across the seam at azimuth 180 (columns 0 and 95) see only the cap:
     * bounds [3000, 3000] with the scale 1.5. A quad reaching 60 degrees
     * sees both: [0, 3000]. */
    {
        enum { W = 96, H = 48 };
        static float img[W * H];
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) img[j * W + i] = j < 12 ? 2000.0f : 0.0f;
        cdl_emitter *e = environment_fixture_image(W, H, img, 0);
        if (e) {
            double t = tan(30.0 * CDL_PI / 180.0);
            cdl_vec3 zen[4] = {unit(t, 0, 1), unit(0, t, 1), unit(-t, 0, 1), unit(0, -t, 1)};
            cdl_luminance lo, hi;
            CHECK(cdl_emitter_luminance_bounds(e, zen, 4, &lo, &hi));
            CHECK_MSG(lo.cd_m2 == 3000.0 && hi.cd_m2 == 3000.0, "zenith quad: [%g, %g]", lo.cd_m2, hi.cd_m2);
            double a = sin(20.0 * CDL_PI / 180.0), b = sin(40.0 * CDL_PI / 180.0);
            cdl_vec3 seam[4] = {unit(-a, -0.05, cos(asin(a))), unit(-a, 0.05, cos(asin(a))),
                                unit(-b, 0.1, cos(asin(b))), unit(-b, -0.1, cos(asin(b)))};
            CHECK(cdl_emitter_luminance_bounds(e, seam, 4, &lo, &hi));
            CHECK_MSG(lo.cd_m2 == 3000.0 && hi.cd_m2 == 3000.0, "seam quad: [%g, %g]", lo.cd_m2, hi.cd_m2);
            double w = tan(60.0 * CDL_PI / 180.0);
            cdl_vec3 wide[4] = {unit(w, 0, 1), unit(0, w, 1), unit(-w, 0, 1), unit(0, -w, 1)};
            CHECK(cdl_emitter_luminance_bounds(e, wide, 4, &lo, &hi));
            CHECK_MSG(lo.cd_m2 == 0.0 && hi.cd_m2 == 3000.0, "wide quad: [%g, %g]", lo.cd_m2, hi.cd_m2);
            CHECK(check_contains(e, 0.6, 99) == 300);
            cdl_emitter_release(e);
        }
    }

    /* Sky models: uniform (one value; 0 included below an upper sky's
     * horizon) and the CIE overcast L_z (1 + 2 cos theta) / 3 from the
     * polygon's range of cos theta: a quad from 30 to 60 degrees about one
     * azimuth (+-d). Its top edge, the great-circle arc between two points
     * at 30 degrees, bulges towards the zenith: at its middle,
     * normalise(a + b), cos theta = cos 30 / sqrt(sin^2 30 cos^2 d +
     * cos^2 30); its bottom edge bulges
     * the same way, so the least cos theta is at the bottom corners. */
    {
        cdl_environment_params p = CDL_ENVIRONMENT_PARAMS_DEFAULT;
        p.luminance = cdl_nits(600.0);
        p.sky = CDL_SKY_CIE_OVERCAST;
        cdl_emitter *e = NULL;
        cdl_error err;
        CHECK_OK(cdl_emitter_create_environment(&p, &e, &err), &err);
        if (e) {
            double s30 = 0.5, c30 = sqrt(3.0) / 2.0, s60 = c30, c60 = 0.5, d = 0.05;
            cdl_vec3 q[4] = {cdl_vec3_make(s30 * cos(-d), s30 * sin(-d), c30), cdl_vec3_make(s30 * cos(d), s30 * sin(d), c30),
                             cdl_vec3_make(s60 * cos(d), s60 * sin(d), c60), cdl_vec3_make(s60 * cos(-d), s60 * sin(-d), c60)};
            cdl_luminance lo, hi;
            CHECK(cdl_emitter_luminance_bounds(e, q, 4, &lo, &hi));
            /* the margin of 1e-9 in cos theta: 2 L_z / 3 x 1e-9 */
            CHECK_MSG(fabs(lo.cd_m2 - 600.0 * (1.0 + 2.0 * c60) / 3.0) <= 1e-6 &&
                          fabs(hi.cd_m2 - 600.0 * (1.0 + 2.0 * c30 / hypot(s30 * cos(d), c30)) / 3.0) <= 1e-6,
                      "overcast: [%.12g, %.12g]", lo.cd_m2, hi.cd_m2);
            CHECK(check_contains(e, 0.7, 123) == 300);
            cdl_emitter_release(e);
        }
        cdl_environment_params u = CDL_ENVIRONMENT_PARAMS_DEFAULT;
        u.luminance = cdl_nits(800.0);
        u.upper_hemisphere_only = 1;
        CHECK_OK(cdl_emitter_create_environment(&u, &e, &err), &err);
        if (e) {
            cdl_vec3 below[3] = {unit(1, 0, 0.2), unit(0, 1, -0.2), unit(-1, -1, 0.3)};
            cdl_vec3 above[3] = {unit(1, 0, 0.5), unit(0, 1, 0.6), unit(-1, -1, 0.7)};
            cdl_luminance lo, hi;
            CHECK(cdl_emitter_luminance_bounds(e, below, 3, &lo, &hi) && lo.cd_m2 == 0.0 && hi.cd_m2 == 800.0);
            CHECK(cdl_emitter_luminance_bounds(e, above, 3, &lo, &hi) && lo.cd_m2 == 800.0 && hi.cd_m2 == 800.0);
            cdl_emitter_release(e);
        }
    }
    /* Not an environment: refused. */
    {
        cdl_point_params pp = {{0, 0, 1}, {100.0}};
        cdl_emitter *e = NULL;
        cdl_error err;
        CHECK_OK(cdl_emitter_create_point(&pp, &e, &err), &err);
        cdl_vec3 v[3] = {unit(1, 0, 1), unit(0, 1, 1), unit(-1, -1, 1)};
        cdl_luminance lo, hi;
        if (e) CHECK(!cdl_emitter_luminance_bounds(e, v, 3, &lo, &hi));
        cdl_emitter_release(e);
    }
    return check_finish();
}
