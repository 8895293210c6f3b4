/* room_flux.c - direct and interreflected flux in a room lit from its
 * ceiling (CIE 190:2010 4.2, CIE 52:1982). */
#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "base/sort_doubles.h"
#include "glare/room_flux.h"
#include "radiometry/constants.h"

const double cdl_room_zone_cosines[4] = {0.75, 0.5, 0.25, 0.0};

double cdl_room_parallel_factor(double a, double b, double c)
{
    /* Hamilton and Morgan, NACA TN 2836 (1952); Howell's catalogue C-11 */
    double X = a / c, Y = b / c;
    double sx = sqrt(1.0 + X * X), sy = sqrt(1.0 + Y * Y);
    double s = 0.5 * log((1.0 + X * X) * (1.0 + Y * Y) / (1.0 + X * X + Y * Y)) + X * sy * atan(X / sy) +
               Y * sx * atan(Y / sx) - X * atan(X) - Y * atan(Y);
    return 2.0 / (CDL_PI * X * Y) * s;
}

/* x = M^-1 b for a 3 x 3 M (Cramer's rule; M here is diagonally dominant). */
static void solve3(const double M[3][3], const double b[3], double x[3])
{
    double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    for (int k = 0; k < 3; ++k) {
        double A[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) A[i][j] = j == k ? b[i] : M[i][j];
        x[k] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) /
               det;
    }
}

void cdl_room_transfer_factors(const cdl_room *room, const cdl_room_reflectances *rho, cdl_room_transfer *out)
{
    enum { F = 0, W = 1, C = 2 };
    double area_floor = room->x_m * room->y_m, area_walls = 2.0 * room->h_m * (room->x_m + room->y_m);
    /* configuration factors f[i][j] from surface i to surface j: floor to
     * ceiling by the parallel rectangles, the rest by summation (each row
     * sums to 1) and reciprocity (A_i f_ij = A_j f_ji) */
    double f_fc = cdl_room_parallel_factor(room->x_m, room->y_m, room->h_m);
    double f_wf = (1.0 - f_fc) * area_floor / area_walls;
    double f[3][3] = {{0.0, 1.0 - f_fc, f_fc}, {f_wf, 1.0 - 2.0 * f_wf, f_wf}, {f_fc, 1.0 - f_fc, 0.0}};
    double r[3] = {rho->floor, rho->walls, rho->ceiling};
    /* flux received Phi_j = Phi_direct_j + sum_i rho_i Phi_i f_ij: (1 - A) Phi = Phi_direct */
    double M[3][3];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) M[j][i] = (i == j ? 1.0 : 0.0) - r[i] * f[i][j];
    double to_walls[3];
    for (int s = 0; s < 3; ++s) {
        double direct[3] = {0.0, 0.0, 0.0}, received[3];
        direct[s] = 1.0;
        solve3(M, direct, received);
        to_walls[s] = received[W] - direct[W];
    }
    out->floor_to_walls = to_walls[F];
    out->walls_to_walls = to_walls[W];
    out->ceiling_to_walls = to_walls[C];
}

/* Fraction of the n luminaires at (k + 1/2) s, k = 0..n-1, in a span of n s
 * whose ray moved by a (either way) lands inside the span. */
static double landing_fraction(size_t n, double s, double a)
{
    double count = floor((double)n + 0.5 - fabs(a) / s);
    return count <= 0.0 ? 0.0 : fmin(count, (double)n) / (double)n;
}

double cdl_room_direct_ratio(const cdl_room *room, double u)
{
    if (!(u > 0.0)) return 0.0;
    if (u >= 1.0) return 1.0;
    double rho = room->h_m * sqrt(1.0 - u * u) / u; /* the ray's horizontal reach */
    double sx = room->x_m / (double)room->nx, sy = room->y_m / (double)room->ny;
    /* Over azimuth phi in [0, pi/2] (the other quadrants by symmetry) the
     * landing fraction fx(rho cos phi) fy(rho sin phi) is constant between
     * the angles where rho cos phi or rho sin phi crosses a half-spacing
     * (k + 1/2) s: acos((k + 1/2) sx / rho), increasing as k falls, and
     * asin((k + 1/2) sy / rho), increasing with k. Merge the two and sum. */
    size_t kx = 0, ky = 0;
    while (kx < room->nx && (kx + 0.5) * sx < rho) ++kx; /* how many acos breaks */
    while (ky < room->ny && (ky + 0.5) * sy < rho) ++ky;
    double sum = 0.0, prev = 0.0;
    size_t ix = kx, iy = 0; /* next acos break: index ix - 1; next asin break: iy */
    for (;;) {
        double ax = ix > 0 ? acos((ix - 0.5) * sx / rho) : 2.0; /* 2 > pi/2: none left */
        double ay = iy < ky ? asin((iy + 0.5) * sy / rho) : 2.0;
        double next = fmin(fmin(ax, ay), 0.5 * CDL_PI);
        double mid = 0.5 * (prev + next);
        sum += (next - prev) * landing_fraction(room->nx, sx, rho * cos(mid)) *
               landing_fraction(room->ny, sy, rho * sin(mid));
        if (next >= 0.5 * CDL_PI) break;
        prev = next;
        if (ax <= ay) --ix;
        else ++iy;
    }
    return sum / (0.5 * CDL_PI);
}

/* -l_i'(u) for the Lagrange basis on the nodes 1, 0.75, 0.5, 0.25, 0 (node i). */
static double basis_slope(int i, double u)
{
    static const double node[5] = {1.0, 0.75, 0.5, 0.25, 0.0};
    double d = 0.0;
    for (int m = 0; m < 5; ++m) {
        if (m == i) continue;
        double term = 1.0 / (node[i] - node[m]);
        for (int q = 0; q < 5; ++q)
            if (q != i && q != m) term *= (u - node[q]) / (node[i] - node[q]);
        d += term;
    }
    return -d;
}

/* 8-point Gauss-Legendre on [-1, 1]: nodes and weights (Abramowitz and
 * Stegun, Table 25.4). */
static const double gl_x[4] = {0.183434642495649805, 0.525532409916328986, 0.796666477413626740,
                               0.960289856497536232};
static const double gl_w[4] = {0.362683783378361983, 0.313706645877887287, 0.222381034453374471,
                               0.101228536290376259};

/* Adds int_a^b D(u) (-l_i'(u)) du for i = 1..4 into fgl[0..3]. D may have
 * a square-root kink at either end (a break entering at azimuth 0 or pi/2
 * moves as sqrt(u - a)): the map u = a + (b - a)(3t^2 - 2t^3) makes it
 * smooth in t, integrated by 8-point Gauss-Legendre. */
static void integrate_segment(const cdl_room *room, double a, double b, double fgl[4])
{
    for (int g = 0; g < 8; ++g) {
        double x = g < 4 ? -gl_x[g] : gl_x[g - 4], t = 0.5 * (1.0 + x);
        double u = a + (b - a) * t * t * (3.0 - 2.0 * t);
        double w = 0.5 * gl_w[g < 4 ? g : g - 4] * (b - a) * 6.0 * t * (1.0 - t) * cdl_room_direct_ratio(room, u);
        for (int i = 1; i <= 4; ++i) fgl[i - 1] += w * basis_slope(i, u);
    }
}

cdl_status cdl_room_geometric_factors(const cdl_room *room, double fgl[4], cdl_error *err)
{
    for (int i = 0; i < 4; ++i) fgl[i] = 0.0;
    /* D(u) is smooth between the reaches H tan(gamma) where the azimuthal
     * breaks change: where one enters (the reach passes a half-spacing
     * (k + 1/2) s, x or y) and where an x break and a y break cross (the
     * reach passes hypot of two half-spacings). Integrate between them. */
    size_t nx = room->nx, ny = room->ny, n = nx + ny + nx * ny;
    double *reach = malloc((n + 1) * sizeof *reach);
    if (!reach) return cdl_error_out_of_memory(err);
    double sx = room->x_m / (double)nx, sy = room->y_m / (double)ny;
    size_t k = 0;
    for (size_t i = 0; i < nx; ++i) reach[k++] = (i + 0.5) * sx;
    for (size_t j = 0; j < ny; ++j) reach[k++] = (j + 0.5) * sy;
    for (size_t i = 0; i < nx; ++i)
        for (size_t j = 0; j < ny; ++j) reach[k++] = hypot((i + 0.5) * sx, (j + 0.5) * sy);
    cdl_sort_doubles(reach, n);
    double upper = 1.0; /* u = cos(gamma) falls as the reach grows */
    for (size_t m = 0; m < n; ++m) {
        double lower = room->h_m / hypot(room->h_m, reach[m]);
        if (lower < upper) integrate_segment(room, lower, upper, fgl);
        upper = lower;
    }
    integrate_segment(room, 0.0, upper, fgl);
    free(reach);
    return CDL_OK;
}
