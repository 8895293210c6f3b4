/* environment_pixels.c - exact projected solid angles of lat-long pixels.
 *
 * A cell the horizon of n crosses is integrated through its boundary. For
 * any region A of the unit sphere, int_A w dw = (1/2) contour_dA w x dw, the
 * boundary run counter-clockwise seen from outside (Stokes' theorem on the
 * cone over A; the first-order irradiance tensor of Arvo, "Applications of
 * irradiance tensors to the simulation of non-Lambertian phenomena",
 * SIGGRAPH 1995, section 3). The clipped cell A = cell and {n.w > 0} is
 * bounded by the parts of the cell's four edges above the horizon and by
 * arcs of the horizon great circle; each piece of n . (w x dw) has a closed
 * form:
 *   parallel theta0, phi from p1 to p2:
 *     -cos t0 sin t0 (n_x (sin p2 - sin p1) - n_y (cos p2 - cos p1))
 *       + n_z sin^2 t0 (p2 - p1);
 *   meridian phi0, theta from t1 to t2: (n_y cos phi0 - n_x sin phi0)(t2 - t1);
 *   horizon arc: w x dw = n dpsi, its angle (the arc runs counter-clockwise
 *     about n, keeping {n.w > 0} on its left, from where the cell's edge
 *     leaves the hemisphere to where it comes back).
 * Q = n . int_A w dw is then exact up to rounding. Each crossing point is
 * computed once and shared by the edge piece and the arc it joins, so an
 * ill-conditioned crossing (the horizon nearly tangent to a parallel) moves
 * the region's boundary along itself and costs only second order, and an
 * edge lying on the horizon (n = up, or n horizontal at a column edge)
 * gives the same sum whichever side rounding puts it on: the arc replaces
 * the edge it coincides with.
 */
#include "lights/environment/environment_pixels.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "radiometry/constants.h"

/* ---- one cell, by its boundary --------------------------------------------------- */

typedef struct cell_edge {
    int parallel;       /* 1: theta fixed, the parameter is phi; 0: phi fixed, the parameter is theta */
    double fc, fs;      /* cos and sin of the fixed angle */
    double t0, t1;      /* the parameter runs from t0 to t1 */
} cell_edge;

static cdl_vec3 edge_point(const cell_edge *e, double t)
{
    if (e->parallel) return cdl_vec3_make(e->fs * cos(t), e->fs * sin(t), e->fc);
    return cdl_vec3_make(sin(t) * e->fc, sin(t) * e->fs, cos(t));
}

/* n.w along the edge as A cos t + B sin t + C. */
static void edge_height(const cell_edge *e, cdl_vec3 n, double *A, double *B, double *C)
{
    if (e->parallel) {
        *A = e->fs * n.x;
        *B = e->fs * n.y;
        *C = e->fc * n.z;
    } else {
        *A = n.z;
        *B = e->fc * n.x + e->fs * n.y;
        *C = 0.0;
    }
}

/* int n . (w x dw) along the edge from parameter a to b (formulas above;
 * sin b - sin a = 2 cos m sin h, cos b - cos a = -2 sin m sin h with m the
 * mean and h the half difference, which keeps short pieces accurate). */
double cdl_env_parallel_flux(double cos_t0, double sin_t0, double phi1, double phi2, cdl_vec3 n)
{
    double m = 0.5 * (phi1 + phi2), sh = sin(0.5 * (phi2 - phi1));
    double dsin = 2.0 * cos(m) * sh, dcos = -2.0 * sin(m) * sh;
    return -cos_t0 * sin_t0 * (n.x * dsin - n.y * dcos) + n.z * sin_t0 * sin_t0 * (phi2 - phi1);
}

static double edge_flux(const cell_edge *e, cdl_vec3 n, double a, double b)
{
    if (!e->parallel) return (n.y * e->fc - n.x * e->fs) * (b - a);
    return cdl_env_parallel_flux(e->fc, e->fs, a, b, n);
}

int cdl_env_sinusoid_roots(double A, double B, double C, double lo, double hi, double *out)
{
    double R = hypot(A, B);
    if (!(R > fabs(C))) return 0;
    double base = atan2(B, A), half = acos(-C / R);
    int k = 0;
    for (int s = -1; s <= 1; s += 2) {
        double t = fmod(base + s * half - lo, CDL_TWO_PI);
        if (t < 0.0) t += CDL_TWO_PI;
        t += lo;
        if (t > lo && t < hi) out[k++] = t;
    }
    if (k == 2 && out[1] < out[0]) {
        double tmp = out[0];
        out[0] = out[1];
        out[1] = tmp;
    }
    return k;
}

typedef struct piece {
    int lit;            /* above the horizon */
    cdl_vec3 start, end;
} piece;

/* Azimuth of w about n on the horizon, from the frame's s towards t
 * (s x t = n: counter-clockwise about n). */
static double horizon_angle(const cdl_frame *f, cdl_vec3 w)
{
    return atan2(cdl_vec3_dot(f->t, w), cdl_vec3_dot(f->s, w));
}

/* The horizon arcs of the clipped cell. Going counter-clockwise about n
 * from a point where the cell's boundary leaves the hemisphere, the
 * horizon stays inside the cell until the boundary comes back: the nearest
 * re-entry ahead, less than pi away (a great circle meets a cell narrower
 * than pi in azimuth in arcs shorter than pi). Pairing by the horizon, not
 * by the order along the boundary, handles cells the horizon crosses
 * twice. */
static double horizon_arcs(cdl_vec3 n, const piece *pieces, int count)
{
    cdl_frame f = cdl_frame_from_normal(n);
    double exits[12], entries[12];
    int ne = 0, nr = 0;
    for (int k = 0; k < count; ++k) {
        int next = (k + 1) % count;
        if (pieces[k].lit == pieces[next].lit) continue;
        double psi = horizon_angle(&f, pieces[k].end);
        if (pieces[k].lit) exits[ne++] = psi;
        else entries[nr++] = psi;
    }
    double total = 0.0;
    for (int a = 0; a < ne; ++a) {
        /* (the boundary touching the horizon re-enters at the exit itself) */
        double best = cdl_env_next_entry(entries, nr, exits[a]);
        if (isfinite(best) && best > 0.0) total += best;
    }
    return total;
}

double cdl_env_cell_projected_solid_angle(double theta_a, double theta_b, double phi_a, double phi_b,
                                          cdl_vec3 n)
{
    /* The arc rule needs cells narrower than pi in azimuth (images 1 or 2
     * pixels wide): halve wider ones, the integral being additive. */
    if (phi_b - phi_a > 0.75 * CDL_PI) {
        double mid = 0.5 * (phi_a + phi_b);
        return cdl_env_cell_projected_solid_angle(theta_a, theta_b, phi_a, mid, n) +
               cdl_env_cell_projected_solid_angle(theta_a, theta_b, mid, phi_b, n);
    }
    /* Counter-clockwise seen from outside: the lower parallel eastwards, the
     * eastern meridian up, the upper parallel westwards, the western down. */
    const cell_edge edges[4] = {
        {1, cos(theta_b), sin(theta_b), phi_a, phi_b},
        {0, cos(phi_b), sin(phi_b), theta_b, theta_a},
        {1, cos(theta_a), sin(theta_a), phi_b, phi_a},
        {0, cos(phi_a), sin(phi_a), theta_a, theta_b},
    };
    piece pieces[12];
    int count = 0, lit = 0;
    double flux = 0.0;
    for (int k = 0; k < 4; ++k) {
        const cell_edge *e = &edges[k];
        double A, B, C, roots[2];
        edge_height(e, n, &A, &B, &C);
        int forward = e->t1 >= e->t0;
        int r = cdl_env_sinusoid_roots(A, B, C, forward ? e->t0 : e->t1, forward ? e->t1 : e->t0, roots);
        double cut[4];
        int m = 0;
        cut[m++] = e->t0;
        for (int q = 0; q < r; ++q) cut[m++] = roots[forward ? q : r - 1 - q];
        cut[m++] = e->t1;
        cdl_vec3 start = edge_point(e, cut[0]);
        for (int q = 0; q + 1 < m; ++q) {
            double mid = 0.5 * (cut[q] + cut[q + 1]);
            piece *p = &pieces[count++];
            p->lit = A * cos(mid) + B * sin(mid) + C > 0.0;
            p->start = start;
            p->end = edge_point(e, cut[q + 1]);
            start = p->end;
            if (p->lit) {
                flux += edge_flux(e, n, cut[q], cut[q + 1]);
                lit++;
            }
        }
    }
    if (lit == 0) return 0.0;
    double Q = 0.5 * (flux + horizon_arcs(n, pieces, count));
    return Q > 0.0 ? Q : 0.0;
}

/* ---- the image's cells --------------------------------------------------------- */

void cdl_env_pixels_free(cdl_env_pixels *px)
{
    /* One block holds every array (see init). */
    free(px->theta_a);
    px->theta_a = NULL;
}

/* dt - sin dt without cancellation for small dt (its Taylor series). */
static double x_minus_sin(double x)
{
    if (fabs(x) > 0.1) return x - sin(x);
    double x2 = x * x;
    return x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0))));
}

cdl_status cdl_env_pixels_init(cdl_env_pixels *px, const float *image, int width, int height, double scale,
                               const cdl_frame *frame, int upper_only, cdl_error *err)
{
    size_t H = (size_t)height, W = (size_t)width;
    double *block = malloc((11 * H + 5 * W + 1) * sizeof *block);
    if (!block) return cdl_error_out_of_memory(err);
    px->width = width;
    px->height = height;
    px->image = image;
    px->scale = scale;
    px->upper_only = upper_only ? 1 : 0;
    px->frame = *frame;
    px->dphi = CDL_TWO_PI / width;
    double **rows[] = {&px->theta_a, &px->theta_b, &px->cos_a, &px->cos_b, &px->sin_a, &px->sin_b,
                       &px->row_s, &px->row_z, &px->mid_sin, &px->mid_cos, &px->reach};
    double *at = block;
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; ++k, at += H) *rows[k] = at;
    px->phi_a = at;
    at += W + 1;
    px->mid_cos_phi = at;
    px->mid_sin_phi = at + W;
    px->col_dsin = at + 2 * W;
    px->col_dcos = at + 3 * W;

    px->rows = 0;
    for (int j = 0; j < height; ++j) {
        /* theta_j = pi j / H; cos theta_j as sin(pi (H - 2j) / (2H)), exactly
         * 0 at the horizon. */
        double ta = CDL_PI * j / height, tb = CDL_PI * (j + 1) / height;
        double ca = sin(CDL_PI * (height - 2 * j) / (2.0 * height)), cb = sin(CDL_PI * (height - 2 * j - 2) / (2.0 * height));
        if (upper_only) {
            if (!(ca > 0.0)) break;
            if (cb < 0.0) {
                tb = 0.5 * CDL_PI;
                cb = 0.0;
            }
        }
        px->theta_a[j] = ta;
        px->theta_b[j] = tb;
        px->cos_a[j] = ca;
        px->cos_b[j] = cb;
        px->sin_a[j] = sin(ta);
        px->sin_b[j] = sin(tb);
        double dt = tb - ta, sum = ta + tb;
        /* int sin^2 t dt = (dt - sin dt cos(ta + tb)) / 2, written
         * (dt - sin dt + 2 sin dt sin^2((ta + tb) / 2)) / 2 to keep polar rows exact. */
        double sh = sin(0.5 * sum);
        px->row_s[j] = 0.5 * (x_minus_sin(dt) + 2.0 * sin(dt) * sh * sh);
        /* int sin t cos t dt = (sin^2 tb - sin^2 ta) / 2 = sin(ta + tb) sin(dt) / 2. */
        px->row_z[j] = 0.5 * sin(sum) * sin(dt);
        double tm = 0.5 * sum;
        px->mid_sin[j] = sin(tm);
        px->mid_cos[j] = cos(tm);
        /* Angle from the cell's middle to any of its points: along the
         * middle meridian to the point's parallel, then along that parallel
         * (a longer path than the great circle): <= dt / 2 + max sin theta x dphi / 2. */
        double smax = (ta < 0.5 * CDL_PI && tb > 0.5 * CDL_PI) ? 1.0 : fmax(sin(ta), sin(tb));
        double r = 0.5 * dt + 0.5 * smax * px->dphi;
        /* cos(angle(n, middle)) >= sin r puts the whole cell on one side; the
         * margin covers rounding in the test's dot product. */
        px->reach[j] = r < 0.5 * CDL_PI ? sin(r) + 1e-12 : 2.0;
        px->rows = j + 1;
    }
    for (int i = 0; i <= width; ++i) px->phi_a[i] = CDL_PI + CDL_TWO_PI * i / width;
    for (int i = 0; i < width; ++i) {
        double pm = 0.5 * (px->phi_a[i] + px->phi_a[i + 1]), sh = sin(0.5 * px->dphi);
        px->mid_cos_phi[i] = cos(pm);
        px->mid_sin_phi[i] = sin(pm);
        /* sin pb - sin pa = 2 cos pm sin(dphi / 2); cos pa - cos pb = 2 sin pm sin(dphi / 2). */
        px->col_dsin[i] = 2.0 * cos(pm) * sh;
        px->col_dcos[i] = 2.0 * sin(pm) * sh;
    }
    return CDL_OK;
}

double cdl_env_pixels_solid_angle(const cdl_env_pixels *px, int j)
{
    /* Omega = int sin t dt dp = dphi (cos theta_a - cos theta_b). */
    return px->dphi * (px->cos_a[j] - px->cos_b[j]);
}

int cdl_env_pixels_locate(const cdl_env_pixels *px, cdl_vec3 w, int *i, int *j)
{
    cdl_vec3 l = cdl_frame_to_local(&px->frame, w);
    double phi = atan2(l.y, l.x);           /* (-pi, pi] */
    double u = (phi - CDL_PI) / CDL_TWO_PI; /* phi = pi + 2 pi u */
    if (u < 0.0) u += 1.0;
    double v = atan2(hypot(l.x, l.y), l.z) / CDL_PI;
    *i = (int)fmin(floor(u * px->width), px->width - 1.0);
    *j = (int)fmin(floor(v * px->height), px->height - 1.0);
    if (*i < 0) *i = 0;
    if (*j < 0) *j = 0;
    return *j < px->rows && !(px->upper_only && !(l.z > 0.0));
}

double cdl_env_pixels_illuminance(const cdl_env_pixels *px, cdl_vec3 n, double *weights)
{
    cdl_vec3 nl = cdl_frame_to_local(&px->frame, n);
    double E = 0.0;
    size_t W = (size_t)px->width;
    for (int j = 0; j < px->rows; ++j) {
        const float *row = px->image + (size_t)j * W;
        double *wrow = weights ? weights + (size_t)j * W : NULL;
        double ms = px->mid_sin[j], mc = px->mid_cos[j] * nl.z, reach = px->reach[j];
        double S = px->row_s[j], Z = nl.z * px->dphi * px->row_z[j];
        double row_sum = 0.0;
        for (size_t i = 0; i < W; ++i) {
            double L = row[i], q = 0.0;
            if (L > 0.0) {
                double d = ms * (nl.x * px->mid_cos_phi[i] + nl.y * px->mid_sin_phi[i]) + mc;
                if (d >= reach)
                    q = fmax(0.0, S * (nl.x * px->col_dsin[i] + nl.y * px->col_dcos[i]) + Z); /* n . V */
                else if (d > -reach)
                    q = cdl_env_cell_projected_solid_angle(px->theta_a[j], px->theta_b[j], px->phi_a[i],
                                                           px->phi_a[i + 1], nl);
                q *= L;
            }
            if (wrow) wrow[i] = q;
            row_sum += q;
        }
        E += row_sum;
    }
    return px->scale * E;
}

double cdl_env_next_entry(const double *entries, int count, double exit)
{
    double best = INFINITY;
    for (int b = 0; b < count; ++b) {
        double d = entries[b] - exit;
        if (d <= -CDL_PI) d += CDL_TWO_PI;
        if (d > CDL_PI) d -= CDL_TWO_PI;
        if (d > -1e-12 && d < best) best = d;
    }
    return best;
}
