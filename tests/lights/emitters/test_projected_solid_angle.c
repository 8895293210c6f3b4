/* Projected solid angles against configuration factors from the literature,
 * bracketing polygons and a direct quadrature.
 *
 * References (configuration factor F from a plane element; Omega_p = pi F):
 *  - parallel rectangle, element under a corner at height c, sides a, b
 *    (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors",
 *    3rd ed., factor B-2; also Siegel and Howell):
 *      F = 1/(2pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))],
 *      X = a/c, Y = b/c;
 *  - perpendicular rectangle, element at distance b from the rectangle's
 *    plane on the normal through a corner of its edge on the element's plane,
 *    rectangle width a along that edge and height c (Howell B-3):
 *      F = 1/(2pi) [atan(1/Y) - Y/sqrt(X^2+Y^2) atan(1/sqrt(X^2+Y^2))],  X = c/a, Y = b/a;
 *  - disk of radius r on the axis at height h: F = r^2/(r^2 + h^2);
 *  - parallel disk, element offset l from the axis at height h (Howell B-13):
 *      F = (1/2)(1 - (Z - 2R^2)/sqrt(Z^2 - 4R^2)),  H = h/l, R = r/l, Z = 1 + H^2 + R^2;
 *  - sphere fully above the element's plane: F = (R/d)^2 cos(beta).
 * (The perpendicular formula's variable assignment was confirmed by a
 * brute-force quadrature before it was written here.)
 */
#include <float.h>
#include <math.h>

#include "check.h"
#include "lights/emitter_checks.h"
#include "lights/emitters/projected_solid_angle.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "base/rng.h"

/* Six uniform numbers for random case t. */
static void case_uniforms(cdl_rng_key key, int t, double u[2], double w[2], double x[2])
{
    cdl_rng_uniform2(key, 3 * (uint64_t)t, u);
    cdl_rng_uniform2(key, 3 * (uint64_t)t + 1, w);
    cdl_rng_uniform2(key, 3 * (uint64_t)t + 2, x);
}


/* Rect origin + s u + t v relative to the receiver, counter-clockwise seen from the side u x v faces. */
static double rect_psa(cdl_vec3 o, cdl_vec3 u, cdl_vec3 v, cdl_vec3 n)
{
    cdl_vec3 r[4] = {o, cdl_vec3_add(o, u), cdl_vec3_add(cdl_vec3_add(o, u), v), cdl_vec3_add(o, v)};
    return cdl_projected_solid_angle_polygon(r, 4, n);
}

static void test_parallel_rectangles(void)
{
    cdl_vec3 up = {0, 0, 1};
    /* Emitting side faces down (-z): u = +y, v = +x gives u x v = -z. The
     * heights span 1e-4 m to 1e5 m; the formula and the contour integral
     * are both evaluated in double precision from well-conditioned terms,
     * so agreement to 1e-12 is what "no loss of precision" means here. */
    double cs[] = {1e-4, 1e-3, 0.37, 1.0, 8.0, 1e3, 1e4, 1e5};
    for (size_t k = 0; k < sizeof cs / sizeof cs[0]; ++k) {
        double a = 1.3, b = 0.7, c = cs[k];
        double omega = rect_psa(cdl_vec3_make(0, 0, c), cdl_vec3_make(0, b, 0), cdl_vec3_make(a, 0, 0), up);
        CHECK_REL(omega, CDL_PI * howell_parallel_corner(a, b, c), 1e-12);
    }
    /* A receiver under the centre of a 1 m^2 square: four corner rectangles. */
    double hs[] = {1e-3, 0.5, 2.0, 1e4};
    for (size_t k = 0; k < sizeof hs / sizeof hs[0]; ++k) {
        double h = hs[k];
        double omega = rect_psa(cdl_vec3_make(-0.5, -0.5, h), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0), up);
        CHECK_REL(omega, 4.0 * CDL_PI * howell_parallel_corner(0.5, 0.5, h), 1e-12);
    }
    /* Near field: at 1e-3 m under the centre of a 1 m^2 square nearly the
     * whole hemisphere is bright: Omega_p = pi (1 - O(h)). */
    double near = rect_psa(cdl_vec3_make(-0.5, -0.5, 1e-3), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0), up);
    CHECK(near < CDL_PI && near > CDL_PI * (1.0 - 4e-3));
    /* Far field: at 1e4 m the square is a point source of I = L A:
     * Omega_p -> A / d^2; the relative difference is O((size/d)^2) = 1e-8. */
    double far = rect_psa(cdl_vec3_make(-0.5, -0.5, 1e4), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0), up);
    CHECK_REL(far, 1.0 / (1e4 * 1e4), 1e-7);
    /* Clockwise seen from the receiver: the negated value. */
    double cw = rect_psa(cdl_vec3_make(0, 0, 1), cdl_vec3_make(1.3, 0, 0), cdl_vec3_make(0, 0.7, 0), up);
    CHECK_REL(cw, -CDL_PI * howell_parallel_corner(1.3, 0.7, 1.0), 1e-12);
}

static void test_perpendicular_rectangles(void)
{
    cdl_vec3 up = {0, 0, 1};
    /* Rect in the plane y = b, x in [0, a], z in [0, c], facing -y. */
    double bs[] = {1e-3, 0.8, 3.0, 1e3};
    for (size_t k = 0; k < sizeof bs / sizeof bs[0]; ++k) {
        double a = 1.1, b = bs[k], c = 0.6;
        double omega = rect_psa(cdl_vec3_make(0, b, 0), cdl_vec3_make(a, 0, 0), cdl_vec3_make(0, 0, c), up);
        CHECK_REL(omega, CDL_PI * howell_perpendicular_corner(a, b, c), 1e-11);
        /* The same wall extended below the receiver's plane: Sutherland-
         * Hodgman clips the lower part away, the answer must not change. */
        double clipped = rect_psa(cdl_vec3_make(0, b, -2.5), cdl_vec3_make(a, 0, 0), cdl_vec3_make(0, 0, c + 2.5), up);
        CHECK_REL(clipped, CDL_PI * howell_perpendicular_corner(a, b, c), 1e-11);
    }
    /* Entirely below the plane: nothing. */
    CHECK_ABS(rect_psa(cdl_vec3_make(0, 1, -1), cdl_vec3_make(1, 0, 0), cdl_vec3_make(0, 0, 0.5), up), 0.0, 0.0);
}

/* Clipped Lambert sum in long double, written independently of the library
 * (plain Sutherland-Hodgman into an array, then the edge sum; no cubature). */
#if LDBL_MANT_DIG < 64
#error "this test's reference needs an extended long double (x86-64 has 64 significand bits)"
#endif
typedef struct { long double x, y, z; } lvec;
static long double ldot(lvec a, lvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static lvec lcross(lvec a, lvec b) { lvec c = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return c; }

static double polygon_reference(const cdl_vec3 *v, int count, cdl_vec3 nd)
{
    lvec in[8], out[16], n = {nd.x, nd.y, nd.z};
    for (int i = 0; i < count; ++i) in[i] = (lvec){v[i].x, v[i].y, v[i].z};
    int m = 0;
    for (int i = 0; i < count; ++i) {
        lvec a = in[i], b = in[(i + 1) % count];
        long double da = ldot(n, a), db = ldot(n, b);
        if ((da >= 0) != (db >= 0)) {
            long double t = da / (da - db);
            out[m++] = (lvec){a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
        }
        if (db >= 0) out[m++] = b;
    }
    long double sum = 0;
    for (int i = 0; i < m; ++i) {
        /* a x b as a x (b - a): two long, nearly parallel vectors would
         * otherwise cost the cross product most of its digits. */
        lvec a = out[i], b = out[(i + 1) % m], e = {b.x - a.x, b.y - a.y, b.z - a.z}, c = lcross(a, e);
        long double len = sqrtl(ldot(c, c));
        if (len > 0) sum += atan2l(len, ldot(a, b)) * ldot(n, c) / len;
    }
    return (double)(-0.5L * sum);
}

static void test_polygon_against_extended_precision(void)
{
    /* Random triangles facing the receiver at distances of 1 to 1e4 times
     * their size (across the switch from Lambert's sum to cubature at 8),
     * receiver planes at random tilts, so that many views are grazing and
     * many triangles are cut. The long double reference keeps ~19 digits
     * through the sum's cancellation (~1e4 here), so it is good to ~1e-15;
     * the library must agree to 1e-12 of the triangle's unclipped scale
     * A / d^2 (a relative test would be meaningless where clipping leaves
     * a sliver). */
    cdl_rng_key key = {77, 3};
    double worst = 0.0;
    for (int t = 0; t < 2000; ++t) {
        double u[2], w[2], x[2];
        case_uniforms(key, t, u, w, x);
        double dist = pow(10.0, 4.0 * u[0]);
        double th = acos(2 * u[1] - 1), ph = CDL_TWO_PI * w[0];
        cdl_vec3 c = cdl_vec3_scale(cdl_vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th)), dist);
        cdl_vec3 v[3] = {cdl_vec3_add(c, cdl_vec3_make(0.3, -0.2, 0.1 * w[1])),
                         cdl_vec3_add(c, cdl_vec3_make(-0.4 * x[0], 0.5, -0.3)),
                         cdl_vec3_add(c, cdl_vec3_make(0.1, 0.2 * x[1], 0.6))};
        /* Counter-clockwise from p: swap if needed. */
        if (cdl_vec3_dot(cdl_vec3_cross(cdl_vec3_sub(v[1], v[0]), cdl_vec3_sub(v[2], v[0])), v[0]) > 0) {
            cdl_vec3 tmp = v[1];
            v[1] = v[2];
            v[2] = tmp;
        }
        /* A receiver normal near-perpendicular to the view half the time (grazing). */
        cdl_vec3 dir = cdl_vec3_scale(c, 1.0 / dist);
        cdl_frame f = cdl_frame_from_normal(dir);
        double tilt = (t % 2) ? 0.5 * CDL_PI - 1e-3 * x[0] : CDL_PI * x[0];
        cdl_vec3 n = cdl_frame_to_world(&f, cdl_vec3_make(sin(tilt) * cos(5 * w[1]), sin(tilt) * sin(5 * w[1]), cos(tilt)));
        double area = 0.5 * cdl_vec3_length(cdl_vec3_cross(cdl_vec3_sub(v[1], v[0]), cdl_vec3_sub(v[2], v[0])));
        double scale = area / (dist * dist);
        double got = cdl_projected_solid_angle_polygon(v, 3, n), ref = polygon_reference(v, 3, n);
        double err = fabs(got - ref) / scale;
        if (err > worst) worst = err;
        CHECK_MSG(err <= 1e-12, "case %d (distance %g): %.17g vs %.17g", t, dist, got, ref);
    }
    fprintf(stderr, "polygon vs long double: worst error %.3g of A/d^2\n", worst);
}

static void test_nonconvex_polygon(void)
{
    /* An L-shaped hexagon above the receiver equals the sum of its two
     * rectangles; tilted so that the receiver's plane cuts it. */
    cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.6, 0.2, 0.3));
    cdl_vec3 o = {-0.4, -0.3, 0.5};
    /* Vertices in the plane z = 0.5, counter-clockwise seen from below (emitting down). */
    cdl_vec3 L[6] = {{0, 0, 0}, {0, 2, 0}, {1, 2, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}};
    for (int i = 0; i < 6; ++i) L[i] = cdl_vec3_add(L[i], o);
    double whole = cdl_projected_solid_angle_polygon(L, 6, n);
    double part1 = rect_psa(o, cdl_vec3_make(0, 2, 0), cdl_vec3_make(1, 0, 0), n);
    double part2 = rect_psa(cdl_vec3_add(o, cdl_vec3_make(1, 0, 0)), cdl_vec3_make(0, 1, 0), cdl_vec3_make(1, 0, 0), n);
    CHECK(whole > 0.0);
    CHECK_REL(whole, part1 + part2, 1e-13);
}

/* Regular N-gon inscribed in (scale 1) or circumscribing (scale 1/cos(pi/N)) the disk. */
static double ngon_psa(cdl_vec3 c, cdl_vec3 m, double R, cdl_vec3 n, int N, double scale)
{
    cdl_vec3 v[4096];
    cdl_frame f = cdl_frame_from_normal(m);
    for (int k = 0; k < N; ++k) {
        double phi = CDL_TWO_PI * k / N;
        v[k] = cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(f.s, R * scale * cos(phi)),
                                            cdl_vec3_scale(f.t, R * scale * sin(phi))));
    }
    return cdl_projected_solid_angle_polygon(v, (size_t)N, n);
}

static void test_disk(void)
{
    cdl_vec3 up = {0, 0, 1}, down = {0, 0, -1};
    /* On the axis: F = r^2 / (r^2 + h^2), full precision from 1e-4 m to 1e5 m. */
    double hs[] = {1e-4, 1e-3, 0.1, 1.0, 10.0, 1e3, 1e5};
    for (size_t k = 0; k < sizeof hs / sizeof hs[0]; ++k) {
        double r = 0.5, h = hs[k];
        CHECK_REL(cdl_projected_solid_angle_disk(cdl_vec3_make(0, 0, h), down, r, up), CDL_PI * r * r / (r * r + h * h),
                  1e-13);
    }
    /* Parallel, offset from the axis (Howell B-13), including offsets inside and outside the rim. */
    double ls[] = {0.1, 0.45, 0.9, 3.0, 50.0};
    for (size_t k = 0; k < sizeof ls / sizeof ls[0]; ++k) {
        double r = 0.5, h = 0.7, l = ls[k];
        long double H = (long double)h / l, R = (long double)r / l, Z = 1 + H * H + R * R;
        double F = (double)(0.5L * (1.0L - (Z - 2 * R * R) / sqrtl(Z * Z - 4 * R * R)));
        CHECK_REL(cdl_projected_solid_angle_disk(cdl_vec3_make(l, 0, h), down, r, up), CDL_PI * F, 1e-11);
    }
    /* Behind the disk: nothing (one-sided). */
    CHECK_ABS(cdl_projected_solid_angle_disk(cdl_vec3_make(0, 0, 1), up, 0.5, up), 0.0, 0.0);

    /* Arbitrary placements, tilts, and receiver planes cutting the disk:
     * the disk lies between its inscribed and circumscribed 4096-gons and
     * the integrand is >= 0, so Omega(inscribed) <= Omega(disk) <=
     * Omega(circumscribed) must hold exactly (up to rounding, 1e-12 of the
     * values), and the bracket is tight (relative width ~(pi/N)^2 ~ 6e-7
     * scaled by how fast the integrand varies across the rim). */
    cdl_rng_key key = {2024, 1};
    int cut = 0;
    for (int t = 0; t < 200; ++t) {
        double u[2], w[2], x[2];
        case_uniforms(key, t, u, w, x);
        cdl_vec3 c = cdl_vec3_make(4 * u[0] - 2, 4 * u[1] - 2, 3 * w[0] - 1);
        double z = 2 * w[1] - 1, ph = CDL_TWO_PI * x[0], s = sqrt(1 - z * z);
        cdl_vec3 m = cdl_vec3_make(s * cos(ph), s * sin(ph), z);
        if (cdl_vec3_dot(m, c) > 0) m = cdl_vec3_neg(m); /* face the receiver */
        double R = 0.2 + 1.5 * x[1];
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.3 * u[1] - 0.1, 0.5 - w[0], 1.0 - x[0]));
        double omega = cdl_projected_solid_angle_disk(c, m, R, n);
        double lo = ngon_psa(c, m, R, n, 4096, 1.0);
        double hi = ngon_psa(c, m, R, n, 4096, 1.0 / cos(CDL_PI / 4096));
        double nc = cdl_vec3_dot(n, c), k = R * sqrt(fmax(0.0, 1.0 - pow(cdl_vec3_dot(n, m), 2)));
        if (fabs(nc) < k) cut++;
        CHECK_MSG(omega >= lo - 1e-12 * fabs(lo) && omega <= hi + 1e-12 * fabs(hi),
                  "case %d: %.17g not in [%.17g, %.17g]", t, omega, lo, hi);
        CHECK_MSG(hi - lo <= 1e-4 * hi + 1e-15, "case %d: bracket [%.17g, %.17g] too wide", t, lo, hi);
    }
    CHECK_MSG(cut > 30, "only %d of 200 cases had the receiver's plane cutting the disk", cut);
}

/* Gauss-Legendre nodes and weights on [0, 1] in long double (Newton on P_N). */
static void gauss_legendre_ld(int N, long double *x, long double *w)
{
    for (int i = 0; i < N; ++i) {
        long double z = cosl(CDL_PI * (i + 0.75L) / (N + 0.5L)), dp = 1, p1 = 1, p2 = 0;
        for (int it = 0; it < 100; ++it) {
            p1 = 1;
            p2 = 0;
            for (int j = 0; j < N; ++j) {
                long double p3 = p2;
                p2 = p1;
                p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
            }
            dp = N * (z * p1 - p2) / (z * z - 1);
            long double z1 = z;
            z = z1 - p1 / dp;
            if (fabsl(z - z1) < 1e-19L) break;
        }
        x[i] = (1 - z) / 2;
        w[i] = 1 / ((1 - z * z) * dp * dp);
    }
}

/* Omega_p of a disk wholly above the receiver's plane by 64 x 64 polar
 * Gauss-Legendre cubature in long double: the integrand is smooth (no
 * clipping), so the rule is exact to ~1e-18 for these placements. */
static double disk_cubature(cdl_vec3 c, cdl_vec3 m, double R, cdl_vec3 n)
{
    long double x[64], w[64], sum = 0;
    gauss_legendre_ld(64, x, w);
    cdl_frame f = cdl_frame_from_normal(m);
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            long double rho = R * x[i], ph = 2.0L * CDL_PI * x[j], cp = cosl(ph) * rho, sp = sinl(ph) * rho;
            long double r[3] = {c.x + cp * f.s.x + sp * f.t.x, c.y + cp * f.s.y + sp * f.t.y, c.z + cp * f.s.z + sp * f.t.z};
            long double d2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
            long double nr = n.x * r[0] + n.y * r[1] + n.z * r[2], mr = -(m.x * r[0] + m.y * r[1] + m.z * r[2]);
            sum += w[i] * w[j] * nr * mr / (d2 * d2) * rho;
        }
    return (double)(sum * R * 2.0L * CDL_PI);
}

static void test_disk_far_and_grazing(void)
{
    /* Disks seen obliquely from 3 m to 1e4 m, some just above the
     * receiver's horizon (where Lambert's polygon sum would cancel): the
     * closed form must keep ~15 digits; 1e-13 leaves margin. */
    double Ds[] = {3, 10, 100, 1e3, 1e4};
    for (size_t i = 0; i < sizeof Ds / sizeof Ds[0]; ++i) {
        double D = Ds[i];
        double hs[] = {0.6, 2.0, 0.5 * D};
        for (size_t k = 0; k < 3; ++k) {
            cdl_vec3 c = {0.3, D, hs[k]}, m = {0, -1, 0}, n = {0, 0, 1};
            CHECK_REL(cdl_projected_solid_angle_disk(c, m, 0.5, n), disk_cubature(c, m, 0.5, n), 1e-13);
        }
        cdl_vec3 c = {0.7 * D, 0.2 * D, 0.05 * D + 1};
        cdl_vec3 m = cdl_vec3_normalize(cdl_vec3_make(-0.3, 0.5, -0.8));
        cdl_vec3 n = cdl_vec3_normalize(cdl_vec3_make(0.1, 0.2, 1));
        if (cdl_vec3_dot(m, c) > 0) m = cdl_vec3_neg(m);
        CHECK_REL(cdl_projected_solid_angle_disk(c, m, 0.5, n), disk_cubature(c, m, 0.5, n), 1e-13);
    }
}

/* Omega_p of a sphere by quadrature over its cone of directions: for each
 * ring at angle t from the axis, the phi integral of max(0, a + b cos phi)
 * is done exactly, t by 20000-point midpoint rule (the integrand in t has
 * at most one kink, error O(h^2) ~ 1e-9 relative). */
static double sphere_psa_quadrature(cdl_vec3 c, double R, cdl_vec3 n)
{
    double d = cdl_vec3_length(c), sigma = asin(R / d);
    cdl_vec3 w = cdl_vec3_scale(c, 1.0 / d);
    double nw = cdl_vec3_dot(n, w), nperp = sqrt(fmax(0.0, 1.0 - nw * nw));
    int N = 20000;
    double sum = 0.0;
    for (int k = 0; k < N; ++k) {
        double t = sigma * (k + 0.5) / N;
        double a = nw * cos(t), b = nperp * sin(t), ring;
        if (a >= b) ring = CDL_TWO_PI * a;
        else if (a <= -b) ring = 0.0;
        else ring = 2.0 * (a * acos(-a / b) + sqrt(b * b - a * a));
        sum += ring * sin(t);
    }
    return sum * sigma / N;
}

static void test_sphere(void)
{
    /* Fully above the plane: pi (R/d)^2 cos(beta), from grazing distance to far away. */
    double ds[] = {1.0 + 1e-9, 1.001, 1.5, 10.0, 1e5};
    double betas[] = {0.0, 0.3, 1.0};
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; ++i)
        for (size_t j = 0; j < sizeof betas / sizeof betas[0]; ++j) {
            double d = ds[i], beta = betas[j], R = 1.0;
            if (cos(beta) * d < R * 1.0000001 && beta > 0) continue; /* not fully visible */
            cdl_vec3 n = {sin(beta), 0, cos(beta)};
            CHECK_REL(cdl_projected_solid_angle_sphere(cdl_vec3_make(0, 0, d), R, n), CDL_PI * cos(beta) / (d * d),
                      1e-12);
        }
    /* Partly below the horizon: against the quadrature above (tolerance 1e-7,
     * well above its ~1e-9 error). Includes the sphere centred in the plane
     * (beta = 90 degrees). */
    double partial[][2] = {{1.2, 1.2}, {2.0, 1.3}, {3.0, CDL_PI / 2}, {1.05, 1.9}, {30.0, 1.56}};
    for (size_t i = 0; i < sizeof partial / sizeof partial[0]; ++i) {
        double d = partial[i][0], beta = partial[i][1];
        cdl_vec3 n = {sin(beta), 0, cos(beta)}, c = {0, 0, d};
        CHECK_REL(cdl_projected_solid_angle_sphere(c, 1.0, n), sphere_psa_quadrature(c, 1.0, n), 1e-7);
    }
    /* Inside or on the sphere: 0 (it is seen from the back). */
    CHECK_ABS(cdl_projected_solid_angle_sphere(cdl_vec3_make(0, 0, 0.5), 1.0, cdl_vec3_make(0, 0, 1)), 0.0, 0.0);
}

int main(void)
{
    test_parallel_rectangles();
    test_perpendicular_rectangles();
    test_nonconvex_polygon();
    test_polygon_against_extended_precision();
    test_disk();
    test_disk_far_and_grazing();
    test_sphere();
    return check_finish();
}
