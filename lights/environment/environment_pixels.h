/* environment_pixels.h - the pixels of a lat-long environment image as cells
 * of the sphere, and their exact projected solid angles (private to lights/).
 *
 * Pixel (i, j) of a W x H image is the cell theta in [theta_a, theta_b]
 * (theta_j = pi j / H from `up`; theta_b clipped at pi / 2 for an
 * upper-hemisphere sky), phi in [phi_a, phi_b] (phi = pi + 2 pi u), a
 * spherical quadrilateral bounded by two parallels and two meridians,
 * coordinates in the emitter's frame (s: azimuth 0, t: azimuth 90, n: up).
 * Its luminance L_ij is constant over it, so a receiver with unit normal n
 * and nothing in the way gets
 *     E(n) = sum_ij L_ij Q_ij(n),  Q_ij(n) = int_cell max(0, n.w) dw,
 * Q the cell's projected solid angle on n's hemisphere. E depends on n only,
 * not on the receiver's position: callers can cache it by normal.
 *
 * Whole cells above the horizon of n: Q = n . V_ij with V_ij = int_cell w dw,
 * in closed form (w = (sin t cos p, sin t sin p, cos t), dw = sin t dt dp):
 *     V_x = S_j (sin phi_b - sin phi_a),  V_y = S_j (cos phi_a - cos phi_b),
 *     V_z = Z_j (phi_b - phi_a),
 *     S_j = int sin^2 t dt = (dt - sin dt cos(theta_a + theta_b)) / 2,
 *     Z_j = int sin t cos t dt = sin(theta_a + theta_b) sin(dt) / 2,
 * dt = theta_b - theta_a. V factors into a row part and a column part, so
 * the per-pixel vectors are kept as those factors (O(W + H) numbers).
 * Whole cells below the horizon: Q = 0. Cells the horizon crosses: the
 * boundary contour integral of the clipped cell (environment_pixels.c).
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_PIXELS_H
#define CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_PIXELS_H

#include "lights/emitters/emitter.h"
#include "base/error.h"
#include "radiometry/frame.h"

typedef struct cdl_env_pixels {
    int width, height;      /* image size */
    int rows;               /* rows that carry light: all, or those above the horizon (upper-only) */
    int upper_only;         /* 1: nothing from below the horizon of up */
    const float *image;     /* W x H luminance before scale (the emitter's copy) */
    double scale;
    cdl_frame frame;        /* s: azimuth 0, t: azimuth 90, n: up */
    double dphi;            /* 2 pi / W */
    /* per row j < rows */
    double *theta_a, *theta_b, *cos_a, *cos_b, *sin_a, *sin_b;
    double *row_s;          /* S_j */
    double *row_z;          /* Z_j */
    double *mid_sin, *mid_cos; /* sin, cos of the row's middle polar angle */
    double *reach;          /* sin of a bound on the angle from a cell's middle to its points, + margin; 2 if >= 90 deg */
    /* per column i */
    double *phi_a;
    double *mid_cos_phi, *mid_sin_phi; /* the column's middle azimuth */
    double *col_dsin, *col_dcos;       /* sin phi_b - sin phi_a, cos phi_a - cos phi_b */
} cdl_env_pixels;

/* Fill the geometry of a W x H image (image and frame borrowed; rows clipped
 * at the horizon when upper_only). CDL_ERR_OUT_OF_MEMORY on failure. */
cdl_status cdl_env_pixels_init(cdl_env_pixels *px, const float *image, int width, int height, double scale,
                               const cdl_frame *frame, int upper_only, cdl_error *err);
void cdl_env_pixels_free(cdl_env_pixels *px);

/* The pixel images seen along unit world direction w (0: below the rows
 * that carry light). */
int cdl_env_pixels_locate(const cdl_env_pixels *px, cdl_vec3 w, int *i, int *j);

/* Solid angle of pixel (i, j) as clipped: (2 pi / W)(cos theta_a - cos theta_b). */
double cdl_env_pixels_solid_angle(const cdl_env_pixels *px, int j);

/* Exact E(n) = scale x sum L_ij Q_ij(n) in lux for unit world normal n; when
 * `weights` is not NULL, weights[j W + i] = L_ij Q_ij(n) (before scale) for
 * the rows that carry light. One pass over the pixels. */
double cdl_env_pixels_illuminance(const cdl_env_pixels *px, cdl_vec3 n, double *weights);

/* Q of cell theta in [theta_a, theta_b], phi in [phi_a, phi_b] (radians,
 * 0 <= theta_a < theta_b <= pi, 0 < phi_b - phi_a <= 2 pi) for unit normal
 * n_local in the emitter's frame, by the boundary contour integral: exact
 * for any cell, the horizon crossing it or not. */
double cdl_env_cell_projected_solid_angle(double theta_a, double theta_b, double phi_a, double phi_b,
                                          cdl_vec3 n_local);

/* int n . (w x dw) along the parallel at polar angle theta0 (its cosine and
 * sine given) from azimuth phi1 to phi2 (radians, either order), n in the
 * emitter's frame: the parallel's part of a boundary integral (above). */
double cdl_env_parallel_flux(double cos_t0, double sin_t0, double phi1, double phi2, cdl_vec3 n);

/* Roots of A cos t + B sin t + C strictly inside (lo, hi), hi - lo <= 2 pi,
 * ascending in out[0 .. 2); returns their count (0 to 2). */
int cdl_env_sinusoid_roots(double A, double B, double C, double lo, double hi, double *out);

/* Going round a boundary that leaves a region at angle `exit` (radians),
 * the signed angle to the nearest of the `count` re-entry angles ahead of
 * it, taken in (-pi, pi] (an entry at the exit itself may come out a
 * rounding error behind it: down to -1e-12 counts); INFINITY when none. */
double cdl_env_next_entry(const double *entries, int count, double exit);

/* The pixel geometry of an image environment; NULL for any other emitter
 * (emitter_environment.c). */
const cdl_env_pixels *cdl_emitter_environment_pixels(const cdl_emitter *emitter);

#endif
