/* emitter_environment.c - light from infinitely far away in every direction.
 *
 *   parameter      meaning                                       unit    default  range
 *   up             zenith                                        -       +z       non-zero
 *   upper_hemi...  1: nothing from below the horizon of up       -       0        0 or 1
 *   luminance      sky model's (image == NULL): everywhere       cd/m^2  -        >= 0
 *                  (uniform) or at the zenith (CIE overcast)
 *   sky            uniform, CIE overcast, CIE general (type 1..  -       uniform
 *                  15) or Perez (image == NULL)
 *   cie_type       CIE general sky's type                        -       -        1..15
 *   perez          Perez sky's a, b, c, d, e                     -       -        b < 0
 *   sun            towards the sun (CIE general, Perez)          -       +z       above the horizon
 *   horizontal     scale to this unobstructed horizontal E       lx      -        >= 0
 *                  instead of L_z (scale_to_horizontal)
 *   image          lat-long luminance, width x height, copied    cd/m^2  NULL     finite, >= 0
 *   scale          multiplies the image                          -       1        > 0
 *
 * Image mapping (DESIGN.md): column u in [0,1) looks towards azimuth
 * phi = pi + 2 pi u, counter-clockwise from the azimuth reference seen from
 * above (left edge -x, centre +x for up = +z); row v in [0,1) towards polar
 * angle theta = pi v from up. Luminance is constant over each pixel's solid
 * angle Omega_j = (2 pi / width)(cos theta_j - cos theta_j+1).
 * Azimuth reference: world +x made perpendicular to up (world +y when up is
 * within 2.6 degrees of the x axis); azimuth 90 is up x reference.
 *
 * Illuminance on a plane of normal n, unoccluded:
 *   uniform, full sphere:      E = pi L for every n;
 *   uniform, upper hemisphere: E = pi L (1 + cos beta) / 2, beta the angle
 *     between n and up (derivation at environment_exact below);
 *   CIE overcast, L = L_z (1 + 2 cos theta) / 3 above the horizon:
 *     E = (L_z / 3) [pi (1 + cos beta) / 2 + (4 / 3)((pi - beta) cos beta
 *     + sin beta)] (derivation at overcast_exact below), 7 pi L_z / 9 on
 *     a horizontal plane (beta = 0);
 *   CIE general and Perez skies: a quadrature about the sun converged to
 *     about 3e-8 (sky_distribution.h), 0.2 ms a plane;
 *   image: E(n) = sum over pixels of L_ij times the pixel's projected solid
 *     angle on n's hemisphere, exact (environment_pixels.h: the per-pixel
 *     vector integral of w for whole pixels, the boundary contour of the
 *     clipped pixel where the horizon of n crosses it); one pass over the
 *     pixels, the same for every receiver with the same normal, so callers
 *     that meet many points with one normal can cache it by normal.
 * "Flux" (cdl_emitter_flux): the flux on the face of a 1 m^2 disk facing up,
 * Phi = int over the upper hemisphere of L cos theta dw: pi L for a uniform
 * sky either way, 7 pi L_z / 9 for the overcast sky; for an image, E(up)
 * above.
 *
 * Sampling: uniform and overcast skies, cosine-weighted about the receiver
 * normal n (pdf = cos / pi: zero variance for a full uniform sky with
 * nothing in the way); CIE general and Perez skies, that mixed half and
 * half with a density about the sun where they brighten towards it
 * (sky_distribution.h);
 * image, a pixel with probability L_ij Omega_j / sum(L Omega), then a
 * uniform direction within the pixel's solid angle: pdf = L_ij / sum(L Omega)
 * in solid angle, exact.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/emitters/distribution2d.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "lights/environment/environment_bounds.h"
#include "lights/environment/environment_pixels.h"
#include "lights/environment/sky_distribution.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "radiometry/sampling.h"

typedef struct environment_emitter {
    cdl_emitter base;
    cdl_frame frame; /* s: azimuth 0, t: azimuth 90, n: up */
    int upper_only;
    cdl_sky_model sky; /* without an image */
    double L;        /* uniform sky; the overcast sky's zenith */
    cdl_sky_distribution model; /* CIE general and Perez skies */
    /* image */
    float *image;
    int width, height;
    double scale;
    cdl_env_pixels px;            /* the pixels as cells of the sphere (rows clipped at the horizon if upper_only) */
    cdl_distribution2d *dist;     /* weights image x pixel solid angle */
    cdl_env_range range;          /* block minima and maxima, for luminance bounds over a region */
    double flux;
} environment_emitter;

static const environment_emitter *as_env(const cdl_emitter *e)
{
    return (const environment_emitter *)e;
}

/* A CIE general or Perez sky (sky_distribution.h). */
static int has_distribution(const environment_emitter *env)
{
    return !env->image && (env->sky == CDL_SKY_CIE_GENERAL || env->sky == CDL_SKY_PEREZ);
}

/* ---- flux ------------------------------------------------------------------- */

static cdl_luminous_flux environment_flux(const cdl_emitter *e)
{
    const environment_emitter *env = as_env(e);
    /* Uniform sky over the upper hemisphere: int L cos dw = pi L; the
     * overcast sky's E on the horizontal (overcast_exact, beta = 0). */
    if (env->image) return cdl_lumens(env->flux);
    if (has_distribution(env)) return cdl_lumens(env->flux);
    return cdl_lumens(env->sky == CDL_SKY_CIE_OVERCAST ? 7.0 * CDL_PI * env->L / 9.0 : CDL_PI * env->L);
}

/* ---- exact illuminance ------------------------------------------------------ */

/* The CIE overcast sky on the plane of n, beta between n and up. Its
 * luminance is L_z (1 + 2 u.w) / 3 over the sky D = {u.w > 0, n.w > 0}
 * (u = up), so
 *     E = (L_z / 3) [int_D n.w dw + 2 int_D (u.w)(n.w) dw].
 * D is a lune: two hemispheres whose boundary great circles meet at
 * +-l, l = u x n / |u x n|. About l as the polar axis (polar angle t,
 * azimuth a from u, u = (1, 0, 0) and n = (cos beta, sin beta, 0) in the
 * plane l is normal to), u.w = sin t cos a and n.w = sin t cos(a - beta),
 * and D is a in [beta - pi/2, pi/2], t in [0, pi]. With int_0^pi sin^2 t
 * dt = pi / 2 and int_0^pi sin^3 t dt = 4 / 3:
 *     int_D n.w dw = (pi / 2) int cos(a - beta) da = (pi / 2)(1 + cos beta),
 *     int_D (u.w)(n.w) dw = (4 / 3) int cos a cos(a - beta) da
 *                         = (2 / 3)((pi - beta) cos beta + sin beta)
 * (cos a cos(a - beta) = [cos beta + cos(2a - beta)] / 2). The first is
 * the uniform sky's view factor again (environment_exact); at beta = 0
 * E = (L_z / 3)(pi + 4 pi / 3) = 7 pi L_z / 9, the overcast sky's
 * classical horizontal illuminance (Moon and Spencer, "Illumination from a
 * non-uniform sky", Illuminating Engineering 37, 1942). */
static double overcast_exact(double L_z, double cos_beta)
{
    double beta = acos(cos_beta), sin_beta = sqrt(fmax(0.0, 1.0 - cos_beta * cos_beta));
    return L_z / 3.0 * (0.5 * CDL_PI * (1.0 + cos_beta) + 4.0 / 3.0 * ((CDL_PI - beta) * cos_beta + sin_beta));
}

static int environment_exact(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_illuminance *E)
{
    (void)p;
    const environment_emitter *env = as_env(e);
    if (env->image) {
        *E = cdl_lux(cdl_env_pixels_illuminance(&env->px, n, NULL));
        return 1;
    }
    if (env->sky == CDL_SKY_CIE_OVERCAST) {
        *E = cdl_lux(overcast_exact(env->L, fmax(-1.0, fmin(1.0, cdl_vec3_dot(n, env->frame.n)))));
        return 1;
    }
    if (has_distribution(env)) {
        *E = cdl_lux(cdl_sky_distribution_illuminance(&env->model, n));
        return 1;
    }
    if (!env->upper_only) {
        /* The receiver's whole hemisphere is sky: int L cos dw = pi L. */
        *E = cdl_lux(CDL_PI * env->L);
        return 1;
    }
    /* Sky above the horizon only. With max(0, x) = (x + |x|)/2:
     *   int_sky n.w dw   = n . int_sky w dw = n . (pi up) = pi cos(beta),
     *   int_sky |n.w| dw = half of int_sphere |n.w| dw = pi
     * (w -> -w maps the sky onto the ground and keeps |n.w|), hence
     *   E = L pi (1 + cos beta) / 2,
     * the isotropic-sky view factor of a tilted plane (e.g. Duffie and
     * Beckman, "Solar Engineering of Thermal Processes", 4th ed., 2013, 2.19). */
    double cos_beta = fmax(-1.0, fmin(1.0, cdl_vec3_dot(n, env->frame.n)));
    *E = cdl_lux(CDL_PI * env->L * 0.5 * (1.0 + cos_beta));
    return 1;
}

/* ---- directions and pixels ------------------------------------------------- */

/* A sky model's luminance towards unit w: uniform, or the CIE overcast
 * sky's L_z (1 + 2 cos theta) / 3 (overcast_exact), nothing below the
 * horizon where the sky has none. */
static cdl_luminance sky_radiance_towards(const environment_emitter *env, cdl_vec3 w)
{
    double cos_theta = cdl_vec3_dot(w, env->frame.n);
    if (env->upper_only && !(cos_theta > 0.0)) return cdl_nits(0.0);
    if (has_distribution(env)) return cdl_nits(cdl_sky_distribution_luminance(&env->model, w));
    if (env->sky == CDL_SKY_CIE_OVERCAST) return cdl_nits(env->L * (1.0 + 2.0 * fmin(1.0, cos_theta)) / 3.0);
    return cdl_nits(env->L);
}

static double pixel_value(const environment_emitter *env, int i, int j)
{
    return env->image[(size_t)j * env->width + i];
}

/* ---- sampling and radiance --------------------------------------------------- */

static int environment_sample(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, double u1, double u2,
                              cdl_light_sample *out)
{
    (void)p;
    const environment_emitter *env = as_env(e);
    cdl_vec3 w;
    double pdf;
    cdl_luminance L;
    if (has_distribution(env)) {
        w = cdl_sky_distribution_sample(&env->model, n, u1, u2, &pdf);
        L = sky_radiance_towards(env, w);
    } else if (!env->image) {
        cdl_frame f = cdl_frame_from_normal(n);
        w = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(u1, u2));
        pdf = fmax(0.0, cdl_vec3_dot(n, w)) * CDL_INV_PI;
        L = sky_radiance_towards(env, w);
    } else {
        size_t i, j;
        double fx, fy;
        if (!cdl_distribution2d_sample(env->dist, u1, u2, &i, &j, &fx, &fy)) return 0;
        /* Uniform in solid angle within the pixel: cos(theta) uniform between
         * the row's bounds, phi uniform across the column. */
        double cos_t = env->px.cos_a[j] - fy * (env->px.cos_a[j] - env->px.cos_b[j]);
        double sin_t = sqrt(fmax(0.0, (1.0 - cos_t) * (1.0 + cos_t)));
        double phi = CDL_PI + CDL_TWO_PI * ((double)i + fx) / env->width;
        w = cdl_frame_to_world(&env->frame, cdl_vec3_make(sin_t * cos(phi), sin_t * sin(phi), cos_t));
        double value = pixel_value(env, (int)i, (int)j);
        /* pdf = P(pixel) / Omega(pixel) = (value Omega / total) / Omega = value / total. */
        pdf = value / cdl_distribution2d_total(env->dist);
        L = cdl_nits(env->scale * value);
    }
    if (!(cdl_vec3_dot(n, w) > 0.0) || !(L.cd_m2 > 0.0) || !(pdf > 0.0)) return 0;
    out->to_light = w;
    out->distance = INFINITY;
    out->L = L;
    out->pdf = pdf;
    return 1;
}

static cdl_luminance environment_radiance(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_vec3 w, double *pdf)
{
    (void)p;
    const environment_emitter *env = as_env(e);
    if (has_distribution(env)) {
        cdl_vec3 u = cdl_vec3_normalize(w);
        if (pdf) *pdf = cdl_sky_distribution_pdf(&env->model, n, u);
        return sky_radiance_towards(env, u);
    }
    if (!env->image) {
        if (pdf) *pdf = fmax(0.0, cdl_vec3_dot(n, w)) * CDL_INV_PI;
        return sky_radiance_towards(env, w);
    }
    int i, j;
    if (!cdl_env_pixels_locate(&env->px, w, &i, &j)) return cdl_nits(0.0);
    double value = pixel_value(env, i, j);
    double total = cdl_distribution2d_total(env->dist);
    if (pdf) *pdf = total > 0.0 ? value / total : 0.0;
    return cdl_nits(env->scale * value);
}

/* ---- construction ------------------------------------------------------------- */

static void environment_destroy(cdl_emitter *e)
{
    environment_emitter *env = (environment_emitter *)e;
    free(env->image);
    cdl_env_pixels_free(&env->px);
    cdl_env_range_free(&env->range);
    cdl_distribution2d_release(env->dist);
}

static const cdl_emitter_ops environment_ops = {environment_flux, NULL, NULL, environment_exact,
                                                environment_sample, environment_radiance, environment_destroy, NULL, NULL};

static cdl_status build_image(environment_emitter *env, const cdl_environment_params *p, cdl_error *err)
{
    if (p->width < 1 || p->height < 1)
        return cdl_error_set(err, CDL_ERR_INPUT, "environment image: expected at least 1 x 1 pixels, found %d x %d",
                             p->width, p->height);
    if (!(isfinite(p->scale) && p->scale > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "environment image: scale: expected a finite number > 0, found %g",
                             p->scale);
    size_t count = (size_t)p->width * (size_t)p->height;
    for (size_t k = 0; k < count; ++k)
        if (!(isfinite(p->image[k]) && p->image[k] >= 0.0f))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "environment image: pixel (column %zu, row %zu): expected a finite luminance >= 0 "
                                 "cd/m^2, found %g",
                                 k % (size_t)p->width, k / (size_t)p->width, (double)p->image[k]);
    env->width = p->width;
    env->height = p->height;
    env->scale = p->scale;
    env->image = malloc(count * sizeof *env->image);
    double *omega = calloc((size_t)p->height, sizeof(double));
    if (!env->image || !omega) {
        free(omega);
        return cdl_error_out_of_memory(err);
    }
    memcpy(env->image, p->image, count * sizeof *env->image);
    cdl_status st = cdl_env_pixels_init(&env->px, env->image, p->width, p->height, p->scale, &env->frame,
                                        env->upper_only, err);
    /* Pixel solid angles; 0 for rows below the horizon of an upper-only sky. */
    for (int j = 0; st == CDL_OK && j < env->px.rows; ++j) omega[j] = cdl_env_pixels_solid_angle(&env->px, j);
    if (st == CDL_OK)
        st = cdl_distribution2d_create(p->image, omega, (size_t)p->width, (size_t)p->height, &env->dist, err);
    free(omega);
    if (st == CDL_OK) st = cdl_env_range_build(&env->range, &env->px, err);
    if (st != CDL_OK) return st;
    env->flux = cdl_env_pixels_illuminance(&env->px, env->frame.n, NULL);
    return CDL_OK;
}

/* A CIE general or Perez sky from its parameters, scaled by its zenith
 * luminance or its horizontal illuminance. */
static cdl_status build_distribution(environment_emitter *env, const cdl_environment_params *p, cdl_error *err)
{
    cdl_status st;
    double coefficients[5], k = 0.0;
    if (p->sky == CDL_SKY_CIE_GENERAL) {
        if (!cdl_sky_cie_parameters(p->cie_type, coefficients))
            return cdl_error_set(err, CDL_ERR_INPUT, "environment emitter: cie_type: expected 1 to 15, found %d",
                                 p->cie_type);
        /* f(pi / 2) = 1 + e cos^2(pi / 2): the indicatrix is 1 at right angles to the sun */
        k = exp(coefficients[3] * 0.5 * CDL_PI);
    } else {
        for (int i = 0; i < 5; ++i) {
            if (!isfinite(p->perez[i]))
                return cdl_error_set(err, CDL_ERR_INPUT, "environment emitter: perez[%d]: expected a finite number, "
                                                         "found %g", i, p->perez[i]);
            coefficients[i] = p->perez[i];
        }
    }
    cdl_vec3 sun;
    if ((st = cdl_emitter_check_direction(p->sun, "environment emitter: sun", &sun, err)) != CDL_OK) return st;
    if (p->scale_to_horizontal &&
        (st = cdl_emitter_check_nonnegative(p->horizontal.lx, "environment emitter: horizontal", "lx", err)) != CDL_OK)
        return st;
    st = cdl_sky_distribution_init(&env->model, env->frame.n, env->frame.s, sun, coefficients, k,
                                   p->sky == CDL_SKY_PEREZ, err);
    if (st == CDL_OK)
        st = cdl_sky_distribution_scale_to(&env->model, p->luminance.cd_m2,
                                           p->scale_to_horizontal ? p->horizontal.lx : -1.0, err);
    if (st != CDL_OK) return cdl_error_prefix(err, "environment emitter: ");
    env->L = cdl_sky_distribution_zenith(&env->model);
    env->flux = cdl_sky_distribution_illuminance(&env->model, env->frame.n);
    return CDL_OK;
}

cdl_status cdl_emitter_create_environment(const cdl_environment_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status st;
    cdl_vec3 up;
    if ((st = cdl_emitter_check_direction(p->up, "environment emitter: up", &up, err)) != CDL_OK) return st;
    if (!p->image && !p->scale_to_horizontal &&
        (st = cdl_emitter_check_nonnegative(p->luminance.cd_m2, "environment emitter: luminance", "cd/m^2", err)) !=
            CDL_OK)
        return st;
    if (p->sky != CDL_SKY_UNIFORM && p->sky != CDL_SKY_CIE_OVERCAST && p->sky != CDL_SKY_CIE_GENERAL &&
        p->sky != CDL_SKY_PEREZ)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "environment emitter: sky: expected uniform, CIE overcast, CIE general or Perez, found %d",
                             (int)p->sky);
    if (p->image && p->sky != CDL_SKY_UNIFORM)
        return cdl_error_set(err, CDL_ERR_INPUT, "environment emitter: sky: expected no sky model with an image, "
                                                 "found sky model %d", (int)p->sky);
    environment_emitter *env = cdl_emitter_alloc(sizeof *env, CDL_EMITTER_ENVIRONMENT, &environment_ops, err);
    if (!env) return CDL_ERR_INTERNAL;
    /* Azimuth reference: world +x made perpendicular to up (Gram-Schmidt). */
    cdl_vec3 ref = fabs(up.x) > 0.999 ? cdl_vec3_make(0.0, 1.0, 0.0) : cdl_vec3_make(1.0, 0.0, 0.0);
    env->frame.n = up;
    env->frame.s = cdl_vec3_normalize(cdl_vec3_madd(ref, -cdl_vec3_dot(ref, up), up));
    env->frame.t = cdl_vec3_cross(up, env->frame.s);
    env->sky = p->image ? CDL_SKY_UNIFORM : p->sky;
    /* The overcast sky has no ground: L would be below L_z / 3 and fall to
     * -L_z / 3 at the nadir. */
    env->upper_only = p->upper_hemisphere_only || env->sky != CDL_SKY_UNIFORM ? 1 : 0;
    env->L = p->image ? 0.0 : p->luminance.cd_m2;
    if (p->image && (st = build_image(env, p, err)) != CDL_OK) {
        cdl_emitter_release(&env->base);
        return st;
    }
    if (!p->image && (p->sky == CDL_SKY_CIE_GENERAL || p->sky == CDL_SKY_PEREZ) &&
        (st = build_distribution(env, p, err)) != CDL_OK) {
        cdl_emitter_release(&env->base);
        return st;
    }
    *out = &env->base;
    return CDL_OK;
}

const cdl_env_pixels *cdl_emitter_environment_pixels(const cdl_emitter *emitter)
{
    if (!emitter || emitter->ops != &environment_ops) return NULL;
    const environment_emitter *env = as_env(emitter);
    return env->image ? &env->px : NULL;
}

const cdl_env_range *cdl_emitter_environment_range(const cdl_emitter *emitter)
{
    if (!emitter || emitter->ops != &environment_ops) return NULL;
    const environment_emitter *env = as_env(emitter);
    return env->image ? &env->range : NULL;
}

/* Bounds over a region (environment_bounds.h): an image's least and
 * greatest pixel over the rows and columns the region touches; a sky
 * model's from the region's range of cos(theta) (uniform: L; overcast:
 * L_z (1 + 2 cos theta) / 3, rising towards the zenith); 0 included where
 * the region reaches below an upper-only sky's horizon. */
int cdl_emitter_luminance_bounds(const cdl_emitter *emitter, const cdl_vec3 *dirs, int count, cdl_luminance *lo,
                                 cdl_luminance *hi)
{
    if (!emitter || emitter->ops != &environment_ops) return 0;
    const environment_emitter *env = as_env(emitter);
    cdl_env_extent e;
    cdl_env_extent_of_polygon(&env->frame, dirs, count, &e);
    double L_lo, L_hi;
    if (env->image) {
        cdl_env_range_query(&env->range, &env->px, &e, &L_lo, &L_hi);
    } else if (has_distribution(env)) {
        cdl_sky_distribution_bounds(&env->model, dirs, count, &L_lo, &L_hi);
    } else if (env->sky == CDL_SKY_CIE_OVERCAST) {
        L_lo = e.cos_lo > 0.0 ? env->L * (1.0 + 2.0 * e.cos_lo) / 3.0 : 0.0;
        L_hi = e.cos_hi > 0.0 ? env->L * (1.0 + 2.0 * e.cos_hi) / 3.0 : 0.0;
    } else {
        L_hi = env->upper_only && !(e.cos_hi > 0.0) ? 0.0 : env->L;
        L_lo = env->upper_only && !(e.cos_lo > 0.0) ? 0.0 : env->L;
    }
    *lo = cdl_nits(L_lo);
    *hi = cdl_nits(L_hi);
    return 1;
}
