/* projected_solid_angle.c - exact cosine-weighted solid angles (see the header). */
#include "lights/emitters/projected_solid_angle.h"

#include <math.h>

#include "radiometry/constants.h"
#include "radiometry/frame.h"

/* Lambert's contour integral. For a closed contour C seen from the origin,
 *     Omega_p = -(1/2) n . oint (r x dr) / |r|^2
 * when C runs counter-clockwise as seen from the origin (Arvo 1995, eq. 5,
 * with his sign convention made explicit). Along a straight edge from a to b
 * the integral is theta u, theta the angle between a and b and u the unit
 * normal of the plane through the origin, a and b. This returns the edge's
 * n . theta u. a x b is formed as a x (b - a) so that two long, nearly
 * parallel position vectors do not cancel. */
static double edge_term(cdl_vec3 a, cdl_vec3 b, cdl_vec3 n)
{
    cdl_vec3 cr = cdl_vec3_cross(a, cdl_vec3_sub(b, a));
    double len = cdl_vec3_length(cr);
    if (!(len > 0.0)) return 0.0;
    /* |a x b| = |a||b| sin(theta), a.b = |a||b| cos(theta): atan2 is exact at every angle. */
    double theta = atan2(len, cdl_vec3_dot(a, b));
    return theta * cdl_vec3_dot(n, cr) / len;
}

/* Far from the receiver (distance >= FAR_RATIO x the polygon's radius) the
 * edge terms are O(size/d) while their sum is O((size/d)^2 cos): Lambert's
 * sum cancels, and for a grazing view it loses ~d/(size cos) of the 16
 * digits (1e-10 relative for 1 m^2 at 1000 m near the horizon). There the
 * integrand of Omega_p = int h (n.r) / |r|^4 dA (h = -m.r, the receiver's
 * distance to the polygon's plane) is analytic over a region FAR_RATIO times
 * larger than the polygon, so an 8 x 8 Gauss-Legendre rule on each fan
 * triangle of the clipped polygon (collapsed square, Duffy 1982) converges
 * like FAR_RATIO^-16 = 4e-15 or faster, with no cancellation: in practice
 * exact to rounding. */
#define FAR_RATIO 8.0
#define GL_N 8
/* 8-point Gauss-Legendre nodes and weights mapped to [0, 1] (Abramowitz and Stegun, table 25.4). */
static const double gl_x[GL_N] = {0.019855071751231856, 0.10166676129318664, 0.23723379504183550, 0.40828267875217511,
                                  0.59171732124782489,  0.76276620495816450, 0.89833323870681336, 0.98014492824876814};
static const double gl_w[GL_N] = {0.050614268145188130, 0.11119051722668724, 0.15685332293894364, 0.18134189168918100,
                                  0.18134189168918100,  0.15685332293894364, 0.11119051722668724, 0.050614268145188130};

/* int over triangle (r0, r1, r2) of (n.r)(-N.r) / |r|^4 dA / |N| with N = (r1-r0) x (r2-r0):
 * Omega_p of the triangle, positive when it is counter-clockwise seen from p. */
static double triangle_cubature(cdl_vec3 r0, cdl_vec3 r1, cdl_vec3 r2, cdl_vec3 n)
{
    cdl_vec3 e1 = cdl_vec3_sub(r1, r0), e2 = cdl_vec3_sub(r2, r0);
    double h = -cdl_vec3_dot(cdl_vec3_cross(e1, e2), r0); /* |N| x distance to the plane, signed */
    double sum = 0.0;
    for (int i = 0; i < GL_N; ++i) {
        double xi = gl_x[i], row = 0.0;
        for (int j = 0; j < GL_N; ++j) {
            /* (xi, eta) -> barycentric (xi (1 - eta), xi eta); dA = |N| xi dxi deta. */
            cdl_vec3 r = cdl_vec3_madd(cdl_vec3_madd(r0, xi * (1.0 - gl_x[j]), e1), xi * gl_x[j], e2);
            double d2 = cdl_vec3_length_squared(r), nr = cdl_vec3_dot(n, r);
            if (nr > 0.0) row += gl_w[j] * nr / d2 / d2;
        }
        sum += gl_w[i] * xi * row;
    }
    return h * sum;
}

/* Accumulates the clipped polygon as its vertices stream out: the edges
 * for Lambert's sum, or the fan triangles (first, prev, v) for cubature. */
typedef struct contour {
    cdl_vec3 n, first, prev;
    int count, far;
    double sum;
} contour;

static void contour_emit(contour *c, cdl_vec3 v)
{
    if (c->count == 0) c->first = v;
    else if (!c->far) c->sum += edge_term(c->prev, v, c->n);
    else if (c->count >= 2) c->sum += triangle_cubature(c->first, c->prev, v, c->n);
    c->prev = v;
    c->count++;
}

/* 1 when p (the origin) is at least FAR_RATIO x the polygon's radius about its centroid away from that centroid. */
static int polygon_is_far(const cdl_vec3 *rel, size_t count)
{
    cdl_vec3 c = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < count; ++i) c = cdl_vec3_add(c, rel[i]);
    c = cdl_vec3_scale(c, 1.0 / (double)count);
    double radius = 0.0;
    for (size_t i = 0; i < count; ++i) radius = fmax(radius, cdl_vec3_length(cdl_vec3_sub(rel[i], c)));
    return cdl_vec3_length(c) >= FAR_RATIO * radius;
}

double cdl_projected_solid_angle_polygon(const cdl_vec3 *rel, size_t count, cdl_vec3 n)
{
    if (count < 3) return 0.0;
    contour c = {n, {0, 0, 0}, {0, 0, 0}, 0, polygon_is_far(rel, count), 0.0};
    /* Sutherland-Hodgman against the half-space n.r >= 0 (Sutherland and
     * Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974), streamed:
     * each output vertex closes one edge (or one fan triangle) of the
     * clipped polygon. */
    for (size_t i = 0; i < count; ++i) {
        cdl_vec3 a = rel[i], b = rel[(i + 1) % count];
        double da = cdl_vec3_dot(n, a), db = cdl_vec3_dot(n, b);
        int a_in = da >= 0.0, b_in = db >= 0.0;
        if (a_in != b_in) {
            /* The crossing point of edge ab with the plane n.r = 0. */
            double t = da / (da - db);
            contour_emit(&c, cdl_vec3_madd(a, t, cdl_vec3_sub(b, a)));
        }
        if (b_in) contour_emit(&c, b);
    }
    if (c.far) return c.sum;
    if (c.count > 0) c.sum += edge_term(c.prev, c.first, n);
    return -0.5 * c.sum;
}

/* atan(x) / x and log1p(x) / x, continuous at 0. */
static double atan_ratio(double x)
{
    return fabs(x) < 1e-8 ? 1.0 - x * x / 3.0 : atan(x) / x;
}

static double log1p_ratio(double x)
{
    return fabs(x) < 1e-8 ? 1.0 - 0.5 * x : log1p(x) / x;
}

double cdl_projected_solid_angle_disk(cdl_vec3 c, cdl_vec3 m, double R, cdl_vec3 n)
{
    double mc = cdl_vec3_dot(m, c);
    if (!(mc < 0.0) || !(R > 0.0)) return 0.0; /* p must be in front: m.(p - centre) > 0 */

    /* Circle r(phi) = c + R (a cos phi + b sin phi), a x b = m, so increasing
     * phi runs counter-clockwise seen from the emitting side, hence from p. */
    cdl_frame f = cdl_frame_from_normal(m);
    cdl_vec3 a = f.s, b = f.t;
    double na = cdl_vec3_dot(n, a), nb = cdl_vec3_dot(n, b), nc = cdl_vec3_dot(n, c);

    /* Height of the circle above the receiver's plane: nc + k cos(phi - phi_n). */
    double k = R * hypot(na, nb);
    double phi_lo, phi_hi;
    int chord = 0;
    if (nc >= k) {
        phi_lo = -CDL_PI;
        phi_hi = CDL_PI;
    } else if (nc <= -k) {
        return 0.0;
    } else {
        double phi_n = atan2(nb, na), delta = acos(-nc / k);
        phi_lo = phi_n - delta;
        phi_hi = phi_n + delta;
        chord = 1;
    }

    /* |r|^2 = A + B cos phi + C sin phi = A + rho cos(phi - phi0). A - rho is
     * formed as a sum of squares: no cancellation however close p is. */
    double ca = cdl_vec3_dot(c, a), cb = cdl_vec3_dot(c, b);
    double c_par = hypot(ca, cb);
    double A = mc * mc + c_par * c_par + R * R;
    double rho = 2.0 * R * c_par;
    double A_minus_rho = mc * mc + (c_par - R) * (c_par - R);
    double s = sqrt(A_minus_rho * (A + rho)); /* sqrt(A^2 - rho^2) */
    double phi0 = atan2(cb, ca);
    double psi1 = phi_lo - phi0, psi2 = phi_hi - phi0, dpsi = psi2 - psi1;

    /* Antiderivatives over psi (checked by differentiation):
     *   int dpsi / (A + rho cos psi)        = (psi - 2 T(psi)) / s,
     *       T(psi) = atan(rho sin psi / (A + s + rho cos psi)), continuous for all psi;
     *   int cos psi / (A + rho cos psi)     = (psi - A int dpsi/(...)) / rho
     *                                       = -rho psi / (s (A + s)) + (2A/s) T(psi)/rho;
     *   int sin psi / (A + rho cos psi)     = -ln(A + rho cos psi) / rho.
     * T/rho and the logarithm are evaluated as ratios that stay exact as
     * rho -> 0 (receiver on the axis, or far away). */
    double K0, Kc, Ks;
    if (!chord) {
        /* The whole circle: T and the logarithm return to their start, and
         * are set so exactly (evaluating them at psi and psi + 2 pi would
         * leave rounding noise that the large beta, gamma of a distant disk
         * would amplify). */
        K0 = CDL_TWO_PI / s;
        Kc = -CDL_TWO_PI * rho / (s * (A + s));
        Ks = 0.0;
    } else {
        double den1 = A + s + rho * cos(psi1), den2 = A + s + rho * cos(psi2);
        double y1 = sin(psi1) / den1, y2 = sin(psi2) / den2;
        double U1 = y1 * atan_ratio(rho * y1), U2 = y2 * atan_ratio(rho * y2); /* T / rho */
        K0 = (dpsi - 2.0 * rho * (U2 - U1)) / s;
        Kc = -rho * dpsi / (s * (A + s)) + 2.0 * A / s * (U2 - U1);
        double x = (cos(psi2) - cos(psi1)) / (A + rho * cos(psi1));
        Ks = -x * log1p_ratio(rho * x);
    }
    /* Back from psi to phi = psi + phi0. */
    double Jc = cos(phi0) * Kc - sin(phi0) * Ks;
    double Js = sin(phi0) * Kc + cos(phi0) * Ks;

    /* n . (r x r') = alpha + beta cos phi + gamma sin phi with
     * r' = R (-a sin phi + b cos phi):
     *   alpha = R^2 n.m, beta = R n.(c x b), gamma = -R n.(c x a). */
    double alpha = R * R * cdl_vec3_dot(n, m);
    double beta = R * cdl_vec3_dot(n, cdl_vec3_cross(c, b));
    double gamma = -R * cdl_vec3_dot(n, cdl_vec3_cross(c, a));
    double sum = alpha * K0 + beta * Jc + gamma * Js;

    if (chord) {
        /* Close the contour along the receiver's plane, from the arc's end back to its start. */
        cdl_vec3 r_hi = cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(a, R * cos(phi_hi)), cdl_vec3_scale(b, R * sin(phi_hi))));
        cdl_vec3 r_lo = cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(a, R * cos(phi_lo)), cdl_vec3_scale(b, R * sin(phi_lo))));
        sum += edge_term(r_hi, r_lo, n);
    }
    return fmax(0.0, -0.5 * sum);
}

double cdl_projected_solid_angle_sphere(cdl_vec3 c, double R, cdl_vec3 n)
{
    double d = cdl_vec3_length(c);
    if (!(d > R) || !(R > 0.0)) return 0.0;
    cdl_vec3 w = cdl_vec3_scale(c, 1.0 / d);
    /* The tangent cone from p touches the sphere on a circle at distance
     * (d^2 - R^2)/d along w, of radius R sqrt(d^2 - R^2)/d (right triangle
     * p, centre, tangent point). The disk it bounds, facing p, subtends the
     * same directions, clipped by the receiver's plane in the same way. */
    double q = (d - R) * (d + R);
    return cdl_projected_solid_angle_disk(cdl_vec3_scale(w, q / d), cdl_vec3_neg(w), R * sqrt(q) / d, n);
}
